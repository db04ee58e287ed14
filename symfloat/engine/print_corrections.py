"""The corrections of a derivation's refuted print: small edits of its quoted LaTeX that make it hold.

The math of the excerpt is edited (:mod:`symfloat.engine.corrections`), each edit read by the allow-list
reader with the hand reading's symbol names, its symbols matched by name, and its chain compared with
the derivation: first at two seeded points of the domain in 30-digit arithmetic, the derived quantities
inserted (a fast sieve; a quote of printed numbers within its printed precision), then, for an edit that passes, by the identity check of the printed formulas
(exact sampling and proof).  Used by ``symfloat verify``'s message for a refuted print without an
erratum, by the evidence of a declared erratum (:func:`smallest_correction`: the
:data:`EVIDENCE_BUDGET` likeliest edits, each read once, the search stopped at the first that holds)
and by the benchmark of the errata (``benchmarks/corrections.py``).  An excerpt of prose (no math
span, a word of four small letters) is not searched: one edit of a sentence never makes a formula.
"""
from __future__ import annotations

import re

import sympy as sp

from ..model.claim import members
from ..model.latex import Unreadable, canonical, read
from ..model.symbol_match import formula_symbols, match_symbols
from .corrections import Correction, corrections
from .identity import Domain

__all__ = ["excerpt_math", "print_corrections", "print_test", "same_reading", "smallest_correction",
           "EVIDENCE_BUDGET"]

_SIEVE_POINTS = 2
_SIEVE_DIGITS = 30
EVIDENCE_BUDGET = 60        # the likeliest edits an erratum's evidence tries (the benchmark measures what it finds)
_MATH = re.compile(r"\$\$(.+?)\$\$|\$(.+?)\$", re.S)
_WORD = re.compile(r"(?<![\\A-Za-z])[a-zäöüß]{4,}")


def excerpt_math(excerpt: str) -> str | None:
    """The one formula of an excerpt: its only math span (or the whole excerpt when it has no dollars and
    no word of four small letters); ``None`` when it has several, or is prose.

    >>> excerpt_math("und $V = a b c$ ist"), excerpt_math("V = a b c"), excerpt_math("Nach 55 ist ferner")
    ('V = a b c', 'V = a b c', None)
    """
    spans = [a or b for a, b in _MATH.findall(excerpt)]
    if not spans:
        return excerpt if "$" not in excerpt and not _WORD.search(excerpt) else None
    return spans[0].strip() if len(spans) == 1 else None


def _sieve_points(domain: Domain, symbols, seed: str):
    draw, points = domain.sampler(seed + "#corrections"), []
    for _ in range(40):
        point = draw(symbols)
        if domain.admits(point):
            points.append(point)
            if len(points) == _SIEVE_POINTS:
                break
    return points


def print_corrections(printed, results: dict, domain: Domain, seed: str, decide, *, limit: int = 3,
                      budget: int = 1500) -> list[Correction]:
    """The likeliest edits of *printed*'s excerpt that make it hold against *results*; *decide(chain)* is
    the caller's full check of a corrected chain (an :class:`~symfloat.engine.identity.IdentityResult`)."""
    tex = excerpt_math(printed.excerpt)
    holds = print_test(printed, results, domain, seed, decide)
    if tex is None or holds is None:
        return []
    return corrections(tex, holds, limit=limit, budget=budget)


def print_test(printed, results: dict, domain: Domain, seed: str, decide):
    """The test of a corrected text of *printed*: ``text -> "proved" | "sampled" | None`` (see the module
    docstring); ``None`` when the quote has no hand reading that is a chain of scalar members."""
    if printed.reading is None:
        return None
    try:
        hand = [sp.sympify(m) for m in members(printed.reading)]
    except (TypeError, ValueError):
        return None
    if any(isinstance(m, sp.MatrixBase) for m in hand):
        return None
    hand_symbols = set().union(*(m.free_symbols for m in hand))
    formulas = formula_symbols(hand_symbols)      # a hand symbol named like a formula stands for it
    hand = [m.subs(formulas) for m in hand] if formulas else hand
    hand_symbols = set().union(*(m.free_symbols for m in hand))
    known = set(domain.intervals) | set(results)
    targets = known | set().union(*(m.free_symbols for m in hand))
    names = frozenset(canonical(s.name) for s in targets)
    declared = {}                       # the quote's declared symbols: a printed letter is the module's ...
    for letter, target, _ in printed.symbols:
        try:
            (key,), _ = read(letter, names).rows[0]
        except (Unreadable, ValueError):
            continue
        declared[key] = target
    points = _sieve_points(domain, sorted(domain.intervals, key=lambda s: s.name), seed)
    if not points:
        return None
    derived = {}                        # each result symbol's value at the sieve points

    def value(expr, k):
        for s in expr.free_symbols & set(results):
            if (s, k) not in derived:
                closed = results[s]
                for _ in range(12):
                    if not closed.free_symbols & set(results):
                        break
                    closed = closed.xreplace(results)
                derived[(s, k)] = sp.N(closed.doit().xreplace(points[k]), _SIEVE_DIGITS)
        return sp.N(expr.xreplace({s: derived[(s, k)] for s in expr.free_symbols & set(results)})
                    .xreplace(points[k]).doit(), _SIEVE_DIGITS)

    def chain_of(text):
        rows = read(text, names).rows
        if len(rows) != 1 or any(r != "=" for r in rows[0][1]):
            return None
        ms = [m.subs(declared) if declared else m for m in rows[0][0] if m is not None]
        printed_symbols = set().union(*(m.free_symbols for m in ms))
        mapping = match_symbols(printed_symbols, hand_symbols, set())     # the hand reading's symbols first
        mapping.update(match_symbols(printed_symbols - set(mapping), known, set()))
        ms = [m.xreplace(mapping) for m in ms]
        if rows[0][0][0] is None or len(ms) == 1:       # the left side lost to the prose is the hand reading's
            ms = hand[:max(1, len(hand) - len(ms))] + ms
        if len(ms) == len(hand):        # a member that is a lone symbol the derivation does not know names
            ms = [h if isinstance(m, sp.Symbol) and m not in known else m for m, h in zip(ms, hand)]  # the hand's
        if any(not m.free_symbols <= known for m in ms):
            return None
        return tuple(ms)

    def holds(text):
        try:
            chain = chain_of(text)
            if chain is None:
                return None
            for k in range(len(points)):
                vs = [value(m, k) for m in chain]
                if any(not v.is_number or v.has(sp.zoo, sp.nan) for v in vs):
                    return None
                allowed = max(sp.Float(10) ** (5 - _SIEVE_DIGITS) * max(1, *(abs(v) for v in vs)),
                              sp.Float(printed.tolerance or 0) * (1 + sp.Float(10) ** -9))   # printed digits
                if any(abs(a - b) > allowed for a, b in zip(vs, vs[1:])):
                    return None
        except (Unreadable, ArithmeticError, TypeError, ValueError, ZeroDivisionError, RecursionError):
            return None
        r = decide(chain)
        return r.status if r.status in ("proved", "sampled") else None

    return holds


def same_reading(text: str, other: str) -> bool | None:
    """Whether *text* and *other* (LaTeX, or an excerpt with one math span) read to the same rows of
    SymPy expressions (the allow-list reader, no vocabulary): how an edit is recognised as a booked
    correction; ``None`` when either cannot be read (then no one can say)."""
    try:
        rows = [[tuple(r[0]) for r in read(excerpt_math(t) or t).rows] for t in (text, other)]
    except (Unreadable, RecursionError, ValueError, TypeError):
        return None
    return rows[0] == rows[1]


def smallest_correction(printed, results: dict, domain: Domain, seed: str, decide, booked: str) -> str:
    """The erratum's evidence sentence on the search: the likeliest of the :data:`EVIDENCE_BUDGET` likeliest
    edits of *printed*'s excerpt that makes it hold, and whether it is the *booked* correction; ``""`` when
    the search cannot run (no one formula in the excerpt, no hand reading that is a chain)."""
    tex = excerpt_math(printed.excerpt)
    holds = print_test(printed, results, domain, seed, decide) if tex is not None else None
    if holds is None:
        return ""
    found = corrections(tex, holds, limit=1, budget=EVIDENCE_BUDGET)
    if not found:
        return f"The correction search: no edit among the {EVIDENCE_BUDGET} likeliest makes the print hold."
    c = found[0]
    how = "confirmed by sampling" if c.status == "sampled" else c.status
    same = same_reading(c.text, booked)
    verdict = {True: "it is the booked one", False: "it is not the booked one",
               None: "whether it is the booked one cannot be read"}[same]
    return (f"The smallest correction found: ${c.text.rstrip('. ')}$ ({change_tex(c.change)}: {c.what}, {c.kind}; "
            f"{how}); {verdict}.")


def change_tex(change: str) -> str:
    """An edit (:attr:`~symfloat.engine.corrections.Correction.change`) in words, its TeX between dollars.

    >>> print(change_tex(r"\\nu → \\mu and v → V"))
    $\\nu$ → $\\mu$ and $v$ → $V$
    >>> print(change_tex(r"\\omega \\operatorname{tg} → \\operatorname{cotg} at all 2 places"))
    $\\omega \\operatorname{tg}$ → $\\operatorname{cotg}$ at all 2 places
    >>> change_tex("b and 2 exchanged across the fraction bar")
    '$b$ and $2$ exchanged across the fraction bar'
    """
    exchanged = re.fullmatch(r"(.+) and (.+) exchanged across the fraction bar", change)
    if exchanged:
        return f"${exchanged[1]}$ and ${exchanged[2]}$ exchanged across the fraction bar"
    core, places = re.fullmatch(r"(.+?)((?: at all \d+ places)?)", change).groups()
    return " and ".join(" → ".join(f"${side}$" if side.strip() else "nothing" for side in edit.split(" → "))
                        for edit in core.split(" and ")) + places
