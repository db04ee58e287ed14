"""What Scheeffer's sections VII and VIII say and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import Derivation, Eq, Erratum
from symfloat.model.symbol_names import symbol
from symfloat.model.vocabulary import StableIff

R = sp.Rational
b, s, F1, F, xs, T, Tp, f, xs1, tau = sp.symbols("b s F_1 F x_s T T^1 f x_s^1 tau", positive=True)
ys, x0, PO, Pw, Pf, x, y, z, xp, mu = sp.symbols("y_s x_0 P_O P_w P_f x y z x' mu", real=True)
# results (VII)
phi2, V, V3, My, M3, e3, e2, V1 = sp.symbols("varphi_2 V V_3 M_y M_3 e_3 e_2 V_1")
X3, Z3 = symbol("V_3x_3", r"V_{3} x_{3}"), symbol("V_3z_3", r"V_{3} z_{3}")        # the moments as printed
Pxy, Pwh, I2, F2, m_, n_, T2, T21, Ks, J1, k_, T1, T11 = sp.symbols(
    "P_xy P_ABCD I_2 F_2 m n T_2 T_2^1 k_s J_1 k T_1 T_1^1")
Tmu, Tm, D = sp.symbols("T_mu T_m D")
# results (VIII)
phi3, x01, My3 = sp.symbols("varphi_3 x_0^1 M_y3")
# VIII prints V_3, V_3 x_3, V_3 z_3, M_3 again for the third region; marked here by the section's number
V3c, X3c, Z3c, M3c = (symbol(name, tex) for name, tex in (
    ("V_3c", r"V_{3}^{\text{VIII}}"), ("V_3cx_3", r"(V_{3} x_{3})^{\text{VIII}}"),
    ("V_3cz_3", r"(V_{3} z_{3})^{\text{VIII}}"), ("M_3c", r"M_{3}^{\text{VIII}}")))

DERIVATION = d = Derivation(
    id="scheeffer-vii-viii",
    source="scheeffer",
    title="The second and third rotation regions of a right prism: one or both bases cut by the water",
    locator="VII-VIII",
    summary="Equilibrium in the second region: int x y df = 0 over the dry part F of the upper base (95a), "
            "tan phi_2 = F_1 b (1-s)/(F x_s) and T(1 + tan^2/2) - F_1 b^2 (1-s)/2 - F x_s x_0 = 0 (103); "
            "stability from the least moment of the waterplane (110)-(117); the third region (118)-(122).",
    requires=("scheeffer-iv-v",),
    domain={b: (1, 3), s: (R(11, 20), R(19, 20)), F1: (2, 4), F: (R(1, 2), R(3, 2)), xs: (R(1, 5), 1),
            ys: (-R(3, 10), R(3, 10)), T: (1, 2), Tp: (R(1, 2), 2), x0: (-R(1, 2), R(1, 2)),
            PO: (-R(1, 5), R(1, 5)), Pw: (-R(1, 5), R(1, 5)), mu: (0, R(3, 2)), x: (0, 1), y: (-1, 1),
            z: (-1, 0), xp: (0, 1), f: (R(1, 10), R(1, 2)), xs1: (R(1, 20), R(3, 10)), tau: (R(1, 100), R(1, 5)),
            Pf: (-R(1, 10), R(1, 10)), phi2: (R(1, 10), R(6, 5)), phi3: (R(1, 10), R(6, 5))},
    constraints=(F * xs > f * xs1,),
    assumptions=(
        "homogeneous right prism, any convex base of area F_1, height b, density s (water 1); VII: the water "
        "plane cuts the upper base and the side faces only (second region), VIII: both bases (third region)",
        "frame: origin N (foot of the perpendicular EF from the base centroid O on GH), x along NE towards the "
        "dry side, y along NG, z along the prism axis up, z = 0 in the upper base; O = (x_0, 0), S = (x_0, 0, -b/2)",
        "F, F x_s, F y_s, T, T^1: area moments of the dry part F of the upper base in that frame; P_O: product "
        "moment of the whole base about O (axes parallel to x, y); P_w: int x y df over the wet part BGH in "
        "the frame of N; VIII: f, f x_s^1, tau, P_f the moments of the dry part f of the lower base from ML",
        "the tilt is the one at which the dry volume is V (1 - s) (Archimedes), so phi_2, phi_3 are derived",
        "Fig. 19 is lost: its y axis is taken along NG; then the text's n (NL, with int_1 y df = -n F_2) is "
        "-y_s, and y_s in (112) is read as the distance of the centroid of F from EN on the side of H (-y_s "
        "here); only its square enters (113), (115), (117)",
        "inequalities are read through the quantity whose sign decides, with the positive factor stated"),
)


def termwise(expr, moments):
    """int expr df for a polynomial in the plane coordinates, termwise from the area moments (linearity);
    the sum of coefficient times moment is left unevaluated, for the engine to check against a closed form."""
    poly = sp.Poly(sp.expand(expr), x, y)
    terms = [sp.Mul(c, moments[(i, j)], evaluate=False) for (i, j), c in poly.terms()]
    return sp.Add(*terms, evaluate=False) if len(terms) > 1 else terms[0] if terms else sp.Integer(0)


def res(expr):
    """*expr* with the values established so far inserted (build time)."""
    r = d.results()
    for _ in range(40):
        new = sp.sympify(expr).xreplace(r)
        if new == expr:
            return new
        expr = new
    return expr


MF = {(0, 0): F, (1, 0): F * xs, (0, 1): F * ys, (2, 0): T, (0, 2): Tp, (1, 1): Pxy}
NOTE_F = "termwise over F: int df = F, int x df = F x_s, int y df = F y_s, int x^2 df = T, int y^2 df = T^1, int x y df"
tg2, c2, sn2 = sp.tan(phi2), sp.cos(phi2), sp.sin(phi2)
up2 = sp.Matrix([sn2, 0, c2])
hor2 = sp.Matrix([c2, 0, -sn2])

# ==== VII. the second region ========================================================================================
d.step("whole-base", (Pwh, termwise((x0 + x) * y, {(0, 1): 0, (1, 1): PO}), PO), "integration", result=Pwh,
       note="int_1 x y df over ABCD from N: with x = x_0 + x' (x' from O) it is x_0 int y df + int x' y df, and "
            "int y df = 0 about EF through the centroid O")
d.step("dry-product", Eq(Pxy, Pwh - Pw), "definition", result=Pxy,
       note="int x y df over AGHCD = over ABCD less over the wet part BGH (additivity)")
d.step("wet-flipped", Eq(I2, -Pw), "definition", result=I2,
       note="int_2 x y df over BGH with the +x axis turned to NF (x -> -x)")
d.step("waterplane", (up2.dot(sp.Matrix([x, y, -x * tg2])), 0), "geometry",
       note="the plane z = -x tan phi_2 through GH is horizontal (normal u)")
col = lambda e: sp.integrate(e, (z, -x * tg2, 0))  # noqa: E731  (the column over df above the water)
d.step("dry-volume", (V3, termwise(col(1), MF), F * xs * tg2), "integration", result=V3,
       note="the column over a point of F reaches from the water plane to the base: length x tan phi_2; " + NOTE_F)
d.step("volume", Eq(V, F1 * b), "definition", result=V)
d.step("tilt", Eq(phi2, sp.atan(F1 * b * (1 - s) / (F * xs))), "definition", result=phi2,
       note="the tilt at which the dry volume F x_s tan phi_2 equals V (1 - s): the submerged volume is s V")
d.step("archimedes", (V3, V * (1 - s)), "algebra", uses=("dry-volume", "tilt"))
d.step("moment-y", (My, termwise(y * col(1), MF), Pxy * tg2), "integration", result=My,
       note="static moment of the dry part about the vertical plane y = 0 (through S across the axis GH)")
d.step("moment-x", (X3, termwise(x * col(1), MF), T * tg2), "integration", result=X3, note="V_3 x_3")
d.step("moment-z", (Z3, termwise(col(-z), MF), T * tg2 ** 2 / 2), "integration", result=Z3,
       note="V_3 z_3, z_3 the depth of S_3 below the upper base")
MS3 = sp.Matrix([X3 - V3 * x0, My, V3 * b / 2 - Z3])        # V_3 (S_3 - S)
d.step("M3", Eq(M3, hor2.dot(MS3)), "definition", result=M3,
       note="V_3 times the horizontal distance of S_3 from the vertical plane through S parallel to GH "
            "(h = (cos phi, 0, -sin phi))")
d.step("e3", Eq(e3, up2.dot(MS3) / V3), "definition", result=e3, note="height of S_3 above S")
d.step("V1", Eq(V1, V - V3), "definition", result=V1, note="the submerged volume")
d.step("e2", Eq(e2, up2.dot(MS3) / V1), "definition", result=e2,
       note="height of S above S_2: V S = V_1 S_2 + V_3 S_3 gives V_1 (S - S_2) = V_3 (S_3 - S)")
d.step("e2-e3", (V1 * e2, V3 * e3), "algebra", uses=("e2", "e3"))
Q2 = T * (1 + tg2 ** 2 / 2) - F1 * b ** 2 * (1 - s) / 2 - F * xs * x0
d.step("M3-sin", (M3 / sn2, Q2), "algebra", uses=("M3", "moment-x", "moment-z", "archimedes"))

# the text's stability remark: M_3 = V_1 dE/dphi (E the height of G above B), shown on the rectangular strip
A_, C_, th = sp.symbols("A C theta", positive=True)
Eb, Mb, wb = sp.symbols("E_box M_box w_box")
d.domain.update({A_: (1, 2), C_: (R(1, 2), 2), th: (R(1, 5), 1)})
d.step("box-strip", Eq(wb, sp.sqrt(2 * A_ * b * (1 - s) / sp.tan(th))), "definition", result=wb,
       note="box A x C x b tilted by theta about an axis parallel to the side C: F is a strip of width w with "
            "C w^2 tan(theta)/2 = A C b (1-s) (volume at the fixed density s)")
_tb = sp.tan(th)
BOX = {V3: C_ * wb ** 2 * _tb / 2, X3: C_ * wb ** 3 * _tb / 3, Z3: C_ * wb ** 3 * _tb ** 2 / 6, My: 0,
       x0: wb - A_ / 2}
_ms3 = MS3.xreplace(BOX)
d.step("box-potential", Eq(Eb, sp.Matrix([sp.sin(th), 0, sp.cos(th)]).dot(_ms3) / (A_ * C_ * b * s)),
       "definition", result=Eb,
       note="E = u.(G - B) = u.V_3 (S_3 - S)/V_1 with the strip's moments (101): V_3 = C w^2 tan/2, V_3 x_3 = C w^3 "
            "tan/3, V_3 z_3 = C w^3 tan^2/6, x_0 = w - A/2")
d.step("box-M3", Eq(Mb, sp.Matrix([sp.cos(th), 0, -sp.sin(th)]).dot(_ms3)), "definition", result=Mb,
       note="M_3 (99) of the strip at the tilt theta")
d.step("box-potential-slope", (A_ * C_ * b * s * sp.Derivative(Eb, th), Mb), "algebra",
       uses=("box-strip", "box-potential", "box-M3"), note="V_1 dE/dtheta = M_3: equilibria are stationary points of E")

# ---- stability: the waterplane (Fig. 19) -------------------------------------------------------------------------
P_wp = sp.Matrix([x, y, -x * tg2])
d.step("wp-coordinates", (sp.Matrix([P_wp.dot(hor2), P_wp[1]]), sp.Matrix([x / c2, y])), "geometry",
       note="the point of the waterplane over (x, y) of F: X = x / cos phi_2 from HN, Y = y along HN")
jac = sp.Matrix([1, 0, -tg2]).cross(sp.Matrix([0, 1, 0]))
d.step("wp-area-element", (sp.sqrt(jac.dot(jac)), 1 / c2), "geometry", note="df_2 = df / cos phi_2")
d.step("wp-area", (F2, termwise(1 / c2, MF), F / c2), "integration", result=F2,
       note="the waterplane is the image of F (in the second region it ends at GH and at the side faces)")
d.step("wp-m", (m_, termwise(x / c2 / c2, MF) / F2, xs / c2), "integration", result=m_,
       note="distance S^1 L of the waterplane centroid from HN")
d.step("wp-n", (n_, -termwise(y / c2, MF) / F2, -ys), "integration", result=n_,
       note="the text's n: int_1 y df = -n F_2")
d.step("T1", (T1, termwise((x - xs) ** 2, MF), T - F * xs ** 2), "integration", result=T1,
       note="moment of F about its centroidal axis parallel to GH")
d.step("T11", (T11, termwise((y - ys) ** 2, MF), Tp - F * ys ** 2), "integration", result=T11,
       note="moment of F about its centroidal axis parallel to EF")
d.step("T2", (T2, termwise((x / c2 - m_) ** 2 / c2, MF), T1 / c2 ** 3), "integration", result=T2,
       uses=("wp-coordinates", "wp-area-element"))
d.step("T21", (T21, termwise((y + n_) ** 2 / c2, MF), T11 / c2), "integration", result=T21)
d.step("J1", (J1, termwise((x / c2) * y / c2, MF), Pxy / c2 ** 2), "integration", result=J1,
       note="int_1 x y df over the waterplane from N")
d.step("Ks", (Ks, termwise((x / c2 - m_) * (y + n_) / c2, MF), J1 + m_ * n_ * F2), "integration", result=Ks,
       note="int_s x y df about the centroid S^1 (x - m, y + n from N)")
SC = 2 * sp.sin(mu) * sp.cos(mu)          # sin 2 mu
CC = sp.cos(mu) ** 2 - sp.sin(mu) ** 2     # cos 2 mu
d.step("Tmu", (Tmu, termwise(((x / c2 - m_) * sp.cos(mu) - (y + n_) * sp.sin(mu)) ** 2 / c2, MF),
               T2 * sp.cos(mu) ** 2 + T21 * sp.sin(mu) ** 2 - Ks * SC), "integration", result=Tmu,
       note="moment about the centroidal axis PQ at the angle mu with J_1K_1 (parallel to HN); sin 2mu = 2 sin mu cos mu")
d.step("k", Eq(k_, m_ * n_ * F2), "definition", result=k_, note="(106): the value of int_s x y df at equilibrium")
d.step("Ks-equilibrium", (Ks, k_ + Pxy / c2 ** 2), "algebra", uses=("Ks", "J1", "k"),
       note="so int_s x y df = k exactly when the first condition int x y df = 0 holds")
# the least moment of any plane figure with central moments T_2, T_2^1 and product k (symbols of their own)
T2g, T21g, kg = sp.symbols("T_2 T_2^1 k", real=True)
Tg, Dg, Rg, Tmg, mus = sp.symbols("T_mu' D' R' T_m' mu^*")
d.domain.update({T2g: (1, 3), T21g: (R(1, 2), 4), kg: (-1, 1)})
Sg = (T2g + T21g) / 2
dbl = lambda th_: Sg - sp.cos(th_) / 2 * (T21g - T2g) - kg * sp.sin(th_)  # noqa: E731  (T_mu at 2 mu = th_)
q_ = 2 * kg / (T21g - T2g)
d.step("Tg", Eq(Tg, T2g * sp.cos(mu) ** 2 + T21g * sp.sin(mu) ** 2 - kg * SC), "definition", result=Tg,
       note="(107) for a plane figure with central moments T_2 (about J_1K_1), T_2^1 and product k")
d.step("Tg-double", (Tg, dbl(2 * mu)), "algebra", uses=("Tg",), note="cos^2 mu = (1 + cos 2mu)/2, ...")
d.step("Tg-derivative", (sp.Derivative(Tg, mu), (T21g - T2g) * SC - 2 * kg * CC), "algebra", uses=("Tg",))
d.step("mu-star", Eq(mus, sp.atan(q_) / 2), "definition", result=mus,
       note="the root of the derivative: tan 2mu = 2k/(T_2^1 - T_2); mu^* + 90 deg is the other")
d.step("Dg", Eq(Dg, (T21g - T2g + 2 * kg * q_) / sp.sqrt(1 + q_ ** 2)), "definition", result=Dg)
d.step("stationary-values", (sp.Matrix([dbl(2 * mus), dbl(2 * mus + sp.pi)]), sp.Matrix([Sg - Dg / 2, Sg + Dg / 2])),
       "algebra", uses=("Tg-double", "mu-star", "Dg"),
       note="cos 2mu^* = 1/sqrt(1 + q^2), sin 2mu^* = q/sqrt(1 + q^2), q = 2k/(T_2^1 - T_2)")
d.step("root", (Rg, sp.sqrt(Dg ** 2), sp.sqrt((T2g - T21g) ** 2 + 4 * kg ** 2)), "algebra", uses=("Dg",), result=Rg)
d.step("Tm-g", Eq(Tmg, Sg - Rg / 2), "definition", result=Tmg, uses=("stationary-values", "root"),
       note="the smaller of the two stationary values Sigma/2 -+ D/2: the least moment")
d.step("Tm", (Tm, sp.Subs(Tmg, (T2g, T21g, kg), (T2, T21, k_)), (T2 + T21) / 2 - sp.sqrt((T2 - T21) ** 2 + 4 * k_ ** 2) / 2),
       "substitution", uses=("Tm-g", "Ks-equilibrium"), result=Tm,
       note="the least moment of the waterplane at an equilibrium (its central product is k there)")
d.step("D", Eq(D, Tm - V1 * e2), "definition", result=D,
       note="Duhamel: V_1 times the metacentric height of the position; stable iff D > 0 (scheeffer-iv-v (33))")
d.defines("stability", D)
d.step("e3-cos", (e3 * c2, b / 2 - Z3 / V3 + sn2 * M3 / V3), "algebra", uses=("e3", "M3"),
       note="so e_3 cos phi_2 = b/2 - z_3 wherever M_3 = 0")
M2h, M2y = symbol("M_2h", r"M_{2,h}"), symbol("M_2y", r"M_{2,y}")
d.step("balance-h", Eq(M2h, -hor2.dot(MS3)), "definition", result=M2h,
       note="V_1 h.(S_2 - S) from V S = V_1 S_2 + V_3 S_3")
d.step("balance-y", Eq(M2y, -My), "definition", result=M2y)
d.step("regular-product", (sp.Subs(sp.Rational(1, 2) * (sp.Symbol("T_x") - sp.Symbol("T_y")) * sp.sin(2 * sp.Symbol("omega"))
                                   + sp.Symbol("J") * sp.cos(2 * sp.Symbol("omega")),
                                   (sp.Symbol("T_x"), sp.Symbol("J")), (sp.Symbol("T_y"), 0)), 0), "substitution",
       uses=("scheeffer-iv-v:Iuv", "scheeffer-iv-v:symmetric-J", "scheeffer-iv-v:T1-isotropic"),
       note="int u v df about central axes at the angle omega (scheeffer-iv-v (44)-(45)) vanishes for a base "
            "with T_x = T_y and a symmetry axis (J = 0): every regular polygon (section V), so P_O = 0")


# ---- which base is cut first (the opening of VII), as in scheeffer-iv-v (53)-(55)
um, um1, sst = sp.symbols("u_m u_m' s^*", positive=True)
d.domain.update({um: (R(1, 5), 2), um1: (R(1, 5), 2)})
d.step("first-contact", Eq(sst, um1 / (um + um1)), "definition", result=sst,
       uses=("scheeffer-iv-v:top-contact", "scheeffer-iv-v:bottom-contact", "scheeffer-iv-v:threshold"),
       note="turned about EF from the upright position, the plane through EF reaches the upper base at tan phi = "
            "b (1-s)/u_m, the lower one at b s/u_m' (u_m, u_m' the farthest base points on the dipping and the rising "
            "side): the upper base first iff s > s^*")
d.step("first-contact-check", ((b * (1 - s) / um - b * s / um1).subs(s, sst), 0), "algebra", uses=("first-contact",))

EQN = "the '= 0' is the equilibrium condition imposed; read as the identity it is imposed on"


AT_EQ = ("read at an equilibrium: the reading inserts the equilibrium's x_0 (103b) and the derived V_3, z_3, e_3, "
         "so that its members are no longer the printed ones")
X0E = (T * (1 + tg2 ** 2 / 2) - F1 * b ** 2 * (1 - s) / 2) / (F * xs)   # the x_0 at which (103b) vanishes


def at_eq(expr):
    """*expr* at a position satisfying the second condition (103b): x_0 = X0E."""
    return res(expr).subs(x0, res(X0E))


d.quote("s-upper", "VII", "Es soll dabei das spec. Gew.  $s > \\frac{1}{2}$\n\nvorausgesetzt werden, sodass also die "
        "obere Grundfläche zum Teil eintaucht.", reading=(sst, R(1, 2)),
        note="read as: beyond the first region the upper base is cut when s > 1/2 (the threshold of s)",
        erratum=Erratum("claim", "high",
                        "the upper base is cut first iff $s > u_m'/(u_m + u_m')$; that is $s > 1/2$ only when the "
                        "base reaches equally far on both sides of the axis ($u_m = u_m'$); otherwise the second "
                        "region may begin with the lower base although $s > 1/2$ (and the formulas apply with dry and "
                        "wet parts exchanged)",
                        (r"The same claim as in IV (53) (Scheeffer IV, the claim on $s > \tfrac12$). Counterexample: "
                         r"equilateral triangular prism of side 1 and height 1, $s = \tfrac35$, turned about an axis "
                         r"parallel to a side with that side dipping ($u_m = 1/(2 \sqrt{3}), u_m' = 1/\sqrt{3}, s^* = "
                         r"2/3$): the clipped prism's lower base reaches the water at $\tan \varphi = 1.0392$ ($= "
                         r"\sqrt{3} s$), the upper one only at $1.3856$ ($= 2 \sqrt{3} (1 - s)$)."),
                        corrected_reading=(sst, um1 / (um + um1)),
                        objection="'sodass also die obere Grundfläche zum Teil eintaucht' may be a stipulation of "
                                  "the case to be treated (s > 1/2 and the upper base cut), not an inference from s "
                                  "> 1/2.",
                        answer="'also' marks a consequence, and the same inference is drawn in IV (53) for the first"
                               " region; for bases that reach unequally far on the two sides (the triangular prism "
                               "at s = 3/5) the lower base is cut first, so the inference fails. The stipulation "
                               "reading would leave the case 'lower base first, s > 1/2' untreated, which the "
                               "section's closing sentence ('vollständigen Bedingungen') denies."))
d.quote("95", "(95)", "„Das statische Moment des über dem Wasser befindlichen Körperteils für die durch  $S$  "
        "senkrecht zur Drehungsachse gelegte Vertikalebene (Ebene der Figur 17) ist Null.“ (95)",
        reading=(My, Pxy * tg2),
        note="read as the moment itself, tg phi_2 int x y df (step moment-y); 'ist Null' is the condition (95a)")
d.quote("95-S3", "VII", r"Da nun  $S_2$  senkrecht unter  $S$  liegt, so muss auch  $S_3$  senkrecht über  $S$  liegen",
        reading=(sp.Matrix([M2h, M2y]), -sp.Matrix([M3, My])),
        note="read as V_1 (S_2 - S) = -V_3 (S_3 - S) in the two horizontal directions")
d.quote("95-element", "VII", r"$z \cdot y \cdot df$ , oder da  $z = x \operatorname{tg} \varphi_2$  ist,  "
        r"$x y \cdot df \cdot \operatorname{tg} \varphi_2$",
        reading=(sp.Integral(y, (z, -x * tg2, 0)), x * y * tg2), note="per unit df")
d.quote("95-volume-element", "VII", r"Das Volumen dieses Körperelements ist  $z \cdot df$",
        reading=(sp.Integral(1, (z, -x * tg2, 0)), x * tg2), note="per unit df: the column from the water plane z = "
                                                                    "-x tg phi_2 to the upper base z = 0")
d.quote("95-moment", "VII", r"stat. Moment des ganzen Körperteils  $\int x y df \cdot \operatorname{tg} \varphi_2$",
        reading=(My, Pxy * tg2))
d.quote("95a", "(95a)", r"$$\int x y \cdot df = 0 \quad (95a)$$", reading=(Pxy, My / tg2), note=EQN, condition=EQN,
        symbols={r"\int x y \cdot df": (Pxy, "int x y df over the dry part A G H C D (the next line) is P_xy")})
d.quote("96", "(96)", r"$$\int x y df = \int_s (x_0 + x) y df + \int_2 x y df. \quad (96)$$",
        reading=(Pxy, Pwh + I2))
d.quote("96-split", "VII", r"$$\int_s (x_0 + x) y df = x_0 \cdot \int_s y df + \int_s x y df.$$",
        reading=(Pwh, x0 * 0 + PO), note="int_s y df = 0 (the next sentence)")
_p, _q = sp.symbols("p_t q_t", real=True)
d.quote("centroid-axis", "VII",
        r"und  $\int y df$  das statische Moment der Grundfläche für die durch ihren Schwerpunkt gehende Achse  "
        r"$E F$ , also gleich Null.",
        reading=(sp.Integral(sp.Integral(_q - R(1, 3), (_q, 0, 1 - _p)), (_p, 0, 1)), 0),
        note="the first moment of a plane figure about an axis through its centroid vanishes: shown on the right "
             "triangle (0, 0), (1, 0), (0, 1), centroid at height 1/3, by integration")
d.quote("97", "(97)", r"$$\int x y df = \int_s x y df + \int_2 x y df = 0. \quad (97)$$", reading=(Pxy, PO + I2),
        note=EQN)
d.quote("98", "(98)", r"$$\int x y df = \int_2 x y df = 0 \quad (98)$$", reading=(sp.Subs(res(Pxy), PO, 0), res(I2)),
        note="regular prism: P_O = 0 (step regular-product); " + EQN)
d.quote("95a-split", "VII", r"$$\int x y \cdot = \int_1 x y df - \int_2 x y df$$",
        unreadable=r"the left member $\int x y \cdot$ has no measure: an integral sign without its $df$",
        erratum=Erratum("transcription", "high", r"\int x y \cdot df = \int_1 x y df - \int_2 x y df",
                        r"The left member is the sum of (95a), written '$\int x y \cdot df$' one display before and "
                        r"'$\int x y\, df$' in (96) two displays after; here the $df$ after the dot is missing, so the "
                        "member is no "
                        "formula. A lost token of the scan (the dot it followed survived); the content is the "
                        r"additivity of $\int x y\, df$ over $ABCD = AGHCD + BGH$, which holds.",
                        corrected_reading=(Pxy, Pwh - Pw),
                        objection=r"'$\int x y \cdot$' may be the author's abbreviation, the element $df$ understood "
                                  "from the right member.",
                        answer=r"One display before and in (96) two displays after the same member is written "
                               r"'$\int x y \cdot df$' and '$\int x y\, df$' in full; a dot followed by nothing is no "
                               "notation of the text, and the dot that stood before $df$ survived."),
        note="int_2 over BGH still from N")
d.quote("regular-Ps", "VII", r"so ist nach Abschnitt V auch  $\int_s x y df = 0$",
        reading=(sp.Subs(sp.Rational(1, 2) * (sp.Symbol("T_x") - sp.Symbol("T_y")) * sp.sin(2 * sp.Symbol("omega"))
                         + sp.Symbol("J") * sp.cos(2 * sp.Symbol("omega")),
                         (sp.Symbol("T_x"), sp.Symbol("J")), (sp.Symbol("T_y"), 0)), 0),
        note="the product moment of a regular polygon about central axes in any direction (step regular-product)")
d.quote("S3-offsets", "VII", "$$S_3 O_3 = P_3 O = x_3 - x_0,$$\n\n$SO$ , die halbe Höhe des Prismas, nach der früheren "
        "Bezeichnung  $= \\frac{b}{2}$ ,\n\n$$SO_3 = SO - O_3 O = \\frac{b}{2} - z_3.$$",
        reading=(sp.Matrix([MS3[0] / V3, MS3[2] / V3]), sp.Matrix([X3 / V3 - x0, b / 2 - Z3 / V3])),
        note="S_3 P_3 = z_3 (depth below the upper base), N P_3 = x_3 (the display before): the offsets of S_3 from S "
             "along NE and along the axis")
d.quote("S3-offsets-used", "VII",
        r"also mit Benutzung der Werte  $S_3 O_3 = x_3 - x_0$  und  $SO_3 = \frac{b}{2} - z_3$",
        reading=(sp.Matrix([MS3[0] / V3, MS3[2] / V3]), sp.Matrix([X3 / V3 - x0, b / 2 - Z3 / V3])),
        note="the offsets of S_3 from S along NE and along the axis, as displayed before (S3-offsets)")
d.quote("complete", "VII", "No. 95 a, 103 a, b und 117 enthalten die vollständigen Bedingungen des Gleichgewichts "
        "und der Stabilität eines geraden Prismas (von beliebiger Form) für das zweite Drehungsgebiet.",
        reading=(sp.Matrix([M2h, M2y]), -sp.Matrix([sn2 * Q2, tg2 * Pxy])),
        note="read as: the two horizontal offsets of S_2 from S (times V_1) are -sin phi_2 x (103b) and -tan phi_2 x "
             "(95a), with the tilt from (103a): the position is an equilibrium exactly when (95a) and (103b) hold; "
             "stability is (117) (sign identity 2 cos phi_2 D, checked with (117))")
d.quote("99", "(99)", r"$$M_3 = V_3 (x_3 - x_0) \cos \varphi_2 - V_3 \left( \frac{b}{2} - z_3 \right) \cdot \sin "
        r"\varphi_2 = 0. \quad (99)$$", reading=(M3, (X3 - V3 * x0) * c2 - (V3 * b / 2 - Z3) * sn2), note=EQN)
d.quote("second-condition-words", "VII",
        "„Das statische Moment des über dem Wasser befindlichen Körperteils für die durch S parallel zur "
        "Drehungsachse gelegte Vertikalebene ist Null.“",
        reading=(M2h, -M3),
        note="V_1 times the offset of S_2 from the vertical through S (across the axis) is -M_3: S_2 lies under S "
             "exactly when the moment M_3 of the dry part vanishes (as 95-S3)")
d.quote("99-transformation", "VII",
        r"$$M_3 = V_3 \cdot \overline{S_3 O_3} \cdot \cos \varphi_2 - V_3 \cdot \overline{S O_3} \cdot \sin \varphi_2,$$",
        reading=(M3, V3 * (X3 / V3 - x0) * c2 - V3 * (b / 2 - Z3 / V3) * sn2),
        note="S_3 O_3 = x_3 - x_0, S O_3 = b/2 - z_3 (the next lines)",
        symbols={r"\overline{S_3 O_3}": (X3 / V3 - x0, "the segment S_3 O_3 is x_3 - x_0 (the next lines)"),
                 r"\overline{S O_3}": (b / 2 - Z3 / V3, "the segment S O_3 is b/2 - z_3 (the next lines)")})
d.quote("stability-direction", "VII",
        "dass das für  $M_3 = 0$  eintretende Gleichgewicht ein (wenigstens für die Drehungsachse) stabiles sein "
        "muss, wenn  $M_3$  mit wachsendem  $\\varphi$  aus dem Negativen durch Null in's Positive übergeht",
        reading=(A_ * C_ * b * s * sp.diff(res(Eb), th), Mb),
        note="read as M_3 = V_1 dE/dphi (E the height of G above B): a zero where M_3 goes from - to + is a "
             "minimum of E; shown on the rectangular strip (steps box-*), witnessed on clipped boxes")
d.quote("100", "(100)", r"so ist das  $\frac{1}{2}$  Volumen des über dem Wasser befindlichen Teils"
        "\n\n$$V_3 = V \\cdot (1 - s) = F_1 \\cdot b \\cdot (1 - s) \\quad (100)$$",
        reading=(V3 / 2, V * (1 - s), F1 * b * (1 - s)),
        erratum=Erratum("transcription", "medium", r"\text{das Volumen ... } V_3 = V (1 - s) = F_1 b (1 - s)",
                        ("The dry part's whole volume is $V (1 - s)$ (the submerged part is $s V$); the text uses "
                         r"$V_3$ so in (103a), (121b). The '$\tfrac12$' before 'Volumen' is a stray sign of the scan "
                         "(perhaps a misread mark); a slip of the printer is possible (medium)."),
                        corrected_reading=(V3, V * (1 - s), F1 * b * (1 - s)),
                        objection="The '1/2' may be the print's own, e.g. a half of the volume meant in a sentence "
                                  "the scan has shortened.",
                        answer=("The display that follows is the whole dry volume $V (1 - s)$, and (103a), (121b) "
                                "use $V_3$ so; no half of it enters any later formula. A stray sign before 'Volumen' "
                                "is more likely the scan's reading of a mark than a compositor's word, but the print "
                                "cannot be seen: medium.")))
d.quote("101", "(101)",
        r"$$\left. \begin{aligned} V_3 z_3 &= \int \frac{1}{2} z^2 \cdot d f = \frac{1}{2} \operatorname{tg}^2 "
        r"\varphi_2 \cdot \int x^2 d f = \frac{1}{2} T \cdot \operatorname{tg}^2 \varphi_2 \\ V_3 x_3 &= \int z x \cdot "
        r"d f = \operatorname{tg} \varphi_2 \cdot \int x^2 d f = T \cdot \operatorname{tg} \varphi_2 \end{aligned} "
        r"\right\} \quad (101)$$",
        reading=(sp.Matrix([Z3, X3]),
                 sp.Matrix([sp.Mul(sp.Rational(1, 2), tg2 ** 2, termwise(x ** 2, MF), evaluate=False),
                            sp.Mul(tg2, termwise(x ** 2, MF), evaluate=False)]),
                 sp.Matrix([T * tg2 ** 2 / 2, T * tg2])),
        note="T: moment of F about GH (int x^2 df)")
d.quote("102-pre", "VII", r"$$M_3 = T \sin \varphi_2 - V_3 x_0 \cos \varphi_2 - V_3 \frac{b}{2} \sin \varphi_2 + "
        r"\frac{1}{2} T \operatorname{tg}^2 \varphi_2 \cdot \sin \varphi_2 = 0$$",
        reading=(M3, T * sn2 - V3 * x0 * c2 - V3 * b / 2 * sn2 + T * tg2 ** 2 * sn2 / 2), note=EQN)
d.quote("into-99", "VII",
        "Setzt man diese beiden Werte in die Gleichung 99, nachdem man sie mit  $V_3$  multipliziert hat, ein, so wird",
        reading=(M3, T * sn2 - V3 * x0 * c2 - V3 * b / 2 * sn2 + T * tg2 ** 2 * sn2 / 2),
        note="(101) inserted into (99) gives the next display (102-pre): the reference is right")
d.quote("102", "(102)", r"$$M_3 = \sin \varphi_2 \cdot \left\{ T \left( 1 + \frac{1}{2} \operatorname{tg}^2 "
        r"\varphi_2 \right) - V_3 \cdot \frac{b}{2} - V_3 x_0 \operatorname{cotg} \varphi_2 \right\} = 0 \quad (102)$$",
        reading=(M3, sn2 * (T * (1 + tg2 ** 2 / 2) - V3 * b / 2 - V3 * x0 / tg2)), note=EQN)
d.quote("V3-F", "VII", r"$$V_3 = F \cdot x_s \cdot \operatorname{tg} \varphi_2$$", reading=(V3, F * xs * tg2))
d.quote("103a", "(103a)", r"$$\operatorname{tg} \varphi_2 = \frac{F_1 \cdot b (1 - s)}{F \cdot x_s} \quad (103a)$$",
        reading=(tg2, F1 * b * (1 - s) / (F * xs)))
d.quote("103b", "(103b)", r"$$\frac{M_3}{\sin \varphi_2} = T \left( 1 + \frac{1}{2} \operatorname{tg}^2 \varphi_2 "
        r"\right) - F_1 \frac{b^2}{2} \cdot (1 - s) - F x_s \cdot x_0 = 0 \quad (103b)$$", reading=(M3 / sn2, Q2),
        note=EQN)
d.quote("103ab-simplest", "(103b)",
        "Die beiden Gleichungen 103a und 103b enthalten die zweite Gleichgewichtsbedingung in möglichst einfacher Form.",
        reading=(M3 / sn2, Q2), note="M_3 / sin phi_2 with the tilt of (103a) is the left side of (103b)")
d.quote("s-below-half", "VII", r"Wenn das spec. Gew.  $s < \frac{1}{2}$  ist, so ist der über dem Wasser befindliche "
        r"Körperteil mit dem eintauchenden zu vertauschen, also  $s$  statt  $1 - s$  zu setzen.",
        reading=(V1 * e2, V3 * e3),
        note="read as: V_1 (S - S_2) = V_3 (S_3 - S), so V_1 E (the potential times the submerged volume) is the "
             "same for the body of density s with u up and that of density 1 - s with -u up, whose submerged part "
             "is this dry part: the equilibria and their stability correspond (witnessed on clipped prisms)")
d.quote("s-below-half-95", "VII", "$$\\int x y \\, d f = 0$$\n\nwo nun die Integration auf den eintauchenden Teil "
        "der unteren Grundfläche auszudehnen ist.", reading=(Pxy, My / tg2),
        note="for s < 1/2 the body of density 1 - s with -u up: its submerged part is the dry part here, so the "
             "integral is the same (witnessed on the turned clipped body); '= 0' imposed")
d.quote("106-first", "VII", r"folglich auch  $\int_1",
        reading=(sp.Subs(res(J1), Pw, PO), 0),
        note="int_1 x y df = 0 at the first condition (the line break of the transcription splits the formula)")
d.quote("104", "(104)", r"$$T_m - V_3 e_3 > 0 \quad (104)$$", reading=(Tm - V3 * e3, D),
        note="D = T_m - V_1 e_2 (Duhamel), V_1 e_2 = V_3 e_3 (step e2-e3); T_m the least moment at equilibrium")
d.says("104-words", "(104)", "so ist das Gleichgewicht stabil, wenn\n\n$$T_m - V_3 e_3 > 0 \\quad (104)$$",
       "stabil", StableIff(Tm - V3 * e3 > 0),
       note="Read as Duhamel's criterion both ways: stable exactly when (104) holds; V_3 e_3 = V_1 e_2 (104-balance) "
            "makes it the sign of the stability D.")
d.quote("104-balance", "VII", r"so ist  $V_1 e_2 = V_3 e_3$", reading=(V1 * e2, V3 * e3))
d.quote("x-direction", "VII", r"Nimmt man  $S S^1$  als  $(+ x)$  Richtung",
        unreadable=("$S$ is the centroid of the body (Fig. 17), no point of the water section of Fig. 19, whose "
                    "points are $O_1$, $H$, $N$, $E_1$, $S^1$, $L$, $J_1$, $K_1$, $P$, $Q$: '$S S^1$' names no "
                    "direction in its plane"),
        erratum=Erratum("misprint", "low", r"\text{Nimmt man } L S^1 \text{ als } (+ x) \text{ Richtung}",
                        ("The $x$ axis of Fig. 19 runs through the centroid $S^1$ across the principal axis $J_1 "
                         "K_1$, which is perpendicular to $S^1 L$: it lies along $S^1 L$. Its sense follows from the "
                         "shift two sentences on, '$x - m$ statt $x$ ... wenn $S^1 L = m$', which moves the origin "
                         "to HN: the points of HN have $x = -m$, so $+x$ points from $L$ to $S^1$: measured from HN "
                         "in that sense, the first moment of the water section is $+m F_2$ (its area $F_2$, pulled "
                         r"back to $F$: $\int x/\cos\varphi_2\, df$ over $F$, stretched by $1/\cos\varphi_2$). "
                         "Neither 'S' for 'L' by the scan nor by the typesetter can be told without the figure; low."),
                        corrected_reading=(termwise(x / c2 ** 2, MF), m_ * F2),
                        objection=("$S S^1$ may be right: $S$, the centroid of the body, projects onto the water "
                                   "section, and the lost Fig. 19 may mark that projection on the line through $S^1$."),
                        answer=("The shift '$x - m$ statt $x$ ... wenn $S^1 L = m$' fixes the axis along $S^1 L$ and "
                                "its sense from $L$ to $S^1$; whether the figure also carried $S$ on that line, and "
                                "whether scan or print wrote $S$ for $L$, cannot be told without the figure, so it "
                                "stays low.")),
        note="x is measured in F from GH (the projection of HN) and stretched by 1/cos phi_2 in the waterplane")
d.quote("105-def", "VII", r"$$T_\mu = \int_s (x \cos \mu - y \sin \mu)^2 \cdot d f$$",
        reading=(Tmu, termwise(((x / c2 - m_) * sp.cos(mu) - (y + n_) * sp.sin(mu)) ** 2 / c2, MF)),
        note="integral over the waterplane from its centroid, pulled back to F")
d.quote("105", "(105)", r"$$\text{oder } T_\mu = T_2 \cdot \cos^2 \mu + T_2^1 \sin^2 \mu - \int_s x y \, d f \cdot "
        r"\sin 2 \mu \quad (105)$$", reading=(Tmu, T2 * sp.cos(mu) ** 2 + T21 * sp.sin(mu) ** 2 - Ks * SC),
        note="sin 2mu read as 2 sin mu cos mu")
d.quote("106-shift", "VII", r"&= \int_1 x y \, d f - \int_1 m y \, d f + \int_1 n x \, d f - m n F_2",
        reading=(Ks, J1 - m_ * (-n_ * F2) + n_ * (m_ * F2) - m_ * n_ * F2),
        note="with int_1 y df = -n F_2, int_1 x df = m F_2")
d.quote("106-moments", "VII", r"$\int_1 y \, d f = - n F_2$  und  $\int_1 x \, d f = m F_2$",
        reading=(sp.Matrix([termwise(y / c2, MF), termwise(x / c2 ** 2, MF)]), sp.Matrix([-n_ * F2, m_ * F2])))
d.quote("106-sum", "VII", r"folglich  $\int_s x y \, d f = \int_1 x y \, d f + m n \cdot F_2$",
        reading=(Ks, J1 + m_ * n_ * F2))
d.quote("106-projection", "VII", r"$\int x y \, d f = \int_1 x y \, d f \cdot \cos^2 \varphi_2 = 0$",
        reading=(Pxy, J1 * c2 ** 2), note=EQN)
d.quote("106", "(106)", r"$$\text{und } \int_s x y \, d f = m n F_2 = k \cdot \quad (106)$$",
        reading=(res(Ks).subs(Pw, PO), m_ * n_ * F2, k_), note="at the first condition (P_w = P_O: int x y df = 0)")
d.quote("107", "(107)", r"$$T_\mu = T_2 \cdot \cos^2 \mu + T_2^1 \sin^2 \mu - k \sin 2 \mu. \quad (107)$$",
        reading=(res(Tmu).subs(Pw, PO), T2 * sp.cos(mu) ** 2 + T21 * sp.sin(mu) ** 2 - k_ * SC),
        note="at the first condition (P_w = P_O); sin 2mu = 2 sin mu cos mu")
d.quote("108", "(108)", r"$$\begin{aligned} (T_2^1 - T_2) \sin 2 \mu - 2 k \cdot \cos 2 \mu &= 0 \\ \text{oder } "
        r"\operatorname{tg} 2 \mu &= \frac{2 k}{T_2^1 - T_2} \end{aligned} \quad (108)$$",
        reading=(sp.Matrix([sp.diff(res(Tg), mu), sp.tan(2 * mus)]),
                 sp.Matrix([(T21g - T2g) * SC - 2 * kg * CC, 2 * kg / (T21g - T2g)])),
        note="dT_mu/dmu (the '= 0' imposed) and its root mu^*; T_2, T_2^1, k of any figure (step Tg)")
d.quote("xs-depth", "VII", r"so ist  $x_s \operatorname{tg} \varphi_2$  seine Entfernung vom Wasserschnitt",
        reading=(V3 / F, xs * tg2),
        note="the mean length of the columns over F (dry volume over area): the column over the centroid, x_s tan phi_2")
d.quote("Tmu-derivative", "VII", r"Setzt man den Differentialquotienten von  $T_\mu$  gleich Null, so erhält man",
        reading=(sp.Derivative(Tg, mu), (T21g - T2g) * SC - 2 * kg * CC),
        note="the derivative of (107) in mu; its zero is (108)")
d.quote("109", "(109)", r"$$T_\mu = \frac{1}{2} (T_2 + T_2^1) - \frac{1}{2} \cos 2 \mu \left\{ T_2^1 - T_2 - 2 k "
        r"\operatorname{tg} 2 \mu \right\} \quad (109)$$",
        reading=(Tg, Sg - sp.cos(2 * mu) / 2 * (T21g - T2g - 2 * kg * sp.tan(2 * mu))),
        erratum=Erratum("misprint", "medium",
                        r"T_\mu = \frac{1}{2} (T_2 + T_2^1) - \frac{1}{2} \cos 2 \mu \left\{ T_2^1 - T_2 + 2 k "
                        r"\operatorname{tg} 2 \mu \right\}",
                        (r"From (107): $T_2 \cos^2\mu + T_2^1 \sin^2\mu = (T_2 + T_2^1)/2 - \cos 2\mu\, (T_2^1 - "
                         r"T_2)/2$ and $-k \sin 2\mu = -\tfrac12 \cos 2\mu\, (2 k \operatorname{tg} 2\mu)$, so the "
                         r"brace has $+ 2 k \operatorname{tg} 2\mu$. Only with $+$ does the next step give $(T_2 + "
                         r"T_2^1)/2 \mp \sqrt{(T_2 - T_2^1)^2 + 4k^2}/2$ (with $-$ the root would be of $((T_2^1 - "
                         "T_2)^2 - 4k^2)^2/((T_2^1 - T_2)^2 + 4k^2)$). A sign slip of the author or printer; a scan "
                         "turning $+$ into $-$ is unusual (medium)."),
                        corrected_reading=(Tg, Sg - sp.cos(2 * mu) / 2 * (T21g - T2g + 2 * kg * sp.tan(2 * mu))),
                        objection=(r"The minus may be right if $k$ is taken with the opposite sign, $k = -\int_2 u_2 "
                                   "v_2 df_2$."),
                        answer=(r"(109) only rewrites (107), $T_\mu = T_2 \cos^2 \mu + T_2^1 \sin^2 \mu - k \sin "
                                r"2\mu$, with the same $k$, whatever its sign: $-k \sin 2\mu$ is $-\tfrac12 \cos "
                                r"2\mu\, (2k \operatorname{tg} 2\mu)$, so the brace has $+ 2k \operatorname{tg} "
                                r"2\mu$, and with the $\operatorname{tg} 2\mu$ of (108) only that gives the root of "
                                "the next line. A plus read as minus is no usual scan fault, so the print's; medium, "
                                "since author and printer cannot be told.")))
d.quote("109-cos", "VII", r"$$\cos 2 \mu = \pm \frac{T_2^1 - T_2}{\sqrt{(T_2^1 - T_2)^2 + 4 k^2}}$$",
        reading=(sp.cos(2 * mus) ** 2, (T21g - T2g) ** 2 / ((T21g - T2g) ** 2 + 4 * kg ** 2)),
        note="the +- read through the square, at the root mu^* of (108)")
d.quote("109-extremes", "VII",
        r"$$T_\mu = \frac{1}{2} (T_2 + T_2^1) \pm \frac{1}{2} \cdot \sqrt{(T_2 - T_2^1)^2 + 4 k^2}$$",
        reading=(sp.Matrix([(dbl(2 * mus) - Sg) ** 2, (dbl(2 * mus + sp.pi) - Sg) ** 2]),
                 sp.Matrix([((T2g - T21g) ** 2 + 4 * kg ** 2) / 4] * 2)),
        note="the two stationary values (mu^*, mu^* + 90 deg) lie half the root above and below the mean")
d.quote("109-max-min", "VII", "Die beiden Werte von  $T_\\mu$  geben das Maximum und das Minimum.",
        reading=(sp.Matrix([(dbl(2 * mus) - Sg) ** 2, (dbl(2 * mus + sp.pi) - Sg) ** 2]),
                 sp.Matrix([((T2g - T21g) ** 2 + 4 * kg ** 2) / 4] * 2)),
        note="T_mu = S + A cos(2 mu - delta) takes its largest and smallest value at the two stationary directions, "
             "half the root above and below the mean S")
d.quote("110", "(110)", r"$$T_m = \frac{1}{2} (T_2 + T_2^1) - \frac{1}{2} \cdot \sqrt{(T_2 - T_2^1)^2 + 4 k^2} \quad (110)$$",
        reading=(Tmg, Sg - sp.sqrt((T2g - T21g) ** 2 + 4 * kg ** 2) / 2))
d.quote("111", "(111)", r"$$T_2 = \frac{T_1}{\cos^3 \varphi_2} \text{ und } T_2^1 = \frac{T_1^1}{\cos \varphi_2} \text{ ist.} "
        r"\quad (111)$$", reading=(sp.Matrix([T2, T21]), sp.Matrix([T1 / c2 ** 3, T11 / c2])))
YS = -ys    # the printed y_s (see the assumptions)
d.quote("112-mn", "VII", r"$$m = \frac{x_s}{\cos \varphi_2} \quad n = y_s \quad F_2 = \frac{F}{\cos \varphi_2}$$",
        reading=(sp.Matrix([m_, n_, F2]), sp.Matrix([xs / c2, YS, F / c2])),
        note="y_s here is the printed one, -y_s of the frame (assumptions)")
d.quote("112", "(112)", r"$$\text{folglich (106) } k = \frac{x_s y_s \cdot F}{\cos^2 \varphi_2} \quad (112)$$",
        reading=(k_, xs * YS * F / c2 ** 2),
        symbols={"y_s": (YS, "Fig. 19 is lost: the printed y_s is -y_s of the module's frame (assumptions)")})
d.quote("113", "(113)", r"$$T_1 = T - F \cdot x_s^2 \quad T_1^1 = T^1 - F \cdot y_s^2 \quad (113)$$",
        reading=(sp.Matrix([T1, T11]), sp.Matrix([T - F * xs ** 2, Tp - F * YS ** 2])))
d.quote("114", "(114)", r"$$T_m \cos \varphi_2 - V_3 e_3 \cos \varphi_2 > 0. \quad (114)$$",
        reading=(Tm * c2 - V3 * e3 * c2, c2 * D), note="sign identity, factor cos phi_2 > 0")
d.quote("115", "(115)", r"$$T_m \cdot \cos \varphi_2 = \frac{1}{2} \left( \frac{T_1}{\cos^2 \varphi_2} + T_1^1 \right) - "
        r"\frac{1}{2} \sqrt{\left( \frac{T_1}{\cos^2 \varphi_2} - T_1^1 \right)^2 + \frac{(2 F x_s y_s)^2}{\cos^2 "
        r"\varphi_2}} \quad (115)$$",
        reading=(Tm * c2, (T1 / c2 ** 2 + T11) / 2 - sp.sqrt((T1 / c2 ** 2 - T11) ** 2 + (2 * F * xs * YS) ** 2 / c2 ** 2) / 2))
d.quote("116-geometry", "VII", r"$$V_3 e_3 \cdot \cos \varphi_2 = V_3 \cdot \left( \frac{b}{2} - z_3 \right)$$",
        reading=(at_eq(V3 * e3 * c2), at_eq(V3 * b / 2 - Z3)), note="at an equilibrium (M_3 = 0, x_0 from (103b))",
        not_compared=AT_EQ)
d.quote("116-pre", "VII", r"$$V_3 e_3 \cos \varphi_2 = \frac{1}{2} \left\{ F_1 b^2 (1 - s) - T \operatorname{tg}^2 \varphi_2 "
        r"\right\}$$", reading=(V3 * b / 2 - Z3, (F1 * b ** 2 * (1 - s) - T * tg2 ** 2) / 2),
        note="its right side is V_3 (b/2 - z_3) by (100), (101)",
        symbols={"e_3": ((V3 * b / 2 - Z3) / (V3 * c2), "V_3 e_3 cos phi_2 is read as V_3 (b/2 - z_3), the line "
                                                       "before (an equilibrium's), which the witness measures")})
d.quote("116", "(116)", r"$$V_3 e_3 \cos \varphi_2 = T - F x_s \cdot x_0 \quad (116)$$",
        reading=(at_eq(V3 * e3 * c2), at_eq(T - F * xs * x0)),
        note="at an equilibrium ('nach 102 b)' means (103b))", not_compared=AT_EQ)
L117 = (T1 / c2 ** 2 + T11 + 2 * F * xs * x0 - 2 * T
        - sp.sqrt((T1 / c2 ** 2 - T11) ** 2 + (2 * F * xs * YS) ** 2 / c2 ** 2))
d.quote("117", "(117)", r"$$\left. \begin{aligned} & \frac{T_1}{\cos^2 \varphi_2} + T_1^1 + 2 F x_s x_0 - 2 T \\ & - "
        r"\sqrt{\left( \frac{T_1}{\cos^2 \varphi_2} - T_1^1 \right)^2 + \frac{(2 F x_s y_s)^2}{\cos^2 \varphi_2}} "
        r"\right\} > 0 \quad (117) \end{aligned}$$", reading=(at_eq(L117), at_eq(2 * c2 * D)),
        note="sign identity at an equilibrium, factor 2 cos phi_2 > 0")
d.quote("117-cos", "VII", r"(nach 102 a)  $\frac{1}{\cos^2 \varphi_2} = \left| \frac{F_1 \cdot b (1 - s)}{F x_s} "
        r"\right|^2 + 1$", reading=(1 / c2 ** 2, (F1 * b * (1 - s) / (F * xs)) ** 2 + 1),
        note="'102 a' means (103a); the bars are brackets")
Q102 = T * (1 + tg2 ** 2 / 2) - V3 * b / 2 - V3 * x0 / tg2     # the bracket of (102) as printed
TAN_USED = F1 * b * (1 - s) / (F * xs)                            # tan phi_2 in the relation quoted after it
d.quote("102a-reference", "VII", r"(nach 102 a)",
        reading=(sp.Matrix([sp.Derivative(Q102, x0), tg2]), sp.Matrix([sp.Derivative(TAN_USED, x0), TAN_USED])),
        erratum=Erratum("misprint", "medium", r"\text{(nach 103 a); before (116): nach 103 b)}",
                        (r"The relation cited, $1/\cos^2 \varphi_2 = (F_1 b (1-s)/(F x_s))^2 + 1$, is $\tan \varphi_2 "
                         "= F_1 b (1-s)/(F x_s)$, i.e. (103a), which comes from the volume (100) and fixes the tilt "
                         "whatever $x_0$. There is no (102a): (102) is the single moment equation $T(1 + "
                         r"\operatorname{tg}^2/2) - V_3 b/2 - V_3 x_0 \operatorname{cotg} \varphi_2 = 0$, which ties "
                         "the tilt to $x_0$ (its derivative in $x_0$ is $-F x_s$, not $0$) and cannot give it. The "
                         "same slip stands before (116), 'also nach 102 b)' for (103b): $F x_s x_0 = T(1 + "
                         r"\operatorname{tg}^2/2) - F_1 b^2 (1-s)/2$ turns $V_3 e_3 \cos\varphi_2 = \{F_1 b^2 (1-s) - "
                         r"T \operatorname{tg}^2\}/2$ into (116), and no (102b) exists either. Two consistent numbers "
                         "point to the print or an earlier numbering of the manuscript rather than the scan (medium)."),
                        corrected_reading=(sp.Matrix([sp.Derivative(V3 - V * (1 - s), x0), tg2]),
                                           sp.Matrix([sp.Derivative(TAN_USED, x0), TAN_USED])),
                        fault="nach 102", places=("VII",),
                        objection="The print may have numbered (102a), (102b) displays that the transcription lost, "
                                  "so that both references are right.",
                        answer=("The transcription carries (102), then (103a) and (103b), and the summary cites '95 "
                                "a, 103 a, b und 117'; the relation cited is (103a) squared plus one, and (102) "
                                "cannot give it (it ties the tilt to $x_0$). Both references off by one in the same "
                                "way point to the print or an earlier numbering, hence medium.")),
        note="read as: the equation cited gives the tilt of the relation quoted after it, independent of x_0; the "
             "derivative in x_0 of the equation cited against that of the relation, and the tilt itself")
d.quote("117-T", "VII", "$$T_1 = T - F \\cdot x_s^2$$\n\n$$T_1^1 = T^1 - F \\cdot y_s^2.$$",
        reading=(sp.Matrix([T1, T11]), sp.Matrix([T - F * xs ** 2, Tp - F * YS ** 2])))
d.step("O-position", Eq(sp.Symbol("x_O"), x0), "definition", result=sp.Symbol("x_O"),
       note="O = N + x_0 (unit vector along NE): x_0 is the coordinate of O from N towards E")
d.quote("x0-sign", "VII", r"Wenn der Punkt  $N$  (s. Fig. 17 und 18) zwischen  $O$  und  $E$  liegt, so wird  $x_0$  negativ.",
        reading=(x0, sp.Symbol("x_O")), note="x_0 is the coordinate x_O of O from N along NE: negative when O "
                                              "lies on the far side of N from E (witnessed: measured on the clipped "
                                              "water line)")

# ==== VIII. the third region =========================================================================================
tg3, c3, sn3 = sp.tan(phi3), sp.cos(phi3), sp.sin(phi3)
up3, hor3 = sp.Matrix([sn3, 0, c3]), sp.Matrix([c3, 0, -sn3])
Mf = {(0, 0): f, (1, 0): f * xs1, (2, 0): tau, (1, 1): Pf}
d.step("tilt-3", Eq(phi3, sp.atan(F1 * b * (1 - s) / (F * xs - f * xs1))), "definition", result=phi3,
       note="the tilt at which the dry volume (121b) is V (1 - s)")
d.step("x01", Eq(x01, b / tg3 - x0), "definition", result=x01,
       note="N_2 (over N_1, where the water line meets EF in the lower base) lies at x = b cot phi_3 from N: "
            "the plane z = -x tan phi_3 reaches z = -b there; x_0^1 = O N_2")
d.step("ML", (-(x0 + x01) * tg3, -b), "geometry", uses=("x01",))
col3 = lambda e: sp.integrate(e, (z, -x * tg3, 0))  # noqa: E731
cut3 = lambda e: sp.expand(sp.integrate(e, (z, -x * tg3, -b)).subs(x, xp + b / tg3))  # noqa: E731  (below the lower base)
Mf_x = lambda e: termwise(sp.expand(e).subs(xp, x), Mf)  # noqa: E731  (x' written as x for termwise)
d.step("cut-column", (sp.Subs(sp.Integral(1, (z, -x * tg3, -b)), x, xp + b / tg3), xp * tg3), "algebra", uses=("x01",),
       note="over f the column x tan phi_3 overshoots the lower base by x' tan phi_3, x' = x - (x_0 + x_0^1)")
d.step("dry-volume-3", (V3c, termwise(col3(1), MF) - Mf_x(cut3(1)), (F * xs - f * xs1) * tg3), "integration",
       result=V3c, note="the prism over F cut by the water plane, less the part below the lower base (over f)")
d.step("archimedes-3", (V3c, F1 * b * (1 - s)), "algebra", uses=("dry-volume-3", "tilt-3"))
d.step("moment-y-3", (My3, termwise(y * col3(1), MF) - Mf_x(y * cut3(1)), (Pxy - Pf) * tg3), "integration", result=My3)
d.step("moment-z-3", (Z3c, termwise(col3(-z), MF) - Mf_x(cut3(-z)),
                      (T - tau) * tg3 ** 2 / 2 - b * f * xs1 * tg3), "integration", result=Z3c)
d.step("moment-x-3", (X3c, termwise(x * col3(1), MF) - Mf_x((xp + x0 + x01) * cut3(1)),
                      (T - tau) * tg3 - (x0 + x01) * xs1 * f * tg3), "integration", result=X3c)
MS3c = sp.Matrix([X3c - V3c * x0, My3, V3c * b / 2 - Z3c])
d.step("M3-3", Eq(M3c, hor3.dot(MS3c)), "definition", result=M3c)
Q3 = ((T - tau) * (1 + tg3 ** 2 / 2) - (x0 + x01 + b * tg3) * f * xs1 - V3c * b / 2 - V3c * x0 / tg3)
d.step("M3-3-sin", (M3c / sn3, Q3), "algebra", uses=("M3-3", "moment-x-3", "moment-z-3"))

d.quote("118", "(118)", r"$$\int x y d f - \int^1 x y d f = 0 \quad (118)$$", reading=(Pxy - Pf, My3 / tg3), note=EQN,
        condition=EQN, symbols={r"\int x y d f": (Pxy, "int x y df over the dry part of the upper base is P_xy"),
                                r"\int^1 x y d f": (Pf, "int^1 x y df over the dry part f of the lower base is P_f")})
# Fig. 21 (lost) with the letters of Fig. 18 (VIII: 'die Buchstaben hier dieselbe Bedeutung haben wie dort'): the
# upper base ABCD, the water line GH (G on AB, H on BC) cuts off the wet corner B (VII: int_2 df = BGH) and leaves
# the dry part F = AGHCD (VII: int df = AGHCD); D is the corner of the dry triangle DML of the lower base, projected
FIG21 = {"A": (0, 1), "B": (1, 1), "C": (1, 0), "D": (0, 0), "G": (R(2, 3), 1), "H": (1, R(1, 4))}


def area21(labels):
    """Area of the polygon of Fig. 21 named by its letters in order (shoelace, exact; built unevaluated, so that
    the engine, not SymPy on building, carries out the arithmetic)."""
    pts = [tuple(sp.sympify(v) for v in FIG21[q]) for q in labels]
    with sp.evaluate(False):
        return sp.Abs(sp.Add(*[p[0] * q[1] - q[0] * p[1] for p, q in zip(pts, pts[1:] + pts[:1])])) / 2


with sp.evaluate(False):
    F21 = area21("ABCD") - area21("BGH")  # the dry part of the upper base: the base less the wet triangle
F_LABEL = (("$F$ is the dry part AGHCD of the upper base, as in VII: the area whose moments $F x_s$, $T$ (120)-(122) "
            r"and $V_3 = (F x_s - f x_s^1) \operatorname{tg}\varphi_3$ (121b) use; VIII keeps the letters of VII, "
            r"where $G$, $H$ lie on the sides at the wet corner $B$ ($\int_2 df = BGH$, the remark after (95a)). "
            r"Checked on a square ABCD with $G = (\tfrac23, 1)$, $H = (1, \tfrac14)$: the dry part is $1 - \tfrac18 = "
            r"\tfrac78$"))
d.quote("118-domain", "(118)",
        r"wo das Zeichen  $\int$  auf die Fläche  $G H D = F$  und das Zeichen  $\int^1$  auf die Fläche  $D M L = f$  "
        r"auszudehnen ist.",
        reading=(area21("GHD"), F21),
        erratum=Erratum("misprint", "low", r"\text{auf die Fläche } A G H C D = F",
                        F_LABEL + ". GHD is a triangle with the vertex D, the corner where the dry part $f = DML$ of the "
                        r"lower base lies; its area ($\tfrac{5}{12}$ on the square) is not $F$. Two letters missing and none "
                        "misread is no glyph a scan confuses, but this transcription is a model's reading, which "
                        "drops and adds letters; VII fixes $F$ and (118) integrates over $F$ ((95a) over AGHCD), so "
                        "the correction stands, and, as for GBH in VIII, the cause is open: low, Fig. 21 being "
                        "lost.",
                        corrected_reading=(area21("AGHCD"), F21),
                        objection="In the third region the lost Fig. 21 may letter the points anew, so that GHD "
                                  "names the dry part of the upper base (G, H on the sides at D).",
                        answer="The section says the letters keep their meaning of Figs. 17, 18 ('dass auch die "
                               "Buchstaben hier dieselbe Bedeutung haben wie dort') except N, and there G, H lie at "
                               "the wet corner B and F is AGHCD; (121b) needs F to be the upper base's whole dry "
                               "part. Low, since Fig. 21 is lost and the letters may be the transcription's."),
        note="read on a square base: the printed domain of int has the area of F, the dry part of the upper base; f = "
             "DML is the projected dry part of the lower base, as the section's construction says")
d.quote("119", "(119)", r"$$M_3 = V_3 (x_3 - x_0) \cos \varphi_3 - V_3 \left( \frac{b}{2} - z_3 \right) \sin \varphi_3 = 0 "
        r"\quad (119)$$", reading=(M3c, (X3c - V3c * x0) * c3 - (V3c * b / 2 - Z3c) * sn3), note=EQN)
d.quote("120", "(120)", r"$$\left. \begin{aligned} V_3 z_3 &= \frac{1}{2} (T - \tau) \operatorname{tg}^2 \varphi_3 - b "
        r"\cdot f x_s^1 \cdot \operatorname{tg} \varphi_3 \\ V_3 x_3 &= (T - \tau) \operatorname{tg} \varphi_3 - (x_0 + "
        r"x_0^1) x_s^1 \cdot f \cdot \operatorname{tg} \varphi_3 \end{aligned} \right\} \quad (120)$$",
        reading=(sp.Matrix([Z3c, X3c]), sp.Matrix([(T - tau) * tg3 ** 2 / 2 - b * f * xs1 * tg3,
                                                  (T - tau) * tg3 - (x0 + x01) * xs1 * f * tg3])))
d.quote("121", "(121)", r"$$\left. \begin{aligned} \frac{M_3}{\sin \varphi_3} &= (T - \tau) \left( 1 + \frac{1}{2} "
        r"\operatorname{tg}^2 \varphi_3 \right) - (x_0 + x_0^1 + b \operatorname{tg} \varphi_3) \cdot f x_s^1 \\ &\quad - "
        r"V_3 \cdot \frac{b}{2} - V_3 \cdot x_0 \cdot \operatorname{cotg} \varphi_3 \end{aligned} \right\} = 0. \quad (121)$$",
        reading=(M3c / sn3, Q3), note=EQN)
d.quote("fig20", "VIII", r"In Fig. 20 ist Winkel  $N_2 N N_1 = \varphi_3$ ,  $N_1 N_2 = b$  und  $N N_2 = x_0 + x_0^1$",
        reading=(sp.Matrix([sp.atan(b / (b / tg3)), b, b / tg3]), sp.Matrix([phi3, b, x0 + x01])),
        note="N_1 is where the water plane z = -x tan phi_3 reaches the lower base z = -b, at x = b cot phi_3 = N N_2; "
             "N_1 N_2 = b is its depth there, the angle at N its slope")
d.quote("121a", "(121a)", r"$$(x_0 + x_0^1) \operatorname{tg} \varphi_3 = b \quad (121 a)$$", reading=((x0 + x01) * tg3, b))
d.quote("121b", "(121b)", r"$$V_3 = (F x_s - f x_s^1) \operatorname{tg} \varphi_3 = F_1 \cdot b (1 - s) \quad (121 b)$$",
        reading=(V3c, (F * xs - f * xs1) * tg3, F1 * b * (1 - s)))
d.quote("121-dry", "VIII", r"Das Volumen des nicht eintauchenden Körperteils ( $V_3$ ) ist jetzt die Differenz aus zwei "
        r"schief abgestumpften Prismen",
        reading=(V3c, termwise(col3(1), MF) - Mf_x(cut3(1))),
        note="the prism over F under the upper base down to the water plane, less its part below the lower base")
d.quote("prism-bases", "VIII", r"mit den Grundflächen  $G B H$  und  $M D L$",
        reading=(area21("GBH"), F21),
        erratum=Erratum("misprint", "low", r"\text{mit den Grundflächen } A G H C D \text{ und } M D L",
                        F_LABEL + ". The dry part is the prism over $F$ less the prism over the projected dry part "
                        "DML of the lower base; GBH is the wet triangle of the upper base, whose prism lies under "
                        "water. Two labels of the same paragraph name $F$ wrongly (GBH here, GHD in (118)'s domain);"
                        " the scan does not turn AGHCD into GBH; low, since Fig. 21 is lost.",
                        corrected_reading=(area21("AGHCD"), F21),
                        objection="GBH may be meant: the prism over the wet triangle GBH of the upper base could be "
                                  "the body whose volume is taken.",
                        answer=(r"The volume built here is $V_3 = (F x_s - f x_s^1) \operatorname{tg} \varphi_3$ "
                                "(121b), the dry part, a prism over $F$ less one over the dry part DML of the lower "
                                "base; the prism over GBH lies under water. The letters differ from 118's GHD too, "
                                "so which label the print had cannot be recovered: low.")),
        note="read on a square base: the first prism's base has the area of the dry part F of the upper base")
x31 = sp.Symbol("x_3^1", positive=True)      # the letter printed in the definition of the centroid distance of f
d.domain.update({x31: (R(1, 20), R(3, 10))})
d.quote("xs1-definition", "VIII", r"$x_3^1$  die Entfernung des Schwerpunktes der Fläche  $f$  von  $M L$",
        reading=(sp.Matrix([Z3c, X3c]), sp.Matrix([(T - tau) * tg3 ** 2 / 2 - b * f * x31 * tg3,
                                                  (T - tau) * tg3 - (x0 + x01) * x31 * f * tg3])),
        erratum=Erratum("transcription", "medium", r"x_s^1 \text{ die Entfernung des Schwerpunktes der Fläche } f "
                                                   r"\text{ von } M L",
                        ("The distance defined here is the one (120), (121), (121b), (122) use as $x_s^1$ ($f x_s^1$ "
                         "is the first moment of $f$ about $ML$, as $F x_s$ that of $F$ about $GH$); $x_3^1$ appears "
                         "in no formula, and $x_3$ is the dry part's centroid, another quantity. Read with the "
                         "printed letter as its own quantity, (120) fails; with $x_s^1$ it is the derived moment. "
                         "The scan read $s$ as $3$ (medium: the print may have had the slip)."),
                        corrected_reading=(sp.Matrix([Z3c, X3c]), sp.Matrix([(T - tau) * tg3 ** 2 / 2 - b * f * xs1 * tg3,
                                                                            (T - tau) * tg3 - (x0 + x01) * xs1 * f * tg3])),
                        objection=("$x_3^1$ may be a quantity of its own, a distance of the dry part's centroid "
                                   "$x_3$ carried to the lower base."),
                        answer=("$x_3^1$ occurs in no formula, while (120), (121), (121b), (122) use $x_s^1$ with "
                                "$f$ as $F x_s$ with $F$; read as its own quantity (120) fails. $s$ read as $3$ is a "
                                "glyph confusion of the scan, but the print may have had it: medium.")),
        note="read through (120), the moments that use the distance defined here")
zw3 = lambda xx: -xx * tg3 + b  # noqa: E731  (height of the water plane z = -x tan phi_3 above the lower base z = -b)
d.quote("N1-lower-base", "VIII",
        r"bis auf den Punkt N, welcher hier (Fig. 20) in der unteren Grundfläche, dort in einer Seitenfläche liegt",
        reading=(zw3(sp.Integer(0)), 0),
        erratum=Erratum("transcription", "medium",
                        r"\text{bis auf den Punkt } N_1\text{, welcher hier (Fig. 20) in der unteren Grundfläche, dort "
                        r"in einer Seitenfläche liegt}",
                        ("$N$ is the foot on $GH$ of the perpendicular from $O$, in the upper base in both regions "
                         "(Fig. 18; the origin of $x$ in (118)-(121), and '$N N_2 = x_0 + x_0^1$' of (121a) runs in "
                         "the upper base). The point of the section's water line $N_1 N$ (Fig. 17) that lies on a "
                         "side face in the second region and in the lower base in the third is $N_1$: the same "
                         "sentence projects it ('$N_2$ die Projektion von $N_1$') and (121a) uses $N_1 N_2 = b$. On "
                         r"the water plane $z = -x \tan\varphi_3$ the point $N$ ($x = 0$) lies $b$ above the lower "
                         "base, $N_1$ ($x = x_0 + x_0^1$) in it. A lost subscript (medium: the print may have "
                         "dropped it)."),
                        corrected_reading=(zw3(x0 + x01), 0),
                        objection="N may be right: the sentence may mean the foot N of the perpendicular, whose "
                                  "place changes with the region.",
                        answer=("(121a) measures '$N N_2 = x_0 + x_0^1$' in the upper base, so $N$ stays there; the "
                                "point of the water line that moves from a side face to the lower base is $N_1$, "
                                "which the same sentence projects ('$N_2$ die Projektion von $N_1$'). A lost "
                                "subscript, scan or print: medium.")),
        note="read as the height above the lower base z = -b of the point on the water line (x = 0 for N)")
L122 = ((T - tau) * tg3 * (1 + tg3 ** 2 / 2) - F1 * b * (1 - s) * (x0 + b / 2 * tg3) - b * f * xs1 * (1 + tg3 ** 2))
d.quote("122", "(122)", r"$$\left. \begin{aligned} (T - \tau) \operatorname{tg} \varphi_3 \left( 1 + \frac{1}{2} "
        r"\operatorname{tg}^2 \varphi_3 \right) &= F_1 b (1 - s) \left( x_0 + \frac{b}{2} \operatorname{tg} \varphi_3 "
        r"\right) \\ &+ b \cdot f x_s^1 (1 + \operatorname{tg}^2 \varphi_3) \\ (x_0 + x_0^1) \operatorname{tg} \varphi_3 "
        r"&= b \\ (F x_s - f x_s^1) \operatorname{tg} \varphi_3 &= F_1 b (1 - s) \end{aligned} \right\} \quad (122)$$",
        reading=(sp.Matrix([L122, (x0 + x01) * tg3 - b, (F * xs - f * xs1) * tg3 - F1 * b * (1 - s)]),
                 sp.Matrix([M3c * tg3 / sn3, 0, 0])),
        note="each equation as left minus right side; the first is tan phi_3 M_3/sin phi_3 (zero at equilibrium)",
        condition="each equation is a condition of equilibrium, read as left minus right side; the first is the "
                  "identity tan phi_3 M_3/sin phi_3 it is imposed on")
