"""Relations: inequalities, equivalences and case tables as readings of the print.

A printed formula or sentence that asserts a range, a sign, a count of roots or which case holds
where is read as one of three relations, each on a *domain* (symbol -> interval; a pair ``(lo, hi)``
is the open interval, a :class:`sympy.Interval` may close an end; a symbol the domain does not name
takes the derivation's interval) and under extra conditions *where* (the derivation's constraints
apply too):

* :class:`Holds` -- ``condition`` (a relation, or ``And``/``Or``/``Not`` of relations) holds at every
  point of the domain: Scheeffer (123), ``(a/b)^2 - 6 s (1 - s) > 0``, read where the text claims it;
* :class:`Iff` -- two conditions are equivalent on the domain: "stable exactly when ...";
* :class:`Cases` -- a printed case table: rows ``(condition, claim)``, the claim holds wherever its
  condition does; ``exhaustive`` (the conditions cover the domain) and ``exclusive`` (no two hold at
  once) where the print says so.

:class:`RealRoots` counts the distinct real roots of a polynomial in an open interval, so that "drei
reelle Wurzeln" is read ``Eq(RealRoots(F, z, -oo, oo), 3)``.  The checks live in
:mod:`symfloat.engine.relation`: a proof where one variable is left and the relations are rational,
or where the signs of the symbols decide, else exact sampling with the domain's boundary; a sampled
counterexample refutes.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from .symbol_names import latex

__all__ = ["Relation", "Holds", "Iff", "Cases", "RealRoots", "is_relation", "relation_latex", "indicator"]


def _interval(bounds) -> sp.Interval:
    if isinstance(bounds, sp.Interval):
        return bounds
    lo, hi = bounds
    return sp.Interval.open(sp.sympify(lo), sp.sympify(hi))


def _domain(domain) -> tuple:
    """The domain as a tuple of ``(symbol, Interval)`` sorted by name (stable, hashable)."""
    pairs = ((s, _interval(b)) for s, b in (domain or {}).items())
    return tuple(sorted(pairs, key=lambda p: p[0].name))


def _boolean(c) -> sp.Basic:
    c = sp.sympify(c)
    if not isinstance(c, (sp.logic.boolalg.Boolean, sp.core.relational.Relational)):
        raise TypeError(f"a condition is a relation or a combination of relations, not {type(c).__name__}: {c}")
    return c


class Relation:
    """Common part of the three relations: the domain and the extra conditions."""

    domain: tuple
    where: tuple

    def parts(self) -> tuple:
        """The conditions of the relation, in order (for symbols and display)."""
        raise NotImplementedError

    def indicators(self):
        """The relation as a chain of 1/0 indicators, for a witness that measures a truth (a stable
        position: 1 or 0) at its cases: ``Holds(c)`` is ``(1 if c, 1)``, ``Iff(a, b)`` is ``(1 if a, 1 if b)``;
        None for a case table."""
        return None

    def intervals(self) -> dict:
        return dict(self.domain)


@dataclass(frozen=True, init=False)
class Holds(Relation):
    """``condition`` holds everywhere on the domain (under *where*)."""

    condition: sp.Basic
    domain: tuple
    where: tuple

    def __init__(self, condition, domain=None, where=()):
        object.__setattr__(self, "condition", _boolean(condition))
        object.__setattr__(self, "domain", _domain(domain))
        object.__setattr__(self, "where", tuple(_boolean(w) for w in where))

    def parts(self):
        return (self.condition,)

    def indicators(self):
        return (indicator(self.condition), sp.Integer(1))


@dataclass(frozen=True, init=False)
class Iff(Relation):
    """``a`` holds exactly where ``b`` holds, on the domain (under *where*)."""

    a: sp.Basic
    b: sp.Basic
    domain: tuple
    where: tuple

    def __init__(self, a, b, domain=None, where=()):
        object.__setattr__(self, "a", _boolean(a))
        object.__setattr__(self, "b", _boolean(b))
        object.__setattr__(self, "domain", _domain(domain))
        object.__setattr__(self, "where", tuple(_boolean(w) for w in where))

    def parts(self):
        return (self.a, self.b)

    def indicators(self):
        return (indicator(self.a), indicator(self.b))


@dataclass(frozen=True, init=False)
class Cases(Relation):
    """A printed case table: in each row ``(condition, claim)`` the claim holds where the condition
    does; ``exhaustive``: some condition holds at every point; ``exclusive``: never two at once."""

    rows: tuple
    domain: tuple
    where: tuple
    exhaustive: bool
    exclusive: bool

    def __init__(self, rows, domain=None, where=(), exhaustive=True, exclusive=True):
        rows = tuple((_boolean(c), _boolean(claim)) for c, claim in rows)
        if not rows:
            raise ValueError("a case table needs at least one row")
        object.__setattr__(self, "rows", rows)
        object.__setattr__(self, "domain", _domain(domain))
        object.__setattr__(self, "where", tuple(_boolean(w) for w in where))
        object.__setattr__(self, "exhaustive", bool(exhaustive))
        object.__setattr__(self, "exclusive", bool(exclusive))

    def parts(self):
        return tuple(x for row in self.rows for x in row)


def indicator(condition) -> sp.Piecewise:
    """1 where *condition* holds, else 0."""
    return sp.Piecewise((1, condition), (0, True))


def is_relation(reading) -> bool:
    return isinstance(reading, Relation)


def _domain_latex(r: Relation) -> str:
    out = [f"{latex(s)} \\in {latex(i)}" for s, i in r.domain] + [latex(w) for w in r.where]
    return (r"\quad \text{on } " + ", ".join(out)) if out else ""


def relation_latex(r: Relation, show=latex) -> str:
    """One LaTeX line for the relation; *show* writes a SymPy expression (a notebook passes its own)."""
    if isinstance(r, Holds):
        body = show(r.condition)
    elif isinstance(r, Iff):
        body = f"{show(r.a)} \\iff {show(r.b)}"
    else:
        body = r"\begin{cases} " + r" \\ ".join(f"{show(claim)} & \\text{{if }} {show(c)}" for c, claim in r.rows) \
            + r" \end{cases}"
    return body + _domain_latex(r)


class RealRoots(sp.Function):
    """``RealRoots(p, x, lo, hi)``: the number of distinct real roots of the polynomial ``p`` in ``x``
    in the open interval ``(lo, hi)`` (``-oo``/``oo`` allowed), evaluated by Sturm sequences once the
    coefficients and the ends are numbers; ``x`` is bound (not a free symbol).

    >>> x = sp.Symbol("x")
    >>> RealRoots(x**3 - x, x, -sp.oo, sp.oo), RealRoots(x**3 - x, x, 0, 1), RealRoots(x**2 + 1, x, -sp.oo, sp.oo)
    (3, 0, 0)
    """

    nargs = 4

    @classmethod
    def eval(cls, p, x, lo, hi):
        if (p.free_symbols - {x}) or lo.free_symbols or hi.free_symbols:
            return None
        if not all(e.is_Rational or e.is_infinite for e in (lo, hi)):
            return None
        poly = sp.Poly(p, x)
        if not (poly.domain.is_QQ or poly.domain.is_ZZ):
            return None                 # Sturm counts are exact over the rationals only: left unevaluated
        poly = poly.sqf_part()
        if poly.is_zero:
            raise ValueError("RealRoots of the zero polynomial")
        n = poly.count_roots(None if lo == -sp.oo else lo, None if hi == sp.oo else hi)
        ends = [e for e in (lo, hi) if e.is_finite and poly.eval(e) == 0]
        return sp.Integer(n - len(ends))

    @property
    def free_symbols(self):
        p, x, lo, hi = self.args
        return (p.free_symbols - {x}) | lo.free_symbols | hi.free_symbols

    def _latex(self, printer):
        p, x, lo, hi = (printer._print(a) for a in self.args)
        return rf"\#\{{{x} \in ({lo}, {hi}) : {p} = 0\}}"
