"""Plane-figure witnesses: a derivation names the figure, the integrand and the cases; nothing else.

A waterplane (or any plane figure) is measured by what defines its moments, ``∫∫ f dA`` over the figure:

* ``Figure.polygon(vertices)``: exact polygon integrals (Green's theorem, edge by edge) of
  :func:`symfloat.geometry.floating.polygon_moments`, the one implementation of polygon moments: the area,
  the centroid and the central second moments, from which every polynomial integrand of degree at most two
  is integrated (``∫∫ x² = J_xx + A x_C²`` and so on);
* ``Figure.strips(across, along, lo, hi, ends)``: a curved figure swept by chords, for ``along`` from ``lo``
  to ``hi`` the chord ``across`` from ``ends[0]`` to ``ends[1]`` (a waterplane given by its half-breadth
  function): the chord by Gauss–Legendre (three nodes, exact for an integrand of degree at most five
  across), along the chords by quadrature, ``breaks`` where an end has a kink;
* ``Figure.interval(var, lo, hi)``: a segment, for a one-dimensional ``∫ f dvar``.

Two arithmetics (:data:`FIGURE_METHODS`): float64 (strips by 64-point Gauss–Legendre on each piece after
the substitution ``t = lo + (hi - lo) s(w)``, ``s(w) = w²(3 - 2w)`` (``smooth=2``, the default) or
``w⁴(35 - 84w + 70w² - 20w³)`` (``smooth=4``), whose derivative vanishes to first or third order at both
ends: ends like ``√(b - y)`` or ``1/√(b - y)`` become smooth with ``smooth=2``, ``(1 - yⁿ)^κ`` with κ a
multiple of 1/4 with ``smooth=4``, at the price of the digits of ``b - y`` lost next to the end), and mpmath
at 50 digits (strips by tanh-sinh).

A quantity is a SymPy expression in ``measured("integral", of=f)`` (the integral of ``f``, an expression in
the figure's coordinates ``coords``, the case's parameters and the centroid, over the figure), the centroid
``measured("centroid, 1")``, ``measured("centroid, 2")`` (along ``coords[0]``, ``coords[1]``) and the case's
parameters, or a tuple of them (:mod:`symfloat.engine.measured`):

>>> import sympy as sp
>>> from symfloat.engine.measured import measured
>>> from symfloat.engine.witness import Case
>>> x, y, a = sp.symbols("x y a")
>>> w = FigureWitness("I", "∫∫ y² over the square", ("t",), (Case({a: 1}),), coords=(x, y),
...                   figure=Figure.polygon([(-a, -a), (a, -a), (a, a), (-a, a)]),
...                   quantity=measured("integral", of=y ** 2))
>>> [round(float(w.measure(w.instances[0], m)), 14) for m in w.methods]     # 4 a⁴/3
[1.33333333333333, 1.33333333333333]
"""
from __future__ import annotations

import functools
import math
from fractions import Fraction
from dataclasses import dataclass

import mpmath
import numpy as np
import sympy as sp
from flint import arb

from ..geometry.floating import polygon_moments
from .floating_witness import _real, number
from .measured import Measured, MeasuredIntegral, measured_names
from .roots import grid_roots
from .enclosure import Unsupported, ball, integral, real_function, sign_change_root, working_precision
from .witness import MeasuredWitness, Precision

__all__ = ["Figure", "FigureWitness", "FIGURE_METHODS", "CurveRoot"]

FIGURE_METHODS = (Precision(15, 1e-10), Precision(50, 1e-40))
_CENTROID = (Measured("centroid, 1"), Measured("centroid, 2"))     # along coords[0], coords[1]


@dataclass(frozen=True)
class Figure:
    """A plane figure whose data are SymPy expressions in a case's parameters (see the module)."""

    kind: str
    data: tuple
    smooth: int = 2

    @classmethod
    def polygon(cls, vertices):
        """A counter-clockwise or clockwise polygon ``[(x, y), ...]`` in the witness's ``coords``."""
        return cls("polygon", tuple(tuple(sp.sympify(c) for c in p) for p in vertices))

    @classmethod
    def strips(cls, across, along, lo, hi, ends, breaks=(), smooth=2):
        """The chords ``ends[0] <= across <= ends[1]`` (expressions in ``along``) for ``lo <= along <= hi``."""
        return cls("strips", (across, along, sp.sympify(lo), sp.sympify(hi), tuple(sp.sympify(e) for e in ends),
                              tuple(sp.sympify(b) for b in breaks)), smooth)

    @classmethod
    def interval(cls, var, lo, hi, breaks=(), smooth=2):
        """The segment ``lo <= var <= hi``: the integral of ``f`` over it is the one-dimensional ``∫ f dvar``."""
        return cls("interval", (var, sp.sympify(lo), sp.sympify(hi), tuple(sp.sympify(b) for b in breaks)), smooth)


# ---- polygons: exact polygon integrals -----------------------------------------------------------------------

def _polygon_integral(vertices, f, coords, dps):
    """∫∫ f over the polygon, f a polynomial of degree <= 2 in *coords* with numeric coefficients: from the
    area A, centroid c and central moments J of :func:`polygon_moments`, ∫∫ x^i y^j for i + j <= 2."""
    raw = _monomial_integrals([tuple(_real(v, dps) for v in p) for p in vertices])
    return sum(_coefficient(k, dps) * raw[m] for m, k in _quadratic_terms(f, coords))


def _monomial_integrals(ring):
    """∫∫ x^i y^j over the polygon *ring* for i + j <= 2, keyed by (i, j), in the arithmetic of its vertices."""
    area, (cx, cy), ((jxx, jxy), (_, jyy)) = polygon_moments(ring)
    if area < 0:                                       # a clockwise ring: the same figure
        area, jxx, jxy, jyy = -area, -jxx, -jxy, -jyy
    return {(0, 0): area, (1, 0): area * cx, (0, 1): area * cy, (2, 0): jxx + area * cx * cx,
            (1, 1): jxy + area * cx * cy, (0, 2): jyy + area * cy * cy}


def _quadratic_terms(f, coords):
    """The terms ((i, j), coefficient) of f, a polynomial of degree <= 2 in *coords*."""
    poly = sp.Poly(sp.expand(f), *coords)
    if poly.total_degree() > 2:
        raise ValueError(f"a polygon's integrals are exact up to degree 2, not for {f}")
    return poly.terms()


def _coefficient(k, dps):
    if not k.free_symbols:
        return _real(number(k, {}, dps), dps)
    raise ValueError(f"a polygon integrand's coefficient {k} is not a number at the case")


def _polygon_centroid(vertices, dps):
    ring = [tuple(_real(v, dps) for v in p) for p in vertices]
    return polygon_moments(ring)[1]


# ---- strips: the chord by Gauss-Legendre, along the chords by quadrature ------------------------------------

_CHORD = {15: np.polynomial.legendre.leggauss(3)}
_ALONG = np.polynomial.legendre.leggauss(64)


def _chord_rule(dps):
    if dps <= 15:
        return [(float(t), float(w)) for t, w in zip(*_CHORD[15])]
    r = mpmath.sqrt(mpmath.mpf(3) / 5)
    return [(-r, mpmath.mpf(5) / 9), (mpmath.mpf(0), mpmath.mpf(8) / 9), (r, mpmath.mpf(5) / 9)]


def _smooth(w, order):
    """The substitution of the float64 rule: 0 -> 0, 1 -> 1, its derivative vanishing to order - 1 at both ends."""
    if order == 2:
        return w * w * (3 - 2 * w), 6 * w * (1 - w)
    return w ** 4 * (35 - 84 * w + 70 * w * w - 20 * w ** 3), 140 * w ** 3 * (1 - w) ** 3


def _integrate_along(g, points, dps, order):
    """∫ g over the pieces between *points*: tanh-sinh at dps digits, or float64 Gauss-Legendre after
    :func:`_smooth`."""
    if dps > 15:
        return mpmath.quad(g, points)
    total = 0.0
    nodes, weights = _ALONG
    for lo, hi in zip(points, points[1:]):
        for t, w in zip(nodes, weights):
            s, ds = _smooth((t + 1) / 2, order)
            total += w / 2 * ds * (hi - lo) * g(lo + (hi - lo) * s)
    return total


@functools.lru_cache(maxsize=512)
def _compiled(expr, symbols, module):
    return sp.lambdify(symbols, expr, module)


def _strips_integral(figure, f, dps):
    """∫∫ f over a figure of strips (or ∫ f over an interval), its data and f free of the case's parameters.
    At ``dps`` > 15 the quadrature runs at twice the digits: tanh-sinh puts nodes so close to the ends that
    ``b - y`` (under a root) keeps its digits only so."""
    if dps > 15:
        with mpmath.workdps(2 * dps):
            return _strips_integral_at(figure, f, 2 * dps)
    return _strips_integral_at(figure, f, dps)


def _strips_integral_at(figure, f, dps):
    module = "mpmath" if dps > 15 else "math"
    num = lambda e: _real(number(e, {}, dps), dps)                  # noqa: E731
    if figure.kind == "interval":
        var, lo, hi, breaks = figure.data
        g = _compiled(f, (var,), module)
        return _integrate_along(g, sorted([num(lo), *map(num, breaks), num(hi)]), dps, figure.smooth)
    across, along, lo, hi, ends, breaks = figure.data
    e0, e1 = (_compiled(e, (along,), module) for e in ends)
    h = _compiled(f, (across, along), module)
    rule = _chord_rule(dps)

    def chord(t):
        lo_, hi_ = e0(t), e1(t)
        half, mid = (hi_ - lo_) / 2, (hi_ + lo_) / 2
        return half * sum(w * h(mid + half * u, t) for u, w in rule)
    return _integrate_along(chord, sorted([num(lo), *map(num, breaks), num(hi)]), dps, figure.smooth)


# ---- the witness ----------------------------------------------------------------------------------------------

_MEASURED = {}      # (figure, integrand, digits) -> value: shared by the witnesses of a module


def _at(expr, params):
    return sp.sympify(expr).xreplace(params)


@dataclass(frozen=True)
class FigureWitness(MeasuredWitness):
    """The quantity (an expression in ``measured("integral", of=f)``, ``measured("centroid, 1")``,
    ``measured("centroid, 2")`` and the case's parameters, or a tuple of them) of ``figure`` at each case, in
    the plane of ``coords``: see the module."""

    figure: Figure = None
    coords: tuple = ()
    quantity: object = None
    methods: tuple = FIGURE_METHODS

    def __post_init__(self):
        items = self.quantity if isinstance(self.quantity, tuple) else (self.quantity,)
        known = {s.name for s in _CENTROID}
        for q in items:
            names = measured_names(q)                   # an integrand's among them
            if not names <= known:
                raise ValueError(f"witness {self.name}: {sorted(names - known)} are not measured on a figure; "
                                 f"known: measured('integral', of=f), {', '.join(sorted(known))}")

    def _integral(self, figure, f, dps):
        key = (figure, f, dps)
        if key not in _MEASURED:
            if figure.kind == "polygon":
                _MEASURED[key] = _polygon_integral(figure.data, f, self.coords, dps)
            else:
                _MEASURED[key] = _strips_integral(figure, f, dps)
        return _MEASURED[key]

    def _centroid(self, figure, dps):
        if figure.kind == "polygon":
            return _polygon_centroid(figure.data, dps)
        area = self._integral(figure, sp.Integer(1), dps)
        return tuple(self._integral(figure, c, dps) / area for c in self.coords)

    def _item(self, q, figure, params, dps):
        q = sp.sympify(q)
        values = {}
        if q.free_symbols & set(_CENTROID):
            values.update({s: sp.Float(v, max(dps, 15) + 5) for s, v in zip(_CENTROID, self._centroid(figure, dps))})
        for atom in q.atoms(MeasuredIntegral):
            values[atom] = sp.Float(self._integral(figure, _at(_at(atom.args[0], params), values), dps),
                                    max(dps, 15) + 5)
        value = _at(_at(q, values), params)
        return _real(number(value, {}, dps), dps)

    def measure(self, case, method):
        dps = method.dps
        with mpmath.workdps(max(dps, 15) + 5):
            figure = Figure(self.figure.kind, tuple(_at_deep(x, case.params) for x in self.figure.data),
                            self.figure.smooth)
            items = self.quantity if isinstance(self.quantity, tuple) else (self.quantity,)
            values = tuple(self._item(q, figure, case.params, dps) for q in items)
        with mpmath.workdps(max(dps, 15)):
            values = tuple(float(v) if dps <= 15 else +mpmath.mpf(v) for v in values)
        return values if isinstance(self.quantity, tuple) else values[0]


    def enclose(self, case, bits):
        """The quantity in Arb: a polygon's integrals and centroid exact (:func:`polygon_moments` in SymPy
        numbers), a strip figure's or an interval's by ``acb.integral`` along (the chord by the three-node
        Gauss–Legendre rule with the exact nodes 0, ±√(3/5), exact for an integrand of degree at most five
        across; another integrand is :class:`~symfloat.engine.enclosure.Unsupported`: undecided)."""
        figure = Figure(self.figure.kind, tuple(_at_deep(x, case.params) for x in self.figure.data),
                        self.figure.smooth)
        items = self.quantity if isinstance(self.quantity, tuple) else (self.quantity,)
        values = tuple(self._enclosed_item(sp.sympify(q).xreplace(case.params), figure, bits) for q in items)
        return values if isinstance(self.quantity, tuple) else values[0]

    def _enclosed_item(self, q, figure, bits):
        if figure.kind == "polygon":          # exact: every integral a SymPy number
            centroid = dict(zip(_CENTROID, polygon_moments([tuple(p) for p in figure.data])[1]))
            exact_q = q.xreplace({atom: _polygon_exact(figure.data, atom.args[0].xreplace(centroid), self.coords)
                                  for atom in q.atoms(MeasuredIntegral)}).xreplace(centroid)
            return Fraction(int(exact_q.p), int(exact_q.q)) if exact_q.is_Rational else ball(exact_q, bits)
        at = {}
        if q.free_symbols & set(_CENTROID) or any(a.free_symbols & set(_CENTROID) for a in q.atoms(MeasuredIntegral)):
            area = _enclosed_integral(figure, sp.Integer(1), bits, {})
            with working_precision(bits):
                at = {s: _enclosed_integral(figure, c, bits, {}) / area for s, c in zip(_CENTROID, self.coords)}
        over = {atom: sp.Dummy() for atom in q.atoms(MeasuredIntegral)}
        values = {over[atom]: _enclosed_integral(figure, atom.args[0], bits, at) for atom in over}
        return ball(q.xreplace(over), bits, {**at, **values})


def _polygon_exact(vertices, f, coords):
    """∫∫ f over the polygon, exactly (f a polynomial of degree <= 2 in *coords*, see :func:`_polygon_integral`)."""
    raw = _monomial_integrals([tuple(p) for p in vertices])
    return sum(k * raw[m] for m, k in _quadratic_terms(f, coords))


def _enclosed_integral(figure, f, bits, at):
    """∫∫ f over a figure of strips (∫ f over an interval) as a ball, *at* the balls of the centroid."""
    if figure.kind == "interval":
        var, lo, hi, breaks = figure.data
        integrand = f
    else:
        across, var, lo, hi, ends, breaks = figure.data
        try:
            degree = sp.Poly(f, across).degree()
        except sp.PolynomialError:
            degree = None
        if degree is None or degree > 5:
            raise Unsupported(f"the integrand {f} is no polynomial of degree at most 5 across the chords")
        antiderivative = sp.integrate(sp.Poly(f, across).as_expr(), across)     # a polynomial's: exact
        integrand = antiderivative.xreplace({across: ends[1]}) - antiderivative.xreplace({across: ends[0]})
    points = sorted([lo, *breaks, hi], key=lambda e: float(e))
    with working_precision(bits):
        return sum((integral(_signed(integrand, var, a, b), var, a, b, bits, at) for a, b in zip(points, points[1:])),
                   arb(0))


def _signed(expr, var, a, b):
    """*expr* on the piece ``[a, b]`` with ``|var|`` written as ``var`` or ``-var`` where the piece fixes its sign
    (a break at 0 is there for that): holomorphic then, where ``|var|`` is not at the piece's end 0."""
    sign = 1 if a >= 0 else -1 if b <= 0 else 0
    return expr.xreplace({sp.Abs(var): sign * var}) if sign else expr


def _at_deep(x, params):
    """*x* (an expression, a symbol naming a coordinate, or nested tuples of them) at the case's parameters."""
    if isinstance(x, tuple):
        return tuple(_at_deep(v, params) for v in x)
    return _at(x, params)


@dataclass(frozen=True)
class CurveRoot(MeasuredWitness):
    """A point of a curve given implicitly: the root in ``variable`` of ``equation`` (a SymPy expression in it
    and the case's parameters, zero on the curve) on ``bracket``, scanned with ``steps`` points and refined
    (:func:`symfloat.engine.roots.grid_roots`) in float64 and at 50 digits."""

    equation: sp.Expr = None
    variable: sp.Symbol = None
    bracket: tuple = (0, 1)
    steps: int = 16
    methods: tuple = FIGURE_METHODS

    def measure(self, case, method):
        dps = method.dps
        expr = _at(self.equation, case.params)
        with mpmath.workdps(max(dps, 15) + 10):
            lo, hi = (float(number(_at(b, case.params), {}, 15)) for b in self.bracket)

        def make(p):
            g = _compiled(expr, (self.variable,), "mpmath" if p > 15 else "math")
            return lambda v: g(mpmath.mpf(v) if p > 15 else float(v))
        grid = [lo + (hi - lo) * k / self.steps for k in range(self.steps + 1)]
        with mpmath.workdps(max(dps, 15) + 10):
            roots = grid_roots(make, grid, dps, only="first")
        if not roots:
            raise ValueError(f"witness {self.name}: no root of {self.equation} on {self.bracket}")
        with mpmath.workdps(max(dps, 15)):
            return float(roots[0]) if dps <= 15 else +mpmath.mpf(roots[0])

    def enclose(self, case, bits):
        """The float64 root (which root: the scan's first) exact where the equation vanishes there in exact
        arithmetic (its binary value substituted into an equation without Floats, whose SymPy arithmetic would
        round): a root that touches zero without a sign change, the section through the vertex of a body,
        ``(x'/a)^2 + (t/c)^2 - 1`` at ``x' = a``, ``t = 0``.  Else proven by a sign change of the equation in
        balls at ``±2^-40 (1 + |root|)`` around it and narrowed by bisection
        (:func:`~symfloat.engine.enclosure.sign_change_root`); non-finite (undecided) without that sign change."""
        root = self.measure(case, FIGURE_METHODS[0])
        equation = _at(self.equation, case.params)
        if not equation.has(sp.Float) and equation.xreplace({self.variable: sp.Rational(root)}) == 0:
            return Fraction(root)
        f = real_function(equation, (self.variable,))
        step = math.ldexp(1 + abs(root), -40)
        return sign_change_root(f, root - step, root + step, bits)

