"""Hasáb (KöMaL-type solved problem): a long square prism of density rho floating in water, by the energy method.

Cross-section: the unit square, body coordinates xi in [-1/2, 1/2] (across), eta in [0, 1] (up from the
bottom face); length l >> 1, water density 1.  Heeled by alpha about the long axis, the water line in the
body frame is eta = s0 + xi tg(alpha); a point lies (eta - s0 - xi tg alpha) cos(alpha) above the water.
The potential energy of the system is that of the prism plus that of the displaced water (its weight times
the depth of its centroid: the work to lift it to the surface), both integrated over the section.

The energy is then expanded to second order, the stability condition and its density ranges follow, and
the energy method is shown equal to the metacentric criterion and to Duhamel's criterion (18) of Scheeffer
(section III there): the exact energy of the heeled prism is Scheeffer's V1 n of (13).  The remark's second
position is the prism standing upright (the edges of length $l$ vertical).

Witnesses: exact clipping of the floating prism (``symfloat.engine.floating_witness``): energies from the
clipped immersed part and its two pieces at the lower end of the water line, the sides where the water plane
crosses them, the second-order coefficient interpolated from the clipped potential at small heels, the density
thresholds as zeros of the clipped metacentric height.
"""
__all__ = ["DERIVATION"]


def __getattr__(name):
    """``DERIVATION`` from the statements, imported when first asked for: a scene imports the predictors (of
    compiled readings) alone."""
    if name == "DERIVATION":
        from .statements import DERIVATION
        return DERIVATION
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
