"""The definition route: a printed formula measured from the definitions it depends on.

A derivation introduces each quantity once, in the first step whose result it is (the member
after the symbol is the definition as stated, e.g. ``T = ∫ u² df``), and later steps derive
closed forms for it.  The identity checks compare a reading with those derived closed forms;
this witness compares it with the *definitions*: every quantity of the reading is replaced by its
defining member (recursively, in the order the steps introduce them), derivatives and
substitutions are carried out exactly, and what remains -- defining integrals included -- is
evaluated numerically at seeded sample points of the derivation's domain: integrals by nested
quadrature (``mpmath.quad``), at 15 digits in hardware doubles (mpmath's float context, its
quadrature and extrapolation without mpmath's software numbers) and at 30 digits.  The first
member of the chain is the measured quantity, every other member a value the print (or its
correction) claims.  Where every member has a rule in ball arithmetic the route decides in Arb first
(:func:`~symfloat.engine.definition_enclosure.route_enclosure`); where that ball decides, it is the route's
only record, and neither method runs (``symfloat bench`` measures them against the enclosure).

It runs for every formula that no declared witness targets, so a numeric cross-check does not
depend on someone writing one.  A member that is, once the definitions are in, the same SymPy
expression as the measured one is not compared (that would evaluate one expression twice); a
chain with nothing left to compare gets a note saying so and no record.

A relation (:mod:`symfloat.model.relation`) is decided on its domain by the relation check, from
the derived closed forms.  The route cross-checks it where its quantities have definitions: each
inequality of its statement compares a difference ``lhs - rhs``, measured from the definitions and
compared with the closed form the relation check used, at the relation check's counterexample (when
it found one) and at seeded points of the domain, at 15 and 30 digits; with the definitions' values
(their signs clearly away from zero) the statement must hold at those points.  Where a side is within
its error of zero where the relation check refutes the statement (at its counterexample, or at every
point the route takes: the neutral case of a condition stated with >=, where the stability vanishes),
the route cannot read the statement there: it records nothing, so that it neither agrees with a
refuted print nor refutes it.  A relation whose
differences are, with the definitions in, the closed forms themselves has no numeric content.

A root count (``RealRoots``, exact by Sturm sequences on the closed form in the relation check:
Scheeffer IX's case tables, X (172)) is counted by another method at the same points (and so is a count
an identity states, IX's counts at exact points), and for a case
table or an implication also at a point where each row's condition holds (if one is drawn): the
polynomial's coefficients evaluated there at 15 and 30 digits, its roots by ``mpmath.polyroots`` with
inclusion discs (:mod:`symfloat.engine.root_count`); a count the discs do not decide leaves the point
unread (said in the note).  The records compare the numeric count with the Sturm count at each point,
and the statement is read with the numeric counts.
"""
from __future__ import annotations

import functools
import itertools
import time
from dataclasses import dataclass

import mpmath
import sympy as sp
from sympy.printing.pycode import MpmathPrinter

from ..model.claim import members
from ..model.relation import Cases, Holds, RealRoots
from .definition_enclosure import route_enclosure
from .enclosure import Unsupported
from .extrapolation import UnsettledLimit, extrapolated_limit
from .identity import Domain
from .quadrature import gauss_legendre
from .relation import boundary_points, inserted, random_points, relation_intervals, statement, truth
from .root_count import count_real_roots
from .witness import Outcome, Precision, record_agrees, record_decision, undecided_reason

__all__ = ["DefinitionRoute", "NothingToMeasure", "definitions", "route_readings", "ROUTE_METHODS"]

# A defining integral may have a square root vanishing at an endpoint (Euler's ellipse, 1/sqrt(b^2 - y^2));
# tanh-sinh nodes rounded past it lose half the working digits.  So each precision is trusted to half
# its digits, less one: 1e-6.5 at 15 digits, 1e-14 at 30.
ROUTE_METHODS = (Precision(15, 10 ** -6.5), Precision(30, 1e-14))
SAMPLES = 3
MAX_DRAWS = 200
PREMISE_DRAWS = 800         # further draws for a case-table row or premise the first draws did not meet


def definitions(steps) -> dict:
    """Quantity -> its defining member: the member after the symbol in the first step whose
    result it is (the first member if the symbol is not written in that step)."""
    out = {}
    for s in steps:
        if s.result is None or s.result in out:
            continue
        ms = members(s.claim)
        out[s.result] = ms[1] if ms[0] == s.result else ms[0]
    return out


def _expanded(expr, defs, memo, stack=()):
    """*expr* with every defined quantity replaced by its definition, recursively."""
    if isinstance(expr, sp.MatrixBase):
        return expr.applyfunc(lambda e: _expanded(e, defs, memo, stack))
    expr = sp.sympify(expr)
    found = {q for q in expr.free_symbols if q in defs}
    if not found:
        return expr
    values = {}
    for q in found:
        if q in stack:
            raise ValueError(f"the definition of {q} depends on itself ({' -> '.join(map(str, stack + (q,)))})")
        if q not in memo:
            memo[q] = _expanded(defs[q], defs, memo, stack + (q,))
        values[q] = memo[q]
    return expr.xreplace(values)


def _singular(f, variables) -> bool:
    """Can *f* be singular (a fractional power, a logarithm) in one of the *variables*?"""
    return any(p.exp.is_Integer is not True and p.base.free_symbols & set(variables)
               for p in f.atoms(sp.Pow)) or any(g.free_symbols & set(variables) for g in f.atoms(sp.log))


class _NestedQuadPrinter(MpmathPrinter):
    """Prints an integral as nested one-dimensional ``mpmath.quad`` calls, innermost variable
    first, so that a limit may depend on the outer variables (mpmath's own multidimensional
    ``quad`` needs constant limits, and SymPy flattens nested integrals into one).  ``maxdegree``
    caps each rule's refinement: :class:`_RoughQuadPrinter` estimates a size, not a value."""

    maxdegree = None

    def _print_Integral(self, e):
        # tanh-sinh copes with a root or logarithm singular at an endpoint (1/sqrt(b^2 - y^2) at
        # y = b) but costs hundreds of nodes per dimension; Gauss-Legendre is exact after a few
        # refinements for the polynomial and trigonometric integrands of moments
        rule = "'tanh-sinh'" if _singular(e.function, e.variables) else "gauss_legendre"
        cap = f", maxdegree={self.maxdegree}" if self.maxdegree else ""
        body = self._print(e.function)
        for lim in e.limits:
            if len(lim) != 3:
                raise ValueError(f"an integral over {lim[0]} without both limits has no value")
            v, lo, hi = (self._print(t) for t in lim)
            body = f"{self._module_format('mpmath.quad')}(lambda {v}: {body}, ({lo}, {hi}), method={rule}{cap})"
        return body

    def _print_NumericLimit(self, e):
        expr, z, z0, direction = e.args
        # each integral once per value of z, however often the expression repeats it (a centroid's quotient
        # in every term of a moment: twelve integrals met 48 times)
        integrals = list(dict.fromkeys(_outermost_integrals(expr)))
        names = [sp.Symbol(f"_integral_{k}") for k in range(len(integrals))]
        inner = self._print(expr.xreplace(dict(zip(integrals, names))))
        if integrals:
            inner = (f"(lambda {', '.join(map(self._print, names))}: {inner})"
                     f"({', '.join(map(self._print, integrals))})")
        body = f"lambda {self._print(z)}: {inner}"
        # "mpmath" is the compiled code's context (mpmath.mp, or the float64 one)
        at = f"{'' if z0 == sp.oo else '-'}mpmath.inf" if z0 in (sp.oo, -sp.oo) else self._print(z0)
        return f"extrapolated_limit(mpmath, {body}, {at}, {int(direction)})"


def _outermost_integrals(expr) -> list:
    """The integrals of *expr* not inside another integral, in the order of a walk of its tree, repeats kept."""
    if isinstance(expr, sp.Integral):
        return [expr]
    return [i for a in expr.args for i in _outermost_integrals(a)]


class _RoughQuadPrinter(_NestedQuadPrinter):
    maxdegree = 2


class NumericLimit(sp.Expr):
    """``Limit(expr, z, z0, dir)`` that SymPy cannot take (a limit of an integral whose limits depend on
    ``z``: the regular n-gon as n -> oo, a section that collapses at zero tilt), left to numeric
    extrapolation (:func:`extrapolated_limit`)."""

    is_extended_real = True                 # the limit of a real quantity (a moment, an area)

    def __new__(cls, expr, z, z0, direction):
        return sp.Expr.__new__(cls, expr, z, z0, direction)

    @property
    def free_symbols(self):
        expr, z, z0, _ = self.args
        return (expr.free_symbols - {z}) | z0.free_symbols


def _numeric_limit(e: sp.Limit):
    expr, z, z0, direction = e.args
    return NumericLimit(_carried_out(expr), z, z0, sp.Integer(-1 if str(direction) == "-" else 1))


_HeldSign = sp.Function("held_sign")      # a sign kept from doit while the rest is carried out (below)


def _carried_out(m):
    """Derivatives, substitutions, sums and limits of *m* carried out exactly (integrals are left to
    quadrature): they must be done before a sample point replaces their variables.  A limit SymPy
    cannot take is left to :class:`NumericLimit`."""
    if isinstance(m, sp.MatrixBase):
        return m.applyfunc(_carried_out)
    return _carried_out_once(m)


@functools.lru_cache(maxsize=4096)
def _carried_out_once(m):
    """:func:`_carried_out` of an expression, once: a reading and its correction share their measured member, and
    a definition's terms recur in the members of several readings."""
    if not m.has(sp.Derivative, sp.Subs, sp.Sum, sp.Limit):
        return m
    m = m.replace(lambda e: isinstance(e, sp.Subs), _substituted)
    # SymPy's sign drops the hints of doit, so the integrals inside a sign would be carried out by SymPy
    # instead of quadrature: a sign is held as an undefined function while the rest is done
    m = m.replace(sp.sign, _HeldSign)
    try:
        done = m.doit(integrals=False)
    except NotImplementedError:              # "Don't know how to calculate the mrv of Integral(...)"
        done = m.replace(lambda e: isinstance(e, sp.Limit), _numeric_limit).doit(integrals=False)
    return done.replace(_HeldSign, sp.sign)


def _collapsed(expr) -> bool:
    """Has *expr* an integral over an interval of length zero (a tilted section at zero tilt), which
    a ratio of such integrals turns into 0/0?"""
    return any(len(lim) == 3 and (lim[1] - lim[2]).is_zero for i in expr.atoms(sp.Integral) for lim in i.limits)


def _substituted(e: sp.Subs):
    """A substitution carried out; where a term of the definitions is singular at the point
    (``6 a z (... - 2 a (1 - s)/(3 z))`` at z = 0, or an integral over a section that shrinks to a line
    at zero tilt) but the whole is not, its limit there."""
    inner = _carried_out(e.expr)
    value = inner.subs(list(zip(e.variables, e.point)))                  # in order, as Subs.doit
    if len(e.variables) == 1 and (value.has(sp.nan, sp.zoo, sp.oo, -sp.oo) or _collapsed(value)):
        if inner.has(sp.Integral):                      # the limit of a quadrature, by extrapolation
            return NumericLimit(inner, e.variables[0], sp.sympify(e.point[0]), sp.Integer(1))
        return sp.limit(inner, e.variables[0], e.point[0])
    return value


def _components(m):
    return list(m) if isinstance(m, sp.MatrixBase) else [m]


class _Float64:
    """mpmath's float64 context (``mpmath.fp``: its quadrature and extrapolation in hardware doubles) as the
    compiled code calls it; a number the printer writes as an mpf's tuple is read as a double."""

    def __getattr__(self, name):
        return getattr(mpmath.fp, name)

    @staticmethod
    def mpf(value):
        return float(mpmath.mpf(value))


FLOAT64 = _Float64()


@functools.lru_cache(maxsize=512)
def _compiled(expr, printer, ctx=mpmath.mp):
    """*expr* as a function of its free symbols (sorted by name), integrals as nested quadrature, in mpmath's
    context *ctx*.  Compiled before the numbers go in: a printer ordering a closed sum's terms would evaluate them."""
    args = sorted(expr.free_symbols, key=lambda q: q.name)
    return args, sp.lambdify(args, expr, modules=[{"mpmath": ctx, "gauss_legendre": gauss_legendre,
                                                         "extrapolated_limit": extrapolated_limit}, "mpmath"],
                             printer=printer)


def _numeric(expr, point, dps, printer=_NestedQuadPrinter):
    """The value of *expr* at *point* (exact numbers) to *dps* digits; integrals by nested quadrature.
    An integral that is closed at *point* (a centroid inside a moment's integrand) is computed once,
    the smallest first, and its value inserted where it occurs."""
    if not expr.has(sp.Integral, NumericLimit):
        v = sp.N(expr.xreplace(point), dps + 5, chop=True)   # an exact zero stays zero
        if v.free_symbols:
            raise ValueError(f"free symbols {sorted(map(str, v.free_symbols))} remain")
        if not v.is_number:
            own = sorted({f.func.__name__ for f in v.atoms(sp.Function) if not f.func.__module__.startswith("sympy")}
                         | {str(f.func) for f in v.atoms(sp.core.function.AppliedUndef)})
            raise ValueError(f"{', '.join(own) or 'a part'} has no numeric value (a function no step defines)")
        return v
    known = set(point)
    closed = sorted((i for i in expr.atoms(sp.Integral) if i.free_symbols <= known), key=sp.count_ops)
    values: dict = {}
    for i in closed:
        values[i] = _quadrature(i.xreplace(values), point, dps, printer)
    rest = expr.xreplace(values)
    return _quadrature(rest, point, dps, printer) if rest.has(sp.Integral, NumericLimit) else _numeric(rest, point, dps)


def _quadrature(expr, point, dps, printer):
    if dps <= 15:
        try:
            return _quadrature_in(FLOAT64, expr, point, dps, printer)
        except UnsettledLimit:      # a limit whose values cancel more than doubles can carry
            pass
    return _quadrature_in(mpmath.mp, expr, point, dps, printer)


def _quadrature_in(ctx, expr, point, dps, printer):
    args, f = _compiled(expr, printer, ctx)
    missing = [q for q in args if q not in point]
    if missing:
        raise ValueError(f"free symbols {sorted(map(str, missing))} remain")
    with mpmath.workdps(dps):
        v = f(*(ctx.mpf(point[q].p) / point[q].q if point[q].is_Rational else ctx.mpf(sp.N(point[q], dps + 5))
                for q in args))
        # a node rounded past an endpoint where a square root vanishes gives an imaginary part
        # of the order of the square root of the unit roundoff
        if isinstance(v, (mpmath.mpc, complex)):
            if abs(v.imag) > mpmath.mpf(10) ** (2 - dps // 2) * max(1, abs(v.real)):
                raise ValueError(f"the definitions give the complex value {v}")
            v = v.real
        return sp.Float(v, dps + 5)


def _magnitude(expr):
    """*expr* with every sum replaced by the sum of its terms' absolute values, through products,
    integer powers and integrands (not limits, not a function's argument): the size of the numbers
    its evaluation adds, against which a cancelling result's rounding is measured."""
    if isinstance(expr, sp.Integral):
        return sp.Integral(_magnitude(expr.function), *expr.limits)
    if isinstance(expr, NumericLimit):      # the size of the terms where the extrapolation samples
        inner, z, z0, direction = expr.args
        if z0 in (sp.oo, -sp.oo):
            return NumericLimit(_magnitude(inner), z, z0, direction)
        return _magnitude(inner).xreplace({z: z0 + direction / sp.Integer(3)})     # its first sample
    if expr.is_Add:
        return sp.Add(*[_magnitude(t) for t in expr.args])
    if expr.is_Mul:
        return sp.Mul(*[_magnitude(t) for t in expr.args])
    if expr.is_Pow and expr.exp.is_Integer:
        return sp.Pow(_magnitude(expr.base), expr.exp)
    return sp.Abs(expr)


def _difference(measured, value, claimed, point, method):
    """Absolute and relative difference of a claimed value from the measured one at *method*'s
    precision.  The relative difference is taken against the larger of the two values, or, where
    that is smaller than the difference allows (a quantity that cancels to zero, an equilibrium
    condition), against the magnitude of the terms whose sums produced them."""
    c = _numeric(claimed, point, method.dps)
    ab = abs(value - c)
    scale = max(abs(value), abs(c))
    if ab > method.tolerance * scale:
        scale = max([scale, *(abs(_numeric(_magnitude(e), point, 10, _RoughQuadPrinter)) for e in (measured, claimed)
                              if not e.has(RealRoots))])     # a root count is its own magnitude
    return float(ab), float(ab / scale) if scale else float(ab)


def _certified(measured, claims, cases, allowance):
    """The certified record of the claims against the measured components in ball arithmetic
    (:func:`~symfloat.engine.definition_enclosure.route_enclosure`), or ``None`` where the members have no
    rigorous rule, no finite enclosure, or one SymPy cannot build at a point (a pole of a member there): the route
    then compares its methods as before, and they say what they find."""
    try:
        return route_enclosure(measured, claims, cases, allowance)
    except (Unsupported, ValueError, TypeError, ArithmeticError, NotImplementedError):
        return None


def _premises(relation) -> list:
    """The conditions under which a relation claims something: the premise of ``Holds(Implies(a, b))``, the
    rows' conditions of a case table (a point where each holds is sampled too)."""
    if isinstance(relation, Cases):
        return [c for c, _ in relation.rows]
    if isinstance(relation, Holds) and isinstance(relation.condition, sp.Implies):
        return [relation.condition.args[0]]
    return []


@functools.lru_cache(maxsize=256)
def _coefficients(p, x) -> tuple:
    """The coefficients of the polynomial *p* in *x* (highest power first), expressions in the parameters."""
    try:
        return tuple(sp.Poly(sp.expand(p), x).all_coeffs())
    except sp.PolynomialError as exc:
        raise ValueError(f"a root count of {p}, which is not a polynomial in {x}") from exc


def _mp(expr, point, dps):
    """*expr* at *point* as an mpmath number at *dps* digits (``-oo``, ``oo`` as mpmath's infinities)."""
    if expr in (sp.oo, -sp.oo):
        return mpmath.inf if expr == sp.oo else -mpmath.inf
    return mpmath.mpf(sp.Float(_numeric(sp.sympify(expr), point, dps), dps + 5)._mpf_)


def _counted(closed, point, dps):
    """``(value, pairs, radius)``: the difference *closed* (with root counts ``RealRoots`` in it) at *point*,
    each count taken numerically by :func:`~symfloat.engine.root_count.count_real_roots` at *dps* digits from
    the polynomial's coefficients evaluated there; *pairs* ``(numeric count, Sturm count)`` for each count,
    *radius* the largest inclusion radius of a counted root.  ``value`` is None when a count is undecided."""
    counts, pairs, widest = {}, [], 0.0
    for f in sorted(closed.atoms(RealRoots), key=sp.default_sort_key):
        p, x, lo, hi = f.args
        with mpmath.workdps(dps):
            coeffs = [_mp(c, point, dps) for c in _coefficients(p, x)]
            n, radius = count_real_roots(coeffs, _mp(lo, point, dps), _mp(hi, point, dps))
        if n is None:
            return None, [], float(radius)
        counts[f] = sp.Integer(n)
        exact = f.xreplace(point)               # RealRoots evaluates itself by Sturm sequences at a rational point
        if exact.is_Integer:
            pairs.append((n, int(exact)))
        widest = max(widest, float(radius))
    return _numeric(closed.xreplace(counts), point, dps), pairs, widest


def _measured(expr, point, dps):
    """*expr* at *point* to *dps* digits, its root counts counted from their roots' inclusion discs
    (:func:`_counted`)."""
    if not expr.has(RealRoots):
        return _numeric(expr, point, dps)
    value, _, radius = _counted(expr, point, dps)
    if value is None:
        raise UncountedRoots(f"a root count the inclusion discs (radius {radius:.1e}) do not decide")
    return value


class UncountedRoots(ArithmeticError):
    """A root count at one point that the inclusion discs do not decide: that point is not read."""


def route_readings(d):
    """``(printed, target, reading)`` for every reading the definition route measures in derivation *d*: the
    print (target its name) and the correction of an erratum (``name#corrected``) of each formula that no
    declared witness targets and whose text is not lost."""
    targeted = {t for w in d.witnesses for t in w.targets}
    for p in d.printed:
        if p.name in targeted or p.lost:
            continue
        if p.reading is not None:
            yield p, p.name, p.reading
        if p.erratum is not None and p.erratum.corrected_reading is not None:
            yield p, p.name + "#corrected", p.erratum.corrected_reading


class NothingToMeasure(ValueError):
    """Why the definition route measures nothing for a reading, in words; *measurable* false where nothing
    numeric is left (the members one expression once the definitions are in)."""

    def __init__(self, why: str, measurable: bool = True):
        super().__init__(why)
        self.measurable = measurable


@dataclass
class DefinitionRoute:
    """The definition-route witness of one derivation (built by the checker, not declared)."""

    steps: list
    domain: Domain
    derivation_id: str

    name = "definition route"

    def __post_init__(self):
        self._defs = definitions(self.steps)
        self._memo: dict = {}

    def outcome(self, target: str, reading, allowance=None) -> Outcome:
        """Compare the members of *reading* with its first member, measured from the definitions.
        Where the chain offers nothing to compare, or cannot be evaluated, the outcome has no
        records and a note saying why.  *allowance*: a printed number's rounding (half a unit in its last digit),
        which the certified record carries (the checker gives the other records theirs)."""
        out = Outcome(self.name)
        try:
            measured, claims, cases = self.members_at(target, reading)
        except NothingToMeasure as why:
            out.note, out.measurable = f"definition route: {why}", why.measurable
            return out
        certified = _certified(measured, claims, cases, allowance)
        if certified is not None and record_decision(certified) != "undecided":
            out.records.append(certified)       # the ball decides: a method would add nothing to the verdict
            out.judged()
            out.note = "" if out.agrees else "definition route: the definitions give another value"
            return out
        if certified is not None:
            out.records.append(certified)
        uncounted = 0
        for method in ROUTE_METHODS:
            t0 = time.perf_counter()
            worst_abs = worst_rel = 0.0
            read = 0
            try:
                for point in cases:
                    try:
                        values = [_measured(c, point, method.dps) for c in measured]
                    except UncountedRoots:
                        uncounted += method is ROUTE_METHODS[-1]
                        continue
                    read += 1
                    for claimed in claims:
                        for e, v, c in zip(measured, values, claimed):
                            ab, rel = _difference(e, v, c, point, method)
                            worst_abs, worst_rel = max(worst_abs, ab), max(worst_rel, rel)
            except (ValueError, TypeError, ArithmeticError, ZeroDivisionError, NotImplementedError) as exc:
                out.records = []
                out.note = f"definition route: not evaluated ({exc})"
                return out
            if not read:
                out.records = []
                out.note = ("definition route: not evaluated (at every point a root count the inclusion discs do "
                            "not decide)")
                return out
            record = {"method": f"definitions, {method.dps} digits", "abs_error": worst_abs, "rel_error": worst_rel,
                      "seconds": time.perf_counter() - t0, "cases": read, "rel_tolerance": method.tolerance}
            out.records.append(record)
        out.judged()
        if out.undecided:
            notes = [f"undecided, {undecided_reason(out.records[0])}"]
        else:
            notes = ["the definitions give another value"] if not out.agrees else []
        if uncounted:
            notes.append(f"at {uncounted} of {len(cases)} points a root count is not decided by its inclusion discs: "
                         "not read there")
        if notes:
            out.note = "definition route: " + "; ".join(notes)
        return out

    def members_at(self, target: str, reading):
        """``(measured, claims, points)``: the components of *reading*'s first member with the derivation's
        definitions inserted (what is measured), those of each other member (the claims), and the seeded sample
        points; :class:`NothingToMeasure` says why there is nothing to measure."""
        try:
            ms = [_carried_out(_expanded(m, self._defs, self._memo)) for m in members(reading)]
        except (ValueError, NotImplementedError) as exc:     # SymPy cannot carry out a limit, say
            raise NothingToMeasure(f"not evaluated ({exc})") from exc
        first = ms[0]
        rest = [m for m in ms[1:] if m != first]
        if not rest:
            raise NothingToMeasure("with the derivation's definitions inserted the members are one SymPy "
                                   "expression, so nothing is left for a number to check", measurable=False)
        symbols = set().union(*(sp.sympify(c).free_symbols for m in ms for c in _components(m)))
        cases = self._cases(symbols, target)
        if cases is None:
            raise NothingToMeasure("no sample point satisfies the derivation's constraints")
        measured = [sp.sympify(c) for c in _components(first)]
        claims = [[sp.sympify(c) for c in _components(m)] for m in rest]
        if any(len(claimed) != len(measured) for claimed in claims):
            raise NothingToMeasure("not evaluated (members of different shapes)")
        return measured, claims, cases

    def _cases(self, symbols, target):
        if not symbols:
            return [{}]
        draw = self.domain.sampler(f"{self.derivation_id}/{target} definition route")
        cases = []
        for _ in range(MAX_DRAWS):
            point = draw(symbols)
            if self.domain.admits(point):
                cases.append(point)
                if len(cases) == SAMPLES:
                    return cases
        return cases or None

    def relation_outcome(self, target: str, relation, results: dict, check=None) -> Outcome:
        """Cross-check the relation *relation* (see the module docstring): *results* are the derivation's
        derived values, *check* the relation check's result (its counterexample is measured first)."""
        out = Outcome(self.name)
        parts = statement(relation)
        atoms = sorted(set().union(*(e.atoms(sp.core.relational.Relational) for _, e in parts)),
                       key=sp.default_sort_key)
        try:                            # a root count is counted, not measured from definitions
            counted = {a: inserted(a.lhs - a.rhs, results) for a in atoms if a.has(RealRoots)}
            sides = {a: (_carried_out(_expanded(a.lhs - a.rhs, self._defs, self._memo)),
                         inserted(a.lhs - a.rhs, results)) for a in atoms if a not in counted}
        except (ValueError, NotImplementedError) as exc:
            out.note = f"definition route: not evaluated ({exc})"
            return out
        measured = {a: rc for a, rc in sides.items() if rc[0] != rc[1]}
        if not measured and not counted:
            out.note = ("definition route: with the derivation's definitions inserted the relation compares the "
                        "closed forms the relation check decides, so nothing is left for a number to check")
            out.measurable = False
            return out
        where = [inserted(sp.sympify(w), results) for w in tuple(self.domain.constraints) + relation.where]
        symbols = set().union(*(e.free_symbols for rc in sides.values() for e in rc),
                              *(e.free_symbols for e in counted.values()))
        symbols |= {q for w in where if w.free_symbols & symbols for q in w.free_symbols}
        premises = [inserted(c, results) for c in _premises(relation)] if counted else []
        counterexample = self._counterexample(check, symbols)
        try:
            points = self._relation_points(target, relation, symbols, where, counterexample, premises)
        except ValueError as exc:
            out.note = f"definition route: not evaluated ({exc})"
            return out
        if not points:
            out.note = "definition route: no sample point satisfies the relation's and the derivation's conditions"
            return out
        failed, undecided, uncounted, differs = [], 0, {}, False
        unread_counterexample = False
        for method in ROUTE_METHODS:
            t0 = time.perf_counter()
            worst_abs = worst_rel = 0.0
            count = {"abs": 0, "rel": 0.0, "radius": 0.0, "points": 0, "seconds": 0.0}
            try:
                for point in points:
                    signs = {}
                    for a, (route, closed) in measured.items():
                        v = _numeric(route, point, method.dps)
                        ab, rel = _difference(route, v, closed, point, method)
                        worst_abs, worst_rel = max(worst_abs, ab), max(worst_rel, rel)
                        size = abs(_numeric(_magnitude(route), point, 10, _RoughQuadPrinter))
                        if abs(v) > 10 * method.tolerance * size:
                            signs[a] = sp.true if a.func(v, 0) else sp.false
                    t1, decided = time.perf_counter(), True
                    for a, closed in counted.items():
                        v, pairs, radius = _counted(closed, point, method.dps)
                        if v is None:
                            decided = False
                            continue
                        signs[a] = sp.true if a.func(v, 0) else sp.false
                        for got, exact in pairs:
                            count["abs"] = max(count["abs"], abs(got - exact))
                            count["rel"] = max(count["rel"], abs(got - exact) / max(1, exact))
                        count["radius"] = max(count["radius"], radius)
                    count["points"] += decided
                    uncounted[method.dps] = uncounted.get(method.dps, 0) + (not decided)
                    count["seconds"] += time.perf_counter() - t1
                    if method is ROUTE_METHODS[-1]:         # the statement, at the finer values
                        verdict = self._statement_at(parts, sides, counted, signs, point)
                        if verdict is None:
                            undecided += 1
                            unread_counterexample |= point is counterexample
                        elif verdict:
                            failed.append((point, verdict))
            except (ValueError, TypeError, ArithmeticError, ZeroDivisionError, NotImplementedError) as exc:
                out.records = []
                out.note = f"definition route: not evaluated ({exc})"
                return out
            if measured:
                out.records.append({"method": f"definitions, {method.dps} digits", "abs_error": worst_abs,
                                    "rel_error": worst_rel, "seconds": time.perf_counter() - t0 - count["seconds"],
                                    "cases": len(points), "rel_tolerance": method.tolerance})
                if not record_agrees(out.records[-1]):
                    out.agrees = False
            if counted and count["points"]:
                out.records.append({"method": f"root count, polyroots and inclusion discs, {method.dps} digits",
                                    "abs_error": float(count["abs"]), "rel_error": float(count["rel"]),
                                    "seconds": count["seconds"], "cases": count["points"],
                                    "radius": float(count["radius"]), "abs_tolerance": 0.0})
                if not record_agrees(out.records[-1]):
                    out.agrees, differs = False, True
        notes = []
        if not out.agrees and not differs:
            notes.append("the definitions give another value of a side")
        if differs:
            notes.append("a numeric root count differs from the Sturm count")
        if failed:
            out.agrees = False
            point, bad = failed[0]
            at = ", ".join(f"{k}={v}" for k, v in sorted(point.items(), key=lambda kv: kv[0].name))
            notes.append(f"with the definitions' values the relation fails at {at} ({', '.join(bad)})")
        for dps, n in uncounted.items():
            if n:
                notes.append(f"at {dps} digits the roots at {n} of {len(points)} points are not parted from each "
                             "other or from an end by their inclusion discs: not counted there")
        if undecided:
            notes.append(f"at {undecided} of {len(points)} points a side is within its error of zero: the statement "
                         "is not read there")
        refuted = check is not None and check.status == "refuted"
        # A neutral case: the statement is not read where the relation check refutes it.  Only then is the route
        # left blank; a value or a count that disagrees, or a failure at another point, stands.
        if (unread_counterexample or (refuted and undecided == len(points))) and out.agrees and not failed:
            out.records = []
            notes = ["where the relation check refutes the statement a side is within its error of zero (a "
                     "neutral case), so the statement is not read there and nothing is recorded"]
        out.note = "definition route: " + "; ".join(notes) if notes else ""
        return out

    def _relation_points(self, target, relation, symbols, where, counterexample, premises=()):
        """The relation check's *counterexample* (when it is a rational point of these symbols), then seeded
        points of the domain that satisfy the derivation's constraints and the relation's conditions, and for
        each of the *premises* the first such point where it holds: among the seeded draws (continued for up to
        :data:`PREMISE_DRAWS` more), else among the domain's boundary points the relation check starts from."""
        points = [p for p in (counterexample,) if p is not None]
        intervals = relation_intervals(relation, symbols, self.domain, target)
        draws = random_points(sorted(symbols, key=lambda q: q.name), intervals,
                              f"{self.derivation_id}/{target} definition route")
        sampled, wanted = [], list(premises)
        for _ in range(MAX_DRAWS):
            point = next(draws)
            if self.domain.admits(point) and all(truth(w, point) is True for w in where):
                met = [c for c in wanted if truth(c, point) is True]
                if len(sampled) < SAMPLES or met:
                    sampled.append(point)
                wanted = [c for c in wanted if c not in met]
                if len(sampled) >= SAMPLES and not wanted:
                    break
        # a narrow case: more draws, then the domain's boundary points (a case next to its edge), its condition first
        more = itertools.chain(itertools.islice(draws, PREMISE_DRAWS),
                               boundary_points(sorted(symbols, key=lambda q: q.name), intervals)) if wanted else ()
        for point in more:
            met = [c for c in wanted if truth(c, point) is True]
            if met and self.domain.admits(point) and all(truth(w, point) is True for w in where):
                sampled.append(point)
                wanted = [c for c in wanted if c not in met]
                if not wanted:
                    break
        return points + sampled

    @staticmethod
    def _counterexample(check, symbols):
        """The relation check's counterexample as a point of *symbols*, or None (none found, a point not
        rational, or of other symbols: the samples only)."""
        if check is None or not check.counterexample:
            return None
        try:
            return {q: sp.Rational(check.counterexample["point"][q.name]) for q in symbols}
        except (KeyError, TypeError, ValueError):
            return None

    @staticmethod
    def _statement_at(parts, sides, counted, signs, point):
        """The names of the statement's parts that fail at *point* (an empty list: it holds), the inequalities
        measured by the definitions or counted taking their *signs*, the others their closed forms; None when a
        sign is not known there."""
        known = {}
        for a in counted:
            if a not in signs:
                return None
            known[a] = signs[a]
        for a, (route, closed) in sides.items():
            if route != closed:
                if a not in signs:
                    return None
                known[a] = signs[a]
            else:
                t = truth(a.func(closed, 0), point)
                if t is None:
                    return None
                known[a] = sp.true if t else sp.false
        bad = []
        for name, e in parts:
            t = truth(e.xreplace(known), {})
            if t is None:
                return None
            if not t:
                bad.append(name)
        return bad
