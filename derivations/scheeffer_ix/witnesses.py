"""Scheeffer IX's witnesses: the clipped floating box (:mod:`symfloat.engine.floating_witness`)."""
from dataclasses import replace

import sympy as sp

from symfloat.engine.declare import cases_of, declarer, part_of
from symfloat.engine.floating_witness import (At, Body, Difference, FloatingRootWitness, Joined, Root, crossing,
                                              potential_curvature, potential_slope)
from symfloat.engine.measured import measured

from .statements import a, b, c, d, phi, rho_s, s, t, z


# ==== witnesses: the clipped floating box ============================================================
# The box is clipped by the water plane at the draught found from the volume (symfloat.engine.floating_witness):
# metacentric heights from the clipped waterplane, equilibrium tilts roots of the clipped potential's slope, the
# tilts at which a corner reaches the water roots of its height over the water, the leg x the height of the
# rising corner D over the water along the side b, m_3 the offset of the centroid of the clipped dry part,
# F', F'' central differences of the clipped quantity in z, the double roots extrema of the clipped righting arm
# at which it vanishes.
ph = sp.Symbol("varphi_w")                           # a witness's tilt from the position with b vertical
UP_C = (sp.sin(ph), sp.cos(ph), 0)                   # turned about the c-axis, raising the corner D = (a/2, b/2)
UP_A = (0, sp.cos(ph), sp.sin(ph))                   # turned about the a-axis
SLOPE_C, SLOPE_A = potential_slope(UP_C, ph), potential_slope(UP_A, ph)
BOX = Body.box(a, b, c)
SECTION = Body.box(a, b, 2)                          # the plane problem of the second region: any length along c
PHI = tuple(0.004 + 0.025 * k for k in range(63))    # (0, pi/2)
EQ_C = Root(SLOPE_C, ph, PHI)                        # the first oblique equilibrium about c
EQ_A = Root(SLOPE_A, ph, PHI)
DOWN, UPWARD = (0, -1, 0), (0, 1, 0)                # along the sides b
DRY_C = crossing(UP_C, (-a / 2, b / 2, 0), DOWN)    # from the top corner C down its side to the water
WET_A = crossing(UP_C, (a / 2, -b / 2, 0), UPWARD)  # from the bottom corner A up its side to the water
CORNER_C, CORNER_A = Root(DRY_C, ph, PHI), Root(WET_A, ph, PHI)            # C or A reaches the water
# the first of the two faces b to reach the water (the top face for s > 1/2, the bottom face for s < 1/2): about c
# their vertices nearest to the water are C and A, about a the edges at z = -c/2 on top and z = c/2 below
TOUCH_C = Root(sp.Min(DRY_C, WET_A), ph, PHI)
TOUCH_A = Root(sp.Min(crossing(UP_A, (0, b / 2, -c / 2), DOWN), crossing(UP_A, (0, -b / 2, c / 2), UPWARD)), ph, PHI)
LEG = crossing(UP_C, (a / 2, b / 2, 0), DOWN)       # x: from the rising corner D down the side b to the water
M3_W = s / (1 - s) * SLOPE_C                       # m_3 = h.S_3 = -(s/sigma) h.(B - G), G at the origin
G_W = 3 * M3_W * (LEG / b) ** 3 / (b * sp.sin(ph))   # 3 m_3 z^3/(b sin phi_2), z the measured x/b
HG_W = measured("waterplane area") / 2                   # the waterplane's width across the axis (SECTION)
TILT_Z = Root(LEG / b - z, ph, PHI)                # the tilt at which x/b = z
ph1w, phtw, phCw, phAw, FCw, FAw, HCw, HAw, dFw = sp.symbols("varphi_1w varphi_tw varphi_Cw varphi_Aw F_Cw F_Aw "
                                                              "HG_Cw HG_Aw dF_w")


floating = declarer(d, FloatingRootWitness, up=UP_C, body=BOX, density=s)


part = part_of(FloatingRootWitness, body=BOX, density=s)     # a part of a Joined witness


C = cases_of(a, b, c, s, z, phi, t)


UP = (C("a = 1, b = 2, c = 3, s = 3/10", a=1, b=2, c=3, s="0.3"), C("a = 3/2, b = 1, c = 2, s = 4/5", a="1.5", b=1, c=2, s="0.8"),
      C("a = 1, b = 1, c = 5/4, s = 1/2", a=1, b=1, c="1.25", s="0.5"))
GM_MAX = measured("I max") / measured("immersed volume") - measured("G above B")     # the metacentric height about the a-axis
UPRIGHT = (0, 1, 0)
floating("upright-min", "metacentric height about the axis parallel to c, upright (clipped, I_min for c > a)",
         ("122", "stability-condition"), UP, measured("metacentric height"), up=UPRIGHT)
floating("upright-min-12", "12 s/b x the same", ("123", "132a"), UP, 12 * s / b * measured("metacentric height"),
         up=UPRIGHT)
floating("upright-max", "metacentric height about the axis parallel to a (I_max), upright (clipped)", ("T11-V1",), UP,
         GM_MAX, up=UPRIGHT)
floating("upright-max-12", "12 s/b x the same", ("124",), UP, 12 * s / b * GM_MAX, up=UPRIGHT)
floating("moments", "smallest waterplane moment, upright (clipped)", ("T1",), UP, measured("I min"), up=UPRIGHT)
floating("largest", "largest waterplane moment, upright (clipped)", ("largest-moment",), UP, measured("I max"), up=UPRIGHT)
floating("volume-height", "submerged volume and height of G above B, upright (clipped)", ("V1-e1",), UP,
         (measured("immersed volume"), measured("G above B")), up=UPRIGHT)
floating("moment-volume-height", "I_min and volume x height of G above B, upright (clipped)", ("T1-V1e1",), UP,
         (measured("I min"), measured("immersed volume") * measured("G above B")), up=UPRIGHT)
floating("moment-difference", "I_max - I_min and the moments, upright (clipped)", ("127",), UP,
         (measured("I max"), measured("I min"), measured("I max") - measured("I min")), up=UPRIGHT)
floating("moment-difference-2", "I_max - I_min, upright (clipped)", ("126",), UP,
         measured("I max") - measured("I min"), up=UPRIGHT)
floating("moment-difference-3", "I_min - I_max, upright (clipped)", ("128-unstable",), UP,
         measured("I min") - measured("I max"),
         up=UPRIGHT)

# first region: both oblique positions inside the region (6s(1-s) > (a/b)^2, (c/b)^2 >= rho)
R1 = (C("a = 21/20, b = 1, c = 11/10, s = 7/10", a="1.05", b=1, c="1.1", s="0.7"),
      C("a = 21/20, b = 1, c = 11/10, s = 3/10", a="1.05", b=1, c="1.1", s="0.3"),
      C("a = 53/50, b = 1, c = 11/10, s = 17/25", a="1.06", b=1, c="1.1", s="0.68"))
R1U = R1[:1] + R1[2:]
floating("oblique-c", "tan^2 of the clipped equilibrium tilt about the c-axis (root of the potential's slope)",
         ("125",), R1, sp.tan(ph) ** 2, roots=((ph, EQ_C),))
floating("oblique-c-pre", "1 + tan^2/2 of the clipped equilibrium tilt about the c-axis", ("125-pre",), R1,
         1 + sp.tan(ph) ** 2 / 2, roots=((ph, EQ_C),))
floating("oblique-c-32", "I_min (1 + tan^2 phi_1/2) - V e_1 with the clipped upright moment, volume, height and tilt",
         ("32",), R1,
         measured("I min") * (1 + sp.tan(ph1w) ** 2 / 2) - measured("immersed volume") * measured("G above B"),
         roots=((ph1w, EQ_C), (ph, 0)))
floating("oblique-a", "tan^2 of the clipped equilibrium tilt about the a-axis", ("128",), R1, sp.tan(ph) ** 2, up=UP_A,
         roots=((ph, EQ_A),))
d.witness(Joined("touch", "tan of the clipped tilt at which the top face reaches the water, about c and about a",
                 ("129",), R1U, parts=(part(quantity=sp.tan(ph), up=UP_C, roots=((ph, TOUCH_C),)),
                                       part(quantity=sp.tan(ph), up=UP_A, roots=((ph, TOUCH_A),)))))
floating("touch-2", "tan^2 of the clipped touching tilt about c", ("129-squared",), R1U, sp.tan(ph) ** 2,
         roots=((ph, TOUCH_C),))
MARGIN = sp.tan(phtw) ** 2 - sp.tan(ph1w) ** 2
TILTS_C, TILTS_A = ((phtw, TOUCH_C), (ph1w, EQ_C), (ph, 0)), ((phtw, TOUCH_A), (ph1w, EQ_A), (ph, 0))
floating("margin", "tan^2(touch) - tan^2(equilibrium) about c, clipped", ("130-pre",), R1U, MARGIN, roots=TILTS_C)
floating("margin-130", "(a/b)^2/2 (tan^2 touch - tan^2 equilibrium) about c, clipped", ("130",), R1U,
         (a / b) ** 2 / 2 * MARGIN, roots=TILTS_C)
# -12 s/b GM upright and the margin of the oblique tilt, about c (I_min) and about a (I_max)
REGION_C = part(quantity=(-12 * s / b * measured("metacentric height"), (a / b) ** 2 / 2 * MARGIN), up=UP_C,
                roots=TILTS_C)
REGION_A = part(quantity=(-12 * s / b * GM_MAX, (c / b) ** 2 / 2 * MARGIN), up=UP_A, roots=TILTS_A)
d.witness(Joined("region-131", "-12 s/b GM and the margins, both axes, clipped", ("131",), R1U,
                 parts=(REGION_C, REGION_A)))
d.witness(Joined("region-132b", "-12 s/b GM about c and the margin, clipped", ("132b",), R1, parts=(REGION_C,)))
d.witness(Joined("region-132c", "-12 s/b GM about a and the margin, clipped", ("132c",), R1, parts=(REGION_A,)))

# second region
R2 = (C("a = 3/2, b = 1, s = 4/5, z = 3/4", a="1.5", b=1, s="0.8", z="0.75"),
      C("a = 6/5, b = 1, s = 9/10, z = 1/2", a="1.2", b=1, s="0.9", z="0.5"),
      C("a = 1, b = 1, s = 7/10, z = 9/10", a=1, b=1, s="0.7", z="0.9"))
STEP_Z = sp.Rational(1, 25)
D1 = Difference(G_W, z, STEP_Z, 1, roots=((ph, TILT_Z),))
floating("quartic", "3 m_3 z^3/(b sin phi_2) of the clipped box at the tilt where x/b = z", ("133", "136"), R2, G_W,
         body=SECTION, roots=((ph, TILT_Z),))
floating("quartic-first", "3 m_3 z^3/b of the clipped box at the tilt where x/b = z", ("133-first",), R2,
         G_W * sp.sin(ph), body=SECTION, roots=((ph, TILT_Z),))
floating("quartic-d1", "five-point derivative in z of the clipped quantity", ("137",), R2[:2], dFw, body=SECTION,
         roots=((dFw, D1),))
floating("quartic-d2", "five-point second derivative in z of the clipped quantity", ("138",), R2[:2], dFw,
         body=SECTION, roots=((dFw, Difference(G_W, z, STEP_Z, 2, roots=((ph, TILT_Z),))),))
floating("quartic-d1-34", "five-point derivative of the clipped quantity at z = 3/4", ("139", "139-pre"),
         (C("a = 3/2, b = 1, s = 4/5", a="1.5", b=1, s="0.8"),), dFw, body=SECTION,
         roots=((z, sp.Rational(3, 4)), (dFw, D1)))
floating("threshold-140", "F'(3/4)/3 of the clipped box with a = b", ("140",), (C("s = 4/5", s="0.8"),), dFw / 3,
         body=SECTION, roots=((a, 1), (b, 1), (z, sp.Rational(3, 4)), (dFw, D1)))
R2T = (C("a = 3/2, b = 1, s = 4/5, varphi_2 = 1/2", a="1.5", b=1, s="0.8", varphi_2="0.5"),
       C("a = 6/5, b = 1, s = 9/10, varphi_2 = 3/5", a="1.2", b=1, s="0.9", varphi_2="0.6"))
AT_PHI = ((ph, phi),)
floating("leg", "x^2: the clipped distance of the rising corner from the water along b, squared", ("134",), R2T,
         LEG ** 2, body=SECTION, roots=AT_PHI)
floating("waterline", "HG: clipped waterplane width across the axis", ("HG",), R2T, HG_W, body=SECTION, roots=AT_PHI)
floating("waterline-2", "HG^2 (clipped)", ("HG2",), R2T, HG_W ** 2, body=SECTION, roots=AT_PHI)
floating("waterline-ratio", "(HG/x)^2 (clipped)", ("sin2",), R2T, (HG_W / LEG) ** 2, body=SECTION, roots=AT_PHI)
floating("cot-leg", "2 a b (1-s)/x^2 with the clipped x", ("cot",), R2T, 2 * a * b * (1 - s) / LEG ** 2, body=SECTION,
         roots=AT_PHI)
R2E = (C("a = 3/2, b = 1, c = 3, s = 4/5", a="1.5", b=1, c=3, s="0.8"), C("a = 6/5, b = 1, c = 2, s = 7/10", a="1.2", b=1, c=2, s="0.7"),
       C("a = 1, b = 1, c = 2, s = 13/20", a=1, b=1, c=2, s="0.65"))
AT_C, AT_A = ((ph, CORNER_C),), ((ph, CORNER_A),)   # the start of the region (corner C at the water) and its end (A)
ENDS = ((phCw, CORNER_C), (phAw, CORNER_A), (FCw, At(G_W, {ph: phCw})), (FAw, At(G_W, {ph: phAw})),
        (HCw, At(HG_W, {ph: phCw})), (HAw, At(HG_W, {ph: phAw})))
SIG2 = 2 * (1 - s) ** 2


def second(name, description, targets, quantity, roots):
    floating(name, description, targets, R2E, quantity, body=SECTION, roots=roots)


second("x-low", "x at the clipped tilt where corner C reaches the water (twice)", ("x-low",), (LEG, LEG), AT_C)
second("z-low", "x/b at the clipped tilt where corner C reaches the water", ("135a",), LEG / b, AT_C)
second("z-high", "x/b at the clipped tilt where corner A reaches the water", ("135b",), LEG / b, AT_A)
second("F-low", "the clipped quantity at the start of the region", ("141",), G_W, AT_C)
second("F-high", "the clipped quantity at the end of the region", ("142",), G_W, AT_A)
second("F-low-143", "-F(2 sigma)/(2 sigma^2), clipped", ("143",), -G_W / SIG2, AT_C)
second("F-low-144", "F(2 sigma)/(2 sigma^2), clipped", ("144",), G_W / SIG2, AT_C)
second("F-ends", "the clipped quantity at both ends of the region", ("161",), (FCw, FAw), ENDS)
second("F-ends-162", "F(2 sigma)/(2 sigma^2) and 2 F(1)/rho, clipped", ("162",), (FCw / SIG2, 2 * FAw / rho_s), ENDS)
second("F-ends-162a", "-F(2 sigma)/(2 sigma^2) and F(2 sigma)/(2 sigma^2), clipped", ("162a",), (-FCw / SIG2, FCw / SIG2),
       ENDS)
second("HG-start", "(c^2 - HG^2)/b^2 at the start of the region (clipped)", ("164",), (c ** 2 - HG_W ** 2) / b ** 2, AT_C)
second("HG-ends", "(HG_start^2 - HG_end^2)/b^2 (clipped)", ("HG-max",), (HCw ** 2 - HAw ** 2) / b ** 2, ENDS)
floating("HG-z", "(c^2 - HG^2)/b^2 at the tilt where x/b = z (clipped)", ("163",),
         (C("a = 3/2, b = 1, c = 2, s = 4/5, z = 3/4", a="1.5", b=1, c=2, s="0.8", z="0.75"),
          C("a = 6/5, b = 1, c = 3/2, s = 9/10, z = 1/2", a="1.2", b=1, c="1.5", s="0.9", z="0.5")),
         (c ** 2 - HG_W ** 2) / b ** 2, body=SECTION, roots=((ph, TILT_Z),))

# third region: the a-vertical position and its oblique neighbour, the last equilibrium before 90 deg; the face
# x = a/2 on top there reaches the water when the corner A does
R3 = (C("a = 21/20, b = 1, c = 2, s = 4/5", a="1.05", b=1, c=2, s="0.8"),
      C("a = 27/25, b = 1, c = 3/2, s = 41/50", a="1.08", b=1, c="1.5", s="0.82"))
R3M = R3 + (C("a = 21/20, b = 1, c = 2, s = 1/5", a="1.05", b=1, c=2, s="0.2"),)
EQ_3 = Root(SLOPE_C, ph, PHI[:-1], which="last")
MARGIN_3 = (b / a) ** 2 / 2 * (1 / sp.tan(phAw) ** 2 - 1 / sp.tan(ph) ** 2)   # tan of the tilt from a vertical: cot
floating("oblique-3", "cot^2 of the clipped equilibrium tilt next to the a-vertical position (last root of the slope)",
         ("166",), R3M, 1 / sp.tan(ph) ** 2, roots=((ph, EQ_3),))
floating("upright-3", "12 s/a x metacentric height with a vertical (clipped)", ("upright-3",), R3M,
         12 * s / a * measured("metacentric height"), up=(1, 0, 0))
floating("unstable-3", "-(a/b)^2/(6s(1-s)) 12 s/a x metacentric height with a vertical (clipped)", ("unstable-3",), R3M,
         -(a / b) ** 2 / (6 * s * (1 - s)) * 12 * s / a * measured("metacentric height"), up=(1, 0, 0))
floating("margin-3", "(b/a)^2/2 (tan^2 touch - tan^2 equilibrium) next to the a-vertical position (clipped)",
         ("165-pre",), R3, MARGIN_3, roots=((phAw, CORNER_A), (ph, EQ_3)))
floating("margin-165", "(a/b)^2/rho x the same (clipped)", ("165",), R3, (a / b) ** 2 / rho_s * MARGIN_3,
         roots=((phAw, CORNER_A), (ph, EQ_3)))


# the double roots at t = 1/2 (b = 1): the edge a at which the clipped righting arm vanishes at an extremum inside
# the second region, a minimum (a > b, the last extremum) or a maximum (a < b, the first)
CURVATURE_C = potential_curvature(UP_C, ph)          # the slope of the righting arm
a_p, a_m, z_p, z_m, phCd, phAd = sp.symbols("a_+w a_-w z_+w z_-w varphi_Cd varphi_Ad")


def _extremum(which):
    """The tilt of the extremum of the arm in the second region (between the corners C and A at the water)."""
    return ((phCd, CORNER_C), (phAd, CORNER_A), (ph, Root.scan(CURVATURE_C, ph, phCd, phAd, 60, which=which)))


def _double(edge, which, grid, zw):
    """The edge (a) and x/b (z) at a double root: roots for a FloatingRootWitness."""
    found = Root(SLOPE_C, a, grid, roots=_extremum(which))
    at = tuple((sym, replace(spec, at={a: edge})) for sym, spec in _extremum(which))
    return ((edge, found),) + at + ((zw, At(LEG, {a: edge})),)


DOUBLE = ((b, 1),) + (_double(a_p, "last", tuple(1.02 + sp.Rational(4, 100) * k for k in range(10)), z_p)
          + _double(a_m, "first", tuple(sp.Rational(98, 100) - sp.Rational(2, 100) * k for k in range(10)), z_m))
DRC = (C("t = 1/2", t="1/2"),)
S_T = 1 - 9 * (1 + 3 * t) / 128                       # s of t by (150)


# the quantities at the double roots of the arm
double = declarer(d, FloatingRootWitness, body=Body.box(a, 1, 2), up=UP_C, density=S_T, roots=DOUBLE)


double("double-root-plus", "x/b at the clipped double root (minimum of the arm, a > b)", ("158",), DRC, z_p)
double("double-roots", "x/b at the clipped double roots (minimum, a > b; maximum, a < b)", ("157", "155", "155-pre"),
       DRC, (z_p, z_m))
double("double-root-n", "(a/b)^2 at the clipped double roots and their product", ("153",), DRC,
       (a_p ** 2, a_m ** 2, a_p ** 2 * a_m ** 2))
double("double-root-n-156", "(a/b)^2 at the clipped double roots", ("156",), DRC, (a_p ** 2, a_m ** 2))
double("double-root-n-156b", "n (1 + 3t)/(1 - t^2) at the clipped double roots", ("156-b",), DRC,
       tuple(e ** 2 * (1 + 3 * t) / (1 - t ** 2) for e in (a_p, a_m)))
S_W = a_p ** 2 + 1 / a_p ** 2
double("double-root-S", "n + 1/n at the clipped double root", ("151", "152", "n-sum", "n-sum-t", "156-S"), DRC, S_W)
double("double-root-S-154", "S - 2, S + 2, S^2 - 4 with S = n + 1/n at the clipped double root", ("154",), DRC,
       (S_W - 2, S_W + 2, S_W ** 2 - 4))
double("double-root-order", "z_+ - z_-, 4 z_+ - 3, 3 - 4 z_- at the clipped double roots", ("minimum",), DRC,
       (z_p - z_m, 4 * z_p - 3, 3 - 4 * z_m))
double("double-root-159", "1 - z_+ at the clipped double root", ("159",), DRC, 1 - z_p)
double("double-root-160", "16 (1 - z_+) at the clipped double root", ("160",), DRC, 16 * (1 - z_p))
