"""Graefe 1866, §1: the tetrahedron lemma and the volume of the prismatoid.

The prismatoid (two parallel convex bases ``G``, ``g`` at distance ``h``,
mid-section ``D``) is cut, as Graefe does, into a pyramid over ``g``, one
pyramid over each triangle of ``G`` and one tetrahedron for each side of
``g``; the tetrahedra are measured with the lemma
``V = (1/3) (2 P) d`` (``P`` the mid-section parallelogram, ``d`` the
distance of the two skew edges).  Result: ``I = h/3 ((G + g)/2 + 2 D)``.
The side faces are counted (Fig. 1): p + q triangles over bases of p and q sides, one face and two
triangles fewer for each pair of parallel facing sides; witnessed by the faces of the exact hull.
"""
from .statements import DERIVATION

__all__ = ["DERIVATION"]
