"""Enclosures: a SymPy number, or an integral of a SymPy integrand, as a ball of FLINT's Arb.

:func:`ball` walks a closed SymPy expression (its symbols replaced by numbers) over a whitelist of node
types and evaluates it in complex ball arithmetic (``acb``) at ``prec`` bits: the ball it returns contains
the exact value.  The nodes: ``Integer``, ``Rational`` (exact numerator over exact denominator), ``Float``
(its **binary value**, the number SymPy holds, rounded once at the working precision, so exact wherever
that holds its mantissa: a decimal written in a formula is the print's, and the print's own rounding is the
allowance its witness gives it, not part of the enclosure; a root a case gives at 60 digits is a ball of its
60 digits), ``pi``, ``E``,
``I``, ``Add``, ``Mul``, ``Pow`` (any exponent; an integer power is exact up to rounding, a half power a
square root, another the principal branch ``exp(t log b)``), ``exp``, ``log``, ``sin``, ``cos``, ``tan``,
``cot`` (a ball that holds a pole gives a non-finite one), ``asin``, ``acos``, ``atan``, ``sinh``, ``cosh``,
``tanh``, ``gamma``, ``Abs``, ``sign`` (decided where the ball excludes 0), ``Min`` and ``Max`` (of real
arguments, :func:`_extreme`); a function of a derivation (Euler's ``Ib``, ``IY``) by the closed form its
``rewrite(gamma)`` gives, which the derivation proves in a step.  Any other node raises :class:`Unsupported`
naming it.

:func:`integral` encloses ``∫_lo^hi f(v) dv`` by ``acb.integral`` (Petras' adaptive Gauss–Legendre with
rigorous error bounds, FLINT's ``acb_calc_integrate``).  The integrand must be holomorphic on a
neighbourhood of the path: each node with a branch cut (``sqrt``, ``log``, a fractional power, ``Abs``,
``asin``, ``acos``, ``atan``, ``Min``, ``Max``) says so by returning a non-finite ball where the ball it is given touches the
cut, and the integrator then bisects or, at its limits, returns a non-finite ball: an enclosure too wide to
decide, never a guess.  A piecewise integrand is not on the whitelist: split it at its breakpoints first.
An integrand with a branch point at an end (a factor ``base**(p/q)``, ``p/q > -1`` not an integer, ``base``
zero there: an integrable singularity as Euler's ``y²/√(b² − y²)`` at ``y = b``, or ``(1 − y)^(3/4)``) is
first rewritten by the substitution that makes it holomorphic there (:func:`_desingularised`); one it
cannot remove is integrated as it is, and an enclosure that is then not finite says so.
:func:`iterated_integral` nests ``acb.integral`` for a multiple integral, each inner variable carried to
``[0, 1]``.

>>> import sympy as sp
>>> x = sp.Symbol("x")
>>> b = ball(sp.sqrt(2) * sp.pi / 3, 128)
>>> b.overlaps(arb(2).sqrt() * arb.pi() / 3), b.rad() < arb(2) ** -120
(True, True)
>>> v = integral(sp.pi * (4 - x ** 2), x, 0, 2, 128)     # 16 pi / 3, a half sphere of radius 2
>>> with working_precision(128):
...     (v - 16 * arb.pi() / 3).abs_upper() < arb(2) ** -100
True
"""
from __future__ import annotations

import functools
import math
from contextlib import contextmanager

import sympy as sp
from flint import acb, arb, ctx

__all__ = ["Unsupported", "ball", "integral", "iterated_integral", "real_function", "sign_change_root",
           "working_precision", "exact", "upper", "lower", "powers_bounded"]


# The integrator's effort: at most this many evaluations of the integrand per bit of precision.  A holomorphic
# integrand with square-root ends (a chord through its vertex) needs about 30; an integrand unbounded at an
# end (an integrable singularity, (1 - u)^(-1/4)) exhausts any limit, and the enclosure is then not finite.
EVALUATIONS = 64


class Unsupported(ValueError):
    """A SymPy node the enclosure walker has no rigorous rule for (its message names it)."""


@contextmanager
def working_precision(prec: int):
    """Arb's working precision set to *prec* bits inside the block, restored after."""
    saved = ctx.prec
    ctx.prec = prec
    try:
        yield
    finally:
        ctx.prec = saved


def exact(value) -> arb:
    """An exact number (int, :class:`fractions.Fraction`, SymPy Integer/Rational) as a ball: radius 0 for an
    integer or a dyadic fraction, else the quotient rounded at the working precision."""
    num, den = (value.p, value.q) if isinstance(value, sp.Rational) else (value.numerator, value.denominator)
    return arb(int(num)) / int(den)


def upper(x: arb) -> float:
    """A float no smaller than every ``|v|`` in the ball *x* (``inf`` for a non-finite ball)."""
    if not x.is_finite():
        return float("inf")
    f = float(x.abs_upper())
    return f if arb(f) >= x.abs_upper() else _next_up(f)


def lower(x: arb) -> float:
    """A float no larger than every ``|v|`` in the ball *x* (0 for a non-finite ball or one holding 0)."""
    if not x.is_finite():
        return 0.0
    f = float(x.abs_lower())
    return f if arb(f) <= x.abs_lower() else max(_next_down(f), 0.0)


def _next_up(f):
    return math.nextafter(f, float("inf"))


def _next_down(f):
    return math.nextafter(f, 0.0)


# ---- the walker: a SymPy tree compiled to a function of the free variables' balls -------------------------

def _cut_free(z: acb, crossing) -> bool:
    """Whether the ball *z* keeps clear of a branch cut (``crossing(z)`` true where it may touch it)."""
    return z.is_finite() and not crossing(z)


def _guarded(f, crossing):
    """*f* (an ``acb`` method without an ``analytic`` flag) made to say where it is not holomorphic."""
    def g(z, analytic):
        if analytic and not _cut_free(z, crossing):
            return acb(arb.nan(), arb.nan())
        return f(z)
    return g


def _on_real_cut(z):          # asin, acos: the real axis outside (-1, 1)
    return z.imag.contains(0) and not (abs(z.real) < 1)


def _on_imag_cut(z):          # atan: the imaginary axis outside (-i, i)
    return z.real.contains(0) and not (abs(z.imag) < 1)


_UNARY = {
    sp.exp: lambda z, a: z.exp(),
    sp.log: lambda z, a: z.log(analytic=a),
    sp.sin: lambda z, a: z.sin(),
    sp.cos: lambda z, a: z.cos(),
    sp.tan: lambda z, a: z.tan(),
    sp.cot: lambda z, a: z.cot(),
    sp.sinh: lambda z, a: z.sinh(),
    sp.cosh: lambda z, a: z.cosh(),
    sp.tanh: lambda z, a: z.tanh(),
    sp.asin: _guarded(acb.asin, _on_real_cut),
    sp.acos: _guarded(acb.acos, _on_real_cut),
    sp.atan: _guarded(acb.atan, _on_imag_cut),
    sp.Abs: lambda z, a: z.real_abs(analytic=True) if a else acb(abs(z)),
    sp.gamma: lambda z, a: z.gamma(),
    sp.sign: lambda z, a: _sign(z),
}


def _sign(z):
    """The sign of a real ball: 1, -1, or 0 for an exact 0; non-finite where the ball holds 0 and more (a
    constant on a ball that excludes 0, so holomorphic there)."""
    x = z.real
    if x > 0 or x < 0:
        return acb(1 if x > 0 else -1)
    return acb(0) if x == 0 and z.imag == 0 else acb(arb.nan(), arb.nan())


def _constant(e):
    """A number node as a function of the working precision: evaluated at ``ctx.prec`` when first called at
    that precision, kept for the calls at the same precision (an integrand is evaluated thousands of times)."""
    if isinstance(e, sp.Rational):           # Integer too: an exact integer, or p / q rounded once
        make = lambda: acb(exact(e))  # noqa: E731
    elif isinstance(e, sp.Float):            # a dyadic number, rounded once at the working precision
        sign, man, exp, _ = e._mpf_
        mantissa, exp = -int(man) if sign else int(man), int(exp)
        make = lambda: acb(arb(mantissa) * arb(2) ** exp)  # noqa: E731
    elif e is sp.pi:
        make = lambda: acb(arb.pi())  # noqa: E731
    elif e is sp.E:
        make = lambda: acb(arb(1).exp())  # noqa: E731
    elif e is sp.I:
        make = lambda: acb(0, 1)  # noqa: E731
    else:
        raise Unsupported(f"no enclosure for the number {e} ({type(e).__name__})")
    kept = {}

    def at_precision():
        if ctx.prec not in kept:
            kept[ctx.prec] = make()
        return kept[ctx.prec]
    return at_precision


def _compile(e, variables):
    """*e* as ``f(values, analytic) -> acb``, *values* the balls of *variables* in order."""
    if e.is_Number or e.is_NumberSymbol or e is sp.I:
        c = _constant(e)
        return lambda v, a: c()
    if isinstance(e, sp.Symbol):
        if e not in variables:
            raise Unsupported(f"the expression still names the symbol {e}")
        k = variables.index(e)
        return lambda v, a: v[k]
    if isinstance(e, (sp.Add, sp.Mul)):
        parts = [_compile(t, variables) for t in e.args]
        if isinstance(e, sp.Add):
            def add(v, a):
                total = parts[0](v, a)
                for p in parts[1:]:
                    total = total + p(v, a)
                return total
            return add

        def mul(v, a):
            total = parts[0](v, a)
            for p in parts[1:]:
                total = total * p(v, a)
            return total
        return mul
    if isinstance(e, sp.Pow):
        base, power = _compile(e.base, variables), e.exp
        if power.is_Integer:
            n = int(power)
            return lambda v, a: base(v, a) ** n
        if power == sp.S.Half:
            return lambda v, a: base(v, a).sqrt(analytic=a)
        if power == -sp.S.Half:
            return lambda v, a: base(v, a).rsqrt(analytic=a)
        t = _compile(power, variables)
        return lambda v, a: base(v, a).pow(t(v, a), analytic=a)
    if isinstance(e, (sp.Min, sp.Max)):
        return _extreme(e, [_compile(t, variables) for t in e.args])
    if e.func in _UNARY and len(e.args) == 1:
        f, arg = _UNARY[e.func], _compile(e.args[0], variables)
        return lambda v, a: f(arg(v, a), a)
    if isinstance(e, sp.Function) and (closed := e.rewrite(sp.gamma)) != e and not closed.has(e.func):
        return _compile(closed, variables)       # a rewrite that keeps its own function would recurse
    raise Unsupported(f"no enclosure for a {type(e).__name__} node ({e})")


def _extreme(e, parts):
    """``Min`` or ``Max`` of the compiled *parts*: of real values, ``arb.min`` / ``arb.max`` (the ball of the
    least or the greatest); in an integrand (``analytic``) the part whose real part is proven below (``Min``)
    or above (``Max``) every other one over the whole ball, a holomorphic function that equals the extreme on
    the real points there; where no part is, the extreme may switch inside the ball and is not holomorphic:
    a non-finite ball."""
    lesser = isinstance(e, sp.Min)

    def extreme(v, a):
        values = [p(v, a) for p in parts]
        if a:
            for k, z in enumerate(values):
                if all((z.real < w.real) if lesser else (z.real > w.real) for j, w in enumerate(values) if j != k):
                    return z
            return acb(arb.nan(), arb.nan())
        reals = [_real(z, e) for z in values]
        out = reals[0]
        for x in reals[1:]:
            out = out.min(x) if lesser else out.max(x)
        return acb(out)
    return extreme


def _real(z: acb, what, prefix: str = "") -> arb:
    """The real part of *z*, whose imaginary part must hold 0 (the value is real), else a clear error naming
    *prefix* and *what* (printed only then: printing an expression costs more than the ball)."""
    if not z.imag.contains(0):
        raise ValueError(f"{prefix}{what} is not a real number (its enclosure is {z})")
    return z.real


def ball(expr, prec: int, at: dict | None = None) -> arb:
    """The real number *expr* (a closed SymPy expression, or one in the symbols of *at*, given as balls) as a
    ball at *prec* bits; see the module."""
    e = sp.sympify(expr)
    variables = tuple(at or ())
    f = _compile(e, variables)
    with working_precision(prec):
        return _real(f(tuple(acb(at[v]) for v in variables), False), e)


def powers_bounded(expr, point: dict, bits: int) -> bool:
    """Whether every power of *expr* whose exponent holds a symbol stays below ``2^bits`` in size at *point*
    (symbol -> rational), judged on 64-bit balls before anything computes it exactly: ``h^{h^{h^h}}`` at h = 2
    is 2^65536, one level more a number no memory holds, which SymPy would compute when the point is put in.
    ``False`` also where a base or exponent has no finite ball there."""
    at = {s: ball(v, 64) for s, v in point.items()}
    for power in sp.preorder_traversal(expr):
        if not (isinstance(power, sp.Pow) and power.exp.free_symbols):
            continue
        try:
            base, exponent = abs(ball(power.base, 64, at)), ball(power.exp, 64, at)
        except (Unsupported, ValueError, ArithmeticError, TypeError):
            return False
        if not (base.is_finite() and exponent.is_finite()):
            return False
        if base.contains(0) or base.contains(1):
            continue
        if (abs(exponent) * abs(base.log())).upper() > bits * math.log(2):     # |e ln b| against bits ln 2
            return False
    return True


def real_function(expr, variables):
    """*expr* (closed but for *variables*) as a function of their balls returning a real ball, at the
    working precision of the call: compiled once, for an expression evaluated many times."""
    f = _compile(sp.sympify(expr), tuple(variables))
    return lambda *values: _real(f(tuple(acb(v) for v in values), False), expr)


def sign_change_root(f, lo: float, hi: float, prec: int) -> arb:
    """A root of the real function *f* (of a ball) in ``[lo, hi]``, where ``f(lo)`` and ``f(hi)`` are balls of
    strictly opposite signs, as a ball of radius at most ``2^-prec (1 + |root|)`` or as narrow as the signs
    of *f* allow: bisection with exact dyadic midpoints, each half kept where the sign change is proven
    (intermediate value theorem).  Non-finite when the signs at the ends are not proven opposite."""
    with working_precision(prec):
        a, b = arb(lo), arb(hi)
        fa, fb = f(a), f(b)
        if not ((fa < 0 and fb > 0) or (fa > 0 and fb < 0)):
            return arb.nan()
        negative_at_a = fa < 0
        while (b - a) > arb(2) ** -prec * (1 + abs(a)):
            m = (a + b) / 2                 # exact: a dyadic midpoint of dyadic ends
            fm = f(m)
            if (fm < 0) == negative_at_a and (fm < 0 or fm > 0):
                a = m
            elif fm < 0 or fm > 0:
                b = m
            else:
                break
        return a.union(b)


def integral(expr, var, lo, hi, prec: int, at: dict | None = None) -> arb:
    """``∫_lo^hi expr dvar`` (*expr* closed but for *var* and the symbols of *at*, given as balls; *lo*, *hi*
    closed SymPy numbers or balls) as a ball at *prec* bits, by ``acb.integral`` with its goal ``2^-prec``
    relative and at most ``EVALUATIONS * prec`` evaluations; non-finite when the integrand is not holomorphic
    near the path or the evaluations run out (see the module)."""
    expr = sp.sympify(expr)
    if not any(isinstance(x, arb) for x in (lo, hi)):
        pieces = _desingularised(expr, var, sp.sympify(lo), sp.sympify(hi))
        if pieces is not None:
            with working_precision(prec):
                return sum((integral(g, t, a, b, prec, at) for g, t, a, b in pieces), arb(0))
    constants = tuple(at or ())
    f = _compile(expr, (var, *constants))
    with working_precision(prec):
        fixed = tuple(acb(at[c]) for c in constants)
        a, b = (x if isinstance(x, arb) else ball(x, prec) for x in (lo, hi))
        value = acb.integral(lambda z, analytic: f((z, *fixed), analytic), a, b, eval_limit=EVALUATIONS * prec)
        if not value.is_finite():
            return arb.nan()
        return _real(value, expr, "the integral of ")


# An iterated integral's budget: at most this many evaluations of its integrand, over all its nested integrals
# together, per bit of precision.  An inner integral that has no finite enclosure makes the outer integrator
# bisect, and each of its evaluations would integrate anew: past the budget the inner integrals return a
# non-finite ball at once, and so does the iterated integral.  A count, never a clock.
ITERATED_EVALUATIONS = 4 * EVALUATIONS


def iterated_integral(expr, limits, prec: int, at: dict | None = None) -> arb:
    """``∫…∫ expr`` over *limits* (SymPy's order, the innermost first, each ``(v, lo, hi)``; an inner end may
    depend on the variables outside it, the outermost ends are closed) as a ball at *prec* bits.

    Each inner variable is carried to ``[0, 1]`` by ``v = lo + (hi - lo) t``, its Jacobian ``hi - lo`` a
    factor of the integrand, so that every inner integral runs over a fixed segment; the integrals are then
    nested in ``acb.integral``.  Where the outer integrator asks for holomorphy (its *analytic* flag) every
    inner evaluation asks for it too, so that the inner integral is proven holomorphic in the outer
    variables.  Non-finite where any integral has no finite enclosure or the evaluations exceed
    :data:`ITERATED_EVALUATIONS` per bit (see :func:`integral`).

    >>> x, y = sp.symbols("x y")
    >>> v = iterated_integral(x * y ** 2, ((y, -x, x), (x, 0, 1)), 128)      # 2/3 * int_0^1 x^4 dx = 2/15
    >>> with working_precision(128):
    ...     (v - arb(2) / 15).abs_upper() < arb(2) ** -100
    True
    """
    expr = sp.sympify(expr)
    if len(limits) == 1:
        return integral(expr, *limits[0], prec, at)
    inner = []
    for k, (v, lo, hi) in enumerate(limits[:-1]):
        t = sp.Dummy(f"t{k}")
        expr = expr.xreplace({v: lo + (hi - lo) * t}) * (hi - lo)
        inner.append(t)
    var, lo, hi = limits[-1]
    constants = tuple(at or ())
    f = _compile(expr, (*inner, var, *constants))
    budget = [ITERATED_EVALUATIONS * prec]
    with working_precision(prec):
        fixed = tuple(acb(at[c]) for c in constants)
        zero, one, nan = acb(0), acb(1), acb(arb.nan(), arb.nan())

        def over(k, outer, analytic):
            """The integral over ``inner[k]`` from 0 to 1, the variables outside it at *outer*."""
            if budget[0] <= 0:
                return nan

            def g(z, a):
                if budget[0] <= 0:
                    return nan
                budget[0] -= 1
                a = a or analytic
                return f((z, *outer, *fixed), a) if k == 0 else over(k - 1, (z, *outer), a)
            return acb.integral(g, zero, one, eval_limit=EVALUATIONS * prec)

        a, b = (x if isinstance(x, arb) else ball(x, prec) for x in (lo, hi))
        value = acb.integral(lambda z, analytic: over(len(inner) - 1, (z,), analytic), a, b,
                             eval_limit=EVALUATIONS * prec)
        if budget[0] <= 0 or not value.is_finite():
            return arb.nan()
        return _real(value, expr, "the integral of ")


def _branch_points(expr, var, ends) -> frozenset:
    """The pairs ``(factor, end)``: each power ``base**e`` in *expr* (at any depth) with ``e > -1`` rational, not
    an integer, and ``base`` zero at the *end* (one of *ends*): a branch point there (an integrable singularity
    where ``e < 0``), where ``acb.integral`` cannot bound the integrand or needs many evaluations to.  Collected
    once per integrand, each base tested at each end once (:func:`_vanishes`)."""
    return frozenset((f, end) for f in expr.atoms(sp.Pow)
                     if f.exp.is_Rational and not f.exp.is_Integer and f.exp > -1 and f.base.has(var)
                     for end in ends if _vanishes(f.base, var, end))


@functools.lru_cache(maxsize=4096)
def _vanishes(base, var, end) -> bool:
    """Whether *base* is zero at ``var = end`` (``sp.simplify`` decides; the same base is met at every
    precision the witness tries)."""
    return sp.simplify(base.subs(var, end)) == 0


def _singular_factors(expr, var, end, branch):
    """The factors of *expr* (a product) that are branch points at *end* (in *branch*, :func:`_branch_points`)."""
    return [f for f in sp.Mul.make_args(expr) if (f, end) in branch]


def _desingularised(expr, var, lo, hi, rooted=False, known=None):
    """``∫_lo^hi expr dvar`` as pieces ``(integrand, t, a, b)`` without a branch point at an end, or ``None``
    where *expr* has none.  At an end e with one factor ``base**(p/q)`` (``p/q > -1`` not an integer,
    ``base = ±(var - e) h`` with ``h(e) != 0``) the substitution ``var = e ∓ t**q`` turns the factor into
    ``t**p h**(p/q)`` and ``dvar`` into ``q t**(q-1) dt``: the integrand becomes ``t**(p+q-1)`` (a power
    ``>= 0``) times a function holomorphic at ``t = 0``.  Branch points at both ends split the interval at
    its midpoint; a sum is integrated term by term.  *known*: the :func:`_branch_points` at *lo* and *hi* of a
    sum that *expr* is a term of (its own are among them)."""
    if known is None:
        branch = _branch_points(expr, var, (lo, hi))
    else:
        powers = expr.atoms(sp.Pow)
        branch = frozenset(pair for pair in known if pair[0] in powers)
    if not branch:
        return None

    def singular_at(term, e):
        return bool(_singular_factors(term, var, e, branch))
    if not any(singular_at(t, e) for t in sp.Add.make_args(expr) for e in (lo, hi)):
        expanded = sp.expand(expr)                     # y²(1 − (1 − y)^(1/4)): the branch factor made a factor
        if expanded != expr:
            expr, branch = expanded, _branch_points(expanded, var, (lo, hi))
    if isinstance(expr, sp.Add):                       # term by term, where a term has a branch point at an end
        if not any(singular_at(term, e) for term in expr.args for e in (lo, hi)):
            return None
        return [piece for term in expr.args
                for piece in (_desingularised(term, var, lo, hi, rooted, branch) or [(term, var, lo, hi)])]
    ends = [e for e in (lo, hi) if singular_at(expr, e)]
    if not ends:
        return None
    if len(ends) == 2:
        mid = (lo + hi) / 2
        return [*(_desingularised(expr, var, lo, mid, rooted) or [(expr, var, lo, mid)]),
                *(_desingularised(expr, var, mid, hi, rooted) or [(expr, var, mid, hi)])]
    end, other = (lo, hi) if ends[0] == lo else (hi, lo)
    factors = _singular_factors(expr, var, end, branch)
    if len(factors) != 1:
        return None
    (factor,) = factors
    roots = sp.ilcm(1, 1, *(x.exp.q for x in factor.base.atoms(sp.Pow) if x.base == var and x.exp.is_Rational))
    if roots > 1 and lo >= 0 and not rooted:           # var = w**roots first: the base a polynomial in w
        w = sp.Dummy("w", positive=True)
        at_w = sp.powdenest(expr.subs(var, w ** roots), force=True) * roots * w ** (roots - 1)
        return _desingularised(at_w, w, lo ** sp.Rational(1, roots), hi ** sp.Rational(1, roots), rooted=True)
    side = 1 if end == lo else -1                      # var = end + side * t**q runs from the end inward
    h = sp.cancel(factor.base / (side * (var - end)))
    if not _finite_nonzero(h.subs(var, end)):
        h = sp.simplify(h)                              # (1 - sqrt(u)) / (1 - u) = 1 / (1 + sqrt(u))
        if not _finite_nonzero(h.subs(var, end)):
            return None
    p, q = factor.exp.p, factor.exp.q
    t = sp.Dummy("t", positive=True)
    rest = (expr / factor).subs(var, end + side * t ** q)
    integrand = rest * h.subs(var, end + side * t ** q) ** factor.exp * q * t ** (p + q - 1)
    reach = (side * (other - end)) ** sp.Rational(1, q)
    return [(integrand, t, sp.Integer(0), reach)]


def _finite_nonzero(value):
    value = sp.simplify(value)
    return value.is_finite is True and value.is_zero is False

