"""Predictors decide with the quoted readings (``Derivation.evaluator``), not with conditions typed again
(issue 13, item 3).  Expected values: the printed formulas named, evaluated by hand from the print."""
from __future__ import annotations

import copy
import dataclasses
import math
from fractions import Fraction

import pytest
import sympy as sp

from symfloat.model.prediction import Scene
from symfloat.registry import load

D, _PACKAGE = load("scheeffer-vi-cf")
CF, CF_SYMBOLS = _PACKAGE.predictors, _PACKAGE.statements


def test_an_evaluator_is_exact_on_rationals_and_float_otherwise():
    # (75): (a/b)^2 > 6 s (1 - s); at a = 1, b = 2, s = 3/10: 1/4 - 126/100 = -101/100 (the upright square
    # prism is unstable there)
    assert CF.MARGIN_75(Fraction(1), Fraction(2), Fraction(3, 10)) == sp.Rational(-101, 100)
    assert abs(CF.MARGIN_75(1.0, 2.0, 0.3) + 1.01) < 1e-15
    # (78d) as printed, s < 1/2: s^2 / (6 s (1 - s) - (a/b)^2) = (9/100) / (101/100) = 9/101
    assert CF.BOUND_78D(Fraction(1), Fraction(2), Fraction(3, 10)) == sp.Rational(9, 101)


def test_the_correction_is_read_when_asked():
    # (81a) prints tg^2 phi_1 = 2 {b s (1 - s) - 1}; the erratum reads 6 for the scan's b: at s = 1/2 and b = 1
    # the print gives 2 (1/4 - 1) = -3/2, the correction 2 (6/4 - 1) = 1
    s, b = CF_SYMBOLS.s, CF_SYMBOLS.b
    assert D.evaluator("81a", (b, s), 1)(1, Fraction(1, 2)) == sp.Rational(-3, 2)
    assert D.evaluator("81a", (s,), 1, corrected=True)(Fraction(1, 2)) == 1


def test_the_evaluator_follows_a_mutated_reading():
    # mutation: 6 s (1 - s) -> 5 s (1 - s) in (75); at a/b = 1/2, s = 3/10 the margin becomes 1/4 - 105/100
    a, b, s = CF_SYMBOLS.a, CF_SYMBOLS.b, CF_SYMBOLS.s
    d = copy.copy(D)
    d.printed = [dataclasses.replace(p, reading=((a / b) ** 2 - 5 * s * (1 - s), p.reading[1])) if p.name == "75"
                 else p for p in D.printed]
    assert d.evaluator("75", (a, b, s), 0)(1, 2, Fraction(3, 10)) == sp.Rational(-4, 5)


def test_a_member_with_other_quantities_is_refused():
    # (87-cos2), member 0 is T_1 itself with F_1: asking for it in r alone names what is missing
    with pytest.raises(ValueError, match="depends on"):
        D.evaluator("87", (CF_SYMBOLS.r,), 1)


def test_the_ngon_evaluators_are_the_printed_closed_forms():
    # (87): T_1 = F_1 r^2/12 (2 + cos(2 pi/n)), F_1 = n r^2/2 sin(2 pi/n); the square (n = 4, r = 1): F_1 = 2,
    # T_1 = 2/12 * 2 = 1/3 (= a^4/12 with a = sqrt 2, VI.E)
    assert abs(CF.T1_87(1.0, 4) - 1 / 3) < 1e-15
    # (88): u_m = r sin((n - 2) pi/(2n) + omega): r cos(pi/n) at omega = 0, r at omega = pi/n
    import math
    assert abs(CF.UM_88(2.0, 6, 0.0) - 2 * math.cos(math.pi / 6)) < 1e-15
    assert abs(CF.UM_88(2.0, 6, math.pi / 6) - 2.0) < 1e-15


def test_hasab_and_metazentrum_predictors_read_their_conditions():
    import math
    hasab = load("hasab")[1].predictors
    # the printed condition rho^2 - rho + 1/6 > 0 (hasab, solution, stability): -1/12 at rho = 1/2, unstable
    assert hasab.CONDITION(Fraction(1, 2)) == -1 and hasab.CONDITION(Fraction(1, 10)) == 1
    # the remark with its radical restored (the erratum): (3l + sqrt(9l^2 - 6))/(6l) at l = 2
    assert abs(hasab.REMARK(2.0) - (6 + math.sqrt(30)) / 12) < 1e-15
    meta = load("metazentrum")[1].predictors
    # e = b^2/(6c^2) - d/(2c)(1 - d/(2c)) as printed (L4): b = 1/2, c = 1, d = 1 gives 1/24 - 1/4 = -5/24
    assert meta.E_PRINTED(Fraction(1, 2), Fraction(1), Fraction(1)) == sp.Rational(-5, 24)


def test_scheeffer_x_locates_the_roots_of_171_as_read():
    import mpmath
    import numpy as np
    x = load("scheeffer-x")[1].predictors
    # (172) as read: (4 + sqrt 2)/7 = 0.77345908...
    assert abs(x.S172 - 0.7734590803390136) < 1e-15
    # (171): 2T {z^2 + (1-s)^2} - z^3 (1-x) - z^2 (1-s), 2T = 1/6 + (1-x)^2 - x^4/12, z = 1 - x + x^3/6; at x = 1,
    # s = 5/6: 2T = 1/12, z = 1/6: 1/12 (1/36 + 1/36) - 0 - 1/36 * 1/6 = 0 (the root at x = 1 of the note of (172))
    assert x.f_num(1, Fraction(5, 6)) == 0
    # the same function on floats, arrays and mpmath numbers
    v = x.f_num(0.3, 0.77)
    assert abs(x.f_num(np.array([0.3]), 0.77)[0] - v) < 1e-16
    assert abs(float(x.f_num(mpmath.mpf("0.3"), mpmath.mpf("0.77"))) - v) < 1e-16


def test_scheeffer_iv_v_tilts_from_54_and_55_as_read():
    import sympy as sp
    iv = load("scheeffer-iv-v")[1].predictors
    # (54): tg^2 phi_1 = F_1 b^2 s(1-s)/T_1 - 2; the unit square base (F_1 = 1, T_1 = 1/12), b = 2, s = 1/2: 12 - 2
    assert iv.TAN2_54(1, 2, Fraction(1, 12), Fraction(1, 2)) == 10
    # (55): b(1-s)/u_m for s > 1/2, b s/u'_m below; exact with an irrational u_m (the half diagonal 1/sqrt 2)
    assert iv.BOUND_55(2, Fraction(3, 4), Fraction(1, 2), Fraction(1, 2)) == 1
    assert iv.BOUND_55(2, Fraction(1, 4), sp.sqrt(2) / 2, sp.sqrt(2) / 2) == sp.sqrt(2) / 2


def test_scheeffer_vi_ab_predictors_read_65_64_70_73():
    ab = load("scheeffer-vi-ab")[1].predictors
    # a = 1, b = 2 (q = (a/b)^2 = 1/4), s = 3/10, s(1-s) = 21/100: (65) I: 1/4 - 252/100 = -227/100; (65) II, lower
    # row: q - 3/2 s (8 - 9 s) = 1/4 - 477/200 = -427/200; (64), lower row: 6 s (2 - 3 s) - q = 198/100 - 1/4
    assert ab.MARGIN_65(1, 2, Fraction(3, 10)) == sp.Rational(-227, 100)
    assert ab.RING_65(1, 2, Fraction(3, 10))[2] == sp.Rational(-427, 200)
    assert ab.ARC_64(1, 2, Fraction(3, 10))[1] == sp.Rational(173, 100)
    # the cylinder r = 1, b = 2 (K2 = (2r/b)^2 = 1): (70) 1 - 8 s + 8 s^2 = -17/25; (73) lower row K2 - 2 s (4 - 5 s)
    assert ab.MARGIN_70(1, 2, Fraction(3, 10)) == sp.Rational(-17, 25)
    assert ab.LIMIT_73(1, 2, Fraction(3, 10))[2] == sp.Rational(-1, 2)


def test_scheeffer_vii_viii_strips_from_103_117_121b_122_as_read():
    _, package = load("scheeffer-vii-viii")
    v = package.predictors
    # the cube (F_1 = 1, b = 1) with a dry strip of width w = 1/2 (F = 1/2, x_s = 1/4): (103a) tan = (1 - s)/(1/8)
    assert v.TAN_103A(1, 1, Fraction(3, 4), Fraction(1, 2), Fraction(1, 4)) == 2
    # (103b) there, with T = 1/24, x_0 = 0: 1/24 (1 + 2) - 1/8 = 0, the box equilibrium at tan phi = 2, s = 3/4
    assert v.EQ_103B(Fraction(1, 24), 1, 1, Fraction(3, 4), Fraction(1, 2), Fraction(1, 4), 0) == 0
    # the designed cube equilibrium of tests/test_scheeffer_vii_viii.py: s = 71/98, tan phi = 4/3, labile by (117)
    assert any(abs(t - 4 / 3) < 1e-12 and stab == "unstable" for t, stab in v._strip2(1.0, 1.0, 1.0, 71 / 98))
    # (121b): the dry volume F_1 b (1 - s); (122) at the third-region box of the same tests (base A x 1, height 1,
    # top strip w = 1/2, A = 2 (w - x_0)): tan phi = 5/2
    assert v.DRY_121B(2, 3, Fraction(1, 4)) == Fraction(9, 2)
    p = package.witnesses._params("box3-eq")
    A = float(2 * (sp.Rational(1, 2) - p[package.statements.x0]))
    assert any(abs(t - 5 / 2) < 1e-12 for t, _ in v._strip3(A, 1.0, 1.0, float(p[package.statements.s])))


@pytest.mark.parametrize("offset, stability", [(Fraction(507, 10 ** 11), "stable"), (Fraction(1, 10 ** 10), "stable"),
                                               (Fraction(-5, 10 ** 9), "unstable"), (Fraction(-1, 10 ** 9), "unstable")])
def test_scheeffer_vii_viii_keeps_the_edge_up_root_next_to_its_pitchfork(offset, stability):
    v = load("scheeffer-vii-viii")[1].predictors
    # the box 1 x 1 x 2 turned about its long edge, edge up (tan phi = 1, the square section's diagonal): its
    # stability changes at 9/32 (Scheeffer IX (140); tests/test_phase_log.py derives 9/32 from GM of the edge-up
    # section), where (103b) has a triple root.  A sign scan on a grid lost the root at 9/32 + 5.07e-9 and
    # 9/32 - 5e-9 (docs/atlas.md); exact isolation keeps it on both sides, with (117) deciding the change.
    scene = Scene(body="box", density=Fraction(9, 32) + offset, dims=(Fraction(1), Fraction(1), Fraction(2)))
    edge_up = [p for p in v.predict(scene) if abs(abs(p.up[0]) - abs(p.up[1])) < 1e-12 and p.up[2] == 0]
    assert [p.stability for p in edge_up] == [stability]
    assert "117" in edge_up[0].printed


# ---- Scheeffer IX: the case tables decide with the readings of the printed formulas ----------------------------
IXD, IX_PACKAGE = load("scheeffer-ix")
IX, IXS = IX_PACKAGE.predictors, IX_PACKAGE.statements
R = Fraction


def _ix_mutated(name, member, change):
    """A copy of scheeffer-ix whose reading of *name* has member *member* replaced by change(that member)."""
    d = copy.copy(IXD)
    d.printed = [dataclasses.replace(p, reading=tuple(change(m) if k == member else m for k, m in enumerate(p.reading)))
                 if p.name == name else p for p in IXD.printed]
    return d


def _tables(s, ratio):
    return lambda: IX.tables_prediction(s, ratio)


def _box(s, *dims):
    return lambda: [(p.up, p.stability, p.printed) for p in IX.predict(Scene(body="box", density=s, dims=dims))]


a_, b_, c_, s_, z_, t_ = IXS.a, IXS.b, IXS.c, IXS.s, IXS.z, IXS.t
_IX_MUTATIONS = {
    # (a/b)^2 > 6 s(1-s) -> 5 s(1-s); s = 3/5, a/b = 57/50: n = 1.2996 between 5 s(1-s) = 1.2 and 6 s(1-s) = 1.44, the
    # upright position turns stable
    "UPRIGHT_132A": ("132a", (a_, b_, s_), 0, None, lambda m: (a_ / b_) ** 2 - 5 * s_ * (1 - s_), _tables(R(3, 5), R(57, 50))),
    # 6 s(1-s) > (a/b)^2 of (132b) -> 5 s(1-s): the oblique position of the first region goes, same point
    "OBLIQUE_132B": ("132b", (a_, b_, s_), 0, None, lambda m: sp.Matrix([5 * s_ * (1 - s_) - (a_ / b_) ** 2, m[1]]),
                     _tables(R(3, 5), R(57, 50))),
    # (125) 12 -> 13: its tilt moves
    "TAN2_125": ("125", (a_, b_, s_), 1, None, lambda m: 13 * (b_ / a_) ** 2 * s_ * (1 - s_) - 2, _tables(R(3, 5), R(57, 50))),
    # (140) s <= 23/32 -> s <= 3/4: at s = 73/100, n = 1.004 the three roots of (162) II become the one of (162a) VI
    "BELOW_140": ("140", (s_,), 0, None, lambda m: sp.Rational(3, 4) - s_, _tables(R(73, 100), R(501, 500))),
    # (162a) VI: rho - n -> rho - n + 2: at s = 7/10, a/b = 3/2 (n = 2.25 > rho = 1.08) a stable root appears
    "ROOT_162A": ("162a", (a_, b_, s_), 0, 0, lambda m: sp.Matrix([m[0] + 2, m[1]]), _tables(R(7, 10), R(3, 2))),
    # (162) n - rho -> n - rho - 1: at s = 73/100, a/b = 11/10 (row V, none) row I (one stable)
    "ENDS_162": ("162", (a_, b_, s_), 0, None, lambda m: sp.Matrix([m[0] - 1, m[1]]), _tables(R(73, 100), R(11, 10))),
    # t = (119 - 128 s)/27 -> (120 - 128 s)/27: n_1 at s = 73/100 from 1.00631 to 1.0011, and n = 1.004004 (a/b =
    # 501/500) rises from row II (three roots) to row I (one)
    "T_147": ("t-of-s", (s_,), 1, None, lambda m: (120 - 128 * s_) / 27, _tables(R(73, 100), R(501, 500))),
    # (156) n_1 - 1/100: the same change of row
    "N1_156": ("156", (t_,), 1, 0, lambda m: sp.Matrix([m[0] - sp.Rational(1, 100), m[1]]), _tables(R(73, 100), R(501, 500))),
    # (136) -4 n sigma^2 -> -5 n sigma^2: the root z (and its tilt) at s = 7/10, a/b = 51/50 moves (the quartic's
    # terms, compiled from the reading)
    "TERMS_136": ("136", (z_, a_, b_, s_), 1, None, lambda m: m - IXS.n * IXS.sg ** 2, _tables(R(7, 10), R(51, 50))),
    # (a/b)^2 > 1/(6 s(1-s)) -> 1/(5 s(1-s)): at s = 4/5, a/b = 21/20 (n = 1.1025) the oblique of the third region goes
    "UNSTABLE_3": ("unstable-3", (a_, b_, s_), 0, None, lambda m: (a_ / b_) ** 2 - 1 / (5 * s_ * (1 - s_)),
                   _tables(R(4, 5), R(21, 20))),
    # (165) 1/rho - n -> 1/rho - n - 1/10: the same oblique leaves the third region (1/rho = 1.136)
    "BOUND_165": ("165", (a_, b_, s_), 0, None,
                  lambda m: IXS.PW(1 / IXS.rho_s - (a_ / b_) ** 2 - sp.Rational(1, 10), 0),
                  _tables(R(4, 5), R(21, 20))),
    # (166) 12 -> 13: its tilt moves
    "COT2_166": ("166", (a_, b_, s_), 1, None, lambda m: 13 * (a_ / b_) ** 2 * s_ * (1 - s_) - 2, _tables(R(4, 5), R(21, 20))),
    # (b/a)^2 > 6 s(1-s) -> 5 s(1-s): at s = 4/5, a/b = 21/20 the other upright position (0.907 against 0.96, 0.8)
    # turns stable
    "UPRIGHT_3": ("upright-3", (a_, b_, s_), 0, None, lambda m: (b_ / a_) ** 2 - 5 * s_ * (1 - s_), _tables(R(4, 5), R(21, 20))),
    # (123) 6 -> 5: the box 21/20 x 1 x 11/10 at s = 7/10 with y up (1.1025 against 1.26, 1.05) turns stable
    "FACE_123": ("123", (a_, b_, s_), 0, None, lambda m: (a_ / b_) ** 2 - 5 * s_ * (1 - s_),
                 _box(R(7, 10), R(21, 20), R(1), R(11, 10))),
    # (163) HG^2 -> 10 HG^2: the stable root of the second region of the box 51/50 x 1 x 3 at s = 7/10 no longer
    # has HG < c
    "HG_163": ("163", (a_, b_, c_, s_, z_), 0, None, lambda m: (c_ / b_) ** 2 - 10 * ((c_ / b_) ** 2 - m),
               _box(R(7, 10), R(51, 50), R(1), R(3))),
    # (127) T_1^1 - T_1 -> T_1 - T_1^1: the first region's oblique positions of the box 21/20 x 1 x 11/10 flip
    "PERP_127": ("127", (a_, c_), 0, 2, lambda m: sp.Matrix([m[0], m[1], -m[2]]), _box(R(7, 10), R(21, 20), R(1), R(11, 10))),
}


@pytest.mark.parametrize("attribute", sorted(_IX_MUTATIONS))
def test_scheeffer_ix_tables_follow_a_mutated_reading(attribute, monkeypatch):
    name, symbols, member, row, change, predict = _IX_MUTATIONS[attribute]
    before = predict()
    mutated = _ix_mutated(name, member, change)
    monkeypatch.setattr(IX, attribute, IX._case_above_half(name, symbols, member, mutated) if attribute == "BOUND_165"
                        else IX._terms_of(mutated.evaluator(name, symbols, member)) if attribute == "TERMS_136"
                        else mutated.evaluator(name, symbols, member, row=row))
    assert predict() != before


def test_scheeffer_ix_tilt_of_the_second_region_follows_134():
    # (134) x^2 = 2 a b (1-s) tg phi_2 -> 3 a b (1-s) tg phi_2: the tilt of the root at s = 7/10, a/b = 51/50 moves,
    # its z stays
    before = IX.tables_prediction(R(7, 10), R(51, 50))
    mutated = _ix_mutated("134", 1, lambda m: 3 * a_ * b_ * (1 - s_) * sp.tan(IXS.phi))
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(IX, "TAN_134", IX._tan_134(mutated))
        after = IX.tables_prediction(R(7, 10), R(51, 50))
    (old,), (new,) = ([e for e in x if e["region"] == 2] for x in (before, after))
    assert old["z"] == new["z"] and abs(math.tan(new["phi"]) / math.tan(old["phi"]) - 2 / 3) < 1e-12


def test_scheeffer_ix_rows_of_162_are_read():
    # (162) II: 'drei Gleichgew. (stabil, labil, stabil)' read as (+1, -1, +1); mutated to (-1, +1, -1) the three
    # roots at s = 73/100, n = 1.004004 (a/b = 501/500 < sqrt n_1) change their stabilities
    assert [e["stability"] for e in IX.tables_prediction(R(73, 100), R(501, 500)) if e["region"] == 2] == \
        ["stable", "unstable", "stable"]
    mutated = _ix_mutated("162-II", 1, lambda m: sp.Matrix(list(m[:4]) + [-1, 1, -1]))
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(IX, "TABLE_162", dict(IX.TABLE_162, II=mutated.evaluator("162-II", (), 1)()))
        after = IX.tables_prediction(R(73, 100), R(501, 500))
    assert [e["stability"] for e in after if e["region"] == 2] == ["unstable", "stable", "unstable"]
