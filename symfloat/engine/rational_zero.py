"""Is an expression 0 as a rational function of its generators?  Decided in FLINT's polynomials.

The ``cancel`` strategy of a proof asks whether ``together(e)`` has the zero polynomial as its numerator, every
atom that is not a rational number (a symbol, ``sqrt(x)``, ``sin(t)``, ``pi``) taken as a generator of its own.
:func:`is_zero_rational_function` asks the same question of ``e`` in ``fmpq_mpoly`` (FLINT's multivariate
polynomials over the rationals), carrying a numerator and a denominator through the tree: a sum cross-multiplies,
a product multiplies, an integer power powers.  A power ``b**(p/q)`` is the generator ``b**(1/L)`` to the power
``pL/q``, L the least common multiple of the roots taken of ``b`` in ``e`` (``b`` itself is ``(b**(1/L))**L``), as
SymPy's polynomials read it.

"Yes" is a proof that ``e`` is 0 wherever it is defined: a polynomial identity in independent generators holds for
any values of them, and ``(b**(1/L))**L = b`` holds for every ``b``, so a root of a number, a sum or a product is
reduced by its radicand.  "No" proves nothing: the generators may be related in other ways (``sin(t)**2 +
cos(t)**2`` is 1, ``sqrt(x*y)`` is ``sqrt(x)*sqrt(y)`` for positive x and y), a float or an infinity has no exact
place here, a power above the 64th is not expanded, and a denominator that is the zero polynomial is a question for
SymPy; the caller then asks SymPy's ``cancel``.
"""
from __future__ import annotations

import math

import sympy as sp
from flint import fmpq, fmpq_mpoly_ctx

__all__ = ["is_zero_rational_function"]


class _NotRational(Exception):
    """The expression holds a float, an infinity, a power above :data:`_LARGEST_POWER`, or a denominator that is the
    zero polynomial."""


_NOT_NUMBERS = frozenset({sp.oo, -sp.oo, sp.zoo, sp.nan})
# a larger integer power is left to SymPy: FLINT's expansion of it cannot be stopped by a search's time limit
# (the claims' largest is far below; a replay has no time limit either way)
_LARGEST_POWER = 64


def _atom(x):
    """``(base, p, q)`` of the atom *x*, read as ``base**(p/q)``: a power with a rational exponent, or *x* to the
    power 1."""
    if x.is_Pow and x.exp.is_Rational:
        return x.base, int(x.exp.p), int(x.exp.q)
    return x, 1, 1


def _roots(e, found: dict) -> None:
    """For each base of an atom of *e* (and of the bases of its roots), the least common multiple of the roots
    taken of it, in *found*."""
    if e.is_Rational:
        return
    if e.is_Float or e in _NOT_NUMBERS:
        raise _NotRational
    if e.is_Add or e.is_Mul:
        for a in e.args:
            _roots(a, found)
    elif e.is_Pow and e.exp.is_Integer:
        if abs(e.exp) > _LARGEST_POWER:
            raise _NotRational
        _roots(e.base, found)
    else:
        base, _, q = _atom(e)
        found[base] = math.lcm(found.get(base, 1), q)
        if q > 1:               # the root of a number, a sum or a product: its base is a rational function too
            _roots(base, found)


def is_zero_rational_function(e) -> bool:
    """``True`` where *e* is the zero rational function of its generators (so ``e = 0`` where defined).

    >>> x, y = sp.symbols("x y")
    >>> is_zero_rational_function(1/(x - y) - 1/(x + y) - 2*y/(x**2 - y**2))
    True
    >>> is_zero_rational_function(1/(x - y) - 1/(x + y) - 3*y/(x**2 - y**2))
    False
    >>> is_zero_rational_function(sp.sqrt(x)/(x + sp.sqrt(x)) - 1/(sp.sqrt(x) + 1))
    True
    >>> is_zero_rational_function(sp.sin(x)**2 + sp.cos(x)**2 - 1)
    False
    """
    roots: dict = {}
    try:
        _roots(e, roots)
    except _NotRational:
        return False
    if not roots:
        return e == 0
    index = {base: i for i, base in enumerate(roots)}
    ctx = fmpq_mpoly_ctx.get(tuple(f"g{i}" for i in range(len(roots))), "lex")
    gens, zero = ctx.gens(), (0,) * len(roots)
    one = ctx.from_dict({zero: 1})
    seen: dict = {}

    def fraction(x):
        """``(numerator, denominator)`` of *x* in the generators, ``base**(1/L)`` for each base."""
        if x in seen:
            return seen[x]
        if x.is_Rational:
            n, d = ctx.from_dict({zero: fmpq(int(x.p), int(x.q))}), one
        elif x.is_Add:
            n, d = fraction(x.args[0])
            for a in x.args[1:]:
                n2, d2 = fraction(a)
                n, d = (n + n2, d) if d2 == d else (n * d2 + n2 * d, d * d2)
        elif x.is_Mul:
            n, d = one, one
            for a in x.args:
                n2, d2 = fraction(a)
                n, d = n * n2, d * d2
        elif x.is_Pow and x.exp.is_Integer:
            n, d = fraction(x.base)
            k = int(x.exp)
            if k < 0:
                n, d, k = d, n, -k
            if d == 0:
                raise _NotRational
            n, d = n ** k, d ** k
        else:
            base, p, q = _atom(x)
            g, k = gens[index[base]], p * (roots[base] // q)
            n, d = (g ** k, one) if k >= 0 else (one, g ** -k)
        seen[x] = n, d
        return n, d

    try:
        numerator = fraction(e)[0]
        # a base that is not a generator itself (a number, a sum, a product) is a relation g**L = base
        relations = [(index[b], L, fraction(b)) for b, L in roots.items()
                     if L > 1 and (b.is_Rational or b.is_Add or b.is_Mul or b.is_Pow)]
    except _NotRational:
        return False
    for _ in range(4 * len(relations)):   # an outer root's base may hold an inner root's generator: reduce again
        if numerator == 0:
            return True
        reducible = [r for r in relations if numerator.degrees()[r[0]] >= r[1]]
        if not reducible:
            return False
        numerator = _reduced(numerator, *reducible[0], ctx)
    return numerator == 0


def _reduced(numerator, i: int, L: int, base, ctx):
    """*numerator* with ``g_i**L`` replaced by ``base = n/d`` (no ``g_i`` in it), times the power of ``d`` that
    keeps it a polynomial: ``c m g_i**(jL + r)`` becomes ``c m g_i**r n**j d**(J - j)``, J the largest j."""
    n, d = base
    terms = numerator.to_dict()
    most = max(e[i] // L for e in terms)
    out = ctx.from_dict({})
    for exponents, c in terms.items():
        j, r = divmod(exponents[i], L)
        monomial = list(exponents)
        monomial[i] = r
        out += ctx.from_dict({tuple(monomial): c}) * n ** j * d ** (most - j)
    return out
