"""Properties of the solver on random bodies (issue 14): for random convex polygons and random boxes at
random densities the index check holds (solve raises IndexCheckError otherwise) and the duality holds:
floating at density s with up u is floating at 1 - s with up -u (the submerged part of one is the
emerged part of the other), so the stable classes at 1 - s are those at s turned upside down.

The default run draws a few examples (fast); ``pytest -m slow`` draws many more."""
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from symfloat.geometry.convex import hull_2d, polygon_area
from symfloat.solver import make_scene, solve
from symfloat.solver.coverage import symmetry_group
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
    assert sol.checks["poincare_hopf_index_sum"] in (2, None)
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
