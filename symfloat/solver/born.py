"""Equilibria born at a symmetric position, from its local expansion.

Where the exactly decided second variation of a position fixed by symmetry
(:mod:`symfloat.solver.exact`) is small, a family is born there or dies into it:
along a mirror plane through the position, ``u(theta) = cos theta a + sin theta d``,
the gradient stays in the plane (the reflection fixes the curve), so the slope

    f(theta) = dU/dtheta = lambda_d theta + c theta^3 + ...        (lambda_d exact)

vanishes at ``theta = 0`` and at ``theta* ~ sqrt(-lambda_d / c)`` where ``lambda_d`` and ``c`` have
opposite signs.  ``f(theta) / theta`` is evaluated at ``dps`` digits (enough for ``lambda_d theta``
at the smallest ``theta`` scanned to exceed the rounding by 1e10) on a geometric grid (ratio 2) from
``1e-3 sqrt(|lambda_d| / size)`` out, and its first change of sign is bracketed and narrowed by false
position to 1e-18 of itself: the root is then an equilibrium (a change of sign of the slope on an invariant curve)
located to the bracket (its error: that, the reach of the rounding of ``f`` at ``dps`` digits, ``10^(5 - dps)
size / |f'|``, and the rounding of the float64 up vector), however small the family is (a ring of radius 8e-5 rad 1e-9 past the
cube's face-up pitchfork, whose potential differs from the axis's by 1e-17, below float64).

Around an axis of order 3 or more (the two eigenvalues equal exactly) the position's rotations make
the family a closed ring where every mirror class of rays meets it at the same ``theta*`` (checked
to 1e-20 of it); otherwise each ray's root is an isolated equilibrium (a pitchfork's pair), and its
stability is that of the second variation there at ``dps`` digits.
"""
from __future__ import annotations

import math

import mpmath
import numpy as np

from ..geometry.floating import floating_state
from .critical import Critical
from .bodies import polyhedron
from .errors import ROUNDING
from .exact import integer_direction
from .local import local, tangent_step
from .symmetry import mirror_normals, orbit, representative, same_class

__all__ = ["born_families", "SOFT_AXIS"]

SOFT_AXIS = 1e-2        # relative to the size of the body: a smaller exact eigenvalue is looked at for a family
REACH = 0.2             # radians: the farthest a family born at the position is looked for


def _rays(u, group) -> list[np.ndarray]:
    """Unit tangent directions at *u* within the mirror planes through it, one per symmetry class of rays."""
    out = []
    for m in mirror_normals(group):
        if abs(float(m @ u)) > 1e-12:
            continue
        d = np.cross(m, u)
        d /= np.linalg.norm(d)
        for ray in (d, -d):
            probe = tangent_step(u, 1e-3 * ray)
            if not any(same_class(probe, tangent_step(u, 1e-3 * r), group, 1e-12) for r in out):
                out.append(ray)
    return out


def _exact_unit(v, turns: int):
    """The unit vector *v* (floats) in mpmath at the current precision, exactly: an integer direction
    normalised (:func:`~symfloat.solver.exact.integer_direction`), else a horizontal direction whose angle is
    a multiple of ``pi / turns`` (a regular prism's mirrors).  The rounding of a float unit vector (5e-17)
    tilts the tangent of the curve against the point, and the slope picks up ``U`` times that: 1e-12 rad
    in a ring's radius 1e-9 past the cube's pitchfork."""
    n = integer_direction(v)
    if n is not None:
        norm = mpmath.sqrt(sum(x * x for x in n))
        return [mpmath.mpf(x) / norm for x in n]
    angle = math.atan2(float(v[1]), float(v[0]))
    k = round(angle * turns / math.pi)
    if abs(float(v[2])) > 1e-15 or abs(angle - k * math.pi / turns) > 1e-12:
        raise ValueError("a ray off the body's mirrors")
    return [mpmath.cospi(mpmath.mpf(k) / turns), mpmath.sinpi(mpmath.mpf(k) / turns), mpmath.mpf(0)]


def _slope(poly, a, d, theta, s):
    """``f(theta)`` (mpf) at the body's precision, *a* and *d* unit vectors in mpmath: the gradient along the
    curve's tangent; and the floating state there."""
    with mpmath.workdps(poly.dps):
        c, sn = mpmath.cos(theta), mpmath.sin(theta)
        u = [c * a[k] + sn * d[k] for k in range(3)]
        t = [-sn * a[k] + c * d[k] for k in range(3)]
        st = floating_state(poly, u, s)
        return sum(t[k] * (st.G[k] - st.B[k]) for k in range(3)), st


def _root(poly, a, d, s, lam, scale):
    """``(theta*, error, f'(theta*), state)`` of the first change of sign of ``f(theta)/theta`` away from
    the sign of *lam*, or None within :data:`REACH`.  The error is the bracket's width plus the reach of the
    arithmetic, ``10^(5 - dps) scale / |f'|``: narrowed to 1e-18 of ``theta``, the ends' values fall to the
    rounding of ``f`` at the body's digits, whose sign is then not known (1e-13 past the box 1 x 2 x 3's
    pitchfork, at 34 digits, the true root lay 2.3e-24 from a bracket 7e-25 wide)."""
    theta = 1e-3 * math.sqrt(abs(lam) / scale)
    sign = 1 if lam > 0 else -1
    with mpmath.workdps(poly.dps):
        lo, f_lo = mpmath.mpf(theta), None
        f_lo = _slope(poly, a, d, lo, s)[0]
        if (f_lo > 0) != (sign > 0):
            return None                             # the expansion does not hold at the first step
        hi = lo
        while True:
            hi = hi * 2
            if hi > REACH:
                return None
            f_hi = _slope(poly, a, d, hi, s)[0]
            if (f_hi > 0) != (sign > 0) or f_hi == 0:
                break
            lo, f_lo = hi, f_hi
        # false position (Illinois) on [lo, hi] to 1e-18 of theta
        side = 0
        while hi - lo > mpmath.mpf(10) ** -18 * hi:
            mid = hi - f_hi * (hi - lo) / (f_hi - f_lo)
            if not lo < mid < hi:
                mid = (lo + hi) / 2
            f_mid = _slope(poly, a, d, mid, s)[0]
            if f_mid == 0:
                lo = hi = mid
                break
            if (f_mid > 0) == (f_lo > 0):
                lo, f_lo = mid, f_mid
                if side == -1:
                    f_hi /= 2
                side = -1
            else:
                hi, f_hi = mid, f_mid
                if side == 1:
                    f_lo /= 2
                side = 1
        root = (lo + hi) / 2
        h = root * mpmath.mpf(10) ** -6
        slope = (_slope(poly, a, d, root + h, s)[0] - _slope(poly, a, d, root - h, s)[0]) / (2 * h)
        rounding = mpmath.mpf(10) ** (5 - poly.dps) * scale
        reach = rounding / abs(slope) if slope else mpmath.inf
        return root, float(hi - lo + reach), float(slope), _slope(poly, a, d, root, s)[1]


def _hessian(st):
    """The metacentric eigenvalues (ascending, floats) of a floating state in mpmath."""
    T = st.tensor
    H = [[T[0][0] / st.volume - st.potential, T[0][1] / st.volume], [T[1][0] / st.volume, T[1][1] / st.volume - st.potential]]
    mean, half = (H[0][0] + H[1][1]) / 2, mpmath.sqrt(((H[0][0] - H[1][1]) / 2) ** 2 + H[0][1] ** 2)
    return float(mean - half), float(mean + half)


def born_families(scene, poly, u, exact, group, scale, prism=None) -> list[Critical]:
    """The equilibria born at the symmetric position *u* of *scene* (*poly* its float64 body; *exact* the
    position's :class:`~symfloat.solver.exact.ExactSecondVariation`) within :data:`REACH`: a closed ring
    around it, or one isolated class per ray (module docstring).  Nothing where its eigenvalues are not
    small, or zero (a degenerate position: its higher orders decide, :mod:`~symfloat.solver.degenerate`).
    *prism*: ``(R, L)`` where *u* is the axis of the body seen as a right prism of length ``L`` over a base of
    circumradius ``R`` whose second moments are isotropic (then a ring, when the tilt keeps the waterplane
    off the end faces: :func:`_lateral`)."""
    soft = min(exact.eigenvalues, key=abs)
    if not 0 < abs(soft) < SOFT_AXIS * scale or exact.product_sign == 0:
        return []
    s = scene.density
    digits = max(30, int(-math.log10(1e-3 * abs(soft) ** 1.5 / scale ** 0.5)) + 15)
    body = polyhedron(scene, dps=digits)        # the exact body at these digits (a prism's float64 n-gon is
    turns = 2 * scene.sides if scene.body == "prism" else 4     # regular to 1e-16 only: a ring's radius to 1e-8)
    rays = _rays(u, group)
    ring = exact.isotropic and prism is not None
    found = []
    for d in rays[:1] if ring else rays:
        lam = soft if exact.isotropic else _along(poly, u, d, s, exact)
        if abs(lam) >= SOFT_AXIS * scale:
            continue            # not the soft eigenvalue's ray (a mirror's: the eigenvectors of the pair)
        with mpmath.workdps(digits):
            a, e = _exact_unit(u, turns), _exact_unit(d, turns)
        root = _root(body, a, e, s, lam, scale)
        if root is not None:
            found.append((d, *root))
    if ring and found and _lateral(found[0][1], s, *prism):
        return [_ring(u, found[0], group)]
    if ring and found:
        return []               # a ring that reaches an end face: not predicted; the search decides
    return [_isolated(u, r, group, digits) for r in found]


def _lateral(theta, s, R, L) -> bool:
    """Whether at tilt *theta* the waterplane of a right prism (length *L*, base circumradius *R*, its
    second moments isotropic) meets its lateral faces only, in every direction of tilt.  Then (the plane
    ``z = h + p . x`` over the base, ``|p| = tan theta``) the submerged volume is ``A (h + L/2)``, so ``h =
    (s - 1/2) L`` whatever the tilt, ``B`` has moments ``J p`` and ``h^2 A + p . J p``, and with ``J``
    isotropic the potential depends on ``|p|`` alone: the root along one ray is a circle of equilibria.
    The condition: ``R tan theta < L min(s, 1 - s)``."""
    with mpmath.workdps(30):
        s = mpmath.mpf(s.numerator) / s.denominator
        return R * mpmath.tan(theta) < L * min(s, 1 - s) * (1 - mpmath.mpf(10) ** -20)


def _along(poly, u, d, s, exact) -> float:
    """Which exact eigenvalue belongs to the ray *d*: the one nearer the float64 second variation along it."""
    loc = local(poly, u, s)
    H3 = loc.basis @ loc.hessian @ loc.basis.T
    value = float(d @ H3 @ d)
    return min(exact.eigenvalues, key=lambda e: abs(e - value))


def _point(u, d, theta) -> np.ndarray:
    return math.cos(theta) * np.asarray(u) + math.sin(theta) * np.asarray(d)


def _ring(u, found, group) -> Critical:
    d, theta, bracket, slope, st = found
    theta = float(theta)
    p = _point(u, d, theta)
    e2 = np.cross(u, d)
    path = tuple(math.cos(theta) * u + math.sin(theta) * (math.cos(a) * d + math.sin(a) * e2)
                 for a in np.linspace(0, 2 * math.pi, 64, endpoint=False))
    c = Critical(representative(p, group), float(st.potential), (0.0, slope), 0.0, bracket + ROUNDING, len(orbit(u, group)),
                 True, "closed", 2 * math.pi * math.sin(theta), 2 * math.pi * bracket, "sign change", 0.0, 0,
                 path=path, axis=np.asarray(u, dtype=float))
    return c


def _isolated(u, found, group, dps: int) -> Critical:
    """One class of a pitchfork's pair: the representative up vector and, where the symmetry that makes it
    the representative is a signed permutation (exact in any arithmetic), its digits (at *dps*, the state's)."""
    d, theta, bracket, slope, st = found
    p = _point(u, d, float(theta))
    rep = representative(p, group)
    g = next(g for g in group if np.array_equal(g @ p, rep))
    with mpmath.workdps(dps):
        digits = tuple(sum(int(g[i, j]) * st.u[j] for j in range(3)) for i in range(3)) \
            if np.all(np.isin(g, (-1, 0, 1))) else ()
    return Critical(rep, float(st.potential), _hessian(st), 0.0, bracket + ROUNDING,
                    len(orbit(p, group)), error_method="sign change", digits=digits)
