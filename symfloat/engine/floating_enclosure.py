"""A floating prism in ball arithmetic: the certified method of the floating witnesses (issue 29).

The body is a right prism (a box, a prism over a polygon, a regular prism) with **exact** dimensions, its vertices
exact triples (:class:`fractions.Fraction`, or SymPy numbers where a dimension is irrational: ``sqrt(2)/2``,
``cos(2 pi/7)``, each a ball at the working precision); the up vector ``w`` and the density ratio ``s`` are balls (exact where
they are rational).  The water plane is ``w . p = tau`` with ``w`` not normalised, so that a vertex's height
``w . p`` is exact for a rational ``w``.

**Clipping with proven sides.**  Every face is clipped by Sutherland–Hodgman against ``w . p <= tau``; a
vertex lies **provably** below or above the plane where its height's ball and ``tau``'s are apart.  Given the
sides, the clipped body's vertices are rational functions of ``tau`` and the data, the same for every point of
the balls, so ball arithmetic encloses every quantity.  A vertex whose height's ball meets ``tau``'s (the plane
through a vertex: a threshold, a cut through a corner) may lie on either side: each assignment of those
vertices is taken and the states' balls joined (:func:`_assignments`); the true one is among them, and at a
vertex on the plane both give its value.  A vertex exactly on the plane (exact height, exact offset) is one
case, not two.  Each
edge's crossing is computed once (from its lower end), the cap polygon is chained from the clipped faces (each
face's exit and entry crossing, the cap traversing that edge the other way), so that no comparison of clipped
points is made.

**Volumes and moments** by the divergence theorem over fan triangles from the body's vertex mean (exact),
``V = sum det(a - c, b - c, d - c) / 6`` and the centroid ``c + sum V_k (a + b + d - 3c) / 4 / V``;
**the waterplane** by :func:`symfloat.geometry.floating._polygon_moments` (Green's theorem) in the orthonormal
basis of :func:`basis` (``e1`` the axis least aligned with ``u``, as the float geometry chooses it).

**The draught** ``tau``: Newton's steps ``tau <- mid(tau - (V(tau) - s V) / (A / |w|))`` at exact dyadic points
from the float64 draught (``dV/dtau`` is the waterplane area over ``|w|``), then a bracket ``[tau - d, tau + d]``
with ``d`` about ``2^-bits`` of the body's size (the arithmetic :data:`GUARD_BITS` finer), **proven** by the
signs of ``V - s V`` at its ends (``V`` grows with ``tau``: the intermediate value theorem); a bracket whose signs
are not proven gives :class:`Ambiguous`.

>>> from fractions import Fraction as F
>>> from flint import arb
>>> body = prism_body([(F(-1, 2), F(-1, 2)), (F(1, 2), F(-1, 2)), (F(1, 2), F(1, 2)), (F(-1, 2), F(1, 2))], F(1))
>>> with working_precision(128 + GUARD_BITS):              # the density 1/3 as fine as the state asks
...     st = floating_state(body, (arb(0), arb(0), arb(1)), arb(1) / 3, 128)
...     (st.t + arb(1) / 6).abs_upper() < arb(2) ** -100     # the unit cube at s = 1/3: t = -1/2 + 1/3
True
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field, fields, replace
from fractions import Fraction
from functools import lru_cache

import sympy as sp
from flint import arb, ctx
from sympy.utilities.iterables import flatten

from ..geometry.floating import _polygon_moments, draught as float_draught, right_prism
from .enclosure import Unsupported, ball, exact, sign_change_root, working_precision
from .measured import Measured, measured_names

__all__ = ["Ambiguous", "BallBody", "BallState", "prism_body", "floating_state", "clipped", "basis", "ball_body",
           "quantity_balls", "closed_ball", "enclosed_values", "missing_method"]

GUARD_BITS = 32        # the state is computed with these bits more than its draught's bracket is wide
NEWTON_STEPS = 12      # from float64 (about 50 bits) to 1024 bits takes 5 quadratic steps; the rest is margin


class Unrealisable(ValueError):
    """An assignment of sides to the vertices that no plane makes (a face cut twice, a water line in two
    pieces): left out of the join (:func:`_assignments`)."""


class Ambiguous(ValueError):
    """The water plane may pass through a vertex of the body within the enclosure (or a bracket's signs are not
    proven): no enclosure at this precision."""


@dataclass(frozen=True)
class BallBody:
    """A convex polyhedron with exact vertices: ``faces`` rings of vertex indices (counter-clockwise seen from
    outside), ``exact`` the vertices as exact triples (:func:`coordinate`), ``G`` its centre of gravity (balls,
    or ``None``: the centroid); ``at`` the balls of the symbols its vertices name (a root that sets a dimension:
    ``((Q, ball),)``)."""

    faces: tuple
    exact: tuple
    G: tuple = None
    at: tuple = ()
    _balls: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    def points(self) -> tuple:
        """The vertices as balls at the working precision (made once per precision: a state asks for them at
        every step of its draught)."""
        balls = self._balls.get(ctx.prec)
        if balls is None:
            balls = self._balls[ctx.prec] = tuple(tuple(coordinate(c, self.at) for c in p) for p in self.exact)
        return balls


def coordinate(x, at=()) -> arb:
    """An exact coordinate as a ball at the working precision: a rational exactly (radius 0 where dyadic), an
    irrational SymPy number (``sqrt(3)/2``, ``cos(2 pi/7)``) enclosed by :func:`~symfloat.engine.enclosure.ball`,
    an expression in the symbols of *at* (pairs symbol, ball) at their balls."""
    if isinstance(x, (int, Fraction, sp.Rational)):
        return exact(x)
    if x.free_symbols:
        return ball(x, ctx.prec, dict(at))
    return _irrational(x, ctx.prec)


@lru_cache(maxsize=4096)
def _irrational(x, prec):
    return ball(x, prec)


def prism_body(polygon, length, G=None, at=()) -> BallBody:
    """The right prism over the convex counter-clockwise *polygon* (pairs of exact numbers: Fractions, or SymPy
    numbers throughout, which may name the symbols of *at*), axis ``z`` from ``-length/2`` to ``length/2``: the
    faces of :func:`symfloat.geometry.floating.right_prism`, exact, its ``n`` lower vertices first."""
    n = len(polygon)
    h = length / 2 if isinstance(length, sp.Expr) else Fraction(length) / 2
    exact_points = tuple((x if isinstance(x, sp.Expr) else Fraction(x), y if isinstance(y, sp.Expr) else Fraction(y), z)
                         for z in (-h, h) for x, y in polygon)
    bottom = tuple(reversed(range(n)))
    top = tuple(n + i for i in range(n))
    sides = tuple((i, (i + 1) % n, n + (i + 1) % n, n + i) for i in range(n))
    return BallBody((bottom, top) + sides, exact_points, G, tuple(at))


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _mean(points):
    return tuple(sum(p[k] for p in points) / len(points) for k in range(3))


def _volume_moment(rings, c, moments=True):
    """Volume and first moment about *c* (``sum V_k (a + b + d - 3c) / 4``; ``None`` without *moments*: the
    draught's steps and bracket need the volume alone) of the closed polyhedron whose faces are *rings* of ball
    points."""
    volume, moment = arb(0), [arb(0)] * 3
    for ring in rings:
        a = tuple(ring[0][k] - c[k] for k in range(3))
        for b, d in zip(ring[1:], ring[2:]):
            b = tuple(b[k] - c[k] for k in range(3))
            d = tuple(d[k] - c[k] for k in range(3))
            v = (a[0] * (b[1] * d[2] - b[2] * d[1]) + a[1] * (b[2] * d[0] - b[0] * d[2])
                 + a[2] * (b[0] * d[1] - b[1] * d[0])) / 6
            volume += v
            if moments:
                moment = [moment[k] + v * (a[k] + b[k] + d[k]) / 4 for k in range(3)]
    return volume, moment if moments else None


MAX_OPEN = 6          # vertices that may lie on either side of the plane: at most 2^6 assignments are joined


def _assignments(body, w, tau):
    """The sides (-1 below, 1 above) that the vertices may have.  A vertex exactly on the plane (its height and
    *tau* exact and equal) counts as above: the edges from below reach it, so it is a corner of the cap.  Each
    vertex whose height's ball meets *tau*'s otherwise may lie either way, vertices of one height together
    (:func:`_same_height`; at most :data:`MAX_OPEN` such groups, else :class:`Ambiguous`); an assignment with no
    vertex below or none above is left out (a floating body, ``0 < s < 1``, has both)."""
    fixed, free = [], []
    for i, p in enumerate(body.points()):
        h = _dot(w, p)
        fixed.append(-1 if h < tau else 1 if h > tau or h == tau else None)      # ==: two exact equal numbers
        if fixed[-1] is None:
            group = next((g for g in free if _same_height(w, body.exact[g[0]], body.exact[i], body.at)), None)
            if group is None:
                free.append([i])
            else:
                group.append(i)
    if len(free) > MAX_OPEN:
        raise Ambiguous(f"the water plane may pass through {len(free)} vertices within the enclosure")
    out = []
    for choice in itertools.product((-1, 1), repeat=len(free)):
        sides = list(fixed)
        for group, x in zip(free, choice):
            for i in group:
                sides[i] = x
        if -1 in sides and 1 in sides:
            out.append(sides)
    return out


def _same_height(w, p, q, at=()) -> bool:
    """Whether the vertices *p* and *q* (exact triples) have the same height ``w . p = w . q`` for every up
    vector in the balls *w*: ``w . (p - q)``, the difference taken exactly, is an exact 0 (radius 0), which
    ball arithmetic gives only where each term is exact, a component of *w* with a radius multiplied by an
    exact 0 (the two ends of an edge along the tilt axis, ``w = (sin phi, cos phi, 0)``, at the tilt where
    they reach the water together).  Split between the two sides, such a pair would be a plane's cut between
    two points of one height, and the crossing on their edge a division by a ball that holds 0."""
    d = _dot(w, tuple(coordinate(p[k] - q[k], at) for k in range(3)))
    return d.rad() == 0 and d.mid() == 0


def clipped(body, w, tau, side):
    """The faces (rings of ball points) of the part of *body* below ``w . p = tau`` and the cap polygon (the
    waterplane, counter-clockwise seen from above), the vertices on the sides *side* (:func:`_assignments`)."""
    points = body.points()
    heights = [_dot(w, p) for p in points]
    crossing = {}

    def cross(i, j):
        lo, hi = (i, j) if side[i] < 0 else (j, i)
        if (lo, hi) not in crossing:
            r = (tau - heights[lo]) / (heights[hi] - heights[lo])
            crossing[lo, hi] = tuple(points[lo][k] + r * (points[hi][k] - points[lo][k]) for k in range(3))
        return (lo, hi)

    faces, cap_next = [], {}
    for ring in body.faces:
        out, entry, exit_ = [], None, None
        for i, j in zip(ring, ring[1:] + ring[:1]):
            if side[i] < 0:
                out.append(points[i])
            if side[i] != side[j]:
                key = cross(i, j)
                out.append(crossing[key])
                if (exit_ if side[i] < 0 else entry) is not None:
                    raise Unrealisable("a plane meets a convex face's boundary twice at most")
                if side[i] < 0:
                    exit_ = key
                else:
                    entry = key
        if exit_ is not None:
            cap_next[entry] = exit_            # the cap runs each cut face's water line backwards
        if len(out) >= 3:
            faces.append(tuple(out))
    cap = []
    if cap_next:
        start = key = next(iter(cap_next))
        while len(cap) <= len(cap_next):
            cap.append(crossing[key])
            key = cap_next.get(key)
            if key == start:
                break
        if key != start or len(cap) != len(cap_next):
            raise Unrealisable("the water line of a convex body is one polygon")
    return faces, cap


def basis(u):
    """An orthonormal basis ``(e1, e2)`` of the plane normal to the unit ball vector *u*, ``e1 x e2 = u``:
    ``e1`` the coordinate axis least aligned with ``u`` (by the balls' midpoints) made orthogonal to it."""
    k = min(range(3), key=lambda i: abs(u[i].mid()))
    e1 = [-u[k] * u[i] for i in range(3)]
    e1[k] += 1
    norm = _dot(e1, e1).sqrt()
    e1 = tuple(x / norm for x in e1)
    return e1, (u[1] * e1[2] - u[2] * e1[1], u[2] * e1[0] - u[0] * e1[2], u[0] * e1[1] - u[1] * e1[0])


@dataclass(frozen=True)
class BallState:
    """The floating state in balls, the fields of :class:`symfloat.geometry.floating.FloatingState` that the
    witness reads: ``u`` unit up, ``t`` the water plane ``u . p = t``, ``volume``, ``B``, ``G``,
    ``waterplane_area``, ``waterplane_centroid``, ``tensor`` (in ``basis``), ``I_min``, ``I_max``,
    ``potential`` = u . (G - B), ``metacentric_height`` = I_min / volume - potential; ``vertices`` the body's
    (balls) and ``exact`` (Fractions); ``corners`` the number of the waterplane's corners, where the water plane
    is proven to pass through no vertex (each edge it crosses is then one corner), else ``None``."""

    u: tuple
    t: arb
    volume: arb
    B: tuple
    G: tuple
    waterplane_area: arb
    waterplane_centroid: tuple
    tensor: tuple
    basis: tuple
    I_min: arb
    I_max: arb
    potential: arb
    metacentric_height: arb
    vertices: tuple
    exact: tuple
    corners: int | None = None


def _volume_below(body, w, tau, c, side, moments=True):
    faces, cap = clipped(body, w, tau, side)
    if len(cap) >= 3:
        faces.append(tuple(cap))
    return _volume_moment(faces, c, moments), cap


def _area(cap, u):
    """The area of the cap polygon (its vector area along *u*)."""
    n = len(cap)
    total = [arb(0)] * 3
    for i in range(n):
        p, q = cap[i], cap[(i + 1) % n]
        total = [total[0] + p[1] * q[2] - p[2] * q[1], total[1] + p[2] * q[0] - p[0] * q[2],
                 total[2] + p[0] * q[1] - p[1] * q[0]]
    return _dot(total, u) / 2


def _draught(body, w, norm, s, whole, c, bits):
    """The offset ``tau`` of the water plane ``w . p = tau`` with ``V(tau) = s V`` as a proven bracket (see the
    module)."""
    points = body.points()
    n = len(points) // 2                                 # prism_body's lower vertices first
    polygon = [(float(p[0].mid()), float(p[1].mid())) for p in points[:n]]
    length = float((points[n][2] - points[0][2]).mid())
    u_float = tuple(float(x.mid()) for x in w)
    t0, _ = float_draught(right_prism(polygon, length), u_float, float(s.mid()))
    target = s * whole
    heights = [_dot(w, p) for p in points]
    size = max(abs(float(h.mid())) for h in heights) + 1
    tau = arb(t0) * norm
    tau = arb(tau.mid())
    step = arb(2) ** (4 - bits) * size
    for _ in range(NEWTON_STEPS):
        (volume, _), cap = _realised(lambda side: _volume_below(body, w, tau, c, side, moments=False),
                                     _assignments(body, w, tau))[0]
        area = _area(cap, w) / norm                      # dV/dtau = A / |w|
        nxt = arb((tau - (volume - target) / (area / norm)).mid())
        done = (nxt - tau).abs_upper() < step / 4
        tau = nxt
        if done:
            break
    for widen in range(0, bits // 2 - 8, 8):             # the data's own balls may need a wider bracket
        lo, hi = tau - step * 2 ** widen, tau + step * 2 ** widen
        if _volume_at(body, w, lo, c) < target and _volume_at(body, w, hi, c) > target:
            return lo.union(hi)
    raise Ambiguous(f"the draught's bracket is not proven at {bits} bits")


def _volume_at(body, w, tau, c):
    """The volume below ``w . p = tau``, joined over the assignments of the vertices on the plane."""
    return _joined(_realised(lambda side: _volume_below(body, w, tau, c, side, moments=False)[0][0],
                             _assignments(body, w, tau)))


def _realised(f, assignments):
    """``f(side)`` for each assignment that a plane can make (:class:`Unrealisable` ones left out)."""
    out = []
    for side in assignments:
        try:
            out.append(f(side))
        except Unrealisable:
            continue
    if not out:
        raise Ambiguous("no assignment of the vertices on the plane is realised by a plane")
    return out


def _root_of_square_sum(x):
    """The square root of *x*, a ball of a sum of squares (never negative): where the ball reaches below 0 (a
    square waterplane, its two moments equal) the root lies in ``[0, sqrt(upper)]``."""
    return x.sqrt() if x > 0 else arb(0).union(x.upper().sqrt())


def _joined(values):
    """The union of balls (componentwise for tuples)."""
    if isinstance(values[0], tuple):
        return tuple(_joined(list(v)) for v in zip(*values))
    out = values[0]
    for v in values[1:]:
        out = out.union(v)
    return out


def floating_state(body, up, s, bits) -> BallState:
    """The :class:`BallState` of *body* (a :class:`BallBody`) with *up* (balls, not necessarily unit) up at the
    density ratio *s* (a ball, ``0 < s < 1``; both computed with :data:`GUARD_BITS` more than *bits*), the
    draught's bracket about ``2^-bits`` of the body's size wide: the union of the states on the pieces of the
    bracket for each assignment of the vertices the plane may pass through (:func:`_assignments`)."""
    with working_precision(bits + GUARD_BITS):
        w = tuple(up)
        norm = _dot(w, w).sqrt()
        points = body.points()
        c = _mean(points)
        faces = [tuple(points[i] for i in ring) for ring in body.faces]
        whole, moment = _volume_moment(faces, c)
        G = tuple(c[k] + moment[k] / whole for k in range(3)) if body.G is None else tuple(body.G)
        tau = _draught(body, w, norm, s, whole, c, bits)
        states = _realised(lambda side: _state(body, w, norm, tau, side, c, G, points), _assignments(body, w, tau))
        apart = all(h < tau or h > tau for h in (_dot(w, p) for p in points))   # no vertex on the plane
        names = [f.name for f in fields(BallState) if f.name != "corners"]
        return BallState(**{name: _joined([getattr(st, name) for st in states]) if name not in ("vertices", "exact")
                            else getattr(states[0], name) for name in names},
                         corners=states[0].corners if apart and len(states) == 1 else None)


def _state(body, w, norm, tau, side, c, G, points):
    """The floating state with the water plane ``w . p = tau``, the vertices on the sides *side*."""
    u = tuple(x / norm for x in w)
    (volume, moment), cap = _volume_below(body, w, tau, c, side)
    B = tuple(c[k] + moment[k] / volume for k in range(3))
    t = tau / norm
    e1, e2 = basis(u)
    o = tuple(t * x for x in u)
    ring2 = [(_dot([p[k] - o[k] for k in range(3)], e1), _dot([p[k] - o[k] for k in range(3)], e2))
             for p in cap]
    area, centre, J = _polygon_moments(ring2, arb(0))
    if J is None:
        raise Ambiguous("the waterplane is degenerate (fewer than three corners, or no area)")
    cx, cy = centre
    centroid = tuple(o[k] + cx * e1[k] + cy * e2[k] for k in range(3))
    mean = (J[0][0] + J[1][1]) / 2
    half = (J[0][0] - J[1][1]) / 2
    rad = _root_of_square_sum(half * half + J[0][1] * J[0][1])
    potential = _dot(u, tuple(G[k] - B[k] for k in range(3)))
    I_min = mean - rad
    return BallState(u, t, volume, B, G, area, centroid, J, (e1, e2), I_min, mean + rad, potential,
                     I_min / volume - potential, tuple(points), body.exact, len(cap))


# ---- the floating witnesses' certified method: their quantities at a case as balls ----------------------------
# Read off a BallState as the float geometry's FloatingState is read (QUANTITIES), except those taking an extreme
# over vertices, which take it in ball arithmetic (arb min/max: no comparison of two balls decides).

def _heights(st, base=0):
    """``u . p - t`` of the vertices as balls: all, or (*base* 1 or -1) those of the base on that side of z (the
    body centred: a vertex's z is proven positive or negative)."""
    if base and not all(p[2] > 0 or p[2] < 0 for p in st.vertices):
        raise Ambiguous("a vertex's base is not proven (its z holds 0)")
    return [_dot(st.u, p) - st.t for p in st.vertices if base == 0 or (p[2] > 0 if base > 0 else p[2] < 0)]


def _corners(st):
    """The number of the waterplane's corners, exact: where the water plane is proven to pass through no vertex."""
    if st.corners is None:
        raise Ambiguous("the water plane may pass through a vertex: its corners are not counted")
    return arb(st.corners)


def _least(values):
    out = values[0]
    for v in values[1:]:
        out = out.min(v)
    return out


def _greatest(values):
    return -_least([-v for v in values])


EXTREMES = {
    "draught": lambda st: -_least(_heights(st)),
    "top clearance": lambda st: _least(_heights(st, 1)),
    "upper base above water": lambda st: _least(_heights(st, 1)),
    "bottom clearance": lambda st: -_greatest(_heights(st, -1)),
    "lower base above water": lambda st: _greatest(_heights(st, -1)),
    "face clearance": lambda st: EXTREMES["top clearance"](st).min(EXTREMES["bottom clearance"](st)),
    "freeboard": lambda st: _greatest(_heights(st)),
    "stability sign": lambda st: _sign(st.metacentric_height),
    "waterplane corners": lambda st: _corners(st),
    "stable": lambda st: (1 + _sign(st.metacentric_height)) / 2,
}


def _sign(x):
    """1 or -1, the proven sign of the ball *x*; :class:`Ambiguous` where it holds 0."""
    if x > 0:
        return arb(1)
    if x < 0:
        return arb(-1)
    raise Ambiguous("the sign of the metacentric height is not proven (its ball holds 0)")
# the quantities of QUANTITIES read off the state's fields alone (sums and products of balls)
FIELDS = ("immersed volume", "G above water", "B below water", "G above B", "waterplane area", "I min", "I max",
          "metacentric radius", "metacentric height", "water level", *(f"B - G, {a}" for a in "xyz"),
          *(f"waterplane centroid, {a}" for a in "xyz"),
          *(f"waterplane {kind}, {'xyz'[i]}{'xyz'[j]}" for kind in ("tensor", "moment")
            for i in range(3) for j in range(i, 3)))


def ball_body(body, params, extra=None):
    """*body* (a :class:`~symfloat.engine.floating_witness.Body` box, prism or regular prism, a ``Loaded`` or a
    ``Marked`` one: its direction is read by the split parts alone, which have no ball method) at the exact
    *params* and the balls *extra* (symbol -> arb: a root that sets a dimension, overriding the case's value) as a
    :class:`BallBody`, its vertices exact (Fractions, or SymPy numbers throughout where a dimension or a
    regular polygon's corner is irrational or names a root of *extra*); ``None`` where a dimension is fixed by
    neither or the body is of another kind (a cylinder)."""
    from .floating_witness import Body, Loaded, Marked
    if type(body) not in (Body, Loaded, Marked) or body.kind not in ("box", "prism", "regular"):
        return None
    extra = extra or {}
    known = {k: v for k, v in params.items() if k not in extra}
    at = lambda e: sp.sympify(e).xreplace(known)      # noqa: E731
    if body.kind == "box":
        a, b, c = (at(x) for x in body.dims)
        polygon, length = [(-a / 2, -b / 2), (a / 2, -b / 2), (a / 2, b / 2), (-a / 2, b / 2)], c
    elif body.kind == "prism":
        polygon, length = [(at(x), at(y)) for x, y in body.dims[0]], at(body.dims[1])
    else:               # the corners of geometry.floating.regular_prism: circumradius side / (2 sin(pi/n))
        n, side, length = body.dims
        radius = at(side) / (2 * sp.sin(sp.pi / n))
        polygon, length = [(radius * sp.cos(2 * sp.pi * k / n), radius * sp.sin(2 * sp.pi * k / n))
                           for k in range(n)], at(length)
    values = [length, *(x for p in polygon for x in p)]
    named = set().union(*(v.free_symbols for v in values))
    if not named <= set(extra) or not all(v.is_real is not False for v in values):
        return None
    if all(v.is_Rational for v in values):
        rational = lambda v: Fraction(int(v.p), int(v.q))      # noqa: E731
        polygon, length = [(rational(x), rational(y)) for x, y in polygon], rational(length)
    return prism_body(polygon, length, getattr(body, "G", None), tuple((k, extra[k]) for k in sorted(named, key=str)))


def closed_ball(expr, params, extra, bits):
    """*expr* at the exact *params* and the balls *extra* (symbol -> arb: a root, which overrides the case's
    value of its symbol), as a ball at *bits* bits."""
    e = sp.sympify(expr).xreplace({k: v for k, v in params.items() if k not in extra})
    return ball(e, bits, {s: extra[s] for s in e.free_symbols if s in extra})


def quantity_balls(witness, params, extra, body, bits):
    """The quantities of the floating *witness* (its ``quantity``, one or a tuple) of *body* at *params*
    (exact) and *extra* (balls), as a tuple of balls; ``None`` where a quantity or the body has no rigorous
    method here (a tilt's wedges, a limit, a sign, a count, a split part); a cylinder's state is
    :func:`symfloat.engine.cylinder_enclosure.cylinder_state`; :class:`Ambiguous` where the enclosure cannot be
    had at *bits*."""
    if witness.limit is not None or witness.reference is not None or getattr(witness, "series", None) is not None:
        return None
    items = (witness.quantity,) if isinstance(witness.quantity, sp.Expr) else tuple(witness.quantity)
    names = {n for q in items for n in measured_names(q)}
    if not names <= set(FIELDS) | set(EXTREMES):
        return None
    fine = bits + GUARD_BITS
    if body.kind == "cylinder":
        st = _cylinder(witness, params, extra, body, bits)
        if st is None:
            return None
        return _read_state(witness, st, items, names, params, extra, fine)
    exact_body = ball_body(body, params, extra)
    if exact_body is None:
        return None
    if exact_body.G is not None:
        exact_body = replace(exact_body, G=tuple(closed_ball(x, params, extra, fine) for x in exact_body.G))
    up = tuple(closed_ball(x, params, extra, fine) for x in _rational_direction(witness.up, params, extra))
    density = _density(witness, params, extra, exact_body, up, fine)
    st = floating_state(exact_body, up, density, bits)
    return _read_state(witness, st, items, names, params, extra, fine)


def _cylinder(witness, params, extra, body, bits):
    """The :class:`BallState` of a cylinder witness's body (radius a ball, possibly a root's; length exact),
    or ``None`` where its length is not rational at *params* or the body is a ``Loaded`` or ``Marked`` one."""
    from .cylinder_enclosure import cylinder_state
    from .floating_witness import Body
    if type(body) is not Body:
        return None
    fine = bits + GUARD_BITS
    length = sp.sympify(body.dims[1]).xreplace(params)
    if not length.is_Rational:
        return None
    radius = closed_ball(body.dims[0], params, extra, fine)
    up = tuple(closed_ball(x, params, extra, fine) for x in _rational_direction(witness.up, params, extra))
    density = closed_ball(witness.density, params, extra, fine)
    return cylinder_state(radius, Fraction(int(length.p), int(length.q)), up, density, bits)


def _read_state(witness, st, items, names, params, extra, fine):
    """The witness's quantities *items* (the measured *names* among them) read off the ball state *st*."""
    from .floating_witness import QUANTITIES
    with working_precision(fine):
        read = {n: (EXTREMES[n](st) if n in EXTREMES else QUANTITIES[n][1](st, None)) for n in names}
        return tuple(read[q.name] if isinstance(q, Measured) else
                     closed_ball(q, params, {**extra, **{Measured(n): v for n, v in read.items()}}, fine)
                     for q in items)


def _rational_direction(up, params, extra):
    """*up* scaled by a positive number to rational components where it can be ((sin 45°, cos 45°, 0) is
    (1, 1, 0)): the vertices' heights are then exact, and a plane through a vertex an exact tie, not an
    ambiguity.  Unchanged where a component depends on a root's ball or a ratio is irrational."""
    values = [sp.sympify(x).xreplace(params) for x in up]
    if any(v.free_symbols for v in values):
        return up
    ref = next((v for v in values if v != 0), None)
    if ref is None or ref.is_Rational or ref.is_positive is not True and ref.is_negative is not True:
        return up
    if not all(_near_simple_fraction(float(v / abs(ref))) for v in values):
        return up       # not worth SymPy's simplification (seconds at a nested search's exact trial values)
    ratios = [sp.nsimplify(sp.simplify(v / abs(ref))) if v != 0 else sp.Integer(0) for v in values]
    return tuple(ratios) if all(r.is_Rational for r in ratios) else up


def _near_simple_fraction(x: float) -> bool:
    """Whether *x* lies within 1e-12 of a fraction of denominator at most 1000: a ratio that may be rational, as
    the tilts of the sources are (1, tan 30° = 1/sqrt 3 over cos 30°, ...); a number in general lies about 1e-6
    from the nearest such fraction."""
    return abs(x - float(Fraction(x).limit_denominator(1000))) <= 1e-12 * max(1.0, abs(x))


def _density(witness, params, extra, body, up, fine):
    """The density ratio: the witness's ``density``, or (a cut witness, ``through``) the share of the volume
    below the plane through that point normal to *up*."""
    through = getattr(witness, "through", None)
    if through is None:
        return closed_ball(witness.density, params, extra, fine)
    with working_precision(fine):
        point = tuple(closed_ball(x, params, extra, fine) for x in through)
        points = body.points()
        c = _mean(points)
        whole = _volume_moment([tuple(points[i] for i in ring) for ring in body.faces], c)[0]
        return _volume_at(body, up, _dot(up, point), c) / whole


def enclosed_values(witness, case, bits):
    """The floating *witness*'s quantity at *case* as a ball (a tuple of balls for several), its ``roots`` first
    (:func:`_root_balls`); ``None`` where there is no rigorous method (see :func:`quantity_balls`); an
    enclosure that cannot be had at *bits* raises :class:`~symfloat.engine.enclosure.Unsupported` (undecided)."""
    body = witness.body if witness.body is not None else case.data["body"]
    if missing_method(witness, body, case):
        return None
    single = isinstance(witness.quantity, sp.Expr)
    items = (witness.quantity,) if single else tuple(witness.quantity)
    params = dict(case.params)
    try:
        solved = _root_balls(witness, case, body, bits) if getattr(witness, "roots", ()) else (params, {})
        if solved is None:
            return None
        params, extra = solved
        if not any(measured_names(q) for q in items):
            values = tuple(closed_ball(q, params, extra, bits + GUARD_BITS) for q in items)  # the roots alone
        else:
            values = quantity_balls(witness, params, extra, body, bits)
    except Ambiguous as exc:
        raise Unsupported(str(exc)) from exc
    if values is None:
        return None
    return values[0] if single else values


def _unreadable(quantity) -> str:
    """Why a quantity (a name, or an expression in ``measured(name)``) is not read off a :class:`BallState`, in
    words; ``""`` where it is."""
    from .floating_witness import SPLIT_QUANTITIES, TILT_QUANTITIES
    missing = measured_names(quantity) - set(FIELDS) - set(EXTREMES)
    if not missing:
        return ""
    if missing & set(TILT_QUANTITIES):
        return "a tilt's wedges from a reference position"
    if missing & set(SPLIT_QUANTITIES):
        return "the split parts of a marked body"
    return f"a quantity read off no ball state ({', '.join(sorted(missing))})"


def missing_method(witness, body, case) -> str:
    """Why the floating *witness* has no ball method at *case*, in words, judged before any work; ``""`` where it
    has one: no limit, series or tilt from a reference, a box, prism or regular prism whose dimensions the case
    or a root fixes or a cylinder whose length the case fixes (its radius may be a root), each root an expression, an ``At`` or a
    ``Root`` (nested roots without a guard), each quantity read off the state (:func:`_unreadable`)."""
    from .floating_witness import At, Body, Loaded, Marked, Root
    if witness.limit is not None:
        return "a limit in the tilt (Neville extrapolation: no bound)"
    if getattr(witness, "series", None) is not None:
        return "a series coefficient in the tilt (interpolated: no bound)"
    if witness.reference is not None:
        return "a tilt's wedges from a reference position"
    roots = {symbol for symbol, _ in getattr(witness, "roots", ())}
    if type(body) is Body and body.kind == "cylinder":
        if getattr(witness, "through", None) is not None:
            return "a cut's share of a cylinder"
        if sp.sympify(body.dims[1]).free_symbols - (set(case.params) - roots):
            return "a cylinder's length that the case does not fix"
        dims = ()
    elif type(body) not in (Body, Loaded, Marked) or body.kind not in ("box", "prism", "regular"):
        return {"cylinder": "a cylinder with a given centre of gravity or split parts"}.get(
            body.kind, f"a body of kind {body.kind}")
    elif body.kind == "prism":
        dims = (*(c for p in body.dims[0] for c in p), body.dims[1])
    else:
        dims = body.dims if body.kind == "box" else body.dims[1:]
    if any(sp.sympify(x).free_symbols - set(case.params) - roots for x in dims):
        return "a dimension that neither the case nor a root fixes"
    for _, root in getattr(witness, "roots", ()):
        if isinstance(root, (Root, At)):
            if isinstance(root, Root) and root.roots and root.guard:
                return "a nested root search with a guard"
            for item in (root.quantity, *(root.guard if isinstance(root, Root) else ())):
                if _unreadable(item):
                    return _unreadable(item)
        elif not isinstance(root, (sp.Basic, int, Fraction)):
            return "a derivative by finite differences (no bound)"
    items = (witness.quantity,) if isinstance(witness.quantity, sp.Expr) else tuple(witness.quantity)
    measured = [q for q in items if measured_names(q)]
    return next((_unreadable(q) for q in measured if _unreadable(q)), "")


ROOT_BRACKETS = (2.0 ** -30, 2.0 ** -20)   # the float64 root's brackets, relative to 1 + |root|, tried in turn


def _root_balls(witness, case, body, bits, starts=None):
    """The witness's ``roots``: ``(params, extra)``, the case's parameters with the roots that are exact numbers
    (an expression in exact values, kept exact) and the others as balls (symbol -> ball): an expression in what
    is known, ``At`` a quantity at other
    parameters, ``Root`` a root of a quantity in a variable, proven by a sign change on a bracket about the
    float64 root (the first of :data:`ROOT_BRACKETS` whose signs are proven) and narrowed by secant steps
    (:func:`_secant_root`), each ``guard`` proven positive there; a ``Root`` with nested ``roots`` the same, its
    quantity at each trial value (the midpoint of its ball, exact) read with the nested roots enclosed there
    (:func:`_nested_point`); ``None`` for a root without a rigorous method (a derivative by differences, a nested
    search that reads a root enclosed before it or has a guard).

    *starts* (symbol -> exact number, filled in as roots are found): a nested search's roots at its previous
    trial value, from which the roots at the next are sought before the float64 search is asked.  The trial
    values lie within ``2^-20`` of the float64 root, where the float64 search found the nested roots it did; a
    root's proof is its bracket's signs either way."""
    from .floating_witness import At, Root
    from .witness import Case
    fine = bits + GUARD_BITS
    params, extra, centres = dict(case.params), {}, None
    for symbol, root in witness.roots:
        if not isinstance(root, (Root, At)):
            if not isinstance(root, (sp.Basic, int, Fraction)):
                return None                                     # a derivative by differences
            value = sp.sympify(root).xreplace({k: v for k, v in params.items() if k not in extra})
            if value.free_symbols:
                extra[symbol] = closed_ball(root, params, extra, fine)
            else:                                               # exact (pi/4): kept exact, a case parameter
                params[symbol] = value
                extra.pop(symbol, None)
            continue
        here_params, here = dict(params), dict(extra)
        for k, v in root.at:
            here[k] = closed_ball(v, params, extra, fine)
            here_params.pop(k, None)
        probe = replace(witness, quantity=root.quantity, roots=())
        if isinstance(root, At):
            values = quantity_balls(probe, here_params, here, body, bits)
            if values is None:
                return None
            extra[symbol] = values[0]
            continue
        nested = None
        if root.roots:
            nested = _nested_point(root, params, extra, witness, body)
            if nested is None or root.guard:
                return None
        here_params.pop(root.variable, None)
        continued: dict = {}        # the nested roots at the last trial value (*starts* of the nested search)

        def f(x, probe=probe, here_params=here_params, here=here, variable=root.variable, root=root, nested=nested,
              continued=continued):
            if nested is None:
                values = quantity_balls(probe, here_params, {**here, variable: x}, body, bits)
            else:               # the nested roots at the trial value, then the quantity there
                trial = Case({**nested, variable: _dyadic(x.mid())})
                solved = _root_balls(replace(probe, roots=root.roots), trial, body, bits, continued)
                values = None if solved is None else quantity_balls(probe, *solved, body, bits)
            if values is None:
                raise _NoMethod
            return values[0]

        def enclosed(centre, f=f):
            for share in ROOT_BRACKETS:
                reach = share * (1 + abs(centre))
                value = _secant_root(f, centre - reach, centre + reach, bits, centre)
                if value.is_finite():
                    break
            return value
        try:
            value = enclosed(starts[symbol]) if starts and symbol in starts else arb.nan()
            if not value.is_finite():
                if centres is None:
                    centres = witness._solve(case.params, body, witness.roots, 15)     # the float64 search, cached
                value = enclosed(float(centres[symbol]))
            for item in root.guard:
                g = quantity_balls(replace(probe, quantity=item), here_params, {**here, root.variable: value}, body,
                                   bits)
                if g is None:
                    return None
                if not g[0] > 0:
                    raise Ambiguous(f"{item} is not proven positive at the root {root.variable}")
        except _NoMethod:
            return None
        if not value.is_finite():
            raise Ambiguous(f"no proven sign change of {root.quantity} about the float64 root {root.variable}")
        extra[symbol] = value
        if starts is not None:
            starts[symbol] = value.mid()
    return params, extra


def _nested_point(root, params, extra, witness, body):
    """The exact parameters at which a nested search's roots are found at each trial value: the case's, with the
    root's ``at`` where it is exact; ``None`` where a value of ``at`` or anything the nested search reads (its
    quantity, the nested roots, the up vector, the density, the body) depends on a root enclosed before it."""
    from .floating_witness import At, Root
    known = {k: v for k, v in params.items() if k not in extra}
    point = dict(known)
    for k, v in root.at:
        value = sp.sympify(v).xreplace(known)
        if value.free_symbols:
            return None
        point[k] = value
    read = [root.quantity, *witness.up, witness.density, *flatten(body.dims)]
    for _, inner in root.roots:
        read += ([inner.quantity, *(v for _, v in inner.at), *getattr(inner, "grid", ()), *getattr(inner, "guard", ())]
                 if isinstance(inner, (Root, At)) else [inner])
    named = set().union(*(sp.sympify(e).free_symbols for e in read if isinstance(e, (sp.Basic, int, float))))
    return None if named & set(extra) else point


def _dyadic(x: arb) -> sp.Rational:
    """The exact value of the midpoint *x* (a dyadic number)."""
    man, exp = x.man_exp()
    return sp.Integer(int(man)) * sp.Rational(2) ** int(exp)


def _secant_root(f, lo, hi, bits, start=None):
    """A root of *f* in ``[lo, hi]`` as a ball about ``2^-bits (1 + |root|)`` wide: secant steps on the balls'
    midpoints at exact dyadic points (from *start*, the float64 root, and a point ``2^-40`` from it), then a
    bracket about the last one whose ends' signs are proven opposite (the intermediate value theorem), as narrow
    as the balls of *f* allow and widened by 2^8 at a time up to ``2^-(bits/2)`` (:func:`_narrowed`).  Where that
    proves nothing, the same from the ends *lo*, *hi* (floats whose values of *f* must be balls of proven opposite
    signs), and then bisection on ``[lo, hi]`` (:func:`~symfloat.engine.enclosure.sign_change_root`); non-finite
    where the signs at *lo*, *hi* are not proven opposite."""
    with working_precision(bits + GUARD_BITS):
        a, b = arb(lo), arb(hi)
        if start is not None and a < arb(start) < b:
            x = arb(start)
            y = arb((x + arb(2) ** -40 * (1 + abs(x))).mid())
            try:
                root = _narrowed(f, a, b, x, f(x), y, f(y), bits)
            except Ambiguous:
                root = None
            if root is not None:
                return root
        fa, fb = f(a), f(b)
        if not ((fa < 0 and fb > 0) or (fa > 0 and fb < 0)):
            return arb.nan()
        root = _narrowed(f, a, b, a, fa, b, fb, bits)
        if root is not None:
            return root
    return sign_change_root(f, lo, hi, bits)


def _narrowed(f, a, b, x, fx, y, fy, bits):
    """Secant steps inside ``[a, b]`` from ``(x, fx)``, ``(y, fy)`` (balls; the steps on their midpoints), then
    the first bracket about the last point whose ends' signs are proven opposite: ``2^(4 - bits) (1 + |y|)`` wide
    times the least power of 2 that spans twice the radius of the last value along the secant's slope (a nested
    root's ball, or the data's, widens every value), widened by 2^8 at a time; ``None`` where none within
    ``[a, b]`` is."""
    centre = y
    for _ in range(SECANT_STEPS):
        if fy.mid() == fx.mid():
            break
        z = arb((y - fy.mid() * (y - x) / (fy.mid() - fx.mid())).mid())
        if not (a < z < b):
            z = (a + b) / 2
        if (z - y).abs_upper() < arb(2) ** -bits * (1 + abs(z)):
            centre = z          # converged: the bracket's ends are evaluated, not z itself
            break
        x, fx, y, fy = y, fy, z, f(z)
        centre = y
    step = arb(2) ** (4 - bits) * (1 + abs(centre))
    for widen in range(_spanned(fx, fy, x, y, step), bits // 2 - 8, 8):
        left, right = centre - step * 2 ** widen, centre + step * 2 ** widen
        if not (a <= left and right <= b):
            break
        fl, fr = f(left), f(right)
        if (fl < 0 and fr > 0) or (fl > 0 and fr < 0):
            return left.union(right)
    return None


def _spanned(fx, fy, x, y, step) -> int:
    """The least ``k >= 0`` with ``step 2^k`` at least ``2 rad(fy) / |slope|``, the slope the secant's through
    ``(x, fx)``, ``(y, fy)`` (their midpoints): a bracket that narrow has ends whose values are apart from 0 by
    about twice their balls' radius; 0 where the slope is 0."""
    slope = abs((fy.mid() - fx.mid()) / (y - x))
    if not slope > 0:
        return 0
    mantissa, exponent = math.frexp(float((2 * fy.rad() / slope / step).upper()))
    return max(0, exponent - (mantissa == 0.5))


SECANT_STEPS = 40


class _NoMethod(Exception):
    """A quantity of a root's search has no rigorous method."""
