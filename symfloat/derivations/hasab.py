"""Hasáb (KöMaL-type solved problem): a long square prism of density rho floating in water, by the energy method.

Cross-section: the unit square, body coordinates xi in [-1/2, 1/2] (across), eta in [0, 1] (up from the
bottom face); length l >> 1, water density 1.  Heeled by alpha about the long axis, the water line in the
body frame is eta = s0 + xi tg(alpha); a point lies (eta - s0 - xi tg alpha) cos(alpha) above the water.
The potential energy of the system is that of the prism plus that of the displaced water (its weight times
the depth of its centroid: the work to lift it to the surface), both integrated over the section.

The energy is then expanded to second order, the stability condition and its density ranges follow, and
the energy method is shown equal to the metacentric criterion and to Duhamel's criterion (18) of Scheeffer
(section III there): the exact energy of the heeled prism is Scheeffer's V1 n of (13).  The remark's second
position is the prism standing upright (the edges of length l vertical).

Witnesses: exact clipping of the floating prism (``symfloat.engine.floating_witness``): energies from the
clipped immersed part and its two pieces at the lower end of the water line, the sides where the water plane
crosses them, the second-order coefficient interpolated from the clipped potential at small heels, the density
thresholds as zeros of the clipped metacentric height.
"""
from fractions import Fraction
import math

import mpmath
import numpy as np
import sympy as sp

from symfloat import Derivation, Erratum, Holds, Iff, Prediction
from symfloat.engine.floating_witness import (MEASURED, PART, QUANTITIES, SERIES_METHODS, Body, Combined,
                                              FloatingRootWitness, FloatingWitness, Marked, Root, SeriesWitness,
                                              crossing)
from symfloat.engine.witness import Case
from symfloat.model.source import get_source

rho, al, l, g = sp.symbols("varrho alpha l g", positive=True)
xi, et, s0 = sp.symbols("xi eta s_0", real=True)
s, xs, ys, OF = sp.symbols("s x y OF", real=True)
E0h, E0v, E0, E1h, E1v, E2v, E1 = sp.symbols(
    r"E_0^{hasab} E_0^{viz} E_0^{teljes} E_1^{hasab} E_{(1)}^{viz} E_2^{viz} E_1^{teljes}", real=True)
c0, c2, GM, R1, R2, Ru = sp.symbols("c_0 c_2 GM R_1 R_2 R_u", real=True)
OFa, A3, h3, d3 = sp.symbols(r"OF_\alpha A_{IG_1H_1} h_{IG_1H_1} d_{IG_1H_1}", real=True)
T1, V1, e1 = sp.symbols("T_1 V_1 e_1", real=True)
t = sp.tan(al)
half = sp.Rational(1, 2)
DISPLAYS = [line for line in get_source("hasab").text().splitlines() if line.startswith("$$")]

DERIVATION = d = Derivation(
    id="hasab",
    source="hasab",
    title="The long square prism by the energy method",
    locator="solution",
    summary="Delta E = (rho^2 - rho + 1/6) alpha^2 / 4 (per l g): stable for rho < (3 - sqrt 3)/6 or "
            "rho > (3 + sqrt 3)/6, the same condition as the metacentric one and Duhamel's (18).",
    requires=("scheeffer-i-iii",),
    domain={rho: (sp.Rational(1, 20), sp.Rational(19, 20)), al: (sp.Rational(1, 50), sp.Rational(3, 10)),
            l: (2, 10), g: (1, 10), s0: (sp.Rational(1, 10), sp.Rational(9, 10))},
    constraints=(sp.tan(al) < 2 * rho, sp.tan(al) < 2 - 2 * rho),
    assumptions=("water density 1, edge of the square 1, l >> 1 so that only heel about the long axis matters",
                 "the water line cuts the two vertical sides: tg alpha < 2 rho and tg alpha < 2 (1 - rho)",
                 "energies per l g from E_2 on, as the text writes them (see the erratum of E_2)"),
)
depth = (s0 + xi * t - et) * sp.cos(al)      # depth of the body point (xi, eta) below the water line
sec = lambda f, lo, hi: sp.Integral(sp.Integral(f, (et, lo, hi)), (xi, -half, half))

# ---- upright ---------------------------------------------------------------------------------
d.step("draught", (s, rho), "definition", result=s, note="Archimedes: immersed area s * 1 equals the mass rho")
d.step("draught-check", (sec(1, 0, s), rho), "integration", uses=("draught",))
d.step("OF", (OF, half - s), "definition", result=OF, note="G at eta = 1/2, the water at eta = s")
d.step("E0-prism", (E0h, l * g * rho * OF), "definition", result=E0h,
       note="weight l g rho times the height of G above the water")
d.step("E0-water", (E0v, l * g * sec(depth.subs({s0: s, al: 0}), 0, s), l * g * rho ** 2 / 2), "integration",
       result=E0v, note="the displaced water lifted to the surface: weight times depth, element by element")
d.step("E0-total", (E0, E0h + E0v, half * l * g * (rho - rho ** 2)), "algebra", result=E0)
d.quote("s", "solution, upright", DISPLAYS[0], reading=(s, rho))
d.quote("OF", "solution, upright", r"$\overline{OF} = 1/2 - \varrho$", reading=(OF, half - rho))
d.quote("E0-prism", "solution, upright", DISPLAYS[1], reading=(E0h, l * g * rho * (half - rho)))
d.quote("E0-water", "solution, upright", DISPLAYS[2], reading=(E0v, l * g * rho / 2),
        erratum=Erratum("transcription", "medium", r"E_0^{\text{víz}} = l \cdot g \cdot \varrho^2/2",
                        "The displaced water has weight l g rho and its centroid lies rho/2 below the surface, as "
                        "the sentence before the formula says: l g rho * rho/2 = l g rho^2/2. The next line, "
                        "E_0 = 1/2 l g (rho - rho^2), is the sum with rho^2/2 (with rho/2 it would be "
                        "l g rho (1 - rho)), so the author had the square: an exponent lost in the "
                        "transcription (or a misprint; the two cannot be told apart from the text).",
                        corrected_reading=(E0v, l * g * rho ** 2 / 2)))
d.quote("E0-total", "solution, upright", DISPLAYS[3], reading=(E0, half * l * g * (rho - rho ** 2)))

# ---- heeled ------------------------------------------------------------------------------------
d.step("volume-condition", (sec(1, 0, s0 + xi * t), s0), "integration",
       note="the immersed trapezoid has the area of its midline s0: Archimedes keeps s0 = rho")
d.step("sides", (xs, (s0 + xi * t).subs({xi: half, s0: rho})), "definition", result=xs,
       note="x, y: the immersed lengths of the two vertical sides")
d.step("sides-y", (ys, (s0 + xi * t).subs({xi: -half, s0: rho})), "definition", result=ys)
d.step("sides-relations", (sp.Matrix([(xs + ys) / 2, xs - ys]), sp.Matrix([rho, t])), "algebra",
       uses=("sides", "sides-y", "volume-condition"))
dep = depth.subs(s0, rho)
d.step("E1-prism", (E1h, l * g * rho * (-dep.subs({xi: 0, et: half})), l * g * rho * (half - rho) * sp.cos(al)),
       "geometry", result=E1h, note="G = (0, 1/2) lies (1/2 - rho) cos(alpha) above the water")
d.step("E1-water-rectangle", (E1v, l * g * sec(dep, 0, ys), l * g * ys * (rho - ys / 2) * sp.cos(al),
                              l * g * (rho ** 2 / 2 - t ** 2 / 8) * sp.cos(al)),
       "integration", result=E1v, uses=("sides-y",), note="the rectangle ABG1I: 0 <= eta <= y")
d.step("E2-water-triangle", (E2v, l * g * sec(dep, ys, rho + xi * t),
                             l * g * (xs - ys) / 2 * (xs - ys) / 3 * sp.cos(al), l * g * t ** 2 / 6 * sp.cos(al)),
       "integration", result=E2v, uses=("sides", "sides-y"),
       note="the triangle IG1H1: area (x - y)/2, centroid (x - y) cos(alpha)/3 below the water")
d.step("G-height", (OFa, -dep.subs({xi: 0, et: half}), (half - rho) * sp.cos(al)), "geometry", result=OFa,
       note="G = (0, 1/2) above the heeled water line eta = rho + xi tg alpha, measured across it")
d.step("triangle-area", (A3, sec(1, ys, rho + xi * t), (xs - ys) / 2), "integration", result=A3,
       uses=("sides", "sides-y"), note="the triangle IG1H1 between eta = y and the water line")
d.step("triangle-height", (h3, dep.subs({xi: half, et: ys}), (xs - ys) * sp.cos(al)), "geometry", result=h3,
       uses=("sides", "sides-y"), note="its deepest corner (xi = 1/2, eta = y) below the water line")
d.step("triangle-centroid", (d3, sec(dep, ys, rho + xi * t) / sec(1, ys, rho + xi * t), h3 / 3), "integration",
       result=d3, uses=("triangle-area", "triangle-height"),
       note="the centroid lies a third of the height below the water: the medians are cut in thirds")
d.step("E1-total", (E1, E1h + E1v + E2v,
                    l * g * (rho * (1 - rho) / 2 * sp.cos(al) + sp.sin(al) * t / 24)), "algebra", result=E1)
d.quote("x+y", "solution, heeled", DISPLAYS[4], reading=((xs + ys) / 2, rho))
d.quote("x-y", "solution, heeled", DISPLAYS[5], reading=(xs - ys, t))
d.quote("x", "solution, heeled", DISPLAYS[6], reading=(xs, rho + t / 2))
d.quote("y", "solution, heeled", DISPLAYS[7], reading=(ys, rho - t / 2))
d.quote("G-height", "solution, heeled", r"$(1/2 - \varrho) \cos \alpha$", reading=(OFa, (half - rho) * sp.cos(al)))
d.quote("triangle-area", "solution, heeled", r"A háromszög területe $(x - y)/2$", reading=(A3, (xs - ys) / 2))
d.quote("triangle-height", "solution, heeled", r"magassága $(x - y) \cdot \cos \alpha$",
        reading=(h3, (xs - ys) * sp.cos(al)))
d.quote("triangle-centroid", "solution, heeled",
        "Mivel a háromszög súlypontja harmadolja a súlyvonalakat, és az I csúshoz tartozó súlyvonal vízfelületre "
        "merőleges vetülete éppen a fenti magasság", reading=(d3, h3 / 3),
        note="the centroid of the triangle lies a third of the printed height below the water (the E_2 display "
             "carries it as the factor 1/3)")
d.quote("E1-prism", "solution, heeled", DISPLAYS[8], reading=(E1h, l * g * rho * (half - rho) * sp.cos(al)))
d.quote("E1-water", "solution, heeled", DISPLAYS[9],
        reading=(E1v, l * g * ys * (rho - ys / 2) * sp.cos(al), l * g * (rho ** 2 / 2 - t ** 2 / 8) * sp.cos(al)))
d.quote("E2-water", "solution, heeled", DISPLAYS[10],
        reading=(E2v, l * g * (xs - ys) / 2 * sp.Rational(1, 3) * (xs - ys) * sp.cos(al), t ** 2 / 6 * sp.cos(al)),
        erratum=Erratum("misprint", "medium",
                        r"E_2^{\text{víz}} = l g \frac{x - y}{2} \frac{1}{3} (x - y) \cos\alpha = "
                        r"l g \frac{\text{tg}^2 \alpha}{6} \cos \alpha",
                        "The last member drops the factor l g that the first member carries (x - y = tg alpha). "
                        "From here on the text writes energies per l g (E_1 total, Delta E), so the slip is a "
                        "change of unit in the middle of an equation, not a wrong value.",
                        corrected_reading=(E2v, l * g * t ** 2 / 6 * sp.cos(al))))

# ---- second order -------------------------------------------------------------------------------
d.step("c0", (c0, sp.Subs(E1 / (l * g), al, 0), (rho - rho ** 2) / 2), "substitution", result=c0)
d.step("c2", (c2, sp.Subs(sp.Derivative(E1 / (l * g), al, 2), al, 0) / 2,
              sp.Rational(1, 4) * (rho ** 2 - rho + sp.Rational(1, 6))), "series", result=c2,
       note="cos alpha = 1 - alpha^2/2, tg alpha = alpha + O(alpha^3): the coefficient of alpha^2 per l g; "
            "the energy is even in alpha")
d.step("c1", (sp.Subs(sp.Derivative(E1, al), al, 0), 0), "series", note="no linear term: the upright position is "
                                                                     "an equilibrium")
d.quote("E1-total", "solution, second order", DISPLAYS[11],
        reading=(c0 + c2 * al ** 2, half * (rho - rho ** 2) + sp.Rational(1, 4) * (rho ** 2 - rho + sp.Rational(1, 6)) * al ** 2),
        note="per l g, to second order in alpha")
d.quote("Delta-E", "solution, second order", DISPLAYS[12],
        reading=(c2 * al ** 2, sp.Rational(1, 4) * (rho ** 2 - rho + sp.Rational(1, 6)) * al ** 2), note="per l g")
d.quote("tg-approx", "solution, second order", r"$\text{tg } \alpha \cong \alpha$",
        reading=(sp.Subs(sp.Derivative(sp.tan(al), al), al, 0) * al, al),
        note="tg alpha to first order in alpha (the next term is alpha^3/3)")
d.quote("cos-approx", "solution, second order", r"$\cos \alpha \cong 1 - \alpha^2/2$",
        reading=(1 + sp.Subs(sp.Derivative(sp.cos(al), al, 2), al, 0) * al ** 2 / 2, 1 - al ** 2 / 2),
        note="cos alpha to second order in alpha")
quad = rho ** 2 - rho + sp.Rational(1, 6)
d.quote("condition", "solution, stability", DISPLAYS[13], reading=(sp.sign(c2), sp.sign(quad)),
        note="the energy has a minimum at alpha = 0 exactly when its alpha^2 coefficient is positive")
r1, r2 = (3 - sp.sqrt(3)) / 6, (3 + sp.sqrt(3)) / 6
d.step("roots", (sp.Matrix([quad.subs(rho, r1), quad.subs(rho, r2)]), sp.Matrix([0, 0])), "algebra")
d.step("R1", (R1, r1), "definition", result=R1, uses=("roots",), note="the smaller root of rho^2 - rho + 1/6")
d.step("R2", (R2, r2), "definition", result=R2, uses=("roots",), note="the larger root")
d.step("ranges", (sp.sign(quad), sp.sign((rho - R1) * (rho - R2))), "algebra", uses=("roots", "R1", "R2"))
d.quote("ranges", "solution, stability", DISPLAYS[14],
        reading=Iff(quad > 0, (rho < r1) | sp.StrictLessThan(r2, 1, evaluate=False), {rho: (0, 1)}),
        erratum=Erratum("transcription", "medium",
                        r"0 < \varrho < \frac{3 - \sqrt{3}}{6} \varrho_{\text{víz}} \quad \text{vagy} \quad "
                        r"\frac{3 + \sqrt{3}}{6} \varrho_{\text{víz}} < \varrho < \varrho_{\text{víz}}",
                        "The second range has lost its middle '< rho': as transcribed it reads "
                        "'(3 + sqrt 3)/6 rho_viz < rho_viz', a true statement without rho, which would make every "
                        "density stable. The roots of rho^2 - rho + 1/6 are (3 -+ sqrt 3)/6 (printed right) and the "
                        "condition holds outside them; the layout of the first range shows the intended form. "
                        "Lost in the transcription rather than the print (the thresholds are correct).",
                        corrected_reading=Iff(quad > 0, (rho < R1) | (rho > R2), {rho: (0, 1)})),
        note="read as: the condition holds exactly on the printed ranges, for 0 < rho < 1 (rho_viz = 1)")
d.quote("thresholds", "solution, stability",
        r"\frac{3 - \sqrt{3}}{6} \cdot \varrho_{\text{víz}}, \quad \text{vagy} \quad \frac{3 + \sqrt{3}}{6}",
        reading=(sp.Matrix([R1, R2]), sp.Matrix([r1, r2])), note="rho_viz = 1")

# ---- energy = metacentric = Duhamel -------------------------------------------------------------
T1p = l * sp.Integral(xi ** 2, (xi, -half, half))     # waterplane l x 1 about the long axis through its centre
V1p = rho * l
e1p = half - rho / 2                                   # G at 1/2, B at rho/2 above the bottom
d.step("T1", (T1, T1p, l / 12), "integration", result=T1)
d.step("V1", (V1, V1p), "definition", result=V1)
d.step("e1", (e1, sp.Integral(et, (et, 0, 1)) - sp.Integral(et, (et, 0, rho)) / rho, e1p), "integration",
       result=e1, note="SS1: height of G above B")
d.step("GM", (GM, T1 / V1 - e1), "definition", result=GM, note="metacentric height I/V - BG")
d.step("energy-is-13", (E1 / g, T1 * sp.sin(al) * t / 2 + V1 * e1 * sp.cos(al)), "lemma",
       uses=("scheeffer-i-iii:moment-13", "E1-total"),
       note="the exact energy of the heeled prism (per g) is Scheeffer's V1 n of (13): weight times the "
            "height of S above S2")
d.step("energy-metacentric", (2 * l * c2, V1 * GM, l * rho * (1 / (12 * rho) - (1 - rho) / 2)), "algebra",
       uses=("c2", "GM", "T1", "V1", "e1"),
       note="E''(0) = weight x metacentric height: the energy method and the metacentric criterion decide alike "
            "(V1 > 0), and with energy-duhamel both equal Duhamel's (18)")
d.step("energy-duhamel", (2 * l * c2, T1 - V1 * e1), "lemma", uses=("scheeffer-i-iii:energy-curvature", "c2"),
       note="Scheeffer: the curvature of V1 n at 0 is T1 - V1 e1 = V1 (T1/V1 - e1), criterion (18)")
d.quote("energy-principle", "solution", "Stabil egyensúlyi helyzetben a rendszer helyzeti energiája minimális.",
        reading=(sp.sign(c2), sp.sign(GM)),
        note="read for this body: the energy has a minimum at alpha = 0 (c_2 > 0) exactly where the metacentric "
             "criterion calls the position stable (GM > 0): E''(0) = weight x GM (the step energy-metacentric)")

# ---- the statement: a long prism need not be checked about the axis across it -------------------------------
Tp, GMp = sp.symbols("T_p GM_p", real=True)
d.step("T-pitch", (Tp, sp.Integral(xi ** 2, (xi, -l / 2, l / 2)), l ** 3 / 12), "integration", result=Tp,
       note="the waterplane l x 1 about its axis across the prism (parallel to the square end faces)")
d.step("GM-pitch", (GMp, Tp / V1 - e1), "definition", result=GMp, uses=("T-pitch", "V1", "e1"),
       note="metacentric height for pitching: l^2/(12 rho) - (1 - rho)/2")
d.quote("long-prism", "problem", r"Mivel a hasáb hosszú, azaz mivel $l \gg 1$, felesleges foglalkozni az alaplappal "
        "párhuzamos tengely körüli elfordulásokkal",
        reading=Holds(GMp > 0, {l: (2, 1000)}),
        note="read as: for a long prism (here l > 2) the position is stable against pitching at every density, so "
             "only the heel about the long axis needs a study. l^2/(12 rho) > (1 - rho)/2 holds for l^2 > 6 rho "
             "(1 - rho), at most 3/2: every l > sqrt(3/2) = 1.22 will do, and 'l >> 1' is more than is needed")

# ---- remark: the upright prism --------------------------------------------------------------------
GMu = (sp.Rational(1, 12)) / (rho * l) - (l / 2 - rho * l / 2)
d.step("upright-GM", (GMu, (6 * l ** 2 * rho ** 2 - 6 * l ** 2 * rho + 1) / (12 * rho * l)), "algebra",
       note="standing on its square face (edges l vertical): waterplane 1 x 1, I = 1/12, V = rho l, "
            "G at l/2, B at rho l/2")
ru2 = (3 * l + sp.sqrt(9 * l ** 2 - 6)) / (6 * l)
ru1 = (3 * l - sp.sqrt(9 * l ** 2 - 6)) / (6 * l)
d.step("upright-roots", (sp.Matrix([GMu.subs(rho, ru1), GMu.subs(rho, ru2)]), sp.Matrix([0, 0])), "algebra",
       uses=("upright-GM",), note="stable for rho < ru1 or rho > ru2 (l > sqrt(2/3))")
d.step("Ru", (Ru, ru2), "definition", result=Ru, uses=("upright-roots",))
d.quote("remark", "Megjegyzés", DISPLAYS[15], reading=(Ru, (3 * l + 9 * l ** 2 - 6) / (6 * l)),
        erratum=Erratum("transcription", "medium",
                        r"\frac{3l + \sqrt{9l^2 - 6}}{6l} \varrho_{\text{víz}} < \varrho < \varrho_{\text{víz}} "
                        r"(\text{and } 0 < \varrho < \frac{3l - \sqrt{9l^2 - 6}}{6l})",
                        "The position meant is the prism standing upright (the OCR's '1 hosszúságú' is 'l "
                        "hosszúságú': edges of length l vertical; edges of length 1 cannot all be vertical). Its "
                        "metacentric height 1/(12 rho l) - l (1 - rho)/2 vanishes at rho = (3l +- sqrt(9l^2 - 6))/(6l). "
                        "The print lost the radical over 9l^2 - 6 (as printed the bound exceeds 1 for every l > 1, "
                        "no density would be stable) and, as in the main result, the '< rho' of the range; the "
                        "lower range 0 < rho < (3l - sqrt(9l^2 - 6))/(6l) (about 1/(6 l^2)) is not printed.",
                        corrected_reading=(Ru, ru2)),
        note="read as the lower bound of the printed stable range")
d.quote("remark-position", "Megjegyzés", "amikor az 1 hosszúságú élek függőlegesen állnak", reading=(Ru, R2),
        erratum=Erratum("transcription", "medium", r"\text{amikor az } l \text{ hosszúságú élek függőlegesen állnak}",
                        "With the edges of length 1 vertical the prism lies on a face, the position already solved, "
                        "whose upper threshold is (3 + sqrt 3)/6; the condition the remark prints next depends on l "
                        "and is that of the prism standing on its square face, the edges of length l vertical "
                        "(metacentric height 1/(12 rho l) - l (1 - rho)/2). The letter l read as the digit 1, the "
                        "fault the remark's display erratum names in its evidence, booked here at its place.",
                        corrected_reading=(Ru, ru2)),
        note="read as: the remark's position (edges of length 1 vertical) has the thresholds of the prism lying on a "
             "face; its printed condition (the upper threshold Ru) is compared with the lying prism's")


# ---- witnesses: the prism clipped exactly (symfloat.engine.floating_witness) -----------------------------------
# The prism is the box 1 x 1 x l, the y axis of the box up when it lies on a face (eta = y + 1/2); heeled with
# tg alpha the side xi = +1/2 dips.  Marked with its upright up, its immersed part splits at the lower end of the
# water line (the side xi = -1/2) into the rectangle ABG1I and the triangle IG1H1.  Energies: weight times the height
# of the centre of gravity above the water, or weight of a part of the displaced water times its depth (its moment).
M = MEASURED
LYING = Body.box(1, 1, l)
HEELED = Marked.of(LYING, (0, 1, 0))
UPRIGHT_UP, UP = (0, 1, 0), (-sp.tan(al), 1, 0)
PRISM = g * l * rho * M["G above water"]               # the prism's weight l g rho times the height of G
WATER = g * M["immersed volume"] * M["B below water"]  # the displaced water's weight times the depth of B
SIDE_X = crossing(UP, (half, -half, 0), (0, 1, 0))     # the water line on the dipping side, above the bottom
SIDE_Y = crossing(UP, (-half, -half, 0), (0, 1, 0))    # on the rising side
ECASES = tuple(Case({rho: r, l: 4, g: sp.Rational(981, 100), al: sp.atan(q)},
                    label=f"rho = {r}, l = 4, g = 9.81, tg alpha = {q}")
               for r, q in ((sp.Rational(1, 2), sp.Rational(1, 5)), (sp.Rational(1, 10), sp.Rational(1, 10)),
                            (sp.Rational(17, 20), sp.Rational(1, 4))))
UPRIGHT = tuple(Case({rho: r, l: 4, g: sp.Rational(981, 100)}, label=f"rho = {r}, l = 4, g = 9.81, upright")
                for r in (sp.Rational(1, 2), sp.Rational(1, 10), sp.Rational(17, 20)))
for name, description, targets, cases, up, quantity in (
        ("prism-energy-upright", "prism weight times the height of G above the water, clipped prism", ("E0-prism",),
         UPRIGHT, UPRIGHT_UP, PRISM),
        ("prism-energy", "prism weight times the height of G above the water, clipped heeled prism", ("E1-prism",),
         ECASES, UP, PRISM),
        ("water-energy", "displaced water's weight times the depth of the clipped immersed part's centroid",
         ("E0-water",), UPRIGHT, UPRIGHT_UP, WATER),
        ("water-rectangle", "g times the moment of the clipped immersed part below the lower end of the water line",
         ("E1-water",), ECASES, UP, g * M["lower part moment"]),
        ("water-triangle", "g times the moment of the clipped immersed part above the lower end of the water line",
         ("E2-water",), ECASES, UP, g * M["upper part moment"]),
        ("total-energy", "prism and water energies of the clipped upright prism", ("E0-total",), UPRIGHT, UPRIGHT_UP,
         PRISM + WATER),
        ("side-x", "immersed length of the dipping side, clipped plane", ("x",), ECASES, UP, SIDE_X),
        ("side-y", "immersed length of the rising side, clipped plane", ("y",), ECASES, UP, SIDE_Y),
        ("sides-mean", "mean immersed side length, clipped plane", ("x+y",), ECASES, UP, (SIDE_X + SIDE_Y) / 2),
        ("sides-difference", "difference of the immersed side lengths, clipped plane", ("x-y",), ECASES, UP,
         SIDE_X - SIDE_Y)):
    d.witness(FloatingWitness(name, description, targets, cases, body=HEELED, up=up, density=rho, quantity=quantity))
DENSITIES = tuple(Case({rho: r, l: 4}, label=f"rho = {r}, l = 4")          # none at a threshold
                  for r in (sp.Rational(1, 2), sp.Rational(1, 10), sp.Rational(17, 20)))
for name, targets, quantity in (("draught", ("s",), "draught"), ("G-above-water", ("OF",), "G above water"),
                                ("stability-sign", ("condition",), "stability sign"),
                                ("stable-upright", ("ranges",), "stable")):
    d.witness(FloatingWitness(name, f"{QUANTITIES[quantity][0]}, clipped prism lying", targets, DENSITIES,
                              body=LYING, up=UPRIGHT_UP, density=rho, quantity=quantity))
d.witness(FloatingWitness("G-height-heeled", "height of G above the heeled water plane, clipped prism",
                          ("G-height",), ECASES, body=LYING, up=UP, density=rho, quantity="G above water"))
d.witness(FloatingWitness("stability-sign-energy", "sign of the clipped lying prism's metacentric height",
                          ("energy-principle",), DENSITIES, body=LYING, up=UPRIGHT_UP, density=rho,
                          quantity="stability sign"))

# the energy per l g is rho times the height of G above B (weight times it, Scheeffer's V1 n): its value upright and
# its coefficient of psi^2 interpolated at small heels psi
psi = sp.Symbol("psi", real=True)
ENERGY = rho * M["G above B"]
C0 = FloatingWitness("", "", (), (), body=LYING, up=UPRIGHT_UP, density=rho, quantity=ENERGY)
C2 = SeriesWitness("", "", (), (), body=LYING, up=(-sp.sin(psi), sp.cos(psi), 0), density=rho, quantity=ENERGY,
                   series=(psi, 2))
d.witness(Combined("second-order-energy", "c0 + c2 alpha^2: the clipped prism's energy upright and its alpha^2 "
                   "coefficient interpolated at small heels", ("E1-total",), ECASES, parts=(C0, C2),
                   values=(PART[0] + PART[1] * al ** 2,), methods=SERIES_METHODS))
d.witness(Combined("energy-change", "c2 alpha^2: the alpha^2 coefficient of the clipped prism's energy, interpolated "
                   "at small heels", ("Delta-E",), ECASES, parts=(C2,), values=(PART[0] * al ** 2,),
                   methods=SERIES_METHODS))

# the density thresholds: zeros in rho of the clipped metacentric height, lying (heel about the long axis) and
# standing upright (the remark)
def gm_zero(lo, hi, which):
    """The first or last zero in rho of the clipped metacentric height, scanned from lo to hi in 18 steps."""
    return Root.scan("metacentric height", rho, lo, hi, 18, which=which)


d.witness(FloatingRootWitness("thresholds-lying", "zeros of the clipped metacentric height of the lying prism in rho",
                              ("thresholds",), (Case({l: 4}, label="lying prism 1 x 1 x 4"),), body=LYING,
                              up=UPRIGHT_UP, density=rho, quantity=(R1, R2),
                              roots=((R1, gm_zero(sp.Rational(1, 20), sp.Rational(19, 20), "first")),
                                     (R2, gm_zero(sp.Rational(1, 20), sp.Rational(19, 20), "last")))))
d.witness(FloatingRootWitness("threshold-upright", "upper zero of the clipped metacentric height of the upright prism",
                              ("remark", "remark-position"), (Case({l: 2}, label="upright prism, l = 2"),
                                                              Case({l: 5}, label="upright prism, l = 5")),
                              body=LYING, up=(0, 0, 1), density=rho, quantity=Ru,
                              roots=((Ru, gm_zero(sp.Rational(1, 2), sp.Rational(999, 1000), "last")),)))


# ---- predictions: the long square prism lying on a face, and standing upright (the remark) ---------------------
CONDITION = d.evaluator("condition", (rho,), 1)        # sign(rho^2 - rho + 1/6), the printed condition
REMARK = d.evaluator("remark", (l,), 1, corrected=True)  # (3l + sqrt(9l^2 - 6))/(6l), the radical restored


def _lying(rv, up):
    """Heel about the long axis: stable iff rho^2 - rho + 1/6 > 0 (the condition and its thresholds)."""
    return Prediction(("condition", "thresholds", "Delta-E"), up, "stable" if CONDITION(rv) > 0 else "unstable",
                      note="lying on a face (edges l horizontal), heel about the long axis")


def _is_square(poly):
    """True when the polygon is a square: four equal sides and equal diagonals (exact arithmetic)."""
    if len(poly) != 4:
        return False
    d2 = lambda p_, q_: (p_[0] - q_[0]) ** 2 + (p_[1] - q_[1]) ** 2  # noqa: E731
    sides = {d2(poly[k], poly[(k + 1) % 4]) for k in range(4)}
    return len(sides) == 1 and d2(poly[0], poly[2]) == d2(poly[1], poly[3])


def predict(scene):
    """section: a square cross-section, lying on a face; box: a long square prism (two equal edges a, the third
    L with L^2 > 3 a^2/2, so that the pitch about the short axis is stable at every density, as the text assumes),
    lying on a face and standing upright (the remark, read with the radical the scan lost)."""
    rv = Fraction(scene.density)
    if scene.body == "section":
        if not _is_square(scene.polygon):
            return []
        (x0, y0), (x1, y1) = scene.polygon[0], scene.polygon[1]
        n_ = (float(y1 - y0), float(x0 - x1))            # outward normal of the first side (counter-clockwise)
        norm = math.hypot(*n_)
        return [_lying(rv, (n_[0] / norm, n_[1] / norm, 0.0))]
    if scene.body != "box":
        return []
    dims = [Fraction(x_) for x_ in scene.dims]
    for k in range(3):
        i, j = [m_ for m_ in range(3) if m_ != k]
        if dims[i] == dims[j] and dims[k] ** 2 > Fraction(3, 2) * dims[i] ** 2:
            upper = REMARK(float(dims[k] / dims[i]))
            up_lying, up_upright = [0.0] * 3, [0.0] * 3
            up_lying[i], up_upright[k] = 1.0, 1.0
            return [_lying(rv, tuple(up_lying)),
                    Prediction(("remark",), tuple(up_upright), "stable" if float(rv) > upper else "unstable",
                               note="standing upright: the printed stable range (3l + sqrt(9l^2 - 6))/(6l) < rho < 1 "
                                    "(the lower range is not printed)")]
    return []


d.predicts(("section", "box"), predict)


def _stiff_forms():
    """The remark's lower threshold (3l - sqrt(9l^2 - 6))/(6l), l up to 1e6, and the width of the unstable range
    sqrt(9l^2 - 6)/(3l) near the double root l = sqrt(2/3), for the float64 study (docs/numerics.md, §4)."""
    from symfloat.numerics.forms import Form, ends, split
    ls = tuple((float(v),) for v in np.logspace(np.log10(0.82), 6, 40))
    out = [Form("long square prism upright: lower threshold (3l - sqrt(9l^2-6))/(6l)", f"{d.id}/upright-roots",
                ru1, (l,), (("l = 0.82 ... 1e6", ls),),
                lambda lv: 1 / (lv * (3 * lv + math.sqrt(9 * lv * lv - 6))),
                "1 / (l (3l + sqrt(9l^2 - 6))) (product of the roots 1/(6 l^2))")]
    with mpmath.workdps(40):
        r23_hi, r23_lo = split(mpmath.sqrt(mpmath.mpf(2) / 3))
    near23 = tuple((r23_hi * (1 + dl),) for dl in ends())
    out.append(Form("long square prism upright: unstable range ru2 - ru1 = sqrt(9l^2-6)/(3l) near l = sqrt(2/3)",
                    f"{d.id}/upright-roots", sp.sqrt(9 * l ** 2 - 6) / (3 * l), (l,),
                    (("l within 1e-15 ... 1e-1 above sqrt(2/3)", near23),),
                    lambda lv: math.sqrt(9 * ((lv - r23_hi) - r23_lo) * (lv + r23_hi)) / (3 * lv),
                    "sqrt(9 (l - r)(l + r))/(3l), r = sqrt(2/3) a sum of two doubles"))
    return out


d.provides("forms", _stiff_forms)
