"""Scheeffer's words on stability read from the stability's definition (issue 31, item 2): the verdict word of a
sentence (stabil, labil) is checked against the sign of the second variation at the position it names, so a
flipped verdict word, a sentence read at the wrong position and 'stabil' where the second variation vanishes are
refuted by the engine, not by a reader."""
import sympy as sp

from symfloat import Derivation, Eq
from symfloat.engine.check import check_derivation
from symfloat.model.relation import Holds
from symfloat.model.vocabulary import Called, DependsOn, IndependentOf, Is, StableIff
from symfloat.registry import statements

a, b, s, phi, mu, om = sp.symbols("a b s varphi mu omega", positive=True)
S, TW = sp.symbols("S_d T_w")
half = sp.Rational(1, 2)
RP, RM = half + sp.sqrt(sp.Rational(1, 12)), half - sp.sqrt(sp.Rational(1, 12))     # (79)
R8P, R8M = (4 + sp.sqrt(2)) / 7, (3 - sp.sqrt(2)) / 7                                  # (80)

# Verbatim sentences of Scheeffer VI.D and VII (symfloat/sources/000_1e9760952686f295.txt, lines 934, 940, 960,
# 1146, 1186-1188)
LAW_81 = "Ein Würfel schwimmt in aufrechter Lage stabil, wenn sein spec. Gewicht  $s > 0,7887$  oder  $s < 0,2113$  ist."
UNSTABLE_81A = "so schwimmt er in aufrechter Lage labil"
HALF_CUBE = (r"D. h. ein Würfel vom spec. Gew.  $\frac{1}{2}$  kann aus der aufrechten labilen Lage nur durch Drehung "
             r"um eine horizontale Achse, die einer Kante parallel ist, in eine schiefe stabile Lage gelangen.")
UPRIGHT_DUHAMEL = (r"Für die Stabilität der aufrechten Lage ist also nach dem Duhamelschen Satz die Bedingung  "
                   r"$\frac{T_1}{V_1} - e_1 > 0$")
TURN_78B = "Im letzteren Falle bleibt die Stabilität in jeder Lage, die das Prisma durch Drehung um seine Hauptachse erhält."
DUHAMEL_104 = "so ist das Gleichgewicht stabil, wenn\n\n$$T_m - V_3 e_3 > 0 \\quad (104)$$"
LABILE_M3 = "dagegen ein labiles, wenn das Umgekehrte der Fall ist"

# The stability of VI.C-D (scheeffer-vi-cf, steps waterplane-moment and stability): the square prism tilted by phi
# in the first domain, turned about the horizontal axis at the angle mu to the tilt axis: waterplane moment over
# volume minus the height of G above B (T_1 = a^4/12, V_1 = a^2 b s, e_1 = b(1-s)/2)
T1, V1, E1 = a ** 4 / 12, a ** 2 * b * s, b * (1 - s) / 2
MOMENT = T1 * (sp.cos(mu) ** 2 / sp.cos(phi) ** 3 + sp.sin(mu) ** 2 / sp.cos(phi))
STABILITY = MOMENT / V1 - (T1 * sp.sin(phi) ** 2 / (2 * V1 * sp.cos(phi)) + E1 * sp.cos(phi))
OBLIQUE = {phi: sp.atan(sp.sqrt(2 * (V1 * E1 / T1 - 1)))}      # the oblique equilibrium (27), (54), (78b)
UPRIGHT_CUBE = {a: b, phi: 0, mu: 0}
AT_HALF_CUBE = {a: b, s: half, phi: sp.pi / 4, mu: sp.pi / 2}


def square_prism():
    d = Derivation(id="test-scheeffer-words", source="scheeffer", title="stability words", locator="test",
                   domain={a: (sp.Rational(1, 2), 2), b: (sp.Rational(1, 2), 2), s: (sp.Rational(1, 20), sp.Rational(19, 20)),
                           phi: (sp.Rational(1, 20), 1), mu: (0, sp.Rational(3, 2))})
    d.step("stability", Eq(S, STABILITY), "definition", result=S)
    d.step("moment", Eq(TW, MOMENT), "definition", result=TW)
    d.defines("stability", S)
    d.defines("moment", TW)
    return d


def verdicts(d):
    return {f.id.split("/")[1]: f.verdict for f in check_derivation(d, prove=False).formulas}


def test_the_stability_is_the_metacentric_height_upright_and_vanishes_across_the_oblique_position():
    assert sp.simplify(STABILITY.subs(phi, 0) - (T1 / V1 - E1)) == 0
    tan2 = 2 * (V1 * E1 / T1 - 1)                   # the oblique equilibrium (27), (54)
    oblique = STABILITY.subs(phi, sp.atan(sp.sqrt(tan2)))
    assert sp.simplify(oblique.subs(mu, sp.pi / 2)) == 0
    assert sp.simplify(STABILITY.subs(AT_HALF_CUBE)) == 0


def test_a_flipped_verdict_word_or_a_wrong_range_is_refuted():
    d = square_prism()
    d.says("81-heavy", "(81)", LAW_81, "stabil", Called(at=UPRIGHT_CUBE, domain={s: (RP, 1)}))
    d.says("81-light", "(81)", LAW_81, "stabil", Called(at=UPRIGHT_CUBE, domain={s: (0, RM)}))
    d.says("81-middle", "(81)", LAW_81, "stabil", Called(at=UPRIGHT_CUBE, domain={s: (R8M, R8P)}))
    d.says("81a-labil", "VI.D", UNSTABLE_81A, "labil", Called(at=UPRIGHT_CUBE, domain={s: (R8P, RP)}))
    d.says("81a-labil-on-stable", "VI.D", UNSTABLE_81A, "labil", Called(at=UPRIGHT_CUBE, domain={s: (RP, 1)}))
    assert verdicts(d) == {"81-heavy": "verified", "81-light": "verified", "81-middle": "erratum",
                           "81a-labil": "verified", "81a-labil-on-stable": "erratum"}


def test_the_half_cube_is_neutral_to_second_order_neither_stable_nor_unstable():
    # the reader's question on scheeffer-vi-d-2: the stability for the turn about G_2 H_2 vanishes there
    d = square_prism()
    d.says("stable", "VI.D", HALF_CUBE, "schiefe stabile Lage", Called(at=AT_HALF_CUBE))
    d.says("unstable", "VI.D", HALF_CUBE, "aufrechten labilen Lage", Called(at=AT_HALF_CUBE))
    d.quote("neutral", "VI.D", HALF_CUBE, reading=d.reads("indifferente Lage", Called(at=AT_HALF_CUBE)))
    d.says("stable-about-the-tilt-axis", "VI.D", HALF_CUBE, "schiefe stabile Lage", Called(at={**AT_HALF_CUBE, mu: 0}))
    assert verdicts(d) == {"stable": "erratum", "unstable": "erratum", "neutral": "verified",
                           "stable-about-the-tilt-axis": "verified"}


def test_a_sentence_naming_the_wrong_quantity_or_dependence_is_refuted():
    d = square_prism()
    upright = Is(T1 / V1 - E1, at={phi: 0, mu: 0})
    d.says("upright", "VI.C", UPRIGHT_DUHAMEL, "Stabilität der aufrechten Lage", upright)
    d.quote("upright-named-moment", "VI.C", UPRIGHT_DUHAMEL, reading=d.reads("Trägheitsmoment", upright))
    d.says("upright-wrong-sign", "VI.C", UPRIGHT_DUHAMEL, "Stabilität der aufrechten Lage",
           Is(T1 / V1 + E1, at={phi: 0, mu: 0}))
    d.says("turn", "(78b)", TURN_78B, "Stabilität", IndependentOf(om))
    d.says("turn-free-of-the-axis", "(78b)", TURN_78B, "Stabilität", IndependentOf(mu, at=OBLIQUE))
    d.says("turn-depends", "(78b)", TURN_78B, "Stabilität", DependsOn(om, at=OBLIQUE))
    assert verdicts(d) == {"upright": "verified", "upright-named-moment": "erratum", "upright-wrong-sign": "erratum",
                           "turn": "verified", "turn-free-of-the-axis": "erratum", "turn-depends": "erratum"}


def test_duhamels_criterion_in_words_and_its_mutations():
    # VII (104): stable exactly when T_m - V_3 e_3 > 0, the stability D = T_m - V_1 e_2 with V_1 e_2 = V_3 e_3
    Tm, X, V1_, V3_ = sp.symbols("T_m X V_1 V_3", positive=True)
    e2, e3, D = sp.symbols("e_2 e_3 D")
    d = Derivation(id="test-scheeffer-104", source="scheeffer", title="Duhamel", locator="test",
                   domain={Tm: (1, 3), X: (1, 3), V1_: (1, 2), V3_: (1, 2)})
    d.step("e2", Eq(e2, X / V1_), "definition", result=e2)
    d.step("e3", Eq(e3, X / V3_), "definition", result=e3)
    d.step("D", Eq(D, Tm - V1_ * e2), "definition", result=D)
    d.defines("stability", D)
    d.says("104", "(104)", DUHAMEL_104, "stabil", StableIff(Tm - V3_ * e3 > 0))
    d.says("104-labil", "VII", LABILE_M3, "labiles", StableIff(Tm - V3_ * e3 > 0))
    d.says("104-with-equality", "(104)", DUHAMEL_104, "stabil", StableIff(Tm - V3_ * e3 >= 0))
    d.says("104-wrong-volume", "(104)", DUHAMEL_104, "stabil", StableIff(Tm - V1_ * e3 > 0))
    assert verdicts(d) == {"104": "verified", "104-labil": "erratum", "104-with-equality": "erratum",
                           "104-wrong-volume": "erratum"}


def test_the_library_reads_scheeffers_stability_words_from_the_definition():
    vicf = statements("scheeffer-vi-cf")
    stability = vicf.definitions["stability"]
    p = vicf.get_printed("half-stable")
    assert isinstance(p.reading, Holds) and p.reading.condition.lhs.expr == stability
    assert p.reading.condition == (sp.Subs(stability, tuple(AT_HALF_CUBE), tuple(AT_HALF_CUBE.values())) > 0)
    assert p.erratum is not None and p.erratum.kind == "claim"
    for name in ("81-stable-heavy", "81-stable-light", "81a-unstable-heavy", "81a-unstable-light", "82-unstable"):
        assert vicf.get_printed(name).reading.condition.lhs.expr == stability
    assert vicf.get_printed("upright-duhamel").reading[0].expr == stability
    assert stability in vicf.get_printed("78b-turn").reading[0].free_symbols
    vii = statements("scheeffer-vii-viii")
    p = vii.get_printed("104-words")
    assert vii.definitions["stability"] in p.reading.condition.free_symbols
