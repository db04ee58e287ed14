"""Scheeffer 1902, sections IV and V (derivation ``scheeffer-iv-v``): verdicts, errata, pinned values from the
clipped-prism geometry, the claims in words, and mutations the engine must refute."""
import copy
import math
from dataclasses import replace

import mpmath
import pytest
import sympy as sp

from symfloat.derivations.scheeffer_iv_v import statements as M, witnesses as W
from symfloat.engine.check import check_derivation
from symfloat.geometry.floating import floating_state, right_prism

ERRATA = {"32": "transcription", "37": "transcription", "38-projection": "misprint", "43a": "misprint", "52": "transcription",
          "law": "claim", "s-half": "claim", "55": "claim", "51-verdict": "claim", "51-moment": "claim"}


@pytest.fixture(scope="module")
def report(reports_by_id):
    return reports_by_id["scheeffer-iv-v"]


def test_no_failures_and_the_expected_errata(report):
    assert report.failures == []
    found = {f.id.split("/")[1]: f.erratum["kind"] for f in report.formulas if f.verdict == "erratum"}
    assert found == ERRATA
    assert all(f.verdict == "verified" for f in report.formulas if f.id.split("/")[1] not in {*ERRATA, "Tx-Ty"})
    # (45) 'int_1 y^2 df = T_x, int_1 x^2 df = T_y' names the moments: a definition, nothing to check
    assert next(f.verdict for f in report.formulas if f.id.endswith("/Tx-Ty")) == "trivial"


def test_numbered_displays_are_witnessed(report):
    # every verified display carrying a number (27)-(55) whose quantity is numeric has >= 2 witness records
    # (37) is an erratum (df for df_2), its witness cases lie at the equilibrium where the term vanishes
    numeric = {"27", "28", "31", "33", "34", "35", "38", "39", "40", "41", "42", "43", "45", "51", "53", "53a",
               "54"}
    for f in report.formulas:
        if f.id.split("/")[1] in numeric:
            assert f.verdict == "verified" and len(f.numeric) >= 2, f.id


def test_37_df_for_df2_is_an_erratum(report):
    # transcription line 264, second line of (37): "sin 2 mu int_2 u_2 v_2 . df" - the element of the waterplane
    # I (df = df_2 cos phi_1) where the first line and (38*) have df_2: refuted for int u v df != 0
    from symfloat.model.source import SOURCES
    f = next(f for f in report.formulas if f.id == "scheeffer-iv-v/37")
    assert f.verdict == "erratum" and (f.erratum["kind"], f.erratum["confidence"]) == ("transcription", "low")
    assert r"\sin 2 \mu \int_2 u_2 v_2 \cdot df. " in SOURCES["scheeffer"].text().splitlines()[264 - 1]
    assert "the print gives" in f.erratum["evidence"]


# ---- pinned values, all measured on the clipped prism (the derivation's floating witnesses), float64 ---------

def _measured(witness, label, cases=None):
    """The float64 value of the derivation's witness at its case *label* (or at the cases of other bodies)."""
    w = next(w for w in M.DERIVATION.witnesses if w.name == witness)
    if cases is not None:
        w = replace(w, cases=W._cases(cases))
    return w.measure(next(c for c in w.instances if c.label == label), w.methods[0])


def test_rectangle_tilt_pinned():
    # (27)/(54), base 1 x 2 turned about its long axis, b = 9/10, s = 2/5: tan^2 phi_1 = 12 b^2 s(1-s) - 2
    # = 12 * 81/100 * 6/25 - 2 = 208/625 (exact); measured as the zero of the clipped righting arm
    assert _measured("tilt-squared", "rect-long") == pytest.approx(208 / 625, rel=1e-12)
    # (35): V_1 e_2 = T_1 / cos phi_1 = (1/6) sqrt(1 + 208/625) = (1/6)(sqrt 833)/25
    assert _measured("Ve2", "rect-long") == pytest.approx(math.sqrt(833) / 150, rel=1e-12)
    # (42): T_m = T_1/cos^3 = (1/6)(833/625)^(3/2), T_m^1 = T_1^1/cos = (2/3) sqrt(833)/25
    T2, T21 = _measured("wp2-ext", "rect-long")
    assert T2 == pytest.approx((833 / 625) ** 1.5 / 6, rel=1e-12)
    assert T21 == pytest.approx(2 / 3 * math.sqrt(833) / 25, rel=1e-12)


def test_rectangle_tilt_at_40_digits():
    # the same zero refined at 40 digits: tan^2 phi_1 = 208/625 to the precision of the clipping
    w = next(w for w in M.DERIVATION.witnesses if w.name == "tilt-squared")
    case = next(c for c in w.instances if c.label == "rect-long")
    with mpmath.workdps(50):
        assert abs(w.measure(case, w.methods[1]) - mpmath.mpf(208) / 625) < 1e-35


def test_claim_43a_stable_iff_T11_greater():
    # IV claim: stable iff T_1 < T_1^1. Clipped metacentric height at the tilt: about the long axis (T_1 = 1/6 <
    # T_1^1 = 2/3) positive, (T_1^1 - T_1)/cos phi_1 / V = (1/2)(sqrt 833/25)/(2 * 9/10 * 2/5); about the short
    # axis (T_1 = 2/3 > 1/6) negative
    V = 2 * 9 / 10 * 2 / 5
    assert _measured("D2", "rect-long") == pytest.approx(min((1 / 6) * 208 / 625, 1 / 2) * math.sqrt(833) / 25,
                                                         rel=1e-10)
    assert _measured("D2", "rect-long") / V > 0
    assert _measured("D2", "rect-short") < 0


def test_isotropic_neutral_51_and_independent_of_omega():
    # (51): T_m^1 - T_1/cos phi_1 = 0 for the square prism (b = 17/20, s = 9/20), EF at 0 and 30 deg
    for name in ("square-0", "square-30", "tri-eq"):
        assert abs(_measured("iso-Tm1", name)) < 1e-12
    # the tilt and V e_2 are the same in every direction (47)-(52): tan^2 phi_1 = 12 b^2 s(1-s) - 2 = 0.1458...
    t0, t30 = _measured("tilt-squared", "square-0"), _measured("tilt-squared", "square-30")
    assert t0 == pytest.approx(t30, rel=1e-12) == pytest.approx(12 * 0.85 ** 2 * 0.45 * 0.55 - 2, rel=1e-12)


def _tilted(name):
    """The clipped prism of a body (float64), its density, and the frame at its tilted equilibrium: up vector,
    horizontal across EF, EF, and the up vector for EF turned by an angle."""
    poly, bb, ss, alpha = W.BODIES[name]
    body = right_prism([(float(x), float(y)) for x, y in poly], float(bb))
    psi = math.atan(_measured("tilt", name))
    frame = lambda turn=0: [tuple(float(c) for c in v.subs({W.ALPHA: alpha + turn, W.PSI: psi}))   # noqa: E731
                            for v in (W.UP, W.HOR, W.EV)]
    return body, float(ss), frame


def _potential(body, s, up):
    st = floating_state(body, up, s)
    return st.volume * st.potential


def _perturbed(up, a, eps):
    v = [up[k] + eps * a[k] for k in range(3)]
    n = math.sqrt(sum(x * x for x in v))
    return tuple(x / n for x in v)


def test_claim_51_stable_tilted_square_energy():
    # (51) claim "folglich das Gleichgewicht stabil": the potential energy V (z_G - z_B) of the clipped square
    # prism at its tilt is a (non-strict) minimum: no small turn lowers it, and turning about the prism axis
    # (the spin family: same tilt, other EF) leaves it unchanged: neutral in that direction, the erratum
    # 51-verdict (stable about every other axis, neutral about G_2 H_2)
    body, s, frame = _tilted("square-0")
    up, h, ev = frame()
    U0 = _potential(body, s, up)
    for a in (h, ev, tuple((h[k] + ev[k]) / math.sqrt(2) for k in range(3)),
              tuple((h[k] - 2 * ev[k]) / math.sqrt(5) for k in range(3))):
        for eps in (0.02, -0.02, 0.05, -0.05):
            assert _potential(body, s, _perturbed(up, a, eps)) >= U0 - 1e-12
    for turn in (0.1, 0.4, 1.0):
        assert _potential(body, s, frame(turn)[0]) == pytest.approx(U0, abs=1e-12)


def test_claim_43a_unstable_tilt_energy():
    # the short-axis tilt of the 2 x 1 rectangle (T_1 > T_1^1) is a saddle: a turn about the axis across EF
    # lowers the clipped potential energy
    body, s, frame = _tilted("rect-short")
    up, h, ev = frame()
    U0 = _potential(body, s, up)
    assert _potential(body, s, _perturbed(up, ev, 0.05)) < U0 - 1e-6


def test_law_counterexample_pinned():
    # erratum 'law': rectangle 1 x 6/5, b = 5/6, s = 1/2, stable tilt about the long axis turned by omega about
    # the prism axis: int u v df = (T_x - T_y) sin 2 omega / 2 = (18/125 - 1/10)/2 * sin 2 omega != 0
    for om in (sp.pi / 12, sp.pi / 6):
        assert _measured("law", f"rect-law, {om}") == pytest.approx((18 / 125 - 1 / 10) / 2 * math.sin(2 * om),
                                                                     rel=1e-10)


def test_law_is_a_claim_of_medium_confidence():
    # the law (transcription line 422) is drawn ('so ergibt sich daraus') from the assumption of line 418 that T_1
    # is the same for every axis through O; read in that context it holds, so the objection stands in part and the
    # erratum is medium, not high (issue 31, item 1)
    law = next(p for p in M.DERIVATION.printed if p.name == "law")
    (f,) = _check_only("law", law.reading).formulas
    assert f.verdict == "erratum" and (f.erratum["kind"], f.erratum["confidence"]) == ("claim", "medium")
    assert "obigen Voraussetzungen" in f.erratum["objection"]


def test_face_limits_counterexample_pinned():
    # erratum (55) / 's-half': equilateral triangle side 1, EF parallel to a side, apex dipping, b = 17/25,
    # s = 2/5 < 1/2. Clipped geometry: the upper base is reached first, at tan = sqrt 3 b (1 - s) = 51 sqrt3/125
    # = 0.70668; (55) would allow up to 2 sqrt 3 b s = 68 sqrt 3/125 = 0.94224, and (54) puts tan phi_1 at
    # sqrt(24 b^2 s (1-s) - 2) = sqrt(10366)/125 = 0.81451, between the two
    assert _measured("first", "tri-eq-apex") == pytest.approx(51 * math.sqrt(3) / 125, rel=1e-12)
    apex = ("tri-eq-apex", "tri-eq-apex-up")
    assert _measured("top", "tri-eq-apex") < _measured("bot", "tri-eq-apex", apex)
    printed = float(M.printed55.subs(W._params("tri-eq-apex")))
    assert printed == pytest.approx(68 * math.sqrt(3) / 125, rel=1e-14)
    assert 51 * math.sqrt(3) / 125 < math.sqrt(10366) / 125 < printed
    # apex rising, s = 3/5 > 1/2: the lower base is reached first, at tan = sqrt 3 b s = 51 sqrt3/125
    assert _measured("first", "tri-eq-apex-up") == pytest.approx(51 * math.sqrt(3) / 125, rel=1e-12)
    assert _measured("bot", "tri-eq-apex-up") < _measured("top", "tri-eq-apex-up", apex)


# ---- mutations -------------------------------------------------------------------------------------------------

def _check_only(name, reading):
    d = copy.copy(M.DERIVATION)
    p = next(p for p in d.printed if p.name == name)
    d.printed = [replace(p, reading=reading)]
    d.witnesses = []
    return check_derivation(d, prove=False, trust_steps=True)


def test_mutated_coefficients_are_refuted():
    t1, c = M.t1, sp.cos(M.phi1)
    rep = _check_only("54", (t1 ** 2, M.F1 * M.b ** 2 / M.T1 * M.s * (1 - M.s) - 3))      # -2 -> -3
    assert rep.formulas[0].verdict == "erratum" and any("refuted" in f for f in rep.failures)
    rep = _check_only("42", (sp.Matrix([M.Tm, M.Tm1]), sp.Matrix([M.T1 / c ** 2, M.T11 / c])))   # cos^3 -> cos^2
    assert any("refuted" in f for f in rep.failures)
    rep = _check_only("27", (t1, sp.sqrt(3 * (M.V1 * M.e1 / M.T1 - 1))))                   # 2 -> 3
    assert any("refuted" in f for f in rep.failures)


def _verdict(name, reading):
    """The verdict on *name*'s sentence read as *reading* (no erratum: a refuted reading fails)."""
    d = copy.copy(M.DERIVATION)
    p = next(p for p in d.printed if p.name == name)
    d.printed = [replace(p, reading=reading, erratum=None)]
    d.witnesses = []
    rep = check_derivation(d, prove=False, trust_steps=True)
    return "refuted" if any("refuted" in f for f in rep.failures) else rep.formulas[0].verdict


def test_the_sentences_in_words_refute_their_mutants():
    """The sentences read through the vocabulary (issue 31): IV's 'das Drehungsmoment, dessen negativer Faktor
    (absolut genommen) mit wachsendem phi kleiner wird' and 'für einen genügend grossen Drehungswinkel phi_1 gleich
    Null' hold as printed and are refuted with the direction flipped or the stability named for the moment; after
    (51) the verdict 'stabil' about G_2 H_2 is refuted (the stability is 0 there: neutral), 'indifferent' holds and
    'labil' is refuted; the Drehungsmoment at the position phi_1 is 0, not positive, while the stability named in
    its place is positive for every axis but G_2 H_2."""
    from symfloat.model.vocabulary import Called, DecreasesWith, GrowsWith, Is
    d, X, phi = M.DERIVATION, M.X, M.phi
    along_tg = dict(per=-sp.sin(phi), at={phi: sp.atan(X)}, domain={X: (0, sp.oo)})
    assert _verdict("Q-decreasing", d.get_printed("Q-decreasing").reading) == "verified"
    assert _verdict("Q-decreasing", d.reads("Drehungsmoment", GrowsWith(X, **along_tg))) == "refuted"
    assert _verdict("Q-decreasing", d.reads("Stabilität", DecreasesWith(X, **along_tg))) == "refuted"
    assert _verdict("moment-zero-words", d.get_printed("moment-zero-words").reading) == "verified"
    assert _verdict("moment-zero-words", d.reads("Stabilität", Is(0, at={phi: M.phi1}))) == "refuted"
    G2H2 = Called(at={M.T11: M.T1, M.mu: sp.pi / 2})
    assert d.get_printed("51-verdict").reading == d.reads("stabil", G2H2)
    assert _verdict("51-verdict", d.reads("stabil", G2H2)) == "refuted"
    assert _verdict("51-verdict", d.reads("indifferent", G2H2)) == "verified"
    assert _verdict("51-verdict", d.reads("labil", G2H2)) == "refuted"
    assert _verdict("51-verdict", d.reads("stabil", Called(at={M.T11: M.T1, M.mu: sp.pi / 3}))) == "verified"
    assert _verdict("51-moment", d.get_printed("51-moment").reading) == "refuted"
    assert _verdict("51-moment", d.get_printed("51-moment").erratum.corrected_reading) == "verified"
