"""Graefe 1866, §2: consequences of the prismatoid formula.

For every body whose section area ``A(z)`` is a polynomial of degree at most
three in the height ``z``, ``∫_0^h A dz = h/3 ((A(0) + A(h))/2 + 2 A(h/2))``:
the prismatoid formula ``I = h/3 ((G + g)/2 + 2 D)`` of §1 holds with
``G = A(0)``, ``g = A(h)``, ``D = A(h/2)``.  This is why bodies with curved
surfaces are "Specialitäten des Prismatoids".  Graefe applies it to

* the sphere (``G = g = 0``, ``h = 2 r``, ``D = r² π``): ``I = 4 r³ π / 3``;
* the paraboloid of height ``x`` (``y² = 2 p x``): ``I = p x² π``;
* the segment of height ``x`` of the prolate ellipsoid
  (``y² = b²/a² (2 a x - x²)``): ``I = b² π x² (3 a - x) / (3 a²)``, and for
  ``x = a`` the half ellipsoid ``2 a b² π / 3``;

and derives Simpson's rule for volumes from equidistant sections ``a, b, …, g``
at spacing ``m``: ``I = m/3 (a + 4b + 2c + 4d + 2e + 4f + g)``.

The print drops the factor 1/3 from the first slab ``I' = 2m/3 (…)`` on, and
carries the omission through to ``I = m (a + 4b + … + g)``; §4 relies on the
wrong factor (see the centroid of a ship's displacement at the end of §4).
"""
from .statements import DERIVATION

__all__ = ["DERIVATION"]
