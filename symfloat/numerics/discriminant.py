"""Numerical stability of the discriminant closed forms of Scheeffer IX (source 000_1e9760952686f295, "## IX.",
(146)-(160)).

The text puts sigma = 1 - s ("ferner 1-s = sigma", before (136)) and t = (128 sigma - 9)/27 (147), i.e.
t = (119 - 128 s)/27 ("Nach 147 ist t = ...", after (160)) and 1 + 3t = 128 sigma/9 (150).  The double-root
locus exists for 23/32 < s < 1, i.e. -1/3 < t < 1.  Evaluated in float64 with t from (147), the printed forms
lose digits at t -> 1 (s -> 23/32: 1 - t, S - 2, S^2 - 4 vanish, n_1 -> 1 and (155) is 0/0), at t -> -1/3
(s -> 1: 1 + 3t vanishes, S and n_1 blow up, n_2, z_2 and the margin of (160) vanish) and at t -> 0
(s -> 119/128: (151) is 0/0 through its factor 1/t).

The stable forms compute the factors directly from s, each with a single rounding (for 1/2 < s < 1 the products
by powers of two and the subtractions 1 - s, 32 s - 23, 73 - 64 s are exact, the last two by Sterbenz's lemma):
  1 - t = 4(32 s - 23)/27,  1 + 3t = 128(1 - s)/9,  1 + t = 2(73 - 64 s)/27,  5 - t = 16(1 + 8 s)/27,
and remove every cancelling difference algebraically:
  S = (3 + 3t + 3t^2 - t^3)/(1 + 3t)                 ((151) with the factor t cancelled),
  n_1 = 1 + (1-t)^3/(2(1+3t)) + (1-t)(1+t) sqrt((5-t)(1-t))/(2(1+3t))   ((156), all terms positive),
  n_2 = 1/n_1                                         ((153): n_1 n_2 = 1),
  z_1 = (3/16){3 + t + sqrt((5-t)(1-t))}              ((158), also for the 0/0 form (155)),
  z_2 = (3/4)(1 + 3t)/(3 + t + sqrt((5-t)(1-t)))     ((157) lower sign; (3+t)^2 - (5-t)(1-t) = 4(1+3t)),
  7 - 3t - 3 sqrt((5-t)(1-t)) = 4(1 + 3t)/(7 - 3t + 3 sqrt((5-t)(1-t)))   ((160); (7-3t)^2 - 9(5-t)(1-t) = 4(1+3t)).
No series expansion is needed: after these rewritings no 0/0 is left.

Every form is written once, generically in s and a square root, so the same code gives the float64 value
(s float, math.sqrt) and the exact value.  The reference is the printed form at the exact value of the float s:
exact rational arithmetic (SymPy Rational) up to the square root, binary floats of 100 and of 150 digits from
there on, the two agreeing to 50 digits (so the cancellation of the printed form does not reach the reference).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import mpmath
import sympy as sp

from ..model.myst import inline
from ..numbers import scientific, written
from ..prose import typeset

UNIT_ROUNDOFF = 2.0 ** -53
CATASTROPHIC_DIGITS = 6.0
REFERENCE_DIGITS = 50
DISTANCES = tuple(10.0 ** -k for k in range(1, 16))
S_THRESHOLD = sp.Rational(23, 32)   # t = 1, (140)
S_T_ZERO = sp.Rational(119, 128)    # t = 0, the factor 1/t of (151)


# printed factors: t from sigma = 1 - s by (147)
def _t(s):
    """t = (128 sigma - 9)/27, sigma = 1 - s (147)."""
    return (128 * (1 - s) - 9) / 27


def _s151(s):
    """S = (1/t){1 + t^2 - (1 - t^2)^2/(1 + 3t)} (151)."""
    t = _t(s)
    return 1 / t * (1 + t ** 2 - (1 - t ** 2) ** 2 / (1 + 3 * t))


def _sq153(s, sqrt):
    """sqrt(S^2 - 4) of (153), S from (151)."""
    S = _s151(s)
    return sqrt(S ** 2 - 4)


def _root154(s, sqrt):
    """sqrt((5 - t)(1 - t)) of (156)-(160), t from (147)."""
    t = _t(s)
    return sqrt((5 - t) * (1 - t))


# stable factors, directly from s
def _m(s):
    """1 - t = 4(32 s - 23)/27 (from (147))."""
    return 4 * (32 * s - 23) / 27


def _p(s):
    """1 + 3t = 128 sigma/9 (150), sigma = 1 - s."""
    return 128 * (1 - s) / 9


def _q(s):
    """1 + t = 2(73 - 64 s)/27 (from (147))."""
    return 2 * (73 - 64 * s) / 27


def _f(s):
    """5 - t = 16(1 + 8 s)/27 (from (147))."""
    return 16 * (1 + 8 * s) / 27


def _stable_root(s, sqrt):
    """sqrt((5 - t)(1 - t)) with both factors from s."""
    return sqrt(_f(s) * _m(s))


def _stable_n1(s, sqrt):
    """n_1 = 1 + (1-t)^3/(2(1+3t)) + (1-t)(1+t) sqrt((5-t)(1-t))/(2(1+3t)) (156), upper sign."""
    m, p = _m(s), _p(s)
    return 1 + m ** 3 / (2 * p) + m * _q(s) * _stable_root(s, sqrt) / (2 * p)


def _stable_z1(s, sqrt):
    """z_1 = (3/16){3 + t + sqrt((5-t)(1-t))} (158)."""
    return 3 * (3 + _t(s) + _stable_root(s, sqrt)) / 16


@dataclass(frozen=True)
class Form:
    """A discriminant quantity: its printed form and a stable rewriting, both generic in (s, sqrt)."""

    name: str
    locator: str
    printed: Callable
    stable: Callable
    both_sides: bool  # defined (real) for s < 23/32 as well

    def reference(self, s: float) -> mpmath.mpf:
        """The printed form at the exact value of the float s, to 50 significant digits: exact rational
        arithmetic (SymPy Rational) up to the square root, binary floats of 100 and of 150 digits from there on;
        the two must agree to 50 digits."""
        values = []
        for dps in (2 * REFERENCE_DIGITS, 3 * REFERENCE_DIGITS):
            with mpmath.workdps(dps):
                values.append(mpmath.mpf(sp.Float(self.printed(sp.Rational(s), _sqrt_at(dps)), dps)._mpf_))
        with mpmath.workdps(REFERENCE_DIGITS):
            if abs(values[0] - values[1]) > mpmath.mpf(10) ** -REFERENCE_DIGITS * abs(values[1]):
                raise ArithmeticError(f"{self.name} {self.locator}: no 50-digit reference at s = {s!r}")
            return +values[1]


def _sqrt_at(dps: int) -> Callable:
    """Square root of an exact Rational (or Float) as a SymPy Float of dps digits."""
    def sqrt(x):
        x = sp.Float(x, dps)
        if x < 0:
            raise ArithmeticError("negative radicand in an exact evaluation")
        return sp.Float(mpmath.sqrt(mpmath.mpf(x._mpf_)), dps)
    return sqrt


FORMS = (
    Form("1 - t", "(147), (154)", lambda s, r: 1 - _t(s), lambda s, r: _m(s), True),
    Form("1 + 3t", "(147), (150)", lambda s, r: 1 + 3 * _t(s), lambda s, r: _p(s), True),
    Form("S", "(151)", lambda s, r: _s151(s),
         lambda s, r: (3 + 3 * _t(s) + 3 * _t(s) ** 2 - _t(s) ** 3) / _p(s), True),
    Form("S - 2", "(154)", lambda s, r: (1 - _t(s)) ** 3 / (1 + 3 * _t(s)), lambda s, r: _m(s) ** 3 / _p(s), True),
    Form("S^2 - 4 from S", "(153) with (151)", lambda s, r: _s151(s) ** 2 - 4,
         lambda s, r: _f(s) * _q(s) ** 2 * _m(s) ** 3 / _p(s) ** 2, True),
    Form("S^2 - 4", "(154)",
         lambda s, r: (5 - _t(s)) * (1 + _t(s)) ** 2 * (1 - _t(s)) ** 3 / (1 + 3 * _t(s)) ** 2,
         lambda s, r: _f(s) * _q(s) ** 2 * _m(s) ** 3 / _p(s) ** 2, True),
    Form("n_1", "(153)", lambda s, r: (_s151(s) + _sq153(s, r)) / 2, _stable_n1, False),
    Form("n_1", "(156)",
         lambda s, r: (1 + (1 - _t(s)) ** 3 / (2 * (1 + 3 * _t(s)))
                       + (1 - _t(s) ** 2) / (2 * (1 + 3 * _t(s))) * _root154(s, r)),
         _stable_n1, False),
    Form("n_2", "(153)", lambda s, r: (_s151(s) - _sq153(s, r)) / 2, lambda s, r: 1 / _stable_n1(s, r), False),
    Form("z_1", "(155) with n₁ of (153)",
         lambda s, r: 3 * (1 + 3 * _t(s)) * ((_s151(s) + _sq153(s, r)) / 2 - _t(s)) / (8 * (1 - _t(s) ** 2)),
         _stable_z1, False),
    Form("z_1", "(158)", lambda s, r: 3 * (3 + _t(s) + _root154(s, r)) / 16, _stable_z1, False),
    Form("z_2", "(157), lower sign", lambda s, r: 3 * (3 + _t(s) - _root154(s, r)) / 16,
         lambda s, r: 3 * _p(s) / (4 * (3 + _t(s) + _stable_root(s, r))), False),
    Form("7 - 3t - 3 sqrt((5-t)(1-t))", "(160)", lambda s, r: 7 - 3 * _t(s) - 3 * _root154(s, r),
         lambda s, r: 4 * _p(s) / (7 - 3 * _t(s) + 3 * _stable_root(s, r)), False),
)


@dataclass(frozen=True)
class Row:
    """One row of the stiffness table."""

    form: str
    locator: str
    point: str       # the singular point approached: "s -> 23/32", "s -> 1", "s -> 119/128"
    s: float
    distance: float  # signed nominal distance s - point
    printed_error: float
    stable_error: float
    digits_lost: float  # by the printed form, log10(error / 2^-53), at least 0

    @property
    def catastrophic(self) -> bool:
        """More than 6 digits lost by the printed form."""
        return self.digits_lost > CATASTROPHIC_DIGITS


def sweep_points() -> list[tuple[str, float, float]]:
    """(point, s, signed distance): s -> 23/32 from both sides, s -> 1 from below, s -> 119/128 from both sides,
    distances 1e-1 ... 1e-15, s kept in the second rotation region 1/2 < s < 1."""
    pts = []
    for name, centre, sides in (("s -> 23/32", S_THRESHOLD, (1, -1)), ("s -> 1", sp.Integer(1), (-1,)),
                                ("s -> 119/128", S_T_ZERO, (1, -1))):
        for side in sides:
            pts += [(name, float(centre) + side * d, side * d) for d in DISTANCES
                    if 0.5 < float(centre) + side * d < 1]
    return pts


def float_sqrt(x: float) -> float:
    """math.sqrt, but NaN (no real value) where rounding made the radicand negative."""
    return math.sqrt(x) if x >= 0 else math.nan


def _relative_error(value: float, ref: mpmath.mpf) -> float:
    """|value - ref|/|ref|; infinite when the float64 evaluation gave no number."""
    if not math.isfinite(value):
        return math.inf
    with mpmath.workdps(REFERENCE_DIGITS):
        return float(abs((mpmath.mpf(value) - ref) / ref))


def _digits_lost(err: float) -> float:
    """log10(err/2^-53), between 0 and all 15.95 digits (err >= 1 leaves no correct digit)."""
    return math.log10(min(max(err, UNIT_ROUNDOFF), 1.0) / UNIT_ROUNDOFF)


def stiffness_table() -> list[Row]:
    """Relative errors of the float64 printed and stable forms against the 50-digit reference over the sweep."""
    rows = []
    for point, s, dist in sweep_points():
        below_threshold = s < float(S_THRESHOLD)
        for form in FORMS:
            if below_threshold and not form.both_sides:
                continue  # n, z are not real for s < 23/32 ((5 - t)(1 - t) < 0 there)
            ref = form.reference(s)
            pe = _relative_error(form.printed(s, float_sqrt), ref)
            se = _relative_error(form.stable(s, float_sqrt), ref)
            rows.append(Row(form.name, form.locator, point, s, dist, pe, se, _digits_lost(pe)))
    return rows


def worst_rows(rows: list[Row]) -> dict[tuple[str, str, str], Row]:
    """For every form and singular point, the row where the printed form loses most digits."""
    out: dict[tuple[str, str, str], Row] = {}
    for r in rows:
        key = (r.form, r.locator, r.point)
        if key not in out or r.digits_lost > out[key].digits_lost:
            out[key] = r
    return out


def table_markdown(rows: list[Row] | None = None) -> str:
    """The stiffness table as Markdown: a summary per form, then every row."""
    rows = stiffness_table() if rows is None else rows
    lines = ["| form | locator | point | worst $s$ | distance | printed rel. error | stable rel. error | digits lost |",
             "|---|---|---|---|---|---|---|---|"]
    for r in worst_rows(rows).values():
        lines.append(_md_row(r))
    worst = max(r.stable_error for r in rows)
    lines += ["", f"Max relative error of the stable forms over the sweep: {scientific(worst, 3)}.",
              rf"Digits lost = $\log_{{10}}$(error / $2^{{-53}}$); more than {CATASTROPHIC_DIGITS:g} is flagged "
              r"**catastrophic**; an error ∞ means the float64 radicand $S^2 - 4$ rounded negative (no real value, "
              "all digits lost).",
              "", "| form | locator | point | $s$ | distance | printed rel. error | stable rel. error | digits lost |",
              "|---|---|---|---|---|---|---|---|"]
    lines += [_md_row(r) for r in rows]
    return "\n".join(lines) + "\n"


def _md_row(r: Row) -> str:
    flag = " **catastrophic**" if r.catastrophic else ""
    form = f"${r.form}$" if len(r.form) == 1 else typeset(r.form)        # S, n_1, 1 - t: typeset
    return (f"| {inline(form, None, cell=True)} | {r.locator} | {inline(typeset(r.point), None, cell=True)} "
            f"| {written(r.s)} | {'+' if r.distance > 0 else ''}{scientific(r.distance, 1)} | "
            f"{scientific(r.printed_error, 3)} | {scientific(r.stable_error, 3)} | {r.digits_lost:.1f}{flag} |")
