"""A relation at a rational point, decided by the sign of its sides' difference at 60 digits.

``lhs < rhs`` (or ``<=``, ``>``, ``>=``, ``=``, ``!=``) at a point whose coordinates are rational
numbers is decided here when ``lhs - rhs``, evaluated with mpmath at 60 digits, is clearly away from
zero: further from it than ``10**-45`` times the larger of 1 and the sides' magnitudes, 15 digits of
margin over the working precision.  Otherwise (the difference may be zero, a side is not finite or
cannot be evaluated, a coordinate is not rational) the answer is ``None`` and the caller decides the
relation exactly, as SymPy evaluates it.  Used by the relation check and by the sampling of identities
(a derivation's constraints, such as ``tan(alpha) < 2 rho``, at every drawn point), where the exact
evaluation of a transcendental side costs milliseconds and gives the same answer.
"""
from __future__ import annotations

import functools

import mpmath
import sympy as sp

from ..model.relation import RealRoots

__all__ = ["decided", "DIGITS"]

DIGITS = 60            # working precision of the sign of the difference
MARGIN = 15            # digits of the working precision the difference must clear

# the truth of each kind of relation from the sign of lhs - rhs, once that difference is known not to be zero
_BY_SIGN = {sp.StrictGreaterThan: lambda d: d > 0, sp.GreaterThan: lambda d: d > 0,
            sp.StrictLessThan: lambda d: d < 0, sp.LessThan: lambda d: d < 0,
            sp.Equality: lambda d: False, sp.Unequality: lambda d: True}


@functools.lru_cache(maxsize=4096)
def _compiled(rel):
    """The two sides of *rel* as one mpmath function of its free symbols (sorted by name), or None."""
    if rel.has(RealRoots) or type(rel) not in _BY_SIGN:
        return None
    symbols = tuple(sorted(rel.free_symbols, key=lambda q: q.name))
    try:
        return symbols, sp.lambdify(symbols, [rel.lhs, rel.rhs], "mpmath")
    except (TypeError, ValueError, NameError, SyntaxError):
        return None


@functools.lru_cache(maxsize=65536)
def _at(rel, values):
    """:func:`decided` at the rational *values* of the symbols of :func:`_compiled` (in their order)."""
    symbols, f = _compiled(rel)
    with mpmath.workdps(DIGITS):
        try:
            lhs, rhs = f(*(mpmath.mpf(v.p) / v.q for v in values))
            lhs, rhs = mpmath.mpf(lhs), mpmath.mpf(rhs)
        except (ArithmeticError, TypeError, ValueError, ZeroDivisionError, NameError):
            return None
        if not (mpmath.isfinite(lhs) and mpmath.isfinite(rhs)):
            return None
        d = lhs - rhs
        if abs(d) <= mpmath.mpf(10) ** (MARGIN - DIGITS) * max(1, abs(lhs), abs(rhs)):
            return None
        return _BY_SIGN[type(rel)](d)


def decided(rel, point) -> bool | None:
    """The truth of the relation *rel* at *point* (symbol -> SymPy number) by the sign of its sides'
    difference at 60 digits, where that difference is clearly not zero; else None (decide exactly).

    >>> x = sp.Symbol("x")
    >>> decided(sp.tan(x) < 2 * x, {x: sp.Rational(1, 3)}), decided(x ** 2 >= 1, {x: sp.Integer(1)})
    (True, None)
    """
    compiled = _compiled(rel)
    if compiled is None:
        return None
    values = tuple(point.get(q) for q in compiled[0])
    if not all(v is not None and v.is_Rational for v in values):
        return None
    return _at(rel, values)
