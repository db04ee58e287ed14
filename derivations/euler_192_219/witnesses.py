"""Euler §§192-219's witnesses: every figure's moments measured (:mod:`symfloat.engine.figure_witness`), the
boxes of §§192-203 floating, heeled or pitched, clipped exactly (:mod:`symfloat.engine.floating_witness`)."""
import sympy as sp

from symfloat.engine.declare import declarer, part_of, rational_cases
from symfloat.engine.figure_witness import CurveRoot, Figure, FigureWitness
from symfloat.engine.floating_witness import (LIMIT_METHODS, Body, Combined, FloatingRootWitness,
                                              FloatingWitness, Joined, Loaded, Root, SeriesWitness, potential_slope)
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case

from .statements import (Iw, Kw, Mw, PM, PN, Pp, Tb, V, X1, X2, Y1, Y2, Yel, a, b, c, d, eb, gneg, h, hb1, hb2, m, phi,
                        x, xe, y)

# ================================================================ witnesses: the moments of each figure
# Every figure is declared with its vertices (or, the ellipse, its half-breadth) and measured by the figure
# witnesses (symfloat.engine.figure_witness): exact polygon integrals in float64 and at 50 digits, the ellipse by
# quadrature of its chords.  The boxes of §§192-203 float, heeled or pitched, by exact clipping
# (symfloat.engine.floating_witness).  Nothing of the formulas under test is used.


figure_witness = declarer(d, FigureWitness, coords=(x, y))      # the moments of a plane figure


XC = measured("centroid, 1")
AREA = measured("integral", of=1)                  # the figure's area
I_YY = measured("integral", of=y ** 2)             # its moments about the axes
I_XX = measured("integral", of=x ** 2)
N_OF_M = sp.sqrt(1 - m ** 2)                       # n, the cosine of the angle whose sine is m (§205)
SQUARE = Figure.polygon([(-a, -a), (a, -a), (a, a), (-a, a)])
RECTANGLE = Figure.polygon([(-a, -b), (a, -b), (a, b), (-a, b)])
RHOMBUS = Figure.polygon([(-a, 0), (0, -b), (a, 0), (0, b)])
KITE = Figure.polygon([(0, 0), (a, -b), (a + c, 0), (a, b)])             # A, f, B, e of §215
KITE_LOWER = Figure.polygon([(0, 0), (a, -b), (a + c, 0)])              # its half below AB
RHOMBUS_OF_KITE = Figure.polygon([(-(a + c) / 2, 0), (0, -b), ((a + c) / 2, 0), (0, b)])   # same AB and ef
ACE, BCE = Figure.polygon([(0, 0), (a, 0), (a, b)]), Figure.polygon([(a, 0), (a + c, 0), (a, b)])
GENERIC = Figure.polygon([(X1, Y1), (X2, Y1), (X2, Y2), (X1, Y2)])      # the rectangle off the origin
STRIP = Figure.polygon([(0, 0), (Pp, 0), (Pp, PM), (0, PM)])            # the strip Pp from AB up to M
STRIP_NM = Figure.polygon([(0, -PN), (Pp, -PN), (Pp, PM), (0, PM)])     # ... from N to M
ELLIPSE = Figure.strips(y, x, -a, a, (-Yel, Yel))

SQ = rational_cases(("a = 1", {a: 1}), ("a = 3/2", {a: "3/2"}))
AB_CASES = rational_cases(("a = 2, b = 1", {a: 2, b: 1}), ("a = 5/2, b = 3/4", {a: "5/2", b: "3/4"}))
Q_CASES = rational_cases(("a = 1, b = 1, c = 2", {a: 1, b: 1, c: 2}),
                         ("a = 5/2, b = 3/4, c = 3/2", {a: "5/2", b: "3/4", c: "3/2"}))

figure_witness("square-moment", "∫∫ y^2 over the square", ("square-I",), SQ, I_YY, figure=SQUARE)
figure_witness("square-quadrant", "∫∫ y^2 and ∫∫ x^2 over the quadrant ACE of the square",
               ("square-quadrant-I", "square-quadrant-K"), SQ, I_YY,
               figure=Figure.polygon([(0, 0), (a, 0), (a, a), (0, a)]))
figure_witness("rect-I", "∫∫ y^2 over the rectangle", ("rect-I",), AB_CASES, I_YY, figure=RECTANGLE)
figure_witness("rect-K", "∫∫ x^2 over the rectangle", ("rect-K",), AB_CASES, I_XX, figure=RECTANGLE)
figure_witness("rhombus-I", "∫∫ y^2 over the rhombus", ("rhombus-I",), AB_CASES, I_YY, figure=RHOMBUS)
figure_witness("rhombus-K", "∫∫ x^2 over the rhombus", ("rhombus-K",), AB_CASES, I_XX, figure=RHOMBUS)
figure_witness("quad-I", "∫∫ y^2 over the quadrilateral AeBf", ("quad-I",), Q_CASES, I_YY, figure=KITE)
figure_witness("Ace-I", "∫∫ y^2 over the triangle Ace", ("Ace-I",), Q_CASES, I_YY, figure=ACE)
figure_witness("Ace-L", "∫∫ (x - a)^2 over the triangle Ace", ("Ace-L",), Q_CASES,
               measured("integral", of=(x - a) ** 2), figure=ACE)
figure_witness("Bce-I", "∫∫ y^2 over the triangle Bce", ("Bce-I",), Q_CASES, I_YY, figure=BCE)
figure_witness("Bce-L", "∫∫ (x - a)^2 over the triangle Bce", ("Bce-L",), Q_CASES,
               measured("integral", of=(x - a) ** 2), figure=BCE)
figure_witness("quad-L", "∫∫ (x - a)^2 over the quadrilateral, ef at x = a", ("quad-L", "quad-L-again"), Q_CASES,
               measured("integral", of=(x - a) ** 2), figure=KITE)
figure_witness("quad-centroid", "Cc = x_C - a, x_C the quadrilateral's centroid", ("centroid", "Cc-again"), Q_CASES,
               XC - a, figure=KITE)
figure_witness("quad-K", "∫∫ (x - x_C)^2 over the quadrilateral, x_C its centroid", ("quad-K",), Q_CASES,
               measured("integral", of=(x - XC) ** 2), figure=KITE)
QM_CASES = rational_cases(("a = 1, b = 1, c = 2, m = 3/5", {a: 1, b: 1, c: 2, m: "3/5"}),
                          ("a = 5/2, b = 3/4, c = 3/2, m = 1/3", {a: "5/2", b: "3/4", c: "3/2", m: "1/3"}))
figure_witness("quad-PQ", "∫∫ (m X - n y)^2 over the quadrilateral about its centroid",
               ("moment-PQ-symmetric", "moment-PQ-increasing"), QM_CASES,
               measured("integral", of=(m * (x - XC) - N_OF_M * y) ** 2), figure=KITE)
figure_witness("quad-RS", "∫∫ (n X + m y)^2 over the quadrilateral about its centroid", ("moment-RS-symmetric",),
               QM_CASES, measured("integral", of=(N_OF_M * (x - XC) + m * y) ** 2), figure=KITE)

T_CASES = rational_cases(
    ("rectangle [-3/2, 5/2] x [-1/2, 5/2], m = 3/5, x_e = 2",
     {X1: "-3/2", Y1: "-1/2", X2: "5/2", Y2: "5/2", m: "3/5", xe: 2}),
    ("rectangle [-1, 1] x [1/4, 2], m = 1/4, x_e = -1/2",
     {X1: -1, Y1: "1/4", X2: 1, Y2: 2, m: "1/4", xe: "-1/2"}))
figure_witness("generic-PQ", "∫∫ (m x - n y)^2 over the generic rectangle", ("moment-PQ-IK", "moment-PQ-restated"),
               T_CASES, measured("integral", of=(m * x - N_OF_M * y) ** 2), figure=GENERIC)
figure_witness("generic-RS", "∫∫ (n x + m y)^2 over the generic rectangle", ("moment-RS-IK",), T_CASES,
               measured("integral", of=(N_OF_M * x + m * y) ** 2), figure=GENERIC)
figure_witness("generic-sum", "∫∫ (x^2 + y^2) over the generic rectangle (polar moment about the origin)",
               ("sum-invariant",), T_CASES, measured("integral", of=x ** 2 + y ** 2), figure=GENERIC)
figure_witness("generic-parallel", "∫∫ (x - x_C)^2 over the generic rectangle, x_C its centroid",
               ("parallel-axis-rule",), T_CASES, measured("integral", of=(x - XC) ** 2), figure=GENERIC)

E_CASES = rational_cases(("a = 3, b = 2", {a: 3, b: 2}), ("a = 5/2, b = 3/4", {a: "5/2", b: "3/4"}))
figure_witness("ellipse-K", "∫∫ x^2 over the ellipse", ("ellipse-K",), E_CASES, I_XX, figure=ELLIPSE)
figure_witness("ellipse-I", "∫∫ y^2 over the ellipse", ("ellipse-I",), E_CASES, I_YY, figure=ELLIPSE)
figure_witness("ellipse-quadrant", "a quarter of ∫∫ x^2 over the ellipse (the quadrants are congruent)",
               ("ellipse-quadrant-K", "ellipse-quadrant-moment"), E_CASES, I_XX / 4, figure=ELLIPSE)
figure_witness("ellipse-quadrant-area", "a quarter of ∫∫ 1 over the ellipse", ("ellipse-quadrant-area",), E_CASES,
               AREA / 4, figure=ELLIPSE)


figure_part = part_of(FigureWitness, coords=(x, y))


d.witness(Combined("rect-rhombus-ratios", "the rectangle's moments over the rhombus' (same a, b)", ("rhombus-twice",),
                   AB_CASES, parts=(figure_part(figure=RECTANGLE, quantity=I_YY), figure_part(figure=RHOMBUS, quantity=I_YY),
                                    figure_part(figure=RECTANGLE, quantity=I_XX),
                                    figure_part(figure=RHOMBUS, quantity=I_XX)),
                   values=(measured("part 1") / measured("part 2"),
                           measured("part 3") / measured("part 4"))))
KITE_EXCESS = dict(parts=(figure_part(figure=KITE, quantity=measured("integral", of=(x - XC) ** 2)),
                          figure_part(figure=RHOMBUS_OF_KITE, quantity=I_XX)),
                   values=(measured("part 1") - measured("part 2"),))
d.witness(Combined("quad-K-excess", "∫∫ (x - x_C)^2 over the quadrilateral minus that of the rhombus with the same "
                   "AB and ef", ("quad-K-larger",), Q_CASES, **KITE_EXCESS))


# ---------------------------------------------------------------- §201/§203: stability of a floating box
# The box 1 (across, x) x 1 (height, y) x 2 (length, z), homogeneous, floats at the density ratio s_w; its
# centre of gravity is moved to the depth b below, or the height b above, the upright centre of buoyancy (at half
# the draught s_w).  The stability per unit angle is M GZ(phi)/phi for phi -> 0, GZ the righting arm of the
# clipped (heeled or pitched) body, extrapolated (LIMIT_METHODS).  Nothing of the formula M(I/V ± b) is used.
sw = sp.Symbol("s_w", positive=True)               # the density ratio of the witnesses' boxes
HEEL = (sp.sin(phi), sp.cos(phi), 0)               # about the long axis z (AB)
PITCH = (0, sp.cos(phi), sp.sin(phi))              # about the cross axis x (EF)
ARM = {HEEL: potential_slope(HEEL, phi), PITCH: potential_slope(PITCH, phi)}


def box_with_G(height):
    """The box 1 x 1 x 2 with G at *height* above its upright centre of buoyancy."""
    return Loaded.of(Body.box(1, 1, 2), (0, sw / 2 - sp.Rational(1, 2) + height, 0))


def stability(up, height, factor=Mw):
    """factor times lim GZ/phi of the box heeled (HEEL) or pitched (PITCH) with G at *height* above B."""
    return FloatingWitness("", "", (), (), body=box_with_G(height), up=up, density=sw, quantity=factor * ARM[up],
                           limit=(phi, 1), methods=LIMIT_METHODS)


B_CASES = (Case({Mw: 1, V: 1, Iw: sp.Rational(1, 6), Kw: sp.Rational(2, 3), h: sp.Rational(1, 10),
                 sw: sp.Rational(1, 2)}, label="box 1 x 1 x 2, s = 1/2, b = 1/10"),
           Case({Mw: sp.Rational(3, 2), V: sp.Rational(3, 2), Iw: sp.Rational(1, 6), Kw: sp.Rational(2, 3),
                 h: sp.Rational(1, 20), sw: sp.Rational(3, 4)}, label="box 1 x 1 x 2, s = 3/4, b = 1/20"))
d.witness(Joined("stability-AB-box", "M GZ/phi of a heeled box by exact clipping (G below, G above B)",
                 ("stability-AB",), B_CASES, parts=(stability(HEEL, -h), stability(HEEL, h))))
d.witness(Joined("stability-EF-box", "M GZ/phi of a pitched box by exact clipping (G below, G above B)",
                 ("stability-EF",), B_CASES, parts=(stability(PITCH, -h), stability(PITCH, h))))
d.witness(Joined("stability-I-box", "M GZ/phi of a heeled box by exact clipping, G below B",
                 ("stability-I",), B_CASES, parts=(stability(HEEL, -h),)))
d.witness(Joined("stability-K-box", "M GZ/phi of a pitched box by exact clipping, G below B",
                 ("stability-K",), B_CASES, parts=(stability(PITCH, -h),)))

# ---- second pass: the strip, the oblique axes and the areas, by the moments of the figures themselves ----------
STRIP_CASES = rational_cases(("PM = 2, Pp = 1/2", {PM: 2, Pp: "1/2"}), ("PM = 5/3, Pp = 3/10", {PM: "5/3", Pp: "3/10"}))
figure_witness("strip-moment", "∫∫ y^2 over the strip Pp wide from AB up to M", ("strip-moment",), STRIP_CASES, I_YY,
               figure=STRIP)
# the generic rectangle off the origin, at angles whose sine and cosine are rational (3-4-5, 5-12-13)
GEN_CASES = rational_cases(("m = 3/5, [-1, 2] x [0, 3]", {m: "3/5", X1: -1, Y1: 0, X2: 2, Y2: 3}),
                           ("m = 5/13, [-3/2, 5/2] x [1/2, 5/2]",
                            {m: "5/13", X1: "-3/2", Y1: "1/2", X2: "5/2", Y2: "5/2"}))
figure_witness("moment-PQ-rectangle", "∫∫ u^2 over a rectangle off the origin, u the distance from PQ", ("moment-PQ",),
               GEN_CASES, measured("integral", of=(m * x - N_OF_M * y) ** 2), figure=GENERIC)
figure_witness("moment-RS-rectangle", "∫∫ t^2 over a rectangle off the origin, t the distance from RS", ("moment-RS",),
               GEN_CASES, measured("integral", of=(N_OF_M * x + m * y) ** 2), figure=GENERIC)
figure_witness("generic-area", "∫∫ 1 over the rectangle off the origin", ("area-2D",), GEN_CASES, AREA, figure=GENERIC)
figure_witness("square-area-quadrature", "∫∫ 1 over the square", ("square-area",), SQ, AREA, figure=SQUARE)
figure_witness("rect-area-quadrature", "∫∫ 1 over the rectangle", ("rect-area",), AB_CASES, AREA, figure=RECTANGLE)
figure_witness("rhombus-area-quadrature", "∫∫ 1 over the rhombus", ("rhombus-area",), AB_CASES, AREA, figure=RHOMBUS)
ELLIPSE_POINTS = rational_cases(("a = 2, b = 1, x = 1/2", {a: 2, b: 1, x: "1/2"}),
                                ("a = 5/2, b = 3/4, x = 2", {a: "5/2", b: "3/4", x: 2}))
d.witness(CurveRoot("ellipse-ordinate-root", "the ordinate of the ellipse by root-finding", ("ellipse-ordinate",),
                    ELLIPSE_POINTS, equation=x ** 2 / a ** 2 + y ** 2 / b ** 2 - 1, variable=y, bracket=(0, b)))

figure_witness("I-K-rectangle", "∫∫ y^2 and ∫∫ x^2 over a rectangle off the origin", ("I-K-definitions",), GEN_CASES,
               (I_YY, I_XX), figure=GENERIC)
figure_witness("polar-rectangle", "∫∫ (x^2 + y^2) over a rectangle off the origin", ("polar-sum",), GEN_CASES,
               measured("integral", of=x ** 2 + y ** 2), figure=GENERIC)
figure_witness("xy-quadrilateral", "∫∫ xy over the quadrilateral AeBf", ("xy-vanishes",), Q_CASES,
               measured("integral", of=x * y), figure=KITE)
SQ_ANGLES = rational_cases(("a = 1, m = 3/5", {a: 1, m: "3/5"}), ("a = 3/2, m = 5/13", {a: "3/2", m: "5/13"}))
figure_witness("square-oblique", "∫∫ u^2 over the square, u the distance from an oblique axis through C",
               ("square-all-axes",), SQ_ANGLES, measured("integral", of=(m * x - N_OF_M * y) ** 2), figure=SQUARE)
STRIP2_CASES = rational_cases(("PM = 2, PN = 1, Pp = 1/2", {PM: 2, PN: 1, Pp: "1/2"}),
                              ("PM = 5/3, PN = 7/4, Pp = 3/10", {PM: "5/3", PN: "7/4", Pp: "3/10"}))
figure_witness("strip-both-sides", "∫∫ y^2 over the strip Pp wide from N to M", ("strip-sum-of-squares",), STRIP2_CASES,
               I_YY, figure=STRIP_NM)
figure_witness("quadrant-xy", "∫∫ xy over the lower half of the quadrilateral AeBf", ("quadrants-cancel",), Q_CASES,
               measured("integral", of=x * y), figure=KITE_LOWER)
figure_witness("quad-area-quadrature", "∫∫ 1 over the quadrilateral AeBf", ("quad-area-2D",), Q_CASES, AREA,
               figure=KITE)
figure_witness("ellipse-quadrant-quadrature", "a quarter of ∫∫ 1 over the ellipse", ("quadrant-area-integral",),
               AB_CASES, AREA / 4, figure=ELLIPSE)
GEN_E_CASES = rational_cases(("[-1, 2] x [0, 3], x_e = 5/2", {X1: -1, Y1: 0, X2: 2, Y2: 3, xe: "5/2"}),
                             ("[-3/2, 5/2] x [1/2, 5/2], x_e = -1", {X1: "-3/2", Y1: "1/2", X2: "5/2", Y2: "5/2", xe: -1}))
figure_witness("L-rectangle", "∫∫ (x - x_e)^2 over a rectangle off the origin", ("L-definition",), GEN_E_CASES,
               measured("integral", of=(x - xe) ** 2), figure=GENERIC)
figure_witness("EF-rectangle", "∫∫ (x - x_C)^2 over a rectangle off the origin, x_C its centroid",
               ("EF-moment-definition",), GEN_E_CASES, measured("integral", of=(x - XC) ** 2), figure=GENERIC)
figure_witness("sum-of-cubes-strip", "3 ∫∫ y^2 over the strip Pp wide from N to M", ("sum-of-cubes",), STRIP2_CASES,
               3 * I_YY, figure=STRIP_NM)
figure_witness("aggregate-strip", "∫∫ y^2 over the strip Pp wide from N to M", ("aggregate",), STRIP2_CASES, I_YY,
               figure=STRIP_NM)
figure_witness("lower-half-moment", "∫∫ y^2 over the half of the quadrilateral below AB", ("equal-quadrants",), Q_CASES,
               I_YY, figure=KITE_LOWER)


def _box_case(s_, hv, label):
    return Case({Mw: 2 * s_, V: 2 * s_, h: hv, a: 1, b: sp.Rational(1, 2), sw: s_}, label=label)


ONE_WAY = (Case({sw: sp.Rational(1, 2)}, label="box 1 x 1 x 2, s = 1/2, G 1/3 above B"),)
d.witness(Joined("stable-one-way-box", "M GZ/phi of the heeled and the pitched box by exact clipping",
                 ("stable-one-way",), ONE_WAY,
                 parts=tuple(stability(up, sp.Rational(1, 3), 1) for up in (HEEL, PITCH))))
d.witness(Combined("pitch-minus-roll-box", "M GZ/phi pitched minus heeled, the box 1 x 1 x 2 by exact clipping",
                   ("pitch-exceeds-roll",),
                   (_box_case(sp.Rational(1, 2), sp.Rational(1, 10), "s = 1/2, b = 1/10"),
                    _box_case(sp.Rational(3, 4), sp.Rational(1, 20), "s = 3/4, b = 1/20")),
                   parts=(stability(PITCH, h), stability(HEEL, h)), values=(measured("part 1") - measured("part 2"),)))
d.witness(Combined("quad-K-excess-220", "∫∫ (x - x_C)^2 over the quadrilateral minus that of the rhombus with the "
                   "same AB and ef", ("unlike-parts-larger",), Q_CASES, **KITE_EXCESS))


# The box 1 x 1 x 2 of the clipping witnesses (e = 1/2, T = s) heeled about its long axis by exact clipping: the
# coefficients of phi and phi^3 in its arm GZ(phi) (odd in phi), and the heeled equilibrium as the first root of the
# arm beyond the upright position, with the arm's slope there (SERIES_METHODS).
def arm_series(height, k, factor=1, **kw):
    """The coefficient of phi^k (about ``centre``, default 0) in factor times the arm of the box with G at *height*
    above B, heeled."""
    return SeriesWitness("", "", (), (), body=box_with_G(height), up=HEEL, density=sw, quantity=factor * ARM[HEEL],
                         series=(phi, k), odd="centre" not in kw, **kw)


BOX_E = {eb: sp.Rational(1, 2), Tb: sp.Rational(1, 2), sw: sp.Rational(1, 2)}
d.witness(SeriesWitness("moment-times-angle-box", "M GZ/phi of the heeled box by exact clipping, phi -> 0",
                        ("moment-times-angle",), (Case({**BOX_E, Mw: 1, h: sp.Rational(1, 10)}, label="b = 1/10"),
                                                  Case({**BOX_E, Mw: 1, h: sp.Rational(1, 4)}, label="b = 1/4")),
                        body=box_with_G(h), up=HEEL, density=sw, quantity=Mw * ARM[HEEL], series=(phi, 1), odd=True))
d.witness(Combined("same-ratio-box", "the ratio of the heeled box's GZ/phi at two heights of G, by clipping",
                   ("same-ratio",), (Case({**BOX_E, hb1: sp.Rational(1, 40), hb2: sp.Rational(1, 50)},
                                          label="b_1 = 1/40, b_2 = 1/50"),),
                   parts=(arm_series(hb1, 1), arm_series(hb2, 1)), values=(measured("part 1") / measured("part 2"),)))
d.witness(SeriesWitness("small-angles-box", "M (GZ - phi GM)/phi^3 of the heeled box by clipping, phi -> 0",
                        ("small-angles-only",), (Case({**BOX_E, Mw: 1, h: sp.Rational(1, 10)}, label="b = 1/10"),),
                        body=box_with_G(h), up=HEEL, density=sw, quantity=Mw * ARM[HEEL], series=(phi, 3), odd=True))
d.witness(Joined("zero-indifferent-box", "GZ/phi and GZ/phi^3 of the box with b = I/V = 1/6, by clipping",
                 ("zero-indifferent",), (Case(dict(BOX_E), label="e = T = 1/2, b = 1/6"),),
                 parts=(arm_series(sp.Rational(1, 6), 1), arm_series(sp.Rational(1, 6), 3))))
phi_eq = sp.Symbol("phi_*", positive=True)         # the heeled equilibrium
HEELED = Root(ARM[HEEL], phi, tuple(sp.Rational(k, 20) for k in range(1, 15)))     # beyond the upright position
d.witness(Joined("negative-unstable-box", "the box with $G$ a distance $1/100$ above the metacentre: M GZ/phi upright, and its "
                 "heeled equilibrium, the first root of the clipped arm beyond the upright position, with the arm's "
                 "slope there", ("negative-unstable",),
                 (Case({**BOX_E, Mw: 1, gneg: sp.Rational(1, 100)}, label="g = 1/100"),),
                 parts=(arm_series(sp.Rational(1, 6) + gneg, 1, Mw),
                        FloatingRootWitness("", "", (), (), body=box_with_G(sp.Rational(1, 6) + gneg), up=HEEL,
                                            density=sw, quantity=ARM[HEEL], roots=((phi, HEELED),)),
                        arm_series(sp.Rational(1, 6) + gneg, 1, centre=phi_eq, roots=((phi_eq, HEELED),)))))
