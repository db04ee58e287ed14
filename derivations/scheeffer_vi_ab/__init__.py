"""Scheeffer 1902, section VI (opening) and VI.A-B: the regular polygon, the regular triangular prism and
the circular cylinder floating with vertical axis, in the first rotation region (no base cut).

Geometry (derived here, not quoted): a right prism (base F, height b, density s) floats upright with the
submerged height b s; tilted by phi about a horizontal axis through the centre O of the waterplane, the
water plane is z = b s + x tan(phi) in body coordinates (z along the axis from the bottom, x across the
rotation axis).  As long as it cuts no base, the submerged part is the set 0 <= z <= b s + x tan(phi) over
F, whose volume, centroid and righting arm follow from the area, first and second moments of F
(integrated here over the equilateral triangle and the disc).  The witnesses clip the real polyhedra
(symfloat.geometry.floating) and float the real cylinder (Body.cylinder, quadrature of exact slices), and
find equilibria as roots of the measured righting arm; the first-region model of the triangle (column
heights not cut by the bases) is the clipped prism extended on either side with a neutral lower part.
"""
__all__ = ["DERIVATION"]


def __getattr__(name):
    """``DERIVATION`` from the statements, imported when first asked for: a scene imports the predictors (of
    compiled readings) alone."""
    if name == "DERIVATION":
        from .statements import DERIVATION
        return DERIVATION
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
