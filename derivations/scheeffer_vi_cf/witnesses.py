"""Scheeffer VI.C-F's witnesses: the clipped floating geometry (:mod:`symfloat.engine.floating_witness`)."""
from dataclasses import replace

import sympy as sp

from symfloat.engine.declare import cases_of, declarer
from symfloat.engine.floating_witness import At, Body, FloatingRootWitness, Root, potential_slope
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case

from .statements import F, a, b, d, half, n, om, phi, pi, psi, r, s

# ==== witnesses: the clipped floating geometry =========================================================
UPV = (sp.sin(phi) * sp.sin(om), -sp.sin(phi) * sp.cos(om), sp.cos(phi))   # the up vector (package docstring)
GZW = potential_slope(UPV, phi)                    # the clipped righting arm h.(B - G) = dE/dphi
PRISM, CUBE_BODY, UNIT_CUBE = Body.box(a, a, b), Body.box(b, b, b), Body.box(1, 1, 1)
PHI_GRID = tuple(0.005 + 0.025 * k for k in range(62))
PHIT_GRID = tuple(0.005 + 0.1 * k for k in range(16))   # the clearance decreases monotonically in the first domain
EQUILIBRIUM = Root(GZW, phi, PHI_GRID)             # the oblique equilibrium: the first zero of GZ in phi
TOUCH = Root(measured("face clearance"), phi, PHIT_GRID)     # the tilt at which an end face reaches the water
ph1, pht, ws, gm0 = sp.symbols("varphi_1w varphi_tw omega_w GM_0w")    # measured: the roots and the upright GM


floating = declarer(d, FloatingRootWitness, body=PRISM, up=UPV, density=s)


C = cases_of(a, b, s, om, psi, n, r, F)


UPRIGHT = (0, 0, 1)
UP = (C("a = 1, b = 2, s = 3/10", a=1, b=2, s="0.3"), C("a = 3/2, b = 1, s = 4/5", a="1.5", b=1, s="0.8"),
      C("a = 1, b = 1, s = 1/2", a=1, b=1, s="0.5"))
floating("square-moments", "waterplane moment and area of the upright square prism (clipped)", ("square-moments",),
         UP, (measured("I min"), measured("waterplane area")), up=UPRIGHT)
# a centred, centrally symmetric body at s = 1/2 has its water plane through the centre: the draught is then the
# largest distance of a point from the plane through the centre normal to up
floating("corner-distance", "largest distance of a vertex of the base from the axis (draught at s = 1/2 with up "
         "towards a corner)", ("OB",), UP, measured("draught"), body=Body.box(a, a, 1), up=(1, 1, 0), density=half)
OMC = (C("a = 1, omega = 0.3", a=1, omega="0.3"), C("a = 3/2, omega = 0.7", a="1.5", omega="0.7"),
       C("a = 2, omega = 0.05", a=2, omega="0.05"))
floating("largest-ordinate", "largest distance xi of a base vertex on the sinking side (draught at s = 1/2, up "
         "along xi)", ("u-m",), OMC, measured("draught"), body=Body.box(a, a, 1), up=(-sp.sin(om), sp.cos(om), 0), density=half)
floating("displacement-tilted", "submerged volume of the clipped prism heeled by 0.2 about an axis at omega = 0.3",
         ("V1",), UP, measured("immersed volume"), up=tuple(u.subs({phi: sp.Rational(1, 5), om: sp.Rational(3, 10)}) for u in UPV))
floating("T-over-V", "I_min / submerged volume, upright (clipped)", ("T1-over-V1",), UP, measured("metacentric radius"),
         up=UPRIGHT)
floating("e1-clipped", "height of G above B, upright (clipped)", ("e1",), UP, measured("G above B"), up=UPRIGHT)
floating("metacentric-height", "metacentric height I_min/V - BG, upright (clipped)", ("upright-condition",), UP,
         measured("metacentric height"), up=UPRIGHT)
floating("duhamel-75", "12 s/b x metacentric height, upright (clipped)", ("75", "78"), UP,
         12 * s / b * measured("metacentric height"), up=UPRIGHT)
floating("duhamel-75-unstable", "-12 s/b x metacentric height, upright (clipped)", ("75-unstable",), UP,
         -12 * s / b * measured("metacentric height"), up=UPRIGHT)
floating("area-b2-over-T", "F_1 b^2 s(1-s)/T_1 from the clipped upright waterplane", ("Fb2-over-T1",), UP,
         measured("waterplane area") * b ** 2 * s * (1 - s) / measured("I min"), up=UPRIGHT)
TOP = (C("a = 1, b = 1, s = 7/10, omega = 0.3", a=1, b=1, s="0.7", omega="0.3"),
       C("a = 6/5, b = 1, s = 9/10, omega = 0.7", a="1.2", b=1, s="0.9", omega="0.7"))
floating("touch-top", "tan of the tilt at which the top face reaches the clipped water plane", ("limit-top",), TOP,
         sp.tan(phi), roots=((phi, TOUCH),))
# the region of (78a): (1-s)(7s-1) <= (a/b)^2 < 6s(1-s) (s > 1/2), s(6-7s) <= (a/b)^2 < 6s(1-s) (s < 1/2)
R78A = (C("a = 11/10, b = 1, s = 7/10, omega = 0.3", a="1.1", b=1, s="0.7", omega="0.3"),
        C("a = 11/10, b = 1, s = 3/10, omega = 0.6", a="1.1", b=1, s="0.3", omega="0.6"),
        C("a = 97/100, b = 1, s = 4/5, omega = 0.1", a="0.97", b=1, s="0.8", omega="0.1"))
Q2 = (a / b) ** 2
AT_OMEGA = ((pht, TOUCH), (phi, EQUILIBRIUM))                       # phi_t and phi_1 at the case's omega
AT_45 = ((pht, replace(TOUCH, at={om: pi / 4})), (phi, EQUILIBRIUM))  # phi_t at 45 deg, phi_1 at omega
floating("oblique-76", "tan^2 of the clipped equilibrium tilt and tan of the clipped touching tilt at omega",
         ("76",), R78A, (sp.tan(phi) ** 2, sp.tan(pht)), roots=AT_OMEGA)
floating("oblique-78b", "tan of the clipped equilibrium tilt (root of GZ)", ("78b",), R78A, sp.tan(phi),
         roots=((phi, EQUILIBRIUM),))
floating("oblique-76-45", "tan^2 phi_1 (at omega) and tan of the touching tilt at omega = 45 deg, clipped",
         ("76-at-45",), R78A, (sp.tan(phi) ** 2, sp.tan(pht)), roots=AT_45)
floating("oblique-76-squared", "tan^2 phi_t(45 deg) - tan^2 phi_1, clipped", ("76-squared",), R78A,
         sp.tan(pht) ** 2 - sp.tan(phi) ** 2, roots=AT_45)
floating("oblique-77", "(a/b)^2/2 (tan^2 phi_t(45 deg) - tan^2 phi_1), clipped", ("77",), R78A,
         Q2 / 2 * (sp.tan(pht) ** 2 - sp.tan(phi) ** 2), roots=AT_45)
floating("oblique-78a", "-12 s/b GM upright and (a/b)^2/2 (tan^2 phi_t(45 deg) - tan^2 phi_1), clipped", ("78a",),
         R78A, (-12 * s / b * gm0, Q2 / 2 * (sp.tan(pht) ** 2 - sp.tan(phi) ** 2)),
         roots=((gm0, At(measured("metacentric height"), {phi: 0})),) + AT_45)
# the region of (78c): 2(1-s)(4s-1) <= (a/b)^2 < (1-s)(7s-1) (s > 1/2) and its mirror
R78C = (C("a = 53/50, b = 1, s = 7/10", a="1.06", b=1, s="0.7"),
        C("a = 53/50, b = 1, s = 3/10", a="1.06", b=1, s="0.3"),
        C("a = 19/20, b = 1, s = 4/5", a="0.95", b=1, s="0.8"))
EDGE = ((ph1, replace(EQUILIBRIUM, at={om: 0})),)                  # phi_1 with the axis along an edge
floating("oblique-78c", "(a/b)^2/2 (tan^2 phi_1 - tan^2 phi_t(45 deg)), phi_1 at omega = 0, clipped", ("78c",), R78C,
         Q2 / 2 * (sp.tan(ph1) ** 2 - sp.tan(pht) ** 2), roots=EDGE + ((om, pi / 4), (pht, TOUCH)))
floating("oblique-78e", "(a/b)^2/2 (tan^2 phi_1 - tan^2 phi_t(0)), clipped", ("78e",), R78C + R78A[:1],
         Q2 / 2 * (sp.tan(ph1) ** 2 - sp.tan(pht) ** 2), roots=EDGE + ((om, 0), (pht, TOUCH)))
# omega*: the axis direction at which an end face reaches the water at the equilibrium tilt phi_1(omega = 0)
OMEGA_STAR = EDGE + ((phi, ph1), (om, Root(measured("face clearance"), om, tuple(0.001 + 0.02 * k for k in range(40)))))
floating("limit-omega", "sin^2(45 deg + omega*), omega* the clipped root of the face clearance at phi_1",
         ("78d",), R78C, sp.sin(pi / 4 + om) ** 2, roots=OMEGA_STAR)

# ---- the cube
CUBE = (C("b = 1, s = 0.3", b=1, s="0.3"), C("b = 2, s = 0.8", b=2, s="0.8"), C("b = 1/2, s = 0.1", b="0.5", s="0.1"))
floating("cube-duhamel", "12 s/b x metacentric height of the upright cube (clipped)", ("cube-78",), CUBE,
         12 * s / b * measured("metacentric height"), body=CUBE_BODY, up=UPRIGHT)
floating("cube-duhamel-2", "2 s/b x metacentric height of the upright cube (clipped)", ("cube-78-square",), CUBE,
         2 * s / b * measured("metacentric height"), body=CUBE_BODY, up=UPRIGHT)
ONE = (Case({}, label="unit cube"),)
s_up, s_lo = sp.symbols("s_+w s_-w")
UPRIGHT_S = tuple((sym, Root(measured("metacentric height"), s, tuple(0.5 + sg * 0.01 * k for k in range(1, 50))))
                  for sym, sg in ((s_up, 1), (s_lo, -1)))          # scanned from 1/2 outwards
floating("cube-upright-thresholds", "densities where the clipped upright cube's metacentric height vanishes",
         ("79",), ONE, (s_up, s_lo), body=UNIT_CUBE, up=UPRIGHT, roots=UPRIGHT_S)
floating("cube-upright-upper", "upper density where the clipped upright cube's metacentric height vanishes",
         ("79-upper-number", "81-upper"), ONE, s_up, body=UNIT_CUBE, up=UPRIGHT, roots=UPRIGHT_S[:1])
floating("cube-upright-lower", "lower density where the clipped upright cube's metacentric height vanishes",
         ("79-lower-number", "81-lower"), ONE, s_lo, body=UNIT_CUBE, up=UPRIGHT, roots=UPRIGHT_S[1:])


def touch_equilibrium(sym, upper, w):
    """The density (scanned from 0.55, or 0.45, outwards) at which the clipped cube's equilibrium tilt at the axis
    angle w is its touching tilt: the root in s of GZ at the root in phi of the face clearance (nested)."""
    grid = tuple(0.5 + (1 if upper else -1) * (0.05 + 0.02 * k) for k in range(13))
    return sym, Root(GZW, s, grid, at={om: w}, roots=((phi, TOUCH),))


OBLIQUE_S = (touch_equilibrium(s_up, True, pi / 4), touch_equilibrium(s_lo, False, pi / 4))
floating("cube-oblique-thresholds", "densities where the clipped cube's equilibrium reaches a face at omega = 45 deg",
         ("80",), ONE, (s_up, s_lo), body=UNIT_CUBE, roots=OBLIQUE_S)
floating("cube-oblique-roots", "the same thresholds, less 4/7 and from 3/7", ("80-roots",), ONE,
         (s_up - sp.Rational(4, 7), sp.Rational(3, 7) - s_lo), body=UNIT_CUBE, roots=OBLIQUE_S)
floating("cube-oblique-upper", "upper density where the clipped equilibrium reaches a face at omega = 45 deg",
         ("80-upper-number", "81-oblique-upper"), ONE, s_up, body=UNIT_CUBE, roots=OBLIQUE_S[:1])
floating("cube-oblique-lower", "lower density where the clipped equilibrium reaches a face at omega = 45 deg",
         ("80-lower-number", "81-oblique-lower"), ONE, s_lo, body=UNIT_CUBE, roots=OBLIQUE_S[1:])
floating("cube-edge-thresholds", "densities nearest 1/2 where the clipped equilibrium reaches a face at omega = 0",
         ("edge-axis-range",), ONE, (s_up, s_lo), body=UNIT_CUBE,
         roots=(touch_equilibrium(s_up, True, 0), touch_equilibrium(s_lo, False, 0)))
CUBE_OBL = (C("b = 1, s = 0.78", b=1, s="0.78"), C("b = 2, s = 0.22", b=2, s="0.22"))
floating("cube-oblique-tilt", "tan^2 of the clipped cube's equilibrium tilt (omega = 0.4)", ("81a",), CUBE_OBL,
         sp.tan(phi) ** 2, body=CUBE_BODY, roots=((om, sp.Rational(2, 5)), (phi, EQUILIBRIUM)))
CUBE_78A = EDGE + ((om, pi / 4), (pht, TOUCH))
floating("cube-78a", "1/2 (tan^2 phi_t(45 deg) - tan^2 phi_1) for the clipped cube", ("cube-78a",), CUBE_OBL,
         (sp.tan(pht) ** 2 - sp.tan(ph1) ** 2) / 2, body=CUBE_BODY, roots=CUBE_78A)
floating("cube-78a-7", "1/14 (tan^2 phi_t(45 deg) - tan^2 phi_1) for the clipped cube", ("cube-78a-square",), CUBE_OBL,
         (sp.tan(pht) ** 2 - sp.tan(ph1) ** 2) / 14, body=CUBE_BODY, roots=CUBE_78A)
floating("cube-limit-omega", "sin^2(45 deg + omega*) for the clipped cube", ("82",),
         (C("b = 1, s = 0.76", b=1, s="0.76"), C("b = 2, s = 0.24", b=2, s="0.24")), sp.sin(pi / 4 + om) ** 2,
         body=CUBE_BODY, roots=OMEGA_STAR)
floating("half-cube-turned", "potential change of the clipped cube (s = 1/2, phi = 45 deg) turned by omega about "
         "its main axis", ("half-stable",), (C("a = 1, omega = 0.1", a=1, omega="0.1"),
                                             C("a = 2, omega = 0.3", a=2, omega="0.3")),
         measured("G above B") - gm0, body=Body.box(a, a, a), density=half,
         roots=((phi, pi / 4), (gm0, At(measured("G above B"), {om: 0}))))
floating("half-tilt-clipped", "clipped equilibrium tilt of the cube at s = 1/2 (root of GZ)", ("half-tilt",), ONE,
         phi, body=UNIT_CUBE, density=half, roots=((om, 0), (phi, EQUILIBRIUM)))
floating("half-waterplane", "waterplane area of the clipped cube at s = 1/2, phi = 45 deg", ("half-waterplane",),
         (C("b = 1", b=1), C("b = 3/2", b="1.5")), measured("waterplane area"), body=CUBE_BODY, density=half,
         roots=((phi, pi / 4), (om, 0)))


# ---- the n-gon: regular prisms (one vertex on +x), upright at s = 1/2 for the moments of the base
def ngon(label, k, side, **kw):
    """A case with its own body: the regular k-gon prism of edge *side* and length b (1 when not given)."""
    return C(label, Body.regular(k, side, b if "b" in kw else 1), **kw)


def by_radius(label, k, **kw):
    return ngon(label, k, 2 * r * sp.sin(pi / k), n=k, **kw)


def by_area(label, k, **kw):
    """The k-gon of area F: k triangles of apex angle 2 pi/k and sides R, F = k R^2 sin(2 pi/k)/2."""
    return ngon(label, k, 2 * sp.sin(pi / k) * sp.sqrt(2 * F / (k * sp.sin(2 * pi / k))), n=k, **kw)


NG = (by_radius("r = 1, n = 3, omega = 0.3", 3, r=1, omega="0.3"),
      by_radius("r = 3/2, n = 5, omega = 0.5", 5, r="1.5", omega="0.5"),
      by_radius("r = 1, n = 8, omega = 0.7", 8, r=1, omega="0.7"))   # omega only enters the misread 'omega tg' prints
floating("polygon-moment", "moment of the regular polygon about an axis through its centre (clipped waterplane)",
         ("84", "85", "86-nA", "87", "87-cos2", "89", "89a", "86a"), NG, measured("I min"), body=None, up=UPRIGHT, density=half)
floating("polygon-moment-2", "2 T_1 and T_1 of the regular polygon (clipped waterplane)", ("86",), NG,
         (2 * measured("I min"), measured("I min")), body=None, up=UPRIGHT, density=half)
floating("polygon-area", "area of the regular polygon (clipped waterplane)", ("area",), NG, measured("waterplane area"),
         body=None, up=UPRIGHT, density=half)
# the largest distance of a vertex from a line through the centre: the freeboard above a water plane normal to
# that line plus the water plane's height above the centre (any density)
floating("polygon-radius", "squared distance of the vertices from the centre (reach towards vertex 0)", ("radius",),
         NG, (measured("freeboard") + measured("water level")) ** 2, body=None, up=(1, 0, 0), density=half)
floating("polygon-apothem", "distance of the centre from the midpoint of a side (reach across the side 0-1)",
         ("apothem",), NG, measured("freeboard") + measured("water level"), body=None,
         up=(sp.cos(pi / n), sp.sin(pi / n), 0), density=half)
NG34 = {k: (by_radius("r = 1", k, r=1), by_radius(f"r = {v}", k, r=v)) for k, v in ((3, "3/2"), (4, "2/3"))}
floating("triangle-moment", "moment of the equilateral triangle (clipped waterplane)", ("triangle-T1",), NG34[3],
         measured("I min"), body=None, up=UPRIGHT, density=half)
floating("square-moment", "moment of the square (clipped waterplane)", ("square-T1",), NG34[4], measured("I min"), body=None,
         up=UPRIGHT, density=half)
floating("polygon-ordinate", "largest distance of a vertex from the axis on the sinking side (reach along xi)",
         ("88",), (by_radius("r = 1, n = 3, omega = 0.7", 3, r=1, omega="0.7"),
                   by_radius("r = 3/2, n = 6, omega = 0.3", 6, r="1.5", omega="0.3"),
                   by_radius("r = 1, n = 4, omega = 0.2", 4, r=1, omega="0.2")),
         measured("freeboard") + measured("water level"), body=None,
         up=(sp.cos(pi / n + om), sp.sin(pi / n + om), 0), density=half)
floating("triangle-at-area", "moment of the equilateral triangle of area F (clipped waterplane)",
         ("triangle-largest",), (by_area("F = 1", 3, F=1), by_area("F = 5/2", 3, F="2.5")), measured("I min"), body=None,
         up=UPRIGHT, density=half)
floating("ngon-tilt", "tan^2 of the clipped equilibrium tilt of regular n-gon prisms of area F", ("54-again",),
         (by_area("F = 1, n = 6, b = 9/10, s = 7/10", 6, F=1, b="0.9", s="0.7"),
          by_area("F = 1, n = 3, b = 97/100, s = 7/10", 3, F=1, b="0.97", s="0.7")), sp.tan(phi) ** 2, body=None,
         roots=((om, 0), (phi, EQUILIBRIUM)))


# the side and the triangles BOC of the n-gon (O the centre, B and C the vertices at -+pi/n from the x axis), turned
# by -psi: the upright prism over the triangle; its moments about the axes through O are the waterplane's central
# ones moved to O (Steiner), its side BC twice the reach of C above the x axis (the triangle is symmetric about it)
def triangle_BOC(label, k, turned, **kw):
    turn = -psi if turned else 0
    corners = [(0, 0)] + [(r * sp.cos(q + turn), r * sp.sin(q + turn)) for q in (-pi / k, pi / k)]
    return C(label, Body.prism(corners, 1), n=k, **kw)


ABOUT_O = (measured("waterplane tensor, yy") + measured("waterplane area") * measured("waterplane centroid, y") ** 2,
           measured("waterplane tensor, xx") + measured("waterplane area") * measured("waterplane centroid, x") ** 2)
floating("polygon-side", "distance of adjacent vertices (twice the reach of C across OQ)", ("side",),
         tuple(triangle_BOC(c.label, int(c.params[n]), False, r=c.params[r], omega=c.params[om]) for c in NG),
         2 * (measured("freeboard") + measured("water level")), body=None, up=(0, 1, 0), density=half)
TRI = (("r = 1, n = 3, psi = 0.4", 3, "1", "0.4"), ("r = 3/2, n = 7, psi = 1.1", 7, "1.5", "1.1"))
floating("triangle-axis", "moment of the triangle BOC turned by -psi about the x axis through O (clipped waterplane)",
         ("triangle-axis", "83"), tuple(triangle_BOC(lb, k, True, r=rv, psi=pv) for lb, k, rv, pv in TRI),
         ABOUT_O[0], body=None, up=UPRIGHT, density=half)
floating("triangle-axes", "moments of the triangle BOC about OQ and the perpendicular through O (clipped waterplane)",
         ("triangle-moments",), tuple(triangle_BOC(lb, k, False, r=rv, psi=pv) for lb, k, rv, pv in TRI),
         ABOUT_O, body=None, up=UPRIGHT, density=half)
