"""Scheeffer 1902, sections I-III: equilibrium, the righting moment of a
body prismatic at the waterline, and Duhamel's criterion.

I.  Body frame of the tilted body: ``v`` across the floating axis (towards
the side that dips), ``u`` down the floating axis from the centroid S.  The
new submerged part is the old one (volume V1, centroid S1 at u = e1) less
the emerged wedge (V3, centroid S4) plus the immersed wedge (V3, centroid
S3): the moment theorem gives (6); the rotation of the frame by phi gives (5)
and with it (7).  World frame of the checks: X horizontal towards the dipping
side, Y vertically down (Scheeffer's SL), so that m (the righting arm SA) is
the X coordinate and n the Y coordinate of S2.

II.  The wedges of a body prismatic near the waterline are sums of prismatic
elements over the old waterplane: the element over df at distance x from the
axis has height x tg phi.  The element integrals are done in general; the
waterplane is then taken concretely as a trapezoid whose parallel sides P1,
P2 (at s = 0 and s = Hh) run parallel to the rotation axis: P2 = P1 is a
rectangle (the box), P2 -> 0 gives a triangle.  Its wedge volumes, moments and its
moment of inertia T1 are integrated symbolically, the axis is shown to pass
through the centroid of the waterplane (V3 = V4), and (10)-(13) follow.

III.  The expansion of (12) in phi gives (16) and Duhamel's criterion (18);
the curvature of V1 n (the energy of the system in units of the weight,
Schülen's approach quoted in the preface) gives the same criterion.

Witnesses: exact clipping of floating prisms (``symfloat.geometry.floating``):
vertical prisms over trapezoids tilted about an axis parallel to the parallel
sides, wedges cut out of the clipped body; horizontal boxes and an apex-down
triangular prism (not prismatic at the waterline) for the small-angle limits.
"""
from .statements import DERIVATION

__all__ = ["DERIVATION"]
