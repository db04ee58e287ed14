"""Straightedge constructions as witnesses: a derivation names the points, the lines and what is measured.

A text that proves a ratio by drawing lines (Graefe §3: the centroid of a tetrahedron found by meeting
lines) is witnessed by doing the construction numerically, not by evaluating its formulas.  The points of
a case (``case.data``, exact coordinates in space, named in order by ``names``) are the start; each
further point is made by one operation, in the order given:

* :class:`Mid` ``(p, q)``: the midpoint of p q;
* :class:`Along` ``(p, q, t)``: the point p + t (q - p) of the line p q (``t`` a rational, a third: 1/3);
* :class:`Meet` ``(p1, p2, q1, q2)``: the meeting point of the lines p1 p2 and q1 q2
  (:func:`symfloat.geometry.construction.line_meet`, least squares on the three coordinates);
* :class:`Centroid` ``(p, q, r)``: the centroid of the triangle p q r, as the meeting point of two medians.

The quantity is a measurement or a tuple of them: :class:`Length` ``(p, q)``, :class:`Area` ``(p, q, r)``
(Heron's formula from the three side lengths, :func:`symfloat.geometry.construction.heron_area`),
:class:`Coordinates` ``(p)`` (three values), :class:`Ratio` ``(a, b)`` and :class:`Sum` ``(a, b, ...)``
of measurements.  It is measured in mpmath at 15 and at 50 digits (:data:`CONSTRUCTION_METHODS`):

>>> from fractions import Fraction
>>> from symfloat.engine.witness import Case
>>> w = ConstructionWitness("s", "a right triangle", ("t",), (Case({}, [(0, 0, 0), (3, 0, 0), (0, 4, 0)]),),
...                         names=("P", "Q", "R"), points=(("S", Centroid("P", "Q", "R")),),
...                         quantity=(Area("P", "Q", "R"), Coordinates("S")))
>>> [round(float(v), 12) for v in w.measure(w.instances[0], w.methods[0])]     # 6, and (1, 4/3, 0)
[6.0, 1.0, 1.333333333333, 0.0]
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import mpmath
import sympy as sp
from flint import arb

from ..geometry.construction import heron_area, line_meet
from .enclosure import exact, working_precision
from .witness import MeasuredWitness, Precision

__all__ = ["ConstructionWitness", "CONSTRUCTION_METHODS", "Mid", "Along", "Meet", "Centroid", "Length", "Area",
           "Coordinates", "Ratio", "Sum"]

CONSTRUCTION_METHODS = (Precision(15, 1e-10), Precision(50, 1e-40))


def _mpf(v):
    q = Fraction(v) if not isinstance(v, sp.Basic) else Fraction(int(v.p), int(v.q))
    return mpmath.mpf(q.numerator) / q.denominator


# ---- points ------------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Mid:
    """The midpoint of p q."""

    p: str
    q: str

    def point(self, at):
        return (at[self.p] + at[self.q]) / 2


@dataclass(frozen=True)
class Along:
    """The point p + t (q - p)."""

    p: str
    q: str
    t: object

    def point(self, at):
        return at[self.p] + at.number(self.t) * (at[self.q] - at[self.p])


@dataclass(frozen=True)
class Meet:
    """The meeting point of the lines p1 p2 and q1 q2 (assumed to meet)."""

    p1: str
    p2: str
    q1: str
    q2: str

    def point(self, at):
        return at.meet(at[self.p1], at[self.p2], at[self.q1], at[self.q2])


@dataclass(frozen=True)
class Centroid:
    """The centroid of the triangle p q r: the median from p meets the median from q."""

    p: str
    q: str
    r: str

    def point(self, at):
        return at.meet(at[self.p], (at[self.q] + at[self.r]) / 2, at[self.q], (at[self.p] + at[self.r]) / 2)


# ---- measurements -------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Length:
    """The distance of p and q."""

    p: str
    q: str

    def values(self, at):
        return (at.norm(at[self.p] - at[self.q]),)


@dataclass(frozen=True)
class Area:
    """The area of the triangle p q r by Heron's formula."""

    p: str
    q: str
    r: str

    def values(self, at):
        return (at.area(at[self.p], at[self.q], at[self.r]),)


@dataclass(frozen=True)
class Coordinates:
    """The three coordinates of p."""

    p: str

    def values(self, at):
        return tuple(at[self.p])


@dataclass(frozen=True)
class Ratio:
    """The ratio of two (one-valued) measurements."""

    a: object
    b: object

    def values(self, at):
        return (self.a.values(at)[0] / self.b.values(at)[0],)


@dataclass(frozen=True, init=False)
class Sum:
    """The sum of (one-valued) measurements."""

    terms: tuple

    def __init__(self, *terms):
        object.__setattr__(self, "terms", terms)

    def values(self, at):
        return (sum(t.values(at)[0] for t in self.terms),)


@dataclass(frozen=True)
class ConstructionWitness(MeasuredWitness):
    """The quantity of a construction (see the module) at each case."""

    names: tuple = ()
    points: tuple = ()
    quantity: object = None
    methods: tuple = CONSTRUCTION_METHODS

    def measure(self, case, method):
        with mpmath.workdps(method.dps):
            return self._built(case, _Points(_mpf, lambda p: mpmath.matrix([_mpf(v) for v in p]), line_meet,
                                             heron_area, mpmath.norm))

    def enclose(self, case, bits):
        """The construction in Arb balls: every point, length and area an enclosure."""
        with working_precision(bits):
            return self._built(case, _Points(_exact, lambda p: _Vector(_exact(v) for v in p), _ball_meet,
                                             _ball_heron, _ball_norm))

    def _built(self, case, at):
        for name, p in zip(self.names, case.data):
            at[name] = at.vector(p)
        for name, op in self.points:
            at[name] = op.point(at)
        items = self.quantity if isinstance(self.quantity, tuple) else (self.quantity,)
        values = tuple(v for item in items for v in item.values(at))
        return values if isinstance(self.quantity, tuple) or len(values) > 1 else values[0]


class _Points(dict):
    """The points of a construction by name, with the arithmetic they are measured in: ``number`` (an exact
    coordinate or parameter as a number), ``vector``, ``meet`` (two lines' meeting point), ``area`` (Heron's
    formula) and ``norm``."""

    def __init__(self, number, vector, meet, area, norm):
        super().__init__()
        self.number, self.vector, self.meet, self.area, self.norm = number, vector, meet, area, norm


class _Vector(tuple):
    """A point in space as three Arb balls, with the vector arithmetic the operations use."""

    def __new__(cls, items):
        return super().__new__(cls, tuple(items))

    def __add__(self, other):
        return _Vector(a + b for a, b in zip(self, other))

    def __sub__(self, other):
        return _Vector(a - b for a, b in zip(self, other))

    def __mul__(self, k):
        return _Vector(a * k for a in self)

    __rmul__ = __mul__

    def __truediv__(self, k):
        return _Vector(a / k for a in self)


def _exact(v):
    return exact(Fraction(v) if not isinstance(v, sp.Basic) else Fraction(int(v.p), int(v.q)))


def _dot(u, v):
    return sum((a * b for a, b in zip(u, v)), arb(0))


def _ball_norm(v):
    return _dot(v, v).sqrt()


def _ball_heron(p, q, r):
    """Heron's formula (:func:`~symfloat.geometry.construction.heron_area`) in balls."""
    x, y, w = _ball_norm(p - q), _ball_norm(q - r), _ball_norm(r - p)
    half = (x + y + w) / 2
    return (half * (half - x) * (half - y) * (half - w)).sqrt()


def _ball_meet(p1, p2, q1, q2):
    """The least-squares meeting point of the lines p1 p2 and q1 q2 (:func:`~symfloat.geometry.construction.line_meet`)
    in balls: ``p1 + s d`` with ``d = p2 - p1``, ``e = q2 - q1``, ``w = q1 - p1`` and
    ``s = ((d·w)(e·e) - (e·w)(d·e)) / ((d·d)(e·e) - (d·e)²)``, the normal equations solved by Cramer's rule."""
    d, e, w = p2 - p1, q2 - q1, q1 - p1
    de = _dot(d, e)
    s = (_dot(d, w) * _dot(e, e) - _dot(e, w) * de) / (_dot(d, d) * _dot(e, e) - de * de)
    return p1 + d * s
