"""The exact value of a rational function at a rational point, in FLINT's rationals.

Sampling a claim puts exact points into its members (:func:`symfloat.engine.identity._sample`); for
a member built of sums, products and integer powers of symbols and rationals, SymPy's substitution
rebuilds the whole tree to arrive at one rational, and at a few hundred thousand points that was a
tenth of every check.  :func:`rational_value` reaches the same rational with ``flint.fmpq``
arithmetic on a tree compiled once per expression; anything else (a root, a function, an
irrational point) is left to SymPy (``None``).
"""
from __future__ import annotations

from functools import lru_cache

import sympy as sp
from flint import fmpq

__all__ = ["rational_value"]


class _NotRational(Exception):
    """The expression has a node other than a sum, a product, an integer power, a symbol or a rational."""


def _compile(expr):
    """*expr* as a function of a ``{symbol: fmpq}`` mapping."""
    if expr.is_Symbol:
        return lambda env: env[expr]
    if expr.is_Rational:
        value = fmpq(int(expr.p), int(expr.q))
        return lambda env: value
    if expr.is_Add or expr.is_Mul:
        terms = [_compile(a) for a in expr.args]
        if expr.is_Add:
            def add(env):
                total = fmpq(0)
                for t in terms:
                    total += t(env)
                return total
            return add

        def mul(env):
            product = fmpq(1)
            for t in terms:
                product *= t(env)
            return product
        return mul
    if expr.is_Pow and expr.exp.is_Integer:
        base, n = _compile(expr.base), int(expr.exp)
        return lambda env: base(env) ** n
    raise _NotRational


@lru_cache(maxsize=4096)
def _compiled(expr):
    try:
        return _compile(expr), frozenset(expr.free_symbols)
    except _NotRational:
        return None


def rational_value(expr, point) -> sp.Rational | None:
    """*expr* at *point* (``{symbol: value}``) as an exact SymPy rational, the value SymPy's
    ``expr.xreplace(point)`` evaluates to; ``None`` where *expr* is not a rational function, a symbol
    of it has no rational value at *point*, or the value is not finite (a zero denominator: SymPy's
    ``zoo`` or ``nan``, left to SymPy to say).

    >>> from sympy.abc import a, b
    >>> rational_value((a + b) ** 2 / (2 * a), {a: sp.Rational(1, 3), b: sp.Integer(2)})
    49/6
    >>> rational_value(sp.sqrt(a), {a: sp.Integer(4)}) is None
    True
    """
    compiled = _compiled(expr)
    if compiled is None:
        return None
    f, symbols = compiled
    env = {}
    for q in symbols:
        v = point.get(q)
        if v is None or not v.is_Rational:
            return None
        env[q] = fmpq(int(v.p), int(v.q))
    try:
        v = f(env)
    except ZeroDivisionError:
        return None
    return sp.Rational(int(v.p), int(v.q))
