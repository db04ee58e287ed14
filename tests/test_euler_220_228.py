"""Euler, Scientia navalis III §§220–228 (curves of the ellipse's area with the greatest breadth off the
middle): the module checks clean, the range's formulas are quoted, its errata are exactly the expected
ones, areas and moments are pinned by independent quadrature, Euler's claims in words are tested, and
mutated prints are refuted."""
import dataclasses
import re

import mpmath
import pytest

from symfloat.engine.check import check_derivation
from symfloat.engine.witness import record_decision
from symfloat.model.source import SOURCES
from symfloat.registry import load

from one_formula import verdict_alone

D, PACKAGE = load("euler-220-228")
MODULE = PACKAGE.statements              # the symbols and quantities of the statements
TEXT = SOURCES["euler"].text()
# §229 begins with "§ 229." (no dot after §) in the transcription: the range ends there.
RANGE = TEXT[TEXT.index("§. 220."):TEXT.index("§ 229. Consideremus")]


@pytest.fixture(scope="module")
def report(check):
    return check("euler-220-228")[-1]


def _quadratures(records):
    """The quadratures beside Arb's record (issue 29): float64 where the ball decides the formula, float64 and 50
    digits where no ball decides it (the witness kind has no enclosure, or it leaves the formula undecided)."""
    certified = [r for r in records if r.get("certified")]
    decided = certified and all(record_decision(r) != "undecided" for r in certified)
    return {"float64"} if decided else {"float64", "mpmath, 50 digits"}


def test_no_check_fails(report):
    assert report.failures == []


# Inline pieces of §§220-228 that are notation, not results: the names of the lines (AO = BO = a,
# ce = cf = b, AP = x, PM = y), the equation of the family and its two branches (the definition of the
# curves: every consequence of it is quoted), the radical sign of §222, the end points y = b of the
# integrals, Y = -cyy/bb of §227 (the choice of §221, quoted there), and the fragment '∫(a-' cut at the
# page break of §227.
NOTATION = {r"$AO = BO = a$", r"$ce = cf = b$", r"$AP = x$", r"$PM = y$",
            r"$x = a + Y \pm a \sqrt{1 - \frac{y^2}{b^2}}$", r"$x = a + Y - a \sqrt{1 - \frac{y^2}{b^2}}$",
            r"$x = a + Y + a \sqrt{1 - \frac{y^2}{b^2}}$", r"$\sqrt{\cdot}$", r"$y = b$", r"$y=b$",
            r"$Y = \frac{-cyy}{bb},$", r"$\int (a-$"}


def test_every_inline_formula_of_the_range_is_quoted_or_notation():
    assert re.findall(r"\$\$.+?\$\$", RANGE, re.S) == []     # no displayed formula in §§220-228
    pieces = re.findall(r"\$[^$]+\$", RANGE)
    assert len(pieces) > 60
    missing = {x for x in pieces if not any(x in p.excerpt or p.excerpt in x for p in D.printed)}
    assert missing <= NOTATION


# The faults found (each argued in its erratum's evidence):
EXPECTED_ERRATA = {
    ("AB-Ace", "transcription", "medium"),          # §223 ∫y⁴dy√(bb-yy) for ∫y⁴dy/√(bb-yy) (bar lost)
    ("AB-Bce", "transcription", "medium"),          # §223 the same
    ("AB-AEB", "transcription", "medium"),          # §223 the same
    ("Aa-Ace-product", "transcription", "medium"),  # §224 the vinculum over x² lost
    ("Aa-Ace-expanded", "transcription", "high"),   # §224 'yy^2 y' for 'yy dy'
    ("Aa-AEB", "transcription", "medium"),          # §225 ∫y dy(a+Y)√ for ∫y dY(a+Y)√
    ("U2-value", "transcription", "high"),          # §225 b³D³/8a for b³D/8a
    ("Aa-AEB-value", "transcription", "high"),      # §225 aaD³/4 for aaD/4
    ("Aa-whole", "misprint", "medium"),             # §225 2a/b for 4a/b (and D³)
    ("DAC-definition", "transcription", "low"),     # §226 ∫y dx for ∫xy dx; low: a whole letter lost, print or
                                                    # scan cannot be told (its objection, issue 31)
    ("DAC", "transcription", "medium"),             # §226 ∫y dy√ for ∫y dY√
    ("moment-EF", "misprint", "medium"),            # §226 2a/b, aa/bbD, no square: 4a/b, 8aa/bbD, (..)²
    ("curve-c", "misprint", "medium"),              # §227 (c/b)√ for ±(a/b)√; the same c/b and + stand in
                                                    # §228: consistent, the print's (was the scan's, low)
    ("Oc", "transcription", "medium"),              # §227 Oc = a for Oc = c
    ("U0-value", "misprint", "low"),                # §227 the three values shifted by one integral, alike
    ("U2-value-c", "misprint", "low"),              # through the line: the print's by the criteria, but a model's
    ("U4-value", "misprint", "low"),                # transcription continues patterns too (§234): low
    ("moment-EF-c", "transcription", "low"),        # §227 c·c²D/128 for c²D/8
    ("curve-c-again", "misprint", "medium"),        # §228 c/b for a/b, the repeat of curve-c (and a = for x =)
    ("middle-named-C", "transcription", "medium"),  # §228 'medio C' for 'medio O' (second pass, line 195)
}


def test_second_pass_middle_of_AB_is_O_not_C(report):
    # Provenance: 002_9b5669e726e363a9.txt line 195, "a punto axis AB medio C distet"; §220 names the middle
    # O, and §227 puts the centroid C at AC = a - c/4.
    f = next(f for f in report.formulas if f.id == "euler-220-228/middle-named-C")
    assert f.verdict == "erratum" and f.erratum["kind"] == "transcription"
    p = next(p for p in D.printed if p.name == "middle-named-C")
    assert p.excerpt in TEXT.splitlines()[194] and "medio C" in p.excerpt


def test_the_errata_are_exactly_the_expected_ones(report):
    found = {(f.id.split("/")[1], f.erratum["kind"], f.erratum["confidence"])
             for f in report.formulas if f.verdict == "erratum"}
    assert found == EXPECTED_ERRATA
    assert all(f.verdict in ("verified", "erratum") for f in report.formulas)


def test_every_area_and_moment_carries_its_quadrature_records(report):
    unwitnessed = {"ends", "axis-AB", "greatest-breadth", "Oc-general", "breadth-b", "ellipse-at-Y0", "boundary-term",
                   "curve-c", "Oc",
                   "moment-grows", "curve-c-again", "c-limit", "c-half",
                   "middle-named-C",   # the midpoint of AB (x = a at y = 0) against the centroid: no integral
                   "curve", "portions", "Y-c",   # the defining branches, their ends, Oc: no integral
                   "Aa-Ace-product",   # its printed reading has loose terms in y: no number to compare
                   "even-Y",           # the mirror condition on the branches: no integral
                   "AB-free-of-Y"}     # read through the vocabulary: its records are the definition route's
    for f in report.formulas:
        name = f.id.split("/")[1]
        if name in unwitnessed:
            continue
        assert {rec["method"] for rec in f.numeric} - {"Arb ball arithmetic"} == _quadratures(f.numeric), name
        assert all(rec["seconds"] >= 0 for rec in f.numeric)
        ball = [rec for rec in f.numeric if rec["method"] == "Arb ball arithmetic"]
        if f.verdict == "erratum":      # the correction agrees with the quadratures
            assert all(rec["rel_error"] < 1e-10 for rec in f.corrected_numeric), name
        if not ball:                    # a kind without an enclosure: the quadratures judge the reading
            limit = (lambda e: e > 1e-3) if f.verdict == "erratum" else (lambda e: e < 1e-10)
            assert all(limit(rec["rel_error"]) for rec in f.numeric), name
            continue
        # with an enclosure, the quadratures' errors are the methods' own, proven against it, and the ball decides
        assert ball[0]["certified"], name
        assert all(rec["rel_error"] < 1e-10 for rec in f.numeric if rec is not ball[0]), name
        if f.verdict == "erratum":
            assert record_decision(ball[0]) == "refuted" and ball[0]["rel_error"] > 1e-3, name
        else:
            # (V2's integrand y²/√(b² − y²), unbounded at y = b, is enclosed after the substitution y = b − t²)
            assert record_decision(ball[0]) == "agrees", name


# ---- values pinned by an independent computation ----------------------------------------------------
# Each value below is computed here by nested mpmath quadrature over the figure (x across, y along;
# not the module's helpers) and compared with the closed form.

def _figure(f, A, B, Y, region="AEB", whole=False):
    def strip(t):
        r = A * mpmath.sqrt(1 - (t / B) ** 2)
        xl, xr, xc = A + Y(t) - r, A + Y(t) + r, A + Y(B)
        lo, hi = {"Ace": (xl, xc), "Bce": (xc, xr), "AEB": (xl, xr)}[region]
        return mpmath.quad(lambda s: f(s, t), [lo, hi])
    with mpmath.workdps(30):
        return mpmath.quad(strip, [-B, 0, B] if whole else [0, B])


def test_area_and_moment_about_AB_do_not_depend_on_Y():
    # §222-223 with a = 2, b = 1 (D = πab/2 = π): area 2D = 2π and moment D b²/2 = π/2 about AB for
    # Y = 0 (the ellipse), Y = -y²/2 (Euler's, c = 1/2) and Y = |y|/4 + y²/8 alike; the portions Ace
    # and Bce change with Y, their sum does not.
    for Y in (lambda t: 0 * t, lambda t: -t * t / 2, lambda t: abs(t) / 4 + t * t / 8):
        assert abs(_figure(lambda s, t: 1, 2, 1, Y, whole=True) - 2 * mpmath.pi) < 1e-12
        assert abs(_figure(lambda s, t: t * t, 2, 1, Y, whole=True) - mpmath.pi / 2) < 1e-12
    Y = lambda t: abs(t) / 4 + t * t / 8     # noqa: E731
    ace = _figure(lambda s, t: 1, 2, 1, Y, "Ace")
    # ∫y dY + (a/b)∫y²dy/√(bb-yy) = (1/8 + 1/12) + 2·π/4 (§222)
    assert abs(ace - (mpmath.mpf(1) / 8 + mpmath.mpf(1) / 12 + mpmath.pi / 2)) < 1e-12


def test_euler_figure_pinned():
    # §227 with a = 2, b = 1, c = 1/2 (D = π): AC = a - c/4 = 15/8; moment about EF a²D/2 + c²D/8 = 65π/32;
    # about aAa a²D/2 + (4a/b)∫(a+Y)²dy√(bb-yy) (§225 corrected), not the print's 2a/b.
    A, B, C = 2, 1, mpmath.mpf(1) / 2
    Y = lambda t: -C * t * t / B ** 2      # noqa: E731
    area = _figure(lambda s, t: 1, A, B, Y, whole=True)
    xc = _figure(lambda s, t: s, A, B, Y, whole=True) / area
    K = _figure(lambda s, t: (s - xc) ** 2, A, B, Y, whole=True)
    Kaa = _figure(lambda s, t: s * s, A, B, Y, whole=True)
    D_ = mpmath.pi
    assert abs(xc - mpmath.mpf(15) / 8) < 1e-12
    assert abs(K - 65 * mpmath.pi / 32) < 1e-12
    S2 = B * D_ * (8 * A * A - 4 * A * C + C * C) / (16 * A)   # §227 ∫(a+Y)²dy√(bb-yy)
    assert abs(Kaa - (A * A * D_ / 2 + 4 * A / B * S2)) < 1e-12      # §225 corrected: 4a/b
    assert abs(Kaa - (A * A * D_ / 2 + 2 * A / B * S2)) > 1            # the print's 2a/b
    # §227 as transcribed: AB²D/8 + c·c²D/128 = 2π + π/1024, not 65π/32
    assert abs(K - (16 * D_ / 8 + C ** 3 * D_ / 128)) > 0.09


def test_the_three_integrals_of_227():
    # ∫_0^b √(bb-yy) dy = πb²/4, ∫y²√ = πb⁴/16, ∫y⁴√ = πb⁶/32 (b = 1); with D = πab/2, a = 2, b = 1:
    # bD/2a, b³D/8a, b⁵D/16a -- the transcription's b³D/8a, b⁵D/16a, b⁹D/16a are the next ones along.
    D_, A, B = mpmath.pi, 2, 1
    with mpmath.workdps(30):
        vals = [mpmath.quad(lambda t, k=k: t ** k * mpmath.sqrt(1 - t * t), [0, 1]) for k in (0, 2, 4)]
    right = [B * D_ / (2 * A), B ** 3 * D_ / (8 * A), B ** 5 * D_ / (16 * A)]
    assert all(abs(v - r) < 1e-12 for v, r in zip(vals, right))
    assert abs(vals[0] - B ** 3 * D_ / (8 * A)) > 0.1


def test_c_cannot_exceed_half_a():
    # §228: with a = 2, b = 1 the branch Ace x = a - cy²/b² - a√(1 - y²/b²) stays at x >= 0 for c <= a/2
    # and runs beyond aa (x < 0) near A for c > a/2 (even slightly).
    def min_x(c):
        return min(2 - c * t * t - 2 * mpmath.sqrt(1 - t * t) for t in mpmath.linspace(0, 1, 2001))
    assert min_x(1) >= 0 and min_x(mpmath.mpf("0.7")) >= 0
    assert min_x(mpmath.mpf("1.02")) < 0 and min_x(mpmath.mpf("1.5")) < 0


def test_moment_about_EF_grows_as_ef_leaves_the_middle():
    # §228: at a = 2, b = 1 the moment about EF (quadrature) increases with c on [0, a/2], from the
    # ellipse's AB²D/8 = 2π to 2π(1 + 1/16) at c = a/2.
    Ks = []
    for C in (0, mpmath.mpf(1) / 4, mpmath.mpf(1) / 2, mpmath.mpf(3) / 4, 1):
        Y = lambda t, C=C: -C * t * t      # noqa: E731
        area = _figure(lambda s, t: 1, 2, 1, Y, whole=True)
        xc = _figure(lambda s, t: s, 2, 1, Y, whole=True) / area
        Ks.append(_figure(lambda s, t: (s - xc) ** 2, 2, 1, Y, whole=True))
    assert all(k1 < k2 for k1, k2 in zip(Ks, Ks[1:]))
    assert abs(Ks[0] - 2 * mpmath.pi) < 1e-12
    assert abs(Ks[-1] / Ks[0] - mpmath.mpf(17) / 16) < 1e-12


# ---- the engine refutes a mutated print --------------------------------------------------------------

def _mutated(name, steps, reading=None, erratum="keep"):
    p = next(q for q in D.printed if q.name == name)
    q = dataclasses.replace(p, reading=reading if reading is not None else p.reading,
                            erratum=p.erratum if erratum == "keep" else erratum)
    return dataclasses.replace(D, steps=[s for s in D.steps if s.name in steps], printed=[q], witnesses=[])


def test_a_mutated_coefficient_is_refuted():
    # §227 a²D/2 + c²D/8 with the 8 mutated to 6
    a, c = MODULE.a, MODULE.c
    rep = check_derivation(_mutated("AC-c", {"area-c", "first-moment-c", "centroid-c"},
                                    reading=(MODULE.ACc, a - c / 3)), prove=False)
    assert rep.formulas[0].verdict == "erratum"
    assert any("AC-c" in f and "no erratum" in f for f in rep.failures)
    rep = check_derivation(_mutated("moment-EF-c", {"semi-ellipse", "moment-EF-c"}, erratum=None,
                                    reading=(MODULE.KEFc, a * a * MODULE.D / 2 + c * c * MODULE.D / 6)),
                           prove=False)
    assert any("moment-EF-c" in f and "no erratum" in f for f in rep.failures)


def test_the_correction_must_hold():
    # the §225 erratum with the print's 2a/b kept in the 'correction' is rejected
    p = next(q for q in D.printed if q.name == "Aa-whole")
    a, b = MODULE.a, MODULE.b
    wrong = dataclasses.replace(p.erratum, corrected_reading=(MODULE.Kwhole, a * a * MODULE.D / 2
                                                              + 2 * a / b * MODULE.S2))
    rep = check_derivation(_mutated("Aa-whole", {"semi-ellipse", "Aa-AEB", "Aa-whole", "S2"}, erratum=wrong),
                           prove=False)
    assert any("correction does not hold" in f for f in rep.failures)


def test_growth_in_words_is_a_relation_that_refutes_its_mutant():
    """§228 'momentum ... maius fieri, quo magis ... distet': the derivative of the moment about EF in c = Oc is
    positive (pi a b c/8, proved by the signs of a, b, c); the moment claimed to fall is refuted."""
    from symfloat.engine.check import _relation
    from symfloat.engine.identity import Domain
    import sympy as sp

    from symfloat.model import Holds
    d, package = load("euler-220-228")
    m = package.statements
    dom = Domain(d.domain, tuple(d.constraints))
    p = d.get_printed("moment-grows")
    status = _relation(p.reading, d.results(), dom, "t", {"proofs": 0.0, "sampling": 0.0}).status
    falls = _relation(Holds(sp.Derivative(m.KEFc, m.c) < 0), d.results(), dom, "t", {"proofs": 0.0, "sampling": 0.0})
    assert (status, falls.status) == ("proved", "refuted")


def test_the_moment_about_AB_free_of_Y_is_read_through_the_vocabulary_and_its_mutant_is_refuted():
    """§223 'momentum respectu axis longitudinalis AB idem prodire, quicquid sit functio Y', read from the moment
    2(I_Ace + I_Bce) the module defines (issue 31): it holds; the dependence turned (the moment said to change
    with Y, or to be free of the half length a) is refuted."""
    from symfloat.model.vocabulary import DependsOn, IndependentOf

    p_, q_ = MODULE.p, MODULE.q
    printed = D.get_printed("AB-free-of-Y")
    assert printed.reading == D.reads("momentum", IndependentOf(p_, q_))

    def verdict(statement):
        return verdict_alone(D, "AB-free-of-Y", D.reads("momentum", statement))
    assert verdict(IndependentOf(p_, q_)) == "verified"
    assert verdict(DependsOn(p_)) == "erratum"
    assert verdict(IndependentOf(MODULE.a)) == "erratum"
