"""Random convex prismatoids: two random convex polygons in parallel planes
and their convex hull, with exact rational coordinates.

The parameters the prismatoid formulas need — the base areas ``G``, ``g``,
the mid-section area ``D`` and the height ``h`` — are measured on the hull
itself (shoelace areas of exact sections), never from a formula.
"""
from __future__ import annotations

import random
from fractions import Fraction

from .convex import hull_2d, polygon_area, section_area

__all__ = ["random_convex_polygon", "random_prismatoid", "prismatoid_parameters"]


def random_convex_polygon(rng: random.Random, points: int = 7, size: int = 12):
    """The hull of random integer points: a convex polygon with >= 3 vertices."""
    while True:
        pts = [(Fraction(rng.randint(-size, size)), Fraction(rng.randint(-size, size))) for _ in range(points)]
        poly = hull_2d(pts)
        if len(poly) >= 3:
            return poly


def random_prismatoid(seed: int, apex_top: bool = False):
    """Vertices of a random prismatoid with its base ``G`` at ``z = 0`` and its
    top ``g`` at ``z = h``; with ``apex_top`` the top is a single point."""
    rng = random.Random(seed)
    h = Fraction(rng.randint(2, 9), rng.randint(1, 3))
    base = random_convex_polygon(rng)
    top = [(Fraction(rng.randint(-6, 6)), Fraction(rng.randint(-6, 6)))] if apex_top \
        else random_convex_polygon(rng, points=5, size=8)
    return [(x, y, Fraction(0)) for x, y in base] + [(x, y, h) for x, y in top]


def prismatoid_parameters(points):
    """``(G, g, D, h)`` measured on the hull: base, top and mid-section areas
    and the height."""
    h = max(p[2] for p in points)
    G = polygon_area(hull_2d([(p[0], p[1]) for p in points if p[2] == 0]))
    top = hull_2d([(p[0], p[1]) for p in points if p[2] == h])
    g = polygon_area(top) if len(top) >= 3 else Fraction(0)
    D = section_area(points, 2, h / 2)
    return G, g, D, h
