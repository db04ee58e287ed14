"""What the Hasáb solution says and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import Derivation, Erratum, Holds, Iff
from symfloat.model.source import get_source
from symfloat.model.symbol_names import symbol
from symfloat.model.vocabulary import Is, StableIff

rho, al, l, g = sp.symbols("varrho alpha l g", positive=True)
xi, et, s0 = sp.symbols("xi eta s_0", real=True)
s, xs, ys, OF = sp.symbols("s x y OF", real=True)
E0h, E0v, E0, E1h, E1v, E2v, E1 = sp.symbols(
    r"E_0^{hasab} E_0^{viz} E_0^{teljes} E_1^{hasab} E_{(1)}^{viz} E_2^{viz} E_1^{teljes}", real=True)
c0, c2, GM, R1, R2, Ru = sp.symbols("c_0 c_2 GM R_1 R_2 R_u", real=True)
OFa = symbol("OF_alpha", r"OF_{\alpha}", real=True)
A3, h3, d3 = sp.symbols("A_{IG_1H_1} h_{IG_1H_1} d_{IG_1H_1}", real=True)
T1, V1, e1 = sp.symbols("T_1 V_1 e_1", real=True)
t = sp.tan(al)
half = sp.Rational(1, 2)
DISPLAYS = [line for line in get_source("hasab").text().splitlines() if line.startswith("$$")]

DERIVATION = d = Derivation(
    id="hasab",
    source="hasab",
    title="The long square prism by the energy method",
    locator="solution",
    summary="Delta E = (rho^2 - rho + 1/6) alpha^2 / 4 (per $l g$): stable for rho < (3 - sqrt 3)/6 or "
            "rho > (3 + sqrt 3)/6, the same condition as the metacentric one and Duhamel's (18).",
    requires=("scheeffer-i-iii",),
    domain={rho: (sp.Rational(1, 20), sp.Rational(19, 20)), al: (sp.Rational(1, 50), sp.Rational(3, 10)),
            l: (2, 10), g: (1, 10), s0: (sp.Rational(1, 10), sp.Rational(9, 10))},
    constraints=(sp.tan(al) < 2 * rho, sp.tan(al) < 2 - 2 * rho),
    assumptions=("water density 1, edge of the square 1, l >> 1 so that only heel about the long axis matters",
                 "the water line cuts the two vertical sides: tg alpha < 2 rho and tg alpha < 2 (1 - rho)",
                 "energies per $l g$ from E_2 on, as the text writes them (see the erratum of E_2)"),
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
                        (r"The displaced water has weight $l g \rho$ and its centroid lies $\rho/2$ below the "
                         r"surface, as the sentence before the formula says: $l g \rho \cdot \rho/2 = l g \rho^2/2$. "
                         r"The next line, $E_0 = \tfrac12 l g (\rho - \rho^2)$, is the sum with $\rho^2/2$ (with "
                         r"$\rho/2$ it would be $l g \rho (1 - \rho)$), so the author had the square: an exponent "
                         "lost in the transcription (or a misprint; the two cannot be told apart from the text)."),
                        corrected_reading=(E0v, l * g * rho ** 2 / 2),
                        objection=("The print may have lost the exponent itself (the kind would then be the "
                                   r"printer's, not the scan's); or $l g \rho/2$ may be meant per unit of displaced "
                                   "weight."),
                        answer=("The sentence before defines the energy as the displaced weight times its centroid's "
                                r"depth, $l g \rho$ times $\rho/2$, and the next line's $\tfrac12 l g (\rho - "
                                r"\rho^2)$ needs the square, so the author had it. A superscript lost is the scan's "
                                "commonest fault in displays and a printer's rarer one, but the two cannot be told "
                                "apart from the text: medium.")))
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
                        ("The last member drops the factor $l g$ that the first member carries ($x - y = "
                         r"\operatorname{tg} \alpha$). From here on the text writes energies per $l g$ ($E_1$ total, "
                         r"$\Delta E$), so the slip is a change of unit in the middle of an equation, not a wrong "
                         "value."),
                        corrected_reading=(E2v, l * g * t ** 2 / 6 * sp.cos(al)),
                        objection=(r"From here on the text writes its energies per $l g$ ($E_1$ total and $\Delta E$ "
                                   "carry no $l g$), so the last member is in the new unit, a convention and not a "
                                   "fault."),
                        answer="The change of unit happens inside one equation: its first member carries $l g$ and its"
                               " last does not, so as printed the two members differ by the factor $l g$. The value in"
                               " the text's later unit is right, which is why the fault changes no result: medium."))

# ---- second order -------------------------------------------------------------------------------
d.step("c0", (c0, sp.Subs(E1 / (l * g), al, 0), (rho - rho ** 2) / 2), "substitution", result=c0)
d.step("c2", (c2, sp.Subs(sp.Derivative(E1 / (l * g), al, 2), al, 0) / 2,
              sp.Rational(1, 4) * (rho ** 2 - rho + sp.Rational(1, 6))), "series", result=c2,
       note="cos alpha = 1 - alpha^2/2, tg alpha = alpha + O(alpha^3): the coefficient of alpha^2 per $l g$; "
            "the energy is even in alpha")
d.step("c1", (sp.Subs(sp.Derivative(E1, al), al, 0), 0), "series", note="no linear term: the upright position is "
                                                                     "an equilibrium")
d.quote("E1-total", "solution, second order", DISPLAYS[11],
        reading=(c0 + c2 * al ** 2, half * (rho - rho ** 2) + sp.Rational(1, 4) * (rho ** 2 - rho + sp.Rational(1, 6)) * al ** 2),
        note="per $l g$, to second order in alpha")
d.quote("Delta-E", "solution, second order", DISPLAYS[12],
        reading=(c2 * al ** 2, sp.Rational(1, 4) * (rho ** 2 - rho + sp.Rational(1, 6)) * al ** 2), note="per $l g$")
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
                        (r"The second range has lost its middle '$< \rho$': as transcribed it reads '$(3 + \sqrt3)/6\ "
                         r"\rho_{\text{viz}} < \rho_{\text{viz}}$', a true statement without $\rho$, which would make "
                         r"every density stable. The roots of $\rho^2 - \rho + 1/6$ are $(3 \mp \sqrt3)/6$ (printed "
                         "right) and the condition holds outside them; the layout of the first range shows the "
                         "intended form. Lost in the transcription rather than the print (the thresholds are "
                         "correct)."),
                        corrected_reading=Iff(quad > 0, (rho < R1) | (rho > R2), {rho: (0, 1)}),
                        objection=(r"'$(3 + \sqrt3)/6\ \rho_{\text{viz}} < \rho_{\text{viz}}$' may be the author's "
                                   "elliptic style, the variable being understood from the first range."),
                        answer=(r"The first range writes its variable ('$0 < \rho < \dots$'), and the condition to be "
                                r"solved, $\rho^2 - \rho + 1/6 > 0$, has $\rho$ on both sides of its upper root: the "
                                r"range needs '$< \rho <$'. As printed the second statement is true for every density "
                                "and says nothing. Print or scan cannot be told apart for a lost middle term: medium.")),
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
       note="$E''(0)$ = weight times metacentric height: the energy method and the metacentric criterion decide alike "
            "(V1 > 0), and with energy-duhamel both equal Duhamel's (18)")
d.step("energy-duhamel", (2 * l * c2, T1 - V1 * e1), "lemma", uses=("scheeffer-i-iii:energy-curvature", "c2"),
       note="Scheeffer: the curvature of V1 n at 0 is T1 - V1 e1 = V1 (T1/V1 - e1), criterion (18)")
d.quote("energy-principle", "solution", "Stabil egyensúlyi helyzetben a rendszer helyzeti energiája minimális.",
        reading=(sp.sign(c2), sp.sign(GM)),
        note="read for this body: the energy has a minimum at alpha = 0 (c_2 > 0) exactly where the metacentric "
             "criterion calls the position stable (GM > 0): $E''(0)$ = weight times GM (the step energy-metacentric)")

# ---- the statement: a long prism need not be checked about the axis across it -------------------------------
Tp, GMp = sp.symbols("T_p GM_p", real=True)
d.step("T-pitch", (Tp, sp.Integral(xi ** 2, (xi, -l / 2, l / 2)), l ** 3 / 12), "integration", result=Tp,
       note="the waterplane l × 1 about its axis across the prism (parallel to the square end faces)")
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
       note="standing on its square face (edges l vertical): waterplane 1 × 1, I = 1/12, V = rho l, "
            "G at l/2, B at rho l/2")
ru2 = (3 * l + sp.sqrt(9 * l ** 2 - 6)) / (6 * l)
ru1 = (3 * l - sp.sqrt(9 * l ** 2 - 6)) / (6 * l)
d.step("upright-roots", (sp.Matrix([GMu.subs(rho, ru1), GMu.subs(rho, ru2)]), sp.Matrix([0, 0])), "algebra",
       uses=("upright-GM",), note="stable for rho < ru1 or rho > ru2 (l > sqrt(2/3))")
d.step("Ru", (Ru, ru2), "definition", result=Ru, uses=("upright-roots",))
d.quote("remark", "Megjegyzés", DISPLAYS[15], reading=(Ru, (3 * l + 9 * l ** 2 - 6) / (6 * l)),
        erratum=Erratum("transcription", "low",
                        r"\frac{3l + \sqrt{9l^2 - 6}}{6l} \varrho_{\text{víz}} < \varrho < \varrho_{\text{víz}} "
                        r"(\text{and } 0 < \varrho < \frac{3l - \sqrt{9l^2 - 6}}{6l})",
                        ("The position meant is the prism standing upright (the OCR's '1 hosszúságú' is 'l "
                         "hosszúságú': edges of length $l$ vertical; edges of length $1$ cannot all be vertical). "
                         r"Its metacentric height $1/(12 \rho l) - l (1 - \rho)/2$ vanishes at $\rho = (3l \pm "
                         r"\sqrt{9l^2 - 6})/(6l)$. The print lost the radical over $9l^2 - 6$ (as printed the bound "
                         "exceeds $1$ for every $l > 1$, no density would be stable) and, as in the main result, the "
                         r"'$< \rho$' of the range; the lower range $0 < \rho < (3l - \sqrt{9l^2 - 6})/(6l)$ (about "
                         "$1/(6 l^2)$) is not printed."),
                        corrected_reading=(Ru, ru2),
                        objection=(r"Two changes (a radical and the middle '$< \rho$') and a range left unprinted are "
                                   "more than one slip of the scan: the author may have written the remark "
                                   "carelessly, a fault of the print."),
                        answer=(r"The same middle '$< \rho$' is lost in the main result above, a systematic loss of "
                                "this transcription, and a radical over a long expression is often dropped by OCR; "
                                "but the remark also omits the lower range, which no scan loses. Kind and correction "
                                "both rest on two changes: lowered to low.")),
        note="read as the lower bound of the printed stable range")
d.quote("remark-position", "Megjegyzés", "amikor az 1 hosszúságú élek függőlegesen állnak", reading=(Ru, R2),
        erratum=Erratum("transcription", "medium", r"\text{amikor az } l \text{ hosszúságú élek függőlegesen állnak}",
                        ("With the edges of length $1$ vertical the prism lies on a face, the position already "
                         r"solved, whose upper threshold is $(3 + \sqrt{3})/6$; the condition the remark prints next "
                         "depends on $l$ and is that of the prism standing on its square face, the edges of length "
                         r"$l$ vertical (metacentric height $1/(12 \rho l) - l (1 - \rho)/2$). The letter $l$ read as "
                         "the digit $1$, the fault the remark's display erratum names in its evidence, booked here "
                         "at its place."),
                        corrected_reading=(Ru, ru2),
                        objection="'az 1 hosszúságú élek függőlegesen' may be right as printed: the prism turned so "
                                  "that edges of length 1 stand vertical is a position of its own.",
                        answer=("With edges of length $1$ vertical the long prism lies on a side face, the position "
                                r"the solution has just treated, whose threshold is $(3 + \sqrt{3})/6$ and does not "
                                "depend on $l$; the condition the remark prints depends on $l$, which is the prism "
                                "standing on its square face with the edges of length $l$ vertical.")),
        note="read as: the remark's position (edges of length 1 vertical) has the thresholds of the prism lying on a "
             "face; its printed condition (the upper threshold Ru) is compared with the lying prism's")

# ---- the words: the quantities the solution names, by their definitions ---------------------------------------
zG, zB = sp.symbols("z_G z_B", real=True)
d.step("prism-centroid-height", (zG, sec(-dep, 0, 1) / sec(1, 0, 1), (half - rho) * sp.cos(al)), "integration",
       result=zG, note="the height of the prism's centroid above the water line: the mean height of the square's "
                       "points above it (the prism heeled by alpha, draught rho)")
d.step("immersed-centroid-depth", (zB, sec(dep, 0, rho + xi * t) / sec(1, 0, rho + xi * t),
                                   (rho / 2 + t ** 2 / (24 * rho)) * sp.cos(al)), "integration", result=zB,
       note="the depth of the immersed part's centroid below the water line: the mean depth of its points")
d.defines("centre of gravity", zG)
d.defines("centre of buoyancy", zB)
d.defines("energy", E1)
d.defines("stability", GM)
UPRIGHT = {al: 0}
d.says("OF-words", "solution, upright", "Így a súlypont távolsága a vízszinttől", "súlypont",
       Is(half - rho, at=UPRIGHT), note="Read as: upright, the prism's centroid lies 1/2 - rho above the water.")
d.says("immersed-centroid-words", "solution, upright",
       "a kiszorított víz súlya szorozva a bemerülő rész súlypontjának a felszíntől mért távolságával",
       "bemerülő rész súlypontjának", Is(E0v / (l * g * rho), at=UPRIGHT),
       note="Read as: the displaced water's energy E_0 is its weight l g rho times the depth of the immersed part's "
            "centroid below the surface, so that depth is E_0 / (l g rho); E_0 as derived (l g rho^2/2, the erratum "
            "of the next display).")
d.says("E0-words", "solution, upright", "Azaz a teljes helyzeti energia kezdetben:", "teljes helyzeti energia",
       Is(half * l * g * (rho - rho ** 2), at=UPRIGHT),
       note="Read as: the total energy of the upright position is the display that follows.")
d.says("G-height-words", "solution, heeled", "Az ábra alapján a súlypont távolsága a víz felszínétől", "súlypont",
       Is((half - rho) * sp.cos(al)),
       note="Read as: heeled by alpha, the prism's centroid lies (1/2 - rho) cos alpha above the water, the value "
            "printed next.")
# an equilibrium: the energy stationary at alpha = 0, which the upright prism's is at every density, its energy being
# even in alpha (the same for a heel alpha to either side)
stationary = sp.Eq(sp.Subs(E1, al, -al), E1, evaluate=False)
d.quote("equilibrium-condition", "solution, stability",
        "Az egyensúlyi feltétel, hogy tetszőlegesen kis α -ra növekedjék az energia",
        reading=Iff(stationary, quad > 0, {rho: (0, 1)}),
        erratum=Erratum("claim", "low", r"\text{A stabil egyensúly feltétele, hogy tetszőlegesen kis } \alpha"
                                        r"\text{-ra növekedjék az energia}",
                        (r"An equilibrium is a position where the energy is stationary, $dE/d\alpha = 0$; the upright "
                         r"prism is one at every density, its energy having no term linear in $\alpha$ (step c1: "
                         r"$\Delta E = \tfrac14 (\rho^2 - \rho + \tfrac16)\alpha^2$ is even in $\alpha$). That the "
                         r"energy increase for every small $\alpha$, $\rho^2 - \rho + 1/6 > 0$, is the condition of "
                         r"a stable equilibrium, the minimum the solution names two paragraphs before ('Stabil "
                         r"egyensúlyi helyzetben a rendszer helyzeti energiája minimális'). As written the sentence "
                         r"calls it the condition of equilibrium: at $\rho = \tfrac12$ the upright prism is in "
                         r"equilibrium, unstable ($\Delta E = -\tfrac{1}{48}\alpha^2$). A word of the solution, not "
                         "of the transcription."),
                        corrected_reading=d.reads("stabil", StableIff(quad > 0, {rho: (0, 1)})),
                        objection=("'Az egyensúlyi feltétel' is short for the condition of the stable equilibrium "
                                   "named two paragraphs before, and the sentence says at once what it means: the "
                                   "energy increases for every small heel. No reader takes it for the condition "
                                   "that an equilibrium exist."),
                        answer=("The words name the equilibrium, which the upright prism has at every density; the "
                                "condition that follows is its stability's. The sentence's own gloss shows what "
                                "was meant, so the fault is one of naming, not of mathematics: low.")),
        note="Read as the words say: the upright position is an equilibrium (the energy stationary, the same for a "
             "heel to either side) exactly when the energy increases for every small alpha, which is rho^2 - rho + "
             "1/6 > 0 (the display that follows; 'condition'). The correction is read through the vocabulary: the "
             "stable equilibrium, the metacentric height positive, exactly there.")
