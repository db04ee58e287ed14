"""Scheeffer 1902, sections IV and V: the tilted equilibrium of a right prism.

A right prism of height ``b`` and specific gravity ``s`` floats upright (axis
vertical) in equilibrium.  When the upright position is unstable for a
horizontal axis EF through the centroid O of the waterplane I, the prism turns
about EF until the righting moment vanishes at the angle ``phi_1`` (27).  The
second equilibrium condition is ``int u v df = 0`` (31), (32); the waterplane II
is the affine stretch of the waterplane I by ``1/cos phi_1`` across EF, so its
moments of inertia are ``T_1/cos^3`` and ``T_1^1/cos`` (38), (42); the tilted
position is stable iff ``T_1^1 > T_1`` (43a).  Section V: for a base with a
symmetry axis the equilibrium needs ``omega = 0, 90 deg`` or ``T_x = T_y``;
in the latter (isotropic) case the tilted position exists for every direction
and is neutral about the axis perpendicular to EF (51); the face-crossing
limits (53)-(55).

Everything is derived in the body frame ``(u, v, z)``: ``u`` across EF
(positive on the side that dips), ``v`` along EF, ``z`` along the prism axis
from the waterplane I.  The prism is the base ``Omega`` times the interval
``[-b s, b (1 - s)]`` of ``z``, with the centroid of the base ``Omega`` at O; integrals over ``Omega`` of polynomials in
``u, v`` are taken termwise with the area moments ``F_1, 0, 0, T_1, T_1^1, P``
(function ``area_integral``).  Scheeffer's (12) and (13) (section II, module
``scheeffer-i-iii``, steps ``righting-moment-12``, ``moment-13``) are re-derived
here from the exact column integrals of the prism, which hold for every tilt of
the first rotation region, not only for small ones.

The witnesses are declarations of floating witnesses (``symfloat.engine.
floating_witness``): the clipped prism, the quantity and the cases; tilts are
zeros of the righting arm or of a base's height above the water
(``FloatingRootWitness``); the draught comes from the submerged volume, never from the
plane through EF.
"""
__all__ = ["DERIVATION"]


def __getattr__(name):
    """``DERIVATION`` from the statements, imported when first asked for: a scene imports the predictors (of
    compiled readings) alone."""
    if name == "DERIVATION":
        from .statements import DERIVATION
        return DERIVATION
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
