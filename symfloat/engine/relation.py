"""Checking a relation (:mod:`symfloat.model.relation`): a proof where it can, else sampling.

The statement checked at a point is: for :class:`Holds` its condition; for :class:`Iff` that both
sides have the same truth; for :class:`Cases` that each row's claim holds where its condition does,
that some condition holds (``exhaustive``) and that no two do (``exclusive``).

* **Proof** (evidence ``symbolic``): when a single variable is left and every relation in the
  statement compares rational functions of it with rational coefficients, each relation keeps its
  truth between the real roots of its numerators and denominators.  Those roots are isolated
  exactly (irreducible factors over Q, rational isolating intervals); the statement is evaluated
  exactly at a rational point of every cell between them, and at every root inside the domain, where
  a relation whose factor vanishes compares 0 and the others keep the sign of the neighbouring cell.
* **Proof by signs** (evidence ``symbolic``), in any number of variables: the statement becomes
  true once the derived values are inserted (SymPy's assumptions decide ``pi a b c/8 > 0``), or it
  is one relation whose difference, factored, is positive once every symbol on a positive interval
  is a positive symbol.
* **Sampling** (evidence ``sampled``): the boundary of the domain first -- a closed end exactly, an
  open end approached to 1/1000 of the interval, in every combination with the other symbols' ends
  and midpoints -- then seeded random rational points; points outside *where* or the derivation's
  constraints, or where the statement cannot be evaluated, are skipped.  Through the boundary points
  and a few random ones the statement is then followed along each symbol, on both sides of every
  root of its relations (exact roots where they are radicals, else 30-digit ones).  Each relation
  is decided by its sign at 60 digits where that is clearly not zero, else exactly.

A point where the statement is false refutes (the counterexample names the point and which part
failed).  No valid point, a relation SymPy cannot decide at a point, or a row of a case table whose
condition held at no point checked leaves it ``undecided``: shown and counted, never a pass.
"""
from __future__ import annotations

import functools
import itertools
import time
from fractions import Fraction

import mpmath
import sympy as sp

from ..model.relation import Cases, Holds, Iff, RealRoots, Relation
from .identity import Domain, IdentityResult
from .roots import grid_roots
from .sign import decided

__all__ = ["check_relation", "statement", "truth", "inserted", "relation_intervals", "random_points", "boundary_points",
           "SAMPLES"]

SAMPLES = 40           # random points after the boundary points
LINES = 16             # at most so many lines through boundary and random points
SLICES = 3             # random points through which the statement is followed along each symbol
NEAR = sp.Rational(1, 1000)


def statement(r: Relation) -> list[tuple[str, sp.Basic]]:
    """The parts to check at every point, each with its name for a counterexample."""
    if isinstance(r, Holds):
        return [("condition", r.condition)]
    if isinstance(r, Iff):
        return [("equivalence", sp.Equivalent(r.a, r.b, evaluate=False))]
    if not isinstance(r, Cases):
        raise TypeError(f"not a relation: {r!r}")
    out = [(f"row {i + 1}", sp.Implies(c, claim, evaluate=False)) for i, (c, claim) in enumerate(r.rows)]
    conds = [c for c, _ in r.rows]
    if r.exhaustive:
        out.append(("some case holds", sp.Or(*conds, evaluate=False)))
    if r.exclusive and len(conds) > 1:
        out.append(("at most one case holds",
                    sp.And(*(sp.Not(sp.And(a, b, evaluate=False), evaluate=False)
                             for a, b in itertools.combinations(conds, 2)), evaluate=False)))
    return out


def truth(expr, point):
    """True/False of a boolean statement at *point*, or None when SymPy cannot decide it.  Each
    relation is decided by its sign at 60 digits (:func:`~symfloat.engine.sign.decided`) where its
    difference is clearly not zero, else exactly."""
    known = {}
    for rel in expr.atoms(sp.core.relational.Relational):
        v = decided(rel, point)
        if v is not None:
            known[rel] = sp.true if v else sp.false
    if known:
        expr = expr.xreplace(known)
    try:
        v = expr.xreplace(point).doit()
        v = sp.simplify_logic(v) if isinstance(v, sp.logic.boolalg.Boolean) and v not in (sp.true, sp.false) \
            else v
    except (ArithmeticError, TypeError, ValueError, ZeroDivisionError):
        return None
    if v == sp.true:
        return True
    if v == sp.false:
        return False
    if not isinstance(v, sp.logic.boolalg.Boolean) or v.free_symbols:
        return None
    try:          # a difference that is zero but not written so: ((3 + sqrt 3)/6)^2 - (3 + sqrt 3)/6 + 1/6
        w = v.xreplace({rel: type(rel)(sp.radsimp(sp.expand(rel.lhs - rel.rhs)), 0)
                        for rel in v.atoms(sp.core.relational.Relational)})
    except (ArithmeticError, TypeError, ValueError):
        return None
    return True if w == sp.true else False if w == sp.false else None


def _valid(point, where) -> bool | None:
    for w in where:
        t = truth(w, point)
        if t is not True:
            return t
    return True


def _finite_ok(expr, point) -> bool:
    """The relations of the statement are defined at *point* (no division by zero)."""
    for rel in expr.atoms(sp.core.relational.Relational):
        if rel.has(RealRoots) or decided(rel, point) is not None:
            continue                    # a root count is always a number
        for side in (rel.lhs, rel.rhs):
            v = sp.sympify(side).xreplace(point)
            if v.has(sp.zoo, sp.nan) or (v.is_number and not v.is_finite):
                return False
    return True


# ---- sampling ---------------------------------------------------------------------------------------------
@functools.lru_cache(maxsize=4096)
def _simplest(x):
    """``sp.nsimplify(x)``, once per number: the same ends of a domain are met at every boundary point, random
    point and slice, and identifying an irrational end (PSLQ) costs tens of milliseconds."""
    return sp.nsimplify(x)


@functools.lru_cache(maxsize=4096)
def _ends(iv: sp.Interval) -> tuple:
    lo, hi = iv.start, iv.end
    if not (lo.is_finite and hi.is_finite):
        lo = lo if lo.is_finite else (hi - 1000 if hi.is_finite else sp.Integer(-1000))
        hi = hi if hi.is_finite else lo + 2000
        iv = sp.Interval(lo, hi, iv.left_open or not iv.start.is_finite, iv.right_open or not iv.end.is_finite)
    w = hi - lo
    left = lo if not iv.left_open else _rational_near(lo + NEAR * w, lo)
    right = hi if not iv.right_open else _rational_near(hi - NEAR * w, hi)
    return left, _rational_near((lo + hi) / 2, (lo + 3 * hi) / 4), right


@functools.lru_cache(maxsize=4096)
def _rational_near(x, towards):
    """*x* when rational, else a rational strictly between *x* and *towards* (20 digits)."""
    x = _simplest(x)
    if x.is_Rational:
        return x
    mid = (x + towards) / 2
    q = sp.Rational(str(sp.N(mid, 20)))
    lo, hi = (x, towards) if sp.N(x - towards, 30) < 0 else (towards, x)
    if not (sp.N(q - lo, 30) > 0 and sp.N(hi - q, 30) > 0):
        raise ValueError(f"no rational found near {x}")
    return q


def _boundary(symbols, intervals, limit=81):
    """Every combination of the symbols' ends and midpoints (at most *limit*, in a stable order)."""
    grids = [_ends(intervals[s]) for s in symbols]
    for i, combo in enumerate(itertools.product(*grids)):
        if i >= limit:
            return
        yield dict(zip(symbols, combo))


def boundary_points(symbols, intervals) -> list:
    """The domain's boundary points the sampling starts from: every combination of the symbols' ends (an open
    end 1/1000 of the interval inside) and midpoints, at most 81."""
    return list(_boundary(symbols, intervals))


def random_points(symbols, intervals, seed):
    """Seeded rational points inside the *intervals* (an open end kept 1/1000 of the interval away)."""
    bounds = {}
    for s in symbols:
        lo, mid, hi = _ends(intervals[s])
        bounds[s] = (_rational_near(lo, mid), _rational_near(hi, mid))
    draw = Domain(bounds).sampler(seed)
    while True:
        yield draw(symbols)


def _sampled(parts, symbols, intervals, where, seed, samples, slices=SLICES):
    """Boundary points, then random points; through every boundary point and the first *slices* valid
    random points, the statement along each symbol (the others fixed) around the roots of its relations."""
    good, undecided, sliced, lines = 0, 0, 0, {}
    points = itertools.chain(_boundary(symbols, intervals),
                             itertools.islice(random_points(symbols, intervals, seed), samples * 10))
    randoms, edge = 0, len(list(_boundary(symbols, intervals)))
    for k, point in enumerate(points):
        if k >= edge:
            randoms += 1
            if randoms > samples and good:
                break
        if _valid(point, where) is not True:
            continue
        if not all(_finite_ok(e, point) for _, e in parts):
            continue
        values = [(name, truth(e, point)) for name, e in parts]
        bad = [name for name, t in values if t is False]
        if bad:
            return "refuted", good + 1, point, bad
        if any(t is None for _, t in values):
            undecided += 1
            continue
        good += 1
        if (k < edge and len(symbols) > 1) or (k >= edge and sliced < slices):
            sliced += k >= edge
            for x in symbols:
                fixed = {y: v for y, v in point.items() if y != x}
                key = (x, tuple(sorted(fixed.items(), key=str)))
                if key not in lines and len(lines) < LINES:
                    lines[key] = fixed
    for (x, _), fixed in lines.items():           # the points first, then the lines through them
        status, at, bad, n = _univariate(parts, x, intervals[x], where, fixed, exact=len(symbols) == 1)
        if status == "refuted":
            return "refuted", good + n, at, bad
        good += n
    return ("sampled" if good and not undecided else "undecided"), good, None, undecided


# ---- proof for one variable -------------------------------------------------------------------------------
def _rational_factors(parts, x):
    """The irreducible factors over Q of the numerators and denominators of every relation, or None."""
    factors = []
    for _, e in parts:
        for rel in e.atoms(sp.core.relational.Relational):
            d = sp.together(sp.sympify(rel.lhs - rel.rhs))
            if d.free_symbols - {x}:
                return None
            for piece in sp.fraction(d):
                try:
                    poly = sp.Poly(piece, x, domain="QQ")
                except (sp.PolynomialError, sp.polys.polyerrors.CoercionFailed, ValueError):
                    return None
                for f, _ in poly.factor_list()[1]:
                    f = f.monic()
                    if f.degree() > 0 and f not in factors:
                        factors.append(f)
    return factors


def _roots(factors, iv):
    """Real roots inside *iv* as (lo, hi, factor): disjoint rational isolating intervals, sorted."""
    if not factors:
        return []
    product = sp.prod(factors[1:], factors[0]) if len(factors) > 1 else factors[0]
    eps = None
    while True:
        ivs = [(sp.Rational(a), sp.Rational(b)) for (a, b), _ in product.intervals(eps=eps)]
        ivs.sort()
        separated = all(b1 < a2 for (_, b1), (a2, _) in zip(ivs, ivs[1:]))
        inside = all(not (a < iv.start < b or a < iv.end < b) for a, b in ivs)
        if separated and inside:
            break
        eps = min(b - a for a, b in ivs if b > a) / 4 if any(b > a for a, b in ivs) else sp.Rational(1, 10 ** 6)
    out = []
    for a, b in ivs:
        if a == b:
            owner = next(f for f in factors if f.eval(a) == 0)
        else:
            owner = next(f for f in factors if f.count_roots(a, b) == 1)
        if (iv.start < a and b < iv.end) if a == b else (iv.start <= a and b <= iv.end):
            out.append((a, b, owner))          # strictly inside: an end is checked as an end
    return out


def _at_root(expr, x, root, cell_point, factors_of):
    """Truth of *expr* at a root: relations whose difference has the root's factor compare 0 (or are
    undefined there: None), the others keep their truth at the neighbouring cell's point."""
    a, b, owner = root
    repl = {}
    for rel in expr.atoms(sp.core.relational.Relational):
        num, den = factors_of[rel]
        if owner in den:
            return None
        if owner in num:
            repl[rel] = type(rel)(sp.Integer(0), sp.Integer(0))
        else:
            repl[rel] = sp.sympify(rel.xreplace({x: cell_point}))
    v = expr.xreplace(repl)
    return truth(v, {})


def _factor_sets(parts, x):
    out = {}
    for _, e in parts:
        for rel in e.atoms(sp.core.relational.Relational):
            num, den = sp.fraction(sp.together(sp.sympify(rel.lhs - rel.rhs)))
            sets = []
            for piece in (num, den):
                poly = sp.Poly(piece, x, domain="QQ")
                sets.append({f.monic() for f, _ in poly.factor_list()[1] if f.degree() > 0})
            out[rel] = tuple(sets)
    return out


def _proved(parts, x, iv, where):
    """``("proved" | "refuted", point, failed parts, cells)``, or None when the proof does not apply."""
    if where:
        parts = [(name, sp.Implies(sp.And(*where), e, evaluate=False)) for name, e in parts]
    if any(sp.sympify(e).has(sp.Function) for _, e in parts):
        return None
    if not (iv.start.is_Rational or iv.start == -sp.oo) or not (iv.end.is_Rational or iv.end == sp.oo):
        return None
    factors = _rational_factors(parts, x)
    if factors is None:
        return None
    roots = _roots(factors, iv)
    factors_of = _factor_sets(parts, x)
    lo = iv.start if iv.start.is_finite else (min([r[0] for r in roots], default=sp.Integer(0)) - 1)
    hi = iv.end if iv.end.is_finite else (max([r[1] for r in roots], default=sp.Integer(0)) + 1)
    cuts = [lo] + [p for a, b, _ in roots for p in (a, b)] + [hi]
    cells = [(cuts[2 * i] + cuts[2 * i + 1]) / 2 for i in range(len(roots) + 1)]
    if where and not any(_valid({x: c}, where) for c in cells):
        return None                 # no cell meets the conditions: nothing is shown, leave it to sampling
    checks = [({x: c}, parts, None) for c in cells]
    for i, root in enumerate(roots):
        if root[0] == root[1] and root[0] in (iv.start, iv.end):
            continue
        checks.append((root, parts, cells[i]))
    for end, closed in ((iv.start, not iv.left_open), (iv.end, not iv.right_open)):
        if closed and end.is_finite:
            checks.append(({x: end}, parts, None))
    for at, ps, neighbour in checks:
        if neighbour is None:
            if not all(_finite_ok(e, at) for _, e in ps):
                continue
            values = [(name, truth(e, at)) for name, e in ps]
            shown = at
        else:
            values = [(name, _at_root(e, x, at, neighbour, factors_of)) for name, e in ps]
            if any(t is None for _, t in values) and any(at[2] in factors_of[rel][1]
                                                        for _, e in ps for rel in e.atoms(sp.core.relational.Relational)):
                continue            # a pole: outside where the statement is defined
            shown = {x: sp.CRootOf(at[2].as_expr(), 0) if at[2].degree() == 1 else
                     f"the root of {sp.sstr(at[2].as_expr())} in [{at[0]}, {at[1]}]"}
        bad = [name for name, t in values if t is False]
        if bad:
            return "refuted", shown, bad, len(cells)
        if any(t is None for _, t in values):
            return None
    return "proved", None, [], len(cells)


# ---- the boundary of the relation, numerically -------------------------------------------------------------
def _numeric_roots(parts, x, lo, hi) -> list:
    """Real roots in (lo, hi) of the relations' numerators and denominators in *x* (other symbols fixed),
    at 30 digits: a polynomial's by ``nroots``, any other's by the sign changes on a grid of 400 cells."""
    found = []
    flo, fhi = mpmath.mpf(sp.N(lo, 30)), mpmath.mpf(sp.N(hi, 30))
    for _, e in parts:
        for rel in e.atoms(sp.core.relational.Relational):
            for piece in sp.fraction(sp.together(sp.sympify(rel.lhs - rel.rhs))):
                if x not in piece.free_symbols or piece.free_symbols - {x} or piece.has(RealRoots):
                    continue            # a root count jumps where its roots merge, not where it vanishes
                with mpmath.workdps(30):
                    try:
                        poly = sp.Poly(piece, x) if piece.is_polynomial(x) else None
                        if poly is not None and poly.domain.is_QQ or poly is not None and poly.domain.is_ZZ:
                            found += [mpmath.mpf(sp.N((u + v) / 2, 30)) for (u, v), _ in
                                      poly.intervals(eps=sp.Rational(1, 10 ** 25))]
                        elif poly is not None:
                            found += [mpmath.mpf(sp.re(r)) for r in poly.nroots(n=30, maxsteps=200)
                                      if abs(sp.im(r)) < 1e-20]
                        else:
                            f = sp.lambdify(x, piece, "mpmath")
                            grid = [flo + (fhi - flo) * k / 400 for k in range(401)]
                            found += grid_roots(lambda dps: f, grid, 15)
                    except (ArithmeticError, TypeError, ValueError, ZeroDivisionError, sp.PolynomialError,
                            mpmath.libmp.NoConvergence):
                        continue
    return sorted(r for r in found if flo < r < fhi)


def _exact_roots(parts, x, iv) -> list:
    """The real roots in the domain, in radicals, of the relations' polynomial numerators of degree at
    most 4 in *x* (a relation may fail exactly at its boundary)."""
    out = []
    for _, e in parts:
        for rel in e.atoms(sp.core.relational.Relational):
            piece = sp.fraction(sp.together(sp.sympify(rel.lhs - rel.rhs)))[0]
            if piece.free_symbols != {x} or piece.has(RealRoots) or not piece.is_polynomial(x):
                continue
            poly = sp.Poly(piece, x)
            if poly.degree() > 4:
                continue
            out += [r for r in sp.roots(poly) if r.is_real and iv.contains(r) == sp.true]
    return sorted(set(out), key=sp.default_sort_key)


def _around_roots(parts, x, iv) -> list:
    """Rational points on both sides of every numeric root in the domain, and between them."""
    lo, _, hi = _ends(iv)
    roots = _numeric_roots(parts, x, lo, hi)
    points = []
    for r in roots:
        d = mpmath.mpf("1e-12") * max(1, abs(r))
        points += [sp.Rational(mpmath.nstr(r - d, 25)), sp.Rational(mpmath.nstr(r + d, 25))]
    cuts = [_simplest(lo)] + [sp.Rational(mpmath.nstr(r, 25)) for r in roots] + [_simplest(hi)]
    points += [(a + b) / 2 for a, b in zip(cuts, cuts[1:])]
    return sorted({q for q in points if iv.contains(q) == sp.true})


def _univariate(parts, x, iv, where, fixed, exact=True):
    """The statement along *x* with the other symbols *fixed*: ``(status, point, failed parts, checks)``,
    status ``proved``/``refuted`` by sign cells, else ``sampled`` (or ``refuted``) at the points around
    its numeric roots."""
    parts = [(name, e.xreplace(fixed)) for name, e in parts]
    where = [w.xreplace(fixed) for w in where]
    proof = _proved(parts, x, iv, where)
    if proof is not None:
        status, point, bad, cells = proof
        return status, ({**fixed, **point} if point else None), bad, cells
    checked = 0
    for q in (_exact_roots(parts, x, iv) if exact else []) + _around_roots(parts, x, iv):
        at = {x: q}
        if _valid(at, where) is not True or not all(_finite_ok(e, at) for _, e in parts):
            continue
        bad = [name for name, e in parts if truth(e, at) is False]
        if bad:
            return "refuted", {**fixed, **at}, bad, checked + 1
        checked += 1
    return "sampled", None, [], checked


# ---- proof by the sign of factors, any number of variables ---------------------------------------------------
def _signed(parts, intervals) -> bool:
    """The statement is one relation ``f > g`` (or ``>=``, ``<``, ``<=``) whose difference, factored, is a
    product of factors SymPy's assumptions call positive once every symbol whose interval lies in (0, oo) is
    a positive symbol (``c D / 4`` for c, D > 0)."""
    if len(parts) != 1 or not isinstance(parts[0][1], sp.core.relational.Relational):
        return False
    rel = parts[0][1]
    if not isinstance(rel, (sp.StrictGreaterThan, sp.GreaterThan, sp.StrictLessThan, sp.LessThan)):
        return False
    if rel.has(RealRoots):
        return False
    diff = rel.lhs - rel.rhs if isinstance(rel, (sp.StrictGreaterThan, sp.GreaterThan)) else rel.rhs - rel.lhs
    positive = {q: sp.Dummy(q.name, positive=True) for q, iv in intervals.items()
                if iv.start.is_nonnegative and (iv.start.is_positive or iv.left_open)}
    try:
        return bool(sp.factor(sp.together(diff.xreplace(positive))).is_positive)
    except (sp.PolynomialError, TypeError, ValueError):
        return False


# ---- the check ---------------------------------------------------------------------------------------------
def inserted(expr, results):
    """*expr* with the derivation's derived values (*results*) inserted and its derivatives, integrals and
    limits carried out: the closed forms the relation check decides."""
    for _ in range(len(results) + 1):
        new = expr.xreplace(results)
        if new == expr:
            break
        expr = new
    expr = expr.replace(lambda e: isinstance(e, sp.Subs), lambda e: e.doit())
    return expr.doit() if expr.has(sp.Derivative, sp.Integral, sp.Limit) else expr


def relation_intervals(r: Relation, symbols, domain: Domain, seed_text: str) -> dict:
    """Symbol -> the interval it is sampled on: the relation's own, else the derivation's (open)."""
    named = r.intervals()
    out = {}
    for s in symbols:
        if s in named:
            out[s] = named[s]
        elif s in domain.intervals:
            lo, hi = domain.intervals[s]
            out[s] = sp.Interval.open(sp.Rational(Fraction(str(lo))), sp.Rational(Fraction(str(hi))))
        else:
            raise ValueError(f"{seed_text}: symbol {s} has no interval in the relation's or the derivation's domain")
    return out


def check_relation(r: Relation, results: dict, domain: Domain, seed_text: str, samples: int = SAMPLES) \
        -> IdentityResult:
    """Decide the relation *r* with the derivation's *results* inserted, on its domain (symbols it does
    not name take *domain*'s intervals; *domain*'s constraints and ``r.where`` restrict the points)."""
    t0 = time.perf_counter()
    if all(c in (sp.true, sp.false) for c in r.parts()):
        return IdentityResult("trivial", tried=["none: SymPy decided the relation when it was built"])
    parts = [(name, inserted(e, results)) for name, e in statement(r)]
    if all(e in (sp.true, sp.false) for _, e in parts):       # the derived values let SymPy decide it
        bad = [name for name, e in parts if e == sp.false]
        result = IdentityResult("refuted" if bad else "proved", strategy="" if bad else "assumptions",
                                tried=["the derived values inserted, SymPy's assumptions on the symbols decide it"])
        if bad:
            result.counterexample = {"point": {}, "lhs": "false (" + ", ".join(bad) + ")", "rhs": "true"}
        result.seconds = time.perf_counter() - t0
        return result
    symbols = set().union(*(e.free_symbols for _, e in parts))
    where = [w for w in (inserted(sp.sympify(w), results) for w in tuple(domain.constraints) + r.where)
             if w.free_symbols & symbols]          # a constraint on other symbols does not restrict these
    intervals = relation_intervals(r, set(symbols) | set().union(*(sp.sympify(w).free_symbols for w in where)),
                                   domain, seed_text)
    symbols = sorted(intervals, key=lambda s: s.name)
    result = IdentityResult("undecided")
    proof = None
    if len(symbols) == 1:
        proof = _proved(parts, symbols[0], intervals[symbols[0]], where)
    if proof is None and _signed(parts, intervals):
        result.status, result.strategy = "proved", "sign of factors"
        result.tried = ["sign of factors: the difference factors into terms of known sign on the domain"]
    elif proof is not None:
        status, point, bad, cells = proof
        result.tried = [f"sign cells: {cells} cells between the real roots of the relations' numerators and "
                        f"denominators, and the roots themselves"]
        result.status = status
        result.samples = cells
        if status == "refuted":
            result.counterexample = _counterexample(point, bad)
        result.strategy = "sign cells" if status == "proved" else ""
    else:
        status, good, point, extra = _sampled(parts, symbols, intervals, where, seed_text, samples,
                                              slices=1 if len(symbols) == 1 else SLICES)
        result.status, result.samples = status, good
        result.tried = [f"sampling: the domain's boundary points and {samples} seeded rational points (exact)"]
        if status == "refuted":
            result.counterexample = _counterexample(point, extra)
        elif status == "undecided":
            result.tried.append(f"{extra} points where SymPy could not decide the statement" if extra
                                else "no point satisfies the domain's conditions")
    if isinstance(r, Cases) and result.holds:
        _rows_occur(r, results, domain, seed_text, samples, result)
    result.seconds = time.perf_counter() - t0
    return result


def _rows_occur(r: Cases, results, domain, seed_text, samples, result):
    """A row whose condition holds at no point checked states nothing: the table is then undecided.
    Each row is looked for as a counterexample to its condition's negation."""
    for i, (cond, _) in enumerate(r.rows):
        probe = check_relation(Holds(sp.Not(cond), dict(r.domain), r.where), results, domain,
                               f"{seed_text}/row {i + 1}", samples)
        if probe.status != "refuted":
            result.status, result.strategy = "undecided", ""
            result.tried.append(f"row {i + 1}: its condition held at no point checked")


def _counterexample(point, bad) -> dict:
    return {"point": {str(k): str(v) for k, v in sorted(point.items(), key=lambda kv: kv[0].name)},
            "lhs": "false (" + ", ".join(bad) + ")", "rhs": "true"}
