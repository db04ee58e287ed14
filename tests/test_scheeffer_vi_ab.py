"""Scheeffer 1902, VI, VI.A, VI.B (derivations/scheeffer_vi_ab/): recomputed worked examples and
thresholds, each pinned with its provenance, and a mutation test."""
import dataclasses
import math

import pytest
import sympy as sp

from symfloat.derivations.scheeffer_vi_ab import statements as M
from symfloat.engine.check import check_derivation
from symfloat.registry import load


def deg(x):
    return math.degrees(x)


def measured(witness, case=0):
    """The float64 value of the derivation's witness at its case number *case*."""
    w = next(w for w in load("scheeffer-vi-ab")[0].witnesses if w.name == witness)
    return w.measure(w.instances[case], w.methods[0])


# ---- Example 1 (VI.A): a/b at which the upright prism with s = 0.8 is neutral.
# Closed form sqrt(12 * 0.8 * 0.2) (from (57)); independently the root of the metacentric height of the
# clipped triangular prism (symfloat.geometry.floating).  Printed: 139/100.
def test_example_1():
    assert float(M.ex1_ratio) == pytest.approx(math.sqrt(1.92), abs=1e-14)
    assert float(measured("example-1")) == pytest.approx(1.3856406460551018, abs=1e-10)
    assert abs(1.3856406460551018 - 1.39) < 0.005


# ---- Example 2 (VI.A): a = b; the densities of zero metacentric height (roots of 12 s(1-s) = 1),
# sympy.solve and the clipped prism.  Printed 0.908 / 0.092, sqrt(0.6667) = 0.8165.
def test_example_2():
    up, lo = measured("example-2-upper"), measured("example-2-lower")
    assert float(up) == pytest.approx((1 + math.sqrt(2 / 3)) / 2, abs=1e-10)      # 0.90825
    assert float(lo) == pytest.approx((1 - math.sqrt(2 / 3)) / 2, abs=1e-10)      # 0.09175
    assert float(M.s_hi_1) == pytest.approx(0.9082482904638630, abs=1e-14)
    assert round(2 * float(M.s_hi_1) - 1, 4) == 0.8165


# ---- Example 3 (VI.A): s = 2/3, (a/b)^2 = (3/2)(1-s)(9s-1) = 5/2, tan(phi_1) = sqrt(2/15):
# phi_1 = 20 deg 3' 34.50'' (printed 20 deg 3' 35''); the clipped prism's equilibrium at omega = 60 deg agrees.
def test_example_3():
    assert M.Q60_3 == sp.Rational(5, 2)
    phi = math.atan(math.sqrt(2 / 15))
    assert deg(phi) == pytest.approx(20 + 3 / 60 + 34.5004 / 3600, abs=1e-7)
    assert float(measured("example-3-angle")) == pytest.approx(deg(phi), abs=1e-9)
    assert abs(math.sqrt(2.5) - 1.58) < 0.005


# ---- Example 4 (VI.A): omega = 15 deg, phi_1 = 30 deg; sympy.solve of (67): s = 7/11, a/b = 12 sqrt2/11
# = sqrt(18)(1-s) = 1.5428 (the transcription's sqrt(181) is an erratum), approx 17/11.
# The clipped prism at that answer: equilibrium and top-vertex contact both at tan 30 deg.
def test_example_4():
    assert M.s4 == sp.Rational(7, 11)
    assert sp.simplify(M.q4 - 12 * sp.sqrt(2) / 11) == 0
    eq, contact = measured("example-4")
    assert float(eq) == pytest.approx(1 / math.sqrt(3), abs=1e-10)
    assert float(contact) == pytest.approx(1 / math.sqrt(3), abs=1e-10)


# ---- Examples 5-7 (VI.B): cylinder thresholds, closed forms and the floating cylinder (Body.cylinder).
# 2r = b: the roots of 8 s(1-s) = 1 are (1 -+ sqrt 0.5)/2 (printed 0.8536, 0.1464); the equilibrium reaches the
# lower base where (2s)^2 = 16 s(1-s) - 2, s = 0.4 - sqrt(0.06) = 0.15505 (printed 0.155); 2r/b = sqrt 2 at s = 1/2.
def test_examples_5_to_7():
    assert float(M.sC_hi1) == pytest.approx(0.8535533905932737, abs=1e-14)    # (1 + sqrt 0.5)/2, printed 0.8536
    assert float(M.sC_lo1) == pytest.approx(0.1464466094067262, abs=1e-14)    # printed 0.1464 and 0.146
    assert float(measured("example-5")) == pytest.approx(math.sqrt(2), abs=1e-10)
    assert float(measured("example-6-upper")) == pytest.approx(0.8535533905932737, abs=1e-10)
    assert float(measured("example-6-lower")) == pytest.approx(0.1464466094067262, abs=1e-10)
    assert float(M.s_b[0]) == pytest.approx(0.4 - math.sqrt(0.06), abs=1e-14)
    assert float(measured("example-7-minus")) == pytest.approx(0.4 - math.sqrt(0.06), abs=1e-9)


# ---- Example 10 (VI.B): tan(phi_1) = sqrt(11/32): phi_1 = 30 deg 22' 59.45'' (printed 18 deg 58' 13'' =
# arctg(11/32): calculation erratum), x = 1.5 + 1.6 sqrt(11/32) = 2.4381 m, x/b = 0.9752, dry part 6.2 cm.
def test_example_10():
    phi = math.atan(math.sqrt(11 / 32))
    assert deg(phi) == pytest.approx(30 + 22 / 60 + 59.448 / 3600, abs=1e-6)
    assert deg(math.atan(11 / 32)) == pytest.approx(18 + 58 / 60 + 13.468 / 3600, abs=1e-6)
    assert float(measured("example-10-angle")) == pytest.approx(deg(phi), abs=1e-9)
    x = float(measured("example-10-x"))
    assert x == pytest.approx(1.5 + 1.6 * math.sqrt(11 / 32), abs=1e-10)     # 2.43808
    assert 250 * (1 - x / 2.5) == pytest.approx(6.1917, abs=1e-3)


# ---- (72a), (73) at example 10's data: the contact tangents 2(1-s) b/(2r) = 0.625 and 2 s b/(2r) = 0.9375, the
# equilibrium tangent^2 11/32; (73)'s margins 8 s(1-s) - (2r/b)^2 = 0.2816, 0.0384 and 0.4384 (times (2r/b)^2/2)
def test_cylinder_limits():
    assert [float(v) for v in measured("cylinder-contacts")] == pytest.approx([0.625, 0.9375], abs=1e-10)
    assert [float(v) for v in measured("cylinder-73")] == pytest.approx([0.2816, 0.0384, 0.4384], abs=1e-10)
    assert [float(v) for v in measured("example-9-claim")] == [-1, -1]


# ---- claims: the triangle's lower base (60-one-base) and region III (65-III-claim)
def test_claim_counterexamples():
    # a = b, s = 3/5, omega = 0: lower base meets the water first, tan = 3 sqrt3/5, not 4 sqrt3/5
    assert float(M.Lbot_cx) == pytest.approx(3 * math.sqrt(3) / 5)
    assert float(M.Ltop_cx) == pytest.approx(4 * math.sqrt(3) / 5)
    # s = 11/20, (a/b)^2 = 11/5: righting arm at the first contact (best axis) is negative
    assert float(M.Delta3) == pytest.approx(-0.0109089663071034, abs=1e-12)
    assert float(measured("region-III-counterexample")) == pytest.approx(-0.0109089663071034, abs=1e-10)


# ---- (61), (63): the first-region model (columns not cut by the bases) at s = 0.55, (a/b)^2 = 2.25: the axis at
# which the equilibrium, tg^2 = 24 (b/a)^2 s(1-s) - 2 = 0.64, meets the upper base (B dipping) has
# sin(30 deg + omega) = (1-s) sqrt3 / sqrt(24 s(1-s) - 2 (a/b)^2) = 0.45 sqrt3 / 1.2, the lower base (B rising)
# 0.55 sqrt3 / 1.2; at omega = 0 the boundaries (a/b)^2 = 6(1-s)(3s-1) = 1.755 and 6s(2-3s) = 1.155 ((64)),
# derived by hand from the column model.
def test_the_first_region_model():
    assert [float(v) for v in measured("model-61")] == pytest.approx([0.45 * math.sqrt(3) / 1.2,
                                                                      0.55 * math.sqrt(3) / 1.2], abs=1e-10)
    assert [float(v) for v in measured("model-omega0-64")] == pytest.approx([1.755 - 2.25, 1.155 - 2.25], abs=1e-10)


@pytest.fixture(scope="module")
def report(reports_by_id):
    return reports_by_id["scheeffer-vi-ab"]


def test_module_checks_clean(report):
    assert report.failures == []
    verdicts = {f.id.split("/")[1]: f.verdict for f in report.formulas}
    assert verdicts["ex10-angle"] == "erratum" and verdicts["57"] == "verified"
    assert sum(v == "erratum" for v in verdicts.values()) == 15


@pytest.mark.parametrize("name, line, kind, confidence, same_as", [
    # line 705: "Diese ist durch die Bedingungen 55 bestimmt, wenn darin F_1 = pi r^2, T_1 = pi r^4/4 ..." - the
    # tilt of the next display is (54) (F_1, T_1 occur only there); (55) only bounds it
    ("72a-cited", 705, "misprint", "low", ""),
    # line 827: "In der aufrechten Schwimmlage ist diese b_s" - the draught b s, the s set as a subscript
    ("upright-draught", 827, "transcription", "medium", "scheeffer-vi-ab/x-formula"),
    # line 829: "x &= b_s + r tg phi" - the same b_s; the next line uses 1,5 = 2,5 * 0,6 = b s
    ("x-formula", 829, "transcription", "medium", ""),
    # line 833: "Der am tiefsten eintauchende Teil der Mantelhoehe betraegt also 41/50" - the x/b of line 831
    # (ex10-fraction) repeated: 49/50 with tg phi_1 = sqrt(11/32)
    ("ex10-deepest", 833, "consequential", "high", "scheeffer-vi-ab/ex10-fraction"),
])
def test_second_pass_faults_are_errata(report, name, line, kind, confidence, same_as):
    from symfloat.model.source import SOURCES
    d, _ = load("scheeffer-vi-ab")
    f = next(f for f in report.formulas if f.id == f"scheeffer-vi-ab/{name}")
    assert f.verdict == "erratum" and (f.erratum["kind"], f.erratum["confidence"]) == (kind, confidence)
    assert f.excerpt in SOURCES["scheeffer"].text().splitlines()[line - 1]
    assert "the print gives" in f.erratum["evidence"]            # the engine refuted the print
    assert next(p for p in d.printed if p.name == name).erratum.same_as == same_as


def test_mutated_coefficient_is_refuted():
    """(57) with 12 replaced by 11 must be refuted (and the witness disagrees)."""
    d, _ = load("scheeffer-vi-ab")
    printed = []
    for p in d.printed:
        if p.name == "57":
            p = dataclasses.replace(p, reading=((M.a / M.b) ** 2 - 11 * M.s * (1 - M.s), 24 * M.s / M.b * M.hA))
        if p.name in ("57",) or not p.tolerance:
            printed.append(p)
    mutated = dataclasses.replace(d, printed=[p for p in printed if p.name in ("57", "triangle-data")],
                                  witnesses=[w for w in d.witnesses if w.name == "triangle-upright-57"
                                             and dataclasses.replace(w, targets=("57",))])
    mutated.witnesses = [dataclasses.replace(w, targets=("57",)) for w in mutated.witnesses]
    rep = check_derivation(mutated, trust_steps=True)
    assert any("(57)" in f and "refuted" in f for f in rep.failures)


def test_the_verdict_words_refute_their_mutants():
    """The sentences that call the upright prism stable or labile are read through the vocabulary (issue 31): the
    stability is Duhamel's T/V - e_1 of the body the sentence speaks of. Each holds as printed and is refuted
    with its verdict word flipped, with the other body's stability, or with the neutral equality counted in."""
    from symfloat.engine.check import _relation
    from symfloat.engine.identity import Domain
    from symfloat.model.vocabulary import StableIff
    d, _ = load("scheeffer-vi-ab")
    dom = Domain(d.domain, tuple(d.constraints))

    def status(reading):
        return _relation(reading, d.results(), dom, "mutant", {"proofs": 0.0, "sampling": 0.0}).status
    triangle, cylinder = StableIff(M.T1 - M.V1 * M.e1 > 0, at=M.TRIANGLE), StableIff(M.T1c / M.V1c - M.e1 > 0,
                                                                                    at=M.CYLINDER)
    labile = (2 * M.r / M.b) ** 2 < 8 * M.s * (1 - M.s)                                        # (72) squared
    assert d.get_printed("duhamel-VA-words").reading == d.reads("Lage stabil", triangle)
    assert d.get_printed("cylinder-labile-words").reading == d.reads("Lage labil", StableIff(labile, at=M.CYLINDER))
    assert status(d.reads("Lage stabil", triangle)) in ("proved", "sampled")
    assert status(d.reads("Lage labil", triangle)) == "refuted"
    assert status(d.reads("stabile", cylinder)) == "proved"
    assert status(d.reads("stabile", StableIff(M.T1c / M.V1c - M.e1 > 0, at=M.TRIANGLE))) == "refuted"
    assert status(d.reads("Lage labil", StableIff(labile, at=M.CYLINDER))) in ("proved", "sampled")
    assert status(d.reads("Lage stabil", StableIff(labile, at=M.CYLINDER))) == "refuted"
    assert status(d.reads("Lage labil", StableIff((2 * M.r / M.b) ** 2 <= 8 * M.s * (1 - M.s),
                                                  at=M.CYLINDER))) == "refuted"                 # neutral at equality
    assert status(d.get_printed("less-satisfied").reading) in ("proved", "sampled")
