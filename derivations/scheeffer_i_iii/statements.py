"""What Scheeffer's sections I-III say and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import Derivation, Eq, Erratum, Iff
from symfloat.model.claim import as_printed
from symfloat.model.symbol_names import symbol
from symfloat.model.vocabulary import GrowsWith, Is


phi = sp.Symbol("varphi", positive=True)
V1, V3, V4 = sp.symbols("V_1 V_3 V_4", positive=True)
e1 = sp.Symbol("e_1", real=True)
u, v, m, n, e, k = sp.symbols("u v m n e k", real=True)
u3, u4, v3, v4 = sp.symbols("u_3 u_4 v_3 v_4", positive=True)
x3, x4, y3, y4 = sp.symbols("x_3 x_4 y_3 y_4", positive=True)
P1, P2, Hh = sp.symbols("P_1 P_2 H", positive=True)
a, a0, c0, h0 = sp.symbols("a a_0 c_0 h_0", real=True)
x, s, eta = sp.symbols("x s eta", real=True)
T1 = sp.Symbol("T_1", positive=True)
J3, J4 = (symbol(f"int_x2_df_{i}", rf"\int_{i}{{x^2df}}", positive=True) for i in (3, 4))   # over the wedges V3, V4
Mx3, My3, Mx4, My4 = (symbol(name, tex, real=True) for name, tex in (
    ("V_3x_3", r"V_{3} x_{3}"), ("V_3y_3", r"V_{3} y_{3}"), ("V_4x_4", r"V_{4} x_{4}"), ("V_4y_4", r"V_{4} y_{4}")))
tg = sp.tan(phi)

DERIVATION = d = Derivation(
    id="scheeffer-i-iii",
    source="scheeffer",
    title="Equilibrium, the righting moment of a prismatic body, Duhamel's criterion",
    locator="I-III",
    summary="V1 m = sin(phi) {(1 + tg^2(phi)/2) T1 - V1 e1} for a body prismatic at the waterline, the axis "
            "through the centroid of the old waterplane; for small phi m = phi (T1/V1 - e1), stable iff "
            "T1/V1 - e1 > 0 (Duhamel), for every body.",
    domain={phi: (sp.Rational(1, 20), 1), V1: (1, 10), e1: (-2, 3), V3: (sp.Rational(1, 10), 3),
            u3: (sp.Rational(1, 10), 3), u4: (sp.Rational(1, 10), 3), v3: (sp.Rational(1, 10), 3),
            v4: (sp.Rational(1, 10), 3), P1: (sp.Rational(1, 2), 4), P2: (sp.Rational(1, 2), 4), Hh: (1, 3),
            a0: (sp.Rational(1, 10), 1), c0: (-1, 1), h0: (0, 2), x: (0, 3)},
    constraints=(a0 < Hh,),
    assumptions=(
        "homogeneous body of volume-weight ratio such that the submerged volume V1 is constant (water of "
        "specific weight 1, the water level unchanged)",
        "0 < phi < pi/2 (sampled in [1/20, 1])",
        "section II: the body is prismatic between the first and the last waterplane (AA1, BB1 perpendicular "
        "to A1B1); the concrete waterplane is a trapezoid with parallel sides P1, P2 > 0 parallel to the "
        "rotation axis at distance H apart (P1 = P2: rectangle; triangles are the limit P2 -> 0 and are "
        "used in the witnesses)",
        "T1 = int x^2 df of the trapezoid ranges over all positive values, so the identities of (12)-(18), "
        "which are linear in T1, are checked in full generality",
        "Fig. 3 (lost): the wedges lie above S (u3, u4 are the absolute values of their negative u "
        "coordinates), as the printed signs of (6) require",
    ),
)

# ---- I. equilibrium, (2), (5), (6), (7) --------------------------------------------------------
d.quote("equilibrium", "(1)", "Hieraus erhält man zwei Bedingungsgleichungen für das Gleichgewicht. (1",
        lost="the two equations (1) (static moments of the submerged part about two vertical planes through S "
             "equal to zero) are not displayed; only '(1' survives")

d.step("buoyancy-moment-v", Eq(v, (V1 * 0 - V3 * (-v4) + V3 * v3) / V1), "definition", result=v,
       note="moment theorem across the axis: new submerged part = old (S1 on the axis) - emerged wedge "
            "(S4 at v = -v4) + immersed wedge (S3 at v = +v3)")
d.step("buoyancy-moment-u", Eq(u, (V1 * e1 - V3 * (-u4) + V3 * (-u3)) / V1), "definition", result=u,
       note="moment theorem along the axis (u downwards from S): S1 at u = e1, S3 and S4 above S at "
            "u = -u3, -u4 (Fig. 3)")
d.step("moments-6-raw", (sp.Matrix([V1 * v, V1 * u]), sp.Matrix([V3 * (v3 + v4), V1 * e1 - V3 * (u3 - u4)])),
       "algebra", uses=("buoyancy-moment-v", "buoyancy-moment-u"))
d.step("e-def", Eq(e, v3 + v4), "definition", result=e, note="e = v3 + v4 = EF")
d.step("k-def", Eq(k, u3 - u4), "definition", result=k, note="k = u3 - u4 = S3F + S4E")
d.step("moments-6", (sp.Matrix([V1 * v, V1 * u]), sp.Matrix([V3 * e, V1 * e1 - V3 * k])), "algebra",
       uses=("moments-6-raw", "e-def", "k-def"))

ev = sp.Matrix([sp.cos(phi), sp.sin(phi)])     # body direction v in the world frame (X, Y down)
eu = sp.Matrix([-sp.sin(phi), sp.cos(phi)])    # body axis (down) in the world frame
d.step("frame", (sp.Matrix([ev.dot(ev), eu.dot(eu), ev.dot(eu), eu[1]]), sp.Matrix([1, 1, 0, sp.cos(phi)])),
       "geometry", note="the body frame (v, u) is orthonormal and its axis SS1 makes the angle phi with the "
                        "vertical SL")
S2w = v * ev + u * eu
d.step("m-def", Eq(m, S2w[0]), "definition", result=m, note="m = SA: horizontal coordinate of S2")
d.step("n-def", Eq(n, S2w[1]), "definition", result=n, note="n = AS2: depth of S2 below S")
d.step("rotation-5", (sp.Matrix([m, n]), sp.Matrix([v * sp.cos(phi) - u * sp.sin(phi),
                                                    v * sp.sin(phi) + u * sp.cos(phi)])),
       "geometry", uses=("frame", "m-def", "n-def"))
rhs7 = sp.Matrix([V3 * e * sp.cos(phi) + V3 * k * sp.sin(phi) - V1 * e1 * sp.sin(phi),
                  V3 * e * sp.sin(phi) - V3 * k * sp.cos(phi) + V1 * e1 * sp.cos(phi)])
d.step("moments-7", (sp.Matrix([V1 * m, V1 * n]), rhs7), "substitution", uses=("rotation-5", "moments-6"))
# the couple: buoyancy V1 upwards (-Y) at S2, weight V1 downwards at S; its moment about S in the sense
# that turns X into Y (the sense of the heel) is X F_Y - Y F_X; restoring is the opposite sense
torque = as_printed(lambda: m * (-V1) - n * 0)
d.step("couple", (-torque, V1 * m), "algebra", uses=("m-def",),
       note="the moment of the couple against the heel is V1 m: positive m turns the body back")
# the quantities the text names in words (symfloat/model/vocabulary.json), by the formulas that define them here:
# the Kraftmoment / Drehungsmoment by the moment of the couple against the heel, the stability by the second
# variation of the potential, T1 - V1 e1 = V1 (T1/V1 - e1) (step energy-curvature, (16), (18))
d.defines("righting moment", -torque)
d.defines("stability", T1 - V1 * e1)

d.quote("equilibrium-moments", "I",
        "Es müssen also die statischen Momente des eintauchenden Teils für zwei durch  $S$  gelegte Vertikalebene "
        "gleich Null sein.", reading=(sp.Subs(V1 * m, phi, 0), 0),
        note="in the plane of the drawing: the moment V1 m of the submerged part about the vertical plane through S "
             "along the rotation axis vanishes in the upright position (the second plane lies in the drawing)")
d.quote("stability-2", "(2)", r"$$V_1 m > 0. \quad (2)$$", reading=as_printed(lambda: (sp.sign(-torque), sp.sign(V1 * m))),
        note="read as: the couple restores (its moment against the heel is positive) exactly when V1 m > 0")
d.quote("turned-back", "I",
        "In dem Falle, den Fig. 1 darstellt, wird der Körper offenbar in seine erste Gleichgewichtslage zurückgedreht, "
        "sein Gleichgewicht war also ein stabiles", reading=as_printed(lambda: (sp.sign(-torque), sp.sign(V1 * m))),
        note="the couple turns the body back (its moment against the heel positive) exactly when m > 0")
d.quote("M-side", "I", "Läge  $M$  aber auf der entgegengesetzten Seite von  $S$ , so wäre  $m$  negativ",
        reading=(sp.sign(sp.Subs(sp.Derivative(m, phi), phi, 0)), sp.sign(T1 / V1 - e1)),
        note="for small phi m = phi SM (M the metacentre on the axis, SM = T1/V1 - e1, III): m has the sign of the "
             "height of M above S")
d.says("couple-words", "I", "Das Kraftmoment ist nun  $V_1 m$ , also die Bedingung für die Stabilität", "Kraftmoment",
       Is(V1 * m), note="Read as: the moment of the couple of weight and buoyancy against the heel is V1 m.")
d.quote("labile-words", "I", "Sein Gleichgewicht wäre dann labil.",
        reading=as_printed(lambda: (sp.sign(-torque), sp.sign(V1 * m))),
        note="with m < 0 the moment of the couple against the heel, V1 m, is negative: the couple turns the body "
             "further away, the equilibrium is labile")
GX = sp.Symbol("G_X", real=True)               # the point G of the print, which section I never introduces
d.domain[GX] = (-2, 2)
d.quote("GL-parallel", "I", r"$GL \parallel MS_2$", reading=(GX, S2w[0] - m),
        note="read as: the parallel to the vertical MS2 is drawn through G, and it is the line of action SL of the "
             "weight named next (abscissa X = 0 of S in the world frame)",
        erratum=Erratum("transcription", "medium", r"SL \parallel MS_2",
                        "The weight acts at the centre of gravity S, and the same sentence goes on 'die in der Richtung "
                        "SL wirkende Schwerkraft'; the next paragraph takes 'die Achsen S L und S A' as the frame of "
                        "m and n. Section I introduces no point G (S, S1, S2, M, A, N, L, C, D only): the line "
                        "drawn parallel to MS2 is SL, and a parallel through any other point misses the line of "
                        "action of the weight. An S read as G by the scan is likelier than a compositor's slip "
                        "(medium).",
                        corrected_reading=(S2w[0] - m, 0),
                        objection="G may be a point of the lost Fig. 1, the letter often used for the centre of "
                                  "gravity, so that GL is the line of the weight as the figure draws it.",
                        answer="Section I calls the centre of gravity S and introduces no G, and the same sentence "
                               "speaks of 'die in der Richtung SL wirkende Schwerkraft', the next paragraph of 'die "
                               "Achsen S L und S A'. S read as G is a confusion of the scan, but a compositor's slip"
                               " is left open: medium."))
d.quote("S2D", "I", r"$S_2 D (= m) \perp S L$", reading=(m, v * sp.cos(phi) - u * sp.sin(phi)),
        note="S2D: the horizontal distance of S2 from the vertical SL through S, the X coordinate of S2")
d.quote("rotation-5", "(5)",
        r"$$\begin{aligned} m &= v \cos \varphi - u \sin \varphi \\ n &= v \sin \varphi + u \cos \varphi "
        r"\end{aligned} \quad (5)$$",
        reading=(sp.Matrix([m, n]), sp.Matrix([v * sp.cos(phi) - u * sp.sin(phi), v * sp.sin(phi) + u * sp.cos(phi)])))
SS1 = e1 * eu                                  # the floating axis from S to S1 (S1 at u = e1)
d.quote("fig3-labels", "I, Fig. 3",
        "Schwimmachse  $S S$ , senkrecht zur Richtung der Drehungsachse gelegte (Vertikal-) Ebene dar.  "
        "$A, B$ , sei die alte,  $A B$  die neue Wasserlinie",
        reading=(sp.Matrix([SS1.dot(SS1), ev.dot(sp.Matrix([1, 0]))]), sp.Matrix([0, 1])),
        note="read as the squared length of the axis named (S S: from S to S) and the cosine of the angle between "
             "the lines named old and new waterline (both A B: one line); the old waterline A1B1 is fixed in the "
             "body across the axis (direction v), the new one horizontal",
        erratum=Erratum("transcription", "high",
                        r"\text{die durch die Schwimmachse } S S_1 \ldots \; A_1 B_1 \text{ sei die alte, } A B "
                        r"\text{ die neue Wasserlinie}",
                        ("The scan read the subscript 1 as a comma twice. '$S S$ ,' names no axis: the floating axis "
                         "is $S S_1$ (section I: 'Die Schwimmachse $S S_1$', '$S S_1$ werde mit $e_1$ ... "
                         "bezeichnet'); '$A$, $B$, sei die alte, $A B$ die neue Wasserlinie' gives the old and the "
                         r"new waterline the same letters, which the rotation by $\varphi$ separates, while section "
                         "II ('wie in Fig. 3') writes '$A B$ die neue, $A_1 B_1$ die alte Wasserlinie'. A comma for "
                         "a subscript 1 after a letter is the scan's, not the printer's (high)."),
                        corrected_reading=(sp.Matrix([SS1.dot(SS1), ev.dot(sp.Matrix([1, 0]))]),
                                           sp.Matrix([e1 ** 2, sp.cos(phi)])),
                        objection="The commas may be the print's punctuation: 'A, B,' a list of the two points, 'S "
                                  "S,' the axis named by S and a point of the figure.",
                        answer=("Read so, the old and the new waterline both are $A B$, which the rotation by "
                                r"$\varphi$ separates; section II ('wie in Fig. 3') writes '$A B$ die neue, $A_1 B_1$ "
                                "die alte Wasserlinie', and the floating axis is $S S_1$ throughout section I. A "
                                "subscript 1 read as a comma is the scan's.")))
d.quote("archimedes-3-4", "I",
        "Nach dem Archimedischen Gesetz muss das Volumen des neu eintauchenden Körperteils gleich dem Volumen des neu "
        "heraustretenden sein.", reading=(V3, V4), note="the wedge volumes of section II, integrated over the waterplane")
d.quote("moments-raw", "I",
        r"$$\begin{aligned} V_1 v &= V_3 (v_3 + v_4) \\ V_1 u &= V_1 e_1 - V_3 (u_3 - u_4). \end{aligned}$$",
        reading=(sp.Matrix([V1 * v, V1 * u]), sp.Matrix([V3 * (v3 + v4), V1 * e1 - V3 * (u3 - u4)])))
d.quote("moments-6", "(6)",
        r"$$\begin{aligned} V_1 v &= V_3 e \\ V_1 u &= V_1 e_1 - V_3 k \end{aligned} \quad (6)$$",
        reading=(sp.Matrix([V1 * v, V1 * u]), sp.Matrix([V3 * e, V1 * e1 - V3 * k])))
d.quote("moments-7", "(7)",
        r"$$\begin{aligned} V_1 m &= V_3 e \cos \varphi + V_3 k \sin \varphi - V_1 e_1 \sin \varphi \\ V_1 n &= "
        r"V_3 e \sin \varphi - V_3 k \cos \varphi + V_1 e_1 \cos \varphi. \end{aligned} \quad (7)$$",
        reading=(sp.Matrix([V1 * m, V1 * n]), rhs7))

d.says("turning-moment-7", "(7)", "Die erste dieser Gleichungen giebt das Drehungsmoment an.", "Drehungsmoment",
       Is(rhs7[0]), note="Read as: the moment of the couple against the heel is the right side of the first line of "
                         "(7).")

# ---- II. the prismatic body: element integrals -------------------------------------------------
d.step("element-volume", (sp.Integral(1, (eta, 0, x * tg)), x * tg), "integration",
       note="the prismatic element PQ over df at distance x from the axis has height y = x tg phi")
d.step("element-moment-y", (sp.Integral(eta, (eta, 0, x * tg)), x ** 2 * tg ** 2 / 2), "integration",
       note="its static moment about the old waterplane, per unit df: df y y/2")
d.step("element-moment-x", (sp.Integral(x, (eta, 0, x * tg)), x ** 2 * tg), "integration",
       note="its static moment about the plane through the axis perpendicular to the old waterplane: df y x")

W = P1 + (P2 - P1) * s / Hh       # length of the waterplane chord at distance s from the side P1
area = sp.Integral(W, (s, 0, Hh))
d.step("trapezoid-area", (area, Hh * (P1 + P2) / 2), "integration")
sbar = Hh * (P1 + 2 * P2) / (3 * (P1 + P2))
d.step("trapezoid-centroid", (sp.Integral(s * W, (s, 0, Hh)) / area, sbar), "integration")


def wedge(f, axis):
    """The immersed (3) and emerged (4) wedge integrals of the element quantity f(x, eta) for the axis at
    s = axis: the element over the chord at s has height |s - axis| tg phi."""
    g3 = sp.Integral(sp.Integral(f.subs(x, s - axis), (eta, 0, (s - axis) * tg)) * W, (s, axis, Hh))
    g4 = sp.Integral(sp.Integral(f.subs(x, axis - s), (eta, 0, (axis - s) * tg)) * W, (s, 0, axis))
    return g3, g4


V3g, V4g = wedge(sp.Integer(1), a0)
d.step("volume-balance", (V3g - V4g, tg * (sp.Integral((s - a0) * W, (s, a0, Hh)) - sp.Integral((a0 - s) * W, (s, 0, a0))),
                          tg * sp.Integral((s - a0) * W, (s, 0, Hh)), tg * area * (sbar - a0)),
       "integration", uses=("element-volume", "trapezoid-area", "trapezoid-centroid"),
       note="for an axis at any distance a0 from the side P1: V3 - V4 = tg phi (int_3 x df - int_4 x df) = "
            "tg phi * area * (centroid - a0), so V3 = V4 (Archimedes) only for a0 at the centroid")
d.step("axis", Eq(a, sbar), "definition", result=a, uses=("volume-balance",),
       note="the rotation axis: the only root a0 of V3 = V4, the centroid line of the old waterplane")
V3i, V4i = wedge(sp.Integer(1), a)
Mx3i, Mx4i = wedge(x, a)
My3i, My4i = wedge(eta, a)


# the closed forms of the wedges' integrals over the two parts of the waterplane, with the axis at its centroid
# (the steps V3, V4, Mx3 ... J4 below integrate and prove them)
K3c = K4c = Hh ** 2 * (P1 + 2 * P2) ** 2 * (2 * P1 + P2) ** 2 / (81 * (P1 + P2) ** 3)
J3c = Hh ** 3 * (2 * P1 + P2) ** 3 * (2 * P1 ** 2 + 11 * P1 * P2 + 11 * P2 ** 2) / (972 * (P1 + P2) ** 4)
J4c = Hh ** 3 * (P1 + 2 * P2) ** 3 * (11 * P1 ** 2 + 11 * P1 * P2 + 2 * P2 ** 2) / (972 * (P1 + P2) ** 4)
T1c = Hh ** 3 * (P1 ** 2 + 4 * P1 * P2 + P2 ** 2) / (36 * (P1 + P2))
d.step("V3", (V3, V3i, tg * K3c), "integration", result=V3, uses=("element-volume", "axis"),
       note="immersed wedge: the sum of the elements over part 3 of the waterplane")
d.step("V4", (V4, V4i, tg * K4c), "integration", result=V4, uses=("element-volume", "axis"),
       note="emerged wedge: the sum of the elements over part 4")
d.step("archimedes", (V3, V4), "algebra", uses=("V3", "V4"))
for sym, val, clo, nm, el in ((Mx3, Mx3i, tg * J3c, "Mx3", "element-moment-x"),
                              (My3, My3i, tg ** 2 / 2 * J3c, "My3", "element-moment-y"),
                              (Mx4, Mx4i, tg * J4c, "Mx4", "element-moment-x"),
                              (My4, My4i, tg ** 2 / 2 * J4c, "My4", "element-moment-y")):
    d.step(nm, (sym, val, clo), "integration", result=sym, uses=(el, "axis"),
           note="static moment of the wedge as the sum of the moments of its prismatic elements")
d.step("J3", (J3, sp.Integral((s - a) ** 2 * W, (s, a, Hh)), J3c), "integration", result=J3, uses=("axis",))
d.step("J4", (J4, sp.Integral((a - s) ** 2 * W, (s, 0, a)), J4c), "integration", result=J4, uses=("axis",))
d.step("T1", (T1, sp.Integral((s - a) ** 2 * W, (s, 0, Hh)), T1c), "integration", result=T1, uses=("axis",),
       note="moment of inertia of the old waterplane about the rotation axis (density 1)")
d.step("T1-parts", (T1, J3 + J4), "algebra", uses=("T1", "J3", "J4"))
d.step("wedge-moments-3", (sp.Matrix([My3, Mx3]), sp.Matrix([tg ** 2 / 2 * J3, tg * J3])), "integration",
       uses=("element-moment-y", "element-moment-x", "My3", "Mx3", "J3"))
d.step("wedge-moments-4", (sp.Matrix([My4, Mx4]), sp.Matrix([tg ** 2 / 2 * J4, tg * J4])), "integration",
       uses=("element-moment-y", "element-moment-x", "My4", "Mx4", "J4"))
# the wedge centroids in the frame of the old waterline (O the axis), and their body coordinates
for centroid, ratio, label in ((x3, Mx3 / V3, "x3"), (y3, My3 / V3, "y3"), (x4, Mx4 / V4, "x4"),
                               (y4, My4 / V4, "y4")):
    d.step(label, Eq(centroid, ratio), "definition", result=centroid, note="wedge centroid: moment over volume")
d.step("body-coordinates", Eq(v3, c0 + x3), "definition", result=v3,
       note="O, the trace of the axis, lies at v = c0 on the old waterline, which lies at the height h0 above S; "
            "S3 lies beyond O by x3 (OF) and above the old waterline by y3 (S3F)")
d.step("body-coordinates-4", Eq(v4, x4 - c0), "definition", result=v4, note="S4 lies on the other side, OE = x4")
d.step("body-coordinates-u3", Eq(u3, h0 + y3), "definition", result=u3)
d.step("body-coordinates-u4", Eq(u4, h0 - y4), "definition", result=u4, note="S4 lies below the old waterline")
d.step("e-k-wedges", (sp.Matrix([e, k]), sp.Matrix([x3 + x4, y3 + y4])), "geometry",
       uses=("e-def", "k-def", "body-coordinates", "body-coordinates-4", "body-coordinates-u3",
             "body-coordinates-u4"), note="EF = e and S3F + S4E = k, for any position (c0, h0) of O")
d.step("wedge-moments-10", (sp.Matrix([V3 * e, V3 * k]), sp.Matrix([V3 * x3 + V3 * x4, V3 * y3 + V3 * y4]),
                            sp.Matrix([T1 * tg, T1 * tg ** 2 / 2])), "integration",
       uses=("e-k-wedges", "archimedes", "wedge-moments-3", "wedge-moments-4", "T1-parts"))
rhs12 = sp.sin(phi) * ((1 + tg ** 2 / 2) * T1 - V1 * e1)
rhs13 = T1 * sp.sin(phi) * tg / 2 + V1 * e1 * sp.cos(phi)
d.step("righting-moment-12", (V1 * m, rhs12), "substitution", uses=("moments-7", "wedge-moments-10"))
d.step("moment-13", (V1 * n, rhs13), "substitution", uses=("moments-7", "wedge-moments-10"))

for name, loc, exc, lhs, rhs in (
        ("EF-v", "I", r"$v_3 + v_4 = E F$", v3 + v4, x3 + x4),
        ("k-u", "I", r"$u_3 - u_4 = S_3 F + S_4 E$", u3 - u4, y3 + y4),
        ("EF-e", "II", r"$E F = e$", x3 + x4, e),
        ("k-S3F", "II", r"$S_3 F + S_4 E = k$", y3 + y4, k),
        ("e-x", "II", r"$e = x_3 + x_4$", e, x3 + x4),
        ("k-y", "II", r"$k = y_3 + y_4$", k, y3 + y4)):
    d.quote(name, loc, exc, reading=(lhs, rhs),
            note="EF = OF + OE = x3 + x4, S3F = y3, S4E = y4 (Fig. 4): through the body coordinates of S3, S4 for any "
                 "position of O")
d.quote("angle-R", "II", r"$R = \varphi$", reading=(sp.acos(ev.dot(sp.Matrix([1, 0]))), phi),
        note="the angle between the old waterplane (fixed in the body, across the axis) and the new (horizontal)")
d.quote("element-y", "II", r"$df \cdot y \cdot \frac{1}{2} y = \frac{1}{2} df \cdot x^2 \operatorname{tg}^2 \varphi$",
        reading=(sp.Integral(eta, (eta, 0, x * tg)), as_printed(lambda: (x * tg) * (x * tg) / 2), x ** 2 * tg ** 2 / 2),
        note="per unit df, y = x tg phi: the moment of the element about the old waterplane")
d.quote("element-x", "II", r"$df \cdot y \cdot x = df \cdot x^2 \operatorname{tg} \varphi$",
        reading=(sp.Integral(x, (eta, 0, x * tg)), as_printed(lambda: (x * tg) * x), x ** 2 * tg),
        note="per unit df: the moment about the plane through the axis perpendicular to the old waterplane")
d.quote("moments-10", "(10)",
        r"$$\begin{aligned} V_3 e &= V_3 x_3 + V_3 x_4 \\ V_3 k &= V_3 y_3 + V_3 y_4 \end{aligned} \quad (10)$$",
        reading=(sp.Matrix([V3 * e, V3 * k]), sp.Matrix([V3 * x3 + V3 * x4, V3 * y3 + V3 * y4])))
d.quote("moments-10a", "(10a)",
        r"$$\begin{aligned} V_3 y_3 &= \int_3 \frac{1}{2} df \cdot x^2 \operatorname{tg}^2 \varphi = \frac{1}{2} "
        r"\operatorname{tg}^2 \varphi \int_3 x^2 df \\ V_3 x_3 &= \int_3 df \cdot x^2 \operatorname{tg} \varphi = "
        r"\operatorname{tg} \varphi \int_3 x^2 df \end{aligned} \quad (10a)$$",
        reading=(sp.Matrix([V3 * y3, V3 * x3]),
                 sp.Matrix([sp.Integral((s - a) ** 2 * tg ** 2 / 2 * W, (s, a, Hh)),
                            sp.Integral((s - a) ** 2 * tg * W, (s, a, Hh))]),
                 sp.Matrix([tg ** 2 / 2 * J3, tg * J3])),
        note="int_3 ... df over the concrete waterplane: the part s > a of the trapezoid, x = s - a")
d.quote("moments-10b", "(10b)",
        r"$$\begin{aligned} V_3 y_4 &= \frac{1}{2} \operatorname{tg}^2 \varphi \int_4 x^2 df \\ V_3 x_4 &= "
        r"\operatorname{tg} \varphi \int_4 x^2 df \end{aligned} \quad (10b)$$",
        reading=(sp.Matrix([V3 * y4, V3 * x4]), sp.Matrix([tg ** 2 / 2 * J4, tg * J4])))
d.quote("moments-sum", "II, after (10b)",
        r"$$\begin{aligned} V_3 e &= \operatorname{tg} \varphi \int x^2 df \\ V_3 k &= \frac{1}{2} "
        r"\operatorname{tg}^2 \varphi \int x^2 df \end{aligned}$$",
        reading=(sp.Matrix([V3 * e, V3 * k]), sp.Matrix([tg * sp.Integral((s - a) ** 2 * W, (s, 0, Hh)),
                                                          tg ** 2 / 2 * sp.Integral((s - a) ** 2 * W, (s, 0, Hh))])))
d.quote("T1-integral", "II", r"$\int x^2 df$", reading=(T1, sp.Integral((s - a) ** 2 * W, (s, 0, Hh))),
        note="over the whole old waterplane: its moment of inertia T1 about the axis")
d.quote("moments-11", "(11)",
        r"$$\begin{aligned} V_3 e &= T_1 \operatorname{tg} \varphi \\ V_3 k &= \frac{1}{2} T_1 \cdot "
        r"\operatorname{tg}^2 \varphi \end{aligned} \quad (11)$$",
        reading=(sp.Matrix([V3 * e, V3 * k]), sp.Matrix([T1 * tg, T1 * tg ** 2 / 2])))
d.quote("volume-V3", "II, wedge volumes",
        r"Der Rauminhalt des neu eintauchenden Körperteils ist  $V_3 = \int_3 y \cdot df = \int_3 x \cdot df "
        r"\cdot \operatorname{tg} \varphi$",
        reading=(V3, sp.Integral((s - a) * tg * W, (s, a, Hh)), tg * sp.Integral((s - a) * W, (s, a, Hh))))
d.quote("volume-V4", "II, wedge volumes",
        r"$$\text{und ebenso gross ist } V_4 = \int_4 x \cdot df \cdot \operatorname{tg} \varphi,$$",
        reading=(V4, V3, tg * sp.Integral((a - s) * W, (s, 0, a))))
d.quote("moments-equal", "II, wedge volumes", r"$$\int_3 x df = \int_4 x df$$",
        reading=(sp.Integral((s - a) * W, (s, a, Hh)), sp.Integral((a - s) * W, (s, 0, a))))
d.quote("axis-centroid", "II, wedge volumes",
        "Dieses sind aber die statischen Momente der beiden Flächenteile in Bezug auf die Drehungsachse, "
        "letztere geht folglich durch den Schwerpunkt des alten Wasserschnitts.",
        reading=(a, sp.Integral(s * W, (s, 0, Hh)) / area),
        note="the axis (at s = a) and the centroid of the old waterplane coincide")
d.quote("moment-12", "(12)",
        r"$$V_1 m = \sin \varphi \left\{ \left( 1 + \frac{1}{2} \operatorname{tg}^2 \varphi \right) T_1 - V_1 e_1 "
        r"\right\} \quad (12)$$", reading=(V1 * m, rhs12))
d.quote("moment-13", "(13)",
        r"$$V_1 n = \frac{1}{2} T_1 \sin \varphi \cdot \operatorname{tg} \varphi + V_1 e_1 \cos \varphi \quad (13)$$",
        reading=(V1 * n, rhs13))
crit15 = (1 + tg ** 2 / 2) * T1 - V1 * e1
d.step("sign-15", (sp.sign(V1 * m), sp.sign(crit15)), "algebra", uses=("righting-moment-12",),
       note="sin phi > 0 for 0 < phi < pi/2: V1 m and the bracket of (12) have the same sign")


D15 = r"$$\left( 1 + \frac{1}{2} \operatorname{tg}^2 \varphi \right) T_1 - V_1 e_1"     # the bracket as (15) prints it
d.quote("stable-V1m", "(15)",
        "so muss (nach 9 und 12)  $V_1 m$  und folglich\n\n" + D15 + r" > 0 \text{ sein.} \quad (15)$$",
        reading=Iff(V1 * m > 0, crit15 > 0),
        note="the complete sentence: one predicate, '> 0 sein', after two subjects joined by 'und folglich' (V1 m, "
             "and consequently the bracket, must be positive); read as the equivalence it draws from (12): V1 m > 0 "
             "exactly when the bracket is positive. The reference 'nach 9' is left as printed (no display of the "
             "transcription carries (9); the stability condition is (2))")
d.quote("labile-V1m", "after (15)", "so ist  $V_1 m$  und daher\n\n" + D15 + " < 0$$",
        reading=Iff(V1 * m < 0, crit15 < 0),
        note="the complete sentence: one predicate, '< 0', after two subjects joined by 'und daher'; read as the "
             "equivalence of the signs by (12). For the labile initial position it holds for the small rotations, "
             "below the zero phi_1 of the increasing bracket (IV (27))")
d.quote("stable-15", "(15)",
        r"$$\left( 1 + \frac{1}{2} \operatorname{tg}^2 \varphi \right) T_1 - V_1 e_1 > 0 \text{ sein.} \quad (15)$$",
        reading=(sp.sign(V1 * m), sp.sign(crit15)),
        note="read as the equivalence of the signs: V1 m > 0 (stable, (2)) exactly when the bracket is "
             "positive; the text's reference '(nach 9 und 12)' names an equation (9) that the transcription "
             "does not display (the stability condition is (2))")
d.quote("labile-15", "after (15)",
        r"$$\left( 1 + \frac{1}{2} \operatorname{tg}^2 \varphi \right) T_1 - V_1 e_1 < 0$$",
        reading=(sp.sign(V1 * m), sp.sign(crit15)),
        note="'so ist V1 m und daher ... < 0' (one predicate for both): the same equivalence for the labile case")

# ---- III. small angles: (16), Duhamel (18) ----------------------------------------------------
m1 = sp.Subs(sp.Derivative(m, phi), phi, 0)
d.step("m-at-zero", (sp.Subs(m, phi, 0), 0), "series", uses=("righting-moment-12",))
d.step("series-16", (m1, T1 / V1 - e1), "series", uses=("righting-moment-12",),
       note="sin phi = phi + O(phi^3), tg^2 phi = O(phi^2)")
d.step("series-m2", (sp.Subs(sp.Derivative(m, phi, 2), phi, 0), 0), "series", uses=("righting-moment-12",),
       note="no phi^2 term: the error of (16) is O(phi^3)")
d.step("series-m3", (sp.Subs(sp.Derivative(m, phi, 3), phi, 0) / 6, T1 / (3 * V1) + e1 / 6), "series",
       uses=("righting-moment-12",), note="m = phi (T1/V1 - e1) + phi^3 (T1/(3 V1) + e1/6) + O(phi^5)")
cx3, cy3, cx4, cy4 = sp.symbols("c_{x3} c_{y3} c_{x4} c_{y4}", real=True)
for coefficient, derivative, leading, series_name, note in (
        (cx3, sp.Subs(sp.Derivative(Mx3, phi), phi, 0), J3, "series-x3", "tg phi = phi + O(phi^3)"),
        (cy3, sp.Subs(sp.Derivative(My3, phi, 2), phi, 0) / 2, J3 / 2, "series-y3", "tg^2 phi = phi^2 + O(phi^4)"),
        (cx4, sp.Subs(sp.Derivative(Mx4, phi), phi, 0), J4, "series-x4", ""),
        (cy4, sp.Subs(sp.Derivative(My4, phi, 2), phi, 0) / 2, J4 / 2, "series-y4", "")):
    d.step(series_name, (coefficient, derivative, leading), "series", uses=("wedge-moments-3", "wedge-moments-4"),
           result=coefficient, note="leading Taylor coefficient in phi (V x of first, V y of second order); " + note)
d.step("energy-curvature", (sp.Subs(sp.Derivative(V1 * n, phi, 2), phi, 0), T1 - V1 * e1, V1 * m1), "series",
       uses=("moment-13", "series-16"),
       note="V1 n is the height of S above S2 times the weight: the potential energy of body and displaced "
            "water (water level fixed). Its curvature at phi = 0 is V1 (T1/V1 - e1): the energy method "
            "(Schülen, preface) gives Duhamel's criterion")

d.quote("duhamel-16", "(16)", r"$$m = \varphi \left( \frac{T_1}{V_1} - e_1 \right) \quad (16)$$",
        reading=(m1, T1 / V1 - e1),
        note="read as the first-order coefficient of m in phi (m(0) = 0), as the text says: lim m/phi")
d.quote("series-3", "III, prism on the waterplane",
        r"$$V_3 x_3 = \varphi \cdot \int_3 x^2 \, d f \quad V_3 y_3 = \frac{1}{2} \varphi^2 \cdot \int_3 x^2 \, d f$$",
        reading=(sp.Matrix([cx3, cy3]), sp.Matrix([J3, J3 / 2])),
        note="read as the leading coefficients in phi: lim V3 x3/phi and lim V3 y3/phi^2")
d.quote("series-4", "III, prism on the waterplane",
        r"$$V_3 x_4 = \varphi \int_4 x^2 \, d f \quad V_3 y_4 = \frac{1}{2} \varphi^2 \int_4 x^2 \, d f.$$",
        reading=(sp.Matrix([cx4, cy4]), sp.Matrix([J4, J4 / 2])),
        note="read as the leading coefficients in phi")
d.quote("general-body", "III, arbitrary body",
        "Es behalten daher auch für den allgemeinen Körper die Formeln 11. 12. 16 für sehr kleines  $\\varphi$  "
        "ihre Giltigkeit.",
        reading=(m1, T1 / V1 - e1),
        note="read as lim m/phi; checked symbolically for the prism; the witness measures the first-order righting arm of a body "
             "that is not prismatic at the waterline (a triangular prism, apex down)")
d.quote("duhamel-18", "(18)", r"$$\frac{T_1}{V_1} = e_1 > 0. \quad (18)$$",
        reading=(T1 / V1, e1),
        erratum=Erratum("transcription", "high", r"\frac{T_1}{V_1} - e_1 > 0",
                        (r"The condition follows from (16), $m = \varphi\, (T_1/V_1 - e_1)$, whose sign decides: "
                         "$T_1/V_1 - e_1 > 0$. The '$=$' is the scan's reading of a minus (a known fault of this "
                         "transcription); printed as an equation the line would fix $T_1/V_1 = e_1$, the boundary "
                         "case, and '$= e_1 > 0$' would make no condition. Duhamel's sentence quoted right after "
                         "states the difference."),
                        corrected_reading=(sp.sign(m1), sp.sign(T1 / V1 - e1)),
                        objection=("'$T_1/V_1 = e_1 > 0$' may be a chain meant as printed: the boundary $T_1/V_1 = "
                                   "e_1$ together with $e_1 > 0$."),
                        answer=(r"(16), $m = \varphi (T_1/V_1 - e_1)$, makes the sign of the difference the "
                                "condition, and Duhamel's sentence quoted next states the difference; an equation "
                                "would fix the boundary case only. The scan reads the minus as '$=$' elsewhere in "
                                "this transcription.")))
T_axis = sp.Symbol("T", positive=True)      # the moment of inertia of the waterplane about any axis through its centroid
d.domain[T_axis] = (sp.Rational(1, 10), 10)
d.says("least-moment", "III",
       "Aus 16 folgt also als Bedingung für die Stabilität:\n\n$$\\frac{T_1}{V_1} = e_1 > 0. \\quad (18)$$\n\n\n\n"
       "Diese Bedingung muss natürlich für jede durch den Schwerpunkt des Wasserschnitts gehende Drehungsachse "
       "erfüllt sein, das ist aber der Fall, wenn sie für die des kleinsten Trägheitsmoments erfüllt ist.",
       "Bedingung für die Stabilität", GrowsWith(T_axis, at={T1: T_axis}),
       note="Read as: the stability for an axis through the waterplane's centroid grows with the moment of inertia T "
            "about that axis (V1 and e1 are the same for every axis), so the axis of the least moment decides. The "
            "display (18) inside the excerpt is booked at duhamel-18.")
d.quote("duhamel-statement", "III, Duhamel",
        "nur muss dann die Entfernung dieser beiden Punkte kleiner sein als das kleinste der Trägheitsmomente der "
        "Schnittfläche des Körpers mit der Wasseroberfläche in Bezug auf die durch ihren Schwerpunkt gezogenen "
        "Geraden, dividiert durch das eingetauchte Volumen",
        reading=(sp.sign(m1), sp.sign(T1 / V1 - e1)),
        note="for the axis of the smallest moment of inertia T1 (the critical one): stable iff e1 < T1/V1")
