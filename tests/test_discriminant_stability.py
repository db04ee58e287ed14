"""Numerical stability of the discriminant closed forms of Scheeffer IX (source 000_1e9760952686f295, "## IX.",
(146)-(160)): symfloat/numerics/discriminant.py.

Provenance: sigma = 1 - s (before (136)), t = (128 sigma - 9)/27 (147) = (119 - 128 s)/27 (after (160)),
128 sigma = 9(1 + 3t) (150), S (151), S -+ 2 and S^2 - 4 (154), n_1, n_2 (153), n (156), z (155), z_1 (158),
z_2 (157, lower sign), the margin 7 - 3t - 3 sqrt((5-t)(1-t)) of (160).  The singular points are t = 1
(s = 23/32, the threshold (140)), t = -1/3 (s = 1) and t = 0 (s = 119/128, the factor 1/t of (151)).
The digit losses pinned below were measured by stiffness_table() (float64 against the 50-digit reference).
"""
import math

import pytest
import sympy as sp

from symfloat.numerics import discriminant as D


@pytest.fixture(scope="module")
def rows():
    return D.stiffness_table()


@pytest.fixture(scope="module")
def worst(rows):
    return D.worst_rows(rows)


def test_sweep_covers_both_singular_points():
    pts = D.sweep_points()
    for point, sides in (("s -> 23/32", (1, -1)), ("s -> 1", (-1,))):
        got = sorted(d for p, _, d in pts if p == point)
        assert got == sorted(side * 10.0 ** -k for side in sides for k in range(1, 16))
    assert all(0.5 < s < 1 for _, s, _ in pts)


def test_stable_forms_match_the_50_digit_reference(rows):
    # every form, every point of the sweep (23/32 +- 1e-1 ... 1e-15, 1 - 1e-1 ... 1e-15, 119/128 +- ...)
    assert len(rows) > 800
    worst_stable = max(r.stable_error for r in rows)
    assert math.isfinite(worst_stable) and worst_stable < 1e-13
    assert worst_stable < 1e-15  # measured: 7.5e-16 (a few units of roundoff)


@pytest.mark.parametrize("form, locator, point, lost", [
    # s -> 23/32 (t -> 1): 1 - t from the float t, and everything built on it
    ("1 - t", "(147), (154)", "s -> 23/32", 13.5),            # measured 14.1 at s - 23/32 = -1e-15
    ("S - 2", "(154)", "s -> 23/32", 13.5),                   # measured 14.6
    ("S^2 - 4", "(154)", "s -> 23/32", 13.5),                 # measured 14.6
    ("S^2 - 4 from S", "(153) with (151)", "s -> 23/32", 15.9),  # radicand rounds negative at +1e-6: nothing left
    ("n_1", "(153)", "s -> 23/32", 15.9),                     # sqrt(S^2 - 4) is NaN at +1e-6; 7.1 digits at +1e-5
    ("n_2", "(153)", "s -> 23/32", 15.9),
    ("z_1", "(155) with n₁ of (153)", "s -> 23/32", 15.9),   # 0/0 of (155) at t = 1
    ("z_1", "(158)", "s -> 23/32", 6.0),                      # measured 6.1 at +1e-15 (sqrt of a lost 1 - t)
    # s -> 1 (t -> -1/3): 1 + 3t from the float t
    ("1 + 3t", "(147), (150)", "s -> 1", 10.5),               # measured 11.2 at 1 - s = 1e-13
    ("S", "(151)", "s -> 1", 10.5),                           # measured 11.2
    ("n_1", "(153)", "s -> 1", 10.5),                         # measured 11.2
    ("n_1", "(156)", "s -> 1", 10.5),                         # measured 11.2
    ("n_2", "(153)", "s -> 1", 15.9),                         # S - sqrt(S^2 - 4) = 0 for 1 - s <= 1e-9
    ("z_2", "(157), lower sign", "s -> 1", 12.0),             # measured 12.4
    ("7 - 3t - 3 sqrt((5-t)(1-t))", "(160)", "s -> 1", 12.5),  # measured 13.0
    # s -> 119/128 (t -> 0): the removable 1/t of (151)
    ("S", "(151)", "s -> 119/128", 10.5),                     # measured 11.2 at +1e-13
    ("n_1", "(153)", "s -> 119/128", 10.5),                   # measured 11.3
])
def test_printed_forms_lose_digits(worst, form, locator, point, lost):
    r = worst[(form, locator, point)]
    assert r.digits_lost > lost and r.catastrophic
    assert r.stable_error < 1e-15


def test_stiffness_is_local(worst):
    # away from their own singular factor the printed forms are fine: (156) is benign at t -> 1 (n_1 -> 1 absorbs
    # the lost 1 - t), (158) at t -> -1/3, 1 - t at s -> 1
    assert worst[("n_1", "(156)", "s -> 23/32")].digits_lost < 1
    assert worst[("z_1", "(158)", "s -> 1")].digits_lost < 1
    assert worst[("1 - t", "(147), (154)", "s -> 1")].digits_lost < 1


def test_n1_153_loses_about_half_the_digits_before_failing(rows):
    # (153) near t = 1: sqrt(S^2 - 4) of a cancelled S^2 - 4 ~ (1-t)^3 keeps about sqrt(eps): 7.1 digits lost at
    # s - 23/32 = 1e-5, NaN at 1e-6 (S rounded below 2), then n_1 = 1 to float precision anyway
    by_d = {r.distance: r for r in rows if (r.form, r.locator, r.point) == ("n_1", "(153)", "s -> 23/32")}
    assert by_d[1e-5].digits_lost > 6.5
    assert math.isinf(by_d[1e-6].printed_error)
    assert by_d[1e-12].digits_lost < 1


@pytest.mark.parametrize("s", [0.85, 0.9])  # S^2 - 4 from S already cancels 2 digits at s = 0.8
def test_printed_and_stable_agree_at_benign_points(s):
    for form in D.FORMS:
        p, q = form.printed(s, math.sqrt), form.stable(s, math.sqrt)
        assert abs(p - q) <= 1e-14 * abs(q), (form.name, form.locator, s)


SYM_S = sp.Symbol("s", positive=True)


@pytest.mark.parametrize("form", [f for f in D.FORMS if f.both_sides], ids=lambda f: f"{f.name} {f.locator}")
def test_rational_rewritings_are_identities(form):
    # 1 - t, 1 + 3t, S, S - 2, S^2 - 4 are rational in s: the rewriting is an identity of rational functions
    assert sp.cancel(form.printed(SYM_S, sp.sqrt) - form.stable(SYM_S, sp.sqrt)) == 0


@pytest.mark.parametrize("form", D.FORMS, ids=lambda f: f"{f.name} {f.locator}")
@pytest.mark.parametrize("s", [sp.Rational(3, 4), sp.Rational(4, 5), sp.Rational(119, 128) + sp.Rational(1, 1000),
                               sp.Rational(19, 20)])
def test_rewritings_are_exact_at_rational_points(form, s):
    # exact algebraic numbers: the difference has minimal polynomial X, i.e. it is 0
    X = sp.Symbol("X")
    assert sp.minimal_polynomial(form.printed(s, sp.sqrt) - form.stable(s, sp.sqrt), X) == X


def test_reference_is_independent_of_the_route():
    # two different exact printed expressions of n_1, (153) and (156), give the same 50-digit number at the
    # stiff points; the reference of the rational S equals the exact rational value of (151)
    n153, n156 = [f for f in D.FORMS if f.name == "n_1"]
    for s in (float(sp.Rational(23, 32)) + 1e-12, 1 - 1e-14, float(sp.Rational(119, 128)) + 1e-15):
        a, b = n153.reference(s), n156.reference(s)
        assert abs(a - b) <= 1e-48 * abs(b)
    s = 1 - 1e-13
    t = (119 - 128 * sp.Rational(s)) / 27
    exact = (1 + t ** 2 - (1 - t ** 2) ** 2 / (1 + 3 * t)) / t
    S = next(f for f in D.FORMS if f.locator == "(151)")
    assert abs(sp.Float(S.reference(s), 50) - exact) < sp.Float(10) ** -48 * abs(exact)


def test_markdown_table(rows):
    md = D.table_markdown(rows)
    lines = md.splitlines()
    assert lines[0].startswith("| form | locator | point |")
    assert "**catastrophic**" in md and "Max relative error of the stable forms" in md
    table_lines = [line for line in lines if line.startswith("| ") and "|---" not in line]
    assert len(table_lines) == len(rows) + len(D.worst_rows(rows)) + 2
