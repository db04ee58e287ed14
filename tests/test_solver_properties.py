"""Properties of the solver on random bodies (issue 14): for random convex polygons and random boxes at
random densities the index check holds (solve raises IndexCheckError otherwise) and the duality holds:
floating at density s with up u is floating at 1 - s with up -u (the submerged part of one is the
emerged part of the other), so the stable classes at 1 - s are those at s turned upside down.

The default run draws a few examples (fast); ``pytest -m slow`` draws many more."""
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from symfloat.geometry.convex import hull_2d, polygon_area
from symfloat.solver import make_scene, solve
from symfloat.solver.symmetry import symmetry_group
from symfloat.solver.symmetry import same_class

densities = st.integers(2, 98).map(lambda k: Fraction(k, 100) + Fraction(1, 997))
dims = st.tuples(*[st.integers(1, 4).map(Fraction)] * 3)
points = st.lists(st.tuples(st.integers(-6, 6), st.integers(-6, 6)), min_size=3, max_size=9, unique=True)


def _polygon(pts):
    hull = hull_2d([(Fraction(x), Fraction(y)) for x, y in pts])
    return hull if len(hull) >= 3 and polygon_area(hull) != 0 else None


def _dual_holds(scene_at):
    s = scene_at.density
    low, high = solve(scene_at), solve(make_scene(scene_at.body, 1 - s, scene_at.dims or None,
                                                  polygon=scene_at.polygon or None))
    group = symmetry_group(scene_at)
    stable = lambda sol: [np.array(e.up) for e in sol.equilibria if e.stability == "stable"]
    a, b = stable(low), stable(high)
    return len(a) == len(b) and all(any(same_class(-u, v, group, 1e-6) for v in b) for u in a)


def _check_box(d, s):
    scene = make_scene("box", s, dims=d)
    sol = solve(scene)                                     # raises IndexCheckError when the sum fails
    assert sol.checks["poincare_hopf_index_sum"] == 2          # families counted: the sum always applies
    assert _dual_holds(scene)


def _check_section(pts, s):
    polygon = _polygon(pts)
    if polygon is None:
        return
    scene = make_scene("section", s, polygon=polygon)
    sol = solve(scene)
    assert sol.checks["minima_minus_maxima"] == 0
    assert _dual_holds(scene)


@settings(max_examples=3, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(dims, densities)
def test_random_boxes_index_and_duality(d, s):
    _check_box(d, s)


@settings(max_examples=6, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(points, densities)
def test_random_sections_index_and_duality(pts, s):
    _check_section(pts, s)


@pytest.mark.slow
@settings(max_examples=40, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(dims, densities)
def test_random_boxes_index_and_duality_many(d, s):
    _check_box(d, s)


@pytest.mark.slow
@settings(max_examples=100, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(points, densities)
def test_random_sections_index_and_duality_many(pts, s):
    _check_section(pts, s)


# next to a bifurcation: a box whose upright position (the edge c vertical over a x b, a <= b) changes stability at
# s* = 1/2 - sqrt(1/4 - (a/c)^2/6) (Scheeffer IV (18)), at s* + offset with offsets from 1e-3 down to 1e-12, where the
# scenes of issue 14 failed (a missed tilted class, an undecided one with the index sum skipped)
near_dims = st.tuples(st.integers(1, 3), st.integers(1, 3), st.integers(4, 9)).map(
    lambda t: (Fraction(min(t[:2])), Fraction(max(t[:2])), Fraction(t[2])))
offsets = st.sampled_from([-1e-3, -1e-7, -1e-12, 1e-12, 1e-9, 1e-7, 1e-5, 1e-3])


def _check_box_near_threshold(d, offset):
    # a square cross-section (a = b) gives birth to a ring around the axis, of radius ~ sqrt(offset): closer
    # than 1e-8 its points are beyond float64 Newton (docs/performance.md), the scene fails its check (exit 1)
    # rather than answer, and the duality cannot be tested there
    assume(d[0] != d[1] or abs(offset) >= 1e-8)
    import mpmath
    with mpmath.workdps(40):
        s_star = mpmath.mpf(1) / 2 - mpmath.sqrt(mpmath.mpf(1) / 4 - (mpmath.mpf(d[0].numerator) / d[2].numerator) ** 2 / 6)
        s = Fraction(mpmath.nstr(s_star + mpmath.mpf(offset), 35))
    _check_box(d, s)


@settings(max_examples=2, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(near_dims, offsets)
def test_boxes_next_to_their_upright_threshold_index_and_duality(d, offset):
    _check_box_near_threshold(d, offset)


@pytest.mark.slow
@settings(max_examples=30, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(near_dims, offsets)
def test_boxes_next_to_their_upright_threshold_index_and_duality_many(d, offset):
    _check_box_near_threshold(d, offset)
