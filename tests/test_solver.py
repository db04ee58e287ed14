"""The equilibrium solver: known cases from the sources, the duality s <-> 1 - s, invariance under
the body's symmetries and under rotations of the frame, completeness, and honest error estimates."""
import math
import re
from fractions import Fraction

import numpy as np
import pytest

from symfloat.geometry.floating import box, floating_state
from symfloat.solver import SceneError, make_scene, solve
from symfloat.solver.bodies import polyhedron
from symfloat.solver.local import local
from symfloat.solver.phase import position_label
from symfloat.solver.symmetry import box_group, planar_group, prism_group, same_class

S_LO = 0.5 - math.sqrt(1 / 12)          # Scheeffer (79): the cube floats upright iff s < 0.2113 or s > 0.7887
S_80 = (3 - math.sqrt(2)) / 7           # Scheeffer (80): the oblique ring exists for 0.2113 < s < 0.2265


def stable_labels(scene):
    return sorted(position_label(e.up, e.family) for e in solve(scene).equilibria if e.stability == "stable")


def by_label(solution):
    return {position_label(e.up, e.family): e for e in solution.equilibria}


# -- known cases from the sources -------------------------------------------------------------

@pytest.mark.parametrize("s, upright", [(0.2, True), (S_LO - 1e-4, True), (S_LO + 1e-4, False), (0.5, False),
                                        (1 - S_LO - 1e-4, False), (1 - S_LO + 1e-4, True)])
def test_cube_upright_threshold_of_79(s, upright):
    eq = by_label(solve(make_scene("cube", Fraction(s))))["face z up"]
    assert (eq.stability == "stable") is upright


def test_cube_oblique_ring_of_80():
    # Scheeffer VI.D, (80): between 0.2113 and 0.2265 the cube leaves the unstable upright position for an
    # oblique one of every azimuth (first rotation region: the potential depends on the tilt only).
    sol = solve(make_scene("cube", "0.22"))
    ring = [e for e in sol.equilibria if e.family == "ring"]
    assert len(ring) == 1 and ring[0].stability == "stable"
    assert by_label(sol)["face z up"].stability == "unstable"
    # the ring's tilt from the independent first-region condition tan^2 phi = 2 (V e / T - 1) of VI.C, with
    # V = s, e = (1 - s)/2, T = 1/12 (unit cube): tan^2 phi = 12 s (1 - s) - 2
    s = 0.22
    assert math.tan(math.radians(ring[0].tilt_deg)) ** 2 == pytest.approx(12 * s * (1 - s) - 2, rel=1e-9)
    # every azimuth is an equilibrium of the same potential
    poly = box(1, 1, 1)
    phi = math.radians(ring[0].tilt_deg)
    for az in (0.1, 0.3, 0.7):
        loc = local(poly, (math.sin(phi) * math.cos(az), math.sin(phi) * math.sin(az), math.cos(phi)), s)
        assert np.linalg.norm(loc.gradient) < 1e-12
        assert loc.U == pytest.approx(ring[0].potential, abs=1e-12)


def test_cube_corner_up_is_stable_between_one_sixth_and_five_sixths():
    # X: with a corner down the waterplane is a triangle for s <= 1/6 (the corner tetrahedron holds 1/6 of
    # the cube) and that position is unstable; the corner-up position with hexagonal waterplane is stable.
    assert "corner up" not in stable_labels(make_scene("cube", "0.15"))
    sol = by_label(solve(make_scene("cube", "0.5")))
    assert sol["corner up"].stability == "stable" and sol["corner up"].waterplane == "hexagon"
    assert "corner up" not in stable_labels(make_scene("cube", "0.85"))


def test_long_square_log_of_hasab():
    # hasab and Scheeffer VI.C: a long square log floats flat for s < 0.2113, corner down for 1/4 < s < 3/4
    sol = solve(make_scene("section", "0.1", polygon="0,0 1,0 1,1 0,1"))
    assert [e.up for e in sol.equilibria if e.stability == "stable"] == [(1.0, 0.0, 0.0)]
    sol = solve(make_scene("section", "0.5", polygon="0,0 1,0 1,1 0,1"))
    stable = [e for e in sol.equilibria if e.stability == "stable"]
    assert len(stable) == 1 and stable[0].up[0] == pytest.approx(math.sqrt(0.5), abs=1e-12)


def test_cylinder_upright_condition():
    # Scheeffer VI.B (Duhamel for a disk waterplane): upright is stable iff r^2 / (4 s L) > L (1 - s) / 2,
    # i.e. (r / L)^2 > 2 s (1 - s); here 1 > 0.5 (stable) and 0.25 < 0.5 (unstable)
    up = lambda sol: next(e for e in sol.equilibria if e.tilt_deg == 0)
    assert up(solve(make_scene("cylinder", "0.5", dims="1,1"))).stability == "stable"
    assert up(solve(make_scene("cylinder", "0.5", dims="1,2"))).stability == "unstable"
    lying = solve(make_scene("cylinder", "0.5", dims="1,3")).equilibria[0]
    assert lying.tilt_deg == 90 and lying.stability == "stable" and lying.waterplane == "rectangle"


@pytest.mark.parametrize("dps", [None, 40])
def test_cylinder_state_against_the_ellipse_and_the_rectangle(dps):
    # r = 1, L = 10 at s = 1/2 tilted by theta = 3/10: by symmetry the water plane passes through the centre (t = 0)
    # and cuts neither base (the waterplane reaches z = +-r tan(theta), well inside +-5): it is the ellipse with
    # semi-axes r/cos(theta) along w and r along y, area pi r^2/cos, int w^2 = pi r^4/(4 cos^3), int y^2 =
    # pi r^4/(4 cos) (the ellipse's second moments).  Lying (theta = pi/2), the rectangle 2r x L: int w^2 =
    # 2r L^3/12, int y^2 = L (2r)^3/12.  Half the volume is submerged in both.
    import mpmath
    from symfloat.geometry.cylinder import cylinder_state
    with mpmath.workdps(50):
        c = mpmath.cos(mpmath.mpf(3) / 10)
        pi = mpmath.pi
        tilted = cylinder_state(1, 10, mpmath.mpf(3) / 10 if dps else 0.3, 0.5, dps)
        lying = cylinder_state(1, 10, pi / 2 if dps else math.pi / 2, 0.5, dps)
        tol = 1e-12 if dps is None else mpmath.mpf(10) ** -30
        for got, exact in ((tilted.t, 0), (tilted.V, 5 * pi), (tilted.area, pi / c), (tilted.centre, 0),
                           (tilted.I_w, pi / (4 * c ** 3)), (tilted.I_y, pi / (4 * c)), (lying.t, 0),
                           (lying.V, 5 * pi), (lying.area, 20), (lying.I_w, 2 * 1000 / mpmath.mpf(12)),
                           (lying.I_y, 10 * mpmath.mpf(8) / 12)):
            assert abs(got - exact) <= tol * max(1, abs(exact)), (got, exact)
    assert (tilted.shape, lying.shape) == ("ellipse", "rectangle")


def test_cylinder_lying_at_half_density_with_length_2r_is_decided_by_higher_orders():
    # lying, s = 1/2: G above B by 4r/(3 pi) (half-disk centroid); pitching moment of the waterplane
    # 2r L^3/12 over the volume pi r^2 L / 2 gives L^2 / (3 pi r): equal when L = 2r, so the second
    # variation vanishes.  The potential rises on tilting, as the fourth power of the tilt: U(90° - d) - U(90°) =
    # 6.3e-14, 3.4e-12, 4.2e-10 at d = 1e-3, 3e-3, 1e-2 rad (exact slices at 30 digits), and 3.4e-3, 4.2e-5,
    # 3.1e-6 at 60°, 80°, 85° for the 128-gon prism of circumradius 1 clipped exactly (2.5e-6 at 85° by the
    # slices): a minimum, stable.  It was called unstable from the potential read beyond 90°, where the meridian's
    # formulas gave 0 (the tilt 90° + d is the tilt 90° - d turned end over end)
    lying = next(e for e in solve(make_scene("cylinder", "0.5", dims="1,2")).equilibria if e.tilt_deg == 90)
    assert abs(lying.eigenvalues[0]) < 1e-14
    assert (lying.stability, lying.stability_evidence) == ("stable", "higher orders")


def test_the_cylinders_minima_minus_maxima_holds_and_fails_on_a_misclassified_position():
    # over a whole turn of the tilt in the meridian plane the potential's minima - maxima is 0: upright and lying
    # count twice (0 and 180°, 90° and 270°), a tilted position four times.  r = 1, L = 2 at s = 1/2 has upright
    # unstable and lying stable (the test above); called unstable, the lying position makes the sum -4, the
    # error the solver raises; undecided, it cannot be made.  Checked over 492 scenes (12 shapes, 41 densities)
    from dataclasses import replace
    from symfloat.solver.solve import _cylinder_index
    sol = solve(make_scene("cylinder", "0.5", dims="1,2"))
    assert _cylinder_index(sol.equilibria) == 0 == sol.checks["minima_minus_maxima"]
    flipped = [replace(e, stability="unstable") if e.tilt_deg == 90 else e for e in sol.equilibria]
    assert _cylinder_index(flipped) == -4
    assert _cylinder_index([replace(e, stability="indifferent") for e in sol.equilibria]) is None


def test_cube_edge_up_at_half_density_is_unstable_by_higher_orders():
    # s = 1/2: the edge-up position's second variation vanishes about the edge's normal in the waterplane
    # (eigenvalue 0 to rounding); turning the cube that way lowers the potential (|eps|^3), as the
    # predictor tests of scheeffer-vi-cf found by differencing, so VI.D's "stable" is wrong there
    edge = by_label(solve(make_scene("cube", "1/2")))["edge up (xz)"]
    assert min(abs(x) for x in edge.eigenvalues) < 1e-14
    assert (edge.stability, edge.stability_evidence) == ("unstable", "higher orders")


def test_box_lies_on_its_largest_face():
    sol = solve(make_scene("box", "1/2", dims="1,2,3"))
    stable = [e for e in sol.equilibria if e.stability == "stable"]
    assert [e.up for e in stable] == [(1.0, 0.0, 0.0)]


# -- duality and symmetry ------------------------------------------------------------------------

@pytest.mark.parametrize("s", ["0.1", "0.22", "0.3"])
def test_duality_of_the_cube(s):
    # a box is centrally symmetric: -u is in the class of u, so the stable sets at s and 1 - s coincide
    assert stable_labels(make_scene("cube", s)) == stable_labels(make_scene("cube", 1 - Fraction(s)))


@pytest.mark.parametrize("body, kw", [("prism", {"sides": 3, "dims": "1,3"}),
                                      ("section", {"polygon": "0,0 3,0 0,1"})])
def test_duality_turns_the_stable_set_upside_down(body, kw):
    for s in ("0.2", "0.35"):
        low = solve(make_scene(body, s, **kw))
        high = solve(make_scene(body, 1 - Fraction(s), **kw))
        group = prism_group(3) if body == "prism" else planar_group(
            [tuple(float(c) for c in p) for p in __import__("symfloat.solver.bodies", fromlist=["x"])
             .centred_polygon(make_scene(body, s, **kw))])
        turned = [tuple(-x for x in e.up) for e in low.equilibria if e.stability == "stable"]
        stable_high = [e.up for e in high.equilibria if e.stability == "stable"]
        assert len(turned) == len(stable_high)
        assert all(any(same_class(u, v, group, 1e-8) for v in stable_high) for u in turned)


@pytest.mark.parametrize("scene", [make_scene("box", "0.3", dims="1,2,3"), make_scene("cube", "0.4"),
                                   make_scene("prism", "0.6", dims="1,2", sides=5)], ids=str)
def test_every_symmetric_copy_is_an_equilibrium_of_equal_potential(scene):
    group = box_group(scene.dims) if scene.body != "prism" else prism_group(scene.sides)
    poly = polyhedron(scene)
    for e in solve(scene).equilibria:
        for g in group[::3]:
            loc = local(poly, g @ np.array(e.up), scene.density)
            assert np.linalg.norm(loc.gradient) < 1e-11
            assert loc.U == pytest.approx(e.potential, abs=1e-12)


def test_rotating_the_frame_rotates_the_answer():
    # the same triangle given in a frame turned by 90 degrees: every up vector turns with it
    a = solve(make_scene("section", "0.3", polygon="0,0 3,0 0,1"))
    b = solve(make_scene("section", "0.3", polygon="0,0 0,3 -1,0"))
    turn = np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    assert [e.stability for e in a.equilibria] == [e.stability for e in b.equilibria]
    for ea, eb in zip(a.equilibria, b.equilibria):
        assert np.allclose(turn @ np.array(ea.up), eb.up, atol=1e-12)
        assert ea.potential == pytest.approx(eb.potential, abs=1e-13)


# -- completeness and accuracy ------------------------------------------------------------------

@pytest.mark.parametrize("scene", [make_scene("box", "0.3", dims="1,2,3"), make_scene("cube", "0.1"),
                                   make_scene("prism", "0.4", dims="1,3", sides=3)], ids=str)
def test_poincare_hopf_index_sum_is_two(scene):
    assert solve(scene).checks["poincare_hopf_index_sum"] == 2


def test_lowest_equilibrium_is_the_global_minimum_of_a_dense_scan():
    # independent of Newton: the potential sampled on 2000 directions never lies below the lowest
    # stable equilibrium the solver reports
    scene = make_scene("box", "0.3", dims="1,2,3")
    lowest = min(e.potential for e in solve(scene).equilibria)
    poly = polyhedron(scene)
    k = np.arange(2000) + 0.5
    z, phi = 1 - 2 * k / 2000, math.pi * (1 + 5 ** 0.5) * k
    pts = np.stack([np.sqrt(1 - z * z) * np.cos(phi), np.sqrt(1 - z * z) * np.sin(phi), z], axis=1)
    sampled = min(floating_state(poly, tuple(p), 0.3).potential for p in pts)
    assert lowest <= sampled + 1e-12


def test_equilibria_are_accurate_to_1e9_rad_against_50_digits():
    # the oblique edge-parallel equilibrium of the box, refined at 50 digits independently of the solver
    import mpmath
    scene = make_scene("box", "0.3", dims="1,2,3")
    poly50 = polyhedron(scene, dps=50)
    for e in solve(scene).equilibria:
        st = floating_state(poly50, e.up, Fraction(3, 10))
        with mpmath.workdps(50):
            d = [g - b for g, b in zip(st.G, st.B)]
            g = [sum(x * y for x, y in zip(basis, d)) for basis in st.basis]
        lam = min(abs(x) for x in e.eigenvalues)
        assert float(mpmath.sqrt(g[0] ** 2 + g[1] ** 2)) / lam <= max(e.error_rad * 10, 1e-14)
        assert e.error_rad <= 1e-9


# -- bad input ---------------------------------------------------------------------------------

@pytest.mark.parametrize("args", [
    ("cube", "0"), ("cube", "1"), ("cube", "-0.2"), ("cube", "nan"), ("cube", "1.5"), ("cube", "inf"),
    ("cube", "2*3"), ("cube", "__import__('os')"), ("box", "0.5", "1,2"), ("box", "0.5", "1,-2,3"),
    ("box", "0.5", "1,0,3"), ("box", "0.5", "1,nan,3"), ("ball", "0.5"), ("cylinder", "0.5", "1,inf"),
])
def test_bad_scene_input_is_refused_with_a_message(args):
    with pytest.raises(SceneError):
        make_scene(*args)


@pytest.mark.parametrize("polygon", ["0,0 1,0", "0,0 1,1 1,0 0,1", "0,0 2,0 1,1 2,2 0,2", "0,0 1,0 2,0 1,1",
                                     "0,0 1,0 1,1 1,0", "0,0 1,0 x,1"])
def test_bad_polygons_are_refused(polygon):
    with pytest.raises(SceneError):
        make_scene("section", "0.5", polygon=polygon)


@pytest.mark.parametrize("polygon, says", [("0,0 1,1 1,0 0,1", "self-intersecting"),       # once "zero area"
                                           ("0,0 2,0 2,2 0,2 2,1", "not convex"),
                                           ("0,0 1,1 2,2", "zero area (its vertices lie on one line)")])
def test_a_bad_polygon_is_named_for_what_is_wrong(polygon, says):
    with pytest.raises(SceneError, match=re.escape(says)):
        make_scene("section", "0.5", polygon=polygon)


def test_prism_sides_are_checked():
    with pytest.raises(SceneError):
        make_scene("prism", "0.5", dims="1,2", sides="2")
    with pytest.raises(SceneError):
        make_scene("prism", "0.5", dims="1,2", sides="3.5")


def test_a_remembered_evaluation_is_the_evaluation_of_its_own_body_direction_and_density():
    # local() remembers float64 evaluations: a repeat is the same object, read-only; another body of the same
    # shape, another direction or another density (also 1/3 given as a float) is evaluated for itself
    from symfloat.solver.local import _evaluated
    cube, long_box = box(1, 1, 1), box(1, 1, 3)
    u = np.array([0.3, 0.2, 0.9])
    first = local(cube, u, Fraction(1, 3))
    assert local(cube, u.copy(), Fraction(1, 3)) is first
    with pytest.raises(ValueError):
        first.gradient[0] = 1.0
    for poly, v, s in ((long_box, u, Fraction(1, 3)), (cube, u + [0, 0, 1e-12], Fraction(1, 3)),
                       (cube, u, Fraction(2, 5)), (cube, u, 1 / 3)):
        got, fresh = local(poly, v, s), _evaluated(poly, v, s)
        assert got is not first and got.U == fresh.U and np.array_equal(got.gradient, fresh.gradient)
    assert local(long_box, u, Fraction(1, 3)).U != first.U
