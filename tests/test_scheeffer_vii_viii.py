"""Scheeffer 1902, VII and VIII (derivation ``scheeffer-vii-viii``): verdicts and errata, coverage of (95)-(122),
the designed and the root-found equilibria on the clipped prisms, the claims in words, and mutated prints that
the engine must refute."""
import dataclasses
import math
import re
from fractions import Fraction

import pytest
import sympy as sp

from symfloat.derivations.scheeffer_vii_viii import predictors as PREDICTORS
from symfloat.derivations.scheeffer_vii_viii import statements as STATEMENTS
from symfloat.derivations.scheeffer_vii_viii import witnesses as WITNESSES
from symfloat.engine.check import check_derivation
from symfloat.engine.witness import CERTIFIED, record_decision
from symfloat.engine.roots import illinois
from symfloat.geometry.floating import box, floating_state, right_prism
from symfloat.model.prediction import Scene
from symfloat.model.source import SOURCES

TEXT = SOURCES["scheeffer"].text()
RANGE = TEXT[TEXT.index("## VII."):TEXT.index("## IX.")]
ERRATA = {"100": "transcription", "109": "misprint", "s-upper": "claim", "95a-split": "transcription",
          "102a-reference": "misprint", "xs1-definition": "transcription", "N1-lower-base": "transcription",
          "prism-bases": "misprint", "118-domain": "misprint", "x-direction": "misprint"}
# printed formulas that are logical or calculus steps on others (no numeric quantity of their own to clip)
UNWITNESSED = {"s-upper", "95-element", "96-split", "117-cos", "regular-Ps", "106-first", "102a-reference",
               "xs1-definition", "N1-lower-base", "fig20", "S3-offsets-used", "xs-depth", "Tmu-derivative",
               # the coverage pass: an element, a centroid-axis moment on a sample triangle, claims in words and
               # references read symbolically
               "95-volume-element", "centroid-axis", "second-condition-words", "into-99", "103ab-simplest",
               "109-max-min",
               # labels read on a model (Fig. 21's square base, the +x sense of Fig. 19): nothing to clip
               "prism-bases", "118-domain", "x-direction",
               # a sentence read from the stability's definition: the definition route measures it, no clipped body
               # can tell which quantity its words name (docs/writing-derivations.md)
               "104-words"}


@pytest.fixture(scope="module")
def report(check):
    return check("scheeffer-vii-viii")[-1]


def test_no_failures_and_the_expected_errata(report):
    assert report.failures == []
    found = {f.id.split("/")[1]: f.erratum["kind"] for f in report.formulas if f.verdict == "erratum"}
    assert found == ERRATA
    assert all(f.verdict == "verified" for f in report.formulas if f.id.split("/")[1] not in ERRATA)
    assert all(s.status in ("proved", "definition", "applied") for s in report.steps)


def test_every_numbered_equation_is_judged_and_none_lacks():
    tagged = {n.replace(" ", "") for n in re.findall(r"\((\d{2,3} ?[ab]?)\)", RANGE)
              if 95 <= int(re.match(r"\d+", n).group()) <= 122}
    locators = {re.sub(r"[()]", "", p.locator) for p in STATEMENTS.d.printed}
    # (102 a) and (102 b) occur only as references (to (103a), (103b)); every displayed number is quoted
    assert tagged - locators <= {"102a", "102b"}
    assert {str(n) for n in range(95, 123)} - {re.match(r"\d+", t).group() for t in locators if t[:1].isdigit()} \
        == set()


def test_numeric_formulas_have_both_precisions(report):
    for f in report.formulas:
        name = f.id.split("/")[1]
        if name in UNWITNESSED:
            continue
        records = f.corrected_numeric if name in ERRATA else f.numeric
        methods = {r["method"] for r in records}
        if CERTIFIED in methods and all(record_decision(r) != "undecided" for r in records if r["method"] == CERTIFIED):
            assert methods == {CERTIFIED, "float64"}, name      # the ball decides; float64 measured beside it
        else:
            assert "float64" in methods and methods & {"mpmath, 50 digits", "mpmath, 40 digits"}, name


# ---- the designed equilibria ---------------------------------------------------------------------------------

def _measure(name, what, dps):
    """A quantity of the module's witnesses (WITNESSES.MEASURE) on the clipped configuration *name*, in float64 or at 40
    digits, as the witnesses declare it (the turned body for 'flip...')."""
    from symfloat.engine.floating_witness import FLOATING_METHODS, FloatingRootWitness
    flip = what.startswith("flip")
    w = FloatingRootWitness(what, what, (), (), body=None, up=tuple(-u for u in WITNESSES.UP) if flip else WITNESSES.UP,
                            density=1 - STATEMENTS.s if flip else STATEMENTS.s, quantity=WITNESSES.MEASURE[what])
    return w.measure(WITNESSES._case(name), FLOATING_METHODS[0 if dps <= 15 else 1])


@pytest.mark.parametrize("name", ["pent-eq", "box-eq", "box3-eq"])
def test_designed_positions_are_equilibria_of_the_clipped_prism(name):
    # built from (95a) and (103b) (VIII: (118), (122)) with exact arithmetic; on the clipped prism both horizontal
    # offsets of the centre of buoyancy from G vanish
    p = WITNESSES._params(name)
    assert sp.simplify(STATEMENTS.res(STATEMENTS.Pxy).xreplace(p)) == 0
    for dps in (15, 40):
        h, e = _measure(name, "balance", dps)
        assert abs(h) < (1e-13 if dps == 15 else 1e-35) and abs(e) < (1e-13 if dps == 15 else 1e-35)


def test_pentagon_design_pinned():
    # raw pentagon (-2,-1), (1,-3/2), (3/2,1/2), (0,2), (-3/2-67/72, 1/2-67/48): the last vertex slid parallel to
    # its neighbours' chord until the centroid O sits at y = int_F x y / int_F x over the dry part x > 0 (exact:
    # lambda = -67/144 of the direction (2, 3)); area 61/8, O = (-349/2196, -35/1464); (103b) then gives b = 475/183
    # for tan phi = 4/3, and (103a) s = 1 - F x_s tan/(F_1 b) = 0.857...
    p = WITNESSES._params("pent-eq")
    assert p[STATEMENTS.F1] == sp.Rational(61, 8) and p[STATEMENTS.x0] == sp.Rational(-349, 2196)
    assert p[STATEMENTS.F] == sp.Rational(85, 24) and p[STATEMENTS.T] == sp.Rational(1015, 576)
    assert sp.simplify(STATEMENTS.res(STATEMENTS.M3 / STATEMENTS.sn2).xreplace(p)) == 0
    assert float(p[STATEMENTS.s]) == pytest.approx(0.8573099415204678, rel=1e-14)
    # the equilibrium is not a symmetric one: the waterplane's central product k = m n F_2 != 0
    assert _measure("pent-eq", "Ks", 15) == pytest.approx(float(STATEMENTS.res(STATEMENTS.k_).xreplace(p)), rel=1e-12)
    assert abs(_measure("pent-eq", "Ks", 15)) > 0.05


def test_stability_of_the_designed_equilibria_pinned():
    # (117) sign identity: the printed left side equals 2 cos phi V_1 GM of the clipped position (GM from the
    # clipped waterplane's least moment and the clipped centre of buoyancy); both designed equilibria are labile:
    # the cube's exactly -15/1372 (exact rational reading of (117) at s = 71/98, tan phi = 4/3), the pentagon's
    # -1.55934272897988 (same reading, exact data, evaluated)
    cube = STATEMENTS.at_eq(STATEMENTS.L117).xreplace(WITNESSES._params("box-eq"))
    assert sp.nsimplify(sp.simplify(cube)) == sp.Rational(-15, 1372)
    assert _measure("box-eq", "2cD", 15) == pytest.approx(-15 / 1372, rel=1e-12)
    pent = float(STATEMENTS.at_eq(STATEMENTS.L117).xreplace(WITNESSES._params("pent-eq")))
    assert pent == pytest.approx(-1.5593427289798802, rel=1e-13)
    assert _measure("pent-eq", "2cD", 15) == pytest.approx(pent, rel=1e-12)


def _box_arm(A, bb, sv, theta):
    st = floating_state(box(A, 1, bb), (math.sin(theta), 0, math.cos(theta)), sv)
    return sum(h * (st.B[k] - st.G[k]) for k, h in enumerate((math.cos(theta), 0, -math.sin(theta))))


def test_box_equilibria_found_by_root_finding():
    # second region: unit cube, s = 71/98 (from (103a) with tan phi = 4/3, w = 9/14); the righting arm of the
    # clipped cube vanishes at tan phi = 4/3 (searched between 0.8 and 1.0 rad, where the top face is cut)
    s2 = float(WITNESSES._params("box-eq")[STATEMENTS.s])
    assert WITNESSES._params("box-eq")[STATEMENTS.s] == sp.Rational(71, 98)
    assert math.tan(illinois(lambda q: _box_arm(1, 1, s2, q), 0.8, 1.0, 1e-15)) == pytest.approx(4 / 3, rel=1e-12)
    # third region: box 9/10 x 1 x 1, s = 2/3, tan phi = 5/2 from (122)
    s3 = float(WITNESSES._params("box3-eq")[STATEMENTS.s])
    assert WITNESSES._params("box3-eq")[STATEMENTS.s] == sp.Rational(2, 3)
    assert math.tan(illinois(lambda q: _box_arm(0.9, 1, s3, q), 1.1, 1.3, 1e-15)) == pytest.approx(2.5, rel=1e-12)


# ---- claims in words ----------------------------------------------------------------------------------------

def test_claim_stability_direction_on_the_cube():
    # 'stable when M_3 passes from - to + with growing phi': at the cube's equilibrium tan phi = 4/3 the clipped
    # arm M_3/V_1 goes from - to +, and the clipped potential has a minimum there (against the tilt)
    s2 = float(WITNESSES._params("box-eq")[STATEMENTS.s])
    ph = math.atan(4 / 3)
    m_minus = -_box_arm(1, 1, s2, ph - 0.02)       # M_3 = V_3 h.(S_3 - S) = -V_1 h.(B - G)
    m_plus = -_box_arm(1, 1, s2, ph + 0.02)
    E = [floating_state(box(1, 1, 1), (math.sin(q), 0, math.cos(q)), s2).potential for q in (ph - 0.02, ph, ph + 0.02)]
    assert m_minus < 0 < m_plus and E[1] < E[0] and E[1] < E[2]


def test_claim_s_below_half_exchanges_wet_and_dry():
    # V_1 E of density s with u up equals that of density 1 - s with -u up (the dry part becomes the submerged one)
    for name in ("rect", "tri", "pent-eq"):
        assert _measure(name, "V1e2", 15) == pytest.approx(_measure(name, "flip", 15), rel=1e-12)


def test_claim_x0_negative_when_N_lies_between_O_and_E():
    # the pentagon's water line crosses EF on the dry side of O (N between O and E): measured x_0 < 0
    assert _measure("pent-eq", "x0", 15) == pytest.approx(-349 / 2196, rel=1e-12)
    assert _measure("rect", "x0", 15) > 0


def test_claim_98_regular_bases_wet_part():
    # for the square and the equilateral triangle P_O = 0, and int xy over the dry part is -int over the wet part
    for name in ("square", "eqtri"):
        p = WITNESSES._params(name)
        assert p[STATEMENTS.PO] == 0
        assert _measure(name, "Pxy", 15) == pytest.approx(-float(p[STATEMENTS.Pw]), rel=1e-12)


# ---- mutations ------------------------------------------------------------------------------------------------

def _mutated(name, reading=None, erratum="keep"):
    p = next(q for q in STATEMENTS.d.printed if q.name == name)
    q = dataclasses.replace(p, reading=reading if reading is not None else p.reading,
                            erratum=p.erratum if erratum == "keep" else erratum)
    return dataclasses.replace(STATEMENTS.d, printed=[q], witnesses=[])


def test_a_mutated_coefficient_of_103b_is_refuted():
    # F_1 b^2 (1 - s)/2 mutated to /3
    m = STATEMENTS
    rd = (m.M3 / m.sn2, m.T * (1 + m.tg2 ** 2 / 2) - m.F1 * m.b ** 2 * (1 - m.s) / 3 - m.F * m.xs * m.x0)
    rep = check_derivation(_mutated("103b", reading=rd), prove=False, trust_steps=True)
    assert rep.formulas[0].verdict == "erratum"
    assert any("103b" in f and "no erratum" in f for f in rep.failures)


def test_the_109_correction_must_hold():
    p = next(q for q in STATEMENTS.d.printed if q.name == "109")
    wrong = dataclasses.replace(p.erratum, corrected_reading=p.reading)
    rep = check_derivation(_mutated("109", erratum=wrong), prove=False, trust_steps=True)
    assert any("correction does not hold" in f for f in rep.failures)


# ---- predictions --------------------------------------------------------------------------------------------

SCENES = [Scene("cube", Fraction(71, 98), (Fraction(1),) * 3), Scene("cube", Fraction(1, 5), (Fraction(1),) * 3),
          Scene("box", Fraction(2, 3), (Fraction(9, 10), Fraction(1), Fraction(1))),
          Scene("box", Fraction(1, 3), (Fraction(9, 10), Fraction(1), Fraction(1)))]


@pytest.mark.parametrize("scene", SCENES, ids=lambda sc: f"{sc.body}-{sc.density}")
def test_predicted_positions_are_clipped_equilibria_with_the_predicted_stability(scene):
    preds = PREDICTORS.predict(scene)
    assert preds and all(set(p.printed) <= {q.name for q in STATEMENTS.d.printed} for p in preds)
    body = box(*[float(q) for q in scene.dims])
    for p in preds:
        st = floating_state(body, p.up, float(scene.density))
        r = [st.B[k] - st.G[k] for k in range(3)]
        along = sum(r[k] * p.up[k] for k in range(3))
        assert max(abs(r[k] - along * p.up[k]) for k in range(3)) < 1e-12      # B vertically below G
        if p.stability is not None:
            assert (st.metacentric_height > 0) == (p.stability == "stable")


def test_predictions_pinned():
    # the cube at s = 71/98: the designed second-region position tan phi = 4/3 (one representative, here seen from
    # the x axis as tan phi = 3/4) and the diagonal one at 45 deg; both labile by (117)
    ups = sorted(tuple(round(abs(q), 12) for q in p.up) for p in PREDICTORS.predict(SCENES[0]))
    assert ups == [(0.707106781187, 0.707106781187, 0.0), (0.8, 0.6, 0.0)]
    # the box 9/10 x 1 x 1 at s = 2/3: the third-region position tan phi = 5/2 of (122), as designed (box3-eq)
    third = [p for p in PREDICTORS.predict(SCENES[2]) if p.printed[0] == "118"]
    assert len(third) == 1 and third[0].up[0] == pytest.approx(5 / math.sqrt(29), rel=1e-12)
    assert PREDICTORS.predict(Scene("prism", Fraction(1, 2), (Fraction(1), Fraction(1)), sides=6)) == []


def test_claim_s_upper_counterexample():
    # equilateral triangular prism, side 1, height 1, s = 3/5 > 1/2, turned about an axis parallel to a side with
    # that side dipping: the clipped water plane reaches the lower base first, at tan phi = sqrt(3) s = 1.0392
    # (first-region formula b s/u_m', u_m' = 1/sqrt 3), while the upper base is still dry there
    r3 = math.sqrt(3)
    body = right_prism([(-0.5, -1 / (2 * r3)), (0.5, -1 / (2 * r3)), (0.0, 1 / r3)], 1)
    top = [p for p in body.vertices if p[2] > 0]
    bot = [p for p in body.vertices if p[2] < 0]

    def clearances(phi):
        u = (0.0, math.sin(phi), math.cos(phi))
        st = floating_state(body, u, 0.6)
        hts = lambda ps: [sum(u[k] * p[k] for k in range(3)) - st.t for p in ps]  # noqa: E731
        return min(hts(top)), max(hts(bot))            # top base dry while > 0, bottom wet while < 0

    ph = illinois(lambda q: clearances(q)[1], 0.5, 1.0, 1e-15)
    assert math.tan(ph) == pytest.approx(r3 * 0.6, rel=1e-10)
    assert clearances(ph)[0] > 0.05


# ---- faults of the second review, each refuted on its own -----------------------------------------------------

@pytest.mark.parametrize("name, kind, confidence", [
    ("95a-split", "transcription", "high"),           # transcription line 1096: the df of the left member lost
    ("102a-reference", "misprint", "medium"),         # line 1279: '(nach 102 a)' for (103a)
    ("N1-lower-base", "transcription", "medium"),     # line 1295: 'den Punkt N' for N_1
    ("xs1-definition", "transcription", "medium"),    # line 1305: 'x_3^1' for x_s^1
    ("prism-bases", "misprint", "low"),               # line 1295: 'Grundflächen G B H' for AGHCD (F of VII)
    ("118-domain", "misprint", "low"),                # line 1299: 'G H D = F' for AGHCD = F (low, as GBH)
    ("x-direction", "misprint", "low"),               # line 1190: 'S S^1' (S not in Fig. 19) for L S^1
])
def test_second_review_faults_are_errata(name, kind, confidence):
    rep = check_derivation(_mutated(name), prove=False, trust_steps=True)
    (f,) = rep.formulas
    assert f.verdict == "erratum" and rep.failures == []
    assert (f.erratum["kind"], f.erratum["confidence"]) == (kind, confidence)


def test_the_102_references_are_one_erratum_with_two_places():
    # transcription lines 1270 'also nach 102 b):' and 1279 '(nach 102 a)': (103b) and (103a) meant, the same slip
    # twice; the erratum quotes the second and lists the first as a place of its words 'nach 102'
    p = next(q for q in STATEMENTS.d.printed if q.name == "102a-reference")
    assert (p.erratum.fault, p.erratum.places) == ("nach 102", ("VII",))
    assert [i + 1 for i, line in enumerate(TEXT.splitlines()) if "nach 102" in line] == [1270, 1279]
    assert "(102a)" not in TEXT and "(102b)" not in TEXT and "(103b)" in TEXT


def test_the_labels_of_F_in_VIII_against_the_dry_part_of_VII():
    # transcription lines 1084/1092 (VII): F = AGHCD, the wet triangle BGH; VIII keeps the letters (line 1295).
    # On the unit square A(0,1) B(1,1) C(1,0) D(0,0), G = (2/3, 1) on AB, H = (1, 1/4) on BC (shoelace by hand):
    # F = 1 - BGH = 1 - (1/3)(3/4)/2 = 7/8; GBH = 1/8 (line 1295) and GHD = |2/3 * 1/4 - 1 * 1|/2 = 5/12 (line 1299)
    area = {q: sp.nsimplify(STATEMENTS.area21(q).doit()) for q in ("AGHCD", "GBH", "GHD")}
    assert area["AGHCD"] == sp.Rational(7, 8) == sp.nsimplify(STATEMENTS.F21.doit())
    assert area["GBH"] == sp.Rational(1, 8) and area["GHD"] == sp.Rational(5, 12)
    for name in ("prism-bases", "118-domain"):
        p = next(q for q in STATEMENTS.d.printed if q.name == name)
        wrong = dataclasses.replace(p.erratum, corrected_reading=p.reading)     # the printed label kept
        rep = check_derivation(_mutated(name, erratum=wrong), prove=False, trust_steps=True)
        assert any("correction does not hold" in f for f in rep.failures)


def test_the_x_direction_correction_needs_the_sense_from_L_to_S1():
    # transcription line 1198: 'x - m statt x ... wenn S^1 L = m': the moment about HN is +m F_2 along L S^1; the
    # opposite sense (S^1 L) would give -m F_2 and must be refuted
    p = next(q for q in STATEMENTS.d.printed if q.name == "x-direction")
    lhs, rhs = p.erratum.corrected_reading
    wrong = dataclasses.replace(p.erratum, corrected_reading=(lhs, -rhs))
    rep = check_derivation(_mutated("x-direction", erratum=wrong), prove=False, trust_steps=True)
    assert any("correction does not hold" in f for f in rep.failures)
