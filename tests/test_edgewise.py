"""The edge-wise floating states (the solver's batched fast path) against the clipping module."""
import math

import numpy as np
import pytest

from symfloat.solver.edgewise import states
from symfloat.geometry.floating import box, floating_state, regular_prism
from symfloat.solver.critical import newton, newton_all, sphere_seeds

BODIES = [box(1, 1, 1), box(1, 2, 3), box(1, 1.5, 20), regular_prism(5, 1, 2)]


def _ups(seed):
    rng = np.random.default_rng(seed)
    ups = rng.normal(size=(60, 3))
    # symmetric positions, where vertices and edges lie in the water plane at s = 1/2 (cube: edge, corner up)
    ups[:4] = [(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 0)]
    return ups


@pytest.mark.parametrize("body", range(len(BODIES)))
@pytest.mark.parametrize("s", [0.01, 0.3, 0.5, 0.77, 0.99])
def test_states_agree_with_the_clipped_polyhedron(body, s):
    # the expected values: floating_state (Sutherland-Hodgman clipping, fan tetrahedra, the hull of the cap)
    poly = BODIES[body]
    size = max(abs(x) for ring in poly.faces for p in ring for x in p)
    ups = _ups(body)
    got = states(poly, ups, s)
    for j, u in enumerate(ups):
        ref = floating_state(poly, tuple(u), s)
        assert abs(got.t[j] - ref.t) <= 1e-13 * size
        assert abs(got.volume[j] - ref.volume) <= 1e-13 * size ** 3
        assert np.abs(got.B[j] - np.array(ref.B)).max() <= 1e-13 * size
        assert abs(got.potential[j] - ref.potential) <= 1e-13 * size
        assert abs(got.area[j] - ref.waterplane_area) <= 1e-13 * size ** 2
        assert np.abs(got.tensor[j] - np.array(ref.tensor, dtype=float)).max() <= 1e-13 * size ** 4
        assert np.abs(got.basis[j] - np.array(ref.basis).T).max() <= 1e-15


def test_a_thin_submerged_slice_keeps_its_digits():
    # s = 1e-3 of a long box: the tetrahedra are taken from a point of the water plane, so they are as small as
    # the submerged part; the reference is the clipped body at 40 digits
    import mpmath
    poly, exact = box(1, 1.5, 20), box(1, 1.5, 20, dps=40)
    ups = _ups(7)[:20]
    got = states(poly, ups, 1e-3)
    for j, u in enumerate(ups):
        ref = floating_state(exact, tuple(mpmath.mpf(float(x)) for x in u), 1e-3)
        assert max(abs(got.B[j][k] - float(ref.B[k])) for k in range(3)) <= 1e-13


@pytest.mark.parametrize("s", [0.05, 0.3])
def test_newton_all_reaches_what_newton_reaches(s):
    # the batched search takes the same steps as Newton's method seed by seed (to rounding)
    poly = box(1, 2, 3)
    seeds = sphere_seeds(4, math.pi / 2, 4)
    batch = newton_all(poly, seeds, s, 3.0)
    for seed, (loc, ok) in zip(seeds, batch):
        ref, ref_ok = newton(poly, seed, s, 3.0)
        assert ok == ref_ok
        if ok:
            assert np.linalg.norm(loc.u - ref.u) <= 1e-9
            assert abs(loc.U - ref.U) <= 1e-12
