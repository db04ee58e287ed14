"""The definition route in ball arithmetic: a reading's members, the definitions inserted, as Arb balls.

At each sample point of the route (exact rationals) every member is evaluated by
:func:`~symfloat.engine.enclosure.ball`, each defining integral closed at the point by
:func:`~symfloat.engine.enclosure.iterated_integral` (``acb.integral``, rigorous error bounds; a multiple
integral as nested ones) and inserted as a ball, the smallest first (a centroid inside a moment's integrand).
The enclosure of each difference *claimed - measured* decides the formula as a declared witness's does
(:func:`~symfloat.engine.witness.record_decision`): agreed when it is proven within the width the
precision asks, refuted when proven away from 0, else the precision is doubled from
:data:`~symfloat.engine.witness.START_BITS` up to 8 times it.

An integral in another's integrand that depends on the outer variable, one factor of a term, is made one
iterated integral with it (:func:`_merged`).  There is no rigorous rule
(:class:`~symfloat.engine.enclosure.Unsupported`, the route then compares its methods as before) for a limit
left to extrapolation, a root count, an integral nested in another's integrand otherwise, a node without a
ball rule (a piecewise function), and for an integrand that has no finite enclosure at the first precision
(not holomorphic near its path, or the integrator's evaluations run out).

>>> import sympy as sp
>>> x, a = sp.symbols("x a", positive=True)
>>> area = sp.Integral(2 * sp.sqrt(a ** 2 - x ** 2), (x, -a, a))     # a disc of radius a
>>> record = route_enclosure([area], [[sp.pi * a ** 2]], [{a: sp.Rational(1, 2)}])
>>> record["method"], record["bits"], record["abs_error"] < 1e-30
('Arb ball arithmetic', 128, True)
>>> route_enclosure([area], [[3 * a ** 2]], [{a: sp.Rational(1, 2)}])["abs_error_lower"] > 0.03
True
"""
from __future__ import annotations

import math
import time
from fractions import Fraction

import sympy as sp
from flint import arb, ctx

from ..model.relation import RealRoots
from .enclosure import Unsupported, ball, exact, iterated_integral, lower, upper, working_precision
from .witness import CERTIFIED, START_BITS, record_decision

__all__ = ["route_enclosure", "definition_ball"]

GUARD_BITS = 32         # each ball is computed with these bits more than the decision asks


def definition_ball(expr, point: dict, bits: int) -> arb:
    """*expr* (a member with the definitions inserted, derivatives carried out) at *point* as a ball, its closed
    integrals by ``acb.integral`` (see the module); non-finite where an integral has no finite enclosure."""
    from .definitions import NumericLimit
    e = _replaced(_bound_apart(sp.sympify(expr)), point)
    if e.has(NumericLimit):
        raise Unsupported("a limit left to extrapolation")
    if e.has(RealRoots):
        raise Unsupported("a root count")
    prec = bits + GUARD_BITS
    balls: dict = {}
    while e.has(sp.Integral):
        closed = [i for i in e.atoms(sp.Integral)
                  if not i.function.has(sp.Integral) and i.free_symbols <= set(balls)]
        if not closed:          # an integral in another's integrand that depends on the outer variable
            merged = {i: m for i in e.atoms(sp.Integral)
                      if i.function.has(sp.Integral) and (m := _merged(i)) is not None}
            if not merged:
                raise Unsupported("an integral nested in another's integrand")
            e = _replaced(e, merged)
            continue
        for i in sorted(closed, key=sp.count_ops):
            if any(len(limit) != 3 for limit in i.limits):
                raise Unsupported("an integral without its ends")
            if any((lo.free_symbols | hi.free_symbols) & set(balls) for _, lo, hi in i.limits):
                raise Unsupported("an integral whose bounds are integrals")
            value = iterated_integral(i.function, i.limits, prec, at={d: balls[d] for d in i.free_symbols})
            if not value.is_finite():
                return arb.nan()
            d = sp.Symbol(f"·integral {len(balls)}")
            balls[d] = value
            e = _replaced(e, {i: d})
    try:
        return ball(e, prec, at=balls)
    except Unsupported:
        raise
    except ValueError as exc:          # a complex value: the 30-digit quadrature's own check reads it
        raise Unsupported(str(exc)) from exc


def _merged(i: sp.Integral):
    """``∫ Σ c_k(s) J_k(s) ds``, each ``J_k = ∫ h_k(η, s) dη`` an integral whose integrand holds none (or
    absent), as the sum of the iterated integrals ``∫∫ c_k h_k dη ds`` (SymPy's multiple integral, the inner ends
    as they were); ``None`` where a term holds an integral otherwise than as one such factor."""
    parts = []
    for term in sp.Add.make_args(i.function):
        factors = sp.Mul.make_args(term)
        inner = [f for f in factors if isinstance(f, sp.Integral)]
        rest = [f for f in factors if not isinstance(f, sp.Integral)]
        if len(inner) > 1 or any(f.has(sp.Integral) for f in (*rest, *(j.function for j in inner))):
            return None
        if inner:
            parts.append(sp.Integral(sp.Mul(*rest, inner[0].function, evaluate=False), *inner[0].limits, *i.limits))
        else:
            parts.append(sp.Integral(term, *i.limits))
    return sp.Add(*parts, evaluate=False) if len(parts) > 1 else parts[0]


def _replaced(expr, mapping: dict):
    """*expr* with the nodes of *mapping* replaced and nothing evaluated: a sum, product, power or function is
    rebuilt with ``evaluate=False`` (SymPy's arithmetic on the exact point would factor a rational under a root;
    the balls do the arithmetic).  The flag is passed to each constructor, never set globally with
    ``sp.evaluate``: SymPy's cache would keep those unevaluated nodes and hand them to later callers."""
    if expr in mapping:
        return mapping[expr]
    if not expr.args or not any(expr.has(k) for k in mapping):
        return expr
    args = [_replaced(a, mapping) for a in expr.args]
    if isinstance(expr, (sp.Add, sp.Mul, sp.Pow, sp.Function)):
        return expr.func(*args, evaluate=False)
    return expr.func(*args)


def _bound_apart(expr):
    """*expr* with each integral's variable renamed (``y·bound``, a name no derivation writes), so that a point
    naming the same symbol as a parameter does not replace it (the definition of a section integrates over a
    symbol the derivation also samples)."""
    def apart(i):
        return i.xreplace({lim[0]: sp.Symbol(f"{lim[0].name}·bound", **lim[0].assumptions0) for lim in i.limits})
    return expr.replace(lambda e: isinstance(e, sp.Integral), apart) if expr.has(sp.Integral) else expr


def route_enclosure(measured: list, claims: list, points: list, allowance=None):
    """The certified record of the claims against the measured components at *points*, at the first precision
    that decides (or the last tried), *allowance* (a printed number's rounding, a SymPy rational) its
    ``abs_tolerance``; ``None`` where an integral has no finite enclosure at the first precision (its integrand
    not holomorphic near the path, or the integrator's evaluations run out: more bits would not help).  Raises
    :class:`~symfloat.engine.enclosure.Unsupported` for a member without a rigorous rule."""
    t0 = time.perf_counter()
    bits = START_BITS
    try:
        while True:
            record = _at(measured, claims, points, bits, allowance)
            if record is None:      # an integral with no finite enclosure: more bits ask it more, not less
                return None
            if record_decision(record) != "undecided" or bits * 2 > 8 * START_BITS:
                break
            bits *= 2
    finally:
        # FLINT keeps pi and the integrator's Gauss-Legendre nodes at the highest precision asked so far, and
        # rounds later requests from them: left filled at this route's precisions, they would change the last
        # bits of the next derivation's enclosures with the order in which a worker checks derivations
        ctx.cleanup()
    record["seconds"] = time.perf_counter() - t0
    return record


def _at(measured, claims, points, bits, allowance):
    """The certified record at *bits* (see :func:`route_enclosure`); ``None`` where a member has no finite
    ball.  The width allowed is ``2^(-bits/2)`` of the largest number met, as for a
    declared witness (:meth:`~symfloat.engine.witness.MeasuredWitness._bounds`): the point's, the members'
    values, and the numbers the members write (a moment that vanishes at a point without parameters,
    ``∫∫ (q - 1/3) dq dp = 0``, is still measured against its ``1/3``)."""
    worst_upper = worst_lower = worst_rel = 0.0
    width = math.inf
    written = [abs(float(n)) for e in (*measured, *(c for claimed in claims for c in claimed))
               for n in sp.sympify(e).atoms(sp.Number)]
    with working_precision(bits):
        for point in points:
            here = [definition_ball(e, point, bits) for e in measured]
            if not all(m.is_finite() for m in here):
                return None
            for claimed in claims:
                values = [definition_ball(c, point, bits) for c in claimed]
                if not all(c.is_finite() for c in values):
                    return None
                sizes = [upper(abs(v)) for v in (*here, *values)]
                sizes += [abs(float(v)) for v in point.values()] + written
                width = min(width, math.ldexp(max(sizes, default=0.0), -bits // 2))
                for m, c in zip(here, values):
                    d = c - m
                    worst_upper, worst_lower = max(worst_upper, upper(d)), max(worst_lower, lower(d))
                    size = upper(abs(c))
                    worst_rel = max(worst_rel, upper(d) / size if size else upper(d))
    return {"method": CERTIFIED, "certified": True, "bits": bits, "abs_error": worst_upper,
            "abs_error_lower": worst_lower, "rel_error": worst_rel, "width": width if math.isfinite(width) else 0.0,
            "abs_tolerance": 0.0 if allowance is None else upper(exact(Fraction(int(allowance.p), int(allowance.q)))),
            "cases": len(points)}
