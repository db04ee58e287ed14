"""Graefe 1866, §3: the centroid of the tetrahedron and of the prismatoid.

Lemma: the centroid of a tetrahedron is the midpoint of the segment joining
the midpoints of two skew edges (a bimedian).  Graefe's synthetic proof is
followed in coordinates: every ratio he states is checked for a general
tetrahedron.  Then the prismatoid is cut as in §1 and the moments about the
base give ``X = h (g/2 + D) / ((G + g)/2 + 2 D)``; the same formula is exact
for every body whose section area is a quadratic polynomial of the height.
"""
from .statements import DERIVATION

__all__ = ["DERIVATION"]
