"""Words that name a quantity: each source's vocabulary, and the readings built from it.

A source names its quantities in words: Euler's *stabilitas* is the weight times the metacentric
height, M(moment/V ± b) (§194, §201), his *momentum* the waterplane's moment about an axis (§202);
Scheeffer's *Schwerpunkt* is the body's centroid, the *Schwerpunkt der verdrängten Wassermasse* the
displaced water's.  ``vocabulary.json`` lists, per source, each quantity with its meaning and the
words (inflections included) that name it, and the words that call an equilibrium stable, neutral
or unstable.  A derivation ties a quantity to the formula that defines it
(``Derivation.defines("stability", S)``); a sentence that names the quantity and says something of
it is read from that definition (``Derivation.says``), so the words decide what is checked: a
sentence that names the body's centroid where the formula gives the displaced water's is refuted.

What a sentence says of the quantity q it names (``at`` puts the sentence's particulars into the
definition, e.g. the square's moment for the generic moment):

* :class:`Is` -- q has the value or formula v: the chain ``q = v``;
* :class:`Compares` -- a sign or a comparison: ``Holds(q op v)``;
* :class:`IndependentOf` -- q does not change with b: ``dq/db = 0``, an identity;
* :class:`DependsOn` -- q changes with a: ``dq/da != 0`` on the domain (a quantity that depends on a
  only away from an extremum is stated with :class:`Compares` on a range instead);
* :class:`GrowsWith`, :class:`DecreasesWith` -- q grows (decreases) with a (with each of several symbols:
  Euler's "eo maior, quo magis ...") on a stated domain: the sign of each derivative, ``Holds(dq/da > 0)`` (``< 0``) at every point of the domain, decided by the relation
  check (a proof where the signs or one variable decide, else exact sampling; a point where the sign is
  wrong refutes).  ``per`` reads the part of q the sentence speaks of, q divided by a factor that does not
  vanish on the domain: Scheeffer IV's "das Drehungsmoment, dessen negativer Faktor (absolut genommen) mit
  wachsendem phi kleiner wird" is the moment (12) V1 m over -sin(phi), the absolute value of the bracket
  where it is negative, decreasing with phi;
* :class:`StableIff` -- the equilibrium is stable (neutral, unstable: the sentence's verdict word)
  exactly when a condition holds: both implications between the condition and the sign of the
  stability, and, for a condition stated with >= or <=, its equality case read at the point where it
  holds (the stability vanishes there, the position is neutral, so "stable if z_M >= z_G" is refuted);
  ``at`` names the body the sentence speaks of where one definition serves several (Scheeffer VI's
  T/V - e_1 with the triangle's or the cylinder's moment and displacement);
* :class:`Called` -- the equilibrium at a stated position is called stable (neutral, unstable): the
  sign of the stability there, ``> 0``, ``= 0`` or ``< 0`` (stable where the stability vanishes is
  refuted: the position is neutral).
"""
from __future__ import annotations

import json
import re
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import sympy as sp

from .relation import Holds

__all__ = ["vocabulary", "quantity_named", "verdict_named", "Is", "Compares", "IndependentOf", "DependsOn",
           "GrowsWith", "DecreasesWith", "StableIff", "Called", "VERDICT_SIGNS"]

VERDICT_SIGNS = {"stable": 1, "neutral": 0, "unstable": -1}     # the sign of the stability each verdict states


@cache
def vocabulary() -> dict:
    """Source key -> ``{"quantities": {name: {"meaning", "words"}}, "verdicts": {verdict: words}}``."""
    return json.loads(Path(__file__).with_name("vocabulary.json").read_text(encoding="utf-8"))["sources"]


def _longest(patterns: dict, words: str, what: str, source: str) -> str:
    """The key of *patterns* whose words match the longest part of *words* (lower case, at a word start)."""
    found = {}
    for key, pattern in patterns.items():
        lengths = [len(m.group(0)) for m in re.finditer(rf"(?<![\w])(?:{pattern})", words.lower())]
        if lengths:
            found[key] = max(lengths)
    if not found:
        raise ValueError(f"{source}: the words {words!r} name no {what} of the source's vocabulary")
    best = max(found.values())
    keys = sorted(k for k, n in found.items() if n == best)
    if len(keys) > 1:
        raise ValueError(f"{source}: the words {words!r} name {' and '.join(keys)} alike: quote more words")
    return keys[0]


def quantity_named(source: str, words: str) -> str:
    """The quantity of *source*'s vocabulary that *words* name (the longest match decides).

    >>> quantity_named("metazentrum", "Schwerpunkt des gekippten Körpers")
    'centre of gravity'
    >>> quantity_named("metazentrum", "Massenschwerpunktes des verdrängten Wassers")
    'centre of buoyancy'
    >>> quantity_named("euler", "hincque stabilitas respectu cuiusuis axis")
    'stability'
    """
    return _longest({k: q["words"] for k, q in vocabulary()[source]["quantities"].items()}, words, "quantity",
                    source)


def verdict_named(source: str, words: str) -> str:
    """``stable``, ``neutral`` or ``unstable``: the verdict *words* give an equilibrium.

    >>> verdict_named("metazentrum", "dass der Quader stabil ist"), verdict_named("euler", "indifferentem")
    ('stable', 'neutral')
    """
    return _longest(vocabulary()[source]["verdicts"], words, "verdict on stability", source)


def _at(q, at):
    """*q* with the sentence's particulars put into its definition (kept unevaluated until the check)."""
    if not at:
        return q
    keys = tuple(at)
    return sp.Subs(q, keys, tuple(at[k] for k in keys))


def _signed(s, verdict):
    """The relation of the stability *s* that *verdict* states."""
    return {"stable": s > 0, "neutral": sp.Eq(s, 0, evaluate=False), "unstable": s < 0}[verdict]


@dataclass(frozen=True, init=False)
class Is:
    """The named quantity has the value or formula *value*."""

    value: object
    at: tuple = ()

    def __init__(self, value, at=None):
        object.__setattr__(self, "value", value)
        object.__setattr__(self, "at", tuple((at or {}).items()))

    def reading(self, q, derived):
        return (_at(q, dict(self.at)), self.value)


@dataclass(frozen=True, init=False)
class Compares:
    """The named quantity stands in the relation *op* (``>``, ``>=``, ``<``, ``<=``) to *other*."""

    op: str
    other: object
    at: tuple = ()
    domain: tuple = ()

    def __init__(self, op, other, at=None, domain=None):
        if op not in (">", ">=", "<", "<="):
            raise ValueError(f"a comparison is one of > >= < <=, not {op!r}")
        object.__setattr__(self, "op", op)
        object.__setattr__(self, "other", other)
        object.__setattr__(self, "at", tuple((at or {}).items()))
        object.__setattr__(self, "domain", tuple((domain or {}).items()))

    def reading(self, q, derived):
        rel = {">": sp.Gt, ">=": sp.Ge, "<": sp.Lt, "<=": sp.Le}[self.op]
        return Holds(rel(_at(q, dict(self.at)), self.other, evaluate=False), dict(self.domain))


@dataclass(frozen=True, init=False)
class IndependentOf:
    """The named quantity does not change with any of *symbols*: each derivative vanishes identically."""

    symbols: tuple
    at: tuple = ()

    def __init__(self, *symbols, at=None):
        object.__setattr__(self, "symbols", symbols)
        object.__setattr__(self, "at", tuple((at or {}).items()))

    def reading(self, q, derived):
        q = _at(q, dict(self.at))
        return (sp.Matrix([sp.Derivative(q, x) for x in self.symbols]), sp.zeros(len(self.symbols), 1))


@dataclass(frozen=True, init=False)
class DependsOn:
    """The named quantity changes with each of *symbols*: its derivative is nowhere zero on the domain."""

    symbols: tuple
    at: tuple = ()
    domain: tuple = ()

    def __init__(self, *symbols, at=None, domain=None):
        object.__setattr__(self, "symbols", symbols)
        object.__setattr__(self, "at", tuple((at or {}).items()))
        object.__setattr__(self, "domain", tuple((domain or {}).items()))

    def reading(self, q, derived):
        q = _at(q, dict(self.at))
        return Holds(sp.And(*(sp.Ne(sp.Derivative(q, x), 0) for x in self.symbols)), dict(self.domain))


@dataclass(frozen=True, init=False)
class GrowsWith:
    """The named quantity (divided by *per*) grows with each of *symbols* on the domain: ``d(q/per)/da > 0``
    there for each."""

    symbols: tuple
    per: object = 1
    at: tuple = ()
    domain: tuple = ()
    sense = ">"

    def __init__(self, *symbols, per=1, at=None, domain=None):
        object.__setattr__(self, "symbols", symbols)
        object.__setattr__(self, "per", sp.sympify(per))
        object.__setattr__(self, "at", tuple((at or {}).items()))
        object.__setattr__(self, "domain", tuple((domain or {}).items()))

    def reading(self, q, derived):
        q = _at(q / self.per, dict(self.at))
        rel = sp.Gt if self.sense == ">" else sp.Lt
        return Holds(sp.And(*(rel(sp.Derivative(q, x), 0, evaluate=False) for x in self.symbols)), dict(self.domain))


class DecreasesWith(GrowsWith):
    """The named quantity (divided by *per*) decreases with each of *symbols* on the domain: ``d(q/per)/da < 0``
    there for each."""

    sense = "<"


@dataclass(frozen=True, init=False)
class StableIff:
    """The equilibrium has the verdict of the sentence's words exactly when *condition* holds (*at*: the
    sentence's particulars put into the stability, e.g. the body's moment and displacement)."""

    condition: object
    domain: tuple = ()
    at: tuple = ()
    verdicts = True

    def __init__(self, condition, domain=None, at=None):
        object.__setattr__(self, "condition", condition)
        object.__setattr__(self, "domain", tuple((domain or {}).items()))
        object.__setattr__(self, "at", tuple((at or {}).items()))

    def reading(self, s, derived, verdict):
        s = _at(s, dict(self.at))
        said = _signed(s, verdict)
        clauses = [sp.Implies(self.condition, said), sp.Implies(said, self.condition)]
        clauses += _equality_case(self.condition, s, verdict, derived, dict(self.domain))
        return Holds(sp.And(*clauses), dict(self.domain))


def _equality_case(condition, s, verdict, derived, domain) -> list:
    """For a condition ``A >= B`` (or ``<=``) of a stable or an unstable verdict: the verdict at the points
    where ``A = B``, found by solving ``A = B`` (derived values inserted) for its first symbol with a solution
    that may lie in the domain (not provably complex, nor provably outside the symbol's interval); there the
    stability vanishes where the equality is the neutral case, which refutes it."""
    if verdict == "neutral" or not isinstance(condition, (sp.GreaterThan, sp.LessThan)):
        return []
    gap = derived(condition.lhs - condition.rhs)
    for x in sorted(gap.free_symbols, key=lambda q: q.name):
        roots = [r for r in sp.solve(gap, x) if _may_lie_in(r, domain.get(x))]
        if roots:
            return [_signed(sp.Subs(s, x, roots[0]), verdict)]
    raise ValueError(f"the equality case of {condition} has no solution in the domain for any of its symbols")


def _may_lie_in(root, interval) -> bool:
    """False when *root* is provably not real, or provably outside *interval* (``(lo, hi)``, either end
    ``None`` for unbounded)."""
    if root.is_extended_real is False:
        return False
    lo, hi = interval if interval is not None else (None, None)
    return not ((lo is not None and (root - lo).is_negative) or (hi is not None and (root - hi).is_positive))


@dataclass(frozen=True, init=False)
class Called:
    """The equilibrium at the position *at* (symbol -> value) has the verdict of the sentence's words."""

    at: tuple = ()
    domain: tuple = ()
    verdicts = True

    def __init__(self, at=None, domain=None):
        object.__setattr__(self, "at", tuple((at or {}).items()))
        object.__setattr__(self, "domain", tuple((domain or {}).items()))

    def reading(self, s, derived, verdict):
        s = _at(s, dict(self.at))
        if verdict == "neutral":
            return (s, sp.Integer(0))
        return Holds(_signed(s, verdict), dict(self.domain))
