"""Graefe 1866, §4: applications of the centroid formula of the prismatoid.

Every body of §4 (except the ship's displacement, treated separately) has a
section area ``A(u)`` that is a polynomial of degree at most 2 in the height
``u`` above the base ``G``.  For such bodies the prismatoid formula of §3,

    X = h (g/2 + D) / ((G + g)/2 + 2 D),   G = A(0), D = A(h/2), g = A(h),

is exact.  For each body ``A(u)`` is built from its own geometry (the
generating circle, parabola or ellipse, similar sections, ...), ``G``, ``D``,
``g`` are read off, the formula is applied and its value is compared with the
direct integral ``∫ u A du / ∫ A du``; the printed lines are then checked.
Bodies: sphere, cone and pyramid frustum, hemisphere, spherical segments with
one and two bases, paraboloids with one and two bases, ellipsoid segment,
half and truncated ellipsoid of revolution, the elliptic body with triangular
sections, triaxial ellipsoid stump and half triaxial ellipsoid.

Notation: ``x``, ``x'`` are abscissae from the centre (spheres, ellipsoids,
``x < x'``: ``G`` is the larger base); for the paraboloid with two bases the
abscissae from the vertex are written ``x_v > x'_v``.
"""
from .statements import DERIVATION

__all__ = ["DERIVATION"]
