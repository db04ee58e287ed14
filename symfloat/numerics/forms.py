"""Stiff and extreme cases of the library's closed forms: float64 against 50 digits.

Each :class:`Form` takes its SymPy expression from a derivation of the
registry (a printed reading, or a result derived from one), evaluates it as
printed in float64 (``lambdify`` with ``math``) and at 50 digits (``lambdify``
with ``mpmath``, the float64 inputs taken exactly), over sweeps that push the
parameters to their ends: densities s -> 0+ and 1- down to 1e-15 from the ends,
aspect ratios 1e-6 ... 1e6, regular n-gons up to 10^6 sides, angles near 0 and
90 deg, densities within 1e-15 of the stability thresholds.  A form whose
printed evaluation loses more than 6 digits (relative error above
``CATASTROPHIC``) has a hand-written stable equivalent that stays within
``STABLE_TOLERANCE``:

* roots of a quadratic: the smaller root from the product of the roots
  (``s_- = (k^2/6)/s_+``, ``rho_1 = 1/(6 l^2 rho_2)``) instead of a difference
  of nearly equal numbers;
* near a threshold root: the factored form ``6 (s - s_-)(s - s_+)`` with each
  root stored as a sum of two doubles, so ``s - s_-`` is exact;
* the excess of the n-gon's moment over the circle's, ``alpha/sin alpha
  (2 + cos alpha)/3 - 1 = alpha^4/180 + ...``: its Taylor series for small alpha;
* the moment about a turned axis, (83), near 90 deg for elongated sections: the
  printed equivalent ``T_y sin^2 + T_x cos^2`` (sum of positive terms).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cache

import mpmath
import numpy as np
import sympy as sp

from ..registry import load

__all__ = ["Form", "FormResult", "forms", "evaluate", "scan", "ScanRow", "CATASTROPHIC", "STABLE_TOLERANCE",
           "REFERENCE_DPS"]

EPS = 2.0 ** -53
CATASTROPHIC = EPS * 1e6          # more than 6 digits lost
STABLE_TOLERANCE = 1e-13
REFERENCE_DPS = 50


@dataclass(frozen=True)
class Form:
    """A closed form of the library, its parameters and sweeps, and a stable equivalent if needed."""

    name: str
    locator: str                  # derivation id and printed name / step
    expr: sp.Expr
    symbols: tuple
    sweeps: tuple                 # (label, tuple of parameter tuples (floats))
    stable: object = None         # float64 function of the same parameters, or None
    stable_text: str = ""


@dataclass
class FormResult:
    """Worst relative error of the printed and the stable float64 evaluation per sweep."""

    form: Form
    naive: dict     # sweep label -> (worst relative error, parameters where it occurs)
    stable: dict

    @property
    def worst_naive(self):
        return max(e for e, _ in self.naive.values())

    @property
    def worst_stable(self):
        return max((e for e, _ in self.stable.values()), default=None)

    @property
    def catastrophic(self):
        return self.worst_naive > CATASTROPHIC


def _reading(did, name, member=-1):
    d, _ = load(did)
    p = next(p for p in d.printed if p.name == name)
    chain = p.reading if p.erratum is None else p.erratum.corrected_reading
    return chain[member]


def _ends(lo=-15, hi=-1, per=3):
    """Distances from an end: 1e-15 ... 1e-1, ``per`` per decade."""
    return tuple(float(x) for x in np.logspace(lo, hi, (hi - lo) * per + 1))


def _near(root: float, deltas):
    return tuple((root + sgn * dl,) for dl in deltas for sgn in (-1, 1))


def _split(x: mpmath.mpf):
    """x as hi + lo, two doubles."""
    hi = float(x)
    return hi, float(x - hi)


def _ngon_excess_series():
    """Coefficients of alpha (2 + cos alpha)/(3 sin alpha) - 1 = sum c_k alpha^(2k), k = 2 .. 14."""
    a = sp.Symbol("alpha")
    ser = sp.series(a * (2 + sp.cos(a)) / (3 * sp.sin(a)) - 1, a, 0, 30).removeO()
    return [float(ser.coeff(a, 2 * k)) for k in range(2, 15)]


@cache
def forms() -> tuple[Form, ...]:
    """The registry of closed forms (built once; readings come from the derivations)."""
    s, a, b, n = sp.symbols("s a b n", positive=True)
    F1n, alph = sp.Symbol("F_1n"), sp.Symbol("alpha")
    out = []

    # (89a): T_1 / F^2 over n = 3 .. 10^6, alpha = 2 pi / n
    t89 = _reading("scheeffer-vi-cf", "89a").subs(F1n, 1).subs(alph, 2 * sp.pi / n)
    ns = tuple((float(v),) for v in np.unique(np.round(np.logspace(np.log10(3), 6, 40))))
    out.append(Form("n-gon moment at equal area, (89a)", "scheeffer-vi-cf/89a", t89, (n,),
                    (("n = 3 ... 10^6", ns),)))

    # the decrease of T_1 towards the circle: T_1 / (F^2/(4 pi)) - 1
    coeffs = _ngon_excess_series()

    def excess_stable(nv):
        al = 2 * math.pi / nv
        if al > 1:
            return al * (2 + math.cos(al)) / (3 * math.sin(al)) - 1
        x2 = al * al
        return sum(c * x2 ** (k + 2) for k, c in enumerate(coeffs))
    out.append(Form("excess of the n-gon's moment over the circle's, (89a) / (89c) - 1", "scheeffer-vi-cf/89a",
                    sp.simplify(t89 * 4 * sp.pi) - 1, (n,), (("n = 3 ... 10^6", ns),), excess_stable,
                    "alpha^4/180 + ... (Taylor series to alpha^28) for alpha = 2 pi/n <= 1"))

    # (78): 1 - 6 s (1 - s) near its roots 1/2 -+ sqrt(1/12) (0.2113, 0.7887; hasab: the same thresholds)
    with mpmath.workdps(40):
        lo_hi, lo_lo = _split(mpmath.mpf(1) / 2 - mpmath.sqrt(mpmath.mpf(1) / 12))
        up_hi, up_lo = _split(mpmath.mpf(1) / 2 + mpmath.sqrt(mpmath.mpf(1) / 12))
    deltas = _ends()
    e78 = _reading("scheeffer-vi-cf", "cube-78", 0)
    out.append(Form("cube upright criterion 1 - 6s(1-s), (78)", "scheeffer-vi-cf/cube-78", e78, (s,),
                    (("s within 1e-15 ... 1e-1 of 0.2113", _near(lo_hi, deltas)),
                     ("s within 1e-15 ... 1e-1 of 0.7887", _near(up_hi, deltas)),
                     ("s -> 0+ and 1-", tuple((v,) for v in deltas) + tuple((1 - v,) for v in deltas))),
                    lambda sv: 6 * ((sv - lo_hi) - lo_lo) * ((sv - up_hi) - up_lo),
                    "6 (s - s_-)(s - s_+), each root a sum of two doubles"))

    # VI.A: the triangular prism's printed thresholds s = (1 -+ sqrt(1 - (a/b)^2/3))/2, aspect k = a/b -> 0
    k = sp.Symbol("k", positive=True)
    thresholds = _reading("scheeffer-vi-ab", "density-range", 0)
    lower = thresholds[1].subs(a, k * b)
    ks = tuple((float(v),) for v in np.logspace(-6, np.log10(1.7), 40))
    out.append(Form("triangular prism: lower threshold density (1 - sqrt(1 - (a/b)^2/3))/2",
                    "scheeffer-vi-ab/density-range",
                    lower, (k,), (("k = a/b = 1e-6 ... 1.7", ks),),
                    lambda kv: (kv * kv / 12) / (0.5 + 0.5 * math.sqrt(1 - kv * kv / 3)),
                    "(k^2/12) / s_+ (product of the roots)"))

    # ... and its discriminant near the singular point a/b -> sqrt 3 (the double root s = 1/2)
    with mpmath.workdps(40):
        r3_hi, r3_lo = _split(mpmath.sqrt(3))
    disc = sp.sqrt(1 - k ** 2 / 3)
    near3 = tuple((r3_hi * (1 - dl),) for dl in _ends())
    out.append(Form("triangular prism: discriminant sqrt(1 - (a/b)^2/3) near a/b = sqrt 3",
                    "scheeffer-vi-ab/density-range", disc, (k,), (("a/b within 1e-15 ... 1e-1 below sqrt 3", near3),),
                    lambda kv: math.sqrt(((r3_hi - kv) + r3_lo) * (r3_hi + kv) / 3),
                    "sqrt((sqrt3 - k)(sqrt3 + k)/3), sqrt 3 a sum of two doubles"))

    # hasab, remark: the lower threshold of the upright prism, (3l - sqrt(9l^2 - 6))/(6l), l up to 1e6,
    # and the width of the unstable range sqrt(9l^2 - 6)/(3l) near the double root l = sqrt(2/3)
    _, hasab = load("hasab")
    l = hasab.l
    ls = tuple((float(v),) for v in np.logspace(np.log10(0.82), 6, 40))
    out.append(Form("long square prism upright: lower threshold (3l - sqrt(9l^2-6))/(6l)", "hasab/upright-roots",
                    hasab.ru1, (l,), (("l = 0.82 ... 1e6", ls),),
                    lambda lv: 1 / (lv * (3 * lv + math.sqrt(9 * lv * lv - 6))),
                    "1 / (l (3l + sqrt(9l^2 - 6))) (product of the roots 1/(6 l^2))"))
    with mpmath.workdps(40):
        r23_hi, r23_lo = _split(mpmath.sqrt(mpmath.mpf(2) / 3))
    width = sp.sqrt(9 * l ** 2 - 6) / (3 * l)
    near23 = tuple((r23_hi * (1 + dl),) for dl in _ends())
    out.append(Form("long square prism upright: unstable range ru2 - ru1 = sqrt(9l^2-6)/(3l) near l = sqrt(2/3)",
                    "hasab/upright-roots", width, (l,), (("l within 1e-15 ... 1e-1 above sqrt(2/3)", near23),),
                    lambda lv: math.sqrt(9 * ((lv - r23_hi) - r23_lo) * (lv + r23_hi)) / (3 * lv),
                    "sqrt(9 (l - r)(l + r))/(3l), r = sqrt(2/3) a sum of two doubles"))

    # VI.C upright metacentric height a^2/(12 b s) - b(1 - s)/2: s -> 0+, 1-, aspect ratios 1e-6 .. 1e6
    gm = _reading("scheeffer-vi-cf", "upright-condition", 0)
    grid = tuple((float(av), 1.0, float(sv)) for av in np.logspace(-6, 6, 13)
                 for sv in (1e-15, 1e-10, 1e-5, 0.5, 1 - 1e-5, 1 - 1e-10, 1 - 1e-15))
    out.append(Form("square prism upright GM a^2/(12bs) - b(1-s)/2", "scheeffer-vi-cf/upright-condition",
                    gm, (a, b, s), (("a/b = 1e-6 ... 1e6 (b = 1), s -> 0+, 1-", grid),)))

    # (83): T = (Tx + Ty)/2 + (Tx - Ty)/2 cos 2 psi near 0 and 90 deg, Tx = 1, Ty = k^2 (aspect k)
    Txs, Tys = sp.Symbol("T_x"), sp.Symbol("T_y")
    psis = sp.Symbol("psi", positive=True)
    t83 = _reading("scheeffer-vi-cf", "83")
    t83 = t83.xreplace({sym: {"T_x": Txs, "T_y": Tys, "psi": psis}.get(sym.name, sym) for sym in t83.free_symbols})
    angles = tuple(math.pi / 2 - dl for dl in _ends(-15, -1, 1)) + tuple(_ends(-15, -1, 1))
    grid83 = tuple((1.0, float(kv) ** 2, ang) for kv in np.logspace(-6, 0, 7) for ang in angles)
    out.append(Form("moment about a turned axis, (83), T_x = 1, T_y = k^2", "scheeffer-vi-cf/83",
                    t83, (Txs, Tys, psis), (("k = 1e-6 ... 1, psi within 1e-15 ... 0.1 of 0 and 90 deg", grid83),),
                    lambda tx, ty, ps: ty * math.sin(ps) ** 2 + tx * math.cos(ps) ** 2,
                    "T_y sin^2 psi + T_x cos^2 psi (the text's own equivalent, VI.E)"))
    return tuple(out)


def _rel(value, ref):
    return float(abs(mpmath.mpf(value) - ref) / abs(ref)) if ref else float(abs(mpmath.mpf(value)))


def evaluate(form: Form) -> FormResult:
    """Worst relative errors of the printed and the stable evaluation over each sweep."""
    naive = sp.lambdify(form.symbols, form.expr, "math")
    ref = sp.lambdify(form.symbols, form.expr, "mpmath")
    res_n, res_s = {}, {}
    for label, points in form.sweeps:
        worst_n, worst_s = (0.0, None), (0.0, None)
        for p in points:
            with mpmath.workdps(REFERENCE_DPS):
                r = ref(*(mpmath.mpf(v) for v in p))
                try:
                    e = _rel(naive(*p), r)
                except (ValueError, ZeroDivisionError, OverflowError):
                    e = math.inf
                worst_n = max(worst_n, (e, p), key=lambda t: t[0])
                if form.stable is not None:
                    worst_s = max(worst_s, (_rel(form.stable(*p), r), p), key=lambda t: t[0])
        res_n[label] = worst_n
        if form.stable is not None:
            res_s[label] = worst_s
    return FormResult(form, res_n, res_s)


DENSITY_NAMES = ("s", "varrho", "rho")
ALLOWED = (sp.Add, sp.Mul, sp.Pow, sp.Symbol, sp.Number, sp.NumberSymbol, sp.sin, sp.cos, sp.tan, sp.cot)


@dataclass
class ScanRow:
    """A closed form in the density found in a derivation: its worst float64 error at the ends of the
    density range and, if flagged, the first algebraic rewrite that stays within the stable tolerance."""

    derivation: str
    formula: str
    expr: sp.Expr
    worst: float
    at: float
    rewrite: str = ""
    rewrite_worst: float | None = None


def _closed(e):
    return all(isinstance(node, ALLOWED) for node in sp.preorder_traversal(e))


def _worst_over(expr, symbols, points):
    f = sp.lambdify(symbols, expr, "math")
    ref = sp.lambdify(symbols, expr, "mpmath")
    worst, at = 0.0, None
    for p in points:
        with mpmath.workdps(REFERENCE_DPS):
            try:
                r = ref(*(mpmath.mpf(v) for v in p))
                if not isinstance(r, mpmath.mpf) or abs(r) < mpmath.mpf(10) ** (10 - REFERENCE_DPS):
                    continue            # complex, or zero: an identity residual, no relative error
                e = _rel(f(*p), r)
            except (ValueError, ZeroDivisionError, OverflowError, TypeError):
                continue
        if e > worst:
            worst, at = e, p
    return worst, at


def scan(selector=None) -> list[ScanRow]:
    """Every closed form in the density (s or rho) among the valid readings of the derivations: float64
    against 50 digits with the density 1e-15 ... 1e-1 from 0 and from 1, the other parameters at the
    middle of their sampling intervals.  Flagged forms try ``factor``, ``cancel``, ``together`` and
    ``expand`` as stable rewrites."""
    from ..engine.check import _resolved
    from ..model.claim import members
    from ..registry import select
    from .bench import _results, _valid_reading
    rows = []
    ends = _ends()
    for did in select(selector):
        d, _ = load(did)
        dens = [sym for sym in d.domain if sym.name in DENSITY_NAMES]
        if not dens:
            continue
        rho, seen, results = dens[0], set(), _results(d)
        mids = {sym: float(sp.Rational(lo) + sp.Rational(hi)) / 2 for sym, (lo, hi) in d.domain.items()}
        for p in d.printed:
            chain = _valid_reading(p)
            if chain is None:
                continue
            for m in members(_resolved(chain, results)):
                for e in (list(m) if isinstance(m, sp.MatrixBase) else [sp.sympify(m)]):
                    if rho not in e.free_symbols or not e.free_symbols <= set(d.domain) or not _closed(e) \
                            or e in seen or sp.count_ops(e) > 80:
                        continue
                    seen.add(e)
                    syms = sorted(e.free_symbols, key=lambda x: x.name)
                    points = [tuple(v if sym == rho else mids[sym] for sym in syms)
                              for v in ends + tuple(1 - x for x in ends)]
                    worst, at = _worst_over(e, syms, points)
                    row = ScanRow(did, p.name, e, worst, at[syms.index(rho)] if at else None)
                    if worst > CATASTROPHIC:
                        for how in (sp.factor, sp.cancel, sp.together, sp.expand):
                            w2, _ = _worst_over(how(e), syms, points)
                            if w2 <= STABLE_TOLERANCE:
                                row.rewrite, row.rewrite_worst = how.__name__, w2
                                break
                    rows.append(row)
    return rows
