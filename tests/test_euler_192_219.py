"""Euler, Scientia navalis III §§192–219 (stability about any horizontal axis; moments of waterplanes):
the module checks clean, the range's formulas are quoted, its errata are exactly the expected ones, the
moments of the figures are pinned by independent quadrature, Euler's claims in words are tested, and a
mutated print is refuted."""
import dataclasses
import re

import mpmath
import pytest
import sympy as sp

from symfloat.engine.check import check_derivation
from symfloat.engine.floating_witness import FloatingWitness
from symfloat.engine.witness import Case, Precision, record_decision
from symfloat.model.source import SOURCES
from symfloat.model.vocabulary import Compares, DecreasesWith, GrowsWith, IndependentOf, Is
from symfloat.registry import load

from one_formula import verdict_alone

D, PACKAGE = load("euler-192-219")
MODULE, WITNESSES = PACKAGE.statements, PACKAGE.witnesses
TEXT = SOURCES["euler"].text()
RANGE = TEXT[TEXT.index("§. 192."):TEXT.index("§. 220.")]


@pytest.fixture(scope="module")
def report(reports_by_id):
    return reports_by_id["euler-192-219"]


def _quadratures(records):
    """The quadratures beside Arb's record (issue 29): float64 where the ball decides the formula, float64 and 50
    digits where no ball decides it (the witness kind has no enclosure, or it leaves the formula undecided)."""
    certified = [r for r in records if r.get("certified")]
    decided = certified and all(record_decision(r) != "undecided" for r in certified)
    return {"float64"} if decided else {"float64", "mpmath, 50 digits"}


def test_no_check_fails(report):
    assert report.failures == []


def test_every_display_of_the_range_is_quoted():
    # The transcription of §§192-219 has no $$ display at all (every formula is set inline, $...$);
    # the first $$ displays of Cap. III are in §232.  So the requirement is met vacuously, and the
    # inline formulas are checked instead (next test).
    displays = re.findall(r"\$\$.+?\$\$", RANGE, re.S)
    assert displays == []
    missing = [x for x in displays if not any(x in p.excerpt or p.excerpt in x for p in D.printed)]
    assert missing == []


# Inline pieces of §§192-219 with '=' that are notation, not formulas to check: names given to
# quantities (M, V, b, m, n, x, y, t, u, I, K, L, the sides of the quadrilateral) and the data of
# the figures (y = a, y = b, x = a).
NOTATION = {r"$= M$", r"$= V$", r"$= b$", r"$= m$", r"$= n$", r"$= 1$", r"$= x$", r"$= y$", r"$= t$",
            r"$= u$", r"$\int y^2 \cdot w = I$", r"$\int x^2 \cdot w = K$", r"$y = a$", r"$y = b$",
            r"$x = a$", r"$Ac = a$", r"$ce = b$", r"$Bc = c$", r"$AP = x$", r"$= L$",
            r"$L = \int w \cdot w n^2$", r"$= \int w \cdot w N^2$"}


def test_every_inline_formula_of_the_range_is_quoted_or_notation():
    pieces = [x for x in re.findall(r"\$[^$]+\$", RANGE) if "=" in x]
    assert len(pieces) > 80
    missing = {x for x in pieces if not any(x in p.excerpt or p.excerpt in x for p in D.printed)}
    assert missing <= NOTATION


# The faults found (each argued in its erratum's evidence):
EXPECTED_ERRATA = {
    ("sine", "transcription", "medium"),               # §205 (xy+yt)/(xx+yy) for (xu+yt)/(xx+yy)
    ("moment-PQ-sine", "transcription", "high"),       # §208 'l' for I in I - m^2 (I - K)
    ("moment-45", "transcription", "high"),            # §208 (l+K)/2 for (I+K)/2
    ("rhombus-twice", "claim", "medium"),              # §214 'twice': four times at equal length/breadth;
                                                       # medium: per unit of area it is twice (its objection)
    ("centroid-equation", "transcription", "low"),     # §215 colons for multiplication dots, Cb for Cc; low:
                                                       # Cb stands again in §218, print or scan (its objection)
    ("centroid", "transcription", "medium"),           # §215 Ce for Cc
    ("Ace-cubes", "transcription", "medium"),          # §216 ∫y^2dx for ∫y^3dx; medium: the line reads without
                                                       # doubt, a 3 set or read as 2 (was low, issue 31)
    ("quad-L", "transcription", "high"),               # §216 D(ac+bc+cc)/3 for D(aa-ac+cc)/3; high: §218 prints
                                                       # the same expression right (was low, issue 31)
    ("quad-K", "transcription", "medium"),             # §218 D·Ce^2/4 for D·Cc^2/4
    ("ellipse-quadrant-area", "transcription", "low"),  # §219 pi/4 for pi ab/4 = D/2
    ("Cc-again", "transcription", "low"),              # §218 Cb for Cc again (second pass, line 126); low
                                                       # with its booking centroid-equation
    ("square-D", "claim", "medium"),                   # §212 'stabilitas' for the moment AB^2 D/6, read from
                                                       # the vocabulary (issue 31, item 2); medium: its objection
}


def test_second_pass_Cb_of_218_is_booked_as_the_repeat_of_215():
    # Provenance: 002_9b5669e726e363a9.txt line 126, "$Cb = \frac{c-a}{3}$" (Cc of §215 read as Cb).
    p = next(p for p in D.printed if p.name == "Cc-again")
    assert p.excerpt in TEXT.splitlines()[125] and "Cb" in p.excerpt
    assert p.erratum.same_as == "euler-192-219/centroid-equation"
    booked = next(q for q in D.printed if q.name == "centroid-equation").erratum
    assert (booked.kind, booked.confidence) == (p.erratum.kind, p.erratum.confidence) == ("transcription", "low")


def test_the_errata_are_exactly_the_expected_ones(report):
    found = {(f.id.split("/")[1], f.erratum["kind"], f.erratum["confidence"])
             for f in report.formulas if f.verdict == "erratum"}
    assert found == EXPECTED_ERRATA
    assert all(f.verdict in ("verified", "erratum") for f in report.formulas)


def test_every_moment_formula_carries_its_quadrature_records(report):
    witnessed = {"square-I", "rect-I", "rect-K", "rhombus-I", "rhombus-K", "quad-I", "quad-K",
                 "quad-L", "centroid", "moment-PQ-IK", "moment-RS-IK", "sum-invariant", "parallel-axis-rule",
                 "moment-PQ-symmetric", "moment-RS-symmetric", "moment-PQ-increasing", "ellipse-K",
                 "ellipse-I", "ellipse-quadrant-moment", "rhombus-twice", "quad-K-larger",
                 "stability-AB", "stability-EF", "stability-I", "stability-K",
                 # second pass
                 "strip-moment", "moment-PQ", "moment-RS", "area-2D", "square-area", "rect-area", "rhombus-area",
                 "ellipse-ordinate", "I-K-definitions", "polar-sum", "xy-vanishes", "square-all-axes",
                 "strip-sum-of-squares", "quadrants-cancel", "quad-area-2D", "quadrant-area-integral",
                 "L-definition", "EF-moment-definition", "sum-of-cubes", "aggregate", "equal-quadrants"}
    by_name = {f.id.split("/")[1]: f for f in report.formulas}
    for name in witnessed:
        methods = {rec["method"] for rec in by_name[name].numeric}
        assert methods - {"Arb ball arithmetic"} == _quadratures(by_name[name].numeric), name
        for rec in by_name[name].numeric:
            assert rec["seconds"] >= 0


# ---- values pinned by an independent computation ----------------------------------------------------
# Each value below is computed here by mpmath quadrature over the figure (not by the module's helpers)
# and compared with the closed form the module derives.

def _area_integral(f, x0, x1, lo, hi, breaks=()):
    with mpmath.workdps(30):
        return mpmath.quad(lambda x: mpmath.quad(lambda y: f(x, y), [lo(x), hi(x)]), [x0, *breaks, x1])


def test_quadrilateral_moments_pinned():
    # §215-218 with Ac = 1, ce = 1, Bc = 2: A = (0,0), e = (1,1), B = (3,0), f = (1,-1); D = 3/2.
    # Centroid x_C = (2a + c)/3 = 4/3, so Cc = 1/3 = (c - a)/3; K = D(a^2 + ac + c^2)/9 = 7/6;
    # the printed D(ac + bc + cc)/3 would give 4 for the moment about ef, the true value is
    # D(aa - ac + cc)/3 = 3/2.
    def hw(x):
        return x if x <= 1 else (3 - x) / 2
    area = _area_integral(lambda x, y: 1, 0, 1, lambda x: -hw(x), hw) + \
        _area_integral(lambda x, y: 1, 1, 3, lambda x: -hw(x), hw)
    xc = (_area_integral(lambda x, y: x, 0, 1, lambda x: -hw(x), hw)
          + _area_integral(lambda x, y: x, 1, 3, lambda x: -hw(x), hw)) / area
    L = sum(_area_integral(lambda x, y: (x - 1) ** 2, p, q, lambda x: -hw(x), hw) for p, q in ((0, 1), (1, 3)))
    K = sum(_area_integral(lambda x, y: (x - xc) ** 2, p, q, lambda x: -hw(x), hw) for p, q in ((0, 1), (1, 3)))
    assert abs(area - 3) < 1e-12 and abs(xc - mpmath.mpf(4) / 3) < 1e-12
    assert abs(L - mpmath.mpf(3) / 2) < 1e-12
    assert abs(K - mpmath.mpf(7) / 6) < 1e-12
    a, b, c = MODULE.a, MODULE.b, MODULE.c
    assert sp.Rational(3, 2) * (a * c + b * c + c * c).subs({a: 1, b: 1, c: 2}) / 3 == 4   # the print
    assert K - mpmath.mpf(3) / 2 * 4 / 12 > 0      # larger than the rhombus of the same AB, ef (§218)


def test_rectangle_is_four_times_the_rhombus_at_equal_length_and_breadth():
    # §214: AC = 2, CE = 1. Rectangle I = 4ab^3/3 = 8/3, rhombus I = ab^3/3 = 2/3: ratio 4, not 2.
    rect = _area_integral(lambda x, y: y ** 2, -2, 2, lambda x: -1, lambda x: 1)
    rhomb = _area_integral(lambda x, y: y ** 2, -2, 2, lambda x: -(1 - abs(x) / 2), lambda x: 1 - abs(x) / 2,
                           breaks=(0,))
    assert abs(rect - mpmath.mpf(8) / 3) < 1e-12 and abs(rhomb - mpmath.mpf(2) / 3) < 1e-12
    assert abs(rect / rhomb - 4) < 1e-14


def test_ellipse_and_oblique_axis_pinned():
    # §219: a = 3, b = 2: K = pi a^3 b/4 = 27 pi/2 = AB^2 D/8 with D = pi a b/2 = 3 pi; quadrant area pi ab/4.
    K = _area_integral(lambda x, y: x ** 2, -3, 3, lambda x: -2 * mpmath.sqrt(1 - x * x / 9),
                       lambda x: 2 * mpmath.sqrt(1 - x * x / 9))
    assert abs(K - 27 * mpmath.pi / 2) < 1e-12
    # §209: the square 2 x 2 about an axis at sine 3/5 has the same moment 4/3 as about AB (§210, §212).
    m, n = mpmath.mpf(3) / 5, mpmath.mpf(4) / 5
    P = _area_integral(lambda x, y: (m * x - n * y) ** 2, -1, 1, lambda x: -1, lambda x: 1)
    assert abs(P - mpmath.mpf(4) / 3) < 1e-12


# ---- the engine refutes a mutated print --------------------------------------------------------------

def _mutated(name, reading=None, erratum="keep"):
    p = next(q for q in D.printed if q.name == name)
    q = dataclasses.replace(p, reading=reading if reading is not None else p.reading,
                            erratum=p.erratum if erratum == "keep" else erratum)
    return dataclasses.replace(D, printed=[q], witnesses=[])


def test_a_mutated_coefficient_of_the_ellipse_is_refuted():
    # §219 EF^2 D/8 with 8 mutated to 6 (the rectangle's divisor)
    b = MODULE.b
    rep = check_derivation(_mutated("ellipse-I", reading=(MODULE.Iel, (2 * b) ** 2 * MODULE.Del / 6)), prove=False, trust_steps=True)
    assert rep.formulas[0].verdict == "erratum"
    assert any("ellipse-I" in f and "no erratum" in f for f in rep.failures)


def test_the_quad_L_correction_must_hold():
    p = next(q for q in D.printed if q.name == "quad-L")
    wrong = dataclasses.replace(p.erratum, corrected_reading=p.reading)
    rep = check_derivation(_mutated("quad-L", erratum=wrong), prove=False, trust_steps=True)
    assert any("correction does not hold" in f for f in rep.failures)


def _arm(hv, phi, dps):
    """The righting arm of the module's witness box (1 x 1 x 2 at s = 1/2, G hv above B) heeled by phi, clipped
    by the floating witness at dps digits."""
    w = FloatingWitness("arm", "", (), (), body=WITNESSES.box_with_G(sp.sympify(hv)), up=WITNESSES.HEEL,
                        density=WITNESSES.sw, quantity=WITNESSES.ARM[WITNESSES.HEEL])
    return w.measure(Case({WITNESSES.sw: sp.Rational(1, 2), MODULE.phi: sp.sympify(phi)}), Precision(dps, 0.0))


def test_the_heeled_box_arm_is_the_clipped_bodys():
    # the wall-sided box of §§192-200 (e = T = 1/2, G 1/10 above B) heeled by 1/10: the arm of step
    # righting-arm-value against exact clipping of the box 1 x 1 x 2 at 50 digits
    e, T, b, phi = sp.Rational(1, 2), sp.Rational(1, 2), sp.Rational(1, 10), sp.Rational(1, 10)
    closed = sp.sin(phi) * (e ** 2 / (3 * T) - b + e ** 2 * sp.tan(phi) ** 2 / (6 * T))
    with mpmath.workdps(50):
        clipped = _arm(b, phi, 50)
        assert abs(clipped - mpmath.mpf(sp.N(closed, 60))) < mpmath.mpf(10) ** -40
        # mutation: the arm without its third-order term (S·phi alone) misses the clipped body
        assert abs(clipped - mpmath.mpf(sp.N(sp.sin(phi) * (e ** 2 / (3 * T) - b), 60))) > mpmath.mpf(10) ** -5   # 8.4e-5


def test_negative_stability_ends_in_a_stable_heeled_equilibrium():
    # G 1/100 above the metacentre (I/V = 1/6): the clipped arm is negative at small angles and vanishes at
    # tan^2 phi = 2g/(I/V) = 3/25, where it grows (Euler §195: turned until a stable position is reached)
    g = sp.Rational(1, 100)
    phi0 = sp.atan(sp.sqrt(2 * g / sp.Rational(1, 6)))
    with mpmath.workdps(30):
        hv = sp.Rational(1, 6) + g
        assert _arm(hv, sp.Rational(1, 20), 30) < 0
        assert abs(_arm(hv, sp.N(phi0, 60), 30)) < mpmath.mpf(10) ** -25
        assert _arm(hv, sp.N(phi0, 60) + sp.Rational(1, 100), 30) > 0


# ---- sentences read through the vocabulary (issue 31): each holds, and is refuted when its words are mutated
# (the wrong quantity named, the dependence or the comparison turned); the mutant is read from the same
# definitions by the same words-to-reading route (Derivation.reads)

def _sentences():
    M = MODULE
    a, b, m, n, Iw, Kw = M.a, M.b, M.m, M.n, M.Iw, M.Kw
    unequal = dict(at={Iw: sp.Subs(M.K, (a, M.c), (M.Lq - M.tq, M.Lq + M.tq))},
                   domain={M.tq: (sp.Rational(1, 10), 1), M.Lq: (sp.Rational(11, 10), 3)})
    inverse = Is(M.Kre * (2 * b) ** 2 / (2 * a) ** 2, at={Iw: M.Ire})
    return [
        # §209: stable about both principal axes, stable about every axis; G above the metacentre of AB, not
        ("stable-about-every-axis", "stabilitatem",
         Compares(">", 0, at=M.BOTH_STABLE, domain={M.gm: (sp.Rational(1, 10), 1), M.dK: (0, 4)}),
         "stabilitatem", Compares(">", 0, at=M.BOTH_STABLE, domain={M.gm: (-1, -sp.Rational(1, 10)), M.dK: (0, 4)})),
        # §210: equal principal moments (K = I) make the stability the same about every axis; K left free it is not
        ("equal-stability-all-axes", "eandem stabilitatem", IndependentOf(m, at={Iw: sp.Subs(M.MOMENT_PQ, Kw, Iw)}),
         "eandem stabilitatem", IndependentOf(m, at={Iw: M.MOMENT_PQ})),
        # §210: the square is equally stable in every direction; the rectangle (a != b) is not
        ("square-equally-stable", "aequa erit stabile", IndependentOf(m, at={Iw: M.Psq}),
         "aequa erit stabile", IndependentOf(m, at={Iw: n ** 2 * M.Ire + m ** 2 * M.Kre})),
        # §213: I : K inversely as AB² : EF²; directly is refuted
        ("rect-inverse-ratio", "momentum", inverse,
         "momentum", Is(M.Kre * (2 * a) ** 2 / (2 * b) ** 2, at={Iw: M.Ire})),
        # §213: the same words with the stability named for the moment are refuted (M(I/V + b) is not K·EF²/AB²)
        ("rect-inverse-ratio", "momentum", inverse, "stabilitas", inverse),
        # §218: the moment about EF grows with the inequality of Ac and Bc; 'falls' is refuted
        ("unequal-parts-larger", "momentum", GrowsWith(M.tq, **unequal), "momentum", DecreasesWith(M.tq, **unequal)),
    ]


@pytest.mark.parametrize("name, words, statement, mutant_words, mutant", _sentences(),
                         ids=[f"{s[0]}-{s[3]}" for s in _sentences()])
def test_a_sentence_read_through_the_vocabulary_holds_and_its_mutant_is_refuted(name, words, statement,
                                                                                 mutant_words, mutant):
    p = D.get_printed(name)
    assert p.reading == D.reads(words, statement)          # the module's reading is the words' reading
    assert verdict_alone(D, name, D.reads(words, statement)) == "verified"
    assert verdict_alone(D, name, D.reads(mutant_words, mutant)) == "erratum"
