"""Graefe 1866, end of §4: the centroid of a ship's displacement.

The immersed body is cut by equidistant planes (spacing ``m``) with areas
``a, b, c, d, e, f, g``; each pair of slabs between ``a`` and ``c``, ``c``
and ``e``, ``e`` and ``g`` is treated as a prismatoid of height ``2m``.  The
centroid of each from §3, ``X = h (g/2 + D) / ((G + g)/2 + 2 D)``, and its
volume from §1 give the moments about the plane ``ABC``; their sum is

    ``X V = m²/3 (a·0 + 4b·1 + 2c·2 + 4d·3 + 2e·4 + 4f·5 + g·6)``

and with ``V = m/3 (a + 4b + 2c + 4d + 2e + 4f + g)``

    ``x = m (a·0 + 4b·1 + … + g·6) / (a + 4b + 2c + 4d + 2e + 4f + g)``.

The print has ``x = m/3 (…)/(…)``: it divides by the ``V = m (…)`` printed
in §2 (where the factor 1/3 is lost), although §4 itself uses the correct
slab volumes ``v' = 2m/3 (…)``.
"""
from .statements import DERIVATION

__all__ = ["DERIVATION"]
