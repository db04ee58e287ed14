"""Scheeffer 1902, VI.C-F: the square prism, the cube, the regular n-gon prism and their comparison.

A right prism (base F_1, height b, density s) floats upright with its axis vertical; tilted by phi
about a horizontal axis through the centroid O of the upright waterplane, the plane through O keeps
the displacement as long as neither base face is cut (Scheeffer's first rotation domain).  The
submerged part is then the union of vertical columns over the base from the bottom face up to the
plane z = xi tan(phi) (xi: distance of a base point from the axis), so its volume and moments are
integrals over the base.  From them: the centre of buoyancy, the righting arm GZ (= d/dphi of the
potential u.(G - B)), the upright metacentric height (Duhamel), the oblique equilibrium
tan^2 phi_1 = F_1 b^2 s(1-s)/T_1 - 2, its stability, and the tilt at which a corner of a base face
reaches the water (the limit of the first domain).  For the square all base integrals are done in
SymPy for an axis at any angle omega to a side; the cube is a = b.  For the n-gon the moment of the
base is built from its n isosceles triangles as in the text and compared with the clipped geometry.

Witnesses (``symfloat.geometry.floating``): the prisms are clipped by the water plane at the
draught found from the submerged volume; moments of the waterplane, the metacentric height and the
centres B, G come from the clipped polyhedron.  Equilibrium tilts are roots of GZ = h.(B - G) (the
derivative of the clipped potential, checked against a difference quotient in the tests); the tilt
at which a base face reaches the water is the root of the lowest top-face (highest bottom-face)
vertex height above the clipped water plane; density thresholds are roots in s of these
quantities (nested root-finding).  Nothing there uses a formula of the text.

Conventions: body frame with the prism axis z, base corners (+-a/2, +-a/2); the tilt axis has
direction (cos w, sin w, 0), w (Scheeffer's omega) measured from a side, 0 < w < 45 deg; the up
vector is u = (sin phi sin w, -sin phi cos w, cos phi) and xi = -x sin w + y cos w, so the points
with large xi sink.  Angles are read in radians (45 deg = pi/4).
"""
__all__ = ["DERIVATION"]


def __getattr__(name):
    """``DERIVATION`` from the statements, imported when first asked for: a scene imports the predictors (of
    compiled readings) alone."""
    if name == "DERIVATION":
        from .statements import DERIVATION
        return DERIVATION
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
