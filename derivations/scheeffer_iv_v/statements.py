"""What Scheeffer's sections IV and V say and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import Derivation, Eq, Erratum
from symfloat.model.claim import as_printed
from symfloat.model.symbol_names import symbol
from symfloat.model.vocabulary import Called, Compares, DecreasesWith, Is


# ---- symbols -------------------------------------------------------------------------------------------------
F1, T1, T11, b, s = sp.symbols("F_1 T_1 T_1^1 b s", positive=True)
P, P3, J = sp.symbols("P P_3 J", real=True)          # P = int_1 u v df, J = int_1 x y df
phi, mu, om = sp.symbols("varphi mu omega", positive=True)
Tx, Ty, T0, w = sp.symbols("T_x T_y T_0 w", positive=True)
u, v, x, y, z = sp.symbols("u v x y z", real=True)
u2, v2 = sp.symbols("u_2 v_2", real=True)
utop, ubot = sp.symbols("u_m u_m'", positive=True)   # farthest points of the upper (dipping) / lower (rising) base
eprime, c1, phi2 = sp.symbols("e^1 c_1 varphi_2", positive=True)   # the scan's / print's stray symbols
dfs = sp.Symbol("df", positive=True)
# results
V1, e1, zS, zS1, Mu, Mv, Mz = sp.symbols("V_1 e_1 z_S z_{S_1} M_u M_v M_z")
m, n, wax, phi1, M2, M3, M4, e2 = sp.symbols("m n w varphi_1 M_2 M_3 M_4 e_2")
rdf, ru, rv, T2, T21, P2, zeta = sp.symbols("r_{df} r_u r_v T_2 T_2^1 P_2 zeta")
Tmu, Tm, Tm1, Tmin, D2, Q, Dmu = sp.symbols("T(mu) T_m T_m^1 T_min D_2 Q D(mu)")
P2e, Tmue = symbol("P_2^{eq}", r"P_{2}^{\text{eq}}"), symbol("T_eq(mu)", r"T_{\text{eq}}(\mu)")
Uw, Vw, T1w, T11w, Iuv, Jsym, T1s, T1iso, Tmi = sp.symbols(
    "u_omega v_omega T_1(omega) T_1^1(omega) I_uv J_sym T_1^s T_1^iso T_m^iso")
T11iso, Tm1i = symbol("T_1^1iso", r"T_{1}^{1,\text{iso}}"), symbol("T_m^1iso", r"T_{m}^{1,\text{iso}}")
phtop, phbot, Lim = sp.symbols("varphi_top varphi_bot L")

DERIVATION = d = Derivation(
    id="scheeffer-iv-v",
    source="scheeffer",
    title="The tilted equilibrium of a right prism in the first rotation region; prisms with a symmetric base",
    locator="IV-V",
    summary="tan phi_1 = sqrt(2 (V_1 e_1/T_1 - 1)) with int u v df = 0; waterplane II has T_1/cos^3 and "
            "T_1^1/cos; the tilted position is stable iff T_1^1 > T_1; isotropic bases tilt in every direction "
            "(neutral about the axis across EF); the face limits tan phi <= b(1-s)/u_m, b s/u_m'.",
    requires=("scheeffer-i-iii",),
    domain={F1: (1, 3), T1: (sp.Rational(1, 10), 1), T11: (sp.Rational(1, 10), 1), b: (1, 4),
            s: (sp.Rational(1, 10), sp.Rational(9, 10)), P: (-sp.Rational(1, 5), sp.Rational(1, 5)),
            P3: (-1, 1), J: (-sp.Rational(1, 5), sp.Rational(1, 5)), phi: (sp.Rational(1, 10), 1),
            mu: (0, sp.Rational(3, 2)), om: (0, sp.Rational(3, 2)), Tx: (sp.Rational(1, 10), 1),
            Ty: (sp.Rational(1, 10), 1), T0: (sp.Rational(1, 10), 1), w: (sp.Rational(1, 5), 2),
            u: (-1, 1), v: (-1, 1), x: (-1, 1), y: (-1, 1), z: (-1, 1), u2: (-1, 1), v2: (-1, 1),
            utop: (sp.Rational(1, 5), 2), ubot: (sp.Rational(1, 5), 2), eprime: (sp.Rational(1, 10), 2),
            c1: (sp.Rational(1, 10), 2), phi2: (sp.Rational(1, 10), 1), dfs: (sp.Rational(1, 10), 1)},
    constraints=(F1 * b ** 2 * s * (1 - s) / 2 > T1, F1 * b ** 2 * s * (1 - s) / 2 > T0),
    assumptions=(
        "homogeneous right prism, base Omega of area F_1 (any plane figure), height b, specific gravity s "
        "(0 < s < 1), in water of specific gravity 1; upright it floats with the base horizontal, draught b s",
        "body frame: O = centroid of the waterplane I (of the base), u across the rotation axis EF (positive "
        "on the dipping side), v along EF, z along the prism axis; T_1 = int u^2 df, T_1^1 = int v^2 df, "
        "P = int u v df over the waterplane I",
        "first rotation region: the waterplane cuts only the side faces, neither base face (Scheeffer: 'bevor "
        "die obere Grundfläche eintaucht', 'so lange keine der beiden Grundflächen vom Wasserspiegel "
        "durchschnitten wird'); all formulas are exact there, for finite tilts",
        "the tilted equilibrium phi_1 exists (upright position unstable about EF): V_1 e_1 > T_1",
        "stability of a position: Duhamel's criterion (18) restated here: smallest moment of inertia of the "
        "waterplane about an axis through its centroid, minus V_1 times the height of S above S_2, positive",
        "section V: the x axis (DC) and y axis (AB) are principal axes of the waterplane I; EF makes the angle "
        "omega with AB; T_x = int y^2 df, T_y = int x^2 df, J = int x y df",
    ),
)


def area_integral(expr, a, c, moments):
    """int_Omega expr df for a polynomial expr in the coordinates a, c, termwise: moments maps the exponent
    pairs (i, j) of a^i c^j to the area moments (linearity of the integral).  The sum of coefficient times
    moment is left unevaluated, so that a step equating it to a closed form is checked by the engine."""
    poly = sp.Poly(sp.expand(expr), a, c)
    terms = []
    for (i, j), coeff in poly.terms():
        if (i, j) not in moments:
            raise ValueError(f"no area moment for {a}^{i} {c}^{j}")
        terms.append(sp.Mul(coeff, moments[(i, j)], evaluate=False))
    return sp.Add(*terms, evaluate=False) if len(terms) > 1 else terms[0] if terms else sp.Integer(0)


MOM_I = {(0, 0): F1, (1, 0): 0, (0, 1): 0, (2, 0): T1, (0, 2): T11, (1, 1): P}
MOM_XY = {(0, 0): F1, (1, 0): 0, (0, 1): 0, (2, 0): Ty, (0, 2): Tx, (1, 1): J}
NOTE_L = ("int over Omega termwise: int df = F_1, int u df = int v df = 0 (O is the centroid), int u^2 df = T_1, "
          "int v^2 df = T_1^1, int u v df = P")
tph = sp.tan(phi)

# ---- IV.0  the prism, upright and tilted: (12), (13) restated ------------------------------------------------
d.step("upright-volume", (V1, area_integral(sp.integrate(1, (z, -b * s, 0)), u, v, MOM_I), F1 * b * s),
       "integration", note="the part below the waterplane I, draught b s (Archimedes: F_1 b s = weight)", result=V1)
d.step("centroid-S", (zS, area_integral(sp.integrate(z, (z, -b * s, b * (1 - s))), u, v, MOM_I) / (F1 * b),
                      b * (1 - 2 * s) / 2), "integration", note="height of the centroid S of the prism above O",
       result=zS)
d.step("centroid-S1", (zS1, area_integral(sp.integrate(z, (z, -b * s, 0)), u, v, MOM_I) / V1, -b * s / 2),
       "integration", result=zS1)
d.step("e1", (e1, zS - zS1, b * (1 - s) / 2), "algebra", uses=("centroid-S", "centroid-S1"), result=e1)
d.step("volume-II", (area_integral(sp.integrate(1, (z, -b * s, u * tph)), u, v, MOM_I), V1), "integration",
       uses=("upright-volume",),
       note="the waterplane II through EF (z = u tan phi) cuts off the volume V_1 for every tilt of the first "
            "rotation region: the axis through the centroid O keeps the displacement (section II)")
d.step("moment-u", (Mu, area_integral(u * sp.integrate(1, (z, -b * s, u * tph)), u, v, MOM_I), T1 * tph),
       "integration", note=NOTE_L, result=Mu)
d.step("moment-v", (Mv, area_integral(v * sp.integrate(1, (z, -b * s, u * tph)), u, v, MOM_I), P * tph),
       "integration", note=NOTE_L, result=Mv)
d.step("moment-z", (Mz, area_integral(sp.integrate(z, (z, -b * s, u * tph)), u, v, MOM_I),
                    (T1 * tph ** 2 - F1 * b ** 2 * s ** 2) / 2), "integration", note=NOTE_L, result=Mz)
kup = sp.Matrix([-sp.sin(phi), 0, sp.cos(phi)])      # upward unit normal of z = u tan phi, in (u, v, z)
hor = sp.Matrix([sp.cos(phi), 0, sp.sin(phi)])       # horizontal, across EF, towards the dipping side
d.step("frame", (sp.Matrix([kup.dot(sp.Matrix([1, 0, tph])), kup.dot(sp.Matrix([0, 1, 0])), kup.dot(kup),
                            hor.dot(kup), hor.dot(hor)]), sp.Matrix([0, 0, 1, 0, 1])), "geometry",
       note="k is the unit normal of the waterplane II (vertical), h the horizontal across EF")
MS2 = sp.Matrix([Mu, Mv, Mz])                       # V_1 times the centroid S_2 of the tilted submerged part
S = sp.Matrix([0, 0, zS])
d.step("arm-m", Eq(m, hor.dot(MS2 - V1 * S) / V1), "definition", result=m,
       note="righting arm (Scheeffer's m, section I): horizontal distance of S_2 from S across EF, positive "
            "when the buoyancy turns the prism back")
d.step("height-n", Eq(n, kup.dot(V1 * S - MS2) / V1), "definition", result=n,
       note="n: height of S above S_2 (Scheeffer's A S_2)")
d.step("axis-w", Eq(wax, (MS2 - V1 * S)[1] / V1), "definition", result=wax,
       note="offset of S_2 from S along EF")
d.step("eq12", (V1 * m, sp.sin(phi) * ((1 + tph ** 2 / 2) * T1 - V1 * e1)), "algebra",
       uses=("moment-u", "moment-z", "arm-m", "e1", "scheeffer-i-iii:righting-moment-12"),
       note="Scheeffer (12), re-derived here from the exact column integrals of the prism (exact in the first "
            "rotation region); agrees with scheeffer-i-iii:righting-moment-12")
d.step("eq13", (V1 * n, T1 * sp.sin(phi) * tph / 2 + V1 * e1 * sp.cos(phi)), "algebra",
       uses=("moment-u", "moment-z", "height-n", "e1", "scheeffer-i-iii:moment-13"),
       note="Scheeffer (13), re-derived here; agrees with scheeffer-i-iii:moment-13")
slope = sp.Symbol("m'(0)")
d.step("upright-slope", (slope, sp.Limit(m / phi, phi, 0), T1 / V1 - e1), "limit", uses=("eq12",), result=slope,
       note="the arm grows like phi (T_1/V_1 - e_1): the criterion (18) for the axis EF")


def res(expr):
    """expr with the values established so far inserted (build time)."""
    r = d.results()
    for _ in range(30):
        new = expr.xreplace(r)
        if new == expr:
            return new
        expr = new
    return expr


# ---- IV.1  the first condition: tan phi_1 (27) -----------------------------------------------------------------
X = sp.Symbol("X", positive=True)
Qx = (1 + X ** 2 / 2) * T1 - V1 * e1
root = sp.sqrt(2 * (V1 * e1 / T1 - 1))
d.step("factor-Q", Eq(Q, (1 + tph ** 2 / 2) * T1 - V1 * e1), "definition", result=Q,
       note="the factor of sin phi in (12)")
d.step("Q-increasing", (sp.Derivative(Q, phi), T1 * tph * (1 + tph ** 2)), "algebra", uses=("factor-Q",),
       note="positive for 0 < phi < 90 deg: Q < 0 near the upright position grows to +oo, one zero")
d.step("root-check", (sp.Subs(Qx, X, root), 0), "algebra",
       note="Q = 0 is quadratic in tan phi, with the roots +-sqrt(2 (V1 e1/T1 - 1)); the positive one is this")
d.step("phi1", Eq(phi1, sp.atan(root)), "definition", uses=("root-check", "Q-increasing"), result=phi1,
       note="the tilted position: the zero of the righting moment (12) for phi > 0, provided V_1 e_1 > T_1")
t1 = sp.tan(phi1)

# ---- IV.2  the second condition (28)-(32) -----------------------------------------------------------------------
u3, v3 = sp.symbols("u_3 v_3", positive=True)
d.domain.update({u3: (sp.Rational(1, 10), 1), v3: (-1, 1)})
d.step("column-3", (sp.Integral(v3, (z, 0, u3 * t1)), u3 * v3 * t1), "integration",
       note="moment of the column over df (height z = u_3 tan phi_1) about the vertical plane through OS "
            "across EF, per unit df")
d.step("M3", Eq(M3, t1 * P3), "definition", uses=("column-3",), result=M3,
       note="P_3 = int_3 u v df over FHE, the dipping part of the waterplane I")
d.step("M4", Eq(M4, t1 * (P3 - P)), "definition", uses=("column-3",), result=M4,
       note="int_4 u_4 v_4 df = P_3 - P: the rising part FGE with u_4 = -u (P = int_3 + int_4 u v df)")
d.step("M2", (M2, res(Mv).subs(phi, phi1), M3 - M4, P * t1), "algebra", uses=("moment-v", "M3", "M4"),
       note="the old submerged part has the moment V_1 * 0 (v centroid 0); M_2 = V_1 w at phi_1", result=M2)
d.step("e2", Eq(e2, res(n).subs(phi, phi1)), "definition", result=e2,
       note="at an equilibrium S lies vertically above S_2, so e_2 = |S S_2| = n (checked next)")
d.step("e2-vertical", (sp.Matrix([res(m).subs(phi, phi1), res(wax).subs(phi, phi1).subs(P, 0)]), sp.Matrix([0, 0])),
       "algebra", uses=("arm-m", "axis-w", "phi1"), note="both horizontal offsets vanish at phi_1 when P = 0")
d.step("eq35", (V1 * e2, T1 * (sp.cos(phi1) + sp.sin(phi1) * t1), T1 / sp.cos(phi1)), "algebra",
       uses=("eq13", "e2", "phi1"))

# ---- IV.3  the waterplane II (36)-(42) --------------------------------------------------------------------------
pt = sp.Matrix([u, v, u * sp.tan(phi1)])              # the point of II above (u, v) of I
hor1, ev = hor.subs(phi, phi1), sp.Matrix([0, 1, 0])
d.step("coords-II", (sp.Matrix([pt.dot(hor1), pt.dot(ev)]), sp.Matrix([u / sp.cos(phi1), v])), "geometry",
       note="coordinates of that point in II: u_2 across EF, v_2 along EF")
jac = sp.Matrix([1, 0, sp.tan(phi1)]).cross(sp.Matrix([0, 1, 0]))
d.step("area-II", (sp.sqrt(jac.dot(jac)), 1 / sp.cos(phi1)), "geometry",
       note=r"area element: $df_2 = |\partial p/\partial u \times \partial p/\partial v| \, df = df/\cos \varphi_1$")
d.step("ratio-df", Eq(rdf, sp.cos(phi1)), "definition", uses=("area-II",), result=rdf, note="df/df_2")
d.step("ratio-u", Eq(ru, sp.cos(phi1)), "definition", uses=("coords-II",), result=ru, note="u/u_2")
d.step("ratio-v", Eq(rv, 1), "definition", uses=("coords-II",), result=rv, note="v/v_2")
c = sp.cos(phi1)
d.step("T2", (T2, area_integral((u / c) ** 2 / c, u, v, MOM_I), T1 / c ** 3), "integration",
       uses=("coords-II", "area-II"), note="int_2 u_2^2 df_2 pulled back to I: " + NOTE_L, result=T2)
d.step("T21", (T21, area_integral(v ** 2 / c, u, v, MOM_I), T11 / c), "integration",
       uses=("coords-II", "area-II"), result=T21)
d.step("P2", (P2, area_integral((u / c) * v / c, u, v, MOM_I), P / c ** 2), "integration",
       uses=("coords-II", "area-II"), result=P2)
d.step("P2-eq", (P2e, sp.Subs(P2, P, 0), 0), "substitution", uses=("P2",), result=P2e,
       note="at the equilibrium int_1 u v df = 0 (31)")
MOM_II = {(2, 0): T2, (0, 2): T21, (1, 1): P2}
zdist = sp.Matrix([u2, v2]).dot(sp.Matrix([sp.cos(mu), sp.sin(mu)]))
d.step("zeta", Eq(zeta, zdist), "definition", result=zeta,
       note="distance of (u_2, v_2) from the axis PQ through O with direction (-sin mu, cos mu): PQ makes the "
            "angle mu with EF, turned towards -u_2 (Fig. 11 is missing: the orientation of mu is free)")
d.step("T-mu", (Tmu, area_integral(zdist ** 2, u2, v2, MOM_II),
                T2 * sp.cos(mu) ** 2 + T21 * sp.sin(mu) ** 2 + sp.sin(2 * mu) * P2), "integration",
       note="int_2 zeta^2 df_2 termwise with T_2, T_2^1, int_2 u_2 v_2 df_2", result=Tmu)
d.step("T-mu-eq", (Tmue, sp.Subs(Tmu, P, 0), T2 * sp.cos(mu) ** 2 + T21 * sp.sin(mu) ** 2), "substitution",
       uses=("T-mu", "P2-eq"), result=Tmue)
d.step("T-mu-between", (Tmue, T2 + (T21 - T2) * sp.sin(mu) ** 2), "algebra", uses=("T-mu-eq",),
       note="T(mu) lies between T_2 and T_2^1: its extreme values are taken at mu = 0 and 90 deg")
d.step("Tm", (Tm, sp.Subs(Tmue, mu, 0), T2), "substitution", uses=("T-mu-eq",), result=Tm)
d.step("Tm1", (Tm1, sp.Subs(Tmue, mu, sp.pi / 2), T21), "substitution", uses=("T-mu-eq",), result=Tm1)
d.step("Tmin", Eq(Tmin, sp.Min(Tm, Tm1)), "definition", uses=("T-mu-between",), result=Tmin)
d.step("D2", Eq(D2, Tmin - V1 * e2), "definition", result=D2,
       note="Duhamel's criterion (18) for the position phi_1: V_1 times its metacentric height, the smallest "
            "moment of inertia of II minus V_1 times the height of S above S_2")
d.step("D2-value", (D2, sp.Min(T1 / c ** 3, T11 / c) - T1 / c), "substitution",
       uses=("D2", "Tm", "Tm1", "T2", "T21", "eq35"))
d.step("D2-cases", (D2, sp.Min(T1 * sp.tan(phi1) ** 2, T11 - T1) / c), "algebra", uses=("D2-value",),
       note="T_1/cos^3 - T_1/cos = T_1 tan^2 phi_1/cos > 0, so D_2 < 0 exactly when T_1^1 < T_1")
d.step("D-mu", Eq(Dmu, Tmue - V1 * e2), "definition", result=Dmu,
       note="the stability of the position phi_1 about the axis through O at the angle mu with EF: the moment of "
            "inertia of II about that axis minus V_1 e_2 (Duhamel (18) for one axis; D_2 is its least value)")
# the quantities the text names in words (symfloat/model/vocabulary.json), by the formulas that define them here:
# the Drehungsmoment by the righting moment V_1 m of the turn phi about EF (12), the stability of the tilted position
# phi_1 by Duhamel's quantity for the axis at the angle mu
d.defines("righting moment", V1 * m)
d.defines("stability", Dmu)

# ---- V  principal axes of the waterplane I ------------------------------------------------------------------
d.step("rotation-44", (sp.Matrix([Uw, Vw]), sp.Matrix([y * sp.sin(om) + x * sp.cos(om),
                                                      y * sp.cos(om) - x * sp.sin(om)])), "definition",
       note="u, v in the principal coordinates x (DC), y (AB): EF has the direction (-sin omega, cos omega), "
            "the angle omega with AB")
d.step("rotation-orthogonal", ((y * sp.sin(om) + x * sp.cos(om)) ** 2 + (y * sp.cos(om) - x * sp.sin(om)) ** 2,
                               x ** 2 + y ** 2), "geometry", note="a rotation: lengths are kept")
d.step("rotation-result-u", Eq(Uw, y * sp.sin(om) + x * sp.cos(om)), "definition", result=Uw)
d.step("rotation-result-v", Eq(Vw, y * sp.cos(om) - x * sp.sin(om)), "definition", result=Vw)
Uv, Vv = y * sp.sin(om) + x * sp.cos(om), y * sp.cos(om) - x * sp.sin(om)
d.step("Iuv", (Iuv, area_integral(Uv * Vv, x, y, MOM_XY),
               sp.Rational(1, 2) * (Tx - Ty) * sp.sin(2 * om) + J * sp.cos(2 * om)), "integration",
       note="int_1 u v df in the principal coordinates, termwise (T_x = int y^2, T_y = int x^2, J = int x y)",
       result=Iuv)
d.step("T1w", (T1w, area_integral(Uv ** 2, x, y, MOM_XY),
               Tx * sp.sin(om) ** 2 + Ty * sp.cos(om) ** 2 + J * sp.sin(2 * om)), "integration", result=T1w)
d.step("T11w", (T11w, area_integral(Vv ** 2, x, y, MOM_XY),
                Tx * sp.cos(om) ** 2 + Ty * sp.sin(om) ** 2 - J * sp.sin(2 * om)), "integration", result=T11w)
d.step("symmetric-J", (Jsym, sp.Integral(x, (x, -w, w)), 0), "integration", result=Jsym,
       note="y axis a symmetry axis: each chord y = const is [-w, w]; int x y df = int y (int_{-w}^{w} x dx) dy")
d.step("T1-symmetric", (T1s, sp.Subs(T1w, J, Jsym), Tx * sp.sin(om) ** 2 + Ty * sp.cos(om) ** 2),
       "substitution", uses=("T1w", "symmetric-J"), result=T1s)
d.step("T1-isotropic", (T1iso, sp.Subs(T1s, (Tx, Ty), (T0, T0)), T0), "substitution", uses=("T1-symmetric",),
       result=T1iso, note="T_x = T_y = T_0")
d.step("T11-isotropic", (T11iso, sp.Subs(T11w, (J, Tx, Ty), (0, T0, T0)), T0), "substitution",
       uses=("T11w", "symmetric-J"), result=T11iso)
d.step("Tm-isotropic", (Tmi, sp.Subs(Tm, T11, T1), T1 / c ** 3), "substitution", uses=("Tm",), result=Tmi,
       note="isotropic base: T_1^1 = T_1 for every axis (T_1 the common value)")
d.step("Tm1-isotropic", (Tm1i, sp.Subs(Tm1, T11, T1), T1 / c), "substitution", uses=("Tm1",), result=Tm1i)

# ---- V  face limits (53)-(55) ----------------------------------------------------------------------------------
d.step("top-contact", Eq(phtop, sp.atan(b * (1 - s) / utop)), "definition", result=phtop,
       note="the plane z = u tan phi reaches the upper base z = b (1 - s) first at its farthest dipping point "
            "u = u_m")
d.step("top-contact-check", (utop * sp.tan(phtop), b * (1 - s)), "geometry", uses=("top-contact",))
d.step("bottom-contact", Eq(phbot, sp.atan(b * s / ubot)), "definition", result=phbot,
       note="the plane z = u tan phi reaches the lower base z = -b s first at its farthest rising point "
            "u = -u_m'")
d.step("bottom-contact-check", (-ubot * sp.tan(phbot), -b * s), "geometry", uses=("bottom-contact",))
d.step("limit", Eq(Lim, sp.Min(sp.tan(phtop), sp.tan(phbot))), "definition", result=Lim,
       note="the first rotation region: tan phi up to the first contact of either base")
sstar = sp.Symbol("s^*")
d.solve("threshold", Eq(b * (1 - s) / utop, b * s / ubot), s, sstar, simplify=False, check=False,
        note="the specific gravity at which both bases are reached at the same tilt (sympy.solve)")
d.step("top-first", (sp.sign(sp.tan(phbot) - sp.tan(phtop)), sp.sign(s - sstar)), "algebra",
       uses=("top-contact", "bottom-contact", "threshold"),
       note="the upper base is reached first iff s > s^* = u_m'/(u_m + u_m'), which is 1/2 only when u_m = u_m'")

# ==== printed formulas =========================================================================================
RED = "(18) restated"
d.quote("stable-18", "IV", r"$$\frac{T_1}{V_1} - e_1 > 0.$$", reading=(slope, T1 / V1 - e1),
        note="read as the quantity whose sign decides (the slope of the righting arm at the upright position); "
             + RED)
d.quote("unstable-18", "IV", r"$$\frac{T_1}{V_1} - e_1 < 0,$$", reading=(slope, T1 / V1 - e1),
        note="as stable-18, the labile case")
d.quote("stable-18-words", "IV", "Das Gleichgewicht ist stabil (18), wenn",
        reading=(sp.sign(slope), sp.sign(T1 / V1 - e1)), note="the slope of the righting arm at the upright position")
d.quote("labile-turns-on", "IV",
        "so ist das Gleichgewicht für diese Achse labil und das Prisma wird, wenn äussere Kräfte es um einen noch so "
        "kleinen Winkel um diese Achse drehen, durch Schwerkraft und Auftrieb weiter gedreht",
        reading=(sp.sign(slope), sp.sign(T1 / V1 - e1)),
        note="(12): the arm grows like phi (T_1/V_1 - e_1), negative when the criterion fails")
d.quote("moment-12", "IV (12)",
        r"$$V_1 m = \sin \varphi \cdot \left\{ \left( 1 + \frac{1}{2} \operatorname{tg}^2 \varphi \right) T_1 - "
        r"V_1 e_1 \right\}$$",
        reading=(V1 * m, sp.sin(phi) * ((1 + tph ** 2 / 2) * T1 - V1 * e1)))
d.quote("moment-zero", "IV (27)",
        r"$$\left( 1 + \frac{1}{2} \operatorname{tg}^2 \varphi_1 \right) T_1 - V_1 e_1 = 0$$",
        reading=((1 + t1 ** 2 / 2) * T1 - V1 * e1, 0))
d.says("Q-decreasing", "IV",
       "Dann wird aber das Drehungsmoment, dessen negativer Faktor (absolut genommen) mit wachsendem  $\\varphi$  "
       "kleiner wird", "Drehungsmoment",
       DecreasesWith(X, per=-sp.sin(phi), at={phi: sp.atan(X)}, domain={X: (0, sp.oo)}),
       note="Read as: the factor of sin(phi) in (12) taken with the opposite sign (its absolute value where it is "
            "negative), V_1 e_1 - (1 + tg^2/2) T_1, decreases as phi grows from 0 to 90 deg, i.e. as X = tg(phi) "
            "grows from 0 (tg increases there): its derivative in X is -T_1 X. So the factor vanishes once, at "
            "phi_1 (27).")
d.says("moment-zero-words", "IV",
       "Dann wird aber das Drehungsmoment, dessen negativer Faktor (absolut genommen) mit wachsendem  $\\varphi$  "
       "kleiner wird, für einen genügend grossen Drehungswinkel  $\\varphi_1$  gleich Null werden.",
       "Drehungsmoment", Is(0, at={phi: phi1}),
       note="Read as: the righting moment (12) vanishes at the tilt phi_1 of (27).")
d.quote("small-negative", "IV", "für noch so kleines  $\\varphi$  negativ ist.",
        reading=(slope, T1 / V1 - e1), note="V_1 m = phi V_1 (T_1/V_1 - e_1) + O(phi^3): negative for every small phi "
                                            "when the criterion fails")
d.quote("27", "(27)", r"$$\text{oder} \quad \operatorname{tg} \varphi_1 = \sqrt{2 \left( \frac{V_1 e_1}{T_1} - 1 "
                      r"\right)} \quad (27)$$", reading=(t1, sp.sqrt(2 * (V1 * e1 / T1 - 1))))
d.quote("first-condition", "IV (27)",
        "das statische Moment des eintauchenden Teils für die durch den Schwerpunkt S parallel zur Drehungsachse "
        "gelegte Vertikalebene ( $V_1 m$ ) ist Null.", reading=(sp.Subs(V1 * m, phi, phi1), 0),
        note="at the tilt phi_1 of (27) the moment V_1 m vanishes")
d.quote("second-plane", "IV (28)",
        "Für diese Ebene muss das statische Moment des eintauchenden Körperteils gleich Null sein.",
        reading=(M2, P * t1), note="the moment M_2 = V_1 w about the plane through OS across EF is tg phi_1 int_1 u v "
                                   "df: zero exactly when (31) holds")
d.quote("second-plane-1", "IV (28)",
        "noch für eine zweite durch S gelegte Vertikal-ebene gleich Null sein.", reading=(M2, P * t1),
        note="the second condition of (1): the moment about the vertical plane through S across the axis; with "
             "M_2 = tg phi_1 int_1 u v df it is (31)")
d.quote("old-part-zero", "IV (28)",
        "so muss, da das statische Moment des vorher eintauchenden Teils (G H J K) gleich Null ist, offenbar",
        reading=(M2, M3 - M4), note="the old submerged part has its centroid in the plane (moment V_1 * 0, step M2)")
d.quote("28", "(28)", r"$$M_2 = M_3 - M_4 = 0 \text{ sein.} \quad (28)$$", reading=(M2, M3 - M4),
        note="the '= 0' is the equilibrium condition imposed, read with (32)")
d.quote("element-moment", "IV (29)",
        r"$$df \cdot z \cdot v_3 = u_3 \cdot v_3 \cdot df \cdot \operatorname{tg} \varphi_1$$",
        reading=(dfs * sp.Integral(1, (z, 0, u3 * t1)) * v3, u3 * v3 * dfs * t1),
        symbols={"z": (u3 * t1, "z is the height of the column over df, u_3 tg phi_1 (the text before); the "
                                "reading integrates dz over it")})
u4, v4 = sp.Symbol("u_4", positive=True), sp.Symbol("v_4", real=True)
d.domain.update({u4: (sp.Rational(1, 10), 1), v4: (-1, 1)})
d.quote("column-height", "IV (29)", r"$z = u_3 \cdot \operatorname{tg} \varphi_1$",
        reading=(sp.Integral(1, (z, 0, u3 * t1)), u3 * t1), note="the column over df at the distance u_3 from EF")
d.quote("column-4-moment", "IV (30)", r"$u_4 v_4 \cdot df \cdot \operatorname{tg} \varphi_1$",
        reading=(dfs * sp.Integral(v4, (z, 0, u4 * t1)), u4 * v4 * dfs * t1),
        note="its moment about the vertical plane through OS across EF (lever v_4)")
d.quote("column-4-height", "IV (30)", r"$z df = u_4 \cdot \operatorname{tg} \varphi_1 \cdot df$",
        reading=(dfs * sp.Integral(1, (z, 0, u4 * t1)), u4 * t1 * dfs),
        note="the emerged column over df at the distance u_4 from EF",
        symbols={"z": (u4 * t1, "z is the height of the emerged column over df, u_4 tg phi_1 (the formula itself); "
                                "the reading integrates dz over it")})
d.quote("29", "(29)", r"$$M_3 = \int_3 u_3 v_3 \cdot df \cdot \operatorname{tg} \varphi_1, \quad (29)$$",
        reading=(M3, P3 * t1))
d.quote("30-M4", "IV (30)", r"$$M_4 = \int_4 u_4 v_4 \cdot df \cdot \operatorname{tg} \varphi_1$$",
        reading=(M4, (P3 - P) * t1), note="unnumbered in the transcription; (30) by its place")
d.quote("M2-difference", "IV (31)",
        r"$$M_2 = \int_3 u_3 v_3 \cdot df \cdot \operatorname{tg} \varphi_1 - \int_4 u_4 v_4 \cdot df \cdot "
        r"\operatorname{tg} \varphi_1$$", reading=(M2, P3 * t1 - (P3 - P) * t1))
d.quote("u4-minus-u3", "IV (31)",
        "oder, wenn wir beide Summen zusammenfassen (da  $u_4$  mit  $-u_3$  bezeichnet werden kann)",
        reading=(M3 - M4, P * t1), note="with u = -u_4 on the rising side the two sums are int_1 u v df tg phi_1")
d.quote("31", "(31)", r"$$\left. \begin{aligned} M_2 &= \int_1 u v \cdot df \cdot \operatorname{tg} \varphi_1 = 0 "
                      r"\\ \text{oder } \int_1 u v \cdot df &= 0 \end{aligned} \right\} \quad (31)$$",
        reading=(M2, P * t1), note="the identity M_2 = tan phi_1 int_1 u v df; '= 0' is the condition imposed")
d.quote("32-from", "(32)",
        "Die beiden Bedingungsgleichungen für die zweite Gleichgewichtslage ( $\\varphi_1$ ) stelle ich (aus 27 und 31) "
        "hier zusammen:",
        reading=(sp.Matrix([V1 * res(m).subs(phi, phi1) / sp.sin(phi1), M2 / t1]),
                 sp.Matrix([T1 * (1 + t1 ** 2 / 2) - V1 * e1, P])),
        note="(27) is the first, (31) the second condition: the two moments over their factors sin phi_1, tg phi_1")
d.quote("32", "(32)", r"$$\left. \begin{aligned} T_1 \left( 1 + \frac{1}{2} \operatorname{tg}^2 \varphi_1 \right) "
                      r"- V_1 e^1 &= 0 \\ \int_1 u v \cdot df &= 0 \end{aligned} \right\} \quad (32)$$",
        reading=(sp.Matrix([V1 * res(m).subs(phi, phi1) / sp.sin(phi1), M2 / t1]),
                 sp.Matrix([T1 * (1 + t1 ** 2 / 2) - V1 * eprime, P])),
        note="the two equilibrium moments over their factors sin phi_1, tan phi_1 must vanish",
        erratum=Erratum("transcription", "medium", r"T_1 \left(1 + \tfrac12 \operatorname{tg}^2\varphi_1\right) - "
                        r"V_1 e_1 = 0",
                        "The transcription has $V_1 e^1$, a quantity never defined; the same condition two lines "
                        "earlier (and (27), (34)) reads $V_1 e_1$. Scheeffer writes superscript 1 for a prime "
                        "($T_1^1$), so $e^1$ is a misplaced index of the scan rather than a new symbol; a slip of "
                        "the printer cannot be excluded.",
                        corrected_reading=(sp.Matrix([V1 * res(m).subs(phi, phi1) / sp.sin(phi1), M2 / t1]),
                                           sp.Matrix([T1 * (1 + t1 ** 2 / 2) - V1 * e1, P])),
                        objection="$e^1$ may be a symbol of its own: Scheeffer writes a superscript 1 for a prime "
                                  "($T_1^1$), so $V_1 e^1$ could name a second distance $e'$ of the section.",
                        answer="No e with a superscript is defined anywhere, and the same condition two lines "
                               "earlier, like (27) and (34), reads $V_1 e_1$; an index set high instead of low is "
                               "the scan's usual fault, but the print may have had it, hence medium."))
d.quote("33-words", "(33)",
        "Soll nun die Gleichgewichtslage ( $\\varphi_1$ ) eine stabile sein, so muss nach dem Duhamel'schen Satze (18)",
        reading=(D2, sp.Min(T1 / c ** 3, T11 / c) - T1 / c),
        note="Duhamel for the tilted position: the smallest moment of II minus V_1 e_2 (D2-value)")
d.quote("33", "(33)", r"$$T_m - V_1 e_2 > 0 \quad (33)$$", reading=(D2, Tmin - V1 * e2),
        note="T_m here is the smallest moment of inertia of II; read as the quantity whose sign decides")
d.quote("13-restated", "IV (13)",
        r"$$V_1 n = \frac{1}{2} T_1 \sin \varphi \cdot \operatorname{tg} \varphi + V_1 e_1 \cos \varphi$$",
        reading=(V1 * n, T1 * sp.sin(phi) * tph / 2 + V1 * e1 * sp.cos(phi)))
d.quote("n-e2", "IV (34)", r"$n = e_2$", reading=(sp.Subs(n, phi, phi1), e2),
        note="at the equilibrium phi_1, S_2 lies vertically below S (m = 0), so n = A S_2 = S S_2")
d.quote("34", "(34)", r"$$V_1 e_2 = \frac{1}{2} T_1 \sin \varphi_1 \cdot \operatorname{tg} \varphi_1 + V_1 e_1 "
                      r"\cos \varphi_1 \quad (34)$$",
        reading=(V1 * e2, T1 * sp.sin(phi1) * t1 / 2 + V1 * e1 * sp.cos(phi1)))
d.quote("32-restated", "IV (34)",
        r"$$V_1 e_1 = T_1 \left( 1 + \frac{1}{2} \operatorname{tg}^2 \varphi_1 \right)$$",
        reading=(V1 * e1, T1 * (1 + t1 ** 2 / 2)))
d.quote("35", "(35)", r"$$\begin{aligned} V_1 e_2 &= T_1 (\cos \varphi_1 + \sin \varphi_1 \cdot \operatorname{tg} "
                      r"\varphi_1) \\ \text{oder } V_1 e_2 &= \frac{T_1}{\cos \varphi_1} \end{aligned} \quad (35)$$",
        reading=(V1 * e2, T1 * (sp.cos(phi1) + sp.sin(phi1) * t1), T1 / sp.cos(phi1)))
d.quote("36", "(36)", r"$$\zeta = u_2 \cos \mu + v_2 \sin \mu, \quad (36)$$", reading=(zeta, u2 * sp.cos(mu) + v2 * sp.sin(mu)),
        note="holds with mu turned from EF towards -u_2; Fig. 11, which fixes the orientation, is missing")
d.quote("37", "(37)", r"$$\begin{aligned} T &= \int_2 \zeta^2 df_2 = \cos^2 \mu \int_2 u_2^2 df_2 + \sin^2 \mu "
                      r"\int_2 v_2^2 df_2 + \sin 2 \mu \int_2 u_2 v_2 \cdot df_2 \\ \text{oder } T &= T_2 \cdot "
                      r"\cos^2 \mu + T_2^1 \cdot \sin^2 \mu + \sin 2 \mu \int_2 u_2 v_2 \cdot df. \end{aligned} "
                      r"\quad (37)$$",
        reading=as_printed(lambda: (Tmu, sp.cos(mu) ** 2 * T2 + sp.sin(mu) ** 2 * T21 + sp.sin(2 * mu) * P2,
                 T2 * sp.cos(mu) ** 2 + T21 * sp.sin(mu) ** 2 + sp.sin(2 * mu) * rdf * P2)),
        note="the last integral of the second line is printed with df, the element of the waterplane I "
             "(df = df_2 cos phi_1, ratio-df), over the waterplane II: int_2 u_2 v_2 df = cos phi_1 int_2 u_2 v_2 df_2",
        erratum=Erratum("transcription", "low",
                        r"T = T_2 \cos^2 \mu + T_2^1 \sin^2 \mu + \sin 2\mu \int_2 u_2 v_2 \, df_2",
                        r"The first line of (37) has $\sin 2\mu \int_2 u_2 v_2 df_2$; the second, which only renames "
                        r"$\int_2 u_2^2 df_2$ and $\int_2 v_2^2 df_2$ as $T_2$ and $T_2^1$, repeats the term with "
                        "$df$. The text defines $df$ as the element of the waterplane I, the projection of $df_2$ "
                        r"(next line; (38*) pairs $\int_2$ with $df_2$ and $\int_1$ with $df$ throughout), so $\int_2 "
                        r"u_2 v_2 df$ differs from $\int_2 u_2 v_2 df_2$ by the factor $\cos \varphi_1$ unless the "
                        "integral vanishes. Harmless for (39), (40), where it is zero. A lost subscript 2: more "
                        "likely the scan's than the printer's, but the text cannot tell (low).",
                        corrected_reading=as_printed(lambda: (Tmu, sp.cos(mu) ** 2 * T2 + sp.sin(mu) ** 2 * T21 + sp.sin(2 * mu) * P2,
                                                              T2 * sp.cos(mu) ** 2 + T21 * sp.sin(mu) ** 2 + sp.sin(2 * mu) * P2)),
                        objection="df in the second line may be Scheeffer's loose writing for the element of "
                                  r"whatever plane the integral's index names, $\int_2 \dots df$ meaning the integral "
                                  "over plane II.",
                        answer=r"The first line of (37) writes $df_2$ under $\int_2$, and the next lines (38*) keep "
                               r"$df_2$ with $\int_2$ and $df$ with $\int_1$ apart, the two differing by $\cos "
                               r"\varphi_1$; so the print distinguishes them here too. Whether print or scan lost the "
                               "subscript 2 cannot be told, and the term vanishes in (39), (40): low."))
d.quote("38-projection", "(38)", r"$$df = \frac{df_2}{\cos \varphi_1} \quad u = \frac{u_2}{\cos \varphi_1} \quad "
                                 r"v = \frac{v_2}{\cos \varphi_1}$$",
        reading=(sp.Matrix([rdf, ru, rv]), sp.Matrix([1 / sp.cos(phi1)] * 3)),
        note="read as the ratios df/df_2, u/u_2, v/v_2",
        erratum=Erratum("misprint", "medium",
                        r"df_2 = \frac{df}{\cos\varphi_1},\quad u_2 = \frac{u}{\cos\varphi_1},\quad v_2 = v",
                        "The waterplane I is the projection of II along the prism axis: lengths across EF shrink by "
                        r"$\cos \varphi_1$, lengths along EF are kept, so $df = df_2 \cos \varphi_1, u = u_2 \cos "
                        r"\varphi_1, v = v_2$. The printed relations invert the first two and wrongly scale $v$; the "
                        r"next lines (38*) are right and need exactly the corrected relations ($\int_1 v^2 df / \cos "
                        r"\varphi_1$ needs $v_2 = v$). Three consistent inversions are unlikely to be a scan fault: a "
                        "slip of the author or printer (roles of the planes exchanged), medium confidence.",
                        corrected_reading=(sp.Matrix([rdf, ru, rv]), sp.Matrix([sp.cos(phi1), sp.cos(phi1), 1])),
                        objection="The roles of the planes may be as printed if plane II, not I, is the projection; "
                                  r"then $df = df_2/\cos \varphi_1$ and $u = u_2/\cos \varphi_1$ would be right.",
                        answer=r"$v = v_2/\cos \varphi_1$ is wrong in either direction, since lengths along EF are "
                               r"kept by the projection, and (38*) that follows needs $v_2 = v$ ($\int_1 v^2 df / "
                               r"\cos \varphi_1$) and $df = df_2 \cos \varphi_1$. Three coherent inversions are no "
                               "scan fault; author or printer cannot be told, hence medium."))
d.quote("38", "(38)", r"$$\left. \begin{aligned} T_2 &= \int_2 u_2^2 df_2 = \int_1 \frac{u^2 \cdot df}{\cos^3 "
                      r"\varphi_1} = \frac{T_1}{\cos^3 \varphi_1} \\ T_2^1 &= \int_2 v_2^2 df_2 = \int_1 \frac{v^2 "
                      r"df}{\cos \varphi_1} = \frac{T_1^1}{\cos \varphi_1} \\ \int_2 u_2 v_2 df_2 &= \frac{1}"
                      r"{\cos^2 \varphi_1} \cdot \int u \cdot v \cdot df \end{aligned} \right\} (38^*)$$",
        reading=(sp.Matrix([T2, T21, P2]), sp.Matrix([T1 / c ** 3, T11 / c, P / c ** 2])),
        note="the star is the footnote mark for T_1^1")
d.quote("39", "(39)", r"$$\int_2 u_2 v_2 df_2 = 0 \quad (39)$$", reading=(P2e, 0))
d.quote("40", "(40)", r"$$T = T_2 \cdot \cos^2 \mu + T_2^1 \cdot \sin^2 \mu \quad (40)$$",
        reading=(Tmue, T2 * sp.cos(mu) ** 2 + T21 * sp.sin(mu) ** 2))
d.quote("dT-zero", "(40)", r"$$\frac{dT}{d\mu} = 0 \text{ sein, also}$$",
        reading=(sp.Matrix([sp.Subs(sp.Derivative(Tmue, mu), mu, 0), sp.Subs(sp.Derivative(Tmue, mu), mu, sp.pi / 2)]),
                 sp.zeros(2, 1)),
        note="read at the extreme values of T (mu = 0, 90 deg, T-mu-between): the derivative vanishes there")
d.quote("dT", "(40)", r"$$(T_2^1 - T_2) \cdot \sin 2\mu = 0$$",
        reading=(sp.Derivative(Tmue, mu), (T21 - T2) * sp.sin(2 * mu)), note="the left side is dT/dmu")
d.quote("nonzero-difference", "(40)", "oder, da  $(T_2^1 - T_2)$  im Allgemeinen von Null verschieden sein wird,",
        reading=(sp.Derivative(Tmue, mu) / (T21 - T2), sp.sin(2 * mu)),
        note="dividing dT/dmu by T_2^1 - T_2 (not zero) leaves sin 2 mu")
d.quote("mu-0-90", "(40)", r"$$\sin 2\mu = 0, \quad \mu = \begin{cases} 0 \\ 90^\circ \end{cases}$$",
        reading=(sp.Matrix([sp.Subs(sp.Derivative(Tmue, mu), mu, 0), sp.Subs(sp.Derivative(Tmue, mu), mu, sp.pi / 2)]),
                 sp.Matrix([0, 0])))
d.quote("extremes-40", "(41)",
        "Diese beiden Werte für  $\\mu$  geben aus 40 das kleinste und das grösste der Trägheitsmomente T:",
        reading=(Tmue, T2 + (T21 - T2) * sp.sin(mu) ** 2),
        note="T(mu) = T_2 + (T_2^1 - T_2) sin^2 mu lies between its values at mu = 0 and 90 deg")
d.quote("41", "(41)", r"$$\left. \begin{aligned} T_m &= T_2 \\ T_m^1 &= T_2^1 \end{aligned} \right\} (41)$$",
        reading=(sp.Matrix([Tm, Tm1]), sp.Matrix([T2, T21])),
        note="T_m, T_m^1: the two extreme values (at mu = 0, 90 deg), not ordered")
d.quote("42-from", "(42)", "Die Werte für diese beiden Trägheitsmomente ergeben sich aus 38 und 41:",
        reading=(sp.Matrix([Tm, Tm1]), sp.Matrix([T1 / c ** 3, T11 / c])), note="(41) with (38*)")
d.quote("42", "(42)", r"$$\left. \begin{aligned} T_m &= \frac{T_1}{\cos^3 \varphi_1} \\ T_m^1 &= \frac{T_1^1}{\cos "
                      r"\varphi_1} \end{aligned} \right\} (42)$$",
        reading=(sp.Matrix([Tm, Tm1]), sp.Matrix([T1 / c ** 3, T11 / c])))
d.quote("43", "(43)", r"$$T - \frac{T_1}{\cos \varphi_1} > 0 \quad (43)$$", reading=(D2, Tmin - T1 / c),
        note="T the smaller of T_m, T_m^1; read as the quantity whose sign decides")
d.quote("T-smaller", "(43)",
        "wo für T der kleinste Wert, d. h. der kleinere von den beiden Werten  $T_m$  und  $T_m^1$  zu setzen ist.",
        reading=(D2, sp.Min(Tm, Tm1) - V1 * e2),
        note="Duhamel's T is the smallest moment of II about axes through its centroid; by (40) T(mu) lies between "
             "its values T_m, T_m^1 at mu = 0, 90 deg")
d.quote("T-Tm", "(43)", r"Es ist aber für  $T = T_m$  (s. 42)", reading=(Tm, T1 / c ** 3),
        note="the reference: (42) gives T_m = T_1/cos^3 phi_1, the value inserted next",
        not_compared="an assignment (T is set to T_m in (43)); the reading states the value (42) gives T_m")
d.quote("43-Tm", "(43)", r"$$T - \frac{T_1}{\cos \varphi_1} = \frac{T_1}{\cos^3 \varphi_1} - \frac{T_1}{\cos "
                         r"\varphi_1} = \frac{T_1}{\cos \varphi_1} \cdot \text{tg}^2 \varphi_1",
        reading=(Tm - T1 / c, T1 / c ** 3 - T1 / c, T1 / c * t1 ** 2), note="T = T_m",
        symbols={"T": (Tm, "für T = T_m, the sentence before")})
d.quote("43-always", "(43)", r"\text{ d. i. } > 0, \text{ also die Bedingung 43 stets erfüllt.}",
        reading=(sp.sign(Tm - V1 * e2), 1))
d.quote("43a", "(43a)", r"$$\frac{T_1^1}{\cos \varphi_2} - \frac{T_1}{\cos \varphi_2} > 0",
        reading=(Tm1 - V1 * e2, T11 / sp.cos(phi2) - T1 / sp.cos(phi2)),
        note="read as the quantity whose sign decides, T = T_m^1",
        erratum=Erratum("misprint", "medium", r"\frac{T_1^1}{\cos\varphi_1} - \frac{T_1}{\cos\varphi_1} > 0",
                        r"$\varphi_2$ is never defined; the condition is (43) with $T = T_m^1 = T_1^1/\cos \varphi_1$ "
                        r"from (42), so both denominators are $\cos \varphi_1$. The index 2 appears twice, which "
                        "points to the print (perhaps contaminated by $T_2$, $e_2$ nearby) rather than a scan "
                        "confusion of 1 and 2; the conclusion $T_1^1 > T_1$ is unaffected.",
                        corrected_reading=(Tm1 - V1 * e2, T11 / c - T1 / c),
                        objection=r"The 2 of $\varphi_2$ may be the scan's reading of a 1, a fault of the "
                                  "transcription rather than of the print.",
                        answer="The same line reads the subscripts of $T_1^1$ and $T_1$ as 1 correctly, and 1 read "
                               "as 2 is no usual confusion of this scan; the index 2 twice points to the print "
                               r"($T_2$, $e_2$ stand nearby). The correction follows from (42), $T = T_1^1/\cos "
                               r"\varphi_1$, but the print cannot be seen, so medium."))
d.quote("43a-conclusion", "(43a)", r"\text{ oder } T_1^1 > T_1 \quad (43a)$$",
        reading=(Tm1 - V1 * e2, (T11 - T1) / c), note="cos phi_1 > 0: the condition is T_1^1 > T_1")
d.quote("T-Tm1", "(43a)", r"Es bleibt also nur ( $T = T_m^1$  gesetzt)", reading=(Tm1, T11 / c),
        note="(42): T_m^1 = T_1^1/cos phi_1, inserted into (43) gives (43a)",
        not_compared="an assignment (T is set to T_m^1 in (43)); the reading states the value (42) gives T_m^1")
d.quote("claim-43a", "IV (43a)",
        "„Die schiefe Gleichgewichtslage eines geraden Prismas (im I. Drehungsgebiet) ist also stabil, wenn das "
        "Trägheitsmoment des I. Wasserschnitts für die Drehungsachse kleiner ist als für die darauf senkrechte "
        "Achse“.", reading=(sp.sign(D2), sp.sign(T11 - T1)),
        note="stable (Duhamel: D_2 > 0) exactly when T_1 < T_1^1; with int_1 u v df = 0 and the tilt phi_1 inside "
             "the first rotation region")

# ---- V printed ------------------------------------------------------------------------------------------------
d.quote("44", "(44)", r"$$\begin{aligned} u &= y \sin \omega + x \cos \omega \\ v &= y \cos \omega - x \sin \omega "
                      r"\end{aligned} \quad (44)$$",
        reading=(sp.Matrix([Uw, Vw]), sp.Matrix([y * sp.sin(om) + x * sp.cos(om), y * sp.cos(om) - x * sp.sin(om)])))
d.quote("uv", "(44)", r"$$u \cdot v = (y^2 - x^2) \sin \omega \cos \omega + x y (\cos^2 \omega - \sin^2 \omega)$$",
        reading=(Uw * Vw, (y ** 2 - x ** 2) * sp.sin(om) * sp.cos(om) + x * y * (sp.cos(om) ** 2 - sp.sin(om) ** 2)))
TXY = "the print names int_1 y^2 df = T_x, int_1 x^2 df = T_y (the next line); J is int_1 x y df"
d.quote("second-condition", "(45)",
        r"$$\left( \int_1 y^2 \cdot d f - \int_1 x^2 \cdot d f \right) \sin \omega \cdot \cos \omega + \int_1 x y "
        r"\cdot d f \cdot (\cos^2 \omega - \sin^2 \omega) = 0$$",
        reading=(Iuv, (Tx - Ty) * sp.sin(om) * sp.cos(om) + J * (sp.cos(om) ** 2 - sp.sin(om) ** 2)),
        note="the left side is int_1 u v df; '= 0' is the condition (32)",
        condition="'= 0' is the condition (32) imposed on int_1 u v df, which the reading writes out",
        symbols={r"\int_1 y^2 \cdot d f": (Tx, TXY), r"\int_1 x^2 \cdot d f": (Ty, TXY),
                 r"\int_1 x y \cdot d f": (J, TXY)})
d.quote("Tx-Ty", "(45)", r"$$\int_1 y^2 \cdot d f = T_x \cdot \quad \int_1 x^2 \cdot d f = T_y$$",
        reading=(sp.Matrix([Tx, Ty]), sp.Matrix([Tx, Ty])),
        note="the print names T_x and T_y (a definition, trivial as a claim); the stray dot after T_x is the scan's")
d.quote("45", "(45)", r"$$\frac{1}{2} (T_x - T_y) \sin 2 \omega + \int_1 x y \cdot d f \cdot \cos 2 \omega = 0 "
                      r"\quad (45)$$", reading=(Iuv, (Tx - Ty) * sp.sin(2 * om) / 2 + J * sp.cos(2 * om)),
        condition="'= 0' is the condition (32) imposed on int_1 u v df, which the reading writes out",
        symbols={r"\int_1 x y \cdot d f": (J, TXY)})
d.quote("xy-zero", "V", r"$$\int_1 x y \cdot d f = 0$$", reading=(Jsym, 0))
lhs46 = 2 * sp.Subs(Iuv, J, Jsym)
d.quote("46", "(46)", r"$$(T_x - T_y) \sin 2 \omega = 0 \quad (46)$$",
        reading=(2 * sp.Subs(Iuv, J, Jsym), (Tx - Ty) * sp.sin(2 * om)),
        note="twice the left side of (45) with int x y df = 0; '= 0' is the condition")
d.quote("46-three", "(47)", "Diese hat drei Lösungen",
        reading=(lhs46, 2 * (Tx - Ty) * sp.sin(om) * sp.cos(om)),
        note="read as: the left side of (46) is the product of three factors T_x - T_y, sin omega, cos omega, each "
             "vanishing at one solution of (47) (omega in [0, 180 deg))")
d.quote("principal-or-isotropic", "(47)",
        "In schiefer Lage kann also das Prisma im Gleichgewicht sein entweder wenn es um eine der beiden Hauptachsen "
        "des Wasserschnitts I gedreht wird, oder wenn die Trägheitsmomente der Fläche für die beiden Hauptachsen "
        "gleich sind.", reading=(sp.Subs(Iuv, J, Jsym), (Tx - Ty) * sp.sin(2 * om) / 2),
        note="for a base with a symmetry axis int_1 u v df = (T_x - T_y) sin(2 omega)/2: zero only for omega = 0, "
             "90 deg or T_x = T_y")
d.quote("47", "(47)", r"$$\omega = 0, \omega = 90^\circ, T_x = T_y. \quad (47)$$",
        reading=(sp.Matrix([sp.Subs(lhs46, om, 0), sp.Subs(lhs46, om, sp.pi / 2), sp.Subs(lhs46, Tx, Ty)]),
                 sp.Matrix([0, 0, 0])),
        note="each is a solution; sin 2 omega = 0 has no other in 0 <= omega < 180 deg")
d.quote("T1-def", "(48)", r"$$T_1 = \int_1 u^2 \cdot d f$$", reading=(T1w, area_integral(Uv ** 2, x, y, MOM_XY)))
d.quote("u-44", "(48)", r"$$u = y \sin \omega + x \cos \omega.$$", reading=(Uw, y * sp.sin(om) + x * sp.cos(om)))
d.quote("T1-expanded", "(48)", r"$$T_1 = \sin^2 \omega \int_1 y^2 d f + \cos^2 \omega \int_1 x^2 d f + \sin 2 \omega "
                               r"\int_1 x y \cdot d f$$",
        reading=(T1w, sp.sin(om) ** 2 * Tx + sp.cos(om) ** 2 * Ty + sp.sin(2 * om) * J))
d.quote("third-term", "(48)", "oder, da das dritte Glied gleich Null ist,",
        reading=(sp.Subs(J * sp.sin(2 * om), J, Jsym), 0), note="the third term J sin 2 omega of T_1(omega): J = 0 "
                                                                 "for a base with a symmetry axis")
d.quote("mirror-pairs", "(45)",
        "da immer die beiden Glieder, die sich auf zwei zu beiden Seiten der Symmetrieachse in gleichen Abständen von "
        "den Hauptachsen liegende Flächenelemente beziehen, entgegengesetzte Vorzeichen haben, also einander aufheben.",
        reading=(Jsym, 0), note="int x y df over a base symmetric about the y axis: each chord contributes int x dx = 0")
d.quote("T1-symmetric", "(48)", r"$$T_1 = T_x \cdot \sin^2 \omega + T_y \cdot \cos^2 \omega$$",
        reading=(T1s, Tx * sp.sin(om) ** 2 + Ty * sp.cos(om) ** 2))
d.quote("isotropic-sign", "(48)",
        "so ist für alle Drehungsachsen die Grösse  $\\frac{T_1}{V_1} - e_1$  entweder positiv oder negativ.",
        reading=(sp.Derivative(T1iso, om), 0),
        note="T_1 does not depend on the direction omega of the axis (T_x = T_y), V_1 and e_1 never do")
d.quote("isotropic-upright", "(48)",
        "das Prisma in der aufrechten Lage stabil, im zweiten Falle ist die aufrechte Lage nach allen Richtungen labil",
        reading=(sp.sign(slope), sp.sign(T1 / V1 - e1)),
        note="(18): the slope of the righting arm at the upright position has the sign of T_1/V_1 - e_1, the same "
             "for every axis here")
d.quote("48", "(48)", r"$$T_1 = T_x = T_y \quad (48)$$", reading=(T1iso, T0),
        note="T_x = T_y = T_0: the second equality is the case's hypothesis, so the reading is T_1 = T_0")
d.quote("49", "(49)", "dass das Trägheitsmoment des Wasserschnitts I oder der Grundfläche des Prismas für alle "
                      "durch den Schwerpunkt gehenden Achsen denselben Wert hat, sobald die Trägheitsmomente für die "
                      "Symmetrieachse und für die darauf senkrechte Achse einander gleich sind. (49)",
        reading=(sp.Derivative(T1iso, om), 0))
d.quote("50-T11", "(50)", r"$$T_1^1 = T_1$$", reading=(T11iso, T1iso))
d.quote("50-Tm", "(50)", r"$$T_m = \frac{T_1}{\cos^3 \varphi_1} \quad T_m^1 = \frac{T_1}{\cos \varphi_1}$$",
        reading=(sp.Matrix([Tmi, Tm1i]), sp.Matrix([T1 / c ** 3, T1 / c])))
d.quote("50-ratio", "(50)", r"$$\text{also } T_m \cdot \cos^2 \varphi_1 = T_m^1$$", reading=(Tmi * c ** 2, Tm1i))
d.quote("50", "(50)", r"$$\text{folglich } T_m^1 < T_m$$", reading=(sp.sign(Tmi - Tm1i), 1))
d.quote("43-again", "(51)", r"$$T - \frac{T_1}{\cos \varphi_1} > 0$$", reading=(D2, Tmin - T1 / c),
        note="(43) repeated")
d.quote("Tm1-min", "(51)", r"$$T_m^1 = \frac{T_1}{\cos \varphi_1}$$", reading=(Tm1i, T1 / c))
d.quote("minimum-T", "(51)", "Setzt man für T das Minimum", reading=(sp.Min(Tmi, Tm1i), T1 / c),
        note="isotropic base: T_m^1 = T_1/cos phi_1 is the smaller of T_1/cos^3 phi_1 and T_1/cos phi_1")
d.quote("51", "(51)", r"$$T_m^1 - \frac{T_1}{\cos \varphi_1} = 0. \quad (51)$$",
        reading=(Tm1i - V1 * e2, Tm1i - T1 / c, 0))
d.quote("51-claim", "(51)",
        "In der Gleichgewichtslage ( $\\varphi_1$ ) ist also das Drehungsmoment für jede durch den Schwerpunkt O des "
        "Wasserschnitts gehende Drehungsachse positiv und nur für die zur ersten Drehungsachse EF senkrechte Achse  "
        "$G_2 H_2$  (Fig. 11) ist es Null, folglich das Gleichgewicht stabil.",
        reading=(res(Tmue).subs(T11, T1) - V1 * e2, T1 * t1 ** 2 * sp.cos(mu) ** 2 / c),
        note="for the axis at the angle mu with EF: T(mu) - V_1 e_2 = T_1 tan^2 phi_1 cos^2 mu / cos phi_1, positive "
             "except at mu = 90 deg (G_2 H_2) where it is 0: the values the sentence states. The zero direction is "
             "the turn about the prism axis, along which the isotropic prism stays in equilibrium at constant "
             "potential energy; the verdict 'stabil' drawn from these signs is read at 51-verdict, the word "
             "'Drehungsmoment' at 51-moment")
SENTENCE_51 = ("In der Gleichgewichtslage ( $\\varphi_1$ ) ist also das Drehungsmoment für jede durch den Schwerpunkt O "
               "des Wasserschnitts gehende Drehungsachse positiv und nur für die zur ersten Drehungsachse EF senkrechte "
               "Achse  $G_2 H_2$  (Fig. 11) ist es Null, folglich das Gleichgewicht stabil.")
ISOTROPIC = {T11: T1}                       # the base of (48)-(51): T_1^1 = T_1 for every axis
d.says("51-verdict", "(51)", SENTENCE_51, "Gleichgewicht stabil", Called(at={**ISOTROPIC, mu: sp.pi / 2}),
       erratum=Erratum("claim", "medium",
                       r"\text{folglich das Gleichgewicht für jede andere Achse stabil, für die Achse } G_2 H_2 "
                       r"\text{ indifferent}",
                       (r"The stability of the tilted position about an axis through O at the angle $\mu$ with EF "
                        r"is $T(\mu) - V_1 e_2 = T_1 \operatorname{tg}^2\varphi_1 \cos^2\mu / \cos\varphi_1$ for "
                        r"the base of (48) (Duhamel (33) for that axis, with (35), (40), (42)): positive for every "
                        r"axis but $G_2 H_2$ ($\mu = 90^\circ$), where (51) makes it $T_m^1 - T_1/\cos\varphi_1 = "
                        r"0$. The text's own condition (43) 'die für jedes der Trägheitsmomente T erfüllt sein muss' "
                        r"is strict and fails there. The zero is not a vanishing second variation with a restoring "
                        r"higher order: a turn about $G_2 H_2$ is, to first order, the turn about the prism's axis "
                        r"that the law after (52) describes, through 'immer neue Gleichgewichtslagen' of the same "
                        r"potential energy; about that axis the position is neutral, and 'stabil' holds for the "
                        r"other axes only."),
                       corrected_reading=d.reads("indifferent", Called(at={**ISOTROPIC, mu: sp.pi / 2})),
                       fault="folglich das Gleichgewicht stabil",
                       objection=("A family of equilibria along which the body can be turned without work is the "
                                  "usual sense of 'stable' for a body that cannot capsize: no turn moves it away "
                                  "from an equilibrium, and the law after (52) calls every position of the family "
                                  "'stabile Gleichgewichtslagen'. Scheeffer's 'stabil' is 'not labile', used so "
                                  "throughout: the law of VI ('so bleibt es in allen Lagen im stabilen "
                                  "Gleichgewicht') and VI.A ('ohne seine Stabilität zu verlieren') say the same of "
                                  "the family; and the sentence itself names the axis $G_2 H_2$ where the moment is "
                                  "zero."),
                       answer=("The sentence draws 'stabil' from the signs it has just stated, including the zero, "
                               "and section I defines stable by a couple that turns the body back ($V_1 m > 0$, "
                               "(2)), labile by one that turns it further; about $G_2 H_2$ there is neither, which "
                               "is the neutral case the text never names, and its own condition (43), 'für jedes "
                               "der Trägheitsmomente T', is strict. The laws speak of the family's positions, stable "
                               "against every turn that leaves the family; here the verdict is drawn from a list of "
                               "signs that contains the zero. The reading 'not labile' is the author's consistent "
                               "usage and the sentence does state the zero, so medium, not high.")),
       note="Read as the verdict about the axis G_2 H_2 (mu = 90 deg), where the sentence itself puts the zero: the "
            "sign of the stability there (the other axes: 51-claim, 51-moment).")
d.says("51-moment", "(51)", SENTENCE_51, "Drehungsmoment", Compares(">", 0, at={phi: phi1}),
       erratum=Erratum("claim", "low",
                       r"\text{In der Gleichgewichtslage } (\varphi_1) \text{ ist also die Stabilität } T - "
                       r"\frac{T_1}{\cos\varphi_1} \text{ für jede } \ldots \text{ Drehungsachse positiv}",
                       (r"The Drehungsmoment of IV is the righting moment (12), $V_1 m$, which the text has just set to "
                        r"zero to find the position: at an equilibrium it vanishes for every axis (the first "
                        r"condition (27) for EF, the second (31) for the axis across it). What the sentence finds "
                        r"positive for every axis and zero for $G_2 H_2$ is the quantity of (43) and (51), $T - "
                        r"T_1/\cos\varphi_1 = T - V_1 e_2$, Duhamel's stability (33) of the tilted position: "
                        r"$T_1 \operatorname{tg}^2\varphi_1 \cos^2\mu/\cos\varphi_1$ for the axis at the angle "
                        r"$\mu$ with EF."),
                       corrected_reading=d.reads("Stabilität", Compares(">", 0, at=ISOTROPIC,
                                                                         domain={mu: (0, sp.pi / 2)})),
                       fault="ist also das Drehungsmoment für jede durch den Schwerpunkt O des Wasserschnitts "
                             "gehende Drehungsachse positiv",
                       objection=("'Das Drehungsmoment für eine Achse' may mean the moment that a small turn about "
                                  r"that axis calls up, $\delta\,(T - V_1 e_2)$ to first order ((16) for the tilted "
                                  "position); it is positive exactly where the stability is, so the sentence names "
                                  "the moment by the sign it takes after the turn, as IV does with 'für noch so "
                                  r"kleines $\varphi$ negativ'."),
                       answer=("In IV the word names $V_1 m$ at the position itself ('weil (nach 12) das "
                               r"Drehungsmoment $V_1 m = \ldots$'), and 'in der Gleichgewichtslage' places this one "
                               r"at $\varphi_1$, where that moment is zero; the values the sentence compares are "
                               "those of (43) and (51). The loose reading, a moment per unit turn, is a usage of the "
                               "period and cannot be excluded: low.")),
       note="Read as the words say: the righting moment (12) at the position phi_1 is positive.")
d.quote("52", "(52)", r"$$\operatorname{tg} \varphi_1 = \sqrt{2 \left( \frac{V_1 c_1}{T_1} - 1 \right)} \quad (52)$$",
        reading=(t1, sp.sqrt(2 * (V1 * c1 / T1 - 1))),
        erratum=Erratum("transcription", "high", r"\operatorname{tg}\varphi_1 = \sqrt{2\left(\frac{V_1 e_1}{T_1} - 1\right)}",
                        "(52) is (27) repeated ('ist zu berechnen aus Gleichung 27'); $c_1$ is never defined and 'c' "
                        "for 'e' is a common scan confusion.",
                        corrected_reading=(t1, sp.sqrt(2 * (V1 * e1 / T1 - 1))),
                        objection="$c_1$ may be a quantity of the author's, a distance $c$ of the first section that "
                                  "the transcription does not show defined.",
                        answer="The text says (52) 'ist zu berechnen aus Gleichung 27', and (27) has $V_1 e_1$; no "
                               "$c_1$ is defined in sections I-V, and c read for e is a common glyph confusion of "
                               "the scan."))
d.quote("52-condition", "(52)", r"$$\frac{T_1}{V_1} - e_1 < 0 \text{ ist.}$$",
        reading=(slope, T1 / V1 - e1), note="as stable-18")
law_R = sp.Rational(1, 2) * (Tx - Ty) * sp.sin(2 * om)
d.quote("law", "V",
        "„Ein in schiefer Lage stabil schwimmendes gerades Prisma gelangt durch Drehung um seine Hauptachse (die durch "
        "die Schwerpunkte der Grundflächen geht) in immer neue stabile Gleichgewichtslagen, so lange keine seiner "
        "Grundflächen von der Wasseroberfläche durchschnitten wird“.",
        reading=(res(Iuv).subs(J, Jsym), 0),
        note="read for a symmetric base turned by omega about its axis from a principal tilt: the second "
             "equilibrium moment int_1 u v df would have to vanish for every omega",
        erratum=Erratum("claim", "medium",
                        r"Only for prisms whose base has equal principal moments ($T_x = T_y$: isotropic bases such "
                        r"as squares, regular polygons); otherwise $\int_1 u v\,df = (T_x - T_y) \sin 2\omega / 2 "
                        r"\ne 0$ for $0 < \omega < 90^\circ$ and the turned position is no equilibrium at all.",
                        "The law is stated for every obliquely stable right prism, but derived (just before) only "
                        r"for $T_x = T_y$. Counterexample: the $1 \times \tfrac65$ rectangle, $b = \tfrac56$, $s = "
                        r"\tfrac12$ floats stably tilted about its long axis ($\tan \varphi_1 = 1/(2 \sqrt{3})$, $T_1 "
                        r"= 1/10 < T_1^1 = 18/125$, first rotation region); turned by $15^\circ$ or $30^\circ$ about "
                        r"its axis, the clipped geometry gives $\int u v\, df = \tan^{-1}\varphi$ times the moment of "
                        r"the submerged part about the vertical plane through $OS$ $= (T_x - T_y) \sin 2\omega / 2$, "
                        "not $0$. The text before the law (and section VI) means the isotropic case; the claim holds "
                        "exactly there.",
                        corrected_reading=(res(Iuv).subs(J, Jsym), law_R),
                        objection="The law is drawn ('so ergibt sich daraus') from the paragraph's assumption 'nach "
                                  "den obigen Voraussetzungen' that $T_1$ is the same for every axis through O, so "
                                  "'ein gerades Prisma' means a prism of that kind, and for it the law holds.",
                        answer="The law itself, set off in quotation marks, names every obliquely stable right "
                               "prism, and the next sentence compares 'ein gerades Prisma' with the circular "
                               "cylinder without the restriction; for the $1 \\times 6/5$ rectangle it is false. The "
                               "contextual reading is a real alternative, so the claim is lowered to medium."))
d.quote("QQ1", "(53)", r"$Q Q_1 = b(1 - s)$", reading=(b - b * s, b * (1 - s)),
        note="height above water of the upright prism: b minus the draught b s")
d.quote("53", "(53)", r"$$\operatorname{tg} \varphi_1 = \frac{b(1 - s)}{u_m} \quad (53)$$",
        reading=(sp.tan(phtop), b * (1 - s) / utop), note="phi_1 is here the limit angle (upper base touched)")
d.quote("53a", "(53a)", r"$$\operatorname{tg} \varphi_1 = \frac{b s}{u_m} \quad (53a)$$",
        reading=(sp.tan(phbot), b * s / ubot), note="u_m of the lower base (rising side): u_m' here")
d.quote("s-half", "(53)", r"Diese Formel giebt den Grenzwert von  $\varphi_1$  an für den Fall, dass die obere "
                          r"Grundfläche zuerst vom Wasserspiegel durchschnitten wird, d. h. wenn  $s > \frac{1}{2}$  ist.",
        reading=(sstar, sp.Rational(1, 2)),
        note="read as the threshold of s above which the upper base is reached first",
        erratum=Erratum("claim", "high",
                        r"the upper base is reached first iff $s > u_m'/(u_m + u_m')$; this is $s > 1/2$ only when the "
                        r"base reaches equally far on both sides of EF ($u_m = u_m'$, e.g. centrally symmetric bases, "
                        r"or EF perpendicular to a symmetry axis)",
                        "Scheeffer himself distinguishes $u_m$ of the upper (dipping side) and of the lower base "
                        "(rising side) in (53a), but then decides by $s$ alone. Counterexample: equilateral triangle "
                        r"of side 1, EF parallel to a side, apex dipping ($u_m = 1/\sqrt{3}, u_m' = 1/(2 \sqrt{3})$), "
                        r"$s = \tfrac25 < \tfrac12$: the clipped prism touches the water with its upper base first "
                        r"($\tan = b (1-s) \sqrt{3} = 1.039 b < 2 \sqrt{3} b s = 1.386 b$). Regular prisms with odd "
                        "$n$ (section VI) are of this kind.",
                        corrected_reading=(sstar, ubot / (utop + ubot)),
                        objection="Scheeffer may tacitly assume bases that reach equally far on both sides of EF "
                                  "($u_m = u_m'$), as his examples, the rectangle and the square, do; then $s > "
                                  r"\tfrac12$ decides.",
                        answer="He distinguishes $u_m$ of the dipping and of the rising side himself in (53a), so he "
                               "does not assume them equal, and the regular prisms of odd $n$ in section VI are his "
                               r"own examples with $u_m \ne u_m'$ (the triangle at $s = \tfrac25$ touches the upper "
                               "base first)."))
d.quote("V1-F1", "(54)", r"$V_1 = F_1 \cdot b s$", reading=(V1, F1 * b * s))
d.quote("e1-b", "(54)", r"$S S_1 = e_1 = \frac{b}{2} - \frac{b s}{2} = \frac{b}{2}(1 - s)$",
        reading=(e1, b / 2 - b * s / 2, b / 2 * (1 - s)))
d.quote("54-from", "(54)",
        "Mit Benutzung dieser Werte ergibt sich aus 52, 53, 53a für die schiefe stabile Lage ( $\\varphi_1$ ) die "
        "Bestimmungsgleichung:", reading=(t1 ** 2, F1 * b ** 2 * s * (1 - s) / T1 - 2),
        note="(27) with V_1 = F_1 b s, e_1 = b (1 - s)/2")
d.quote("54", "(54)", r"$$\operatorname{tg}^2 \varphi_1 = \frac{F_1 b^2}{T_1} \cdot s (1 - s) - 2 \quad (54)$$",
        reading=(t1 ** 2, F1 * b ** 2 / T1 * s * (1 - s) - 2))
printed55 = sp.Piecewise((b * (1 - s) / utop, s > sp.Rational(1, 2)), (b * s / ubot, True))
d.quote("55", "(55)", r"$$\operatorname{tg} \varphi_1 \leq \begin{cases} \frac{b (1 - s)}{u_m} & \text{für } s > "
                      r"\frac{1}{2} \\ \frac{b s}{u_m} & \text{für } s < \frac{1}{2} \end{cases} \quad (55)$$",
        reading=(Lim, printed55),
        note="read as the bound on tan phi_1 (the end of the first rotation region); u_m of the upper base in the "
             "first line, of the lower base (u_m') in the second, as (53), (53a) define them",
        erratum=Erratum("claim", "high",
                        r"$\operatorname{tg}\varphi_1 \le \min\left(\frac{b(1-s)}{u_m}, \frac{b s}{u_m'}\right)$, "
                        r"$u_m$, $u_m'$ the farthest points of the base on the dipping and on the rising side of EF; "
                        r"the case split by $s$ is right only for $u_m = u_m'$",
                        "Both bases must stay out of the water, so both bounds apply; which one is smaller depends "
                        "on $s u_m$ versus $(1-s) u_m'$, not on $s$ alone. Counterexample (from the clipped "
                        "geometry): equilateral triangle of side 1, EF parallel to a side, apex dipping, $b = "
                        r"\tfrac{17}{25}$, $s = \tfrac25$: (55) admits $\tan \varphi_1$ up to $2 \sqrt{3} b s = 0.942$, "
                        r"but the upper base is touched at $\tan = \sqrt{3} b (1-s) = 0.707$, and (54) gives $\tan "
                        r"\varphi_1 = 0.815$ in between: the tilted position of (54) is not in the first rotation "
                        r"region although (55) says it is. Same with the apex rising and $s = \tfrac35 > \tfrac12$ "
                        "(lower base first).",
                        corrected_reading=(Lim, sp.Min(b * (1 - s) / utop, b * s / ubot)),
                        objection="As for s-half: with $u_m = u_m'$ tacitly assumed, the case split by $s$ is right.",
                        answer="(53a) distinguishes $u_m$ and $u_m'$, and (55) is applied in section VI to regular "
                               r"prisms of odd $n$, where they differ; for the triangle at $b = \tfrac{17}{25}$, $s = "
                               r"\tfrac25$ the tilt of (54) passes the bound that (55) allows."))
