"""Scheeffer 1902, IX: the rectangular parallelepiped turned about an axis parallel to an edge.

A box with edges a, b, c (density s) floats upright with b vertical; it is turned about a horizontal
axis parallel to c (c > a).  Everything happens in the cross-section a × b, so the problem is plane.

First region (A): the water plane cuts the two long side faces only, the first rotation domain of
sections IV-V.  Upright stability is Duhamel's (a/b)^2 > 6s(1-s) (123); the oblique equilibrium is
tan^2 phi_1 = 12 (b/a)^2 s(1-s) - 2 (125), stable because the base moment about the perpendicular
axis is the larger one (126, 127); it stays in the first region while (a/b)^2 >= 2(1-s)(4s-1)
(130-132).  Turned about the a-axis instead, the same formulas with c for a (128), partly unstable.

Second region (B): the dry part is a right triangle at the rising top corner with legs x (along b)
and x cot phi_2 (along a).  Its area fixes x^2 = 2ab(1-s) tan phi_2 (134); the horizontal offset m_3
of its centroid from the vertical through the centroid S of the body is the righting arm up to the
factor (1-s)/s, and with z = x/b it is sin phi_2 F(z) b/(3 z^3) with the quartic
F(z) = z^4 - 3/2 z^3 + 3 n sigma z - 4 n sigma^2 (133, 136), n = (a/b)^2, sigma = 1 - s.  Here F is
derived from the wedge geometry of the tilted section (the centroid of the dry triangle), and
d(potential)/d phi_2 = (sigma/s) m_3 is checked by differentiating the closed potential.  The region is
2 sigma <= z <= 1 (135).  Scheeffer counts the roots of F in that interval: F'' = 3z(4z-3) (138) gives
the inflections, F'(3/4) >= 0 makes F monotone (139), which holds for all n >= 1 when s <= 23/32
(140); F(2 sigma) and F(1) (141, 142) then decide (143, 144).  For s > 23/32 the double roots of F
are found by eliminating z between F = 0 and F' = 0 (146-149) with t = (128 sigma - 9)/27; here the
double-root locus is parametrised by the double root itself (sigma and n are rational functions of
it), which gives S = n + 1/n (151-154), n_1 (153, 156) and the double root z_1 (155-158) and shows
2 sigma < z_1 < 1 (159, 160).  The case tables (161, 162, 162a), each row read at an exact point, and the
bound for complete stability, HG < c (163), with the sufficient (164); HG < c is itself only sufficient (the
exact condition is HG c^3/12 > V BG, erratum HG-complete).

Third region (C): the first region with a and b exchanged: the other upright position (a vertical)
and its oblique equilibrium cot^2 phi_3 = 12 (a/b)^2 s(1-s) - 2 (164a-166), and the closing tables.

Witnesses (declared, ``symfloat.engine.floating_witness``): the box is clipped by the water plane at
the draught found from the volume.  Metacentric heights come from the clipped waterplane; equilibrium
tilts are roots of the righting arm h.(G - B) (``potential_slope``, checked against a difference
quotient of the clipped potential in the tests); a corner reaching the water is a root of the length
from it along its side to the water (``crossing``); the dry leg x is that length from the rising
corner down the side b; m_3 is the offset of the centroid of the clipped dry part; F', F'' are
five-point differences in z of the clipped quantity (``Difference``); the double root (z_1, n_1) is
the edge a at which the clipped arm vanishes at its extremum in the second region, a root of the
arm's slope I_h/V - E (``potential_curvature``).

Conventions: body frame x along a, y along b, z along c; the up vector u = (sin phi, cos phi, 0)
raises the corner D = (a/2, b/2); h = du/dphi.  The predictor (``tables_prediction``) reads the
printed tables for any box and any edge as axis: it decides with the readings of the printed conditions, tilts
and the quartic (``Derivation.evaluator``), exactly.
"""
__all__ = ["DERIVATION"]


def __getattr__(name):
    """``DERIVATION`` from the statements, imported when first asked for: a scene imports the predictors (of
    compiled readings) alone."""
    if name == "DERIVATION":
        from .statements import DERIVATION
        return DERIVATION
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
