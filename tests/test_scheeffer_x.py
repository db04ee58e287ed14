"""Scheeffer 1902, X (the floating cube): the module checks clean, its errata are exactly the expected ones,
every display and every equation number of the range is quoted, the claims are tested on the clipped
cube by an independent search for all equilibria (roots of the gradient of the potential over
orientations, classified by the Hessian), the predictor is compared with that search, and a mutated print
is refuted."""
import dataclasses
import math
import re
from fractions import Fraction

import mpmath
import numpy as np
import pytest
import sympy as sp

from symfloat.engine.cache import ReportCache
from symfloat.engine.check import check_derivation
from symfloat.engine.runner import verify
from symfloat.geometry.floating import box, floating_state, submerged
from symfloat import Holds
from symfloat.model.prediction import Scene
from symfloat.model.source import SOURCES
from symfloat.registry import load

D, MODULE = load("scheeffer-x")
STATEMENTS, PREDICTORS = MODULE.statements, MODULE.predictors
TEXT = SOURCES["scheeffer"].text()
RANGE = TEXT[TEXT.index("## X."):TEXT.index("#### Druckfehler.")]
CUBE = box(1, 1, 1)


@pytest.fixture(scope="module")
def report(cache_dir):
    return verify("scheeffer-x", cache=ReportCache(cache_dir))[-1]


def test_no_check_fails(report):
    assert report.failures == []


def test_every_display_of_the_range_is_quoted():
    displays = re.findall(r"\$\$.+?\$\$", RANGE, re.S)
    assert len(displays) >= 25
    missing = [x for x in displays if not any(x in p.excerpt or p.excerpt in x for p in D.printed)]
    assert missing == []


def test_every_equation_number_is_quoted_and_none_is_lacking():
    tags = re.findall(r"\((1\d\d[ab]?)\)", RANGE)
    expected = ["167", "168", "169", "169a", "169b", "170", "171", "172", "173", "174", "175"]
    assert sorted(set(tags)) == expected          # the transcription lacks none of 167..175
    quoted = {t for p in D.printed for t in re.findall(r"\((1\d\d[ab]?)\)", p.excerpt)}
    assert quoted == set(expected)


EXPECTED_ERRATA = {
    ("pentagon-exists", "claim", "high"),        # below s = 0.7623 the root of (171) is a hexagon, no pentagon
    ("pentagon-stable", "claim", "medium"),      # of two pentagonal equilibria one is unstable
    ("dual-exists", "consequential", "high"),    # the same for s < 1/2
    ("104-reference", "misprint", "medium"),     # transcription line 1817: 'in 104 ein' for (167)
    ("fig19-reference", "misprint", "low"),      # line 1833: '(s. Fig. 19)', the waterplane of VII, for Fig. 23
    ("heading", "misprint", "medium"),           # line 1779 and the contents, line 1947: 'Gewichtslagen'
}


def test_the_errata_are_exactly_the_expected_ones(report):
    found = {(f.id.split("/")[1], f.erratum["kind"], f.erratum["confidence"])
             for f in report.formulas if f.verdict == "erratum"}
    assert found == EXPECTED_ERRATA
    assert all(f.verdict in ("verified", "erratum") for f in report.formulas)


def _decided(records) -> bool:
    """Whether every certified record among *records* decided (agrees or refuted): a check then measures only
    the cheapest method beside the ball (symfloat/engine/witness.py)."""
    from symfloat.engine.witness import CERTIFIED, record_decision
    return all(record_decision(r) != "undecided" for r in records if r["method"] == CERTIFIED)


def test_numeric_displays_carry_witness_records_at_both_precisions(report):
    witnessed = {"HPB", "GPB", "167-sum", "167", "u", "v", "168", "area", "170", "171", "172-number", "98",
                 "diagonal-claim", "hex-follows", "118-form", "173-only-45",
                 "173", "174", "tetra", "five-sixths", "tri-unstable", "hex-half", "pentagon-exists",
                 "pentagon-stable", "dual-exists"}
    by = {f.id.split("/")[1]: f for f in report.formulas}
    for name in witnessed:
        methods = {r["method"] for r in by[name].numeric}
        if "Arb ball arithmetic" in methods and _decided(by[name].numeric):
            assert methods == {"Arb ball arithmetic", "float64"}, name    # the ball decides; float64 beside it
        else:
            assert methods - {"Arb ball arithmetic"} in ({"float64", "mpmath, 50 digits"},
                                                         {"float64", "mpmath, 40 digits"}), name
    for name in ("168", "171", "173"):
        assert max(r["rel_error"] for r in by[name].numeric if r["method"] == "float64") < 1e-10
        # the ball's decision: the reading within what it resolves at 128 bits (171, a root, about 1e-29)
        assert max(r["rel_error"] for r in by[name].numeric if r["method"] == "Arb ball arithmetic") < 1e-28


# ---- the clipped cube: gradient, Hessian, all equilibria -------------------------------------------------

def _up(ab):
    n = math.sqrt(ab[0] ** 2 + ab[1] ** 2 + 1)
    return (ab[0] / n, ab[1] / n, 1 / n)


def _grad(ab, s):
    """Gradient of the clipped potential u.(G - B) in the chart u ~ (a, b, 1): (du/da).(G - B), (du/db).(G - B)."""
    a, b = ab
    n = math.sqrt(a * a + b * b + 1)
    st = floating_state(CUBE, _up(ab), s)
    g = [st.G[i] - st.B[i] for i in range(3)]
    du_a = (1 / n - a * a / n ** 3, -a * b / n ** 3, -a / n ** 3)
    du_b = (-a * b / n ** 3, 1 / n - b * b / n ** 3, -b / n ** 3)
    return np.array([sum(du_a[i] * g[i] for i in range(3)), sum(du_b[i] * g[i] for i in range(3))])


def _hessian(ab, s, h=1e-6):
    cols = [(_grad(np.add(ab, dv), s) - _grad(np.subtract(ab, dv), s)) / (2 * h) for dv in ((h, 0), (0, h))]
    J = np.column_stack(cols)
    return (J + J.T) / 2


def _vertices(u, s):
    st = floating_state(CUBE, u, s)
    pts = []
    for p in submerged(CUBE, st.u, st.t).waterplane.polygon:
        if all(max(abs(p[i] - q[i]) for i in range(3)) > 1e-7 for q in pts):
            pts.append(p)
    return len(pts)


def _canonical(ab):
    """The representative with 0 <= a <= b <= 1 under the 48 symmetries of the cube (E(u) = E(-u) too)."""
    c = sorted(abs(v) for v in (ab[0], ab[1], 1.0))
    return (c[0] / c[2], c[1] / c[2])


def _newton(ab, s):
    x = np.array(ab, float)
    for _ in range(40):
        g = _grad(x, s)
        try:
            dx = np.linalg.solve(_hessian(x, s), -g)
        except np.linalg.LinAlgError:
            return None
        if np.linalg.norm(dx) > 0.2:
            dx *= 0.2 / np.linalg.norm(dx)
        x = x + dx
        if np.linalg.norm(dx) < 1e-12:
            break
    return x if np.linalg.norm(_grad(x, s)) < 1e-10 else None


def equilibria(s, grid=8):
    """All equilibria of the clipped cube at density s found from a grid of starts over the fundamental domain:
    [(a, b) canonical, vertices of the waterplane, Hessian eigenvalues]."""
    found = []
    for i in range(grid + 1):
        for j in range(i, grid + 1):
            x = _newton((i / grid + 0.013, j / grid + 0.021), s)
            if x is None:
                continue
            c = _canonical(x)
            if any(abs(c[0] - f[0][0]) < 1e-6 and abs(c[1] - f[0][1]) < 1e-6 for f in found):
                continue
            found.append((c, _vertices(_up(c), s), np.linalg.eigvalsh(_hessian(c, s))))
    return found


@pytest.fixture(scope="module")
def eq077():
    return equilibria(0.77)


def test_potential_derivative_is_the_tangential_part_of_G_minus_B():
    # the assumption behind the witnesses: dE along a turn of u is (du).(G - B) (u.dB = 0), against a
    # central difference quotient of the clipped potential
    for ab, s in (((0.3, 0.25), 0.77), ((0.8, 0.5), 0.6), ((1.0, 0.95), 0.9)):
        h = 1e-6
        fd = [(floating_state(CUBE, _up(np.add(ab, dv)), s).potential
               - floating_state(CUBE, _up(np.subtract(ab, dv)), s).potential) / (2 * h) for dv in ((h, 0), (0, h))]
        assert np.allclose(fd, _grad(ab, s), atol=1e-8)


# fold of (171): f = df/dx = 0, solved with mpmath from the printed (171) itself (independent of the clipped
# cube); below it (171) has no root with a pentagonal waterplane
S_FOLD = 0.7623092388663755


def test_the_fold_of_171_where_the_pentagonal_equilibria_are_born():
    f = PREDICTORS.f_num
    mpmath.mp.dps = 30
    x0, s0 = mpmath.findroot(lambda x, s: [f(x, s), mpmath.diff(lambda t: f(t, s), x)], (0.36, 0.762))
    assert abs(float(s0) - S_FOLD) < 1e-12 and abs(float(x0) - 0.3581293505777) < 1e-10
    assert STATEMENTS.beta(float(x0), float(s0)) < 1            # the fold itself is pentagonal
    # the clipped cube, diagonal plane: no pentagonal equilibrium just below, two just above
    below, above = _diagonal_roots(S_FOLD - 0.002), _diagonal_roots(S_FOLD + 0.002)
    assert [nv for _, nv in below] == [6] and [nv for _, nv in above] == [5, 5, 6]


def _diagonal_roots(s):
    """Equilibria of the clipped cube in the diagonal plane u ~ (-p, -p, 1), 0 < p < 1 (sign changes of the
    gradient on a grid of tilts up to the corner-up position), with the vertices of their waterplanes."""
    def g(th):
        return _grad((-math.tan(th) / math.sqrt(2),) * 2, s)[0]
    ths = [0.02 * j for j in range(1, 48)] + [math.atan(math.sqrt(2)) + 0.01]
    vals = [g(t) for t in ths]
    out = []
    for t, t2, v, w in zip(ths, ths[1:], vals, vals[1:]):
        if (v > 0) != (w > 0):
            lo, hi = t, t2
            for _ in range(45):
                m = (lo + hi) / 2
                lo, hi = (m, hi) if (g(m) > 0) == (v > 0) else (lo, m)
            out.append((m, _vertices(_up((-math.tan(m) / math.sqrt(2),) * 2), s)))
    return out


def test_pentagonal_equilibria_up_to_five_sixths_are_unstable():
    # above 0.7735 one pentagonal equilibrium (the roots of (171) with beta < 1), unstable, up to s = 5/6
    for s in (0.8, 0.82):
        pent = [t for t, nv in _diagonal_roots(s) if nv == 5]
        assert len(pent) == 1
        c = (-math.tan(pent[0]) / math.sqrt(2),) * 2
        assert min(np.linalg.eigvalsh(_hessian(c, s))) < 0
    assert not any(nv == 5 for _, nv in _diagonal_roots(0.84))


def test_the_waterplane_is_a_triangle_quadrilateral_pentagon_or_hexagon():
    # 'kann der Wasserschnitt ein Fünfeck, Dreieck, Sechseck, Trapez sein': all shapes occur, no other
    rng = np.random.default_rng(10)
    counts = {_vertices(tuple(rng.normal(size=3)), float(rng.uniform(0.05, 0.95))) for _ in range(400)}
    assert counts == {3, 4, 5, 6}


def test_pentagonal_equilibria_at_077_are_the_roots_of_171(eq077):
    # (171) at s = 0.77: roots 0.0858 and 0.5684 with beta < 1 (pentagons), 0.8768 with beta > 1
    xs = [float(r) for r in STATEMENTS.roots_171(sp.Rational(77, 100))]
    assert [round(v, 4) for v in xs] == [0.0858, 0.5684, 0.8768]
    pent = sorted(((c, ev) for c, nv, ev in eq077 if nv == 5 and abs(c[0] - c[1]) < 1e-6), key=lambda q: q[0][0])
    assert len(pent) == 2
    for (c, ev), xr in zip(pent, xs[:2]):
        p = 0.23 / (1 - xr + xr ** 3 / 6)                  # u ~ (-p, -p, 1): the orientation (171) prescribes
        assert abs(c[0] - p) < 1e-7
    assert all(ev > 0 for ev in pent[0][1])                 # the small leg: stable
    assert min(pent[1][1]) < 0                              # the other: unstable (the claim's exception)
    assert STATEMENTS.beta(xs[2], 0.77) > 1


def test_no_pentagonal_equilibrium_where_the_text_promises_one():
    # s = 3/5: upright unstable (s < 0.7887), no oblique position in the first domain (s < 0.7735); the only root
    # of (171) is x = 0.5498 with beta = 1.214: its orientation has a hexagonal waterplane and is no equilibrium
    eq = equilibria(0.6)
    assert not any(nv == 5 for _, nv, _ in eq)
    stable = [(c, nv) for c, nv, ev in eq if all(ev > 0)]
    assert len(stable) == 1 and stable[0][1] == 6 and np.allclose(stable[0][0], (1, 1))   # the corner up
    xr = float(STATEMENTS.X_COUNTER)
    assert abs(xr - 0.5498088) < 1e-6 and abs(STATEMENTS.beta(xr, 0.6) - 1.2138) < 1e-4
    p = 0.4 / (1 - xr + xr ** 3 / 6)
    assert _vertices(_up((-p, -p)), 0.6) == 6
    assert np.linalg.norm(_grad((-p, -p), 0.6)) > 1e-3


@pytest.mark.parametrize("s", [0.55, 0.7, 0.8])
def test_hexagonal_equilibria_lie_across_a_diagonal(s):
    eq = equilibria(s)
    hexa = [c for c, nv, _ in eq if nv == 6]
    assert hexa and all(np.allclose(c, (1, 1), atol=1e-7) for c in hexa)


def test_triangular_waterplane_symmetric_and_unstable():
    for s in (0.85, 0.9, 0.95):
        eq = equilibria(s, grid=6)
        tri = [(c, ev) for c, nv, ev in eq if nv == 3]
        assert len(tri) == 1 and np.allclose(tri[0][0], (1, 1), atol=1e-7) and max(tri[0][1]) < 0
        # the derived metacentric height sqrt3 L^3 (L - 1)/(12 s), L^3 = 6 (1 - s), against the clipped one
        L = (6 * (1 - s)) ** (1 / 3)
        gm = floating_state(CUBE, (1, 1, 1), s).metacentric_height
        assert abs(gm - math.sqrt(3) * L ** 3 * (L - 1) / (12 * s)) < 1e-12


def test_the_regular_hexagon_at_one_half():
    st = floating_state(CUBE, (1, 1, 1), 0.5)
    assert abs(st.metacentric_height - math.sqrt(3) / 48) < 1e-13        # hex-GM
    assert _vertices((1, 1, 1), 0.5) == 6
    poly = submerged(CUBE, st.u, st.t).waterplane.polygon
    sides = [math.dist(poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly))]
    assert max(sides) - min(sides) < 1e-12 and abs(sides[0] - 1 / math.sqrt(2)) < 1e-12
    assert all(ev > 0 for ev in np.linalg.eigvalsh(_hessian((1.0, 1.0), 0.5)))


def test_first_condition_off_the_diagonal_has_the_sign_of_cos_minus_sin():
    # the clipped dry moment across the axis for a triangle cut at omega != 45 deg (sign-of-P)
    from symfloat.engine.witness import Case
    witness = next(w_ for w_ in D.witnesses if w_.name == "dry-moment")
    for w in ("0.2", "0.5", "0.7", "0.9", "1.2"):
        case = Case({STATEMENTS.a: 1, STATEMENTS.om: sp.Rational(w), STATEMENTS.rho: sp.Rational(2, 5)})
        m = witness.measure(case, witness.methods[0])
        assert (m > 0) == (math.cos(float(w)) > math.sin(float(w)))


# ---- the predictor ---------------------------------------------------------------------------------------

def _scene(s):
    return Scene("cube", Fraction(s), (Fraction(1),) * 3)


def test_predictor_speaks_only_about_cubes():
    for s in ("1/10", "2/5", "1/2", "77/100", "9/10"):
        assert PREDICTORS.predict(_scene(s))
    assert PREDICTORS.predict(Scene("box", Fraction(1, 2), (Fraction(1), Fraction(2), Fraction(1)))) == []
    assert PREDICTORS.predict(Scene("box", Fraction(1, 2), (Fraction(2),) * 3))


def test_predictions_against_the_clipped_cube():
    names = {p.name for p in D.printed}
    # s = 0.77: three roots of (171) predicted stable; the first is a stable equilibrium, the second an
    # unstable one, the third no equilibrium at all (beta > 1)
    preds = [p for p in PREDICTORS.predict(_scene("77/100")) if "171" in p.printed]
    assert all(set(p.printed) <= names for p in PREDICTORS.predict(_scene("77/100")))
    assert [p.stability for p in preds] == ["stable"] * 3
    ab = [(p.up[0] / p.up[2], p.up[1] / p.up[2]) for p in preds]
    assert np.linalg.norm(_grad(ab[0], 0.77)) < 1e-9 and all(np.linalg.eigvalsh(_hessian(ab[0], 0.77)) > 0)
    assert np.linalg.norm(_grad(ab[1], 0.77)) < 1e-9 and min(np.linalg.eigvalsh(_hessian(ab[1], 0.77))) < 0
    assert np.linalg.norm(_grad(ab[2], 0.77)) > 1e-5       # 5.8e-5: near, but not at, the corner-up position
    # s = 2/5 (dual): the predicted pentagon is no equilibrium
    pent = [p for p in PREDICTORS.predict(_scene("2/5")) if "171" in p.printed]
    assert len(pent) == 1 and np.linalg.norm(_grad((pent[0].up[0] / pent[0].up[2], pent[0].up[1] / pent[0].up[2]),
                                                   0.4)) > 1e-3
    # s = 9/10: the triangle, unstable; s = 1/2: the regular hexagon, stable
    (tri,) = PREDICTORS.predict(_scene("9/10"))
    assert tri.stability == "unstable" and max(np.linalg.eigvalsh(_hessian((1.0, 1.0), 0.9))) < 0
    (hexa,) = PREDICTORS.predict(_scene("1/2"))
    assert hexa.stability == "stable" and np.linalg.norm(_grad((1.0, 1.0), 0.5)) < 1e-12


# ---- the engine refutes a mutated print -------------------------------------------------------------------

def test_a_mutated_coefficient_of_168_is_refuted():
    # (168) with the divisor 24 mutated to 12
    m = STATEMENTS
    p = next(q for q in D.printed if q.name == "168")
    wrong = (m.P, m.h_ ** 3 * (m.co - m.si) / (12 * m.si * m.co ** 2) * (2 * m.a * m.co - m.rho * (m.co + m.si)))
    dm = dataclasses.replace(D, printed=[dataclasses.replace(p, reading=wrong)], witnesses=[])
    rep = check_derivation(dm, prove=False, trust_steps=True)
    assert rep.formulas[0].verdict == "erratum"
    assert any("168" in f and "no erratum" in f for f in rep.failures)


def test_each_root_of_171_is_an_equilibrium_exactly_when_its_waterplane_is_a_pentagon():
    # every root 0 < x < 1 of (171) on a grid of densities: at the orientation it prescribes, u ~ (-p, -p, 1),
    # p = (1 - s)/z, the clipped waterplane is a pentagon iff beta < 1, and only then is the gradient zero
    seen = {True: 0, False: 0}
    for s in [k / 100 for k in range(52, 84)] + [0.7625 + 0.002 * j for j in range(6)]:
        for xr in PREDICTORS._roots_171_float(s):
            p = (1 - s) / (1 - xr + xr ** 3 / 6)
            pent = STATEMENTS.beta(xr, s) < 1
            assert (_vertices(_up((-p, -p)), s) == 5) == pent
            assert (np.linalg.norm(_grad((-p, -p), s)) < 1e-9) == pent
            seen[pent] += 1
    assert seen[True] >= 18 and seen[False] >= 30


@pytest.mark.parametrize("s", [0.7635, 0.765, 0.773])
def test_between_the_fold_and_0_7735_the_small_leg_pentagon_is_stable_the_other_not(s):
    pent = [t for t, nv in _diagonal_roots(s) if nv == 5]
    assert len(pent) == 2
    small, large = ((-math.tan(t) / math.sqrt(2),) * 2 for t in sorted(pent))
    small, large = (_newton(c, s) for c in (small, large))     # refine to the equilibria
    assert min(np.linalg.eigvalsh(_hessian(small, s))) > 0
    assert min(np.linalg.eigvalsh(_hessian(large, s))) < 0


def test_the_104_reference_is_an_erratum_on_its_own():
    # transcription line 1817, 'Setzt man diese Werte in 104 ein': u, v go into (167), which gives (168)
    p = next(q for q in D.printed if q.name == "104-reference")
    rep = check_derivation(dataclasses.replace(D, printed=[p], witnesses=[]), prove=False, trust_steps=True)
    (f,) = rep.formulas
    assert f.verdict == "erratum" and rep.failures == []
    assert (f.erratum["kind"], f.erratum["confidence"]) == ("misprint", "medium")


# ---- (172) read as a root count -----------------------------------------------------------------------------
def _poly_171(sv):
    """(171) as printed (transcription line 1853: 2T = 1/6 + (1-x)^2 - x^4/12, z = 1 - x + x^3/6), left minus
    right side times 432, at the density sv: typed here from the print, not taken from the module."""
    xx = sp.Symbol("x")
    two_t, z = sp.Rational(1, 6) + (1 - xx) ** 2 - xx ** 4 / 12, 1 - xx + xx ** 3 / 6
    return sp.Poly(sp.expand(432 * (two_t * (z ** 2 + (1 - sv) ** 2) - z ** 3 * (1 - xx) - z ** 2 * (1 - sv))), xx)


# s -> number of distinct roots in 0 < x < 1 (SymPy's exact isolation; the same counts as numpy's eigenvalue roots
# below): one up to the fold 0.7623, three up to (4 + sqrt 2)/7 = 0.77346, two up to 5/6, none beyond
COUNTS_171 = {"1/2": 1, "7/10": 1, "0.762": 1, "0.763": 3, "0.77": 3, "0.773": 3, "0.774": 2, "0.8": 2,
              "0.833": 2, "0.834": 0}


@pytest.mark.parametrize("sv, count", sorted(COUNTS_171.items()))
def test_root_counts_of_171(sv, count):
    poly = _poly_171(sp.Rational(sv))
    exact = sorted({r for r in poly.real_roots() if 0 < r < 1}, key=float)
    assert len(exact) == count
    companion = [r.real for r in np.roots([float(c) for c in poly.all_coeffs()])
                 if abs(r.imag) < 1e-9 and 1e-9 < r.real < 1 - 1e-9]
    assert len(companion) == count


def test_the_fold_of_171_lies_between_0_7623_and_0_7624():
    # the count jumps where f and df/dx vanish together: a root of the resultant in x, between 0.7623 and 0.7624
    s_ = sp.Symbol("s")
    xx_ = _poly_171(s_).gens[0]
    f = _poly_171(s_).as_expr()
    res = sp.Poly(sp.resultant(f, sp.diff(f, xx_), xx_), s_)
    assert res.count_roots(sp.Rational("0.7623"), sp.Rational("0.7624")) == 1
    assert res.count_roots(sp.Rational("0.7624"), sp.Rational("0.7734")) == 0     # (4 + sqrt 2)/7 = 0.77346


def _checked_172(reading=None):
    p = next(q for q in D.printed if q.name == "172")
    p = p if reading is None else dataclasses.replace(p, reading=reading)
    rep = check_derivation(dataclasses.replace(D, printed=[p], witnesses=[]), prove=False, trust_steps=True)
    (f,) = rep.formulas
    return f, rep.failures


def test_172_is_an_existence_statement_verified_as_printed():
    # transcription lines 1857-1859: 'eine reelle Wurzel, wenn s < (4 + sqrt 2)/7': a real root, which (171) has on
    # 1/2 < s < 0.7735 (one, or three between the fold and the bound); read as 'exactly one' it would fail there
    f, failures = _checked_172()
    assert f.verdict == "verified" and failures == [] and f.erratum is None
    s, count = STATEMENTS.s, STATEMENTS.COUNT_171(0, 1)
    exactly_one = Holds(sp.Implies(s < STATEMENTS.s172, sp.Eq(count, 1)), {s: (sp.Rational(1, 2), 1)})
    f, failures = _checked_172(exactly_one)
    assert f.verdict == "erratum" and any("no erratum" in x for x in failures)
    point = sp.Rational(f.identity["counterexample"]["point"]["s"])       # where 'one' fails: three roots
    assert sp.Rational("0.7623") < point < (4 + sp.sqrt(2)) / 7


def test_the_172_root_counts_are_counted_again_numerically():
    # the definition route counts the roots of (171) from its coefficients' values (polyroots and inclusion
    # discs) at seeded densities: the counts agree with Sturm's
    f, failures = _checked_172()
    assert failures == [] and f.numeric_content
    methods = [f"root count, polyroots and inclusion discs, {n} digits" for n in (15, 30)]
    assert [r["method"] for r in f.numeric] == methods
    assert all(r["abs_error"] == 0 and r["cases"] >= 3 for r in f.numeric)


def test_an_existence_bound_beyond_five_sixths_is_refuted():
    # (171) has no root in 0 < x < 1 from s = 5/6 on (f(1) = (5 - 6s)^2/432, COUNTS_171 at 0.834): a root
    # promised up to s = 9/10 must fail
    s, count = STATEMENTS.s, STATEMENTS.COUNT_171(0, 1)
    f, failures = _checked_172(
        Holds(sp.Implies(s < sp.Rational(9, 10), count >= 1), {s: (sp.Rational(1, 2), 1)}))
    assert f.verdict == "erratum" and any("no erratum" in x for x in failures)


def test_the_heading_word_is_one_erratum_with_its_contents_line():
    # transcription line 1779 '### Die Gewichtslagen eines schwimmenden Würfels.' and the contents, line 1947; the
    # text says 'Gleichgewichtslage' 56 times (counted here), 'Gewichtslage' nowhere else
    p = next(q for q in D.printed if q.name == "heading")
    assert (p.erratum.fault, p.erratum.places) == ("Gewichtslagen", ("Inhalt",))
    assert [i + 1 for i, line in enumerate(TEXT.splitlines()) if "Gewichtslage" in line] == [1779, 1947]
    assert TEXT.count("Gleichgewichtslage") == 56
    rep = check_derivation(dataclasses.replace(D, printed=[p], witnesses=[]), prove=False, trust_steps=True)
    (f,) = rep.formulas
    assert f.verdict == "erratum" and rep.failures == []
    kept = dataclasses.replace(p.erratum, corrected_reading=p.reading)      # 'positions of the weight' kept
    rep = check_derivation(dataclasses.replace(D, printed=[dataclasses.replace(p, erratum=kept)], witnesses=[]),
                           prove=False, trust_steps=True)
    assert any("correction does not hold" in x for x in rep.failures)
