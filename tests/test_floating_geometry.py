"""Floating convex bodies by clipping, against values known independently.

Every expected value is elementary (boxes, similar triangles, symmetry) or
classical (the semicircle's centroid), and its provenance is stated beside
it.  Key tests run in float64 and in mpmath at 30 digits, with the error
each arithmetic promises in ``symfloat/geometry/floating.py``.
"""
import math
import random
from fractions import Fraction as F

import mpmath
import pytest

from symfloat.geometry.convex import hull_volume_centroid
from symfloat.geometry.floating import (
    Polyhedron, box, clip_below, cylinder_state, draught, floating_state, heel, regular_prism,
    right_prism, submerged, volume_centroid, waterplane_basis,
)
from symfloat.geometry.prismatoid import random_convex_polygon

PRECISIONS = [None, 30]


def tol(dps):
    """The relative error the module promises: 1e-12 (float64), 10**(-dps+5)."""
    return 1e-12 if dps is None else mpmath.mpf(10) ** (5 - dps)


def ae(a, b, dps, scale=1):
    return abs(a - b) <= tol(dps) * scale


def sqrt(x, dps):
    return math.sqrt(x) if dps is None else mpmath.sqrt(x)


def random_body(seed, dps=None):
    """A prism over a random convex lattice polygon, and a random 3-D up vector."""
    rng = random.Random(seed)
    polygon = random_convex_polygon(rng, points=8, size=5)
    u = [rng.uniform(-1, 1) for _ in range(3)]
    return polygon, right_prism(polygon, rng.randint(2, 9), dps), u


@pytest.mark.parametrize("dps", PRECISIONS)
def test_upright_box(dps):
    # a x b x c box, u = z, density s: immersion depth s c, so t = -c/2 + s c;
    # B at half that depth; waterplane the a x b rectangle with central
    # second moments a^3 b / 12 (about the y-parallel axis) and a b^3 / 12 (elementary)
    a, b, c = 3, 2, 5
    body = box(a, b, c, dps)
    with mpmath.workdps(dps or 15):
        for s in (F(1, 5), F(1, 2), F(7, 9)):
            s_ = float(s) if dps is None else mpmath.mpf(s.numerator) / s.denominator
            st = floating_state(body, (0, 0, 1), s_)
            assert ae(st.t, -c / 2 + s_ * c, dps, c)
            assert st.t_err <= tol(dps) * c
            assert ae(st.volume, s_ * a * b * c, dps, a * b * c)
            assert ae(st.B[2], st.t - s_ * c / 2, dps, c) and ae(st.B[0], 0, dps) and ae(st.B[1], 0, dps)
            assert st.G == (0, 0, 0) and ae(st.potential, c / 2 - s_ * c / 2, dps, c)
            assert st.basis[0] == (1, 0, 0) and st.basis[1] == (0, 1, 0)
            assert ae(st.waterplane_area, a * b, dps, a * b)
            (jxx, jxy), (jyx, jyy) = st.tensor
            assert ae(jxx, F(a ** 3 * b, 12), dps, a ** 4) and ae(jyy, F(a * b ** 3, 12), dps, a ** 4)
            assert ae(jxy, 0, dps, a ** 4) and jxy == jyx
            # I_min / V - BG from the elementary parts
            assert ae(st.metacentric_height, a * b ** 3 / (12 * s_ * a * b * c) - (c - s_ * c) / 2, dps, c)


@pytest.mark.parametrize("dps", PRECISIONS)
def test_cube_turned_45_degrees_about_an_edge_direction(dps):
    # u = (1, 1, 0)/sqrt 2: the plane t = 0 halves the cube by central symmetry;
    # it cuts the cube in a sqrt2 a (across, along e2) by a (along e1 = z) rectangle (elementary)
    a = 2
    body = box(a, a, a, dps)
    with mpmath.workdps(dps or 15):
        r2 = sqrt(2, dps)
        u = (1 / r2, 1 / r2, 0)
        sub = submerged(body, u, 0)
        assert ae(sub.volume, a ** 3 / 2, dps, a ** 3)
        wp = sub.waterplane
        assert len(wp.polygon) == 4 and ae(wp.area, r2 * a * a, dps, a * a)
        assert wp.basis[0] == (0, 0, 1)
        (j11, j12), (_, j22) = wp.tensor
        assert ae(j11, a ** 3 * (r2 * a) / 12, dps, a ** 4)     # along e1 = z: side a
        assert ae(j22, (r2 * a) ** 3 * a / 12, dps, a ** 4)     # along e2: side sqrt2 a
        assert ae(j12, 0, dps, a ** 4)
        t, err = draught(body, u, 0.5)
        assert abs(t) <= err <= tol(dps) * a


@pytest.mark.parametrize("dps", PRECISIONS)
def test_long_square_prism_with_a_diagonal_vertical(dps):
    # a x a section, length 5a, lying with a diagonal vertical, s = 1/2: the water
    # line is the other diagonal, of length a sqrt2 (elementary)
    a, length = 1, 5
    body = box(a, a, length, dps)
    with mpmath.workdps(dps or 15):
        r2 = sqrt(2, dps)
        st = floating_state(body, (1 / r2, 1 / r2, 0), 0.5)
        assert abs(st.t) <= st.t_err
        assert ae(st.waterplane_area / length, a * r2, dps, length)
        e2 = st.basis[1]
        across = [sum(p[k] * e2[k] for k in range(3)) for p in submerged(body, st.u, st.t).waterplane.polygon]
        assert ae(max(across) - min(across), a * r2, dps, length)
        assert ae(st.I_min, length * (a * r2) ** 3 / 12, dps, length ** 4)   # rectangle L x a sqrt2


@pytest.mark.parametrize("dps", PRECISIONS)
def test_triangular_prism_apex_down_is_similar(dps):
    # triangle with a horizontal top side of width 3 at height 2.5 above its apex:
    # below a water line d above the apex lies a similar triangle, of area
    # 3.75 (d / 2.5)^2, width 3 d / 2.5 and centroid 2d/3 above the apex (similar triangles)
    apex_y, height, width, length = -1, F(5, 2), 3, 2
    body = right_prism([(F(3, 10), apex_y), (2, F(3, 2)), (-1, F(3, 2))], length, dps)
    with mpmath.workdps(dps or 15):
        for d in (F(1, 10), F(1, 2), F(13, 10), F(5, 2)):
            sub = submerged(body, (0, 1, 0), apex_y + d)
            ratio = d / height
            assert ae(sub.volume, width * height / 2 * ratio ** 2 * length, dps, 10)
            assert ae(sub.waterplane.area, width * ratio * length, dps, 10)
            assert ae(sub.centroid[1], apex_y + 2 * d / 3, dps, 10)
        v1 = submerged(body, (0, 1, 0), apex_y + F(1, 4)).volume
        v2 = submerged(body, (0, 1, 0), apex_y + F(1, 2)).volume
        assert ae(v2 / v1, 4, dps, 10)                                 # area ~ draught^2


def test_submerged_volume_is_monotone_continuous_with_slope_the_waterplane_area():
    # V(t) = int_{-inf}^t A(tau) dtau for a convex body, so V is non-decreasing and
    # V'(t) = A(t); a cubic in t between vertex heights, so the central difference
    # is exact up to h^2 V''' / 6 (elementary)
    for seed in range(3):
        polygon, body, u = random_body(seed)
        total = volume_centroid(body)[0]
        norm = math.sqrt(sum(x * x for x in u))
        heights = [sum(p[k] * u[k] for k in range(3)) / norm for p in body.vertices]
        lo, hi = min(heights), max(heights)
        ts = [lo - 1 + (hi - lo + 2) * k / 120 for k in range(121)]
        vols = [submerged(body, u, t).volume for t in ts]
        assert vols[0] == 0 and abs(vols[-1] - total) <= 1e-12 * total
        assert all(b >= a - 1e-12 * total for a, b in zip(vols, vols[1:]))
        h = 1e-4 * (hi - lo)
        for t in ts[20:100:7]:
            slope = (submerged(body, u, t + h).volume - submerged(body, u, t - h).volume) / (2 * h)
            area = submerged(body, u, t).waterplane.area
            assert abs(slope - area) <= 1e-6 * (1 + area)
            assert abs(submerged(body, u, t + 1e-9).volume - submerged(body, u, t).volume) <= 2e-9 * (area + 1)


@pytest.mark.parametrize("dps", PRECISIONS)
def test_draught_root_and_its_bracket(dps):
    # the returned t satisfies V(t) = s V to within area * err, and the bracket
    # [t - err, t + err] straddles the root (the promise of draught())
    polygon, body, u = random_body(7, dps)
    with mpmath.workdps(dps or 15):
        total = volume_centroid(body)[0]
        for s in (0.03, 0.41, 0.5, 0.97):
            t, err = draught(body, u, s)
            sub = submerged(body, u, t)
            assert abs(sub.volume - s * total) <= sub.waterplane.area * err + tol(dps) * total
            assert submerged(body, u, t - err).volume <= s * total <= submerged(body, u, t + err).volume
            assert err <= 10 * tol(dps)
        t, err = draught(body, u, 0.3, tol=1e-4)
        assert err <= 1e-4


def test_clipping_above_or_below_the_body():
    # the plane above the body keeps all of it; below it keeps nothing (definition)
    for seed in range(4):
        polygon, body, u = random_body(seed)
        whole = volume_centroid(body)
        above = submerged(body, u, 1e3)
        assert above.volume == whole[0] and above.centroid == whole[1] and above.waterplane.area == 0
        assert volume_centroid(clip_below(body, u, 1e3)) == whole
        below = clip_below(body, u, -1e3)
        assert below.faces == () and volume_centroid(below) == (0, None)


@pytest.mark.parametrize("dps", PRECISIONS)
def test_planes_through_faces_edges_and_vertices(dps):
    # the plane through the top face keeps the whole box, through the bottom face
    # nothing; with u = (1,1,1)/sqrt3 the plane through the lowest vertex keeps nothing,
    # through its three neighbours the corner tetrahedron with legs 2 (volume 8/6, cap
    # equilateral of side 2 sqrt2, area 2 sqrt3), through the centre half the cube (elementary)
    body = box(2, 2, 2, dps)
    with mpmath.workdps(dps or 15):
        top, bottom = submerged(body, (0, 0, 1), 1), submerged(body, (0, 0, 1), -1)
        assert ae(top.volume, 8, dps, 8) and top.centroid == (0, 0, 0) and ae(top.waterplane.area, 4, dps)
        assert ae(bottom.volume, 0, dps, 8)
        r3 = sqrt(3, dps)
        u = (1 / r3, 1 / r3, 1 / r3)
        lowest = submerged(body, u, -r3)                # through (-1, -1, -1) only
        assert ae(lowest.volume, 0, dps, 8) and ae(lowest.waterplane.area, 0, dps, 8)
        corner = submerged(body, u, -1 / r3)            # through (1, -1, -1), (-1, 1, -1), (-1, -1, 1)
        assert len(corner.waterplane.polygon) == 3
        assert ae(corner.volume, F(8, 6), dps, 8)
        assert ae(corner.waterplane.area, 2 * r3, dps, 8)
        assert ae(submerged(body, u, 0).volume, 4, dps, 8)


def test_prism_volume_against_the_exact_rational_hull():
    # the prism's faces against convex.hull_volume_centroid in exact rationals
    for seed in range(4):
        polygon, body, u = random_body(seed)
        length = 2 * max(p[2] for p in body.vertices)
        exact_v, exact_c = hull_volume_centroid(
            [(x, y, z) for x, y in polygon for z in (-F(length) / 2, F(length) / 2)])
        v, c = volume_centroid(body)
        assert abs(v - exact_v) <= 1e-12 * exact_v
        assert all(abs(a - b) <= 1e-12 * 10 for a, b in zip(c, exact_c))


@pytest.mark.parametrize("dps", PRECISIONS)
def test_duality_of_the_two_sides_of_the_plane(dps):
    # {u.p <= t} and {-u.p <= -t} split the body: volumes add to the whole and
    # V1 B1 + V2 B2 = V G; the two see the same waterplane (definition)
    for seed in range(3):
        polygon, body, u = random_body(seed, dps)
        with mpmath.workdps(dps or 15):
            V, G = volume_centroid(body)
            t = 0.3 * (seed - 1)
            lower, upper = submerged(body, u, t), submerged(body, [-x for x in u], -t)
            assert ae(lower.volume + upper.volume, V, dps, V)
            for k in range(3):
                assert ae(lower.volume * lower.centroid[k] + upper.volume * upper.centroid[k], V * G[k], dps, 10 * V)
            assert ae(lower.waterplane.area, upper.waterplane.area, dps, V)
            assert ae(lower.waterplane.I_min, upper.waterplane.I_min, dps, V * 10)
            assert all(ae(a, b, dps, 10) for a, b in zip(lower.waterplane.centroid, upper.waterplane.centroid))


def test_float64_against_mpmath():
    # the float64 promise, 1e-12 relative to the body, against 30 digits
    for seed in range(2):
        polygon, body, u = random_body(seed)
        body30 = right_prism(polygon, 2 * max(p[2] for p in body.vertices), 30)
        a, b = floating_state(body, u, 0.37), floating_state(body30, u, 0.37)
        size = max(abs(c) for p in body.vertices for c in p)
        for f in ("t", "volume", "waterplane_area", "I_min", "I_max", "potential", "metacentric_height"):
            scale = {"volume": size ** 3, "waterplane_area": size ** 2, "I_min": size ** 4, "I_max": size ** 4}
            assert abs(getattr(a, f) - getattr(b, f)) <= 1e-12 * scale.get(f, size), f


def test_heel_and_the_waterplane_basis():
    # heel(phi) = (sin phi, cos phi, 0); (e1, e2, u) right-handed orthonormal; for u
    # across the axis z, e1 = z (definition)
    phi = 0.7
    u = heel(phi)
    assert u == (math.sin(phi), math.cos(phi), 0.0)
    e1, e2 = waterplane_basis(u)
    assert e1 == (0, 0, 1)
    for v in (heel(0.3, 0.4), (1, -2, 0.5)):
        e1, e2 = waterplane_basis(v)
        n = math.sqrt(sum(x * x for x in v))
        cross = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
        assert all(abs(c - x / n) < 1e-15 for c, x in zip(cross, v))


def test_regular_prism():
    # regular hexagon of side 1: area 3 sqrt3 / 2, circumradius 1, vertex on +x (elementary)
    body = regular_prism(6, 1, 2)
    v, c = volume_centroid(body)
    assert abs(v - 3 * math.sqrt(3)) < 1e-14 and all(abs(x) < 1e-15 for x in c)
    assert any(abs(p[0] - 1) < 1e-15 and p[1] == 0 for p in body.vertices)


def test_horizontal_cylinder_half_submerged():
    # s = 1/2 lying: water line through the axis, width 2r, waterplane L x 2r with
    # I_min = L (2r)^3 / 12; B at 4r / (3 pi) below the axis (centroid of a
    # semicircle, classical) -- within the stated Richardson error
    r, length = 1.5, 4
    for phi in (0.0, 0.3):
        u = heel(phi)
        cs = cylinder_state(r, length, u, 0.5, sides=64)
        value, err = cs.waterplane_area
        assert abs(value - 2 * r * length) <= err
        value, err = cs.I_min
        assert abs(value - length * (2 * r) ** 3 / 12) <= err
        depth = -sum(b * x for b, x in zip(cs.B[0], u))
        assert abs(depth - 4 * r / (3 * math.pi)) <= sum(cs.B[1])
        value, err = cs.volume
        assert abs(value - math.pi * r * r * length / 2) <= err
        assert sum(cs.B[1]) < 2e-3 and cs.waterplane_area[1] < 0.1


def test_heeled_cylinder_against_the_circular_segment():
    # s = 0.2: the segment of half-angle a with (2a - sin 2a) / 2 = s pi has chord 2 sin a
    # and centroid 4 sin^3 a / (3 (2a - sin 2a)) below the centre (classical); the
    # docstring promises the error is below the stated error
    r, length, s = 1, 3, 0.2
    a = float(mpmath.findroot(lambda a: (2 * a - mpmath.sin(2 * a)) / 2 - s * mpmath.pi, 1))
    for phi in (0.3, 1.1):
        u = heel(phi)
        cs = cylinder_state(r, length, u, s, sides=64)
        value, err = cs.waterplane_area
        assert abs(value - 2 * math.sin(a) * length) <= err / 2
        assert abs(cs.fine.waterplane_area - 2 * math.sin(a) * length) <= err / 2
        value, err = cs.t
        assert abs(value + math.cos(a)) <= err / 2
        depth = -sum(b * x for b, x in zip(cs.B[0], u))
        assert abs(depth - 4 * math.sin(a) ** 3 / (3 * (2 * a - math.sin(2 * a)))) <= sum(cs.B[1]) / 2


def test_upright_cylinder():
    # u along the axis: volume pi r^2 L s, waterplane the disk, pi r^2, with both
    # central second moments pi r^4 / 4 (classical)
    r, length, s = 2, 3, 0.3
    cs = cylinder_state(r, length, (0, 0, 1), s, sides=32)
    for (value, err), exact in ((cs.volume, math.pi * r * r * length * s), (cs.waterplane_area, math.pi * r * r),
                                (cs.I_min, math.pi * r ** 4 / 4), (cs.I_max, math.pi * r ** 4 / 4)):
        assert abs(value - exact) <= err / 2 and err < 1e-1 * exact
    value, err = cs.t
    assert abs(value - (-length / 2 + s * length)) <= 1e-12


def test_arguments_are_checked_and_precision_restored():
    body = box(1, 1, 1)
    with pytest.raises(ValueError):
        draught(body, (0, 0, 1), 1)
    with pytest.raises(ValueError):
        right_prism([(0, 0), (0, 1), (1, 0)], 1)           # clockwise
    with pytest.raises(ValueError):
        right_prism([(0, 0), (2, 0), (1, 0.2), (1, 1)], 1)  # not convex
    with pytest.raises(ValueError):
        submerged(body, (0, 0, 0), 0)
    with pytest.raises(TypeError):
        submerged([(0, 0, 0)], (0, 0, 1), 0)
    dps = mpmath.mp.dps
    floating_state(box(1, 2, 3, dps=40), (0, 0, 1), 0.5)
    assert mpmath.mp.dps == dps and isinstance(Polyhedron((), 40).dps, int)


def test_polygon_moments_keep_the_arithmetic_of_the_coordinates():
    # the one implementation of polygon moments (geometry/floating.py). Scheeffer IV-V's rectangle
    # (-1, -1/2) ... (1, 1/2) has Python int coordinates: their mean, divided by 4, was a float, and the
    # moments came out as 15-digit Floats (the digits lost when the derivation first used them); exact input
    # must give exact output.
    import sympy as sp
    from symfloat.geometry.floating import polygon_moments
    R = sp.Rational
    A, c, J = polygon_moments([(-1, R(-1, 2)), (1, R(-1, 2)), (1, R(1, 2)), (-1, R(1, 2))])
    assert (A, c, J) == (2, (0, 0), ((R(2, 3), 0), (0, R(1, 6))))      # 2 x 1: b h^3 / 12, h b^3 / 12
    assert all(isinstance(v, sp.Rational) for v in (A, J[0][0], J[1][1]))
    tri = polygon_moments([(F(0), F(0)), (F(2), F(0)), (F(0), F(1))])
    assert tri[0] == 1 and tri[1] == (F(2, 3), F(1, 3))   # the triangle's centroid, exactly
    assert isinstance(polygon_moments([(0.0, 0), (1, 0), (0, 1)])[0], float)


def test_an_mpmath_draught_starts_from_float64_and_keeps_its_bracket(monkeypatch):
    # a box with a corner out of the water (its volume a cubic in the offset): from the float64 draught Newton
    # needs two 40-digit clippings and the certifying bracket two more (from the mean offset it needed 5 to 12);
    # the result lies within its returned error of the 70-digit draught
    import symfloat.geometry.floating as floating
    calls = []
    clip = floating._volume_and_area
    monkeypatch.setattr(floating, "_volume_and_area", lambda poly, *a: calls.append(poly.dps) or clip(poly, *a))
    rng = random.Random(3)
    for _ in range(12):
        with mpmath.workdps(40):
            body = box(mpmath.mpf(3) / 2, 1, 2, 40)
            u = tuple(mpmath.mpf(rng.uniform(-1, 1)) for _ in range(3))
            s = mpmath.mpf(rng.choice(("0.02", "0.3", "0.8", "0.97")))
            del calls[:]
            t, err = draught(body, u, s)
            assert calls.count(40) <= 5
            assert 0 < err <= 10 * tol(40)
        with mpmath.workdps(70):
            fine = draught(box(mpmath.mpf(3) / 2, 1, 2, 70), u, s)[0]
        assert abs(t - fine) <= err
