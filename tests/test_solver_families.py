"""The index check with one-parameter families (issue 14): an arc counts the winding of the gradient on a
stadium round it, a closed ring that on the annulus round it, and the sum must be 2 in every scene.

Before, a scene with a family skipped the check ("one-parameter families present"), and three scenes exited 0
with a stable class missing or a position fixed by symmetry missing.  Expected values, computed without the
solver:

- duality: floating at s with up u is floating at 1 - s with up -u, with the same stability; a box's group
  holds -1, so the classes at s and 1 - s have the same representatives;
- the positions on a mirror of the box 1 x 3/2 x 1 (|u_x| = |u_z|) and of the long square log 1 x 1 x 4
  (|u_x| = |u_y|): the minimum of the potential along the mirror, from the clipped body's floating state
  (golden-section search), as in tests/test_solver_log.py;
- the potential along the ring of the box 1 x 3/2 x 1 round y (tilt 0.1752 rad from y, the arcs' tilt),
  evaluated by the floating state: it falls past an arc's ends towards the diagonal, so each arc counts -1.
"""
import importlib
import math
from fractions import Fraction

import numpy as np
import pytest

from symfloat.geometry.floating import box, floating_state
from symfloat.solver import make_scene, solve
from symfloat.solver.bodies import polyhedron
from symfloat.solver.critical import critical_points, distinct_seeds, sphere_seeds
from symfloat.solver.families import contour_winding, stadium
from symfloat.solver.selfcheck import IndexCheckError
from symfloat.solver.symmetry import box_group, same_class

solve_module = importlib.import_module("symfloat.solver.solve")    # the module, not the function it exports
families_module = importlib.import_module("symfloat.solver.families")
DIAGONAL = np.array([0.123210, 0.984702, 0.123210])     # the stable class of the box 1 x 3/2 x 1 at 0.081949 (its dual)


def _mirror_minimum(dims, s, mirror, lo: float, hi: float) -> float:
    """The angle t of the potential's minimum along the mirror curve ``mirror(t)`` (golden-section search), the
    potential of a 30-digit body: where the minimum is flat (curvature c about 1e-10), float64's rounding of the
    potential (about 1e-16) would move it by sqrt(1e-16 / c), 1e-3; at 30 digits by about 1e-9."""
    body = box(*dims, dps=30)
    potential = lambda t: floating_state(body, tuple(mirror(t)), s).potential  # noqa: E731
    golden = (math.sqrt(5) - 1) / 2
    a, b = hi - golden * (hi - lo), lo + golden * (hi - lo)
    pa, pb = potential(a), potential(b)
    for _ in range(60):
        if pa < pb:
            hi, b, pb = b, a, pa
            a = hi - golden * (hi - lo)
            pa = potential(a)
        else:
            lo, a, pa = a, b, pb
            b = lo + golden * (hi - lo)
            pb = potential(b)
    return (lo + hi) / 2


def _from_y(t):       # the mirror |u_x| = |u_z| of the box 1 x 3/2 x 1, t the tilt from y
    return (math.sin(t) / math.sqrt(2), math.cos(t), math.sin(t) / math.sqrt(2))


def _stable_in_class(sol, u, tol=1e-5):
    group = box_group(sol.scene.dims)
    return [e for e in sol.equilibria if e.stability == "stable" and e.family == "isolated"
            and same_class(np.array(e.up), u / np.linalg.norm(u), group, tol)]


@pytest.mark.parametrize("s", [Fraction("0.918051"), Fraction("0.081949")])
def test_the_stable_diagonal_class_of_the_box_1_15_1_is_found_on_both_sides(s):
    # before: at 0.918051 exit 0 with 6 classes, the stable class at -(0.123210, 0.984702, 0.123210) (pentagon
    # waterplane) missing while its dual 0.081949 lists it (docs/atlas.md, cell b/a = 3/2, c/a = 1)
    sol = solve(make_scene("box", s, "1,3/2,1"))
    found = _stable_in_class(sol, DIAGONAL)
    assert len(found) == 1 and found[0].waterplane == "pentagon"
    t = _mirror_minimum((1, Fraction(3, 2), 1), s, _from_y, 0.1, 0.21)
    assert abs(math.acos(max(abs(x) for x in found[0].up)) - t) <= 1e-6
    assert sol.checks["poincare_hopf_index_sum"] == 2 and sol.checks["family_indices"] == [-1]


def test_the_long_log_keeps_its_stable_diagonal_class_beside_the_arcs():
    # before: at 1 - 0.0105466 the walk along an arc crossed the gap where the stable diagonal class lies (its
    # potential the arcs' to 1e-13) and took it in: exit 0, a stable class missing that the dual 0.0105466 lists
    s = 1 - Fraction("0.0105466")
    sol = solve(make_scene("box", s, "1,1,4"))
    diagonal = lambda t: (math.sin(t) / math.sqrt(2), math.sin(t) / math.sqrt(2), math.cos(t))  # noqa: E731
    stable = [e for e in sol.equilibria if e.stability == "stable" and e.family == "isolated"
              and abs(abs(e.up[0]) - abs(e.up[1])) <= 1e-9 and 0 < abs(e.up[2]) < 1]
    assert len(stable) == 1 and not stable[0].ring_shape
    assert abs(math.acos(abs(stable[0].up[2])) - _mirror_minimum((1, 1, 4), s, diagonal, 0.055, 0.062)) <= 1e-6
    arcs = [e for e in sol.equilibria if e.family == "ring"]
    assert len(arcs) == 1 and arcs[0].ring_shape == "arc" and sol.checks["family_indices"] == [-1]


@pytest.mark.parametrize("x", ["0.0105465"])
def test_the_long_log_7e_8_past_its_vertex_event_keeps_its_diagonal_class_on_both_sides(x):
    # before: at 1 - 0.0105465 the stable diagonal class (soft eigenvalue 1.2e-10, decided: the arcs' is 5e-15)
    # was walked as a point of one closed ring round the end face; ring (index 0), stable and saddle diagonal
    # classes (+8 - 8) summed to 2, exit 0, while the dual 0.0105465 lists the arcs and the stable class
    low, high = (solve(make_scene("box", s, "1,1,4")) for s in (Fraction(x), 1 - Fraction(x)))
    group = box_group(low.scene.dims)
    a, b = _stable_isolated(low), _stable_isolated(high)
    assert len(a) == len(b) == 2 and all(any(same_class(-u, v, group, 1e-6) for v in b) for u in a)
    for sol in (low, high):
        assert [e.ring_shape for e in sol.equilibria if e.family == "ring"] == ["arc"]
        assert sol.checks["family_indices"] == [-1] and sol.checks["poincare_hopf_index_sum"] == 2


def test_the_gradient_above_one_half_is_the_dual_bodys():
    # floating at s with up u is floating at 1 - s with up -u: grad U_s(u) = -(1 - s) / s grad U_(1 - s)(-u) and
    # U_s(u) = (1 - s) / s U_(1 - s)(-u), from the clipped bodies at both densities (not from the identity)
    body, s = box(1, 1, 4), 1 - 0.0105465
    points = np.array([[0.05, 0.02, 0.998], [0.3, 0.1, 0.9], [0.6, 0.7, 0.1]])
    points /= np.linalg.norm(points, axis=1)[:, None]
    g, U = families_module._gradient(body, s)(points)          # evaluated at 1 - s, up -u
    for p, gp, Up in zip(points, g, U):
        state = floating_state(body, tuple(p), s)               # the body itself at s, up u
        direct = np.asarray(state.G, dtype=float) - np.asarray(state.B, dtype=float)
        direct -= (direct @ p) * p
        k = np.linalg.norm(direct) / np.linalg.norm(gp)
        # same direction, not reversed; to 1e-9: the direct float64 gradient near s = 1 is a difference of two
        # centroids 4e-7 apart and keeps about 10 digits (2e-11 here), which is why the dual is evaluated
        assert np.linalg.norm(direct - k * gp) <= 1e-9 * np.linalg.norm(direct)
        assert k == pytest.approx((1 - s) / s, rel=1e-9)
        assert float(state.potential) == pytest.approx(k * Up, rel=1e-9)


@pytest.mark.parametrize("s", [Fraction("0.9194351"), Fraction("0.0805649")])
def test_the_ring_born_from_y_up_has_its_axis_inside(s):
    # before: just below 0.9194352 the small ring round y was found but y up, an equilibrium by symmetry
    # (fixed by the mirrors x -> -x and z -> -z), was dropped as a point of the ring (same potential, soft)
    sol = solve(make_scene("box", s, "1,3/2,1"))
    assert [e.up for e in sol.equilibria if e.up == (0.0, 1.0, 0.0)] == [(0.0, 1.0, 0.0)]
    rings = [e for e in sol.equilibria if e.family == "ring"]
    assert len(rings) == 1 and rings[0].ring_shape == "closed"
    assert sol.checks["family_indices"] == [0] and sol.checks["poincare_hopf_index_sum"] == 2


def test_a_closed_ring_counts_zero():
    # the long square log's ring round its end face at 0.01054 (tests/test_solver_log.py), Morse-Bott: the
    # annulus round it has Euler characteristic 0, measured as the winding outside less the winding inside
    sol = solve(make_scene("box", Fraction("0.01054"), "1,1,4"))
    assert [e.ring_shape for e in sol.equilibria if e.family == "ring"] == ["closed"]
    assert sol.checks["family_indices"] == [0] and sol.checks["poincare_hopf_index_sum"] == 2


def test_the_arcs_of_the_box_1_15_1_fall_past_their_ends():
    # the arc's index -1 (each of 8 copies) from the potential along its circle: flat on the arc, lower past its
    # ends (towards the stable diagonal class between two arcs), which makes the arc a saddle of the ring
    s = Fraction("0.081949")
    body = box(1, Fraction(3, 2), 1)
    tilt = math.acos(0.984708)

    def potential(azimuth):       # round y, azimuth from z towards x
        u = (math.sin(tilt) * math.sin(azimuth), math.cos(tilt), math.sin(tilt) * math.cos(azimuth))
        return float(floating_state(body, u, s).potential)
    middle, past = potential(0.0), [potential(a) for a in (math.radians(42), -math.radians(42))]
    assert all(p < middle - 1e-10 for p in past)           # 3.5e-10 lower at 42 degrees
    sol = solve(make_scene("box", s, "1,3/2,1"))
    assert sol.checks["family_indices"] == [-1]


@pytest.mark.parametrize("sign, expected", [(1, 1), (-1, -1), (0, 0)])
def test_the_winding_round_an_analytic_arc(sign, expected):
    # f = y^2 + sign * h(x) (h = (|x| - a)^4 past the segment |x| <= a, zero on it), near the north pole in the
    # coordinates x = u_x / u_z, y = u_y / u_z: a flat segment of minima across; rising past both ends: index +1
    # (a minimum), falling past both: -1 (a saddle), rising past one end only (sign 0 here: + on the right,
    # - on the left): 0
    a = 0.02
    path = [np.array([x, 0.0, 1.0]) / math.hypot(x, 1.0) for x in np.linspace(-a, a, 9)]

    def gradient(points):
        x, y = points[:, 0] / points[:, 2], points[:, 1] / points[:, 2]
        past = np.maximum(np.abs(x) - a, 0.0)
        slope = 4 * past ** 3 * np.sign(x) * (sign if sign else np.sign(x))
        g = np.stack([slope, 2 * y, np.zeros_like(x)], axis=1)
        return g, np.zeros(len(x))
    turns, least, _ = contour_winding(stadium(path, 0.01), np.array([0.0, 0.0, 1.0]), gradient)
    assert turns == expected and least > 0


def test_dropping_any_class_breaks_the_sum():
    # mutation: the classes of the box 1 x 3/2 x 1 at 0.081949 close the sum; without any one of them it fails
    scene = make_scene("box", Fraction("0.081949"), "1,3/2,1")
    poly, group, scale = polyhedron(scene), box_group(scene.dims), 1.5
    seeds = distinct_seeds(sphere_seeds(10, math.pi / 2, 10), group)
    classified, _, index = solve_module._searched(poly, scene.density, seeds, group, scale)
    points = [c for c, _, _ in classified]
    assert index == 2 and len(points) == 7
    for k in range(len(points)):
        assert solve_module._index_sum(poly, scene.density, points[:k] + points[k + 1:], group, scale) != 2


def test_a_missed_class_next_to_a_family_is_an_error(monkeypatch):
    # mutation: a search that never keeps the stable diagonal class must fail the scene (exit 1) naming the arc,
    # never exit 0 with a wrong stable set
    group = box_group((1, Fraction(3, 2), 1))

    def blind(*args, **kwargs):
        return [c for c in critical_points(*args, **kwargs)
                if not same_class(c.u, DIAGONAL / np.linalg.norm(DIAGONAL), group, 1e-5)]
    monkeypatch.setattr(solve_module, "critical_points", blind)
    with pytest.raises(IndexCheckError, match=r"index sum of the equilibria found is -6, not 2.*families: arc"):
        solve(make_scene("box", Fraction("0.081949"), "1,3/2,1"))


def _stable_isolated(sol):
    return [np.array(e.up) for e in sol.equilibria if e.stability == "stable" and e.family == "isolated"]


@pytest.mark.slow
@pytest.mark.parametrize("dims, densities", [
    ("1,1,4", ["0.01054645", "0.0105466", "0.0105467", "0.0105468", "0.010547", "0.0105473"]),   # vertex event 0.0105464
    ("1,3/2,1", ["0.08191", "0.081925", "0.08194", "0.081949", "0.08196", "0.08198"]),
])
def test_next_to_the_vertex_events_both_sides_agree(dims, densities):
    # duality (u -> -u, same stability) scene by scene, from 2e-8 past the long log's vertex event (0.0105464:
    # docs/numerics.md section 4) to past the fold
    for x in densities:
        low, high = (solve(make_scene("box", s, dims)) for s in (Fraction(x), 1 - Fraction(x)))
        group = box_group(low.scene.dims)
        a, b = _stable_isolated(low), _stable_isolated(high)
        assert len(a) == len(b) == 2 and all(any(same_class(-u, v, group, 1e-6) for v in b) for u in a), x
        assert [e.ring_shape for e in low.equilibria if e.family == "ring"] == ["arc"] == \
            [e.ring_shape for e in high.equilibria if e.family == "ring"]


def test_the_cube_1e_6_past_the_end_of_its_whole_ring_counts_its_arcs():
    # (3 - sqrt 2)/7 + 1e-6, the atlas's look beside Scheeffer X's threshold (80): the stable diagonal class's soft
    # eigenvalue is 8e-15 (decided at 30 digits), the arcs' walk stops 2.4e-5 short of it and the winding round
    # their ends was rounding (index 0, sum 26, exit 1); each arc falls past both ends into a minimum: -1
    import mpmath
    with mpmath.workdps(50):
        s = Fraction(mpmath.nstr((3 - mpmath.sqrt(2)) / 7 + mpmath.mpf("1e-6"), 40))
    sol = solve(make_scene("cube", s))
    diagonal = [e for e in sol.equilibria if e.stability == "stable" and e.family == "isolated"
                and abs(abs(e.up[0]) - abs(e.up[1])) <= 1e-9 and 0.9 < abs(e.up[2]) < 1]
    assert len(diagonal) == 1 and diagonal[0].copies == 24
    assert sol.checks["family_indices"] == [-1] and sol.checks["poincare_hopf_index_sum"] == 2


def test_an_arc_walked_past_its_end_is_not_closed():
    # the box 1 x 3/2 x 1 at 0.0820247 (an interval sample of the atlas's cell b/a = 3/2, c/a = 1): past the end of
    # the arc about y Newton's method settled behind the walk, which went back through its start and called the
    # arc a closed ring of length 0.176 (index 0, sum 10, exit 1); a step must now go ahead
    s = Fraction(1477625250177179, 18014398509481984)
    sol = solve(make_scene("box", s, "1,3/2,1"))
    rings = [e for e in sol.equilibria if e.family == "ring"]
    assert [e.ring_shape for e in rings] == ["arc"] and sol.checks["family_indices"] == [-1]
    # the stable class on the mirror |u_x| = |u_z| at the potential's minimum along it (golden-section search)
    found = _stable_in_class(sol, DIAGONAL, 0.05)
    assert len(found) == 1
    assert abs(math.acos(max(abs(x) for x in found[0].up)) - _mirror_minimum((1, Fraction(3, 2), 1), s, _from_y, 0.1,
                                                                              0.25)) <= 1e-6


@pytest.mark.slow
@pytest.mark.parametrize("delta", ["1e-11", "1e-10", "1e-9", "3e-9"])
def test_closer_to_the_vertex_event_a_scene_is_right_or_stops(delta):
    # e = (96 - sqrt 8768)/224 (the ring's diagonal points reach a bottom vertex; phase box --dims 1,1,4 locates it to
    # 6e-16): within 6e-9 past e the stable diagonal class's soft eigenvalue is below 1e-12 and a side may not
    # resolve it, but it never reports the closed ring past e and exits 0 (docs/performance.md)
    import mpmath
    with mpmath.workdps(50):
        s = Fraction(mpmath.nstr((96 - mpmath.sqrt(8768)) / 224 + mpmath.mpf(delta), 40))
    for side in (s, 1 - s):
        try:
            sol = solve(make_scene("box", side, "1,1,4"))
        except IndexCheckError:
            continue
        assert [e.ring_shape for e in sol.equilibria if e.family == "ring"] == ["arc"]
        assert len(_stable_isolated(sol)) == 2 and sol.checks["poincare_hopf_index_sum"] == 2


@pytest.mark.parametrize("s", [Fraction("0.2266"), Fraction("0.7734")])
def test_the_cube_just_past_the_end_of_its_whole_ring_has_its_diagonal_class(s):
    # issue 14: "tilted, |u_x| = |u_y|: stable above" (3 - sqrt 2)/7 = 0.2265409 (Scheeffer X); at 0.2266 and its dual
    # the scene listed the arc round z without the stable class between two arcs (exit 0, the index sum skipped)
    sol = solve(make_scene("cube", s))
    diagonal = [e for e in sol.equilibria if e.stability == "stable" and e.family == "isolated"
                and abs(abs(e.up[0]) - abs(e.up[1])) <= 1e-9 and 0.9 < abs(e.up[2]) < 1]
    assert len(diagonal) == 1 and diagonal[0].copies == 24
    mirror = lambda t: (math.sin(t) / math.sqrt(2), math.sin(t) / math.sqrt(2), math.cos(t))  # noqa: E731
    assert abs(math.acos(abs(diagonal[0].up[2])) - _mirror_minimum((1, 1, 1), s, mirror, 0.25, 0.37)) <= 1e-6
    assert sol.checks["poincare_hopf_index_sum"] == 2 and sol.checks["family_indices"] == [-1]


@pytest.mark.parametrize("body, dims, end, delta", [
    ("cube", None, Fraction(1, 4), Fraction(1, 10 ** 6)),           # the end of the ring round z (phase cube)
    ("cube", None, Fraction(1, 4), Fraction(1, 10 ** 9)),
    ("box", "1,3/2,1", Fraction(1, 12), Fraction(1, 10 ** 6)),     # the end of the ring round y (phase box)
])
def test_a_short_arc_beside_a_ring_end_is_an_arc(body, dims, end, delta):
    # issue 33: beside a ring's end, where the waterplane meets a vertex (the cube at 1/4, the box 1 x 3/2 x 1 at
    # 1/12: the thresholds of their phase diagrams), only arcs of the ring remain, shorter than the walk reports
    # as a family; they were reported as isolated stable points with a zero eigenvalue (the cube at 1/4 - 1e-6:
    # eigenvalues [1.4e-49, 0.093], its error 3.6e-6 rad the arc's half length)
    sol = solve(make_scene(body, end - delta, dims))
    assert sol.checks["poincare_hopf_index_sum"] == 2
    zero = [e for e in sol.equilibria if e.family == "isolated" and min(abs(x) for x in e.eigenvalues) < 1e-12]
    arcs = [e for e in sol.equilibria if e.family == "ring"]
    assert not zero and [(e.ring_shape, e.stability) for e in arcs] == [("arc", "stable")]
    assert 0 < arcs[0].ring_length <= arcs[0].ring_length + arcs[0].ring_length_error < 0.1
    if body == "cube" and delta == Fraction(1, 10 ** 6):
        # its length, 16 delta sin(theta) at tilt theta = atan(1/2) (the brute-force measurement), resolved
        assert abs(arcs[0].ring_length - 16 * float(delta) / math.sqrt(5)) <= 1e-3 * arcs[0].ring_length
