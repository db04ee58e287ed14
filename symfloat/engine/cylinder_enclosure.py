"""The floating circular cylinder in ball arithmetic: the certified method of its witnesses (issue 29).

The slice integrals of :mod:`symfloat.geometry.cylinder` by the same elementary primitives, in Arb.  The
radius ``r`` and the length ``L`` are balls (exact where they are rational), the up vector and the density
ratio ``s`` balls.  In the meridian plane of the up vector, ``sin theta`` is the length of its horizontal
part and ``cos theta`` the absolute value of its vertical one (no angle is formed); the cylinder is upright
where the horizontal part is exactly 0, lying where the vertical one is, and a ball that holds 0 without
being it (a tilt that may be upright or not) has no enclosure here (:class:`Ambiguous`: the tilted slices
divide by both).

**The branches** (which base the water cuts, how far the fully submerged disks reach) are not chosen by a
comparison: the tilted formulas take the bounds of the partial slices ``a = max(-L/2, z_full)``,
``b = min(L/2, z_empty)``, ``z_full, z_empty = (t -+ r sin theta) / cos theta``, and of the full disks
``max(-L/2, min(L/2, z_full))``, by Arb's ``min`` and ``max``, which enclose the true bound for every
point of the balls: where a ball straddles a base, both branches are joined.  A slice's angle is
``psi = acos((t - z cos theta) / (r sin theta))`` clamped to ``[0, pi]`` (:func:`_angle`: the arccosine of
the ends of the clamped ball, joined); a primitive ``F`` at an angle's ball ``p`` is taken in the mean-value
form ``F(mid p) + F'(p) (p - mid p)`` (:func:`_primitive`): near 0 and pi, where the slice integrands vanish
to high order, the arccosine's square-root loss does not reach the integral.  The waterplane likewise, the
ends of its chords ``max(w_lo, z_lo)``, ``min(w_hi, z_hi)``.

**The draught** ``t``: closed upright (``t = (s - 1/2) L``); else Newton's steps at exact dyadic points from
the float64 draught (``dV/dt`` is the waterplane area), then a bracket ``[t - d, t + d]``, ``d`` about
``2^-bits`` of ``r + L`` plus twice what the data's balls move the draught (a density found as a root),
**proven** by the signs of ``V - s V_total`` at its ends (``V`` grows with ``t``);
a bracket whose signs are not proven at the precision gives :class:`Ambiguous`.

>>> from fractions import Fraction as F
>>> from flint import arb
>>> from symfloat.engine.enclosure import working_precision
>>> with working_precision(128 + GUARD_BITS):              # lying: half immersed at s = 1/2, t = 0
...     st = cylinder_state(arb(1), F(2), (arb(1), arb(0), arb(0)), arb(1) / 2, 128)
...     st.t.abs_upper() < arb(2) ** -100
True
"""
from __future__ import annotations

import math
from fractions import Fraction

from flint import arb

from ..geometry.cylinder import cylinder_state as float_cylinder_state
from .enclosure import exact, working_precision
from .floating_enclosure import GUARD_BITS, NEWTON_STEPS, Ambiguous, BallState

__all__ = ["cylinder_state", "slice_integrals"]


def _angle(x):
    """``acos`` of the ball *x* clamped to ``[-1, 1]``: the arccosines of the clamped ends, joined (``acos`` is
    decreasing)."""
    one = arb(1)
    lo, hi = x.lower(), x.upper()
    top = arb(0) if hi >= one else arb(hi).acos()
    bottom = arb.pi() if lo <= -one else arb(lo).acos()
    return top.union(bottom)


def _integrands(p):
    """The slice integrands at *p* (see :func:`_primitives_at`)."""
    sn, cs = p.sin(), p.cos()
    area = arb.pi() - p + sn * cs
    return {"A sin": area * sn, "A sin cos": area * sn * cs, "sin^4": sn ** 4, "sin^2": sn * sn,
            "sin^2 cos": sn * sn * cs, "sin^2 cos^2": (sn * cs) ** 2}


def _primitives_at(p):
    """The primitives of :func:`symfloat.geometry.cylinder._primitives` at the ball *p*, A(p) = pi - p + sin p cos p:

    int A sin p = -(pi - p) cos p - sin p + sin^3 p / 3,
    int A sin p cos p = -(pi - p) cos 2p / 4 - sin 2p / 8 + p / 8 - sin 4p / 32,
    int sin^4 p = 3p/8 - sin 2p / 4 + sin 4p / 32,
    int sin^2 p = p/2 - sin 2p / 4,   int sin^2 p cos p = sin^3 p / 3,   int sin^2 p cos^2 p = p/8 - sin 4p / 32."""
    sn, cs = p.sin(), p.cos()
    s2, c2 = 2 * sn * cs, cs * cs - sn * sn
    s4 = 2 * s2 * c2
    rest = arb.pi() - p
    return {"A sin": -rest * cs - sn + sn ** 3 / 3,
            "A sin cos": -rest * c2 / 4 - s2 / 8 + p / 8 - s4 / 32,
            "sin^4": 3 * p / 8 - s2 / 4 + s4 / 32,
            "sin^2": p / 2 - s2 / 4,
            "sin^2 cos": sn ** 3 / 3,
            "sin^2 cos^2": p / 8 - s4 / 32}


def _primitive(p):
    """The primitives at the ball *p* in the mean-value form ``F(m) + F'(p) (p - m)``, ``m`` its midpoint."""
    if p.rad() == 0:
        return _primitives_at(p)
    m = arb(p.mid())
    at, slope = _primitives_at(m), _integrands(p)
    return {k: at[k] + slope[k] * (p - m) for k in at}


def slice_integrals(a, b):
    """The slice integrals over ``[a, b]`` (balls, ``a <= b``) by the primitives (:func:`_primitive`)."""
    lo, hi = _primitive(a), _primitive(b)
    return {k: hi[k] - lo[k] for k in lo}


def _zero(x):
    """Whether the ball *x* is exactly 0; :class:`Ambiguous` where it holds 0 without being it."""
    if x == 0:
        return True
    if x > 0 or x < 0:
        return False
    raise Ambiguous("the tilt's ball holds the upright or the lying position without being it: the cylinder's "
                    "branches divide by its sine and cosine")


def _volume_moments(r, L, st, ct, t):
    """Submerged volume and its moments ``(V, int x dV, int z dV)`` in the meridian frame (as
    :func:`symfloat.geometry.cylinder._volume_moments`, the bounds by ``min``/``max``)."""
    pi, zero = arb.pi(), arb(0)
    if st == 0:
        h = (t + L / 2).max(zero).min(L)
        return pi * r * r * h, zero, pi * r * r * ((-L / 2 + h) ** 2 - L * L / 4) / 2
    if ct == 0:
        psi = _angle(t / r)
        return L * r * r * (pi - psi + psi.sin() * psi.cos()), L * (-2 * r ** 3 * psi.sin() ** 3 / 3), zero
    z_full, z_empty = (t - r * st) / ct, (t + r * st) / ct
    lo, hi = -L / 2, L / 2
    full_hi = z_full.min(hi).max(lo)
    V = pi * r * r * (full_hi - lo)
    Mz = pi * r * r * (full_hi ** 2 - lo ** 2) / 2
    a, b = z_full.max(lo), z_empty.min(hi)
    if not b > a:
        raise Ambiguous("the partial slices' range is not proven non-empty (the water plane may miss the body)")
    jac = r * st / ct
    i = slice_integrals(_angle((t - a * ct) / (st * r)), _angle((t - b * ct) / (st * r)))
    V += r * r * jac * i["A sin"]
    Mz += r * r * jac / ct * (t * i["A sin"] - r * st * i["A sin cos"])
    Mx = -2 * r ** 3 / 3 * jac * i["sin^4"]
    return V, Mx, Mz


def _waterplane(r, L, st, ct, t, area_only=False):
    """Area, centroid ``w``, central second moments ``I_w`` (about e_y) and ``I_y`` (about the w axis) of the
    waterplane, as :func:`symfloat.geometry.cylinder._waterplane` (``area_only``: the area alone)."""
    pi, zero = arb.pi(), arb(0)
    if st == 0:
        return pi * r * r if area_only else (pi * r * r, zero, pi * r ** 4 / 4, pi * r ** 4 / 4)
    if ct == 0:
        half = (r * r - t * t).max(zero).sqrt()
        return 2 * half * L if area_only else (2 * half * L, zero, 2 * half * L ** 3 / 12, L * (2 * half) ** 3 / 12)
    a = ((-r - t * st) / ct).max((t * ct - L / 2) / st)
    b = ((r - t * st) / ct).min((t * ct + L / 2) / st)
    if not b > a:
        raise Ambiguous("the waterplane's chords are not proven to span a positive width")
    # the chord at w(phi) = (-r cos phi - t sin theta)/cos theta, of width 2 r sin phi (phi increases with w)
    i = slice_integrals(_angle(-(t * st + a * ct) / r), _angle(-(t * st + b * ct) / r))
    weight = 2 * r * r / ct
    area = weight * i["sin^2"]
    if area_only:
        return area
    if not area > 0:
        raise Ambiguous("the waterplane's area is not proven positive")
    centre = weight / ct * (-r * i["sin^2 cos"] - t * st * i["sin^2"]) / area
    about = -(t * st + centre * ct) / r
    central = i["sin^2 cos^2"] - 2 * about * i["sin^2 cos"] + about * about * i["sin^2"]
    return area, centre, weight * (r / ct) ** 2 * central, 2 * r ** 4 / (3 * ct) * i["sin^4"]


def _draught(r, L, st, ct, s, bits):
    """The draught as a proven bracket (see the module)."""
    if st == 0:
        return (s - arb(1) / 2) * L
    target = s * arb.pi() * r * r * L
    theta = math.atan2(float(st.mid()), float(ct.mid()))
    t = arb(float_cylinder_state(float(r.mid()), float(L.mid()), theta, float(s.mid())).t)
    step = arb(2) ** (4 - bits) * (r + L)
    for _ in range(NEWTON_STEPS):
        f = _volume_moments(r, L, st, ct, t)[0] - target
        nxt = arb((t - f / _waterplane(r, L, st, ct, t, area_only=True)).mid())
        done = (nxt - t).abs_upper() < step / 4
        t = nxt
        if done:
            break
    # the bracket at least twice as wide as the balls of the data move the draught (a density's ball: dt = dV / A)
    step += 2 * arb(target.rad() + (_volume_moments(r, L, st, ct, t)[0]).rad()) / _waterplane(r, L, st, ct, t,
                                                                                                   area_only=True)
    for widen in range(0, bits // 2 - 8, 8):
        lo, hi = t - step * 2 ** widen, t + step * 2 ** widen
        if _volume_moments(r, L, st, ct, lo)[0] < target and _volume_moments(r, L, st, ct, hi)[0] > target:
            return lo.union(hi)
    raise Ambiguous(f"the cylinder's draught bracket is not proven at {bits} bits")


def cylinder_state(r, L, up, s, bits) -> BallState:
    """The :class:`~symfloat.engine.floating_enclosure.BallState` of the cylinder of radius *r* (a ball) and
    length *L* (a Fraction: its bases' heights are read by their exact z), axis z, centred, with *up* (balls, not
    necessarily unit) up at the density ratio *s* (a ball), computed at ``bits + GUARD_BITS``: the fields as
    :func:`symfloat.engine.floating_witness._cylinder_state` carries the meridian state to the body frame; its
    ``vertices`` the four rim points extreme along the up vector (``exact``: their z alone)."""
    with working_precision(bits + GUARD_BITS):
        length = exact(Fraction(L))
        norm = (up[0] * up[0] + up[1] * up[1] + up[2] * up[2]).sqrt()
        u = tuple(x / norm for x in up)
        zero = arb(0)
        if _zero(u[0]) and _zero(u[1]):
            h, st = (arb(1), zero), zero
        else:
            st = (u[0] * u[0] + u[1] * u[1]).sqrt()
            h = (u[0] / st, u[1] / st)
        sign = 1 if _zero(u[2]) or u[2] > 0 else -1                   # z mirrored when the axis points down
        ct = zero if u[2] == 0 else abs(u[2])
        t = _draught(r, length, st, ct, s, bits)
        V, Mx, Mz = _volume_moments(r, length, st, ct, t)
        area, centre, I_w, I_y = _waterplane(r, length, st, ct, t)
        B = (Mx / V * h[0], Mx / V * h[1], sign * Mz / V)
        e1, e2 = (ct * h[0], ct * h[1], -sign * st), (-h[1], h[0], zero)
        zs = (Fraction(L) / 2, -Fraction(L) / 2)
        vertices = tuple((k * r * h[0], k * r * h[1], exact(z)) for k in (1, -1) for z in zs)
        potential = -(u[0] * B[0] + u[1] * B[1] + u[2] * B[2])
        I_min, I_max = I_w.min(I_y), I_w.max(I_y)
        return BallState(u, t, V, B, (zero,) * 3, area, tuple(t * a + centre * b for a, b in zip(u, e1)),
                         ((I_w, zero), (zero, I_y)), (e1, e2), I_min, I_max, potential, I_min / V - potential,
                         vertices, tuple((None, None, z) for k in (1, -1) for z in zs))
