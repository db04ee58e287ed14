"""Scheeffer 1902, X: the equilibrium positions of a floating cube.

Beyond the first rotation domain (section VI.D) the water plane cuts a face of the cube: the waterplane is a
pentagon, triangle, hexagon or trapezoid, and from one face (or from two parallel faces) a triangle is cut off.

First condition, one face cut (167)-(170).  Fig. 23: the top face, the immersed corner triangle BHG (right
angle at B, BH = rho, angle BHG = omega, height BP = h), N the foot of the perpendicular from the centre O
onto the water line GH, x across GH towards B, y along GH towards G.  The first equilibrium condition (98)
is int xy df = 0 over the triangle; split at P it is (167), and with NH = u, NG = v from the square it
becomes (168) = h^3 (cos w - sin w)(2a cos w - rho(cos w + sin w))/(24 sin w cos^2 w).  The second
factor cannot vanish for a triangle inside the face (169a, b contradict each other), so omega = 45 deg
(170): with a pentagonal or triangular waterplane the cut triangle is isosceles ('in 104' before (168)
means (167): misprint).  All of this is derived
here by integrating over the triangles, and the condition itself is measured on the clipped cube as the
moment of the dry part about the vertical plane across the axis.

Second condition, pentagonal waterplane (171), (172).  With omega = 45 deg, a = 1 and the leg x of the
cut triangle, the dry part is the set of columns over the dry part F of the top face down to the water
plane; its volume 1 - s fixes the tilt, and B below G gives (171) (derived: 2T(z^2 + (1-s)^2) - z^3(1-x)
- z^2(1-s) is a positive multiple of the derivative of the potential along the diagonal plane).  (171)
has a root in 0 < x < 1 for (4 - sqrt 2)/7 < s < (4 + sqrt 2)/7, as (172) says (an existence statement,
verified): for s > 1/2 one up to the fold s = 0.7623, three from there to (4 + sqrt 2)/7 (where a root
leaves through x = 0), two up to 5/6 (Sturm counts).  The text's conclusion, a stable pentagonal
equilibrium for every 1/2 < s < 0.7735, is wrong: below s = 0.7623 the root of (171) lies where the
bottom face is already cut (the waterplane there is a hexagon, the clipped cube has no pentagonal
equilibrium at all), and where two pentagonal roots exist (0.7623 < s < 0.7735) one of them is unstable.
The same holds mirrored for s < 1/2.

Triangle and hexagon.  The dry corner is a tetrahedron, a triangular waterplane needs s >= 5/6 (right);
by (170) on all three faces it lies across a diagonal, and it is always unstable (metacentric height
sqrt 3 L^3 (L - 1)/(12 s) < 0, L < 1 the leg).  With two parallel faces cut, the first condition is
(173), the sum of two terms of the form (174), (175), each of the sign of cos w - sin w, so again
omega = 45 deg; the regular hexagon at s = 1/2 is stable (metacentric height sqrt 3/48).  Derived by
integrating over the two triangles with the water plane through both water lines, and measured on the
clipped cube.

Heading.  'Die Gewichtslagen eines schwimmenden Würfels' (so also in the contents) for Gleichgewichtslagen:
on the diagonal family of (171) the cube displaces its weight at every leg x, but is in equilibrium only at
the roots of (171) (misprint, medium).

Witnesses (``symfloat.geometry.floating``): moments of the clipped dry part, waterplane polygons and their
vertex counts, metacentric heights of the clipped cube, and equilibria found as roots of the derivative
of the clipped potential u.(G - B) along the diagonal plane (its derivative is (du/dtheta).(G - B)).
Angles in radians.
"""
__all__ = ["DERIVATION"]


def __getattr__(name):
    """``DERIVATION`` from the statements, imported when first asked for: a scene imports the predictors (of
    compiled readings) alone."""
    if name == "DERIVATION":
        from .statements import DERIVATION
        return DERIVATION
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
