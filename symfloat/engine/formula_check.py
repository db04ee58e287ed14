r"""Checking one formula of any text: a printed formula in LaTeX against another formula or a definition.

``check(printed, against)`` reads both with the allow-list reader (:mod:`symfloat.model.latex`;
nothing is evaluated as code), with their integrals (``\int_a^b f \, dx``).  Each row
``S = e`` of *against* whose left side is a symbol defines ``S``; a row without one is the value the
printed formula must have.  The definitions are put into the printed formula and every link of its
chain is decided by the engine's identity check (:func:`~symfloat.engine.identity.check_identity`):
exact sampling at seeded rational points of the domain, then a symbolic proof.  A refuted link is
shown at the simplest point where it fails (small whole numbers and halves first), its sides labelled
*printed* and *derived*.  Where a definition is an integral, a numeric witness integrates it by
quadrature (mpmath's tanh-sinh, never the closed form) at that point.  A side printed as a number with
decimals alone (``0,245``) stands for what rounds to it: against a closed value it holds within half a unit
in its last digit.  A refuted print gets the likeliest small edits that make it hold
(:mod:`symfloat.engine.corrections`), each proved, sampled or rounded.

>>> r = check(r"\bar z = \frac{3(2r-h)^2}{3(3r-h)}",
...           r"\bar z = \frac{\int_{r-h}^{r} x \pi (r^2 - x^2) \, dx}{\int_{r-h}^{r} \pi (r^2 - x^2) \, dx}",
...           where="h < r")
>>> r.verdict, r.counterexample["point"], r.counterexample["printed"], r.counterexample["derived"]
('refuted', {'h': '1', 'r': '2'}, '9/5', '27/20')
>>> r.witness["agrees_with"], [(c.text, c.kind, c.status) for c in r.corrections][:1]
('derived', [('\\bar z = \\frac{3(2r-h)^2}{4(3r-h)}', 'print-like', 'proved')])
>>> check(r"V = \frac{\pi h^2}{3} (3r - h)", r"V = \int_{r-h}^{r} \pi (r^2 - x^2) \, dx").verdict
'holds'
"""
from __future__ import annotations

import heapq
import itertools
import re
from dataclasses import dataclass, field
from decimal import Decimal, localcontext
from fractions import Fraction

import sympy as sp

from ..errors import InputError, quoted
from ..model.latex import Unreadable, read
from ..model.evidence_tex import tex_number
from ..model.symbol_names import tex_name
from .corrections import Correction, corrections
from .identity import DIGITS, Domain, check_identity, check_rounded, computable

__all__ = ["FormulaCheck", "check", "proposed", "parse_domain", "DEFAULT_INTERVAL"]

DEFAULT_INTERVAL = (0, 4)      # where a symbol without --domain is sampled: a positive length or ratio
_SMALL_POINTS = 400            # at most this many simple points are tried for the shown counterexample
_GRID = 20_000                 # at most this many points are ordered by simplicity, whatever the symbols' count
_WITNESS_POINTS = 20           # the simple points tried for a witness of a print that holds
_RANDOM_POINTS = 200           # then the seeded random points tried for a counterexample where both sides are real
_PROOF_SECONDS = 5.0           # the proof search of one link (the clock can end a search, never refute)
_RELATIONS = {"<": sp.StrictLessThan, ">": sp.StrictGreaterThan, "<=": sp.LessThan, ">=": sp.GreaterThan}


@dataclass
class FormulaCheck:
    """The verdict on a printed formula: ``holds`` (with ``evidence`` ``symbolic``, ``sampled (exact)``,
    ``sampled (60 digits)`` or ``rounded (60 digits)``), ``refuted`` (with the counterexample, its sides labelled)
    or ``undecided``; the witness's measurement where a definition is an integral; the corrections that make a
    refuted print hold; ``rounding``, where a printed number written with decimals was compared to its printed
    digits, half a unit in its last digit; ``reason``, why a print is undecided."""

    printed: str
    against: list
    verdict: str
    evidence: str
    strategy: str = ""
    samples: int = 0
    counterexample: dict | None = None
    witness: dict | None = None
    corrections: list = field(default_factory=list)
    tried: list = field(default_factory=list)
    rounding: str = ""
    reason: str = ""

    def to_json(self) -> dict:
        data = dict(self.__dict__)
        data["corrections"] = [c.to_json() for c in self.corrections]
        return data


_INTERVAL = re.compile(r"\s*(.+?)\s*=\s*([^:=]+?)\s*:\s*([^:=]+?)\s*")


def parse_domain(text: str | None) -> dict:
    """``--domain 'r=1:3, h=0:1'``: symbol name -> (low, high); a name as the formulas type it (``\\alpha``,
    ``x_{1}``, ``\\bar z``) or as the reader names it (``alpha``, ``zbar``), the ends whole numbers, p/q or
    decimals, kept exact.

    >>> parse_domain("r=1:3, h=0:1/2")
    {'r': (Fraction(1, 1), Fraction(3, 1)), 'h': (Fraction(0, 1), Fraction(1, 2))}
    >>> parse_domain(r"\\alpha=0.5:0.75, \\bar z = 1e-3:1")
    {'alpha': (Fraction(1, 2), Fraction(3, 4)), 'zbar': (Fraction(1, 1000), Fraction(1, 1))}
    """
    out = {}
    for part in (text or "").split(","):
        if not part.strip():
            continue
        m = _INTERVAL.fullmatch(part)
        if not m:
            raise InputError(f"--domain is name=low:high, ... (r=1:3, h=0:1/2), not {quoted(part.strip(), 40)}")
        name = _symbol_name(m[1])
        try:
            low, high = Fraction(m[2]), Fraction(m[3])
        except ZeroDivisionError:
            raise InputError(f"--domain divides by zero in {quoted(part.strip(), 40)}") from None
        except ValueError:
            raise InputError(f"--domain: an interval's ends are numbers (1, 1/2, 0.5, 1e-3), not "
                             f"{quoted(part.strip(), 40)}") from None
        if low >= high:
            raise InputError(f"--domain needs low < high, not {quoted(part.strip(), 40)}")
        if name in out:
            raise InputError(f"--domain gives {name} two intervals")
        out[name] = (low, high)
    return out


def _symbol_name(text: str) -> str:
    """The name of the symbol *text* types (``\\alpha``: ``alpha``), or *text* itself where it is already one."""
    try:
        rows = read(text).rows
    except Unreadable:
        rows = []
    if len(rows) == 1 and len(rows[0][0]) == 1 and isinstance(rows[0][0][0], sp.Symbol):
        return rows[0][0][0].name
    if re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", text):
        return text
    raise InputError(f"--domain names a symbol (r, \\alpha, x_{{1}}), not {quoted(text, 40)}")


# The signs of arithmetic a keyboard types as themselves, as the reader takes them
_SIGNS = str.maketrans({"×": r" \times ", "÷": " / ", "·": r" \cdot ", "−": "-"})


def _reading(tex: str, what: str, integrals=False):
    try:
        return read(tex.translate(_SIGNS), integrals=integrals)
    except Unreadable as exc:
        raise InputError(f"{what}: {exc}") from None


def _definitions(against: list[str]):
    """Symbol -> its definition (earlier definitions put in), the value a formula must have (``None`` if no
    row gives one), and symbol -> its definition as given."""
    defined, target = {}, None
    for tex in against:
        for members, relations in _reading(tex, "--against", integrals=True).rows:
            if any(r != "=" for r in relations) or members[0] is None:
                raise InputError(f"--against: a definition is S = expression or an expression, not {quoted(tex, 60)}")
            if len(members) == 1:
                if target is not None:
                    raise InputError(f"--against gives two values the print must have: {quoted(tex, 60)} and "
                                     "an earlier one")
                target = members[0]
            elif isinstance(members[0], sp.Symbol):
                if members[0] in defined:
                    raise InputError(f"--against defines {quoted(members[0].name)} twice")
                defined[members[0]] = members[-1]
            else:
                raise InputError(f"--against: the left side of {quoted(tex, 60)} is not a symbol")
    given = dict(defined)
    bound = _integrated(defined.values(), defined)
    if bound:
        raise InputError(f"--against defines {', '.join(bound)}, the variable of an integral in a definition")
    for _ in range(len(defined)):                                   # definitions may use earlier ones
        defined = {s: e.xreplace(defined) for s, e in defined.items()}
    circular = sorted(s.name for s in given if s in _reached(given, s))
    if circular:
        raise InputError(f"--against defines {', '.join(circular)} by itself, directly or through another definition")
    return defined, target, given


def _integrated(exprs, defined) -> list[str]:
    """The names of the *defined* symbols that an integral of *exprs* integrates over."""
    return sorted({v.name for e in exprs if e is not None for i in e.atoms(sp.Integral) for v in i.variables}
                  & {s.name for s in defined})


def _reached(given: dict, *start) -> set:
    """The defined symbols the definitions *given* of the symbols *start* use, directly or through others."""
    reached, todo = set(), [t for s in start for t in given[s].free_symbols if t in given]
    while todo:
        s = todo.pop()
        if s not in reached:
            reached.add(s)
            todo += [t for t in given[s].free_symbols if t in given]
    return reached


def _unused(given: dict, printed) -> list[str]:
    """The names of the definitions *given* that the *printed* formula's members do not reach, directly or through
    another definition."""
    named = {s for m in printed[0] if m is not None for s in m.free_symbols if s in given}
    return sorted(s.name for s in set(given) - named - _reached(given, *named))


def _constraints(where: str):
    """``h < r``, ``0 < h < r``: the relations that restrict the domain."""
    if not where:
        return ()
    out = []
    for members, relations in _reading(where, "--where").rows:
        if members[0] is None or not relations or any(r not in _RELATIONS for r in relations):
            raise InputError(f"--where holds inequalities such as 0 < h < r, not {quoted(where, 60)}")
        out += [_RELATIONS[r](a, b) for a, b, r in zip(members, members[1:], relations)]
    return tuple(out)


def _domain(symbols, intervals: dict, constraints) -> Domain:
    names = {s.name for s in symbols}
    unknown = sorted(set(intervals) - names)
    if unknown:
        raise InputError(f"--domain names {', '.join(unknown)}, which the formulas do not have")
    return Domain({s: intervals.get(s.name, DEFAULT_INTERVAL) for s in symbols}, constraints)


def _links(printed, defined, target):
    """The pairs to decide, each ``(a, b, label of a, label of b)``: a member that is a defined symbol
    (or the target value) is *derived*, the others *printed*, the definitions put into them."""
    members, relations = printed
    if any(r != "=" for r in relations) or members[0] is None:
        raise InputError("the printed formula is an equation (a = b, a chain a = b = c or an expression)")

    def side(m):
        if isinstance(m, sp.Symbol) and m in defined:
            return defined[m], "derived"
        try:
            return m.xreplace(defined), "printed"
        except ValueError:          # an integral's variable that a definition gives a value
            raise InputError("the printed formula integrates over a variable that --against defines") from None

    sides = [side(m) for m in members]
    if target is not None:
        sides.insert(0, (target, "derived"))
    if len(sides) < 2:
        raise InputError("nothing to compare: give --against the value or a definition of the printed symbol")
    return [(a, b, la, lb) for (a, la), (b, lb) in zip(sides, sides[1:])]


def _simple_values(lo, hi, count: int):
    """The *count* simplest rationals inside (lo, hi): whole numbers, then halves, thirds, quarters, each
    from the low end up.

    >>> [str(v) for v in _simple_values(0, 10**9, 5)], [str(v) for v in _simple_values(0, 2, 6)]
    (['1', '2', '3', '4', '5'], ['1', '1/2', '3/2', '1/3', '2/3', '4/3'])
    """
    lo, hi = Fraction(str(lo)), Fraction(str(hi))
    seen = {}
    for q in range(1, 5):
        p = (lo * q).__floor__()
        while len(seen) < count and Fraction(p, q) < hi:
            if lo < Fraction(p, q):
                seen.setdefault(Fraction(p, q), None)
            p += 1
    return list(seen)


def _simple_points(symbols, domain: Domain):
    """Admissible points of *symbols*, simplest first (small denominators, then small values), at most
    :data:`_SMALL_POINTS`: the simplest values of each symbol (as many as :data:`_GRID` points of all of them
    allow) combined best first, without listing every combination (2^20 of them for twenty symbols).

    >>> x, y = sp.symbols("x y")
    >>> [tuple(p.values()) for p in itertools.islice(_simple_points([x, y], Domain({x: (0, 4), y: (0, 4)})), 4)]
    [(1, 1), (1, 2), (2, 1), (1, 3)]
    """
    per_symbol = max(2, int(_GRID ** (1 / max(len(symbols), 1))))
    grids = [_simple_values(*domain.intervals[s], per_symbol) for s in symbols]
    if not all(grids):
        return

    def key(index):             # a point is simpler than another by this (its values' order in each grid agrees)
        values = [g[i] for g, i in zip(grids, index)]
        return sum(v.denominator for v in values), sum(values), index

    first = (0,) * len(grids)
    frontier, seen = [key(first)], {first}
    for _ in range(_SMALL_POINTS):
        if not frontier:
            return
        *_, index = heapq.heappop(frontier)
        point = {s: sp.Rational(g[i].numerator, g[i].denominator) for s, g, i in zip(symbols, grids, index)}
        if domain.admits(point):
            yield point
        for k in range(len(index)):
            after = index[:k] + (index[k] + 1,) + index[k + 1:]
            if index[k] + 1 < len(grids[k]) and after not in seen:
                seen.add(after)
                heapq.heappush(frontier, key(after))


_NUMERIC = (sp.Integral, sp.hyper, sp.meijerg, sp.exp_polar)     # what a value is computed from, not shown in


def _closed(value):
    """*value* (closed) as shown: as it is, or where it holds an integral SymPy left or a hypergeometric function
    its integration made (``\\int_0^1 \\sqrt{1 + x^3} \\, dx``), to 30 digits (real where its imaginary part is
    below 10^-25 of it, the rounding of a real value computed through complex ones)."""
    if not value.has(*_NUMERIC):
        return value
    v = sp.N(value, 30)
    re, im = v.as_real_imag()
    return sp.N(re, 30) if abs(im) <= sp.Float(10) ** -25 * max(abs(re), 1) else v


def _differing(a, b, point):
    """``(value of a, value of b)`` at *point* where both are real numbers that differ (by more than 10^-20 of
    their size where a value is numeric: an integral without a closed form), else ``None``; a point where a power
    would be too large to compute (:func:`~symfloat.engine.identity.computable`) is passed over."""
    if not (computable(a, point) and computable(b, point)):
        return None
    try:
        va, vb = (_closed(sp.simplify(x.xreplace(point))) for x in (a, b))
    except (ArithmeticError, ZeroDivisionError, TypeError, ValueError):
        return None
    if va.free_symbols or vb.free_symbols or any(v.has(sp.zoo, sp.nan, sp.oo, -sp.oo, *_NUMERIC) for v in (va, vb)):
        return None
    if va.is_real is False or vb.is_real is False:      # a point where a side is not a real number
        return None
    difference = sp.simplify(va - vb)
    if difference == 0 or difference.free_symbols:
        return None
    size = max(abs(sp.N(va, 30)), abs(sp.N(vb, 30)), 1)
    return (va, vb) if abs(sp.N(difference, 30)) > sp.Float(10) ** -20 * size else None


def _tried_points(symbols, domain: Domain, seed: str):
    """The admissible points a counterexample is looked for at: the simple points (:func:`_simple_points`), then
    those of :data:`_RANDOM_POINTS` seeded random points that *domain* admits."""
    yield from _simple_points(symbols, domain)
    draw = domain.sampler(seed)
    for _ in range(_RANDOM_POINTS):
        point = draw(symbols)
        if domain.admits(point):
            yield point


def _simplest_counterexample(a, b, domain: Domain, seed: str):
    """The first point, in order of simplicity, where *a* and *b* (evaluated) are real numbers that differ (else the
    first such random point), with both values, or ``None``."""
    for point in _tried_points(sorted(a.free_symbols | b.free_symbols, key=lambda s: s.name), domain, seed):
        if (values := _differing(a, b, point)) is not None:
            return (point, *values)
    return None


def _shown(point, va, vb, la, lb) -> dict:
    """The counterexample's point and sides as strings (SymPy's), and as TeX under ``tex`` for a reader: the
    refuted link's ``left`` and ``right`` values with their labels (``sides``), and under ``printed`` and
    ``derived`` the side so labelled (``""`` where the link has none: a link between two printed members, or
    two defined symbols, compares sides of one kind)."""
    values = {lb: vb, la: va}           # sides of one kind: the left one under its label
    tex = {"point": {_tex(sp.Symbol(str(k))): _tex(v) for k, v in point.items()},
           **{side: _tex(values[side]) if side in values else "" for side in ("printed", "derived")},
           "left": _tex(va), "right": _tex(vb)}
    return {"point": {str(k): str(v) for k, v in point.items()},
            "printed": str(values.get("printed", "")), "derived": str(values.get("derived", "")),
            "left": str(va), "right": str(vb), "sides": [la, lb], "tex": tex}


def _tex(value) -> str:
    r"""*value* (a SymPy expression, or a number as a string) as TeX, each symbol under its typeset name and a
    symbol the reader made of ``\bar z`` (``zbar``) as ``\bar{z}``.

    >>> _tex(sp.sqrt(2) * sp.pi * sp.Symbol("lambda") * sp.Symbol("rbar")), _tex("9/5")
    ('\\sqrt{2} \\pi \\lambda \\bar{r}', '\\tfrac{9}{5}')
    """
    if isinstance(value, str):
        try:
            return tex_number(value)
        except ValueError:
            return value
    names = {}
    for s in value.free_symbols:
        base = s.name[:-3] if s.name.endswith("bar") and len(s.name) > 3 else None
        names[s] = rf"\bar{{{tex_name(base) or base}}}" if base else tex_name(s.name) or s.name
    return sp.latex(value, symbol_names=names)


def _counterexample(a, b, la, lb, domain, seed: str):
    """The counterexample shown: the simplest point where both sides are real numbers that differ, or ``None``
    where no such point is found (the sides differ where one of them is not real: ``\\sqrt{x - 3}`` beside
    ``\\sqrt{3 - x}``)."""
    found = _simplest_counterexample(a.doit(), b.doit(), domain, seed)
    return _shown(*found, la, lb) if found is not None else None


def _witness(links, point) -> dict | None:
    """Where a derived side holds an integral: both sides at *point*, the integral by quadrature."""
    for a, b, la, lb in links:
        derived, printed = (a, b) if la == "derived" else (b, a)
        if la == lb or not derived.has(sp.Integral):
            continue
        subs = {sp.Symbol(k): sp.Rational(v) for k, v in point.items()}
        # subs, not xreplace: an integral's own variable may share a name with a symbol of the point
        measured = sp.N(derived.subs(subs), 30)                    # Integral.evalf: quadrature, not integration
        claimed = sp.N(printed.subs(subs).doit(), 30)
        closed = sp.N(derived.doit().subs(subs), 30)
        if not all(v.is_real and v.is_finite for v in (measured, claimed, closed)):
            return None                                            # no value there (0/0, a pole, a complex one)
        scale = max(abs(measured), 1)
        agree_printed = abs(measured - claimed) <= sp.Float(10) ** -20 * scale
        agree_derived = abs(measured - closed) <= sp.Float(10) ** -20 * scale
        return {"method": "quadrature (mpmath tanh-sinh, 30 digits)", "point": dict(point),
                "measured": sp.sstr(measured, full_prec=False), "printed": sp.sstr(claimed, full_prec=False),
                "agrees_with": "printed" if agree_printed else "derived" if agree_derived else "neither",
                "tex": {"point": {_tex(sp.Symbol(k)): _tex(v) for k, v in point.items()}}}
    return None


_DECIMAL = re.compile(r"-?\d+(?:[.,]|\{,\})(\d+)")


def _side_texts(printed: str, members, target) -> list[str]:
    """The text of each side of :func:`_links` as typed (``""`` for the target value, and for every side where the
    print does not split into its members at its equals signs)."""
    texts = [t.strip() for t in printed.strip().strip("$").split("=")]
    return ([""] if target is not None else []) + (texts if len(texts) == len(members) else [""] * len(members))


def _roundings(printed: str, members, target) -> list:
    """For each link of :func:`_links`, half a unit in the last digit of each of its printed sides written as a
    decimal number alone (``0,245``: 1/2000), summed, or ``None`` where neither side is one.

    >>> _roundings("y = 0,245", read("y = 0,245").rows[0][0], None), _roundings("y = 1/3", [None, None], None)
    ([1/2000], [None])
    """
    texts = _side_texts(printed, members, target)
    halves = [sp.Rational(1, 2 * 10 ** len(m.group(1))) if (m := _DECIMAL.fullmatch(t)) else None for t in texts]
    return [None if a is None and b is None else (a or 0) + (b or 0) for a, b in zip(halves, halves[1:])]


def _decimal(q) -> str:
    """The rational *q*, whose denominator divides a power of ten, as a decimal (1/2000: ``0.0005``)."""
    with localcontext() as ctx:
        ctx.prec = 100
        return format(Decimal(int(q.p)) / Decimal(int(q.q)), "f")


def _decide(links, domain, seed, prove=True, roundings=()):
    """The weakest link's outcome: ``(status, result, link)``.  A link of two closed numbers with a *rounding*
    (:func:`_roundings`) agrees where they differ by at most that, at 60 digits."""
    order = {"refuted": 0, "undecided": 1, "sampled": 2, "agrees": 2, "proved": 3}
    worst = None
    roundings = list(roundings) + [None] * (len(links) - len(roundings))
    for link, rounding in zip(links, roundings):
        if rounding is not None and not (link[0].free_symbols or link[1].free_symbols):
            r = check_rounded(link[0], link[1], rounding, seed)
        else:
            r = check_identity(link[0], link[1], domain, seed, prove=prove, limit=_PROOF_SECONDS)
        if worst is None or order[r.status] < order[worst[0].status]:
            worst = (r, link)
        if r.status == "refuted":
            break
    return worst


def check(printed: str, against, *, where: str = "", domain: dict | None = None,
          propose: bool = True) -> FormulaCheck:
    r"""Check the LaTeX formula *printed* against *against* (a LaTeX formula or definition, or a list of
    them) on *domain* (symbol name -> interval, default :data:`DEFAULT_INTERVAL`) restricted by
    *where* (inequalities, ``0 < h < r``).  See the module docstring; *propose* searches the corrections
    of a refuted print."""
    against = [against] if isinstance(against, str) else list(against)
    shown, printed = printed, printed.translate(_SIGNS)
    defined, target, given = _definitions(against)
    rows = _reading(printed, "the printed formula", integrals=True).rows
    if len(rows) != 1:
        raise InputError("check one printed formula at a time")
    bound = _integrated(rows[0][0], defined)
    if bound:
        raise InputError(f"the printed formula integrates over {', '.join(bound)}, which --against defines")
    unused = _unused(given, rows[0])
    if unused:
        raise InputError(f"--against defines {', '.join(unused)}, which the printed formula does not use "
                         "(a misspelt name defines nothing)")
    constraints = tuple(c.xreplace(defined) for c in _constraints(where))     # a defined symbol's definition put in
    links = _links(rows[0], defined, target)
    symbols = set().union(*(a.free_symbols | b.free_symbols for a, b, *_ in links))
    stray = sorted({s.name for c in constraints for s in c.free_symbols - symbols})
    if stray:
        raise InputError(f"--where names {', '.join(stray)}, which no formula has (a misspelt symbol restricts nothing)")
    named = sorted(set(domain or {}) & {s.name for s in defined})
    if named:
        raise InputError(f"--domain gives {', '.join(named)} an interval, which --against defines: the symbols its "
                         "definition uses are sampled")
    space = _domain(symbols, domain or {}, constraints)
    if constraints and next(_tried_points(sorted(symbols, key=lambda s: s.name), space, printed), None) is None:
        raise InputError(f"--where admits no point of {_RANDOM_POINTS} drawn from the domain: {quoted(where, 60)}")
    roundings = _roundings(printed, rows[0][0], target)
    r, link = _decide(links, space, printed, roundings=roundings)
    verdict = {"proved": "holds", "sampled": "holds", "agrees": "holds", "refuted": "refuted"}.get(r.status,
                                                                                                   "undecided")
    digits = "exact" if r.exact else f"{DIGITS} digits"
    kind = {"sampled": "sampled", "agrees": "rounded"}.get(r.status, "counterexample")
    evidence = "symbolic" if r.evidence == "symbolic" else f"{kind} ({digits})"
    rounding = roundings[links.index(link)]
    rounded = rounding is not None and not (link[0].free_symbols or link[1].free_symbols)
    result = FormulaCheck(shown, against, verdict, evidence if verdict != "undecided" else "", r.strategy,
                          r.samples, tried=list(r.tried), rounding=_decimal(rounding) if rounded else "")
    if r.status == "refuted":
        result.counterexample = _counterexample(*link, space, printed)
        if result.counterexample is None:
            result.verdict, result.evidence = "undecided", ""
            result.reason = "the sides differ only where one of them is not a real number"
            return result
        if rounded:                 # a number compared to its printed digits is shown as printed
            i = links.index(link)
            for place, label, text in zip(("left", "right"), link[2:], _side_texts(printed, rows[0][0], target)[i:]):
                if label == "printed" and _DECIMAL.fullmatch(text):
                    result.counterexample["tex"][place] = result.counterexample["tex"]["printed"] = text
        result.witness = _witness(links, result.counterexample["point"])
        if propose:
            result.corrections = proposed(printed, defined, target, space)
    elif verdict == "undecided":
        result.reason = ("at no sampled point do both sides have a finite value (a division by zero, a power too "
                         "large to compute)")
    elif verdict == "holds":
        witnesses = (_witness(links, point) for point in _first_points(links, space))
        result.witness = next((w for w in witnesses if w is not None), None)
    return result


def _first_points(links, domain):
    """The simplest admissible points of the links' symbols (where a witness measures a print that holds)."""
    symbols = sorted(set().union(*(a.free_symbols | b.free_symbols for a, b, *_ in links)), key=lambda s: s.name)
    for point in itertools.islice(_simple_points(symbols, domain), _WITNESS_POINTS):
        yield {str(s): str(v) for s, v in point.items()}


def proposed(printed: str, defined: dict, target, domain: Domain) -> list[Correction]:
    """The likeliest edits of *printed* that make it hold against the same definitions; an edit that brings a
    defined symbol into a member of the print (where its definition would be put in: the print stated by what it
    should equal) is not one."""
    def _inside(members) -> set:
        return {s for m in members if m is not None and not (isinstance(m, sp.Symbol) and m in defined)
                for s in m.free_symbols if s in defined}

    inside = _inside(read(printed, integrals=True).rows[0][0])

    def holds(text):
        try:
            rows = read(text, integrals=True).rows
            links = _links(rows[0], defined, target) if len(rows) == 1 else None
        except (Unreadable, InputError):
            return None
        if links is None or not set().union(*(a.free_symbols | b.free_symbols for a, b, *_ in links)) \
                <= set(domain.intervals):
            return None
        if all(a == b and la == lb for a, b, la, lb in links):
            return None           # one side's thing equal to itself (h = h, y = y for y = h) proves nothing
        if _inside(rows[0][0]) - inside:
            return None           # a defined symbol brought into a printed member (y = y^2 for y = x^2, y = 1)
        roundings = _roundings(text, rows[0][0], target)
        if _decide(links, domain, printed, prove=False, roundings=roundings)[0].status not in ("sampled", "agrees"):
            return None
        status = _decide(links, domain, printed, roundings=roundings)[0].status
        return {"agrees": "rounded"}.get(status, status) if status in ("proved", "sampled", "agrees") else None

    return corrections(printed, holds)
