"""Vertex events: where a ring of equilibria round a prism's axis breaks, known from the body.

A right prism of length ``L`` over a base of area ``A`` whose second moment ``I`` about every line through its
centroid is the same (a square, a regular polygon) and whose circumradius is ``R``, tilted so that its waterplane
``z = h + p . x`` meets the lateral faces only, has ``h = (s - 1/2) L`` and a buoyancy centre ``(I p, (A h^2 + I
|p|^2 - A L^2 / 4) / 2) / V``; it lies on the up vector ``(-p, 1)`` where

    tan^2 theta* = |p|^2 = A L^2 s (1 - s) / I - 2,

a closed ring round the axis while the plane keeps off the end faces, ``R tan theta* < L s'`` (``s' = min(s, 1 -
s)``, the end face below or above).  It breaks where a base vertex reaches the waterplane,

    R^2 (A L^2 s' (1 - s') / I - 2) = L^2 s'^2,

a quadratic in ``s'`` (the cube: ``7 s^2 - 6 s + 1 = 0``, ``s = 3/7 - sqrt(2)/7``, Scheeffer X (171)).  Past it
the vertex lies ``depth = R tan theta* - L s'`` beyond the plane: the ring becomes arcs with a class between them
in the vertex's direction, whose potential differs from the arcs' by the corner the plane cuts off, of order
``depth^3`` (its soft eigenvalue 8.1e-24 at 1e-9 past the cube's event, 8.1e-33 at 1e-12), far below float64.
"""
from __future__ import annotations

import math

import mpmath

from ..model.prediction import Scene
from .bodies import polyhedron

__all__ = ["ring_axes", "vertex_depths", "event_digits", "lateral_arc", "EVENT_DIGITS", "ARC_DIGITS"]

# the most digits spent on a class beside a vertex event; closer still, the scene refuses.  The bounds that decide
# the class are float64 (critical._decided): at d digits the arithmetic's error 10^(5 - d) and the square of the soft
# eigenvalue, about (depth^3 / 30)^2 = 10^(20 - d) / 900 by :func:`event_digits`, stay above float64's smallest normal
# number 2.2e-308 up to about 300 digits (1e-55 past the cube's event, 346 digits, divided by a square that was 0.0)
EVENT_DIGITS = 300
ARC_DIGITS = 40         # the digits at which an arc's ends are located (bisected to 10^(10 - ARC_DIGITS) rad)


def ring_axes(scene: Scene) -> list[tuple[tuple[int, int, int], mpmath.mpf, mpmath.mpf, mpmath.mpf, mpmath.mpf]]:
    """``(axis, A, I, R^2, L)`` (mpf at the current precision) for every axis of *scene* about which the body is a
    right prism over a base of isotropic second moments: the cube's three face normals, a box's axis whose two
    other edges are equal, a regular prism's axis (its base of side ``a``: ``I / A = a^2 (1 + 3 cot^2(pi / n)) /
    48``, ``R = a / (2 sin(pi / n))``)."""
    mp = lambda x: mpmath.mpf(x.numerator) / x.denominator
    out = []
    if scene.body in ("cube", "box"):
        for k in range(3):
            a, b = (scene.dims[i] for i in range(3) if i != k)
            if a == b:
                axis = tuple(int(i == k) for i in range(3))
                out.append((axis, mp(a) ** 2, mp(a) ** 4 / 12, mp(a) ** 2 / 2, mp(scene.dims[k])))
    elif scene.body == "prism":
        n, a, L = scene.sides, mp(scene.dims[0]), mp(scene.dims[1])
        area = n * a ** 2 / (4 * mpmath.tan(mpmath.pi / n))
        out.append(((0, 0, 1), area, area * a ** 2 * (1 + 3 * mpmath.cot(mpmath.pi / n) ** 2) / 48,
                    (a / (2 * mpmath.sin(mpmath.pi / n))) ** 2, L))
    return out


def vertex_depths(scene: Scene, dps: int = 50) -> list[tuple[tuple[int, int, int], mpmath.mpf, mpmath.mpf]]:
    """``(axis, depth, theta*)`` for every ring axis of *scene* where the ring exists (``tan^2 theta* > 0``): how
    far (in the body's length units) a base vertex lies beyond the waterplane at the ring's tilt ``theta*``;
    negative before the vertex event, where the ring is closed.  The depth is a difference of two lengths that
    cancel at the event, and a density ``p/q`` can lie within about ``1/q^2`` of an irrational event (a convergent
    of its continued fraction: depth 2.3e-116 at a density of 58 digits past the cube's): it is computed at *dps*
    digits plus twice the density's, and at four times those digits where it is within their rounding of zero.  A
    depth still within the rounding is the event itself (a rational event, the box 3 x 3 x 4 at s = 3/28): 0, the
    vertex on the plane and the ring closed, whatever the body's scale."""
    s = scene.density
    digits = dps + 2 * len(str(s.denominator))
    for _ in range(2):
        out = _depths(scene, digits)
        if all(abs(depth) > rounding for _, depth, _, rounding in out):
            break
        digits *= 4
    return [(axis, depth if abs(depth) > rounding else mpmath.mpf(0), theta) for axis, depth, theta, rounding in out]


def _depths(scene: Scene, digits: int) -> list:
    """``(axis, depth, theta*, rounding)`` at *digits* digits, the rounding a bound of the depth's error
    (``10^(5 - digits)`` times the length and the circumradius)."""
    s = scene.density
    with mpmath.workdps(digits):
        t = mpmath.mpf(min(s, 1 - s).numerator) / min(s, 1 - s).denominator
        out = []
        for axis, area, second, r2, L in ring_axes(scene):
            tan2 = area * L ** 2 * t * (1 - t) / second - 2
            if tan2 > 0:
                rounding = mpmath.mpf(10) ** (5 - digits) * (L + mpmath.sqrt(r2))
                out.append((axis, +(mpmath.sqrt(r2 * tan2) - L * t), mpmath.atan(mpmath.sqrt(tan2)), rounding))
    return out


def event_digits(scene: Scene, scale: float) -> int:
    """The digits at which a class beside a ring just past a vertex event is polished: its soft eigenvalue is
    about ``depth^3 / (30 scale)`` (the cube: 8.1e-33 at depth 6.2e-12), and Newton–Kantorovich decides it where
    the residual at ``d`` digits, ``10^(2 - d) scale``, is below ``lambda^2 / (2 L)``: ``d = 20 - 6 log10(depth /
    scale)`` (20 digits to spare).  0 where no ring is past an event; the event is passed by less than the
    arithmetic resolves beyond :data:`EVENT_DIGITS`."""
    depths = [d for _, d, _ in vertex_depths(scene) if d > 0]
    if not depths:
        return 0
    return math.ceil(20 - 6 * float(mpmath.log10(min(depths) / scale)))


def lateral_arc(scene: Scene, u, tol: float) -> tuple[float, float] | None:
    """``(length, error)`` in radians on the sphere of the arc of equilibria through the up vector *u*, where it is
    a piece of the ring round a ring axis (:func:`ring_axes`; the tilt of *u* from the axis within *tol* of
    ``theta*``): up ``cos theta* a + sin theta* (cos phi e1 + sin phi e2)`` is an equilibrium while its waterplane,
    through ``(s - 1/2) L a``, keeps every vertex of the end face below it under water and every vertex of the end
    face above it dry; each end is where a vertex reaches the plane, bracketed between the vertices' azimuths
    (between two of them each vertex's margin is monotone in ``phi``, so the first change of sign is the only one)
    and bisected at :data:`ARC_DIGITS` digits to ``10^(10 - ARC_DIGITS)`` rad.  The length is ``sin theta*`` times
    the azimuths between the brackets' middles, its error ``sin theta*`` times half the two brackets' widths (the
    margin's rounding, ``10^-ARC_DIGITS`` over its slope, is far below them) and the length's float64 rounding.
    None where *u* lies on no such ring, or the ring through it is closed."""
    s = scene.density
    body = polyhedron(scene, dps=ARC_DIGITS)
    with mpmath.workdps(ARC_DIGITS):
        t = mpmath.mpf(min(s, 1 - s).numerator) / min(s, 1 - s).denominator
        h = (mpmath.mpf(s.numerator) / s.denominator - mpmath.mpf(1) / 2)
        w = [mpmath.mpf(float(x)) for x in u]
        w = [x / mpmath.sqrt(sum(y * y for y in w)) for x in w]
        for axis, area, second, _, L in ring_axes(scene):
            tan2 = area * L ** 2 * t * (1 - t) / second - 2
            if tan2 <= 0:
                continue
            k = axis.index(1)
            sign = 1 if w[k] > 0 else -1
            e1, e2 = [i for i in range(3) if i != k]
            theta = mpmath.atan(mpmath.sqrt(tan2))
            if abs(mpmath.atan2(mpmath.hypot(w[e1], w[e2]), abs(w[k])) - theta) > tol:
                continue
            c, sn = mpmath.cos(theta), mpmath.sin(theta)

            def margin(phi):
                up = [mpmath.mpf(0)] * 3
                up[k], up[e1], up[e2] = sign * c, sn * mpmath.cos(phi), sn * mpmath.sin(phi)
                level = h * L * c
                return min((level - sum(a * b for a, b in zip(up, v))) * (1 if sign * v[k] < 0 else -1)
                           for v in body.vertices)
            phi0 = mpmath.atan2(w[e2], w[e1])
            if margin(phi0) <= 0:
                continue
            azimuths = sorted({mpmath.atan2(v[e2], v[e1]) % (2 * mpmath.pi) for v in body.vertices}
                              | {(mpmath.atan2(v[e2], v[e1]) + mpmath.pi) % (2 * mpmath.pi) for v in body.vertices})
            ends = []
            for direction in (1, -1):
                ahead = sorted(((b - phi0) * direction) % (2 * mpmath.pi) for b in azimuths)
                ahead = [phi0 + direction * x for x in ahead if x > 0] + [phi0 + direction * 2 * mpmath.pi]
                lo = phi0
                hi = next((b for b in ahead if margin(b) <= 0), None)
                if hi is None or abs(hi - phi0) >= 2 * mpmath.pi:
                    return None             # the ring is closed
                while abs(hi - lo) > mpmath.mpf(10) ** (10 - ARC_DIGITS):
                    mid = (lo + hi) / 2
                    lo, hi = (mid, hi) if margin(mid) > 0 else (lo, mid)
                ends.append(((lo + hi) / 2, abs(hi - lo)))
            length = float(sn * abs(ends[0][0] - ends[1][0]))
            return length, float(sn * (ends[0][1] + ends[1][1]) / 2) + math.ulp(length)
    return None
