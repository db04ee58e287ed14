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

from ..registry import provided

__all__ = ["Form", "FormResult", "forms", "evaluate", "scan", "ScanRow", "CATASTROPHIC", "STABLE_TOLERANCE",
           "REFERENCE_DPS", "reading", "ends", "near", "split", "ngon_excess_series"]

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


def reading(d, name, member=-1):
    """Member *member* of the reading of printed formula *name* of derivation *d* (the corrected one
    where the print is an erratum)."""
    p = next(p for p in d.printed if p.name == name)
    chain = p.reading if p.erratum is None else p.erratum.corrected_reading
    return chain[member]


def ends(lo=-15, hi=-1, per=3):
    """Distances from an end: 1e-15 ... 1e-1, ``per`` per decade."""
    return tuple(float(x) for x in np.logspace(lo, hi, (hi - lo) * per + 1))


def near(root: float, deltas):
    return tuple((root + sgn * dl,) for dl in deltas for sgn in (-1, 1))


def split(x: mpmath.mpf):
    """x as hi + lo, two doubles."""
    hi = float(x)
    return hi, float(x - hi)


def ngon_excess_series():
    """Coefficients of alpha (2 + cos alpha)/(3 sin alpha) - 1 = sum c_k alpha^(2k), k = 2 .. 14."""
    a = sp.Symbol("alpha")
    ser = sp.series(a * (2 + sp.cos(a)) / (3 * sp.sin(a)) - 1, a, 0, 30).removeO()
    return [float(ser.coeff(a, 2 * k)) for k in range(2, 15)]


@cache
def forms() -> tuple[Form, ...]:
    """The closed forms the derivations hand to the study (``provides("forms", build)``; built once)."""
    out = []
    for _, build in provided("forms"):
        out += build()
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
    from ..model.relation import is_relation
    from ..registry import select, statements
    from .bench import _results, _valid_reading
    rows = []
    ends_ = ends()
    for did in select(selector):
        d = statements(did)
        dens = [sym for sym in d.domain if sym.name in DENSITY_NAMES]
        if not dens:
            continue
        rho, seen, results = dens[0], set(), _results(d)
        mids = {sym: float(sp.Rational(lo) + sp.Rational(hi)) / 2 for sym, (lo, hi) in d.domain.items()}
        for p in d.printed:
            chain = _valid_reading(p)
            if chain is None or is_relation(p.reading):       # a relation states conditions, not closed forms
                continue
            for m in members(_resolved(chain, results)):
                for e in (list(m) if isinstance(m, sp.MatrixBase) else [sp.sympify(m)]):
                    if rho not in e.free_symbols or not e.free_symbols <= set(d.domain) or not _closed(e) \
                            or e in seen or sp.count_ops(e) > 80:
                        continue
                    seen.add(e)
                    syms = sorted(e.free_symbols, key=lambda x: x.name)
                    points = [tuple(v if sym == rho else mids[sym] for sym in syms)
                              for v in ends_ + tuple(1 - x for x in ends_)]
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
