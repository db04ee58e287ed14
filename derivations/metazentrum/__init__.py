"""Web lesson "Auftrieb Stabilität": the metacentre of a rectangular hull.

The hull is a homogeneous box 2a × 2b × 2c (length, breadth, height) floating
upright with draught d; heel about the long axis (a > b).  Coordinates: z up
from the water surface, y across.  Volumes, centroids and the waterplane's
moment of inertia are integrated; the shift of the centre of buoyancy on heel
is computed from the two wedge triangles (the lesson's route, exact in tg phi,
read to first order in phi as the lesson does), the metacentre from it, and
the stability function e from z_M >= z_G.  The closing sentence ("größer als
eins" for stability) and the Vasa remark are checked as claims.

Witnesses: the floating box clipped exactly (``symfloat.engine.floating_witness``):
immersed volume, centres of buoyancy and gravity, the waterplane's I_min / V -
(G - B) upright, the righting arm at small heels extrapolated to phi -> 0, and
the share of the volume below the draught.
"""
__all__ = ["DERIVATION"]


def __getattr__(name):
    """``DERIVATION`` from the statements, imported when first asked for: a scene imports the predictors (of
    compiled readings) alone."""
    if name == "DERIVATION":
        from .statements import DERIVATION
        return DERIVATION
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
