"""Floating convex bodies by clipping: the independent witness for floating prisms.

A body is a convex polyhedron given by its faces.  It floats with the unit
vector ``u`` (body frame) pointing up; the water plane is ``u . p = t`` and the
submerged part is ``u . p <= t``.  Everything is measured on the clipped
polyhedron and its waterplane polygon with exact polygon and polyhedron
integrals; nothing here knows a metacentre formula or a closed form for a
wedge or a segment.

Arithmetic.  A body carries its precision: ``dps=None`` (the default) is
float64, ``dps=k`` is mpmath at ``k`` significant digits, applied with
``mpmath.workdps`` around every operation on the body, so the global
precision is never changed.  Clipping and the integrals are a fixed, short
sequence of field operations, so for bodies of moderate aspect ratio with up
to a few hundred faces the relative error of volumes, centroids, areas and
second moments is at most ``1e-12`` in float64 and ``10**(-dps + 5)`` with
mpmath (both relative to the size of the body).  The draught is found to a
tolerance and returned with a bracket that certifies it (:func:`draught`).

>>> cube = box(1, 1, 1)
>>> st = floating_state(cube, (0, 0, 1), 0.25)
>>> round(st.t, 12), round(st.volume, 12), [round(c, 12) + 0 for c in st.B]
(-0.25, 0.25, [0.0, 0.0, -0.375])
>>> [[round(m, 12) + 0 for m in row] for row in st.tensor]
[[0.083333333333, 0.0], [0.0, 0.083333333333]]
"""
from __future__ import annotations

import contextlib
import functools
import itertools
import math
from array import array
from dataclasses import dataclass, field
from typing import Callable
from fractions import Fraction

import gmpy2
import mpmath

from .convex import hull_2d

try:                # the float64 clipping in C, built by setup.py where a compiler is at hand
    from ._clipped import submerged as _compiled_submerged
    from ._clipped import volume_and_area as _compiled_volume_and_area
except ImportError:                                         # pragma: no cover - no compiler at install
    _compiled_volume_and_area = _compiled_submerged = None

__all__ = [
    "Polyhedron", "Waterplane", "Submerged", "FloatingState", "CylinderState",
    "right_prism", "box", "regular_prism", "heel", "volume_centroid", "clip_below",
    "waterplane_basis", "submerged", "draught", "floating_state", "cylinder_state", "polygon_moments",
]


# -- numbers ---------------------------------------------------------------

def _precision(dps):
    """``mpmath.workdps(dps)``, or nothing for float64."""
    return contextlib.nullcontext() if dps is None else mpmath.workdps(dps)


def _num(x, dps):
    """*x* as a float (``dps=None``) or an mpf at the current precision."""
    if dps is None:
        return float(x)
    if isinstance(x, Fraction):
        return mpmath.mpf(x.numerator) / x.denominator
    return mpmath.mpf(x)


def _sqrt(x, dps):
    return math.sqrt(x) if dps is None else mpmath.sqrt(x)


def _at_body_precision(f):
    """Run *f* under the precision of its first argument, a :class:`Polyhedron`."""
    @functools.wraps(f)
    def wrapper(poly, *args, **kwargs):
        if not isinstance(poly, Polyhedron):
            raise TypeError(f"{f.__name__} needs a Polyhedron, not {type(poly).__name__}")
        with _precision(poly.dps):
            return f(poly, *args, **kwargs)
    return wrapper


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


# -- bodies ----------------------------------------------------------------

@dataclass(frozen=True)
class Polyhedron:
    """A convex polyhedron: each face a ring of 3-D points in counter-clockwise
    order seen from outside (outward normal by the right-hand rule).  ``dps``
    is its arithmetic: ``None`` for float64, else mpmath digits; ``at_digits(dps)``, where given, makes the same
    body from its exact description at *dps* digits (not from its float64 vertices)."""
    faces: tuple
    dps: int | None = None
    at_digits: Callable | None = field(default=None, compare=False, repr=False)

    @property
    def vertices(self):
        """The distinct vertices (each face ring lists its own copies)."""
        return _distinct_points(self.faces)

    @functools.cached_property
    def packed(self) -> tuple[bytes, bytes]:
        """A float64 body as the C step takes it (:func:`_volume_and_area`): the rings' vertices as doubles,
        ring after ring, and the rings' lengths as 32-bit integers."""
        points = array("d", (c for ring in self.faces for p in ring for c in p))
        return points.tobytes(), array("i", (len(ring) for ring in self.faces)).tobytes()

    def in_mpfr(self, prec: int) -> tuple:
        """An mpmath body's face rings in MPFR's numbers of *prec* bits (:func:`_in_mpfr`), made once per precision."""
        made = self.__dict__.setdefault("_in_mpfr", {})
        if prec not in made:
            with gmpy2.context(precision=prec):
                made[prec] = _to_mpfr(self.faces)
        return made[prec]


def _distinct_points(rings):
    """The distinct points of the face *rings*, each where it first occurs."""
    return list(dict.fromkeys(itertools.chain.from_iterable(rings)))


def right_prism(polygon, length, dps=None):
    """The right prism over a convex counter-clockwise *polygon* ``[(x, y), ...]``
    with its axis along ``z`` from ``-length/2`` to ``+length/2``.

    >>> len(right_prism([(0, 0), (1, 0), (0, 1)], 2).faces)
    5
    """
    with _precision(dps):
        poly = [(_num(x, dps), _num(y, dps)) for x, y in polygon]
        n = len(poly)
        if n < 3:
            raise ValueError("a prism needs a polygon with at least 3 vertices")
        turns = [(poly[(i + 1) % n][0] - poly[i][0]) * (poly[(i + 2) % n][1] - poly[i][1])
                 - (poly[(i + 1) % n][1] - poly[i][1]) * (poly[(i + 2) % n][0] - poly[i][0])
                 for i in range(n)]
        if min(turns) < 0 or max(turns) <= 0:
            raise ValueError("the polygon must be convex and counter-clockwise")
        h = _num(length, dps) / 2
        if not h > 0:
            raise ValueError("the prism length must be positive")
        top = tuple((x, y, h) for x, y in poly)
        bottom = tuple((x, y, -h) for x, y in reversed(poly))
        sides = tuple(((poly[i][0], poly[i][1], -h), (poly[(i + 1) % n][0], poly[(i + 1) % n][1], -h),
                       (poly[(i + 1) % n][0], poly[(i + 1) % n][1], h), (poly[i][0], poly[i][1], h))
                      for i in range(n))
        return Polyhedron((bottom, top) + sides, dps)


def box(a, b, c, dps=None):
    """The box ``[-a/2, a/2] x [-b/2, b/2] x [-c/2, c/2]``."""
    with _precision(dps):
        a2, b2 = _num(a, dps) / 2, _num(b, dps) / 2
        return right_prism([(-a2, -b2), (a2, -b2), (a2, b2), (-a2, b2)], c, dps)


def _regular_polygon(n, circumradius, dps):
    if n < 3:
        raise ValueError("a regular polygon needs n >= 3")
    if dps is None:
        return [(circumradius * math.cos(2 * math.pi * k / n), circumradius * math.sin(2 * math.pi * k / n))
                for k in range(n)]
    return [(circumradius * mpmath.cospi(mpmath.mpf(2 * k) / n), circumradius * mpmath.sinpi(mpmath.mpf(2 * k) / n))
            for k in range(n)]


def regular_prism(n, side, length, dps=None):
    """The right prism over the regular *n*-gon of edge *side*, centroid at the
    origin, one vertex on the ``+x`` axis (circumradius ``side / (2 sin(pi/n))``)."""
    with _precision(dps):
        s = _num(side, dps)
        R = s / (2 * (math.sin(math.pi / n) if dps is None else mpmath.sinpi(mpmath.mpf(1) / n)))
        return right_prism(_regular_polygon(n, R, dps), length, dps)


def heel(phi, trim=0):
    """The up vector of a prism heeled by *phi* about its axis ``z`` and trimmed
    by *trim* (its axis rising by that angle):
    ``u = (sin phi cos trim, cos phi cos trim, sin trim)``.

    With ``trim = 0`` the axis is horizontal (Scheeffer's position); any other
    unit vector may be passed as ``u`` directly.
    """
    return (math.sin(phi) * math.cos(trim), math.cos(phi) * math.cos(trim), math.sin(trim))


# -- volumes and clipping -------------------------------------------------

@_at_body_precision
def volume_centroid(poly):
    """Volume and centroid by fan tetrahedra from the vertex mean ``c``:
    ``V = sum det(a - c, b - c, d - c) / 6`` over fan triangles ``(a, b, d)`` of
    every face, centroid ``c + sum V_k (a + b + d - 3c) / 4 / V``.  An empty
    body gives ``(0, None)``."""
    return _volume_centroid(poly.faces, _num(0, poly.dps))


def _volume_centroid(faces, zero):
    """:func:`volume_centroid` of the body with face rings *faces*, in the arithmetic of *zero*."""
    verts = _distinct_points(faces)
    if not verts:
        return zero, None
    s0 = s1 = s2 = 0                # the vertex mean, summed left to right
    for v in verts:
        s0 += v[0]
        s1 += v[1]
        s2 += v[2]
    c0, c1, c2 = s0 / len(verts), s1 / len(verts), s2 / len(verts)
    volume, m0, m1, m2 = zero, zero, zero, zero
    for ring in faces:          # _sub, _cross and _dot inlined (the same operations in the same order)
        a0, a1, a2 = ring[0][0] - c0, ring[0][1] - c1, ring[0][2] - c2
        for b, d in zip(ring[1:], ring[2:]):
            b0, b1, b2 = b[0] - c0, b[1] - c1, b[2] - c2
            d0, d1, d2 = d[0] - c0, d[1] - c1, d[2] - c2
            v = (a0 * (b1 * d2 - b2 * d1) + a1 * (b2 * d0 - b0 * d2) + a2 * (b0 * d1 - b1 * d0)) / 6
            volume += v
            m0 += v * (a0 + b0 + d0)
            m1 += v * (a1 + b1 + d1)
            m2 += v * (a2 + b2 + d2)
    if volume == 0:
        return volume, None
    return volume, (c0 + m0 / (4 * volume), c1 + m1 / (4 * volume), c2 + m2 / (4 * volume))


def _unit(u, dps):
    u = tuple(_num(x, dps) for x in u)
    norm = _sqrt(_dot(u, u), dps)
    if not norm > 0:
        raise ValueError("the up vector must be non-zero")
    return tuple(x / norm for x in u)


def waterplane_basis(u, dps=None):
    """An orthonormal basis ``(e1, e2)`` of the plane normal to *u* with
    ``e1 x e2 = u``: ``e1`` is the coordinate axis least aligned with *u*
    (the first on ties) made orthogonal to it, ``e2 = u x e1``.  So for
    ``u = z`` it is ``(x, y)``, and for *u* across a prism axis ``z`` it is
    ``e1 = z`` (along the axis)."""
    with _precision(dps):
        u = _unit(u, dps)
        k = min(range(3), key=lambda i: abs(u[i]))
        e = [_num(0, dps)] * 3
        e[k] = _num(1, dps)
        e1 = tuple(e[i] - u[k] * u[i] for i in range(3))
        n1 = _sqrt(_dot(e1, e1), dps)
        e1 = tuple(x / n1 for x in e1)
        return e1, _cross(u, e1)


def _newell(ring):
    """Newell's normal of a face ring: ``sum p_i x p_(i+1)``, twice its vector area."""
    n = len(ring)
    crosses = [_cross(ring[i], ring[(i + 1) % n]) for i in range(n)]
    return tuple(sum(c[k] for c in crosses) for k in range(3))


def _clip(rings, u, t):
    """Sutherland-Hodgman on every face ring against ``u . p <= t``; returns the
    clipped face rings and the points lying on the plane.  A face lying in
    the plane with outward normal along ``+u`` is left out: the cap, built
    from the points on the plane, replaces it (one lying there facing ``-u``
    is kept and cancels the cap: the body is then flat)."""
    faces, on_plane = [], []
    for ring in rings:
        out = []
        n = len(ring)
        u0, u1, u2 = u
        heights = [u0 * p[0] + u1 * p[1] + u2 * p[2] for p in ring]      # _dot(u, p), inlined
        if all(h == t for h in heights) and _dot(_newell(ring), u) > 0:
            on_plane.extend(ring)       # a top face in the plane: the cap replaces it
            continue
        for i in range(n):
            p, q, hp, hq = ring[i], ring[(i + 1) % n], heights[i], heights[(i + 1) % n]
            if hp <= t:
                out.append(p)
                if hp == t:
                    on_plane.append(p)
            if (hp <= t) != (hq <= t):
                # from the point below to the point above, so that the two
                # faces sharing the edge compute the same point bit for bit
                a, b, ha, hb = (p, q, hp, hq) if hp <= t else (q, p, hq, hp)
                r = (t - ha) / (hb - ha)
                x = (a[0] + r * (b[0] - a[0]), a[1] + r * (b[1] - a[1]), a[2] + r * (b[2] - a[2]))
                out.append(x)
                on_plane.append(x)
        if len(out) >= 3:
            faces.append(tuple(out))
    return faces, on_plane


def _cap(on_plane, u, e1, e2, t):
    """The waterplane polygon, counter-clockwise seen from above, as 3-D points
    and as 2-D coordinates ``((p - t u) . e1, (p - t u) . e2)``."""
    o0, o1, o2 = (t * x for x in u)
    (f0, f1, f2), (g0, g1, g2) = e1, e2
    coords = {}
    for p in on_plane:          # _sub and _dot inlined
        d0, d1, d2 = p[0] - o0, p[1] - o1, p[2] - o2
        coords.setdefault((d0 * f0 + d1 * f1 + d2 * f2, d0 * g0 + d1 * g1 + d2 * g2), p)
    ring2 = hull_2d(list(coords))
    return [coords[q] for q in ring2], ring2


def _polygon_moments(ring2, zero):
    """Exact polygon integrals (Green's theorem, edge by edge, about the
    vertex mean ``m``): area ``A``, centroid and the central second moments
    ``Jxx = int x^2``, ``Jxy = int x y``, ``Jyy = int y^2`` with

    ``A = sum c / 2``, ``int x = sum (x_i + x_j) c / 6``,
    ``int x^2 = sum (x_i^2 + x_i x_j + x_j^2) c / 12``,
    ``int x y = sum (2 x_i y_i + x_i y_j + x_j y_i + 2 x_j y_j) c / 24``,
    ``c = x_i y_j - x_j y_i``."""
    n = len(ring2)
    if n < 3:
        return zero, None, None
    mx = sum(p[0] for p in ring2) / n
    my = sum(p[1] for p in ring2) / n
    pts = [(x - mx, y - my) for x, y in ring2]
    A = Sx = Sy = Sxx = Sxy = Syy = zero
    for i in range(n):
        (xi, yi), (xj, yj) = pts[i], pts[(i + 1) % n]
        c = xi * yj - xj * yi
        A += c
        Sx += (xi + xj) * c
        Sy += (yi + yj) * c
        Sxx += (xi * xi + xi * xj + xj * xj) * c
        Syy += (yi * yi + yi * yj + yj * yj) * c
        Sxy += (2 * xi * yi + xi * yj + xj * yi + 2 * xj * yj) * c
    A /= 2
    if A == 0:
        return A, None, None
    cx, cy = Sx / 6 / A, Sy / 6 / A
    J = ((Sxx / 12 - A * cx * cx, Sxy / 24 - A * cx * cy),
         (Sxy / 24 - A * cx * cy, Syy / 12 - A * cy * cy))
    return A, (cx + mx, cy + my), J


def _zero_like(values):
    """The zero of the richest arithmetic among *values*: SymPy, then mpmath, then FLINT's exact rationals
    (``fmpq``), then float; ints and Fractions give an exact Fraction.  Every coordinate is lifted into it: the vertex mean of Python ints divided by
    their count is a float (true division), and subtracting it made exact SymPy coordinates 15-digit Floats,
    the digits Scheeffer IV-V lost when it first used these moments (its rectangles have int coordinates)."""
    kinds = {type(v).__module__.split(".")[0] for v in values}
    if "sympy" in kinds:
        import sympy
        return sympy.Integer(0)
    if "mpmath" in kinds:
        return mpmath.mpf(0)
    if "flint" in kinds:
        from flint import fmpq
        return fmpq(0)
    if float in {type(v) for v in values}:
        return 0.0
    return Fraction(0)


def polygon_moments(points):
    """Area, centroid and central second moments ``((Jxx, Jxy), (Jxy, Jyy))`` of a counter-clockwise polygon
    ``[(x, y), ...]`` (the one implementation of polygon moments, :func:`_polygon_moments`), in the
    arithmetic of its coordinates: exact for ints, Fractions and SymPy numbers, else float64 or mpmath.

    >>> polygon_moments([(0, 0), (2, 0), (2, 1), (0, 1)])[::2]    # 2 x 1 rectangle: J = (8/12, 0; 0, 2/12)
    (Fraction(2, 1), ((Fraction(2, 3), Fraction(0, 1)), (Fraction(0, 1), Fraction(1, 6))))
    """
    ring = [tuple(p) for p in points]
    zero = _zero_like([c for p in ring for c in p])
    return _polygon_moments([(zero + x, zero + y) for x, y in ring], zero)


@functools.lru_cache(maxsize=64)
def body_volume_centroid(poly):
    """:func:`volume_centroid` of a whole body, kept for the bodies used last: every draught and floating
    state of a scene asks for it again (a polyhedron is immutable, its precision part of it)."""
    return volume_centroid(poly)


@_at_body_precision
def clip_below(poly, u, t):
    """The convex polyhedron ``{p in poly : u . p <= t}`` (``u`` normalised):
    every face clipped by Sutherland-Hodgman, plus the cap face, the
    waterplane polygon, with outward normal ``u``.  Empty when the plane
    lies below the body; the body itself when above it."""
    u = _unit(u, poly.dps)
    t = _num(t, poly.dps)
    faces, on_plane = _clip(poly.faces, u, t)
    e1, e2 = waterplane_basis(u, poly.dps)
    ring, ring2 = _cap(on_plane, u, e1, e2, t)
    if len(ring) >= 3:
        faces.append(tuple(ring))
    return Polyhedron(tuple(faces), poly.dps)


# -- submerged part and waterplane ------------------------------------------

@dataclass(frozen=True)
class Waterplane:
    """The waterplane polygon ``polygon`` (3-D points, counter-clockwise seen
    from above), its ``area`` and ``centroid`` (3-D), the orthonormal ``basis``
    ``(e1, e2)`` and ``tensor``, the central second moments
    ``[[int xi^2, int xi eta], [int xi eta, int eta^2]]`` in the coordinates
    ``xi, eta`` along ``e1, e2`` from the centroid.  The moment of inertia
    about the horizontal axis through the centroid along a unit ``w`` is
    ``n^T tensor n``, ``n`` the in-plane normal of ``w``; ``I_min`` and
    ``I_max`` are the eigenvalues of the tensor."""
    polygon: tuple
    area: object
    centroid: tuple | None
    basis: tuple
    tensor: tuple | None
    I_min: object
    I_max: object


@dataclass(frozen=True)
class Submerged:
    """Volume and centroid (the centre of buoyancy) of the part below the
    water plane, and the waterplane."""
    volume: object
    centroid: tuple | None
    waterplane: Waterplane


def _waterplane(ring, area, c2, J, u, t, basis, dps):
    """The :class:`Waterplane` of the cap *ring* (3-D points) with the moments *area*, *c2*, *J* of its plane
    coordinates along *basis* (:func:`_polygon_moments`)."""
    e1, e2 = basis
    if J is None:
        zero = _num(0, dps)
        return Waterplane(tuple(ring), area, None, basis, None, zero, zero)
    centroid = tuple(t * u[k] + c2[0] * e1[k] + c2[1] * e2[k] for k in range(3))
    mean = (J[0][0] + J[1][1]) / 2
    rad = _sqrt(((J[0][0] - J[1][1]) / 2) ** 2 + J[0][1] ** 2, dps)
    return Waterplane(tuple(ring), area, centroid, basis, J, mean - rad, mean + rad)


@_at_body_precision
def submerged(poly, u, t):
    """The part of *poly* below the plane ``u . p = t`` (``u`` normalised):
    its volume, its centroid ``B`` (:func:`volume_centroid` of
    :func:`clip_below`) and its :class:`Waterplane`.

    A float64 body is clipped by the C step (``_clipped.c``), an mpmath body in MPFR's numbers (as
    :func:`_in_mpfr` measures the draught's step): each gives the numbers of :func:`_submerged_part` in the
    body's own arithmetic bit for bit (tested).

    >>> sub = submerged(box(2, 2, 2), (0, 0, 1), 0)
    >>> sub.volume, sub.centroid, sub.waterplane.area
    (4.0, (0.0, 0.0, -0.5), 4.0)
    """
    u = _unit(u, poly.dps)
    t = _num(t, poly.dps)
    basis = waterplane_basis(u, poly.dps)
    if poly.dps is None and _compiled_submerged is not None:
        part = _compiled_submerged(*poly.packed, u[0], u[1], u[2], t, *basis)
    elif poly.dps is not None and _mpfr_serves(poly, (*u, t, *basis[0], *basis[1])):
        with _mpfr_context():
            part = _from_mpfr(_submerged_part(poly.in_mpfr(mpmath.mp.prec), *_to_mpfr((u, t, basis)), gmpy2.mpfr(0)))
    else:
        part = _submerged_part(poly.faces, u, t, basis, _num(0, poly.dps))
    volume, centroid, ring, area, c2, J = part
    return Submerged(volume, centroid, _waterplane(ring, area, c2, J, u, t, basis, poly.dps))


def _submerged_part(faces, u, t, basis, zero):
    """The submerged part of the body with face rings *faces* below ``u . p = t`` (*u* a unit vector, *basis* its
    :func:`waterplane_basis`), in the arithmetic of *zero*: its volume and centroid, the waterplane polygon
    (3-D points) and its area, centroid and central second moments in plane coordinates
    (:func:`_polygon_moments`)."""
    faces, on_plane = _clip(faces, u, t)
    ring, ring2 = _cap(on_plane, u, *basis, t)
    area, c2, J = _polygon_moments(ring2, zero)
    if len(ring) >= 3:
        faces.append(tuple(ring))
    return (*_volume_centroid(faces, zero), tuple(ring), area, c2, J)


def _volume_and_area(poly, u, t):
    """The volume below the plane ``u . p = t`` and the waterplane's area, by the divergence theorem over the
    clipped faces alone, measured from the point ``o = t u`` of the plane:

    ``V = sum_f (p_f - o) . N_f / 3``,  ``A = -u . sum_f N_f``,  ``N_f = sum_i (p_i - o) x (p_(i+1) - o) / 2``

    (``N_f`` the vector area of a clipped face ``f``, ``p_f`` any of its points).  The cap lies in the plane
    through ``o``, so it adds nothing to ``V``, and the closed surface's vector areas sum to zero, so its area
    ``A`` (normal ``u``) is minus the others' along ``u``.  No hull of the waterplane, no vertex mean: the
    draught's Newton steps need only these two numbers (:func:`draught`).

    A float64 body is measured by the C step (``_clipped.c``), an mpmath body in MPFR's numbers
    (:func:`_in_mpfr`): the same operations in the same order, each rounded as Python's floats and mpmath's
    numbers round it, so that each gives the same numbers bit for bit as the arithmetic of the body (tested)."""
    if poly.dps is None and _compiled_volume_and_area is not None:
        return _compiled_volume_and_area(*poly.packed, u[0], u[1], u[2], t)
    if poly.dps is not None:
        return _in_mpfr(poly, u, t)
    return _clipped_volume_and_area(poly.faces, u, t, 0.0)


def _clipped_volume_and_area(faces, u, t, zero):
    """:func:`_volume_and_area` of the body with face rings *faces*, in the arithmetic of its numbers."""
    faces, _ = _clip(faces, u, t)
    u0, u1, u2 = u
    o0, o1, o2 = t * u0, t * u1, t * u2
    volume = n0 = n1 = n2 = zero
    for ring in faces:          # _sub, _cross and _dot inlined
        x0, y0, z0 = ring[-1][0] - o0, ring[-1][1] - o1, ring[-1][2] - o2
        f0 = f1 = f2 = 0
        for p in ring:
            x1, y1, z1 = p[0] - o0, p[1] - o1, p[2] - o2
            f0 += y0 * z1 - z0 * y1
            f1 += z0 * x1 - x0 * z1
            f2 += x0 * y1 - y0 * x1
            x0, y0, z0 = x1, y1, z1
        volume += x0 * f0 + y0 * f1 + z0 * f2
        n0, n1, n2 = n0 + f0, n1 + f1, n2 + f2
    return volume / 6, -(u0 * n0 + u1 * n1 + u2 * n2) / 2


def _in_mpfr(poly, u, t):
    """:func:`_volume_and_area` of an mpmath body in MPFR's numbers (gmpy2) at mpmath's working precision, rounded
    to nearest: mpmath's sums, products and quotients are correctly rounded to nearest as MPFR's are, so the
    numbers are mpmath's, computed in C (the body converted once, :meth:`Polyhedron.in_mpfr`).  Where a number
    has more bits than the working precision (:func:`_mpfr_serves`), mpmath's numbers serve."""
    if not _mpfr_serves(poly, (*u, t)):
        return _clipped_volume_and_area(poly.faces, u, t, mpmath.mpf(0))
    with _mpfr_context():
        return _from_mpfr(_clipped_volume_and_area(poly.in_mpfr(mpmath.mp.prec), *_to_mpfr((u, t)), gmpy2.mpfr(0)))


def _mpfr_context():
    """MPFR's arithmetic at mpmath's working precision, rounded to nearest as mpmath rounds."""
    return gmpy2.context(precision=mpmath.mp.prec, round=gmpy2.RoundToNearest)


def _mpfr_serves(poly, numbers) -> bool:
    """Whether MPFR at mpmath's working precision gives mpmath's numbers for *poly* and *numbers*: the body made
    at this precision and no number wider than it (MPFR would round such a number on the way in, mpmath does
    not: the body made at other digits, an offset computed at more)."""
    prec = mpmath.mp.prec
    return prec == mpmath.libmp.dps_to_prec(poly.dps) and not any(
        x._mpf_[3] > prec for x in numbers if isinstance(x, mpmath.mpf))


def _to_mpfr(x):
    """An mpf (or a number mpmath takes) of at most the context's precision as an MPFR number, exactly; a
    tuple's numbers, and a tuple's tuples', likewise."""
    if isinstance(x, tuple):
        return tuple(_to_mpfr(v) for v in x)
    sign, man, exp, _ = mpmath.mpf(x)._mpf_
    value = gmpy2.mul_2exp(gmpy2.mpfr(man), exp)
    return -value if sign else value


def _from_mpfr(x):
    """An MPFR number as an mpf, exactly (at the precision it was computed at); a tuple's numbers, and a tuple's
    tuples', likewise (``None`` stays)."""
    if isinstance(x, tuple):
        return tuple(_from_mpfr(v) for v in x)
    if x is None:
        return None
    man, exp = x.as_mantissa_exp()
    return mpmath.mpf((int(man), int(exp)))


@_at_body_precision
def draught(poly, u, s, tol=None):
    """The offset ``t`` of the water plane ``u . p = t`` at which the submerged
    volume is ``s`` times the whole (``0 < s < 1``), and a bound ``err`` with
    ``V(t - err) <= s V <= V(t + err)`` as evaluated.

    ``V(t)`` increases with ``dV/dt`` = waterplane area, so Newton's method
    is run inside a bracket ``[lo, hi]`` (bisection whenever a step leaves
    it) and the result is certified by evaluating ``V`` at ``t +- tol/2``.
    The default *tol* is ``1e-13`` (float64) or ``10**(-dps + 3)`` times the
    height of the body along ``u``; evaluation rounding adds about
    ``1e-16 V / A`` (float64) to the true error.

    In mpmath Newton starts from the float64 draught of the same body (a
    float64 clipping costs a twentieth of a 40-digit one) and the bracket is
    tried as soon as the step is below ``1e-6 sqrt(tol h)`` (``h`` the height):
    Newton's next error, about ``(A'/2A) step^2``, is then far below
    ``tol/4``.  Four 40-digit clippings instead of five to twelve; where the
    bracket does not hold, the iteration goes on as before, so the result is
    certified in the same way.
    """
    dps = poly.dps
    u = _unit(u, dps)
    s = _num(s, dps)
    if not 0 < s < 1:
        raise ValueError("the density ratio s must lie strictly between 0 and 1")
    total = body_volume_centroid(poly)[0]
    target = s * total
    heights = [_dot(u, p) for p in poly.vertices]
    lo, hi = min(heights), max(heights)
    if tol is None:
        tol = (hi - lo) * (_num("1e-13", dps) if dps is None else mpmath.mpf(10) ** (3 - dps))
    tol = _num(tol, dps)
    t = lo + s * (hi - lo)
    near = tol / 4                                    # a Newton step this small has converged
    if dps is not None:
        near = max(near, _sqrt(tol * (hi - lo), dps) / 10 ** 6)
        start = _float_start(poly, u, s)
        if start is not None and lo < start < hi:
            t = mpmath.mpf(start)
    for _ in range(400):
        volume, area = _volume_and_area(poly, u, t)
        f = volume - target
        if f < 0:
            lo = t
        else:
            hi = t
        if hi - lo <= tol:
            break
        step = f / area if area > 0 else None
        if step is not None and abs(step) <= near:
            # Newton has converged: certify a bracket of width tol around it
            tn = t - step
            a, b = max(lo, tn - tol / 2), min(hi, tn + tol / 2)
            # V(lo) <= target <= V(hi) holds already: an end that is lo or hi is not evaluated again (in
            # float64 one of them always is, t itself, which lies within tol/4 of tn)
            if a != lo and _volume_and_area(poly, u, a)[0] <= target:
                lo = a
            if b != hi and _volume_and_area(poly, u, b)[0] >= target:
                hi = b
            if hi - lo <= tol:
                t = tn if lo <= tn <= hi else (lo + hi) / 2
                break
        tn = t - step if step is not None else None
        if tn is None or not lo < tn < hi:
            tn = (lo + hi) / 2
        if tn == t:
            break
        t = tn
    if not lo <= t <= hi:
        t = (lo + hi) / 2
    return t, max(t - lo, hi - t)


def _float_start(poly, u, s):
    """The float64 draught of an mpmath body (its vertices rounded), a start for its Newton steps; ``None``
    where float64 cannot give one (a number beyond its range, a degenerate body)."""
    try:
        body = Polyhedron(tuple(tuple(tuple(float(c) for c in p) for p in ring) for ring in poly.faces), None)
        start = draught(body, tuple(float(x) for x in u), float(s))[0]
    except (ValueError, OverflowError, ZeroDivisionError):
        return None
    return start if math.isfinite(start) else None


# -- the floating state -----------------------------------------------------

@dataclass(frozen=True)
class FloatingState:
    """A homogeneous body floating at density ratio ``s`` with ``u`` up:

    ``t`` and ``t_err`` (water plane ``u . p = t``, :func:`draught`),
    ``volume`` submerged, ``B`` centre of buoyancy, ``G`` centre of gravity,
    ``waterplane_area``, ``waterplane_centroid``, ``tensor`` and ``basis`` (see
    :class:`Waterplane`), ``I_min``, ``I_max``,
    ``potential = u . (G - B)`` (height of G above B) and
    ``metacentric_height = I_min / volume - u . (G - B)``, computed from the
    clipped waterplane; positive means stable against every small tilt.
    """
    u: tuple
    s: object
    t: object
    t_err: object
    volume: object
    B: tuple
    G: tuple
    waterplane_area: object
    waterplane_centroid: tuple
    tensor: tuple
    basis: tuple
    I_min: object
    I_max: object
    potential: object
    metacentric_height: object


@_at_body_precision
def floating_state(poly, u, s, tol=None, G=None):
    """The :class:`FloatingState` of *poly* with *u* up at density ratio *s*.
    ``G`` defaults to the centroid of the body (homogeneous body).

    >>> st = floating_state(box(2, 1, 1), (0, 0, 1), 0.5)
    >>> round(st.metacentric_height, 12)    # (2 * 1**3 / 12) / 1 - 1/4
    -0.083333333333
    """
    u = _unit(u, poly.dps)
    t, err = draught(poly, u, s, tol)
    sub = submerged(poly, u, t)
    G = body_volume_centroid(poly)[1] if G is None else tuple(_num(x, poly.dps) for x in G)
    wp = sub.waterplane
    potential = _dot(u, _sub(G, sub.centroid))
    return FloatingState(u, _num(s, poly.dps), t, err, sub.volume, sub.centroid, G, wp.area, wp.centroid,
                         wp.tensor, wp.basis, wp.I_min, wp.I_max, potential,
                         wp.I_min / sub.volume - potential)


# -- the circular cylinder ------------------------------------------------

@dataclass(frozen=True)
class CylinderState:
    """Richardson-extrapolated quantities of a floating circular cylinder,
    each ``(value, error)``; ``coarse`` and ``fine`` are the phase-averaged
    polygonal values with ``n`` and ``2n`` sides, as :class:`FloatingState`."""
    t: tuple
    volume: tuple
    B: tuple
    waterplane_area: tuple
    tensor: tuple
    I_min: tuple
    I_max: tuple
    metacentric_height: tuple
    coarse: FloatingState
    fine: FloatingState


_AVERAGED = ("t", "t_err", "volume", "B", "G", "waterplane_area", "waterplane_centroid", "tensor",
             "I_min", "I_max", "potential", "metacentric_height")


def _mean(values):
    """Componentwise mean of equal-shaped scalars, vectors or 2x2 tensors."""
    first = values[0]
    if isinstance(first, tuple):
        return tuple(_mean([v[i] for v in values]) for i in range(len(first)))
    return sum(values) / len(values)


def _richardson(a, b):
    """``(b + (b - a) / 3, |b - a|)`` componentwise."""
    if isinstance(a, tuple):
        pairs = [_richardson(x, y) for x, y in zip(a, b)]
        return tuple(p[0] for p in pairs), tuple(p[1] for p in pairs)
    return b + (b - a) / 3, abs(b - a)


def cylinder_state(r, length, u, s, sides=128, phases=3, dps=None):
    """A circular cylinder of radius *r*, axis ``z``, centre at the origin,
    floating with *u* up at density ratio *s*, as the limit of inscribed
    regular prisms with ``n = sides`` and ``2n`` sides.

    The error of an ``n``-gon is ``c / n^2`` plus, where the water line cuts
    the edges (a heeled cylinder), a term of the same order that oscillates
    with the position of the cut inside an edge and spoils plain Richardson
    extrapolation.  The cylinder is symmetric under rotation about its axis,
    so each ``n``-gon state is averaged over ``phases`` rotations of the
    polygon by ``j / phases`` of an edge angle, which leaves a smooth
    ``c' / n^2``; then each quantity ``q`` is extrapolated as
    ``q_2n + (q_2n - q_n) / 3`` and its stated error is ``|q_2n - q_n|``.
    In the cases tested (horizontal and upright cylinders, ``n = 32 .. 256``,
    several heels and densities) the true error of the extrapolated value
    and of ``q_2n`` stayed below half the stated error; for lengths the
    stated error is of order ``(2 pi / n)^2 r``.  The error of the
    arithmetic (module docstring) is far smaller.

    >>> cs = cylinder_state(1, 2, (0, 0, 1), 0.5, sides=64)   # upright
    >>> value, error = cs.waterplane_area
    >>> abs(value - 3.141592653589793) < error < 1e-2
    True
    """
    if sides < 3 or phases < 1:
        raise ValueError("the cylinder needs sides >= 3 and phases >= 1")
    with _precision(dps):
        R = _num(r, dps)
        pi = math.pi if dps is None else mpmath.pi
        averaged = []
        for n in (sides, 2 * sides):
            states = []
            for j in range(phases):
                turn = 2 * pi * j / (n * phases)
                cos, sin = (math.cos(turn), math.sin(turn)) if dps is None else (mpmath.cos(turn), mpmath.sin(turn))
                polygon = [(x * cos - y * sin, x * sin + y * cos) for x, y in _regular_polygon(n, R, dps)]
                states.append(floating_state(right_prism(polygon, length, dps), u, s))
            fields = {f: _mean([getattr(st, f) for st in states]) for f in _AVERAGED}
            averaged.append(FloatingState(u=states[0].u, s=states[0].s, basis=states[0].basis, **fields))
        lo, hi = averaged
        rich = {f: _richardson(getattr(lo, f), getattr(hi, f))
                for f in ("t", "volume", "B", "waterplane_area", "tensor", "I_min", "I_max", "metacentric_height")}
        return CylinderState(coarse=lo, fine=hi, **rich)
