"""`symfloat phase`: thresholds located to 10 digits and matched with the sources' closed forms."""
import math

import mpmath
import pytest

from symfloat.report.phase import phase_record, phase_table
from symfloat.cli import main
from symfloat.comparison.thresholds import phase_with_sources


@pytest.fixture(scope="module")
def box_phase():
    # a box 1 x 2 x 3 on a coarse sweep: every threshold is still found (the source thresholds outside the
    # sweep are looked for at their own density)
    return phase_with_sources("box", "1,2,3", steps=8)


def test_box_thresholds_match_the_upright_closed_form(box_phase):
    # Scheeffer IV (18) / metazentrum: with edge k vertical over the base w x l (w the shorter), the upright
    # position is stable iff 6 s (1 - s) < (w/h)^2: s = 1/2 - sqrt(1/4 - (w/h)^2/6)
    expected = {"face z up": 0.5 - math.sqrt(0.25 - (1 / 3) ** 2 / 6),
                "face y up": 0.5 - math.sqrt(0.25 - (1 / 2) ** 2 / 6)}
    for label, value in expected.items():
        found = [t for t in box_phase.thresholds if t.label == label and t.density < 0.5]
        assert len(found) == 1 and abs(found[0].density - value) < 1e-10
        assert found[0].source, "the source's threshold is named"
        upper = [t for t in box_phase.thresholds if t.label == label and t.density > 0.5]
        assert abs(upper[0].density - (1 - value)) < 1e-10           # the duality s <-> 1 - s
    assert box_phase.duality_ok and box_phase.unmatched_sources == []


def test_phase_outputs(box_phase, tmp_path):
    record = phase_record(box_phase)
    assert {"body", "dims", "sweep", "thresholds", "duality_holds"} <= set(record)
    from test_json_schemas import errors
    assert errors("phase", record) == []                  # symfloat/schemas/phase.schema.json
    assert "duality s ↔ 1 − s: holds" in phase_table(box_phase)


def test_the_table_cites_each_closed_form_once_with_its_places(box_phase):
    # the sources that print a threshold by the same closed form are one citation of their places (the record keeps
    # one entry per derivation): the box's upright threshold is printed by the web lesson and by Scheeffer in
    # several sections, and no derivation's id reaches the table
    from symfloat import registry
    table = phase_table(box_phase)
    upright = next(line for line in table.splitlines() if "face z up: stable below" in line)
    assert upright.count(" = ") == 1 and "Scheeffer 1902 IV, " in upright and "Auftrieb Stabilität “" in upright
    assert not any(f"{i} " in table for i in registry.ids())


def test_the_table_shows_a_records_closed_forms_in_signs():
    # the record keeps SymPy's text (docs/figures/phase-cube.json: "1/2 - sqrt(3)/6", "at s -+ 1e-06"); the table
    # a reader sees writes their signs
    from symfloat.numbers import signs
    assert signs("1/2 - sqrt(3)/6") == "1/2 − √3/6" and signs("sqrt(2)/7 + 4/7") == "√2/7 + 4/7"
    assert signs("at s -+ 1e-06 the solver finds") == "at s ± 1e-06 the solver finds"
    assert signs("1/4") == "1/4"


def _box_fold_xz():
    """The fold that ends the tilted window above s_z of the 1 x 2 x 3 box, independently: mpmath.findroot at
    30 digits on U'(theta) = U''(theta) = 0 in the x-z plane, the derivatives of the exactly clipped body
    (refine._local_mp), not the solver's float64 extended system: 0.0190009553001899470923612444513."""
    from symfloat.geometry.floating import box
    from symfloat.solver.refine import _local_mp
    with mpmath.workdps(30):
        poly = box(1, 2, 3, dps=30)

        def equations(theta, s):
            u = (mpmath.sin(theta), mpmath.mpf(0), mpmath.cos(theta))
            e = (mpmath.cos(theta), mpmath.mpf(0), -mpmath.sin(theta))
            st, g, H = _local_mp(poly, u, s)
            b = [sum(basis[k] * e[k] for k in range(3)) for basis in st.basis]
            return g[0] * b[0] + g[1] * b[1], sum(b[i] * H[i, j] * b[j] for i in range(2) for j in range(2))
        return float(mpmath.findroot(equations, (mpmath.radians(6.56), mpmath.mpf("0.0190009553")))[1])


def test_box_window_above_s_z_is_found_with_its_dual(box_phase):
    # issue 14: the stable window of the 4 tilted copies from s_z = (1 - sqrt(25/27))/2 (a pitchfork of face z
    # up, Scheeffer IV (18) with w/h = 1/3) to a fold near 0.0190 was missing from `phase box --dims 1,2,3`;
    # the sweep of 8 densities (spacing 1/9) has no density in it.  Both ends, and their duals at 1 - s
    s_z, fold = 0.5 - math.sqrt(0.25 - (1 / 3) ** 2 / 6), _box_fold_xz()
    tilted = [t for t in box_phase.thresholds if t.label == "tilted in the x-z plane"]
    for value, change in ((s_z, "stable above"), (fold, "stable below"),
                          (1 - fold, "stable above"), (1 - s_z, "stable below")):
        found = [t for t in tilted if abs(t.density - value) <= max(t.bracket, 1e-15) and t.change == change]
        assert len(found) == 1, (value, change)
        assert found[0].bracket < 1e-12
    assert box_phase.unpaired == []


def test_follow_finds_the_cube_fold_from_a_birth_at_a_vertex():
    # the atlas's cube cell (sweep 1/20 ... 19/20, no density in the diagonal window) lost the fold that ends the
    # diagonal positions: born at (3 - sqrt 2)/7 where the waterplane passes a vertex, their second variation is
    # zero to rounding 1e-6 past the birth, and the continuation gave up there.  The fold: Scheeffer X (171),
    # 1 - 0.76230923886637546 at 30 digits (tests/test_scheeffer_x.py)
    from fractions import Fraction

    from symfloat.geometry.floating import box
    from symfloat.solver import make_scene
    from symfloat.solver.phase import _follow, _stable, _thresholds_between
    from symfloat.solver.solve import body_scale
    from symfloat.solver.symmetry import box_group
    base = make_scene("cube", "1/2")
    poly, group, scale = box(*base.dims), box_group(base.dims), body_scale(base)
    birth = (3 - math.sqrt(2)) / 7
    sa, sb = Fraction(birth - 1e-3), Fraction(birth + 1e-3)
    born = _thresholds_between(poly, group, scale, _stable(make_scene("cube", sa)), _stable(make_scene("cube", sb)),
                               float(sa), float(sb))
    assert [(t.label, t.change) for t in born] == [("tilted, |u_x| = |u_y|", "stable above")]
    ends = _follow(poly, group, scale, born, [1 / 20 + k / 10 for k in range(10)])
    fold = 1 - 0.76230923886637546
    assert [(t.label, t.change) for t in ends] == [("tilted, |u_x| = |u_y|", "stable below")]
    assert abs(ends[0].density - fold) <= max(ends[0].bracket, 1e-13)


def test_no_threshold_at_the_look_density_next_to_a_ring_end():
    # issue 33: `phase box --dims 1,3/2,1` reported "tilted in the y-z plane" stable below 1/12 - 1e-6 exactly
    # (and its dual 11/12 + 1e-6): the source's look at the ring's end 1/12 -+ 1e-6 (where the waterplane passes
    # a vertex) found a short arc of equilibria there that the scene reports as one class stable across it,
    # flat along it, which the bisection's tracking cannot follow from its first step.  No threshold is made
    # of it; the ring's end itself is located at 1/12 (the threshold list checked in the slow run)
    from fractions import Fraction

    from symfloat.geometry.floating import box
    from symfloat.solver import make_scene
    from symfloat.solver.phase import _stable, _thresholds_between
    from symfloat.solver.solve import body_scale
    from symfloat.solver.symmetry import box_group
    base = make_scene("box", "1/2", "1,3/2,1")
    sa, sb = Fraction(1, 12) - Fraction(1, 10 ** 6), Fraction(1, 12) + Fraction(1, 10 ** 6)
    a, b = _stable(make_scene("box", sa, "1,3/2,1")), _stable(make_scene("box", sb, "1,3/2,1"))
    # the scene's view: the short arc (a piece of the ring round y, labelled an arc) stable below, not above
    assert "ring around y" in set(a) - set(b)
    found = _thresholds_between(box(*base.dims), box_group(base.dims), body_scale(base), a, b, float(sa), float(sb))
    assert not [t for t in found if abs(t.density - float(sa)) < 1e-9]


def test_each_density_is_solved_once(monkeypatch):
    # two printed thresholds at 1/2 that the solver does not find: each is looked for at 1/2 -+ 1e-6 and
    # 1/2 -+ 1e-3, the same four densities; the diagram solves every density once and both looks still decide
    from collections import Counter

    from symfloat.solver import phase
    solve, solved = phase.solve, Counter()

    def counting(scene):
        solved[scene.density] += 1
        return solve(scene)
    monkeypatch.setattr(phase, "solve", counting)
    known = [{"value": 0.5, "label": label, "change": "stable above", "claim": "unstable beyond", "locators": ["X"],
              "errata": [], "derivation": "d", "expression": ""} for label in ("corner up", "edge up (xz)")]
    diagram = phase.phase_diagram("cube", densities=[0.4, 0.6], known=known)
    assert len(solved) == 6 and set(solved.values()) == {1}
    assert [k["seen"] for k in diagram.unmatched_sources] == ["stable on both sides", "stable on neither side"]


def test_a_thin_box_sweeps_only_the_densities_the_solver_handles(capsys):
    # a box 1 x 0.03 x 1 is handled for min(s, 1 - s) >= 1e-4 / 0.03 = 0.0033; the sources' thresholds were
    # swept from s = 1/400 all the same, and the command stopped on a density the user never gave (exit 2)
    assert main(["phase", "box", "--dims", "1,0.03,1", "--steps", "4", "--quiet"]) == 0
    assert "duality s ↔ 1 − s: holds" in capsys.readouterr().out
