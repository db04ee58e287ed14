"""Floating-body witnesses: a derivation names the body, the quantity and the cases; nothing else.

The measurement is the exact clipping of :mod:`symfloat.geometry.floating`: the body is built at the
case's numbers, floated at its density with the given up vector (the draught found by certified Newton
steps), and the quantity read off the clipped body and its waterplane.  No closed form of a metacentre,
a wedge or a segment enters.  Two arithmetics: float64 (relative error of the clipped quantities at
most 1e-12 of the body's size, see the geometry module) and 40-digit mpmath.

>>> import sympy as sp
>>> from symfloat.engine.witness import Case
>>> rho = sp.Symbol("rho", positive=True)
>>> w = FloatingWitness("draught", "draught of the unit cube", ("t",), (Case({rho: sp.Rational(1, 3)}),),
...                     body=Body.box(1, 1, 1), up=(0, 0, 1), density=rho, quantity=measured("draught"))
>>> [round(float(w.measure(w.instances[0], m)), 12) for m in w.methods]     # Archimedes: s * 1 / 1
[0.333333333333, 0.333333333333]
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import sympy as sp
from flint import arb

from ..geometry.floating import (FloatingState, _dot, _sub, _unit, body_volume_centroid, box, clip_below, draught,
                                 floating_state, regular_prism, right_prism, submerged, volume_centroid)
from ..geometry.cylinder import cylinder_state
from .extrapolation import at_zero
from .measured import Measured, in_words, measured, measured_names, numbered
from .witness import MeasuredWitness, Precision

__all__ = ["Body", "FloatingWitness", "QUANTITIES", "TILT_QUANTITIES", "FLOATING_METHODS",
           "LIMIT_METHODS"]

FLOATING_METHODS = (Precision(15, 1e-9), Precision(40, 1e-30))
# the limit of a quantity over a power of the tilt, by Neville extrapolation: in float64 from the tilts 1e-3 ...
# 1e-3/8 (truncation about 1e-12, rounding amplified to about 1e-9 for a second-order moment); at 50 digits
# the clipping runs at 90 digits from 1e-10 ... 1e-10/32 (truncation about 1e-60, rounding about 1e-70)
LIMIT_METHODS = (Precision(15, 1e-7), Precision(50, 1e-35))
_LIMIT_STEPS = {15: (1e-3, 3, 15), 50: ("1e-10", 5, 90)}


def number(expr, params, dps):
    """The value of a SymPy expression at *params*: a :class:`Fraction` when it is rational (the geometry
    then works with the exact value), else a float (``dps`` 15) or an mpf at ``dps`` digits.  Where a parameter
    it depends on is a float (a trial value of a root search), the expression is evaluated by its compiled form
    (:func:`_compiled`) at ``dps + 10`` digits, not by SymPy."""
    expr = expr if isinstance(expr, sp.Basic) else sp.sympify(expr)
    if expr.is_Rational:                     # a dimension, a constant: what _exact gives, without its cache's keys
        return Fraction(int(expr.p), int(expr.q))
    if isinstance(expr, sp.Float) and _unrounded(expr, dps):
        return float(expr) if dps <= 15 else +mpmath.mpf(expr)    # a trial value, as _exact gives it
    symbols = _parameters(expr)
    if not any(isinstance(params.get(x), sp.Float) for x in symbols):
        value = _exact(expr, tuple((x, params[x]) for x in symbols if x in params), dps)
        return +value if isinstance(value, mpmath.mpf) else value
    names, f = _compiled(expr)
    missing = [x for x in names if x not in params]
    if missing:
        raise ValueError(f"a floating witness needs a number, {expr} is not one at {params} ({missing} unknown)")
    with mpmath.workdps(max(dps, 15) + 10):
        value = f(*(_mp(params[x], dps) for x in names))
    return float(value) if dps <= 15 else +value


def _digits(dps) -> int:
    """The digits at which :func:`_exact` evaluates for a method of *dps* digits: 30 for float64, ``dps + 10``."""
    return 30 if dps <= 15 else dps + 10


def _unrounded(x: sp.Float, dps) -> bool:
    """Whether :func:`_exact` would take the Float *x* unrounded (no more bits than its :func:`_digits`)."""
    return x._prec <= mpmath.libmp.dps_to_prec(_digits(dps))


@functools.lru_cache(maxsize=4096)
def _parameters(expr):
    """The free symbols of *expr* sorted by name: :func:`number` asks for them at every trial value of a root
    search, and SymPy walks the expression for them each time."""
    return tuple(sorted(expr.free_symbols, key=str))


@functools.lru_cache(maxsize=4096)
def _exact(expr, params, dps):
    """:func:`number` of *expr* at exact *params* (pairs of a symbol and a SymPy number): the same case's
    dimensions and constants are met at every trial value of a root search, and evaluated once."""
    value = expr.xreplace(dict(params))
    if value.free_symbols:
        raise ValueError(f"a floating witness needs a number, {expr} is {value} at {dict(params)}")
    if value.is_Rational:
        return Fraction(int(value.p), int(value.q))
    if dps <= 15:
        return float(sp.N(value, _digits(dps)))
    with mpmath.workdps(_digits(dps)):
        return mpmath.mpf(sp.N(value, _digits(dps)))


def _mp(x, dps):
    """A parameter's value (a SymPy number) as an mpf at the working precision."""
    if isinstance(x, sp.Float):
        return mpmath.mpf(x)
    if isinstance(x, sp.Rational):
        return mpmath.mpf(int(x.p)) / int(x.q)
    return mpmath.mpf(sp.N(x, max(dps, 15) + 15))


@dataclass(frozen=True)
class Body:
    """A convex prism whose dimensions are SymPy expressions in a case's parameters: ``box(a, b, c)``
    (centred, edges along the axes), ``prism(polygon, length)`` (axis along ``z``), ``regular(n, side,
    length)``."""

    kind: str
    dims: tuple

    @classmethod
    def box(cls, a, b, c):
        return cls("box", (a, b, c))

    @classmethod
    def prism(cls, polygon, length):
        return cls("prism", (tuple(tuple(p) for p in polygon), length))

    @classmethod
    def regular(cls, n, side, length):
        return cls("regular", (int(n), side, length))

    @classmethod
    def cylinder(cls, radius, length):
        """A circular cylinder, axis z, centred (see :class:`Cylinder`)."""
        return cls("cylinder", (radius, length))

    def build(self, params, dps):
        """The :class:`~symfloat.geometry.floating.Polyhedron` at *params*, float64 (``dps`` 15) or mpmath."""
        prec = None if dps <= 15 else dps
        at = lambda e: number(e, params, dps)      # noqa: E731
        if self.kind == "cylinder":
            return Cylinder(*(_real(at(x), dps) for x in self.dims), prec)
        if self.kind == "box":
            return box(*(at(x) for x in self.dims), prec)
        if self.kind == "prism":
            polygon, length = self.dims
            return right_prism([(at(x), at(y)) for x, y in polygon], at(length), prec)
        n, side, length = self.dims
        return regular_prism(n, at(side), at(length), prec)


def _height(u, p, t):
    return sum(a * b for a, b in zip(u, p)) - t


def _stability_sign(st):
    """The sign of the metacentric height, refused when it is within the clipping's error of zero (relative
    to the larger of its two terms)."""
    value, scale = st.metacentric_height, max(abs(st.potential), st.I_min / st.volume)
    if abs(value) <= 1e-9 * scale:
        raise ValueError(f"a floating witness cannot decide the sign of {value}: it is within the "
                         "clipping's error of zero (choose a case away from the threshold)")
    return 1 if value > 0 else -1


# quantity -> (what it is, how to read it from the floating state and the body)
QUANTITIES = {
    "draught": ("depth of the lowest point of the body below the water plane",
                lambda st, body: st.t - min(sum(a * b for a, b in zip(st.u, p)) for p in body.vertices)),
    "immersed volume": ("volume of the clipped part below the water", lambda st, body: st.volume),
    "G above water": ("height of the centre of gravity above the water plane",
                      lambda st, body: _height(st.u, st.G, st.t)),
    "B below water": ("depth of the centre of buoyancy below the water plane",
                      lambda st, body: -_height(st.u, st.B, st.t)),
    "G above B": ("height of the centre of gravity above the centre of buoyancy", lambda st, body: st.potential),
    "waterplane area": ("area of the clipped waterplane", lambda st, body: st.waterplane_area),
    "I min": ("least second moment of the waterplane about an axis through its centroid",
              lambda st, body: st.I_min),
    "I max": ("greatest second moment of the waterplane about an axis through its centroid",
              lambda st, body: st.I_max),
    "metacentric radius": ("I min over the immersed volume", lambda st, body: st.I_min / st.volume),
    "metacentric height": ("I min over the immersed volume minus the height of G above B",
                           lambda st, body: st.metacentric_height),
    "stability sign": ("sign of the metacentric height: 1 stable, -1 unstable against the weakest tilt",
                       lambda st, body: _stability_sign(st)),
    "stable": ("1 when the metacentric height is positive, 0 when it is negative",
               lambda st, body: (1 + _stability_sign(st)) // 2),
    **{f"B - G, {axis}": (f"{axis} component of B - G in the body frame",
                          lambda st, body, k=k: st.B[k] - st.G[k]) for k, axis in enumerate("xyz")},
}


def _real(x, dps):
    """A parameter's value in the witness's arithmetic (a Fraction becomes a float or an mpf)."""
    if isinstance(x, Fraction):
        return float(x) if dps <= 15 else mpmath.mpf(x.numerator) / x.denominator
    return x


@functools.lru_cache(maxsize=4096)
def _compiled(expr):
    """*expr* (measured symbols and case parameters) as a function of its free symbols, sorted by name:
    compiled once, called at every case, tilt and precision."""
    symbols = tuple(sorted(expr.free_symbols, key=str))
    return symbols, sp.lambdify(symbols, expr, "mpmath")


@dataclass(frozen=True)
class Tilt:
    """The body tilted from a reference position ``r`` (unit up, draught ``t0``) to its floating state:
    ``h0``, the horizontal of the old water plane towards the side that dips; ``alpha``, the line where the
    old and the new water plane meet, as its coordinate along ``h0``; the immersed wedge (below the new
    plane, above the old) and the emerged one (above the new, below the old), clipped from the body."""

    r: tuple
    t0: object
    h0: tuple
    alpha: object
    arm: object
    V3: object
    c3: tuple
    V4: object
    c4: tuple


def _tilt(body, st, reference, density):
    r = _unit(reference, body.dps)
    t0 = draught(body, r, density)[0]
    u, ur = st.u, _dot(st.u, r)
    h0 = _unit(tuple(ur * ri - ui for ri, ui in zip(r, u)), body.dps)
    hor = _unit(tuple(ri - ur * ui for ri, ui in zip(r, u)), body.dps)     # the same, in the new frame
    imm = clip_below(clip_below(body, u, st.t), tuple(-x for x in r), -t0)
    emg = clip_below(clip_below(body, tuple(-x for x in u), -st.t), r, t0)
    V3, c3 = volume_centroid(imm)
    V4, c4 = volume_centroid(emg)
    return Tilt(r, t0, h0, (st.t - t0 * ur) / _dot(u, h0), _dot(_sub(st.B, st.G), hor), V3, c3, V4, c4)


# quantity -> (what it is, how to read it from the body tilted from the reference position at the same density)
TILT_QUANTITIES = {
    "righting arm": ("horizontal distance of B from G towards the side that dips (the arm of the couple)",
                     lambda w: w.arm),
    "axis position": ("where the old and the new water plane meet, along the old horizontal towards the dip",
                      lambda w: w.alpha),
    "immersed wedge volume": ("volume below the new and above the old water plane", lambda w: w.V3),
    "emerged wedge volume": ("volume above the new and below the old water plane", lambda w: w.V4),
    "immersed wedge moment, horizontal": ("its static moment about the line where the planes meet, towards the dip",
                                          lambda w: w.V3 * (_dot(w.c3, w.h0) - w.alpha)),
    "immersed wedge moment, vertical": ("its static moment about the old water plane, upwards",
                                        lambda w: w.V3 * (_dot(w.c3, w.r) - w.t0)),
    "emerged wedge moment, horizontal": ("its static moment about the line where the planes meet, away from the dip",
                                         lambda w: w.V4 * (w.alpha - _dot(w.c4, w.h0))),
    "emerged wedge moment, vertical": ("its static moment about the old water plane, downwards",
                                       lambda w: w.V4 * (w.t0 - _dot(w.c4, w.r))),
}


def _neville_at_zero(f, h, levels):
    """Neville extrapolation to 0 of f at h, h/2, ..., h/2^levels (a polynomial in the step), componentwise."""
    xs = [h / 2 ** j for j in range(levels + 1)]
    ps = [f(x) for x in xs]
    return tuple(at_zero(xs, [p[i] for p in ps]) for i in range(len(ps[0])))


@dataclass(frozen=True)
class FloatingWitness(MeasuredWitness):
    """A quantity of :data:`QUANTITIES` of ``body`` floating at ``density`` with ``up`` (body frame, SymPy
    expressions in the case's parameters) pointing up.  ``quantity`` may also be a tuple, for targets whose
    reading lists several numbers, and each item a SymPy expression in ``measured(name)``
    (:mod:`symfloat.engine.measured`) and the case's parameters (a product with the immersed volume, a ratio).
    Without ``body`` each case names its own (``Case(..., {"body": Body...})``).  With ``reference`` (the up vector of the position the body
    is tilted from, at the same density) the quantities of :data:`TILT_QUANTITIES` are measured too.  With
    ``limit = (psi, k)``, ``up`` depends on the tilt ``psi`` and the witness measures the limit of the
    quantity over psi^k as psi -> 0, by extrapolation (:data:`LIMIT_METHODS`)."""

    body: Body = None
    up: tuple = (0, 0, 1)
    density: object = None
    quantity: object = measured("draught")
    methods: tuple = FLOATING_METHODS
    reference: tuple = None
    limit: tuple = None

    def __post_init__(self):
        items = self.quantity if isinstance(self.quantity, tuple) else (self.quantity,)
        names = set()
        for q in items:             # its other symbols are the case's parameters (checked when measured)
            names |= measured_names(in_words(q, self.name))
        for q in names:
            if q not in QUANTITIES and q not in TILT_QUANTITIES:
                raise ValueError(f"witness {self.name}: unknown quantity {q!r}; known: "
                                 f"{', '.join((*QUANTITIES, *TILT_QUANTITIES))}")
            if q in TILT_QUANTITIES and self.reference is None:
                raise ValueError(f"witness {self.name}: {q!r} needs the reference position it is tilted from")
        if self.limit is not None and any(m.dps not in _LIMIT_STEPS for m in self.methods):
            raise ValueError(f"witness {self.name}: a limit is extrapolated at {sorted(_LIMIT_STEPS)} digits only "
                             f"(methods=LIMIT_METHODS)")

    def _values(self, params, body, dps):
        body = body.build(params, dps)
        up = tuple(number(x, params, dps) for x in self.up)      # the geometry normalises it
        density = number(self.density, params, dps)
        st = _floating_state(body, up, density)
        tilt = []

        def value_of(name):
            if name in QUANTITIES:
                return QUANTITIES[name][1](st, body)
            if not tilt:
                tilt.append(_tilt(body, st, tuple(number(x, params, dps) for x in self.reference), density))
            return TILT_QUANTITIES[name][1](tilt[0])

        def item(q):
            if isinstance(q, Measured):
                return value_of(q.name)
            symbols, f = _compiled(q)
            unknown = [str(s) for s in symbols if not isinstance(s, Measured) and s not in params]
            if unknown:
                raise ValueError(f"witness {self.name}: {unknown} are neither measured nor given by the case")
            return f(*(_real(number(params[s], params, dps), dps) if s in params else value_of(str(s))
                       for s in symbols))
        if isinstance(self.quantity, sp.Expr):
            return (item(self.quantity),)
        return tuple(item(q) for q in self.quantity)

    def measure(self, case, method):
        body = self.body if self.body is not None else case.data["body"]
        if self.limit is None:
            with mpmath.workdps(max(method.dps, 15)):
                values = self._values(case.params, body, method.dps)
        else:
            psi, power = self.limit
            h, levels, dps = _LIMIT_STEPS[method.dps]
            with mpmath.workdps(dps):
                step = mpmath.mpf(h) if dps > 15 else h
                values = _neville_at_zero(
                    lambda x: tuple(v / x ** power for v in self._values({**case.params, psi: sp.Float(x, dps + 5)},
                                                                         body, dps)), step, levels)
        with mpmath.workdps(max(method.dps, 15)):
            values = tuple(float(v) if method.dps <= 15 else +v for v in values)   # rounded to the method's digits
        return values[0] if isinstance(self.quantity, sp.Expr) else values

    def enclose(self, case, bits):
        """The quantity in ball arithmetic (:func:`symfloat.engine.floating_enclosure.enclosed_values`: exact
        clipping with proven sides, a cylinder's slice integrals by their primitives in balls
        (:mod:`symfloat.engine.cylinder_enclosure`), the draught and each root a proven bracket), or ``None`` where
        it has no rigorous method (a limit, a tilt's wedges, a nested root search)."""
        from .floating_enclosure import enclosed_values
        return enclosed_values(self, case, bits)


# ---- the waterplane's moments in the body frame, a prism's bases ---------------------------------------------
def _waterplane_moment(i, j):
    """int p_i p_j over the waterplane about its centroid, body-frame components i, j: the tensor of the
    floating state (in the waterplane basis e1, e2) carried back, sum_ab e_a[i] J_ab e_b[j]."""
    def read(st, body):
        J, (e1, e2) = st.tensor, st.basis
        e = (e1, e2)
        return sum(e[a][i] * J[a][b] * e[b][j] for a in range(2) for b in range(2))
    return read


def _base_vertices(body, sign):
    """The vertices of the base of a prism (axis z) on the side *sign* of z: those at its largest or smallest z."""
    end = max(sign * p[2] for p in body.vertices)
    return [p for p in body.vertices if sign * p[2] == end]


BODY_FRAME_QUANTITIES = {
    **{f"waterplane moment, {'xyz'[i]}{'xyz'[j]}": (
        f"int {'xyz'[i]} {'xyz'[j]} (body frame) over the waterplane, about its centroid", _waterplane_moment(i, j))
       for i in range(3) for j in range(i, 3)},
    "upper base above water": ("height above the water plane of the lowest vertex of the base at +z (negative "
                               "once that base is cut)",
                               lambda st, body: min(_dot(st.u, p) for p in _base_vertices(body, 1)) - st.t),
    "lower base above water": ("height above the water plane of the highest vertex of the base at -z (positive "
                               "once that base is cut)",
                               lambda st, body: max(_dot(st.u, p) for p in _base_vertices(body, -1)) - st.t),
}
QUANTITIES.update(BODY_FRAME_QUANTITIES)


def waterplane_moment(n, m):
    """The expression int (n . p)(m . p) over the waterplane about its centroid for body-frame vectors n, m
    (SymPy expressions in the case's parameters): with n = m the unit normal of a horizontal line in the
    waterplane, the waterplane's moment of inertia about that line; with n, m the normal and the direction of
    the line, its product moment in those axes."""
    k = "xyz"
    return sp.Add(*(n[i] * m[j] * measured(f"waterplane moment, {k[min(i, j)]}{k[max(i, j)]}")
                    for i in range(3) for j in range(3)))


def parts_methods(parts) -> tuple:
    """The methods a whole measures its *parts* at, where it names none: the parts' own, or, where they differ,
    those of the part whose float64 method is the least precise (a limit's or a series' beside a plain
    quantity's: the whole is no more precise than that part)."""
    return max((part.methods for part in parts), key=lambda methods: methods[0].tolerance)


@dataclass(frozen=True)
class Joined(MeasuredWitness):
    """Several floating witnesses (``parts``, each with its own body) measured at the same case, their values
    joined into one tuple: for a reading that lists quantities of different bodies.  ``methods`` defaults to
    :func:`parts_methods`."""

    parts: tuple = ()
    methods: tuple = None

    def __post_init__(self):
        if self.methods is None:
            object.__setattr__(self, "methods", parts_methods(self.parts))

    def measure(self, case, method):
        out = []
        for part in self.parts:
            value = part.measure(case, method)
            out.extend(value if isinstance(value, tuple) else (value,))
        return tuple(out)

    def enclose(self, case, bits):
        """The parts' enclosures joined, or ``None`` where a part has none."""
        out = []
        for part in self.parts:
            value = part.enclose(case, bits)
            if value is None:
                return None
            out.extend(value if isinstance(value, tuple) else (value,))
        return tuple(out)


# ---- roots of a quantity along a parameter, face clearances, the waterplane's corners -----------------------------
from dataclasses import replace  # noqa: E402

from .roots import grid_roots  # noqa: E402
from .witness import Case  # noqa: E402


def _face_heights(st, body, top):
    """Heights above the water plane of the vertices of the body's top (largest z) or bottom (least z) face."""
    zs = [p[2] for p in body.vertices]
    end = max(zs) if top else min(zs)
    return [_height(st.u, p, st.t) for p in body.vertices if p[2] == end]


def _corners(st, body):
    """Distinct corners of the clipped waterplane polygon (points closer than 1e-9 of the body's size, in
    float64, or half the digits, in mpmath, are one corner)."""
    from ..geometry.floating import submerged
    size = max(abs(c) for p in body.vertices for c in p)
    eps = size * (1e-9 if body.dps is None else mpmath.mpf(10) ** (-body.dps // 2))
    pts = []
    for p in submerged(body, st.u, st.t).waterplane.polygon:
        if all(max(abs(a - b) for a, b in zip(p, q)) > eps for q in pts):
            pts.append(p)
    return len(pts)


QUANTITIES.update({
    "top clearance": ("height above the water plane of the lowest vertex of the top face (largest z): positive "
                      "while that face is dry, zero when it reaches the water",
                      lambda st, body: min(_face_heights(st, body, True))),
    "bottom clearance": ("depth below the water plane of the highest vertex of the bottom face (least z): "
                         "positive while that face is submerged", lambda st, body: -max(_face_heights(st, body, False))),
    "waterplane corners": ("number of distinct corners of the clipped waterplane polygon",
                           lambda st, body: _corners(st, body)),
    "face clearance": ("the lesser of the top and the bottom clearance: positive while the water plane cuts "
                       "neither end face, zero when the first of them reaches the water",
                       lambda st, body: min(min(_face_heights(st, body, True)), -max(_face_heights(st, body, False)))),
    "water level": ("height of the water plane above the body's origin (along the up vector)", lambda st, body: st.t),
    "freeboard": ("height of the highest point of the body above the water plane",
                  lambda st, body: max(_height(st.u, p, st.t) for p in body.vertices)),
})


def _tensor3(st, i, j):
    """Component (i, j) of the waterplane's central second-moment tensor in the body frame,
    int (p - c)_i (p - c)_j dA = sum over the waterplane basis e_a, e_b of J_ab (e_a)_i (e_b)_j."""
    return sum(st.tensor[a][b] * st.basis[a][i] * st.basis[b][j] for a in range(2) for b in range(2))


QUANTITIES.update({
    **{f"waterplane centroid, {axis}": (f"{axis} coordinate of the centroid of the clipped waterplane (body frame)",
                                        lambda st, body, k=k: st.waterplane_centroid[k]) for k, axis in enumerate("xyz")},
    **{f"waterplane tensor, {'xyz'[i]}{'xyz'[j]}": (
        f"int (p - c)_{'xyz'[i]} (p - c)_{'xyz'[j]} dA over the clipped waterplane about its centroid (body frame): "
        "v . T v (T this tensor, v a unit vector in the waterplane) is its second moment about the centroidal axis "
        "normal to v",
        lambda st, body, i=i, j=j: _tensor3(st, i, j)) for i in range(3) for j in range(i, 3)},
})


def potential_slope(up, variable):
    """dE/d(variable) of the potential E = u.(G - B) (height of G above B) along a family of up vectors
    ``up(variable)``, as an expression in ``measured(name)``: -(du/dvariable).(B - G), u = up/|up|; B moves
    perpendicular to u to first order, so only u is differentiated (the righting arm of a tilt)."""
    up = sp.Matrix(up)
    u = up / sp.sqrt(up.dot(up))
    return -sum(sp.diff(u[k], variable) * measured(f"B - G, {axis}") for k, axis in enumerate("xyz"))


@dataclass(frozen=True)
class Root:
    """A root in ``variable`` of ``quantity`` (a name of :data:`QUANTITIES` or an expression in ``measured(name)``),
    the others of the witness's body, up vector and density: the sign changes on ``grid`` (numbers, or SymPy
    expressions in the case's parameters) refined by :func:`symfloat.engine.roots.grid_roots` in float64 and at
    the method's digits; ``which`` is ``"first"``, ``"last"`` or an index into all of them.  ``at`` overrides
    parameters for this search (expressions in the case's parameters and the roots found before it: the position
    found in one attitude and read in another), ``roots`` are found at each trial value first (nested: the
    aspect ratio at which an equilibrium reaches a base), and each item of ``guard`` (as ``quantity``) must be
    positive at the root (a condition of the source's region, such as no base cut)."""

    quantity: object
    variable: sp.Symbol
    grid: tuple
    which: object = "first"
    at: dict = None
    roots: tuple = ()
    guard: tuple = ()

    def __post_init__(self):
        in_words(self.quantity, f"Root in {self.variable}")
        object.__setattr__(self, "grid", tuple(self.grid))
        object.__setattr__(self, "at", tuple(sorted(dict(self.at or {}).items(), key=str)))
        object.__setattr__(self, "guard", tuple(in_words(g, f"Root in {self.variable}") for g in self.guard))

    @classmethod
    def scan(cls, quantity, variable, lo, hi, steps, **kw):
        """The root sought on the grid ``lo + (hi - lo) k / steps``, k = 0 ... steps (``lo``, ``hi`` numbers or
        SymPy expressions in the case's parameters)."""
        lo, hi = sp.sympify(lo), sp.sympify(hi)
        return cls(quantity, variable, tuple(lo + (hi - lo) * sp.Rational(k, steps) for k in range(steps + 1)), **kw)


@dataclass(frozen=True)
class At:
    """The value of ``quantity`` (as in :class:`Root`) with the parameters ``at`` overriding the case's (an
    upright metacentric height beside a tilted position), for the ``roots`` of a :class:`FloatingRootWitness`."""

    quantity: object
    at: dict = None

    def __post_init__(self):
        in_words(self.quantity, "At")
        object.__setattr__(self, "at", tuple(sorted(dict(self.at or {}).items(), key=str)))


_SOLVED = {}     # (witness geometry, symbol, Root or At, parameters, digits) -> value: shared by the witnesses
_NOT_READ = ("name", "description", "targets", "cases", "methods", "roots")   # a witness's fields that read no root


def _read(x) -> frozenset:
    """The symbols whose values *x* (an expression, a :class:`Root`, :class:`At`, :class:`Difference`, a body, a
    tuple of them) reads at the method's digits.  A Root's ``grid`` is not among them: it is rounded to float64
    before the search (:meth:`FloatingRootWitness._solve_one`)."""
    if isinstance(x, sp.Basic):
        return frozenset(x.free_symbols)
    if isinstance(x, Root):
        return _read((x.quantity, x.variable, x.at, x.roots, x.guard))
    if isinstance(x, (tuple, list)):
        return frozenset().union(*(_read(y) for y in x))
    if isinstance(x, dict):
        return _read(tuple(x.items()))
    if hasattr(x, "__dataclass_fields__") and not isinstance(x, type):
        return _read(tuple(getattr(x, f) for f in x.__dataclass_fields__))
    return frozenset(getattr(x, "free_symbols", ()))      # a matrix; a number or a word (``which``) reads none


@functools.lru_cache(maxsize=1024)
def _exactly_read(fields, body, later):
    """:func:`_read` of a witness's *fields*, its *body* and the *later* roots, kept (the same witness solves its
    roots at every trial value of an outer search)."""
    return _read((fields, body, later))


@dataclass(frozen=True)
class FloatingRootWitness(FloatingWitness):
    """A :class:`FloatingWitness` whose case parameters are completed by roots: ``roots`` is a tuple of
    ``(symbol, Root)``, ``(symbol, At)`` or ``(symbol, expression)`` (a fixed value, in what is known so far),
    found in order at the method's digits; ``quantity`` and ``up`` may use the symbols (an equilibrium tilt as
    a root of the :func:`potential_slope`, the tilt or density at which a face reaches the water as a root of a
    clearance).  A quantity in the roots and parameters alone is read off them, with no floating state."""

    roots: tuple = ()

    def _solve(self, params, body, roots, dps, reads=()):
        """*params* completed by *roots* at *dps* digits.  A Root whose symbol nothing after it reads at those
        digits (not the quantity, the up vector, the density, a later root's quantity; *reads* too, a guard's
        items) but only a later search's grid, which is float64, is found in float64: in Scheeffer IX's double
        roots the tilts at which the corners reach the water bound the grid of the arm's extremum, and a
        40-digit search for them at every trial edge was half of all its 40-digit floating states."""
        params = dict(params)
        fields = None
        for i, (symbol, root) in enumerate(roots):
            digits = dps
            if dps > 15 and isinstance(root, Root):
                if fields is None:
                    fields = tuple(getattr(self, f) for f in self.__dataclass_fields__ if f not in _NOT_READ)
                if symbol not in _exactly_read(fields + (reads,), body, tuple(r for _, r in roots[i + 1:])):
                    digits = 15
            key = (type(self), body, self.up, self.density, self.reference, getattr(self, "through", None), symbol,
                   root, tuple(sorted(params.items(), key=lambda item: str(item[0]))), digits)
            if key not in _SOLVED:
                _SOLVED[key] = self._solve_one(params, body, symbol, root, digits)
            params[symbol] = _SOLVED[key]
        return params

    def _solve_one(self, params, body, symbol, root, dps):
        if isinstance(root, Difference):                     # a derivative along a parameter (its block below)
            return root.value(self, params, body, dps)
        if not isinstance(root, (Root, At)):                 # a value: an expression in what is known
            return sp.sympify(root).xreplace(params)
        at = {**params, **{k: sp.sympify(v).xreplace(params) for k, v in root.at}}
        probe = replace(self, quantity=root.quantity, name=f"{self.name}: {symbol}")
        if isinstance(root, At):
            return sp.Float(probe._values(at, body, dps)[0], max(dps, 15) + 5)

        def make(p):
            def f(v):
                trial = probe._solve({**at, root.variable: sp.Float(v, max(p, 15) + 5)}, body, root.roots, p)
                return probe._values(trial, body, p)[0]
            return f
        grid = [g if isinstance(g, float) else float(number(g, at, 15)) for g in root.grid]
        found = grid_roots(make, grid, dps, only=root.which if isinstance(root.which, str) else None)
        if not isinstance(root.which, str):
            found = found[root.which:root.which + 1]
        if not found:
            raise ValueError(f"witness {self.name}: no root of {root.quantity} in {root.variable} on its grid")
        value = sp.Float(found[0], max(dps, 15) + 5)
        if root.guard:
            there = probe._solve({**at, root.variable: value}, body, root.roots, dps, reads=root.guard)
            for item in root.guard:
                if not replace(probe, quantity=item)._values(there, body, dps)[0] > 0:
                    raise ValueError(f"witness {self.name}: {item} is not positive at the root {root.variable} = "
                                     f"{float(value):.6g}")
        return value

    def measure(self, case, method):
        body = self.body if self.body is not None else case.data["body"]
        with mpmath.workdps(max(method.dps, 15)):
            params = self._solve(case.params, body, self.roots, method.dps)
            single = isinstance(self.quantity, sp.Expr)
            items = (self.quantity,) if single else self.quantity
            if not any(measured_names(q) for q in items):
                # the roots alone: no floating state at the end
                values = tuple(_real(number(q, params, method.dps), method.dps) for q in items)
                values = tuple(float(v) if method.dps <= 15 else +v for v in values)
                return values[0] if single else values
        return super().measure(Case(params, case.data, case.label), method)


@dataclass(frozen=True)
class CutWitness(FloatingRootWitness):
    """A :class:`FloatingRootWitness` whose water plane passes through the point ``through`` (body frame, SymPy
    expressions in the case's parameters) normal to ``up``, instead of a given density: the body floats at the
    share of its volume below that plane (the dry part above a water line drawn in a figure, a plane through
    three vertices)."""

    through: tuple = None

    def _values(self, params, body, dps):
        from ..geometry.floating import body_volume_centroid, submerged
        poly = body.build(params, dps)
        u = _unit(tuple(number(x, params, dps) for x in self.up), poly.dps)
        t = _dot(u, tuple(_real(number(x, params, dps), dps) for x in self.through))
        share = submerged(poly, u, t).volume / body_volume_centroid(poly)[0]
        return FloatingWitness._values(replace(self, density=sp.Float(share, max(dps, 15) + 10)), params, body, dps)


__all__ += ["Joined", "waterplane_moment", "Root", "At", "FloatingRootWitness", "CutWitness",
            "potential_slope"]


# ---- the circular cylinder (quadrature of exact slices) and witnesses combined by an expression ----

@dataclass
class Cylinder:
    """A circular cylinder of radius ``r``, axis z from -length/2 to length/2 (G at the origin), in float64
    (``dps`` None) or mpmath.  Floated with up vector u it is turned about its axis so that u lies in the
    meridian plane of :mod:`symfloat.geometry.cylinder`: draught, volume, centre of buoyancy and waterplane
    there by quadrature of exact slices (exact branches upright and lying; base cuts included).
    ``vertices``: the four rim points extreme along the last up vector, the only points that a reading of
    the extreme heights of the body or of a base sees."""

    r: object
    length: object
    dps: int | None = None
    vertices: tuple = ()


def _cylinder_state(cyl, u, s):
    """The :class:`~symfloat.geometry.floating.FloatingState` of a :class:`Cylinder` with *u* (body frame) up
    at density ratio *s*: :func:`symfloat.geometry.cylinder.cylinder_state` in the meridian plane of u, carried
    to the body frame; the waterplane's tensor in the basis (e_theta, e_y), diagonal by symmetry."""
    dps = cyl.dps or 15
    m, zero = (math, 0.0) if cyl.dps is None else (mpmath, mpmath.mpf(0))
    u = tuple(_real(x, dps) for x in u)
    norm = m.sqrt(sum(x * x for x in u))
    u = tuple(x / norm for x in u)
    w = m.sqrt(u[0] ** 2 + u[1] ** 2)
    h = (u[0] / w, u[1] / w) if w > 0 else (zero + 1, zero)             # the meridian's horizontal x
    sign = 1 if u[2] >= 0 else -1                                      # z mirrored when the axis points down
    r, L, s = cyl.r, cyl.length, zero + _real(s, dps)
    c = cylinder_state(r, L, m.atan2(w, abs(u[2])), s, cyl.dps)
    B = (c.Mx / c.V * h[0], c.Mx / c.V * h[1], sign * c.Mz / c.V)
    e1, e2 = (c.cos * h[0], c.cos * h[1], -sign * c.sin), (-h[1], h[0], zero)
    cyl.vertices = tuple((k * r * h[0], k * r * h[1], z) for k in (1, -1) for z in (L / 2, -L / 2))
    potential = -_dot(u, B)
    I_min, I_max = min(c.I_w, c.I_y), max(c.I_w, c.I_y)
    return FloatingState(u, s, c.t, zero, c.V, B, (zero,) * 3, c.area,
                         tuple(c.t * a + c.centre * b for a, b in zip(u, e1)), ((c.I_w, zero), (zero, c.I_y)),
                         (e1, e2), I_min, I_max, potential, I_min / c.V - potential)


@dataclass(frozen=True)
class Loaded(Body):
    """A :class:`Body` whose centre of gravity ``G`` (body frame, SymPy expressions in the case's parameters) is
    given, not its centroid: a body with a light part, such as a prism extended beyond a base that the water
    must not cut (the wall-sided model of a source that lets the water rise above that base)."""

    G: tuple = (0, 0, 0)

    @classmethod
    def of(cls, body, G):
        return cls(body.kind, body.dims, tuple(G))

    def build(self, params, dps):
        return _Built(Body(self.kind, self.dims).build(params, dps), tuple(number(x, params, dps) for x in self.G))


@dataclass(frozen=True)
class _Built:
    """A built body (``poly``) with its centre of gravity ``G``."""

    poly: object
    G: tuple

    @property
    def vertices(self):
        return self.poly.vertices


def _floating_state(body, up, density):
    """The floating state of a built body: a clipped polyhedron (with a given centre of gravity), or a
    :class:`Cylinder`."""
    if isinstance(body, Cylinder):
        return _cylinder_state(body, up, density)
    if isinstance(body, _Built):
        return floating_state(body.poly, up, density, G=body.G)
    return floating_state(body, up, density)


@dataclass(frozen=True)
class Combined(MeasuredWitness):
    """Witnesses measured at the same case (``parts``, one value each) and combined: ``values``, SymPy
    expressions in ``measured("part 1")``, ``measured("part 2")``, ... (the value of each part, in order) and
    the case's parameters, such as the difference of two roots.  ``methods`` defaults to :func:`parts_methods`."""

    parts: tuple = ()
    values: tuple = ()
    methods: tuple = None

    def __post_init__(self):
        if self.methods is None:
            object.__setattr__(self, "methods", parts_methods(self.parts))
        known = {s.name for s in numbered("part", len(self.parts))}
        for e in self.values:
            if not measured_names(e) <= known:
                raise ValueError(f"witness {self.name}: {sorted(measured_names(e) - known)} are not among the "
                                 f"parts measured: {', '.join(sorted(known))}")

    def measure(self, case, method):
        got = {p: part.measure(case, method) for p, part in zip(numbered("part", len(self.parts)), self.parts)}
        with mpmath.workdps(max(method.dps, 15)):
            out = []
            for expr in self.values:
                symbols, f = _compiled(sp.sympify(expr))
                out.append(f(*(got[x] if x in got else _real(number(case.params[x], case.params, method.dps),
                                                                method.dps) for x in symbols)))
            out = tuple(float(v) if method.dps <= 15 else +v for v in out)
        return out[0] if len(out) == 1 else out

    def enclose(self, case, bits):
        """The parts' enclosures combined in ball arithmetic, or ``None`` where a part has none."""
        from .enclosure import ball, exact, working_precision
        got = {}
        for p, part in zip(numbered("part", len(self.parts)), self.parts):
            value = part.enclose(case, bits)
            if value is None or isinstance(value, tuple):
                return None
            with working_precision(bits):                   # an exact part (a hull's Fraction) rounded at bits
                got[p] = value if isinstance(value, arb) else exact(Fraction(value))
        out = tuple(ball(sp.sympify(e).xreplace(case.params), bits, got) for e in self.values)
        return out[0] if len(out) == 1 else out


__all__ += ["Combined", "Loaded"]


# ---- the coefficients of a quantity's expansion in a parameter (a tilt), about a value or a root -----------------
# float64: the nodes h j / N, j = 1 .. N, of h = 0.3, N = 6 (odd), or 0 and +-h j / N of h = 0.05, N = 3, clipped
# in float64 (the coefficients of phi and phi^3 of an arm to about 1e-9 and 1e-6); 50 digits: h = 1e-3, N = 8,
# clipped at 90 digits (about 1e-45)
SERIES_METHODS = (Precision(15, 1e-5), Precision(50, 1e-15))
_SERIES_STEPS = {15: {"odd": (0.3, 6, 15), None: (0.05, 3, 15)}, 50: {"odd": ("1e-3", 8, 90), None: ("1e-3", 8, 90)}}


def series_coefficient(f, k, h, nodes, odd=False):
    """The coefficient of t^k of the polynomial interpolating f at t = h j / nodes, j = 1 .. nodes, in odd powers
    t, t^3, ..., t^(2 nodes - 1) (``odd``, f odd in t), or at t = 0, +-h j / nodes in all powers up to
    t^(2 nodes): the Taylor coefficient of f at 0 up to the interpolation's truncation.  Solved at the current
    mpmath precision.

    >>> import mpmath
    >>> round(float(series_coefficient(mpmath.sin, 3, mpmath.mpf("0.01"), 5, odd=True) * 6), 8)   # sin t = t - t^3/6 ...
    -1.0
    """
    if odd:
        ts = [mpmath.mpf(h) * j / nodes for j in range(1, nodes + 1)]
        powers = [2 * i + 1 for i in range(nodes)]
    else:
        ts = [mpmath.mpf(h) * j / nodes for j in range(-nodes, nodes + 1)]
        powers = list(range(2 * nodes + 1))
    if k not in powers:
        raise ValueError(f"the power {k} is not among the interpolated {powers}")
    A = mpmath.matrix([[t ** p for p in powers] for t in ts])
    c = mpmath.lu_solve(A, mpmath.matrix([mpmath.mpf(f(t)) for t in ts]))
    return c[powers.index(k)]


@dataclass(frozen=True)
class SeriesWitness(FloatingRootWitness):
    """The coefficient of (psi - centre)^k in the expansion of the quantity in the tilt ``series = (psi, k)``,
    ``up`` depending on psi: the quantity at nodes about ``centre`` (an expression in the case's parameters and
    the ``roots``, which are found first, as in :class:`FloatingRootWitness`) interpolated by
    :func:`series_coefficient`; ``odd`` when the quantity is odd about the centre (the arm of a symmetric body
    heeled from its symmetric position), which halves the nodes.  The stability of a position is the coefficient
    of psi in the arm, its departure from the linear theory the coefficient of psi^3 (:data:`SERIES_METHODS`)."""

    series: tuple = None
    centre: object = 0
    odd: bool = False
    methods: tuple = SERIES_METHODS

    def measure(self, case, method):
        body = self.body if self.body is not None else case.data["body"]
        psi, k = self.series
        h, nodes, dps = _SERIES_STEPS[method.dps]["odd" if self.odd else None]
        with mpmath.workdps(max(method.dps, 15)):
            params = self._solve(case.params, body, self.roots, method.dps)
            centre = sp.sympify(self.centre).xreplace(params)
        with mpmath.workdps(max(dps, 30)):
            def f(t):
                at = {**params, psi: sp.Float(centre + sp.Float(t, max(dps, 30) + 5), max(dps, 15) + 5)}
                return self._values(at, body, dps)[0]
            value = series_coefficient(f, k, mpmath.mpf(h), nodes, self.odd)
        with mpmath.workdps(max(method.dps, 15)):
            return float(value) if method.dps <= 15 else +value


__all__ += ["SeriesWitness", "SERIES_METHODS", "series_coefficient"]


# ---- where the water plane crosses a line of the body; the immersed part split at the water line's lowest point ----

def crossing(up, point, direction):
    """The parameter lam at which the water plane meets the body-frame line ``point + lam direction``, as an
    expression in ``measured("water level")`` (t) and the up vector: u . (point + lam direction) = t with
    u = up/|up| gives lam = (|up| t - up . point)/(up . direction).  From a bottom corner up a side of a heeled
    prism, the immersed length of that side."""
    up, point, direction = (sp.Matrix(v) for v in (up, point, direction))
    return (sp.sqrt(up.dot(up)) * measured("water level") - up.dot(point)) / up.dot(direction)


@dataclass(frozen=True)
class Marked(Body):
    """A :class:`Body` (a polyhedron) with a direction marked on it: ``direction`` (body frame, SymPy expressions in
    the case's parameters), the up vector of the position it is heeled from.  The quantities ``lower part ...`` and
    ``upper part ...`` split its immersed part by the plane normal to that direction through the lowest point of
    the water line (a heeled box lying on a face: the rectangle below the lower end of the water line, the
    triangle above it).  An unmarked body is split along the up vector, by the water plane itself: all of the
    immersed part is the lower part."""

    direction: tuple = (0, 0, 1)

    @classmethod
    def of(cls, body, direction):
        return cls(body.kind, body.dims, tuple(direction))

    def build(self, params, dps):
        poly = Body(self.kind, self.dims).build(params, dps)
        if isinstance(poly, Cylinder):
            raise ValueError("a marked body is a polyhedron, not a cylinder")
        return _MarkedBuilt(poly, body_volume_centroid(poly)[1], tuple(number(x, params, dps) for x in self.direction))


@dataclass(frozen=True)
class _MarkedBuilt(_Built):
    """A built polyhedron (``poly``, its centroid ``G``) with its marked ``direction``."""

    direction: tuple


def _split_part(st, body, upper):
    """Volume and moment (volume times the depth of its centroid below the water plane) of the immersed part
    below (``upper`` False) or above the plane normal to the body's marked direction (the up vector when it has
    none) through the lowest point of the water line along that direction."""
    if isinstance(body, Cylinder):
        raise ValueError("the immersed part is split on a polyhedron, not a cylinder")
    poly = body.poly if isinstance(body, _Built) else body
    n = _unit(getattr(body, "direction", st.u), poly.dps)
    level = min(_dot(n, p) for p in submerged(poly, st.u, st.t).waterplane.polygon)
    immersed = clip_below(poly, st.u, st.t)
    part = clip_below(immersed, tuple(-x for x in n), -level) if upper else clip_below(immersed, n, level)
    volume, centroid = volume_centroid(part)
    return volume, (volume * (st.t - _dot(st.u, centroid)) if centroid is not None else volume)


SPLIT_QUANTITIES = {
    "lower part volume": ("volume of the immersed part below the plane normal to the marked direction through the "
                          "lowest point of the water line (Marked)", lambda st, body: _split_part(st, body, False)[0]),
    "lower part moment": ("its volume times the depth of its centroid below the water plane (the work to lift it to "
                          "the surface per unit weight)", lambda st, body: _split_part(st, body, False)[1]),
    "upper part volume": ("volume of the immersed part above that plane (Marked)",
                          lambda st, body: _split_part(st, body, True)[0]),
    "upper part moment": ("its volume times the depth of its centroid below the water plane",
                          lambda st, body: _split_part(st, body, True)[1]),
}
QUANTITIES.update(SPLIT_QUANTITIES)

__all__ += ["crossing", "Marked", "SPLIT_QUANTITIES"]


# ---- the potential's curvature along a turn, derivatives of a quantity along a parameter -----------------------
def potential_curvature(up, variable):
    """d^2E/d(variable)^2 of the potential E = u.(G - B) along a turn of the body about a fixed horizontal axis
    at unit rate (``up(variable)`` a unit vector turning in a plane, so that h = du/dvariable is a unit vector
    and dh/dvariable = -u), as an expression in ``measured(name)``: I_h/V - E, I_h the waterplane's moment about
    its centroidal line along the axis (normal to h).  dE/dvariable = h.(G - B) (:func:`potential_slope`); B
    moves by the wedges, V dB/dvariable = -I_h h along h, so the slope of the righting arm is the metacentric
    height for that axis, at any tilt (an extremum of the arm is a root of it)."""
    up = sp.Matrix(up)
    h = sp.diff(up, variable)
    if sp.simplify(up.dot(up) - 1) != 0 or sp.simplify(sp.diff(h, variable) + up) != sp.zeros(3, 1):
        raise ValueError(f"potential_curvature needs a unit up vector turning at unit rate in {variable}, not {tuple(up)}")
    return waterplane_moment(h, h) / measured("immersed volume") - measured("G above B")


_STENCILS = {1: ((-2, 1), (-1, -8), (1, 8), (2, -1)), 2: ((-2, -1), (-1, 16), (0, -30), (1, 16), (2, -1))}


@dataclass(frozen=True)
class Difference:
    """For the ``roots`` of a :class:`FloatingRootWitness`: the derivative of order 1 or 2 of ``quantity`` (as in
    :class:`Root`) in the parameter ``variable``, at its value in the parameters known so far, by the five-point
    central difference of step ``step`` (a number or an expression in the parameters):
    f' = (f(-2h) - 8 f(-h) + 8 f(h) - f(2h))/(12 h), exact for a polynomial of degree 4, and
    f'' = (-f(-2h) + 16 f(-h) - 30 f(0) + 16 f(h) - f(2h))/(12 h^2), exact for degree 5; else the truncation is
    of order h^4.  ``roots`` are found at each point first (the tilt at which a measured length takes the point's
    value), as in :class:`Root`."""

    quantity: object
    variable: sp.Symbol
    step: object
    order: int = 1
    roots: tuple = ()

    def __post_init__(self):
        in_words(self.quantity, f"Difference in {self.variable}")
        if self.order not in _STENCILS:
            raise ValueError(f"a Difference is of order 1 or 2, not {self.order}")

    def value(self, witness, params, body, dps):
        """The derivative at *params* (a SymPy Float at the method's digits and guard digits)."""
        if self.variable not in params:
            raise ValueError(f"witness {witness.name}: the derivative in {self.variable} needs its value (a case "
                             "parameter or a root found before it)")
        probe = replace(witness, quantity=self.quantity, name=f"{witness.name}: d/d{self.variable}")
        x0, h = sp.sympify(params[self.variable]), sp.sympify(self.step).xreplace(params)

        def f(k):
            there = probe._solve({**params, self.variable: x0 + k * h}, body, self.roots, dps)
            return probe._values(there, body, dps)[0]
        total = sum(w * f(k) for k, w in _STENCILS[self.order])
        return sp.Float(total / (12 * _real(number(h, params, dps), dps) ** self.order), max(dps, 15) + 5)


__all__ += ["potential_curvature", "Difference"]
