"""Scheeffer 1902, sections VII and VIII: the second and third rotation regions of a right prism.

VII.  The prism (base F_1, height b, density s > 1/2) is turned so far that the water plane cuts the upper
base along GH.  The part above the water is the right prism over the dry part F = AGHCD of the upper base,
cut off obliquely by the water plane: over a point at the distance x from GH its column has the length
x tan(phi_2).  From the area moments of F the text gets its volume, its static moments and so the two
equilibrium conditions: S_3 (centroid of the dry part) lies on the vertical through S, i.e. int x y df = 0
over F (95a), and M_3 = 0 (99)-(103b), with the tilt fixed by the volume (103a).  For a regular prism the
first condition may be taken over the wet part BGH instead (96)-(98).  Stability (Duhamel): the smallest
moment of inertia T_m of the waterplane, the affine image of F stretched by 1/cos(phi_2) across GH, minus
V_3 e_3 must be positive (104)-(117).
VIII.  Turned further, the water plane cuts both bases; the dry part is the prism over F less the prism
over the dry part f of the lower base (projected), and (118)-(122) follow the same way.

Frame (the text's, Figs. 17-21 are not in the transcription): origin N, the foot on GH of the
perpendicular EF from the centroid O of the upper base; x along NE (towards the dry side), y along NG,
z along the prism axis upwards with z = 0 in the upper base; O = (x0, 0, 0), S = (x0, 0, -b/2); up is
u = (sin phi, 0, cos phi) and the water plane through GH is z = -x tan(phi).  The area moments of F in
this frame, F, F x_s, F y_s, T = int x^2, T^1 = int y^2, are kept as symbols and integrals of polynomials
over F are taken termwise.  int x y df over F is the integral over the whole base (shifted to O) less that
over the wet part BGH (additivity).  In VIII the lower base's dry part f is measured from ML (x' = x - b
cot phi_3): f, f x_s^1, tau = int x'^2, int x' y.

Claims judged: S_3 lies vertically above S when S_2 lies below it (mass balance); M_3 = V_1 dE/dphi, so an
equilibrium where M_3 passes from - to + is stable about the axis (shown on the rectangular strip, measured on
clipped boxes by difference quotients of the potential); for s < 1/2 dry and wet parts exchange (V_1 E is the
same for the turned body of density 1 - s); x_0 < 0 when N lies between O and E;
'No. 95a, 103a, b und 117 enthalten die vollständigen Bedingungen' (the two horizontal offsets of S_2 are -sin phi
(103b), -tan phi (95a)); 's > 1/2, sodass also die obere Grundfläche zum Teil eintaucht' holds only for bases
reaching equally far on both sides of the axis (claim erratum, as in IV).  Errata: the stray '1/2' before
'Volumen' in (100) (scan), the sign of 2 k tg 2mu in (109) (print), the lost df of the split of (95a) (scan),
'nach 102 a' for (103a) (print), 'den Punkt N' for N_1 and 'x_3^1' for x_s^1 in VIII (scan), the labels 'G B H' (a
base of the dry part) and 'G H D = F' ((118)'s domain) for F = AGHCD in VIII (print).
The references '102 a', '102 b' in (116), (117) mean (103a), (103b); '102 b' is not booked, since (102) with
(100) gives (116) as well.

Witnesses (``symfloat.engine.floating_witness``): rectangles, triangles, squares, an equilateral triangle and a
pentagon are clipped at the tilt with the draught found from the volume; the dry part is the body less the
clipped submerged part (V_3 = V - V_1, V_3 (S_3 - S) = -V_1 (B - G)); x_0 is read off where the clipped water
plane meets the upper base, the waterplane moments from the clipped waterplane's tensor and centroid.  The case data (F,
x_s, T, ... of the plane pieces) come from exact 2-D polygon moments.  Equilibria: a pentagon (unsymmetric,
k != 0) and two boxes (second and third region) are designed from the printed conditions in exact arithmetic
and then checked on the clipped body (both horizontal offsets of B from G vanish); the box tilts are also
found as roots of the clipped righting arm (tests).

Predictions: boxes and cubes turned about an axis parallel to an edge (the dry part of a base a strip): the
second-region positions from (103a), (103b) with their stability from (117), the third-region ones from
(121b), (122) (no stability: the text gives none); s < 1/2 by the exchange of dry and wet parts.
"""
__all__ = ["DERIVATION"]


def __getattr__(name):
    """``DERIVATION`` from the statements, imported when first asked for: a scene imports the predictors (of
    compiled readings) alone."""
    if name == "DERIVATION":
        from .statements import DERIVATION
        return DERIVATION
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
