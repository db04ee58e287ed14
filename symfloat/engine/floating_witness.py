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
...                     body=Body.box(1, 1, 1), up=(0, 0, 1), density=rho, quantity="draught")
>>> [round(float(w.measure(w.instances[0], m)), 12) for m in w.methods]     # Archimedes: s * 1 / 1
[0.333333333333, 0.333333333333]
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import mpmath
import sympy as sp

from ..geometry.floating import box, floating_state, regular_prism, right_prism
from .witness import MeasuredWitness, Precision

__all__ = ["Body", "FloatingWitness", "QUANTITIES", "FLOATING_METHODS"]

FLOATING_METHODS = (Precision(15, 1e-9), Precision(40, 1e-30))


def number(expr, params, dps):
    """The value of a SymPy expression at *params*: a :class:`Fraction` when it is rational (the geometry
    then works with the exact value), else a float (``dps`` 15) or an mpf at ``dps`` digits."""
    v = sp.sympify(expr).xreplace(params)
    if v.free_symbols:
        raise ValueError(f"a floating witness needs a number, {expr} is {v} at {params}")
    if v.is_Rational:
        return Fraction(int(v.p), int(v.q))
    if dps <= 15:
        return float(sp.N(v, 30))
    return mpmath.mpf(sp.N(v, dps + 10))


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

    def build(self, params, dps):
        """The :class:`~symfloat.geometry.floating.Polyhedron` at *params*, float64 (``dps`` 15) or mpmath."""
        prec = None if dps <= 15 else dps
        at = lambda e: number(e, params, dps)      # noqa: E731
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
}


@dataclass(frozen=True)
class FloatingWitness(MeasuredWitness):
    """A quantity of :data:`QUANTITIES` of ``body`` floating at ``density`` with ``up`` (body frame, SymPy
    expressions in the case's parameters) pointing up; ``quantity`` may also be a tuple of names, for
    targets whose reading lists several numbers."""

    body: Body = None
    up: tuple = (0, 0, 1)
    density: object = None
    quantity: object = "draught"
    methods: tuple = FLOATING_METHODS

    def __post_init__(self):
        for q in (self.quantity,) if isinstance(self.quantity, str) else self.quantity:
            if q not in QUANTITIES:
                raise ValueError(f"witness {self.name}: unknown quantity {q!r}; known: {', '.join(QUANTITIES)}")

    def measure(self, case, method):
        dps = method.dps
        with mpmath.workdps(max(dps, 15)):
            body = self.body.build(case.params, dps)
            up = tuple(number(x, case.params, dps) for x in self.up)      # the geometry normalises it
            st = floating_state(body, up, number(self.density, case.params, dps))
            if isinstance(self.quantity, str):
                return QUANTITIES[self.quantity][1](st, body)
            return tuple(QUANTITIES[q][1](st, body) for q in self.quantity)
