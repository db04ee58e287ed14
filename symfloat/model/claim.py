"""Claims: the statements a step or a printed formula makes.

A claim is a chain of members asserted equal, ``a = b = c``.  It may be given
as a SymPy ``Eq``, a tuple of expressions, or a ``Matrix`` equation (vectors
are compared component by component).
"""
from __future__ import annotations

import sympy as sp

from .relation import is_relation, relation_latex
from .symbol_names import latex

__all__ = ["Eq", "members", "as_latex", "pairs", "identical_links", "as_printed", "expressions"]


def Eq(lhs, rhs) -> sp.Equality:
    """The equation ``lhs = rhs`` as written, left for the checker to decide.

    SymPy's own ``Eq`` tries to decide an equation when it is built; in a
    derivation module that is work done at every import (a scene reading a
    predictor pays for it) and, where it succeeds, it replaces the claim by
    ``True``.  This one never decides: the members stay as given.

    >>> import sympy as sp
    >>> x = sp.Symbol("x")
    >>> Eq(x + x, 2 * x).rhs
    2*x
    """
    return sp.Equality(lhs, rhs, evaluate=False)


def members(claim) -> tuple:
    """The members of *claim* (at least two), as SymPy objects."""
    if isinstance(claim, sp.Equality):
        return (claim.lhs, claim.rhs)
    if isinstance(claim, (tuple, list)):
        if len(claim) < 2:
            raise ValueError("a chain of equalities needs at least two members")
        return tuple(sp.sympify(m) if not isinstance(m, sp.MatrixBase) else m for m in claim)
    raise TypeError(f"a claim is an Eq or a tuple of members, not {type(claim).__name__}")


def pairs(claim):
    """Consecutive pairs ``(a, b)`` of the chain, each one identity to prove."""
    ms = members(claim)
    return list(zip(ms, ms[1:]))


def expressions(reading) -> tuple:
    """The SymPy objects a reading states: the members of a chain, the conditions of a relation
    (:mod:`symfloat.model.relation`); for the symbols a reading uses."""
    return reading.parts() if is_relation(reading) else members(reading)


def as_latex(claim) -> str:
    """The chain as one LaTeX line ``a = b = c`` (a relation as its own line)."""
    if is_relation(claim):
        return relation_latex(claim)
    return " = ".join(latex(m) for m in members(claim))


def identical_links(ms) -> list[bool]:
    """For each consecutive pair of the members *ms*: are the two identical as built?

    Structural equality of the SymPy objects as the derivation constructed them,
    before any substitution of derived values or ``doit``.  Such a link is true by
    construction (e.g. a printed ``g (1/2)^2 = g/4`` that SymPy evaluated on
    building), so checking it proves nothing about the print.

    >>> import sympy as sp
    >>> g = sp.Symbol("g")
    >>> identical_links((g * sp.Rational(1, 2) ** 2, g / 4))
    [True]
    >>> identical_links((sp.Mul(g, sp.Pow(sp.Rational(1, 2), 2, evaluate=False), evaluate=False), g / 4))
    [False]
    """
    out = []
    for a, b in zip(ms, ms[1:]):
        if isinstance(a, sp.MatrixBase) or isinstance(b, sp.MatrixBase):
            same = (isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase) and a.shape == b.shape
                    and all(x == y for x, y in zip(a, b)))
        else:
            same = a == b
        out.append(bool(same))
    return out


def as_printed(build):
    """What ``build()`` returns, built with SymPy's automatic evaluation off.

    A reading keeps the print's arithmetic this way (``g (1/2)^2`` stays a
    product of ``g`` and a square), so that the engine carries it out when it
    compares, instead of SymPy when the reading is built.

    >>> import sympy as sp
    >>> g = sp.Symbol("g")
    >>> as_printed(lambda: g * sp.Rational(1, 2) ** 2) == g / 4, (g * sp.Rational(1, 2) ** 2) == g / 4
    (False, True)
    """
    with sp.evaluate(False):
        return build()
