"""The floating-body witness of the witness library against closed forms it must not use.

References: a box a x b x c floating upright (c vertical) at density s has draught s c (Archimedes), G at
c/2 above the bottom, B at s c / 2, waterplane a x b with I = a b^3 / 12 and b a^3 / 12 (the rectangle's
second moments), hence the metacentric height min(a b^3, b a^3) / (12 a b s c) - c (1 - s) / 2.
"""
import math
from fractions import Fraction

import mpmath
import pytest
import sympy as sp

from symfloat.engine.floating_witness import QUANTITIES, Body, FloatingWitness, number
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case

A, B, C, S = sp.symbols("a b c s", positive=True)
CASE = Case({A: 3, B: 2, C: 1, S: sp.Rational(2, 5)}, label="box 3 x 2 x 1 at s = 2/5")
EXACT = {                                               # closed forms at the case, from the module docstring
    "draught": sp.Rational(2, 5),
    "immersed volume": sp.Rational(12, 5),
    "G above water": sp.Rational(1, 2) - sp.Rational(2, 5),
    "B below water": sp.Rational(1, 5),
    "G above B": sp.Rational(1, 2) - sp.Rational(1, 5),
    "waterplane area": sp.Integer(6),
    "I min": sp.Rational(3 * 8, 12),
    "I max": sp.Rational(2 * 27, 12),
    "metacentric radius": sp.Rational(2, 1) / sp.Rational(12, 5),
    "metacentric height": sp.Rational(5, 6) - sp.Rational(3, 10),
    "stability sign": sp.Integer(1),
    "stable": sp.Integer(1),
    "B - G, x": sp.Integer(0),                          # G at the centre, B on the axis
    "B - G, y": sp.Integer(0),
    "B - G, z": sp.Rational(1, 5) - sp.Rational(1, 2),  # B at s c/2 = 1/5 above the bottom, G at c/2
    "top clearance": sp.Rational(3, 5),                 # c - s c: the top face above the water
    "bottom clearance": sp.Rational(2, 5),              # s c: the bottom face below it
    "waterplane corners": sp.Integer(4),                # the rectangle a x b
    "face clearance": sp.Rational(2, 5),                # the lesser of the two
    "water level": sp.Rational(2, 5) - sp.Rational(1, 2),  # s c above the bottom face, which is c/2 below the origin
    "freeboard": sp.Rational(3, 5),                     # the top face, c - s c
    "waterplane centroid, x": sp.Integer(0),            # the centre of the rectangle, at the water level
    "waterplane centroid, y": sp.Integer(0),
    "waterplane centroid, z": sp.Rational(2, 5) - sp.Rational(1, 2),
    "waterplane tensor, xx": sp.Rational(2 * 27, 12),   # int x^2 dA = b a^3 / 12
    "waterplane tensor, yy": sp.Rational(3 * 8, 12),    # int y^2 dA = a b^3 / 12
    "waterplane tensor, xy": sp.Integer(0),
    "waterplane tensor, xz": sp.Integer(0),             # the waterplane is horizontal: no z extent
    "waterplane tensor, yz": sp.Integer(0),
    "waterplane tensor, zz": sp.Integer(0),
    # an unmarked body is split by the water plane itself: the lower part is all of the immersed part (volume
    # a b s c = 12/5, its centroid s c / 2 = 1/5 deep), the upper part is empty
    "lower part volume": sp.Rational(12, 5),
    "lower part moment": sp.Rational(12, 5) * sp.Rational(1, 5),
    "upper part volume": sp.Integer(0),
    "upper part moment": sp.Integer(0),
}


def _named(quantity):
    """A quantity the tests' helpers take by its name, or as an expression in measured ones."""
    return measured(quantity) if isinstance(quantity, str) else quantity


def witness(name, case=CASE, up=(0, 0, 1)):
    return FloatingWitness(name, name, ("f",), (case,), body=Body.box(A, B, C), up=up, density=S,
                           quantity=measured(name))


def test_every_quantity_is_tested():
    assert set(EXACT) == set(QUANTITIES)


@pytest.mark.parametrize("quantity", sorted(EXACT))
def test_quantities_of_a_floating_box_agree_with_their_closed_forms(quantity):
    w = witness(quantity)
    for method in w.methods:
        value = w.measure(CASE, method)
        assert abs(float(value) - float(EXACT[quantity])) <= 1e-12, (quantity, method.name)


def test_the_witness_confirms_a_formula_and_refutes_its_mutation():
    # the draught formula s c, and the same with its coefficient changed to 21/20 s c
    d = sp.Symbol("d")
    out = witness("draught").run({"f": (d, S * C), "f#mutated": (d, sp.Rational(21, 20) * S * C)})
    assert out["f"].agrees and not out["f#mutated"].agrees
    assert max(r["rel_error"] for r in out["f#mutated"].records) == pytest.approx(1 / 21, rel=1e-12)


def test_an_unstable_box_and_a_heeled_one():
    # a 1 x 1 x 1 cube at s = 1/2 upright: GM = 1/(12 * 1/2) - 1/4 < 0 (unstable, Scheeffer VI.C)
    cube = Case({A: 1, B: 1, C: 1, S: sp.Rational(1, 2)})
    assert witness("stability sign", cube).measure(cube, witness("stable").methods[1]) == -1
    assert witness("stable", cube).measure(cube, witness("stable").methods[0]) == 0
    # heeled by 45 degrees about x, the half-immersed cube still displaces half its volume
    heeled = witness("immersed volume", cube, up=(0, -sp.sin(sp.pi / 4), sp.cos(sp.pi / 4)))
    assert abs(float(heeled.measure(cube, heeled.methods[1])) - 0.5) < 1e-30


def test_a_sign_at_a_threshold_is_refused():
    # the square log at s = (3 - sqrt 3)/6 has metacentric height 0 (hasab, the thresholds)
    at = Case({A: 1, B: 4, C: 1, S: (3 - sp.sqrt(3)) / 6})
    w = FloatingWitness("sign", "sign", ("f",), (at,), body=Body.box(A, B, C), up=(1, 0, 0), density=S,
                        quantity=measured("stability sign"))
    with pytest.raises(ValueError, match="cannot decide the sign"):
        w.measure(at, w.methods[1])


def test_an_unknown_quantity_is_one_clear_error():
    with pytest.raises(ValueError, match="unknown quantity 'volume'"):
        witness("volume")


def test_rational_dimensions_reach_the_geometry_exactly():
    from symfloat.engine.floating_witness import number
    assert number(sp.Rational(1, 3) * A, {A: 3}, 40) == Fraction(1)


# ---- a box tilted from its upright position: the wedges and the righting arm ------------------------------------
# The box W x H (section, y and z) x L (along x), W = 2, H = 3, L = 1, half immersed, tilted by psi with tan psi =
# 1/4 about the x axis (the -y side dips; the water line stays on the vertical sides).  The new water line passes
# through the centre (the section is centrally symmetric): each wedge is the triangle (0, 0), (W/2, 0),
# (W/2, W/2 tan psi) times L: volume L W^2 tan psi / 8 = 1/8, centroid W/3 from the axis and W tan psi/6 from
# the old water plane (moments 1/12 and 1/96).  The righting arm of a wall-sided body is
# sin psi (GM + BM tan^2 psi / 2), BM = W^2/(6H) = 2/9, GM = BM - H/4 = -19/36: -75/(144 sqrt 17).
from symfloat.engine.floating_witness import LIMIT_METHODS, TILT_QUANTITIES  # noqa: E402

W_, H_, L_ = sp.symbols("W H L", positive=True)
TILTED = Case({W_: 2, H_: 3, L_: 1, S: sp.Rational(1, 2)}, label="box 2 x 3 x 1, half immersed, tan psi = 1/4")
TILT_EXACT = {
    "immersed wedge volume": sp.Rational(1, 8), "emerged wedge volume": sp.Rational(1, 8),
    "immersed wedge moment, horizontal": sp.Rational(1, 12), "emerged wedge moment, horizontal": sp.Rational(1, 12),
    "immersed wedge moment, vertical": sp.Rational(1, 96), "emerged wedge moment, vertical": sp.Rational(1, 96),
    "axis position": sp.Integer(0),
    "righting arm": -sp.Rational(75, 144) / sp.sqrt(17),
}


def tilted(quantity, **kw):
    """The tilted box's *quantity* (a name of TILT_QUANTITIES, or an expression in measured ones)."""
    kw.setdefault("up", (0, sp.Rational(1, 4), 1))
    return FloatingWitness("tilt", "tilt", ("f",), (TILTED,), body=Body.box(L_, W_, H_), density=S,
                           reference=(0, 0, 1), quantity=_named(quantity), **kw)


def test_every_tilt_quantity_is_tested():
    assert set(TILT_EXACT) == set(TILT_QUANTITIES)


@pytest.mark.parametrize("quantity", sorted(TILT_EXACT))
def test_the_wedges_and_the_arm_of_a_tilted_box_agree_with_their_closed_forms(quantity):
    w = tilted(quantity)
    for method in w.methods:
        assert abs(float(w.measure(TILTED, method)) - float(TILT_EXACT[quantity])) <= 1e-12, (quantity, method.name)


def test_an_expression_in_measured_quantities():
    # V B_z: the immersed volume (3, upright) times the height of B above G (-3/4): -9/4
    w = FloatingWitness("VB", "VB", ("f",), (TILTED,), body=Body.box(L_, W_, H_), density=S,
                        quantity=(measured("immersed volume") * measured("B - G, z"), measured("immersed volume")))
    assert [float(v) for v in w.measure(TILTED, w.methods[1])] == [-2.25, 3.0]
    with pytest.raises(ValueError, match="needs the reference"):
        FloatingWitness("x", "x", ("f",), (TILTED,), body=Body.box(L_, W_, H_), density=S, quantity=measured("righting arm"))


def test_the_limit_of_the_arm_over_the_tilt_is_the_metacentric_height():
    # GZ / psi -> GM = -19/36 as psi -> 0 (the wall-sided formula above), extrapolated from the clipped arm;
    # a mutated expectation (-19/35) is refuted
    psi = sp.Symbol("psi")
    w = tilted("righting arm", up=(0, sp.sin(psi), sp.cos(psi)), limit=(psi, 1), methods=LIMIT_METHODS)
    out = w.run({"f": (sp.Symbol("g"), -sp.Rational(19, 36)), "f#mutated": (sp.Symbol("g"), -sp.Rational(19, 35))})
    assert out["f"].agrees and out["f"].records[1]["rel_error"] < 1e-35
    assert not out["f#mutated"].agrees


# ---- the waterplane's moments in the body frame, a prism's bases, a root of a quantity ----------------------------
# Upright box 3 x 2 x 1 at s = 2/5 (CASE): the waterplane is the 3 x 2 rectangle, int x^2 = 2 * 3^3/12 = 9/2,
# int y^2 = 3 * 2^3/12 = 2, the rest 0; the water at z = -1/2 + 2/5 = -1/10, the upper base (z = 1/2) 3/5 above
# it, the lower base (z = -1/2) 2/5 below.  The tilted box (TILTED, up (0, 1, 4)/sqrt 17, half immersed) has the
# water plane through its centre: the rectangle L = 1 by W / cos psi = sqrt(17)/2, whose moment about the line
# along x is L (sqrt(17)/2)^3/12 = 17 sqrt 17/96, with normal n = (0, -4, 1)/sqrt 17, and int x^2 = sqrt(17)/24.
from symfloat.engine.floating_witness import FloatingRootWitness, Root, waterplane_moment  # noqa: E402

EXACT.update({
    "waterplane moment, xx": sp.Rational(9, 2), "waterplane moment, yy": sp.Integer(2),
    **{f"waterplane moment, {k}": sp.Integer(0) for k in ("xy", "xz", "yz", "zz")},
    "upper base above water": sp.Rational(3, 5), "lower base above water": -sp.Rational(2, 5),
})


def test_the_waterplane_moments_of_a_tilted_box_in_the_body_frame():
    r17 = sp.sqrt(17)
    n, x = (0, -4 / r17, 1 / r17), (1, 0, 0)
    w = tilted((waterplane_moment(n, n), waterplane_moment(x, x), waterplane_moment(x, n),
                measured("waterplane moment, yz")))
    exact = (17 * r17 / 96, r17 / 24, 0, -r17 / 24)      # yz = n_y n_z I_nn = -4/17 * 17 sqrt 17/96
    for method in w.methods:
        assert all(abs(float(v - e)) < 1e-12 for v, e in zip(w.measure(TILTED, method), exact)), method.name


# The box W x H x L = 2 x 9/5 x 1, half immersed, tilted by psi about x: the water plane passes through the
# centre, so the upper base is reached at tan psi = H/W = 9/10, and the wall-sided righting arm
# sin psi (GM + BM tan^2 psi/2), BM = W^2/(6H) = 10/27, GM = BM - H/4 = -43/540, vanishes at tan^2 psi =
# -2 GM/BM = 43/100 (before the contact).
PSI = sp.Symbol("psi")
LOG = Case({W_: 2, H_: sp.Rational(9, 5), L_: 1, S: sp.Rational(1, 2)}, label="box 2 x 9/5 x 1, half immersed")


def rooted(quantity, vanish, case=LOG, guard=(), at=None):
    """*quantity* at the first zero of *vanish* (each a name, or an expression in measured ones) as the tilt psi
    grows (scanned in 28 steps over [1/50, 7/5])."""
    return FloatingRootWitness("root", "root", ("f",), (case,), body=Body.box(L_, W_, H_),
                               up=(0, sp.sin(PSI), sp.cos(PSI)), density=S, reference=(0, 0, 1),
                               quantity=_named(quantity),
                               roots=((PSI, Root.scan(_named(vanish), PSI, sp.Rational(1, 50), sp.Rational(7, 5), 28,
                                                      guard=guard, at=at)),))


def test_the_zero_of_the_righting_arm_and_the_contact_of_a_base():
    arm = rooted(sp.tan(PSI) ** 2, "righting arm")
    contact = rooted(sp.tan(PSI), -measured("upper base above water"))
    for w, exact in ((arm, sp.Rational(43, 100)), (contact, sp.Rational(9, 10))):
        assert abs(float(w.measure(LOG, w.methods[0]) - exact)) < 1e-13
        with mpmath.workdps(50):
            assert abs(w.measure(LOG, w.methods[1]) - mpmath.mpf(exact.p) / exact.q) < 1e-35
    # the wall-sided root, and the same root perturbed in its second digit (refuted at both precisions)
    out = arm.run({"f": (sp.Symbol("t"), sp.Rational(43, 100)), "f#mutated": (sp.Symbol("t"), sp.Rational(44, 100))})
    assert out["f"].agrees and not out["f#mutated"].agrees
    out = contact.run({"f": (sp.Symbol("t"), sp.Rational(9, 10)),
                       "f#mutated": (sp.Symbol("t"), sp.Rational(9, 10) + sp.Rational(1, 10 ** 12))})
    assert out["f"].agrees and not out["f#mutated"].agrees


def test_a_root_along_the_density_a_guard_and_a_position_found_elsewhere():
    # the draught s H of the upright box equals 27/100 at s = 3/20; the grid's ends are expressions in the case
    # (from H/180 to H/2: 1/100 ... 9/10)
    w = FloatingRootWitness("s", "s", ("f",), (LOG,), body=Body.box(L_, W_, H_), density=S, quantity=S,
                            roots=((S, Root.scan(measured("draught") - sp.Rational(27, 100), S, H_ / 180, H_ / 2,
                                                 30)),))
    assert abs(float(w.measure(LOG, w.methods[0])) - 0.15) < 1e-15
    with mpmath.workdps(50):
        assert abs(w.measure(LOG, w.methods[1]) - mpmath.mpf(3) / 20) < 1e-35
    # the lower base stays under water at the zero of the arm: a guard asking it to be above is refused
    with pytest.raises(ValueError, match="not positive at the root"):
        rooted(sp.tan(PSI), "righting arm", guard=(measured("lower base above water"),)).measure(LOG, w.methods[0])
    # the zero found for L = 1, the volume read for L = 2 (the arm does not depend on L): 2 * 2 * 9/5 / 2
    twice = Case({**LOG.params, L_: 2})
    w = rooted("immersed volume", "righting arm", case=twice, at={L_: 1})
    assert abs(float(w.measure(twice, w.methods[0])) - 3.6) < 1e-12


def test_witnesses_of_several_bodies_joined():
    # the draughts of the box (s c = 2/5) and of the same box on its side (s a = 6/5), in one tuple
    from symfloat.engine.floating_witness import Joined
    parts = (witness("draught"), witness("draught", up=(1, 0, 0)))
    w = Joined("two", "two", ("f",), (CASE,), parts=parts)
    assert [float(v) for v in w.measure(CASE, w.methods[0])] == pytest.approx([0.4, 1.2], abs=1e-12)


def test_a_zero_found_inside_another():
    # the height H at which the zero of the arm (tan^2 = 3 H^2/4 - 2 by the wall-sided formula, W = 2) reaches the
    # upper base's contact (tan = H/2): 3 H^2/4 - 2 = H^2/4, H = 2 (the inner zero along the tilt, the outer along H)
    inner = Root.scan(measured("righting arm"), PSI, sp.Rational(1, 50), sp.Rational(7, 5), 28)
    outer = FloatingRootWitness("H", "H", ("f",), (LOG,), body=Body.box(L_, W_, H_), up=(0, sp.sin(PSI), sp.cos(PSI)),
                                density=S, reference=(0, 0, 1), quantity=H_,
                                roots=((H_, Root.scan(measured("upper base above water"), H_, sp.Rational(17, 10),
                                                      sp.Rational(23, 10), 6, roots=((PSI, inner),))),))
    assert abs(float(outer.measure(LOG, outer.methods[0])) - 2) < 1e-12
    with mpmath.workdps(50):
        assert abs(outer.measure(LOG, outer.methods[1]) - 2) < 1e-30


def test_grid_roots_first_last_and_all_and_the_grid_scanned_until_found():
    # x^2 - 2 has its zero on [0, 3] at sqrt 2; cos on [1, 10] has zeros at pi/2, 3 pi/2, 5 pi/2 (the exact values)
    from symfloat.engine.roots import grid_roots
    grid = [0.5 * k for k in range(7)]
    assert abs(grid_roots(lambda d: lambda x: x * x - 2, grid, 15, only="first")[0] - math.sqrt(2)) < 1e-15
    with mpmath.workdps(60):
        assert abs(grid_roots(lambda d: lambda x: x * x - 2, grid, 50)[0] - mpmath.sqrt(2)) < 1e-44
        cos_grid = [1 + k for k in range(10)]
        first, last = (grid_roots(lambda d: mpmath.cos, cos_grid, 50, only=w)[0] for w in ("first", "last"))
        assert abs(first - mpmath.pi / 2) < 1e-44 and abs(last - 5 * mpmath.pi / 2) < 1e-44
        assert len(grid_roots(lambda d: mpmath.cos, cos_grid, 15)) == 3
    assert grid_roots(lambda d: lambda x: x * x + 1, grid, 15) == []
    seen = []
    grid_roots(lambda d: lambda x: seen.append(x) or x - 1.2, grid, 15, only="first")
    assert seen[:4] == [0, 0.5, 1.0, 1.5] and 3.0 not in seen     # the cell [1, 3/2] found, the rest not scanned


# ---- roots along a parameter ---------------------------------------------------------------------------------
# A box 1 x 1 x h (h = 137/100) at density s > 1/2, tilted by phi about the x axis (up = (0, sin phi, cos phi)).
# While the water plane cuts the side faces only (wall-sided), it passes through the centre of the upright
# waterplane, so the top face reaches the water at tan phi_t = 2 h (1 - s) (the edge at y = -1/2 rises by
# tan phi / 2 above it, h (1 - s) being its height over the water upright); the righting arm of a wall-sided
# body is sin phi (GM + BM tan^2 phi / 2), BM = 1/(12 s h), GM = BM - h (1 - s)/2, so the oblique equilibrium
# has tan^2 phi_1 = 12 s (1 - s) h^2 - 2; the two meet where h^2 (1 - s)(16 s - 4) = 2.
PHI, DENS, H = sp.symbols("phi_r s_r h_r", positive=True)
TILT_UP = (0, sp.sin(PHI), sp.cos(PHI))
H_CASE = {H: sp.Rational(137, 100)}


def _root_witness(quantity, roots, density=DENS, params=None, methods=None):
    from symfloat.engine.floating_witness import FLOATING_METHODS, FloatingRootWitness
    case = Case({**H_CASE, **(params or {})}, label="box 1 x 1 x 137/100")
    return FloatingRootWitness("root", "root", ("f",), (case,), body=Body.box(1, 1, H), up=TILT_UP,
                               density=density, quantity=quantity, roots=roots,
                               methods=methods or FLOATING_METHODS), case


def test_the_tilt_at_which_the_top_face_reaches_the_water():
    from symfloat.engine.floating_witness import Root
    w, case = _root_witness(sp.tan(PHI), ((PHI, Root(measured("top clearance"), PHI, [0.05 * k for k in range(1, 25)])),),
                            params={DENS: sp.Rational(9, 10)})
    exact = 2 * sp.Rational(137, 100) * sp.Rational(1, 10)
    for method, tol in zip(w.methods, (1e-12, 1e-30)):
        assert abs(w.measure(case, method) - sp.N(exact, 50)) <= tol, method.name


def test_an_oblique_equilibrium_is_a_root_of_the_potential_slope():
    from symfloat.engine.floating_witness import Root, potential_slope
    w, case = _root_witness(sp.tan(PHI) ** 2, ((PHI, Root(potential_slope(TILT_UP, PHI), PHI,
                                                       [0.01 * k for k in range(1, 26)])),),
                            params={DENS: sp.Rational(9, 10)})
    h, s_ = sp.Rational(137, 100), sp.Rational(9, 10)
    exact = 12 * s_ * (1 - s_) * h ** 2 - 2
    for method, tol in zip(w.methods, (1e-10, 1e-28)):
        assert abs(w.measure(case, method) - sp.N(exact, 50)) <= tol, method.name


def test_the_density_where_the_equilibrium_reaches_the_top_face_by_nested_roots():
    from symfloat.engine.floating_witness import Root, potential_slope
    touch = Root(measured("top clearance"), PHI, [0.05 * k for k in range(1, 25)])
    slope_at_touch = Root(potential_slope(TILT_UP, PHI), DENS, [0.86 + 0.02 * k for k in range(6)],
                          roots=((PHI, touch),))
    from symfloat.engine.floating_witness import FLOATING_METHODS
    # float64 only (the nested search at 40 digits takes half a minute; the digits are tested above)
    w, case = _root_witness(DENS, ((DENS, slope_at_touch), (PHI, touch)), methods=FLOATING_METHODS[:1])
    h2 = sp.Rational(137, 100) ** 2
    exact = (20 + sp.sqrt(400 - 64 * (4 + 2 / h2))) / 32          # 16 s^2 - 20 s + 4 + 2/h^2 = 0
    for method, tol in zip(w.methods, (1e-10,)):
        assert abs(w.measure(case, method) - sp.N(exact, 50)) <= tol, method.name


def test_a_root_that_is_not_on_its_grid_is_one_clear_error():
    from symfloat.engine.floating_witness import Root
    w, case = _root_witness(PHI, ((PHI, Root(measured("top clearance"), PHI, [0.01, 0.02])),), params={DENS: sp.Rational(9, 10)})
    with pytest.raises(ValueError, match="no root"):
        w.measure(case, w.methods[0])


def test_the_corners_of_a_cube_corner_up_at_half_density():
    # the plane through the centre normal to a body diagonal cuts the cube in a regular hexagon
    w = FloatingWitness("corners", "corners", ("f",), (CASE,), body=Body.box(1, 1, 1), up=(1, 1, 1),
                        density=sp.Rational(1, 2), quantity=measured("waterplane corners"))
    assert [w.measure(CASE, m) for m in w.methods] == [6, 6]


def test_a_quantity_at_other_parameters_beside_a_root():
    # the upright metacentric height BM - h (1 - s)/2 (closed form above) beside the tilt where the top face
    # reaches the water, both in one measurement
    from symfloat.engine.floating_witness import At, Root
    gm = sp.Symbol("gm_r")
    w, case = _root_witness((gm, sp.tan(PHI)), ((gm, At(measured("metacentric height"), {PHI: 0})),
                                                (PHI, Root(measured("face clearance"), PHI, [0.05 * k for k in range(1, 25)]))),
                            params={DENS: sp.Rational(9, 10)})
    h, s_ = sp.Rational(137, 100), sp.Rational(9, 10)
    exact = (1 / (12 * s_ * h) - h * (1 - s_) / 2, 2 * h * (1 - s_))
    for method, tol in zip(w.methods, (1e-12, 1e-30)):
        assert all(abs(v - sp.N(e, 50)) <= tol for v, e in zip(w.measure(case, method), exact)), method.name


def test_a_water_plane_through_given_vertices():
    # the plane through the three vertices next to the corner (1/2, 1/2, 1/2) of the unit cube cuts off the corner
    # tetrahedron with three edges of length 1 at a right corner: volume 1/6; the plane u.p = 1/(2 sqrt 3) lies
    # 2/sqrt 3 above the opposite corner
    from symfloat.engine.floating_witness import CutWitness
    w = CutWitness("cut", "cut", ("f",), (CASE,), body=Body.box(1, 1, 1), up=(1, 1, 1),
                   through=(sp.Rational(1, 2), sp.Rational(1, 2), -sp.Rational(1, 2)),
                   quantity=(measured("immersed volume"), measured("draught")))
    for method, tol in zip(w.methods, (1e-14, 1e-35)):
        volume, depth = w.measure(CASE, method)
        assert abs(volume - sp.N(sp.Rational(5, 6), 50)) <= tol and abs(depth - sp.N(2 / sp.sqrt(3), 50)) <= tol, method.name


def test_the_waterplane_tensor_of_a_heeled_box_is_the_rectangle_turned():
    # box 3 x 2 x 4 at s = 1/2 heeled about x by phi (tan phi = 3/4 keeps the water plane through the centre within
    # the side faces): the waterplane is the rectangle 3 x 2/cos phi, its side 2/cos phi along
    # (0, cos phi, -sin phi): T_yy = cos^2 phi * 3 (2/cos phi)^3 / 12, T_yz = -sin phi cos phi * the same / cos^2 phi
    q = ("waterplane tensor, yy", "waterplane tensor, yz", "waterplane tensor, xx")
    w = FloatingWitness("t", "t", ("f",), (CASE,), body=Body.box(3, 2, 4), up=(0, 3, 4), density=sp.Rational(1, 2),
                        quantity=tuple(measured(n) for n in q))
    c, s_ = sp.Rational(4, 5), sp.Rational(3, 5)
    along = 3 * (2 / c) ** 3 / 12                   # second moment along the heeled side
    exact = (c ** 2 * along, -s_ * c * along, (2 / c) * 27 / 12)
    for method in w.methods:
        assert all(abs(v - sp.N(e, 50)) <= 1e-12 for v, e in zip(w.measure(CASE, method), exact)), method.name


# ---- the circular cylinder (Body.cylinder), radius r, length L, axis z, against closed forms -------------------
# Upright at density s (Archimedes): draught s L, B at s L/2 and G at L/2 above the bottom, the waterplane a disc
# of area pi r^2 and second moment pi r^4/4 (int y^2 over the disc = int_0^2pi int_0^r rho^3 sin^2 = pi r^4/4),
# hence the metacentric height (pi r^4/4)/(pi r^2 s L) - (1 - s) L/2 = r^2/(4 L s) - (1 - s) L/2 (Scheeffer's
# (69) is this sign condition; the reference is derived here, not taken from the module).
# Tilted by phi with no base cut (the waterplane a whole ellipse): the immersed part is the column over the disc
# from the bottom to z_c + x tan(phi) (x towards the dipping side), z_c = (s - 1/2) L from the volume s pi r^2 L;
# with int x dA = 0 and int x^2 dA = pi r^4/4 its moments give B - G = (tan(phi) r^2/(4 s L) towards the dip,
# -(1 - s) L/2 + tan^2(phi) r^2/(8 s L) along the axis); the waterplane is the ellipse with semi-axes
# r / cos(phi) and r: area pi r^2 / cos(phi), I = pi r^4 / (4 cos phi) and pi r^4 / (4 cos^3 phi) (pi a b^3/4).
# Lying at s = 1/2: the waterplane is the rectangle L x 2r (I min = L (2r)^3/12, I max = 2r L^3/12), B the
# centroid of a half disc, 4r/(3 pi) below the axis; the metacentric height 2r^3 L/3 / (pi r^2 L/2) - 4r/(3 pi)
# vanishes (a circular section is neutral).
R_, L2_, PHI_ = sp.symbols("r L phi", positive=True)
UPRIGHT_GM = sp.Rational(1, 4 * 4) / sp.Rational(3, 10) - sp.Rational(7, 10) * 4 / 2    # r = 1, L = 4, s = 3/10


def cylinder(name, up, s):
    case = Case({R_: 1, L2_: 4, S: s, PHI_: sp.atan(sp.Rational(1, 4))})
    w = FloatingWitness(name, name, ("f",), (case,), body=Body.cylinder(R_, L2_), up=up, density=S,
                        quantity=measured(name))
    return [w.measure(case, m) for m in w.methods]


@pytest.mark.parametrize("quantity, up, s, exact", [
    ("draught", (0, 0, 1), sp.Rational(3, 10), sp.Rational(6, 5)),
    ("waterplane area", (0, 0, 1), sp.Rational(3, 10), sp.pi),
    ("I min", (0, 0, 1), sp.Rational(3, 10), sp.pi / 4),
    ("metacentric height", (0, 0, 1), sp.Rational(3, 10), UPRIGHT_GM),
    ("metacentric height", (0, 0, -1), sp.Rational(3, 10), UPRIGHT_GM),
    ("immersed volume", (sp.sin(PHI_), 0, sp.cos(PHI_)), HALF := sp.Rational(1, 2), 2 * sp.pi),
    ("B - G, x", (sp.sin(PHI_), 0, sp.cos(PHI_)), HALF, -sp.Rational(1, 4) / (4 * HALF * 4)),
    ("B - G, z", (sp.sin(PHI_), 0, sp.cos(PHI_)), HALF, -2 * HALF + sp.Rational(1, 16) / (8 * HALF * 4)),
    ("B - G, y", (0, sp.sin(PHI_), -sp.cos(PHI_)), HALF, -sp.Rational(1, 4) / (4 * HALF * 4)),  # -y dips
    ("waterplane area", (sp.sin(PHI_), 0, sp.cos(PHI_)), HALF, sp.pi / sp.cos(PHI_)),
    ("I min", (sp.sin(PHI_), 0, sp.cos(PHI_)), HALF, sp.pi / (4 * sp.cos(PHI_))),
    ("I max", (sp.sin(PHI_), 0, sp.cos(PHI_)), HALF, sp.pi / (4 * sp.cos(PHI_) ** 3)),
    ("I min", (1, 0, 0), HALF, 4 * sp.Integer(2) ** 3 / 12),
    ("I max", (1, 0, 0), HALF, 2 * sp.Integer(4) ** 3 / 12),
    ("B below water", (1, 0, 0), HALF, 4 / (3 * sp.pi)),
    ("metacentric height", (0, 1, 0), HALF, sp.Integer(0)),
])
def test_the_cylinder_against_closed_forms(quantity, up, s, exact):
    ref = sp.N(exact.subs(PHI_, sp.atan(sp.Rational(1, 4))), 50)
    low, high = cylinder(quantity, up, s)
    assert abs(float(low) - float(ref)) < 1e-12
    with mpmath.workdps(50):
        assert abs(high - mpmath.mpf(str(ref))) < 1e-30


def test_the_cylinder_with_a_base_cut_keeps_its_volume():
    # tilted by 60 deg at s = 0.3: the upper water line crosses the lower base, which a column model cannot
    # float; the volume is still s pi r^2 L and G - B has no component along the waterplane's normal axis
    up = (sp.sqrt(3) / 2, 0, sp.Rational(1, 2))
    (vol, _), (cut, _) = cylinder("immersed volume", up, sp.Rational(3, 10)), cylinder("lower base above water", up,
                                                                                       sp.Rational(3, 10))
    assert cut > 0 and abs(vol - 1.2 * float(mpmath.pi)) < 1e-12
    assert abs(cylinder("B - G, y", up, sp.Rational(3, 10))[0]) < 1e-15


def test_witnesses_combined_by_an_expression():
    # the draughts of the box upright (2/5) and on its side (6/5): their difference and the ratio to c
    from symfloat.engine.floating_witness import Combined
    w = Combined("c", "c", ("f",), (CASE,), parts=(witness("draught"), witness("draught", up=(1, 0, 0))),
                 values=(measured("part 2") - measured("part 1"), measured("part 1") / C))
    assert [float(v) for v in w.measure(CASE, w.methods[0])] == pytest.approx([0.8, 0.4], abs=1e-14)


def test_a_body_with_a_given_centre_of_gravity():
    # the box 3 x 2 x 1 at s = 2/5 with G lowered by 1/10 from its centroid: G above B is 3/10 - 1/10 and the
    # metacentric height 5/6 - 1/5 (the waterplane and B do not depend on G)
    from symfloat.engine.floating_witness import Loaded
    for q, exact in (("G above B", Fraction(1, 5)), ("metacentric height", Fraction(5, 6) - Fraction(1, 5)),
                     ("B below water", Fraction(1, 5))):
        w = FloatingWitness(q, q, ("f",), (CASE,), body=Loaded.of(Body.box(A, B, C), (0, 0, -C / 10)), density=S,
                            quantity=measured(q))
        assert float(w.measure(CASE, w.methods[0])) == pytest.approx(float(exact), abs=1e-13)
        with mpmath.workdps(40):
            assert abs(w.measure(CASE, w.methods[1]) - mpmath.mpf(exact.numerator) / exact.denominator) < 1e-35


# ---- the coefficients of a quantity's expansion in the tilt (SeriesWitness) ------------------------------------
# Reference: the box 1 x 1 x 2 (across x, height y, length z) half immersed, G the height g above its upright
# centre of buoyancy, heeled by phi about z while wall-sided (tan phi < 1): the immersed section is the trapezoid
# below the waterline through the middle, whose centroid gives the arm
# GZ = sin phi (e²/(3T) - g + e² tan²phi/(6T)), e = T = 1/2 (Euler §§192-200, the worked body; Atwood's
# formula for a wall-sided section).  Its Taylor coefficients: phi: 1/6 - g; phi³: -(1/6 - g)/6 + 1/12.

def _heeled_box(g):
    from symfloat.engine.floating_witness import Loaded
    return Loaded.of(Body.box(1, 1, 2), (0, S / 2 - sp.Rational(1, 2) + g, 0))


TILT = sp.Symbol("phi", positive=True)
HEEL = (sp.sin(TILT), sp.cos(TILT), 0)


@pytest.mark.parametrize("k", [1, 3])
def test_the_arm_coefficients_of_a_heeled_box(k):
    from symfloat.engine.floating_witness import SeriesWitness, potential_slope
    g = sp.Rational(1, 10)
    exact = {1: sp.Rational(1, 6) - g, 3: -(sp.Rational(1, 6) - g) / 6 + sp.Rational(1, 12)}[k]
    case = Case({S: sp.Rational(1, 2)})
    for odd in (True, False):
        w = SeriesWitness("arm", "", (), (case,), body=_heeled_box(g), up=HEEL, density=S,
                          quantity=potential_slope(HEEL, TILT), series=(TILT, k), odd=odd)
        for method in w.methods:
            with mpmath.workdps(60):
                err = abs(w.measure(case, method) - mpmath.mpf(sp.N(exact, 60))) / abs(mpmath.mpf(sp.N(exact, 60)))
            assert err < method.tolerance, (k, odd, method.name, err)
    # mutation: the coefficient of phi^3 is not the linear theory's zero, nor the coefficient of phi
    if k == 3:
        assert abs(float(exact)) > 0.05 and exact != sp.Rational(1, 6) - g


def test_the_slope_of_the_arm_at_a_heeled_equilibrium():
    # G the height g = 1/6 + 1/100 above B: the arm vanishes again at tan²phi* = 2 (g - 1/6)/(1/6) = 3/25 and its
    # slope there is dGZ/dphi = 2 (g - 1/6) sqrt(1 + 6 T (g - 1/6)/e²) = (1/50) sqrt(112/100) (from the arm above)
    from symfloat.engine.floating_witness import FloatingRootWitness, Root, SeriesWitness, potential_slope
    g, star = sp.Rational(1, 6) + sp.Rational(1, 100), sp.Symbol("phi_star", positive=True)
    arm = potential_slope(HEEL, TILT)
    root = Root(arm, TILT, tuple(sp.Rational(j, 20) for j in range(1, 15)))
    case = Case({S: sp.Rational(1, 2)})
    slope = SeriesWitness("slope", "", (), (case,), body=_heeled_box(g), up=HEEL, density=S, quantity=arm,
                          series=(TILT, 1), centre=star, roots=((star, root),))
    where = FloatingRootWitness("root", "", (), (case,), body=_heeled_box(g), up=HEEL, density=S,
                                quantity=sp.tan(TILT) ** 2, roots=((TILT, root),))
    exact = sp.Rational(1, 50) * sp.sqrt(sp.Rational(112, 100))
    for method in slope.methods:
        with mpmath.workdps(60):
            assert abs(slope.measure(case, method) - mpmath.mpf(sp.N(exact, 60))) < method.tolerance * float(exact)
            assert abs(where.measure(case, method) - mpmath.mpf(3) / 25) < method.tolerance


def test_polynomial_roots_part_a_nearly_triple_root_and_keep_rational_roots_exact():
    from symfloat.engine.roots import polynomial_roots
    x = sp.Symbol("x")
    # (x - 3/4)((x - 3/4)^2 - 1e-10): three roots 1e-5 apart, the middle one rational (a pitchfork's shape, as
    # Scheeffer IX's quartic next to s = 9/32); a grid of step 1e-3 sees one sign change there
    eps2 = sp.Rational(1, 10 ** 10)
    poly = sp.Poly(sp.expand((x - sp.Rational(3, 4)) * ((x - sp.Rational(3, 4)) ** 2 - eps2) * (x + 2)), x, domain=sp.QQ)
    with mpmath.workdps(40):
        roots = polynomial_roots(poly, mpmath.mpf(10) ** -38)
        expected = [-2, mpmath.mpf(3) / 4 - mpmath.mpf(10) ** -5, mpmath.mpf(3) / 4, mpmath.mpf(3) / 4 + mpmath.mpf(10) ** -5]
        assert len(roots) == 4
        assert all(abs(r - e) < mpmath.mpf(10) ** -36 for r, e in zip(roots, expected))
        assert roots[2] == mpmath.mpf(3) / 4 and roots[0] == -2         # rational roots come out exact
    # x^2 - 2: the irrational pair, refined to the tolerance asked
    with mpmath.workdps(30):
        r = polynomial_roots(sp.Poly(x ** 2 - 2, x, domain=sp.QQ), mpmath.mpf(10) ** -28)
        assert abs(r[1] - mpmath.sqrt(2)) < mpmath.mpf(10) ** -27 and abs(r[0] + mpmath.sqrt(2)) < mpmath.mpf(10) ** -27


def test_polynomial_terms_built_once_and_evaluated_exactly():
    from symfloat.engine.roots import polynomial_at, polynomial_terms
    x, a, s = sp.symbols("x a s")
    # (a x - s)^2 (x + a/3) at a = 3/2, s = 1/4 against SymPy's own substitution
    expr = sp.expand((a * x - s) ** 2 * (x + a / 3))
    terms = polynomial_terms(expr, x, (a, s))
    got = polynomial_at(terms, x, (Fraction(3, 2), Fraction(1, 4)))
    assert got == sp.Poly(expr.subs({a: sp.Rational(3, 2), s: sp.Rational(1, 4)}), x, domain=sp.QQ)
    assert got.degree() == 3 and got.eval(sp.Rational(1, 6)) == 0          # a x = s at x = 1/6


# ---- where the water plane crosses a side, and the immersed part split at the water line's lowest point ------------
# The tilted box of the wedges above (W = 2 across y, H = 3 high, L = 1 long, half immersed, up (0, 1/4, 1)): the water
# plane passes through the centre, so the water line meets the side y = +1 at z = -1/4 and the side y = -1 at
# z = +1/4 (z = -y/4): from the bottom z = -3/2 their immersed lengths are 5/4 and 7/4.  Marked with the upright
# direction z, the immersed part splits at z = -1/4 into the block 1 x 2 x 5/4 (volume 5/2, centroid at z = -7/8, so
# 7/8 * 4/sqrt 17 below the water plane u . p = 0) and the triangle (-1, -1/4), (1, -1/4), (-1, 1/4) times L (volume
# 1/2, centroid (y, z) = (-1/3, -1/12), depth (1/12 + 1/12) * 4/sqrt 17); the two moments add up to V times the
# depth of B, 3 * 109/(36 sqrt 17) (B from the two centroids).
SPLIT_EXACT = {
    "lower part volume": sp.Rational(5, 2), "lower part moment": sp.Rational(5, 2) * sp.Rational(7, 2) / sp.sqrt(17),
    "upper part volume": sp.Rational(1, 2), "upper part moment": sp.Rational(1, 2) * sp.Rational(2, 3) / sp.sqrt(17),
}


@pytest.mark.parametrize("quantity", sorted(SPLIT_EXACT))
def test_the_immersed_part_of_a_tilted_box_split_at_the_lowest_point_of_its_water_line(quantity):
    from symfloat.engine.floating_witness import Marked
    w = FloatingWitness(quantity, quantity, ("f",), (TILTED,), body=Marked.of(Body.box(L_, W_, H_), (0, 0, 1)),
                        up=(0, sp.Rational(1, 4), 1), density=S, quantity=measured(quantity))
    for method in w.methods:
        with mpmath.workdps(50):
            err = abs(w.measure(TILTED, method) - mpmath.mpf(sp.N(SPLIT_EXACT[quantity], 50)))
        assert err < (1e-13 if method.dps <= 15 else 1e-35), (quantity, method.name, err)


def test_the_split_parts_make_up_the_immersed_part():
    from symfloat.engine.floating_witness import Marked
    parts = (measured("lower part moment") + measured("upper part moment")
             - measured("immersed volume") * measured("B below water"),
             measured("lower part volume") + measured("upper part volume") - measured("immersed volume"))
    w = FloatingWitness("sum", "", ("f",), (TILTED,), body=Marked.of(Body.box(L_, W_, H_), (0, 0, 1)),
                        up=(0, sp.Rational(1, 4), 1), density=S, quantity=parts)
    assert max(abs(v) for v in w.measure(TILTED, w.methods[1])) < 1e-35
    # marked along the tilted up vector itself, the plane is the water plane: nothing lies above it
    w = FloatingWitness("up", "", ("f",), (TILTED,), body=Marked.of(Body.box(L_, W_, H_), (0, sp.Rational(1, 4), 1)),
                        up=(0, sp.Rational(1, 4), 1), density=S, quantity=measured("upper part volume"))
    assert abs(w.measure(TILTED, w.methods[1])) < 1e-35


def test_where_the_water_plane_crosses_the_sides_of_a_tilted_box():
    from symfloat.engine.floating_witness import crossing
    up = (0, sp.Rational(1, 4), 1)
    for point, exact in (((0, 1, -H_ / 2), sp.Rational(5, 4)), ((0, -1, -H_ / 2), sp.Rational(7, 4)),
                         ((0, 0, -H_ / 2), sp.Rational(3, 2))):       # the centre line: the plane passes through 0
        w = FloatingWitness("x", "", ("f",), (TILTED,), body=Body.box(L_, W_, H_), up=up, density=S,
                            quantity=crossing(up, point, (0, 0, 1)))
        for method in w.methods:
            assert abs(float(w.measure(TILTED, method)) - float(exact)) < 1e-14, (point, method.name)
    # along the width, at the height of the bottom: the plane y/4 + z = 0 meets z = -3/2 at y = 6, outside the box
    w = FloatingWitness("y", "", ("f",), (TILTED,), body=Body.box(L_, W_, H_), up=up, density=S,
                        quantity=crossing(up, (0, 0, -H_ / 2), (0, 1, 0)))
    assert abs(float(w.measure(TILTED, w.methods[0])) - 6) < 1e-13


# ---- the potential's curvature along a turn, derivatives along a parameter ------------------------------------
# The wall-sided box 1 x 1 x h of the tests above, tilted by phi with no face cut: the arm is
# sin phi (GM + BM tan^2 phi / 2).
def test_the_curvature_of_the_potential_is_the_slope_of_the_arm():
    from symfloat.engine.floating_witness import potential_curvature
    h, s_ = sp.Rational(137, 100), sp.Rational(9, 10)
    bm = 1 / (12 * s_ * h)
    gm = bm - h * (1 - s_) / 2
    x = sp.Symbol("x")
    arm = sp.sin(x) * (gm + bm * sp.tan(x) ** 2 / 2)
    for phi in (0, sp.Rational(1, 5)):
        w, case = _root_witness(potential_curvature(TILT_UP, PHI), (), params={DENS: s_, PHI: phi})
        exact = sp.diff(arm, x).subs(x, phi)                # at 0 the upright metacentric height gm
        for method, tol in zip(w.methods, (1e-12, 1e-30)):
            assert abs(w.measure(case, method) - sp.N(exact, 50)) <= tol, (phi, method.name)
    with pytest.raises(ValueError, match="unit rate"):
        potential_curvature((0, 2 * sp.sin(PHI), 2 * sp.cos(PHI)), PHI)


def test_derivatives_along_a_parameter_by_central_differences():
    from symfloat.engine.floating_witness import Difference, Root
    d1, d2 = sp.symbols("d1 d2")
    # I max of the upright 3 x 2 x 1 box is B A^3/12 (the waterplane A x B, A > B): d/dA = B A^2/4, d2/dA2 = B A/2
    from symfloat.engine.floating_witness import FloatingRootWitness
    w = FloatingRootWitness("d", "d", ("f",), (CASE,), body=Body.box(A, B, C), up=(0, 0, 1), density=S,
                            quantity=(d1, d2), roots=((d1, Difference(measured("I max"), A, sp.Rational(1, 10))),
                                                      (d2, Difference(measured("I max"), A, sp.Rational(1, 10), order=2))))
    for method, tol in zip(w.methods, (1e-12, 1e-28)):
        assert all(abs(v - sp.N(e, 50)) <= tol for v, e in zip(w.measure(CASE, method), (sp.Rational(9, 2), 3))), \
            method.name
    # with a root at each point: the tilt at which the top face reaches the water, tan phi_t = 2 h (1 - s), so
    # d tan(phi_t)/ds = -2 h
    touch = Root(measured("top clearance"), PHI, [0.05 * k for k in range(1, 25)])
    w, case = _root_witness(d1, ((d1, Difference(sp.tan(PHI), DENS, sp.Rational(1, 100), roots=((PHI, touch),))),),
                            params={DENS: sp.Rational(9, 10)})
    for method, tol in zip(w.methods, (1e-9, 1e-28)):
        assert abs(w.measure(case, method) - sp.N(-2 * sp.Rational(137, 100), 50)) <= tol, method.name
    with pytest.raises(ValueError, match="order 1 or 2"):
        Difference(measured("I max"), A, 1, order=3)
    w, case = _root_witness(d1, ((d1, Difference(measured("I max"), A, 1)),), params={DENS: sp.Rational(9, 10)})
    with pytest.raises(ValueError, match="needs its value"):
        w.measure(case, w.methods[0])


def test_a_number_at_a_trial_value_is_computed_to_the_method_digits():
    # a root search's trial value is a SymPy Float: the expression is evaluated by its compiled form at dps + 10
    # digits, not by SymPy; against SymPy's own evaluation at 60 digits it holds to the method's digits (a
    # compiled form run at 15 digits would miss 40 digits by 1e-17), and the exact numbers of a case stay exact
    x, y = sp.symbols("x y", positive=True)
    expr = sp.sqrt(x) * sp.cos(y) + sp.pi / 3
    params = {x: sp.Rational(3, 7), y: sp.Float("0.7123456789012345678901234567890123456789012345", 50)}
    exact = sp.N(expr.xreplace(params), 60)
    for dps, tol in ((15, 1e-15), (40, mpmath.mpf(10) ** -39)):
        with mpmath.workdps(max(dps, 15)):
            got = number(expr, params, dps)
            assert abs(got - mpmath.mpf(exact)) <= tol * abs(mpmath.mpf(exact)), dps
    assert number(x ** 2 + 1, params, 40) == Fraction(58, 49)
    with pytest.raises(ValueError, match="needs a number"):
        number(x + sp.Symbol("z"), params, 15)


def test_a_number_that_is_a_float_or_a_rational_is_what_the_case_s_evaluation_gives():
    # a trial value (a Float) or a dimension (a Rational) is read without SymPy's substitution: bit for bit what
    # _exact gives it (a Float of more digits than _exact evaluates at is rounded there first, so it goes that way)
    from symfloat.engine.floating_witness import _exact
    values = [sp.Float("0.1", 20), sp.Float("-2.718281828459045235360287", 25), sp.pi.evalf(45),
              sp.Float(sp.Rational(1, 3), 55), sp.sqrt(2).evalf(80), sp.Rational(-7, 3), sp.Integer(0)]
    for dps in (15, 40):
        for v in values:
            with mpmath.workdps(max(dps, 15)):
                fast, slow = number(v, {}, dps), _exact(v, (), dps)
                slow = +slow if isinstance(slow, mpmath.mpf) else slow
                assert type(fast) is type(slow) and fast == slow, (v, dps)
    assert number(sp.Rational(3, 4), {}, 15) == Fraction(3, 4)
    # 1 + 2^-53 + 2^-120 in 150 bits: rounded to a double at once it is 1 + 2^-52; _exact rounds it to 30 digits
    # first (1 + 2^-53, a tie) and then to the even double 1, and so must number
    twice_rounded = sp.Float(sp.Rational(2 ** 120 + 2 ** 67 + 1, 2 ** 120), precision=150)
    assert float(twice_rounded) == 1 + 2 ** -52 and number(twice_rounded, {}, 15) == 1.0


def test_a_root_read_only_by_a_later_grid_is_found_in_float64():
    # the tilt of the upper base's contact bounds the grid of the arm's zero and nothing else reads it: at 40
    # digits it is found in float64, the arm's zero (the quantity reads it) at 40 digits, to 1e-35 as before
    from symfloat.engine.floating_witness import _SOLVED
    top = sp.Symbol("psi_top")
    roots = ((top, Root.scan(-measured("upper base above water"), PSI, sp.Rational(1, 50), sp.Rational(7, 5), 28)),
             (PSI, Root.scan(measured("righting arm"), PSI, sp.Rational(1, 50), top, 28)))
    found = FloatingRootWitness("root", "root", ("f",), (LOG,), body=Body.box(L_, W_, H_),
                                up=(0, sp.sin(PSI), sp.cos(PSI)), density=S, reference=(0, 0, 1),
                                quantity=sp.tan(PSI) ** 2, roots=roots)
    with mpmath.workdps(50):
        assert abs(found.measure(LOG, found.methods[1]) - mpmath.mpf(43) / 100) < 1e-35
    digits = {key[6]: key[-1] for key in _SOLVED if (key[6], key[7]) in roots}
    assert digits == {top: 15, PSI: 40}
    read = FloatingRootWitness(**{**found.__dict__, "quantity": sp.tan(top)})   # now the quantity reads it
    with mpmath.workdps(50):
        assert abs(read.measure(LOG, read.methods[1]) - mpmath.mpf(9) / 10) < 1e-35


def test_a_whole_measures_its_parts_at_their_methods_or_the_least_precise_of_them():
    """Combined and Joined name no methods: the parts' own, or, where they differ, those of the part whose float64
    method is the least precise (a limit's LIMIT_METHODS beside a plain quantity's FLOATING_METHODS)."""
    from symfloat.engine.floating_witness import (FLOATING_METHODS, LIMIT_METHODS, Body, Combined, FloatingWitness,
                                                  Joined)
    psi = sp.Symbol("psi")
    plain = FloatingWitness("", "", (), (), body=Body.box(2, 1, 1), density=sp.Rational(1, 2))
    limit = FloatingWitness("", "", (), (), body=Body.box(2, 1, 1), density=sp.Rational(1, 2),
                            up=(sp.sin(psi), 0, sp.cos(psi)), quantity=measured("draught"),
                            limit=(psi, 0), methods=LIMIT_METHODS)
    assert Joined("j", "", (), (), parts=(plain, plain)).methods == FLOATING_METHODS
    assert Combined("c", "", (), (), parts=(plain, limit), values=(measured("part 1"),)).methods == LIMIT_METHODS
    assert Joined("j", "", (), (), parts=(limit, plain)).methods == LIMIT_METHODS
    assert Joined("j", "", (), (), parts=(plain,), methods=LIMIT_METHODS).methods == LIMIT_METHODS
