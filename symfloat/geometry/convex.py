"""Exact convex geometry in rational arithmetic.

Used as an independent witness: volumes and centroids of convex polyhedra
come from their hull faces (divergence theorem), section areas from the
intersection of a plane with every segment between two vertices.  Nothing
here knows any formula of the sources.

>>> from fractions import Fraction as F
>>> cube = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
>>> volume, centroid = hull_volume_centroid(cube)
>>> volume, centroid
(Fraction(1, 1), (Fraction(1, 2), Fraction(1, 2), Fraction(1, 2)))
>>> section_area(cube, axis=2, height=F(1, 3))
Fraction(1, 1)
"""
from __future__ import annotations

from fractions import Fraction
from itertools import combinations
from math import lcm

__all__ = ["hull_2d", "polygon_area", "hull_faces", "hull_volume_centroid", "section_polygon", "section_area",
           "side_faces", "side_faces_by_sections"]


def _cross2(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def hull_2d(points):
    """Convex hull of 2-D points, counter-clockwise, collinear points dropped
    (Andrew's monotone chain)."""
    pts = sorted(set(points))
    if len(pts) <= 2:
        return pts
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and _cross2(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and _cross2(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def polygon_area(poly):
    """Shoelace area of a simple polygon (positive when counter-clockwise)."""
    n = len(poly)
    return sum(poly[i][0] * poly[(i + 1) % n][1] - poly[(i + 1) % n][0] * poly[i][1]
               for i in range(n)) / 2 if n >= 3 else Fraction(0)


def _sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def _faces(points):
    """Supporting planes of the hull, each with its vertices in outward
    counter-clockwise order.  The planes are found on the points scaled by
    the common denominator of their coordinates, in integers (a positive
    scale keeps every sign, order and orientation; in Fractions the search
    took nine times as long), and the rings given in the points themselves."""
    pts = [tuple(Fraction(c) for c in p) for p in set(map(tuple, points))]
    scale = lcm(*(c.denominator for p in pts for c in p))
    grid = [tuple(c.numerator * (scale // c.denominator) for c in p) for p in pts]
    seen, faces = set(), []
    for i, j, k in combinations(range(len(pts)), 3):
        n = _cross(_sub(grid[j], grid[i]), _sub(grid[k], grid[i]))
        if n == (0, 0, 0):
            continue
        side = [_dot(n, _sub(p, grid[i])) for p in grid]
        if all(s <= 0 for s in side):
            normal = n
        elif all(s >= 0 for s in side):
            normal = tuple(-c for c in n)
        else:
            continue
        on = frozenset(q for q, s in zip(range(len(pts)), side) if s == 0)
        if on in seen:
            continue
        seen.add(on)
        drop = max(range(3), key=lambda c: abs(normal[c]))
        keep = [c for c in range(3) if c != drop]
        proj = {(grid[q][keep[0]], grid[q][keep[1]]): pts[q] for q in on}
        ring = [proj[p] for p in hull_2d(list(proj))]
        # hull_2d is counter-clockwise in the projected plane; flip when that
        # plane is seen from behind by the outward normal.
        sign = normal[drop] if drop != 1 else -normal[drop]
        if sign < 0:
            ring.reverse()
        faces.append(ring)
    return faces


def hull_faces(points):
    """The faces of the convex hull of 3-D points (coplanar facets merged), each the ring of its vertices
    (exact ``Fraction`` coordinates), counter-clockwise seen from outside."""
    return _faces(points)


def hull_volume_centroid(points):
    """Exact volume and centroid of the convex hull of 3-D points.

    The hull is cut into tetrahedra with apex at the origin over fan
    triangles of each face: ``V = sum det(a, b, c) / 6`` and the centroid
    is the volume-weighted mean of ``(a + b + c) / 4``.
    """
    volume = Fraction(0)
    moment = [Fraction(0)] * 3
    for ring in _faces(points):
        a = ring[0]
        for b, c in zip(ring[1:], ring[2:]):
            v = _dot(a, _cross(b, c)) / 6
            volume += v
            for t in range(3):
                moment[t] += v * (a[t] + b[t] + c[t]) / 4
    if volume <= 0:
        raise ValueError("the points do not span a solid")
    return volume, tuple(m / volume for m in moment)


def section_polygon(points, axis, height):
    """The section of the convex hull of *points* by the plane
    ``x[axis] = height``, as a counter-clockwise polygon in the other two
    coordinates.  Every section vertex lies on a segment between two hull
    vertices, so intersecting all such segments and taking the 2-D hull is
    exact."""
    others = [c for c in range(3) if c != axis]
    hits = []
    for p in points:
        if p[axis] == height:
            hits.append((p[others[0]], p[others[1]]))
    for p, q in combinations(points, 2):
        lo, hi = sorted((p[axis], q[axis]))
        if lo < height < hi:
            t = (height - p[axis]) / (q[axis] - p[axis])
            hits.append(tuple(p[c] + t * (q[c] - p[c]) for c in others))
    return hull_2d(hits)


def section_area(points, axis, height):
    """Area of :func:`section_polygon`."""
    return polygon_area(section_polygon(points, axis, height))


def _exact(points):
    return [tuple(Fraction(c) for c in p) for p in points]


def side_faces(points, axis=2):
    """``(faces, triangles)``: the faces of the hull of *points* that do not lie in a plane ``x[axis] = const``
    (the side faces of a prismatoid), and how many of them are triangles, from the hull's faces.

    >>> side_faces([(0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1)])    # a frustum: 3 trapezoids
    (3, 0)
    """
    faces = [f for f in _faces(_exact(points)) if len({v[axis] for v in f}) > 1]
    return len(faces), sum(len(f) == 3 for f in faces)


def side_faces_by_sections(points, axis=2):
    """:func:`side_faces` of a prismatoid (every point in one of the two extreme planes along *axis*) from two
    plane sections instead of the hull's faces: a plane between the bases cuts every side face in one edge of
    the section polygon, of the same direction from plane to plane (no two edges of a convex polygon share
    one) and of a length linear in the height; so the edges of the sections at 1/3 and 2/3 of the height,
    matched by direction, are the side faces, and a face is a triangle where its length extrapolates to
    zero at a base (``2 l_1 - l_2`` or ``2 l_2 - l_1``).

    >>> side_faces_by_sections([(0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1)])
    (3, 0)
    >>> side_faces_by_sections([(0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, 1)])         # a tetrahedron: 3 triangles
    (3, 3)
    """
    pts = _exact(points)
    lo, hi = min(p[axis] for p in pts), max(p[axis] for p in pts)
    if any(lo < p[axis] < hi for p in pts):
        raise ValueError("a point lies between the extreme planes: not a prismatoid")
    rings = [section_polygon(pts, axis, lo + (hi - lo) * t) for t in (Fraction(1, 3), Fraction(2, 3))]
    edges = [[(q[0] - p[0], q[1] - p[1]) for p, q in zip(r, r[1:] + r[:1])] for r in rings]
    triangles = 0
    for e in edges[0]:
        f = next((g for g in edges[1] if e[0] * g[1] - e[1] * g[0] == 0 and e[0] * g[0] + e[1] * g[1] > 0), None)
        if f is None or len(edges[0]) != len(edges[1]):
            raise ValueError("the two sections' edges do not pair up: not a prismatoid's side faces")
        k = 0 if e[0] != 0 else 1              # lengths along the common direction, by one nonzero component
        triangles += 2 * e[k] - f[k] == 0 or 2 * f[k] - e[k] == 0
    return len(edges[0]), triangles
