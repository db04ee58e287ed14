"""Deciding one identity ``a = b``: sampling first, then symbolic proof.

Cheap evidence comes first.  Both sides are evaluated at seeded random
rational points inside the derivation's domain: exactly when the values are
rational (Schwartz–Zippel for rational identities), otherwise with 60-digit
arithmetic.  A single disagreeing point refutes the identity and is kept as
the counterexample.  When every sample agrees, the claim's proof certificate
(:mod:`symfloat.engine.proofs`) is replayed: exactly the recorded strategy,
with no time limit.  Only a claim without a certificate for its present form
is *searched*: the strategies are tried in turn under a shared time limit,
and the outcome (the strategy that proved it, or none) becomes its
certificate.  The clock can end a search; it never decides a replayed check.
"""
from __future__ import annotations

import functools
import hashlib
import random
import time
from dataclasses import dataclass, field
from fractions import Fraction

import mpmath
import sympy as sp

from flint import arb

from ..model.compiled import CompiledError, compile_expr
from ..model.relation import RealRoots
from .enclosure import Unsupported, exact, powers_bounded, real_function, working_precision
from .branches import branches
from .pythagoras import pythagoras
from .rational_zero import is_zero_rational_function
from .proofs import Certificate, ProofBook, claim_digest, slowdown
from .sign import decided
from .timelimit import TimeLimitExceeded, time_limit

__all__ = ["IdentityResult", "check_identity", "check_rounded", "Domain", "DIGITS", "STRATEGIES",
           "SEARCH_SECONDS"]

DIGITS = 60            # working precision of non-rational sampling
AGREEMENT = 10 ** -45  # relative tolerance of non-rational sampling
SAMPLES = 6
SEARCH_SECONDS = 10.0  # time limit shared by the strategies of one proof search (never of a replay)


@dataclass
class IdentityResult:
    """Outcome of one identity check.

    ``status`` is ``proved`` (a symbolic strategy reduced the difference to
    zero), ``sampled`` (every sample agreed, no proof), ``agrees`` (a printed
    number matches the computed value to its printed precision), ``refuted``
    (a sample disagreed: see ``counterexample``) or ``undecided``.

    ``certificate`` is the proof certificate the check used or found (see
    :class:`~symfloat.engine.proofs.Certificate`), and ``proof`` says how:
    ``replayed``, ``searched``, or ``replay failed`` (the certificate of this
    very claim no longer proves it: a failure of the derivation).
    """

    status: str
    strategy: str = ""
    samples: int = 0
    exact: bool = True
    counterexample: dict | None = None
    residual: str = ""
    tried: list = field(default_factory=list)
    seconds: float = 0.0
    certificate: dict | None = None
    proof: str = ""
    proof_seconds: float = 0.0

    @property
    def evidence(self) -> str | None:
        return {"proved": "symbolic", "sampled": "sampled", "agrees": "numeric"}.get(self.status)

    @property
    def holds(self) -> bool:
        return self.status in ("proved", "sampled", "agrees")

    def to_json(self) -> dict:
        return {k: v for k, v in self.__dict__.items()}

    @classmethod
    def from_json(cls, data: dict) -> "IdentityResult":
        return cls(**data)


def _nonnegative(e) -> bool:
    """Sums, products and quotients of square roots and positive constants:
    non-negative wherever they are real (lengths, areas and their ratios)."""
    if e.is_number:
        return bool(e.is_nonnegative)
    if e.is_Pow and e.exp in (sp.S.Half, -sp.S.Half):
        return True
    if e.is_Pow and e.exp.is_Integer:
        return _nonnegative(e.base) or e.exp.is_even
    if e.is_Add or e.is_Mul:
        return all(_nonnegative(t) for t in e.args)
    return bool(e.is_nonnegative)


def _squares(pair):
    """``a = b`` from ``a**2 = b**2`` when both sides are manifestly
    non-negative: removes square roots of different radicands."""
    a, b = pair
    if not (_nonnegative(a) and _nonnegative(b)):
        return a - b
    return sp.cancel(sp.together(sp.expand(a ** 2 - b ** 2)))


def _cancelled(e):
    """``cancel(together(e))``, which is 0 exactly when the numerator of ``together(e)`` is the zero polynomial
    in its generators: FLINT's polynomials ask that first (:mod:`~symfloat.engine.rational_zero`, a thousandth of
    SymPy's time), then SymPy's numerator expanded (no greatest common divisor with the denominator to compute),
    which is cancelled only where it is not 0."""
    if is_zero_rational_function(e):
        return sp.Integer(0)
    combined = sp.together(e)
    if sp.expand(sp.fraction(combined)[0]) == 0:
        return sp.Integer(0)
    return sp.cancel(combined)


def _strategy(name):
    return {
        "squares": _squares,
        "cancel": _cancelled,
        "expand": lambda e: sp.expand(sp.powsimp(sp.expand(e), force=True)),
        "radsimp": lambda e: sp.cancel(sp.radsimp(sp.together(e))),
        "pythagoras": pythagoras,
        "branches": branches,
        "simplify": sp.simplify,
    }[name]


STRATEGIES = ("cancel", "squares", "expand", "radsimp", "pythagoras", "branches", "simplify")


@dataclass(frozen=True)
class Domain:
    """Where samples are drawn: intervals per symbol and extra constraints."""

    intervals: dict
    constraints: tuple = ()

    def sampler(self, seed_text: str):
        seed = int.from_bytes(hashlib.sha256(seed_text.encode()).digest()[:8], "big")
        rng = random.Random(seed)
        bounds = {}         # symbol -> its interval's ends as fractions, read once per sampler

        def draw(symbols):
            point = {}
            for s in sorted(symbols, key=lambda s: s.name):
                if s not in self.intervals:
                    raise ValueError(f"symbol {s} has no sampling interval in the derivation's domain")
                if s not in bounds:
                    bounds[s] = tuple(Fraction(str(v)) for v in self.intervals[s])
                lo, hi = bounds[s]
                den = rng.randint(7, 97)
                t = Fraction(rng.randint(1, den - 1), den)
                point[s] = sp.Rational(lo + (hi - lo) * t)
            return point

        return draw

    def admits(self, point) -> bool:
        """Every constraint on the symbols of *point* holds there: by its sign at 60 digits where that is
        clearly decided (:func:`~symfloat.engine.sign.decided`), else exactly."""
        for c in self.constraints:
            c = sp.sympify(c)
            if not c.free_symbols <= point.keys():
                continue
            known = decided(c, point) if isinstance(c, sp.core.relational.Relational) else None
            if not (known if known is not None else c.xreplace(point)):
                return False
        return True


def _flatten(a, b):
    if isinstance(a, sp.MatrixBase) or isinstance(b, sp.MatrixBase):
        a, b = sp.Matrix(a), sp.Matrix(b)
        if a.shape != b.shape:
            raise ValueError(f"cannot compare shapes {a.shape} and {b.shape}")
        return list(zip(a, b))
    return [(a, b)]


@functools.lru_cache(maxsize=8192, typed=True)
def _evaluate(expr):
    """Carry out the integrals, limits, derivatives and root counts (Sturm sequences) a claim contains;
    once per expression (a chain's middle member is met by two links, and an integral SymPy cannot
    carry out would be tried again at every check of a claim that still holds it)."""
    expr = sp.sympify(expr)
    if expr.has(sp.Integral, sp.Limit, sp.Derivative, sp.Subs, RealRoots):
        expr = expr.doit()
    return expr


def _value(expr):
    """Exact rational value, or a 60-digit float, of a closed expression."""
    if expr.is_Rational:
        return expr, True
    v = sp.N(expr, DIGITS)
    if not v.is_number or v.has(sp.zoo, sp.nan, sp.oo, -sp.oo):        # -oo is not oo: both compare equal to all
        raise ArithmeticError("not a finite number")
    return v, False


def _compiled(expr, compile_in, outside):
    """``(symbols, function)``: *expr* compiled by *compile_in* in its free symbols (sorted by name), or ``None``
    where the compiler raises *outside* (a node off its whitelist)."""
    symbols = tuple(sorted(expr.free_symbols, key=lambda q: q.name))
    try:
        return symbols, compile_in(expr, symbols)
    except outside:
        return None


@functools.lru_cache(maxsize=4096)
def _exact_form(expr):
    """*expr* as a compiled reading of its free symbols (exact rational arithmetic), or ``None``."""
    return _compiled(expr, compile_expr, CompiledError)


def value_at(expr, point):
    """*expr* at *point*: where it is rational there, by the compiled reading's exact arithmetic
    (:class:`~symfloat.model.compiled.Compiled`: the rational SymPy's substitution reaches, without rebuilding
    the expression, about twenty times faster); anything else (an irrational value, a zero denominator, a
    symbol without a rational value) by SymPy's ``xreplace``."""
    v = _rational_at(expr, point)
    return v if v is not None else expr.xreplace(point)


def _rational_at(expr, point):
    """*expr*'s rational value at *point* by its compiled reading, or ``None`` (see :func:`value_at`)."""
    form = _exact_form(expr)
    if form is not None:
        symbols, compiled = form
        values = [point.get(q) for q in symbols]
        if all(v is not None and v.is_Rational for v in values):
            try:
                v = compiled(*(Fraction(int(v.p), int(v.q)) for v in values))
            except (ArithmeticError, ValueError, TypeError):
                v = None
            if isinstance(v, Fraction):
                return sp.Rational(v.numerator, v.denominator)
    return None


POWER_BITS = 4096       # a sampled value's powers are below 2^4096 (about 10^1233), or the point is passed over
EXPONENT_BITS = 32      # and a fractional exponent's denominator below 2^32 (see computable)
_BALL_BITS = 256        # a sampled value's ball: its midpoint is the 60-digit value where its radius allows


@functools.lru_cache(maxsize=4096)
def _ball_form(expr):
    """*expr* compiled for ball arithmetic in its free symbols (:mod:`~symfloat.engine.enclosure`), or ``None``."""
    return _compiled(expr, real_function, Unsupported)


def _ball_value(expr, point):
    """*expr* at the rational *point* from its ball at 256 bits: the midpoint as a 60-digit float where the ball
    is finite and narrower than ``2^-200`` of it (the value to 60 digits, proven), else ``None``.  An expression
    that has no ball form in its symbols (a function of a derivation whose rule needs numbers for its arguments:
    Euler's ``IY``, whose expansion into Beta integrals expands a power) gets its ball at the point itself."""
    form = _ball_form(expr)
    try:
        with working_precision(_BALL_BITS):
            if form is not None:
                symbols, f = form
                b = f(*(exact(point[q]) for q in symbols))
            elif (b := _point_ball(expr, point)) is None:
                return None
            if b.is_finite() and b.rad() <= abs(b.mid()) * arb(2) ** -200:
                return sp.Float(b.mid().str(70, radius=False), DIGITS)
    except (KeyError, ValueError, ArithmeticError):
        pass
    return None


_NO_POINT_BALL: set = set()     # expressions with a node that has no ball at a point either (hyper, polygamma)


def _point_ball(expr, point):
    """The ball of *expr* with *point* put in, or ``None`` where one of its nodes has no rule at any point."""
    if expr in _NO_POINT_BALL:
        return None
    closed = expr.xreplace(point)
    if closed.free_symbols:
        return None
    try:
        return real_function(closed, ())()
    except Unsupported:
        if len(_NO_POINT_BALL) < 4096:
            _NO_POINT_BALL.add(expr)
        return None


def computable(expr, point) -> bool:
    """Whether SymPy can put the rational *point* into *expr* in bounded time and memory: every power whose
    exponent holds a symbol is below ``2^POWER_BITS`` there (:func:`~symfloat.engine.enclosure.powers_bounded`);
    where its exponent is a fraction ``p/q``, q is below ``2^EXPONENT_BITS`` and, where its base is a rational
    b, ``b^p`` is below ``2^POWER_BITS`` too: SymPy raises a rational to ``p/q`` by way of its ``p``-th power
    and factors it (``(20/9)^((20/9)^8)`` would build a number of 2e10 digits)."""
    if not powers_bounded(expr, point, POWER_BITS):
        return False
    for power in sp.preorder_traversal(expr):
        if not (isinstance(power, sp.Pow) and power.exp.free_symbols):
            continue
        e = _rational_at(power.exp, point)
        if e is None or e.q == 1:
            continue
        b = _rational_at(power.base, point)
        size = abs(e.p) * max(abs(b.p).bit_length(), b.q.bit_length()) if b is not None else 0
        if e.q.bit_length() > EXPONENT_BITS or size > POWER_BITS:
            return False
    return True


def _sympy_value(expr, point):
    """``(value, exact)`` as SymPy gives it: a rational where the value is one, else a 60-digit float."""
    return _value(value_at(expr, point))


def _sample(pairs, domain: Domain, seed_text: str, samples: int, balls: bool = True):
    """Compare the pairs at rational points drawn from *domain*: ``(status, good points, exact, counterexample)``,
    *exact* where every value was rational.  A value the compiled reading does not give as a rational is taken
    from its ball (*balls*, :func:`_ball_value`; SymPy's substitution and ``N`` cost about a millisecond a
    value), which may be a rational SymPy would have found (``log(exp(z))`` at a rational z): where that could
    change the outcome (every other value exact, or a disagreement to report) the points are sampled again with
    SymPy's values."""
    symbols = set()
    for a, b in pairs:
        symbols |= a.free_symbols | b.free_symbols
    own = set(symbols)
    for c in domain.constraints:  # a constraint on a sampled symbol fixes its partners too
        if sp.sympify(c).free_symbols & symbols:
            symbols |= sp.sympify(c).free_symbols
    draw = domain.sampler(seed_text)
    good, exact = 0, True
    by_ball = None          # the first value of a point kept that was taken from a ball: (expression, point)
    irrational = False      # a value of a point kept that SymPy gave was not rational

    def value(expr, point):
        """``(value, exact, from a ball)``."""
        v = _rational_at(expr, point)
        if v is not None:
            return v, True, False
        if balls and (v := _ball_value(expr, point)) is not None:
            return v, False, True
        if not computable(expr, point):
            raise ArithmeticError("a power too large to compute at this point")
        return (*_value(expr.xreplace(point)), False)

    for _ in range(samples * 20):
        if good >= samples:
            break
        point = draw(symbols)
        if not domain.admits(point):
            continue
        try:
            values = [(value(a, point), value(b, point)) for a, b in pairs]
        except (ArithmeticError, ZeroDivisionError, TypeError):
            continue
        good += 1
        for (a, b), ((va, ea, ball_a), (vb, eb, ball_b)) in zip(pairs, values):
            for expr, e, ball in ((a, ea, ball_a), (b, eb, ball_b)):
                by_ball = by_ball or ((expr, point) if ball else None)
                irrational = irrational or not (e or ball)
            exact = exact and ea and eb
            if ea and eb:
                agree = va == vb
            else:
                scale = max(abs(va), abs(vb), 1)
                agree = abs(va - vb) <= AGREEMENT * scale
            if not agree:
                if by_ball:
                    return _sample(pairs, domain, seed_text, samples, balls=False)
                return "refuted", good, exact, {
                    "point": {str(k): str(v) for k, v in sorted(point.items(), key=lambda kv: kv[0].name)
                              if k in own},
                    "lhs": _show(va), "rhs": _show(vb)}
    if by_ball and not exact and not irrational and _sympy_value(*by_ball)[1]:
        # inexact only where a ball gave a value, and SymPy's value of the first of them is rational
        return _sample(pairs, domain, seed_text, samples, balls=False)
    return ("sampled" if good else "undecided"), good, exact, None


_SHOWN_EXPONENT = 10 ** 5   # a value beyond 2^(10^5) in size is shown from its logarithm


def _show(v):
    """*v* as a counterexample shows it: a rational as it is, else to 20 digits; a value beyond 2^100000 in size
    from its logarithm (SymPy would print every digit of its exponent: e^(e^(e^(e^3))) is about 10^(10^(2e8)))."""
    if v.is_Rational:
        return str(v)
    f = sp.N(v, 20)
    if isinstance(f, sp.Float) and f != 0 and abs(f._mpf_[2] + f._mpf_[3]) > _SHOWN_EXPONENT:
        return _by_logarithm(f._to_mpmath(f._prec))
    return sp.sstr(f)


def _by_logarithm(x) -> str:
    """The mpmath number *x*, far from 1 in size, as ``m e+k``, or as ``10^(...)`` where k itself is too long to
    write (its logarithm shown the same way)."""
    sign = "-" if x < 0 else ""
    with mpmath.workprec(abs(mpmath.mpf(x).exp).bit_length() + 80):
        log = mpmath.log10(abs(x))
        if abs(log) < 10 ** 15:
            k = int(mpmath.floor(log))
            m = mpmath.nstr(mpmath.power(10, log - k), 15)
            m, k = ("1.0", k + 1) if m.startswith("10") else (m, k)        # 9.99...9 rounded up to 10
            return f"{sign}{m}e{k:+d}"
        inner = _by_logarithm(log) if abs(log.exp + log.man.bit_length()) > _SHOWN_EXPONENT else mpmath.nstr(log, 15)
        return f"{sign}10^({inner})"


def _search(pairs, diffs, strategies, limit: float):
    """Try *strategies* in turn under a shared time limit of *limit* seconds (divided by
    :func:`~symfloat.engine.proofs.slowdown`); return the proving strategy (or ``None``),
    what was tried, and the residual of the last strategy that ran."""
    limit = limit / slowdown()
    deadline = time.perf_counter() + limit
    tried, residual = [], ""
    for name in strategies:
        budget = deadline - time.perf_counter()
        if budget <= 0:
            tried.append(f"{name} (not tried: the search's time limit was spent)")
            continue
        try:
            with time_limit(budget):
                rest = _apply(name, pairs, diffs)
        except TimeLimitExceeded:
            tried.append(f"{name} (stopped at the search's time limit)")
            continue
        except Exception as exc:  # a strategy that crashes is a strategy that failed
            tried.append(f"{name} ({type(exc).__name__})")
            continue
        tried.append(name)
        if all(r == 0 for r in rest):
            return name, tried, ""
        residual = sp.sstr(next(r for r in rest if r != 0))[:300]
    return None, tried, residual


def _apply(name, pairs, diffs):
    fn = _strategy(name)
    return [fn(p) for p in pairs] if name == "squares" else [fn(d) for d in diffs]


@functools.lru_cache(maxsize=4096)
def _digest(stated: tuple) -> str:
    """:func:`~symfloat.engine.proofs.claim_digest` once per claim as stated (printing it is the cost)."""
    return claim_digest(stated)


@functools.lru_cache(maxsize=4096)
def _replayed(strategy: str, pairs: tuple):
    """*strategy* replayed on *pairs*: ``None`` where it reduces every difference to 0, else the first residual
    (printed, 300 characters).  Once per claim and strategy: a claim is met again (the reading of a printed
    formula and the step that derives it, as built: a third of all certificates), and a replay has no time
    limit and gives the same result every time.  Keyed by the pairs themselves, not their printed digest, which
    does not tell symbols of one name and different assumptions apart."""
    rest = _apply(strategy, list(pairs), [x - y for x, y in pairs])
    return next((sp.sstr(r)[:300] for r in rest if r != 0), None)


def check_identity(a, b, domain: Domain, seed_text: str, *, prove=True, book: ProofBook | None = None,
                   claim: str | None = None, limit: float = SEARCH_SECONDS, samples: int = SAMPLES,
                   strategies=STRATEGIES) -> IdentityResult:
    """Decide ``a = b`` inside *domain*; see the module docstring for the order
    of evidence.  *seed_text* seeds the samples; *claim* (default: the seed
    text) keys the claim's certificate in *book* (without a book every check is
    a search)."""
    t0 = time.perf_counter()
    stated = _flatten(a, b)
    pairs = [(_evaluate(x), _evaluate(y)) for x, y in stated]
    status, n, exact, cex = _sample(pairs, domain, seed_text, samples)
    result = IdentityResult(status, samples=n, exact=exact, counterexample=cex,
                            tried=[f"sampling ({'exact' if exact else f'{DIGITS} digits'})"])
    if status == "refuted" or not prove:
        result.seconds = time.perf_counter() - t0
        return result
    t_proof = time.perf_counter()
    digest = _digest(tuple(stated))
    cert = book.get(claim or seed_text, digest) if book is not None else None
    if cert is None:
        strategy, tried, residual = _search(pairs, [x - y for x, y in pairs], strategies, limit)
        cert, result.proof = Certificate(digest, strategy, tuple(tried), residual), "searched"
    else:
        result.proof = "replayed"
    result.residual = cert.residual
    if cert.strategy is not None and result.proof == "replayed":
        residual = _replayed(cert.strategy, tuple(pairs))
        result.proof = "replayed" if residual is None else "replay failed"
        if residual is not None:
            result.residual = residual
    result.tried += list(cert.tried)
    result.certificate = cert.to_json()
    if cert.strategy is not None and result.proof != "replay failed":
        result.status, result.strategy = "proved", cert.strategy
    result.seconds = time.perf_counter() - t0
    result.proof_seconds = time.perf_counter() - t_proof
    return result


def check_rounded(a, b, tolerance, seed_text: str = "") -> IdentityResult:
    """Decide whether the closed numbers *a* and *b* differ by at most
    *tolerance* (half a unit of the last printed digit), at 60 digits.

    >>> import sympy as sp
    >>> check_rounded(sp.sqrt(2), sp.Rational(1414, 1000), sp.Rational(1, 2000)).status
    'agrees'
    >>> check_rounded(sp.sqrt(2), sp.Rational(1415, 1000), sp.Rational(1, 2000)).status
    'refuted'
    """
    t0 = time.perf_counter()
    va, vb = (sp.N(_evaluate(x), DIGITS) for x in (a, b))
    if va.free_symbols or vb.free_symbols:
        raise ValueError(f"{seed_text}: a rounded comparison needs closed numbers, got {va} and {vb}")
    ok = abs(va - vb) <= sp.N(tolerance, DIGITS)
    result = IdentityResult("agrees" if ok else "refuted", samples=1, exact=False,
                            tried=[f"60-digit comparison within {tolerance}"])
    if not ok:
        result.counterexample = {"point": {}, "lhs": _show(va), "rhs": _show(vb), "tolerance": str(tolerance)}
    result.seconds = time.perf_counter() - t0
    return result
