"""Exact convex geometry against values known independently."""
import random
from fractions import Fraction as F

import pytest

from symfloat.geometry.convex import hull_2d, hull_volume_centroid, polygon_area, section_area
from symfloat.geometry.prismatoid import prismatoid_parameters, random_prismatoid


def test_unit_tetrahedron():
    # volume 1/6 and centroid (1/4, 1/4, 1/4): elementary
    pts = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    assert hull_volume_centroid(pts) == (F(1, 6), (F(1, 4), F(1, 4), F(1, 4)))


def test_a_tetrahedron_with_coordinates_of_several_denominators():
    # the hull's planes are found on the points scaled by the common denominator 30: volume (1/2)(1/3)(1/5)/6 and
    # centroid the vertices' mean (1/8, 1/12, 1/20); a point given as an int and as a Fraction is one point
    pts = [(0, 0, 0), (F(1, 2), 0, 0), (0, F(1, 3), 0), (0, 0, F(1, 5)), (F(0), F(0), F(0)), (F(1, 10), F(1, 12), 0)]
    assert hull_volume_centroid(pts) == (F(1, 180), (F(1, 8), F(1, 12), F(1, 20)))


def test_interior_points_do_not_change_the_hull():
    cube = [(x, y, z) for x in (0, 2) for y in (0, 2) for z in (0, 2)]
    assert hull_volume_centroid(cube + [(1, 1, 1), (1, 0, 1)]) == (F(8), (F(1), F(1), F(1)))


def test_box_with_coplanar_face_points():
    # a 3 x 2 x 1 box with extra points on its faces: volume 6, centre (3/2, 1, 1/2)
    box = [(x, y, z) for x in (0, 3) for y in (0, 2) for z in (0, 1)] + [(1, 0, 0), (3, 1, 1), (2, 2, 0)]
    assert hull_volume_centroid(box) == (F(6), (F(3, 2), F(1), F(1, 2)))


def test_square_pyramid_sections():
    # apex (0,0,3) over the square [-1,1]^2: section at height z is (2 (1 - z/3))^2
    pts = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0), (0, 0, 3)]
    for k in range(4):
        zz = F(k, 2)
        assert section_area(pts, 2, zz) == (2 * (1 - zz / 3)) ** 2
    assert hull_volume_centroid(pts)[0] == F(4)        # base 4, height 3: 4*3/3


def test_polygon_hull_and_area():
    poly = hull_2d([(0, 0), (2, 0), (2, 2), (0, 2), (1, 1), (1, 0)])
    assert poly == [(0, 0), (2, 0), (2, 2), (0, 2)] and polygon_area(poly) == 4


@pytest.mark.parametrize("seed", range(5))
def test_random_prismatoid_volume_by_slices_matches_hull(seed):
    # Independent of every formula: the hull volume equals the integral of the
    # exact section areas, which are quadratic in z, integrated by Simpson's
    # rule on a fine grid of 20 panels (exact for quadratics).
    pts = random_prismatoid(seed)
    G, g, D, h = prismatoid_parameters(pts)
    n = 20
    areas = [section_area(pts, 2, h * k / n) for k in range(n + 1)]
    simpson = h / n / 3 * sum(a * (1 if k in (0, n) else 4 if k % 2 else 2) for k, a in enumerate(areas))
    assert hull_volume_centroid(pts)[0] == simpson
    assert (G, g) == (areas[0], areas[-1]) and D == areas[n // 2]


def test_random_polygon_is_convex_and_ccw():
    rng = random.Random(3)
    from symfloat.geometry.prismatoid import random_convex_polygon
    poly = random_convex_polygon(rng)
    n = len(poly)
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = poly[i], poly[(i + 1) % n], poly[(i + 2) % n]
        assert (bx - ax) * (cy - by) - (by - ay) * (cx - bx) > 0


def test_heron_area_against_the_cross_product_and_line_meet_against_exact_rationals():
    # symfloat.geometry.construction: Heron's formula from the side lengths alone against |(q - p) x (r - p)|/2 in
    # exact rationals (its square), at 50 digits; the meeting point of two lines against Cramer's rule in Fractions
    import random
    from fractions import Fraction as F
    import mpmath
    from symfloat.geometry.construction import heron_area, line_meet
    rng = random.Random(5)
    with mpmath.workdps(50):
        for _ in range(5):
            p, q, r = ([F(rng.randint(-9, 9)) for _ in range(3)] for _ in range(3))
            u, v = [b - a for a, b in zip(p, q)], [b - a for a, b in zip(p, r)]
            cross = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
            area2 = sum(c * c for c in cross) / 4
            exact2 = mpmath.mpf(area2.numerator) / area2.denominator
            got = heron_area(*(mpmath.matrix([mpmath.mpf(int(x)) for x in pt]) for pt in (p, q, r)))
            assert abs(got ** 2 - exact2) < mpmath.mpf(10) ** -40 * (1 + exact2)
            # the lines p + t (q - p) and r + t' (m - r), m the midpoint of p q (they meet there, t = 1/2)
            m = [(a + b) / 2 for a, b in zip(p, q)]
            meet = line_meet(*(mpmath.matrix([mpmath.mpf(x.numerator) / x.denominator for x in pt]) for pt in (p, q, r, m)))
            if area2:
                assert all(abs(meet[k] - mpmath.mpf(m[k].numerator) / m[k].denominator) < mpmath.mpf(10) ** -40
                           for k in range(3))


# ---- side faces of prismatoids: the hull's faces and two plane sections --------------------------------------
# counts by hand: a prism has one rectangle per side; a pyramid one triangle per side of its base; a square over
# the same square turned by 45 degrees (an antiprism) 4 + 4 triangles; a trapezoid frustum one trapezoid per side
PRISMATOIDS = {
    "triangular prism": ([(0, 0, 0), (3, 0, 0), (0, 3, 0), (0, 0, 2), (3, 0, 2), (0, 3, 2)], (3, 0)),
    "square pyramid": ([(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (1, 1, 3)], (4, 4)),
    "square antiprism": ([(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0), (0, -2, 1), (2, 0, 1), (0, 2, 1), (-2, 0, 1)],
                         (8, 8)),
    "frustum with a parallel pair": ([(0, 0, 0), (4, 0, 0), (4, 4, 0), (0, 4, 0), (1, 1, 1), (3, 1, 1), ("5/2", 3, 1),
                                      ("3/2", "5/2", 1)], (7, 6)),
}


@pytest.mark.parametrize("name", sorted(PRISMATOIDS))
def test_side_faces_by_the_hull_and_by_sections(name):
    from symfloat.geometry.convex import side_faces, side_faces_by_sections
    points, expected = PRISMATOIDS[name]
    assert side_faces(points) == expected == side_faces_by_sections(points)


def test_side_faces_by_sections_refuse_a_point_between_the_bases():
    from symfloat.geometry.convex import side_faces_by_sections
    with pytest.raises(ValueError):
        side_faces_by_sections([(0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, 2), (1, 1, 1)])


def test_the_side_faces_witness_refutes_a_wrong_count():
    import sympy as sp
    from symfloat.engine.witness import Case, SideFaces
    points, (faces, triangles) = PRISMATOIDS["frustum with a parallel pair"]
    w = SideFaces("f", "faces", ("t",), (Case({}, points),))
    assert w.run({"t": (sp.Symbol("q"), sp.Matrix([faces, triangles]))})["t"].agrees
    out = w.run({"t": (sp.Symbol("q"), sp.Matrix([faces, triangles + 1]))})["t"]     # mutation: one triangle more
    # refuted by the certified (radius 0) Arb record, the exact hull's count beside it
    assert not out.agrees and len(out.records) == 2 and out.records[0]["method"] == "Arb ball arithmetic"
