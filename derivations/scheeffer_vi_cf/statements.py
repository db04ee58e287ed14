"""What Scheeffer's VI.C-F say and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import PRINTED_DIGITS, Derivation, Eq, Erratum
from symfloat.model.claim import as_printed
from symfloat.model.symbol_names import symbol
from symfloat.model.vocabulary import Called, IndependentOf, Is


a, b, s, F = sp.symbols("a b s F", positive=True)
phi, om, psi, mu = sp.symbols("varphi omega psi mu", positive=True)
x, y, z, X, Y, t_, al_, be_ = sp.symbols("x y z X Y t alpha_t beta_t", real=True)
n, r = sp.symbols("n r", positive=True)
half = sp.Rational(1, 2)
pi = sp.pi

# quantities established by steps (result symbols)
F1, T1, P1, V1, Vt, e1 = sp.symbols("F_1 T_1 P_1 V_1 V_t e_1")
Mxi, Meta, Mz, GZ, Ez, GM = sp.symbols("M_xi M_eta M_z GZ E GM")
tan2, tan1, um, OB, tanlim, Sw = sp.symbols("tan^2varphi_1 tanvarphi_1 u_m OB tanvarphi_lim S_omega")
GMc, shi, slo, s80hi, s80lo, sedhi, sedlo = sp.symbols("GM_c s_+ s_- s_80+ s_80- s_e+ s_e-")
Ah, Jtri, Dlt, AII = sp.symbols("A_h J_T Delta A_II")
Fg, Tg, tan2g = sp.symbols("F_g T_g tan^2varphi_g")
h_, A_, Tx, Ty, TL, aE, alph, Sc, rE = sp.symbols("h A T_x T_y T_L a_E alpha Sigma_c r_E")
# the regular n-gon prism's T_1, F_1, u_m; its T_1 at a given base area F
T1n, F1n, umn = symbol("T_1n", r"T_{1}^{(n)}"), symbol("F_1n", r"F_{1}^{(n)}"), symbol("u_mn", r"u_{m}^{(n)}")
T1F, tan2F = symbol("T_1F", r"T_{1}^{(n)}(F)"), sp.Symbol("tan^2varphi_F")

DERIVATION = d = Derivation(
    id="scheeffer-vi-cf",
    source="scheeffer",
    title="The square prism, the cube, the regular n-gon prism and their comparison",
    locator="VI.C-F",
    summary="Upright stability (a/b)^2 > 6s(1-s), the oblique position tan^2 phi_1 = 12 (b/a)^2 s(1-s) - 2 and "
            "its limits for the square prism; the cube's density ranges; the moment of inertia of the regular "
            "n-gon F_1 r^2 (2 + cos 2pi/n)/12 and its decrease with n at equal area.",
    domain={a: (0.5, 2), b: (0.5, 2), s: (0.05, 0.95), phi: (0.05, 1.2), om: (0.01, 0.78), psi: (0.01, 1.5),
            n: (3, 12), r: (0.5, 2), F: (0.5, 3), x: (-1, 1), y: (-1, 1), t_: (0, 1), X: (-1, 2),
            al_: (0.1, 3), Fg: (0.5, 3), Tg: (0.1, 2), mu: (0, 1.57)},
    constraints=(),
    assumptions=("a: base edge (square prism; the cube has a = b), b: height (side edge), 0 < s < 1: density "
                 "relative to the water, the body homogeneous",
                 "first rotation domain: the water plane cuts no base face (the text's standing assumption)",
                 "mu: angle of a horizontal turning axis through the waterplane's centroid with the tilt axis EF "
                 "(the stability of a position is read for the turn about it; mu = 90 deg is the axis G_2 H_2 of (51))",
                 "omega: angle of the horizontal tilt axis with a side of the base, 0 < omega < 45 deg "
                 "(other directions follow by the symmetry of the square)",
                 "n-gon: circumradius $r$, n >= 3 sides; n is sampled as a real number in the identities that hold "
                 "for real n (the cosine sums are checked for n = 3..12)",
                 "sign identities: a printed condition L > R is read as L - R = (positive factor) × (the "
                 "quantity whose sign decides: a metacentric height, or tan^2 of the limiting tilt minus "
                 "tan^2 of the equilibrium tilt); the factor is stated in each note"),
)

# ==== C. the square prism ===========================================================================
xi = -x * sp.sin(om) + y * sp.cos(om)
eta = x * sp.cos(om) + y * sp.sin(om)
SQ = ((x, -a / 2, a / 2), (y, -a / 2, a / 2))


def over_square(f):
    return sp.Integral(f, *SQ)


d.step("square-area", (F1, over_square(1), a ** 2), "integration", result=F1)
d.step("square-inertia", (T1, over_square(xi ** 2), a ** 4 / 12), "integration", result=T1,
       note="moment of the base about the tilt axis through O at the angle omega to a side: the same for "
            "every omega")
d.step("square-first-moment", (over_square(xi), 0), "integration", note="O is the centroid of the base")
d.step("square-product-moment", (P1, over_square(xi * eta), 0), "integration", result=P1,
       note="condition (31)/(46): the product moment vanishes for every omega, so the oblique position is "
            "independent of the direction of the axis")
d.step("tilted-volume-def", Eq(Vt, over_square(b * s + xi * sp.tan(phi))), "definition", result=Vt,
       note="first domain: the submerged part is the set of columns over the base from the bottom face (b s below "
            "O) up to the plane z = xi tan(phi) through O")
d.step("upright-volume", Eq(V1, F1 * b * s), "definition", result=V1)
d.step("tilted-volume", (Vt, a ** 2 * b * s, V1), "integration", uses=("tilted-volume-def", "square-area"),
       note="the plane through O keeps the displacement at every tilt of the first domain")
d.step("e1", (e1, b / 2 - sp.Integral(z, (z, 0, b * s)) / (b * s), b * (1 - s) / 2), "integration", result=e1,
       note="G lies b/2 above the bottom, the upright centre of buoyancy b s/2")
d.step("moment-xi", (Mxi, over_square(xi * (b * s + xi * sp.tan(phi))), T1 * sp.tan(phi)), "integration",
       uses=("square-inertia", "square-first-moment"), result=Mxi)
d.step("moment-eta", (Meta, over_square(eta * (b * s + xi * sp.tan(phi))), P1 * sp.tan(phi), 0), "integration",
       uses=("square-product-moment",), result=Meta)
d.step("moment-z", (Mz, over_square(sp.Integral(z, (z, -b * s, xi * sp.tan(phi)))),
                    T1 * sp.tan(phi) ** 2 / 2 - F1 * b ** 2 * s ** 2 / 2), "integration", result=Mz,
       note="moments of the submerged part about the planes through O (body frame xi, eta, z)")
B = sp.Matrix([Mxi, Meta, Mz]) / V1
G = sp.Matrix([0, 0, b / 2 - b * s])
u_up = sp.Matrix([-sp.sin(phi), 0, sp.cos(phi)])
h_dir = sp.Matrix([sp.cos(phi), 0, sp.sin(phi)])
d.step("righting-arm", Eq(GZ, h_dir.dot(B - G)), "definition", result=GZ,
       note="horizontal distance of B from G across the tilt axis (u = (-sin phi, 0, cos phi) is up, "
            "h = (cos phi, 0, sin phi) horizontal)")
d.step("righting-arm-value", (GZ, sp.sin(phi) / V1 * (T1 * (1 + sp.tan(phi) ** 2 / 2) - V1 * e1)), "algebra",
       uses=("righting-arm", "moment-xi", "moment-z", "e1"), note="Scheeffer's (12)")
d.step("second-component", ((sp.Matrix([0, 1, 0])).dot(B - G), 0), "algebra", uses=("moment-eta",),
       note="the centre of buoyancy stays in the vertical plane through G across the axis: (31) holds")
d.step("potential", Eq(Ez, u_up.dot(G - B)), "definition", result=Ez,
       note="height of G above B: the potential energy over the weight, up to a constant")
d.step("potential-derivative", (sp.Derivative(Ez, phi), GZ), "integration", uses=("potential", "righting-arm"),
       note="dE/dphi = GZ: equilibria are the stationary points of the potential")
d.step("potential-independent-of-omega", (sp.Derivative(Ez, om), 0), "integration", uses=("potential",),
       note="rotation about the main axis changes nothing in the first domain (Scheeffer's law (52a))")
d.step("upright-metacentric-height", (GM, sp.Limit(GZ / phi, phi, 0), T1 / V1 - e1,
                                      a ** 2 / (12 * b * s) - b * (1 - s) / 2), "limit",
       uses=("righting-arm-value",), result=GM, note="Duhamel's condition (18): stable upright iff GM > 0")
Tw, Sd = sp.symbols("T_w S_d")
d.step("waterplane-moment", (Tw, over_square((xi / sp.cos(phi) * sp.cos(mu) - eta * sp.sin(mu)) ** 2 / sp.cos(phi)),
                             T1 * (sp.cos(mu) ** 2 / sp.cos(phi) ** 3 + sp.sin(mu) ** 2 / sp.cos(phi))), "integration",
       uses=("square-inertia", "square-product-moment"), result=Tw,
       note="moment of the waterplane z = xi tan(phi) about the horizontal axis through its centroid O at the angle "
            "mu to the tilt axis EF: a base point (xi, eta) lies xi/cos(phi) across EF and eta along it in the plane, "
            "area element df/cos(phi) (VII's T_2 = T_1/cos^3 and T_2^1 = T_1^1/cos of the tilted section)")
d.step("stability", Eq(Sd, Tw / V1 - Ez), "definition", result=Sd,
       note="Duhamel's condition (18), (43): at a position of equilibrium the metacentric height for the turn about "
            "that axis, moment over volume minus the height E of G above B, is the second variation of the "
            "potential over the weight: > 0 stable, = 0 neutral, < 0 unstable for the turn. Upright (phi = 0) it is "
            "GM for every mu; at the oblique position it is T_1 tan^2 phi_1 cos^2 mu/(V_1 cos phi_1), zero for the "
            "axis G_2 H_2 (mu = 90 deg) as (51) says")
d.defines("stability", Sd)
d.step("oblique-equilibrium", Eq(tan2, 2 * (V1 * e1 / T1 - 1)), "definition", result=tan2,
       note="the non-zero root of GZ: T_1 (1 + tan^2 phi/2) = V_1 e_1 (Scheeffer's (27))")
d.step("oblique-equilibrium-check", (T1 * (1 + tan2 / 2) - V1 * e1, 0), "algebra", uses=("oblique-equilibrium",))
d.step("oblique-equilibrium-square", (tan2, F1 * b ** 2 * s * (1 - s) / T1 - 2, 12 * (b / a) ** 2 * s * (1 - s) - 2),
       "algebra", uses=("oblique-equilibrium", "e1", "square-inertia"), note="(54) for the square")
d.step("oblique-tan", Eq(tan1, sp.sqrt(tan2)), "definition", result=tan1, note="0 < phi_1 < 90 deg")
d.step("oblique-stable-in-phi", (sp.diff(sp.sin(phi) / V1 * (T1 * (1 + sp.tan(phi) ** 2 / 2) - V1 * e1), phi)
                                 .subs(sp.tan(phi), tan1).subs(phi, sp.atan(tan1)),
                                 T1 * tan2 / (V1 * sp.cos(sp.atan(tan1)))), "algebra",
       uses=("righting-arm-value", "oblique-equilibrium"),
       note="E'' = GZ' = T_1 tan^2 phi_1/(V_1 cos phi_1) > 0 at phi_1: stable against tilting; with the "
            "omega-independence the position is stable, neutral about the main axis ((43), (51))")
d.step("stability-upright", (sp.Subs(Sd, phi, 0), GM), "substitution",
       uses=("stability", "waterplane-moment", "potential", "moment-xi", "moment-z", "upright-metacentric-height"),
       note="upright the stability is the metacentric height GM for the turn about every horizontal axis")
d.step("stability-oblique", (sp.Subs(Sd, phi, sp.atan(tan1)),
                             T1 * tan2 * sp.cos(mu) ** 2 / (V1 * sp.cos(sp.atan(tan1)))), "algebra",
       uses=("stability", "waterplane-moment", "potential", "moment-xi", "moment-z", "oblique-tan",
             "oblique-equilibrium"),
       note="at the oblique position: positive for the tilt axis (mu = 0, as oblique-stable-in-phi), zero for the "
            "axis G_2 H_2 (mu = 90 deg), along which the turn about the main axis leads through equilibria at "
            "constant potential (potential-independent-of-omega): (51)")
corners = [(sx * a / 2, sy * a / 2) for sx in (-1, 1) for sy in (-1, 1)]
d.step("corner-distance", (OB, as_printed(lambda: sp.sqrt((a / 2) ** 2 + (a / 2) ** 2)), sp.sqrt(2) * a / 2), "geometry",
       result=OB)
d.step("largest-ordinate", (um, sp.Max(*[xi.subs({x: cx, y: cy}) for cx, cy in corners]),
                            a / 2 * (sp.sin(om) + sp.cos(om)), OB * sp.sin(pi / 4 + om)), "geometry", result=um,
       note="u_m: the largest distance xi of a corner from the axis (the corner (-a/2, a/2) for 0 < omega < 45 deg); "
            "the smallest is -u_m (central symmetry)")
d.step("limit-tilt", Eq(tanlim, sp.Min(b * (1 - s), b * s) / um), "definition", result=tanlim,
       note="the top corner at xi = u_m, z = b(1-s) above O has height b(1-s) cos phi - u_m sin phi over the "
            "water, the bottom corner at xi = -u_m, z = -b s has u_m sin phi - b s cos phi: the first domain "
            "ends at the smaller of b(1-s)/u_m, b s/u_m (the text's (53), (53a), (55))")
d.step("limit-tilt-top", (sp.Subs(b * (1 - s) * sp.cos(phi) - um * sp.sin(phi), phi, sp.atan(b * (1 - s) / um)), 0),
       "geometry", uses=("largest-ordinate",))
d.step("limit-omega", Eq(Sw, 2 * (sp.Min(b * (1 - s), b * s) / tan1) ** 2 / a ** 2), "definition", result=Sw,
       note="S_omega = sin^2(45 deg + omega*), omega* the axis direction at which the limit tilt equals phi_1: "
            "u_m(omega*) = min(b(1-s), b s)/tan phi_1 and sin(45 deg + omega*) = sqrt(2) u_m/a")
d.step("limit-omega-value", (Sw, 2 * b ** 2 * sp.Min(s, 1 - s) ** 2 / (a ** 2 * tan2)), "algebra",
       uses=("limit-omega", "oblique-tan"))

tl45, tl0 = sp.symbols("tanvarphi_lim45 tanvarphi_lim0")
d.step("limit-tilt-45", (tl45, sp.Subs(tanlim, om, pi / 4), sp.sqrt(2) * sp.Min(b * (1 - s), b * s) / a), "substitution",
       uses=("limit-tilt", "largest-ordinate"), result=tl45, note="axis along a diagonal: the smallest limit tilt")
d.step("limit-tilt-0", (tl0, sp.Subs(tanlim, om, 0), 2 * sp.Min(b * (1 - s), b * s) / a), "substitution",
       uses=("limit-tilt", "largest-ordinate"), result=tl0, note="axis parallel to a side: the largest limit tilt")
PW = lambda hi, lo: sp.Piecewise((hi, s > half), (lo, True))  # noqa: E731  (the text's two cases)

d.quote("square-moments", "VI.C",
        r"ist das Trägheitsmoment  $T_1 = \frac{1}{12} \cdot a^4$  und der Inhalt  $F_1 = a^2$",
        reading=(sp.Matrix([T1, F1]), sp.Matrix([a ** 4 / 12, a ** 2])))
d.quote("OB", "VI.C", r"$\text{OB} = \frac{a}{2} \sqrt{2}$", reading=(OB, a / 2 * sp.sqrt(2)))
d.quote("BG-um", "VI.C", r"$\text{BG} = u_m$",
        reading=(sp.Max(*(a / 2 * sp.sqrt(2) * sp.sin(pi / 4 + om + k * pi / 2) for k in range(4))), um),
        note="BG: the distance of the corner B (at OB from O, 45 deg + omega from EF) from the axis EF, the largest "
             "signed distance of the four corners on the sinking side for 0 <= omega < 45 deg")
d.quote("u-m", "(74)", r"$$u_m = \frac{a}{2} \sqrt{2} \cdot \sin(45^\circ + \omega) \quad (74)$$",
        reading=(um, a / 2 * sp.sqrt(2) * sp.sin(pi / 4 + om)))
d.quote("V1", "VI.C", r"$V_1 = F_1 b \cdot s = a^2 b s$", reading=(V1, F1 * b * s, a ** 2 * b * s))
d.quote("T1-over-V1", "VI.C",
        r"$\frac{T_1}{V_1} = \frac{\frac{1}{12} a^4}{a^2 b s} = \frac{a^2}{12 b s}$",
        reading=as_printed(lambda: (T1 / V1, (a ** 4 / 12) / (a ** 2 * b * s), a ** 2 / (12 * b * s))))
d.quote("e1", "VI.C", r"$e_1 = \frac{b}{2} (1 - s)$", reading=(e1, b / 2 * (1 - s)))
d.quote("upright-condition", "VI.C", r"$\frac{a^2}{12 b s} - \frac{b}{2} (1 - s) > 0$",
        reading=(a ** 2 / (12 * b * s) - b / 2 * (1 - s), GM),
        note="the left side is the upright metacentric height")
d.says("upright-duhamel", "VI.C",
       r"Für die Stabilität der aufrechten Lage ist also nach dem Duhamelschen Satz die Bedingung  "
       r"$\frac{T_1}{V_1} - e_1 > 0$", "Stabilität der aufrechten Lage", Is(T1 / V1 - e1, at={phi: 0, mu: 0}),
       note="Read as: the stability of the upright position, whose sign the condition states, is T_1/V_1 - e_1 "
            "(the same for every turning axis, stability-upright).")
d.quote("75", "(75)", r"oder  $\left(\frac{a}{b}\right)^2 > 6 s (1 - s)^*$  (75)",
        reading=((a / b) ** 2 - 6 * s * (1 - s), 12 * s / b * GM),
        note="sign identity, factor 12 s/b > 0; the asterisk is the footnote mark (Schülen)")
d.quote("75-unstable", "VI.C",
        r"Ist aber  $\left(\frac{a}{b}\right)^2 < 6 s (1 - s)$ , so ist die aufrechte Lage labil",
        reading=(6 * s * (1 - s) - (a / b) ** 2, -12 * s / b * GM))
d.quote("Fb2-over-T1", "VI.C",
        r"$\frac{F_1 b^2 s (1 - s)}{T_1} = \frac{12 a^2 b^2 s (1 - s)}{a^4} = 12 \left(\frac{b}{a}\right)^2 s (1 - s)$",
        reading=as_printed(lambda: (F1 * b ** 2 * s * (1 - s) / T1, 12 * a ** 2 * b ** 2 * s * (1 - s) / a ** 4,
                 12 * (b / a) ** 2 * s * (1 - s))))
d.quote("limit-top", "VI.C",
        r"$\frac{b (1 - s)}{u_m} = \frac{b}{a} \cdot \frac{(1 - s) \sqrt{2}}{\sin(45^\circ + \omega)}$",
        reading=(b * (1 - s) / um, b / a * (1 - s) * sp.sqrt(2) / sp.sin(pi / 4 + om)))
d.quote("76", "(76)",
        r"$$\begin{aligned} \text{tg}^2 \varphi_1 &= 12 \left(\frac{b}{a}\right)^2 s (1 - s) - 2 \\ \text{tg} "
        r"\varphi_1 &\leq \begin{cases} \frac{b}{a} \cdot \frac{(1 - s) \sqrt{2}}{\sin(45^\circ + \omega)} & "
        r"\text{für } s > \frac{1}{2} \\ \frac{b}{a} \cdot \frac{s \sqrt{2}}{\sin(45^\circ + \omega)} & \text{für } "
        r"s < \frac{1}{2} \end{cases} \end{aligned} \quad (76)$$",
        reading=(sp.Matrix([tan2, tanlim]),
                 sp.Matrix([12 * (b / a) ** 2 * s * (1 - s) - 2,
                            PW(b / a * (1 - s) * sp.sqrt(2) / sp.sin(pi / 4 + om),
                               b / a * s * sp.sqrt(2) / sp.sin(pi / 4 + om))])),
        note="the second line read as its bound: the tilt at which a base face reaches the water; the direction "
             "of the inequality is checked in (77)")
d.quote("sin-90", "VI.C", r"Für letzteren wird aber  $\sin(45^\circ + \omega) = 1$",
        reading=as_printed(lambda: (sp.sin(pi / 4 + pi / 4), 1)),
        note="u_m is largest, the limit tilt smallest, at omega = 45 deg (the axis along a diagonal)")
d.quote("76-at-45", "VI.C",
        r"$$\begin{aligned} \text{tg}^2 \varphi_1 &= 12 \left(\frac{b}{a}\right)^2 s (1 - s) - 2 \\ \text{tg} "
        r"\varphi_1 &\leq \begin{cases} \frac{b}{a} \cdot (1 - s) \sqrt{2} & \text{für } s > \frac{1}{2} \\ "
        r"\frac{b}{a} s \cdot \sqrt{2} & \text{für } s < \frac{1}{2} \end{cases} \end{aligned}$$",
        reading=(sp.Matrix([tan2, tl45]), sp.Matrix([12 * (b / a) ** 2 * s * (1 - s) - 2,
                                                     PW(b / a * (1 - s) * sp.sqrt(2), b / a * s * sp.sqrt(2))])))
d.quote("76-squared", "VI.C",
        r"$$12 \left(\frac{b}{a}\right)^2 s (1 - s) - 2 \leq \begin{cases} 2 \left(\frac{b}{a}\right)^2 (1 - s)^2 & "
        r"\text{wenn } s > \frac{1}{2} \\ 2 \left(\frac{b}{a}\right)^2 s^2 & \text{wenn } s < \frac{1}{2} "
        r"\end{cases}$$",
        reading=(PW(2 * (b / a) ** 2 * (1 - s) ** 2, 2 * (b / a) ** 2 * s ** 2)
                 - (12 * (b / a) ** 2 * s * (1 - s) - 2), tl45 ** 2 - tan2),
        note="sign identity: right minus left side = tan^2 phi_lim(45 deg) - tan^2 phi_1")
Q77_sign = (a / b) ** 2 / 2 * (tl45 ** 2 - tan2)
d.quote("77", "(77)",
        r"$$\left(\frac{a}{b}\right)^2 \geq \begin{cases} (1 - s)(7s - 1) & \text{wenn } s > \frac{1}{2} \\ "
        r"s(6 - 7s) & \text{wenn } s < \frac{1}{2} \end{cases} \quad (77)$$",
        reading=((a / b) ** 2 - PW((1 - s) * (7 * s - 1), s * (6 - 7 * s)), Q77_sign),
        note="sign identity, factor (a/b)^2/2: (77) holds iff phi_1 does not exceed the limit tilt at 45 deg")
d.quote("78", "(78)", r"$$\left(\frac{a}{b}\right)^2 > 6s(1 - s) \quad (78)$$",
        reading=((a / b) ** 2 - 6 * s * (1 - s), 12 * s / b * GM))
d.quote("78-stable", "(78)", "so schwimmt es in aufrechter Lage stabil; wenn",
        reading=(sp.sign(12 * s / b * GM), sp.sign((a / b) ** 2 - 6 * s * (1 - s))),
        note="under (78) the metacentric height GM of the upright prism is positive (margin of (78) = 12 s/b GM)")
d.quote("78a", "(78a)",
        r"$$6s(1 - s) > \left(\frac{a}{b}\right)^2 \geq \begin{cases} (1 - s)(7s - 1) & \text{für } s > \frac{1}{2} "
        r"\\ s(6 - 7s) & \text{für } s < \frac{1}{2} \end{cases} \quad (78a)$$",
        reading=(sp.Matrix([6 * s * (1 - s) - (a / b) ** 2, (a / b) ** 2 - PW((1 - s) * (7 * s - 1), s * (6 - 7 * s))]),
                 sp.Matrix([-12 * s / b * GM, Q77_sign])),
        note="both inequalities as sign identities: unstable upright, and phi_1 within the first domain for every "
             "omega; the stated conclusions (oblique position stable for every axis direction, stability kept "
             "under rotation about the main axis) follow from oblique-stable-in-phi and "
             "potential-independent-of-omega, and are tested on the clipped geometry in the tests")
d.quote("78a-words", "(78a)",
        "so schwimmt es aufrecht labil und nach einer Drehung um den Winkel  $\\varphi_1$  in schiefer Lage stabil",
        reading=(sp.Matrix([6 * s * (1 - s) - (a / b) ** 2, (a / b) ** 2 - PW((1 - s) * (7 * s - 1), s * (6 - 7 * s))]),
                 sp.Matrix([-12 * s / b * GM, Q77_sign])),
        note="as (78a): GM < 0 upright, and the tilt phi_1 of (78b) stays within the limit of the first domain")
d.quote("78b", "(78b)",
        r"$$\operatorname{tg} \varphi_1 = \sqrt{12 \cdot \left(\frac{b}{a}\right)^2 s (1 - s) - 2} \quad (78b)$$",
        reading=(tan1, sp.sqrt(12 * (b / a) ** 2 * s * (1 - s) - 2)))
d.says("78b-turn", "(78b)",
       "Im letzteren Falle bleibt die Stabilität in jeder Lage, die das Prisma durch Drehung um seine Hauptachse "
       "erhält.", "Stabilität", IndependentOf(om),
       note="Read for every tilt of the first domain, the oblique position of (78b) among them: the stability, for "
            "every turning axis mu, does not change with the direction omega of the tilt axis, i.e. as the prism is "
            "turned about its main axis; under (78a) the tilt stays within the first domain for every omega (77).")
d.quote("78c", "(78c)",
        r"$$\text{Ist jedoch } \left(\frac{a}{b}\right)^2 < \begin{cases} (1 - s)(7s - 1) & \text{für } s < "
        r"\frac{1}{2} \\ s(6 - 7s) & \text{für } s > \frac{1}{2} \end{cases} \quad (78c)$$",
        reading=(sp.Piecewise((s * (6 - 7 * s), s > half), ((1 - s) * (7 * s - 1), True)) - (a / b) ** 2, -Q77_sign),
        erratum=Erratum(
            "misprint", "medium",
            r"\left(\frac{a}{b}\right)^2 < \begin{cases} (1 - s)(7s - 1) & \text{für } s > \frac{1}{2} \\ "
            r"s(6 - 7s) & \text{für } s < \frac{1}{2} \end{cases}",
            ("(78c) is meant as the negation of the right half of (78a) (the text goes on: the prism can be turned "
             "about its main axis only until a base face is cut), so its bounds must be those of (77)/(78a), "
             r"$(1-s)(7s-1)$ for $s > \tfrac12$ and $s(6-7s)$ for $s < \tfrac12$; the print attaches them to the "
             "opposite cases. With the swap the condition is wrong, e.g. for $s = 0.3$ it gives the bound $0.77$ "
             "instead of $1.17$. Both case labels are exchanged consistently, which a scan does not do; a misprint "
             "of the original is the likelier cause (the scan cannot be excluded: medium)."),
            corrected_reading=(PW((1 - s) * (7 * s - 1), s * (6 - 7 * s)) - (a / b) ** 2, -Q77_sign),
                        objection="(78c) may be meant as printed, as a condition of its own for the second-region "
                                  "case rather than the negation of (78a)'s right half.",
                        answer=("The text goes on that the prism can be turned about its main axis only until a base "
                                "face is cut, which is the negation of (78a); its bounds are those of (77)/(78a) "
                                "with the cases as there, and the printed attachment gives at $s = 0.3$ the bound "
                                "$0.77$ instead of $1.17$. Both labels exchanged together is no glyph fault of the "
                                "scan; medium, since the transcriber may have set the cases in the wrong order.")))
d.quote("78c-turn", "(78c)",
        "so kann das Prisma in der schiefen stabilen Lage nur soweit um die Hauptachse gedreht werden, bis eine der "
        "Grundflächen den Wasserspiegel durchschneidet.",
        reading=(sp.Derivative(tanlim, om), -tanlim * sp.cos(pi / 4 + om) / sp.sin(pi / 4 + om)),
        note="sign identity: the limit tilt of the first domain decreases as the axis turns from a side (omega = 0) "
             "towards the diagonal (45 deg); under (78c) phi_1 exceeds it at 45 deg (the negation of (77)), so the "
             "turn keeps the oblique position only up to the omega* of (78d), where a base face reaches the water")
d.quote("78d", "(78d)",
        r"$$\sin^2 (45^\circ + \omega) \leq \begin{cases} \frac{(1 - s)^2}{6s(1 - s) - \left(\frac{a}{b}\right)^2} & "
        r"\text{für } s > \frac{1}{2} \\ \frac{s^2}{6s(1 - s) - \left(\frac{a}{b}\right)^2} & \text{für } s < "
        r"\frac{1}{2} \end{cases} \quad (78d)$$",
        reading=(Sw, PW((1 - s) ** 2 / (6 * s * (1 - s) - (a / b) ** 2), s ** 2 / (6 * s * (1 - s) - (a / b) ** 2))),
        note="read as the bound: S_omega = sin^2(45 deg + omega*) at the limiting axis direction omega*; the limit "
             "tilt decreases as omega grows, so the condition holds for omega <= omega*")
d.quote("78d-from-76", "(78d)",
        "Die Grenzbedingung dafür, die also den grössten Wert von  $\\omega$  bestimmt, folgt aus 76:",
        reading=(Sw, PW((1 - s) ** 2 / (6 * s * (1 - s) - (a / b) ** 2), s ** 2 / (6 * s * (1 - s) - (a / b) ** 2))),
        note="the reference: (76), the tilt phi_1 at its limit for the direction omega, gives the bound (78d)")
d.quote("78e", "(78e)",
        r"$$\left(\frac{a}{b}\right)^2 < \left\{ \begin{array}{ll} 2(1-s)(4s-1) & \text{für } s > \frac{1}{2} \\ "
        r"2s(3-4s) & \text{für } s < \frac{1}{2} \end{array} \right\} \quad (78e)$$",
        reading=(PW(2 * (1 - s) * (4 * s - 1), 2 * s * (3 - 4 * s)) - (a / b) ** 2, (a / b) ** 2 / 2 * (tan2 - tl0 ** 2)),
        note="sign identity, factor (a/b)^2/2: (78e) holds iff phi_1 exceeds the limit tilt already at omega = 0 "
             "(sin^2 45 deg = 1/2), the least restrictive direction; then the first domain holds no oblique "
             "equilibrium for any axis (the text's conclusion)")

# ==== D. the cube ====================================================================================
d.quote("78e-none", "(78e)",
        "Ist diese Bedingung auch für  $\\omega = 0$  nicht erfüllt, so gibt es unter der obigen Voraussetzung "
        "überhaupt keine stabile Gleichgewichtslage.",
        reading=(PW(2 * (1 - s) * (4 * s - 1), 2 * s * (3 - 4 * s)) - (a / b) ** 2, (a / b) ** 2 / 2 * (tan2 - tl0 ** 2)),
        note="as (78e): omega = 0 is the least restrictive direction; where phi_1 exceeds its limit there, it does "
             "for every omega, and the first domain holds no oblique position")
d.quote("sin2-45", "(78e)", r"$\sin^2(45^\circ) = \frac{1}{2}$",
        reading=as_printed(lambda: (sp.sin(pi / 4) ** 2, sp.Rational(1, 2))))
d.step("cube-metacentric-height", (GMc, sp.Subs(GM, a, b), b * (1 - 6 * s * (1 - s)) / (12 * s)), "substitution",
       uses=("upright-metacentric-height",), result=GMc)
rp, rm = half + sp.sqrt(sp.Rational(1, 12)), half - sp.sqrt(sp.Rational(1, 12))
Qc, tan2c, Swc = sp.symbols("Q_c tan^2varphi_c S_omegac")
d.step("cube-oblique-margin", (Qc, sp.Subs((a / b) ** 2 / 2 * (tl45 ** 2 - tan2), a, b),
                               (2 * sp.Min(s, 1 - s) ** 2 - 12 * s * (1 - s) + 2) / 2), "substitution",
       uses=("limit-tilt-45", "oblique-equilibrium-square"), result=Qc,
       note="(tan^2 phi_lim(45 deg) - tan^2 phi_1)/2 for a = b")
d.step("cube-oblique-tilt", (tan2c, sp.Subs(tan2, a, b), 12 * s * (1 - s) - 2), "substitution",
       uses=("oblique-equilibrium-square",), result=tan2c)
d.step("cube-limit-omega", (Swc, sp.Subs(Sw, a, b), 2 * sp.Min(s, 1 - s) ** 2 / (12 * s * (1 - s) - 2)), "substitution",
       uses=("limit-omega-value",), result=Swc)
d.step("cube-upright-roots", (sp.Matrix([1 - 6 * rp * (1 - rp), 1 - 6 * rm * (1 - rm)]), sp.zeros(2, 1)), "algebra",
       note="the two roots of 6 s (1-s) = 1, one on each side of 1/2")
d.step("cube-upright-threshold-upper", Eq(shi, rp), "definition", result=shi, uses=("cube-upright-roots",))
d.step("cube-upright-threshold-lower", Eq(slo, rm), "definition", result=slo, uses=("cube-upright-roots",))
r8p, r8m = (4 + sp.sqrt(2)) / 7, (3 - sp.sqrt(2)) / 7
d.step("cube-oblique-roots", (sp.Matrix([1 - (1 - r8p) * (7 * r8p - 1), 1 - r8m * (6 - 7 * r8m)]), sp.zeros(2, 1)),
       "algebra", note="(4 + sqrt 2)/7 > 1/2 is the root of 1 = (1-s)(7s-1) on the branch s > 1/2, "
                       "(3 - sqrt 2)/7 < 1/2 that of 1 = s(6-7s) on s < 1/2 (the other roots lie on the wrong side)")
d.step("cube-oblique-threshold-upper", Eq(s80hi, r8p), "definition", result=s80hi, uses=("cube-oblique-roots",))
d.step("cube-oblique-threshold-lower", Eq(s80lo, r8m), "definition", result=s80lo, uses=("cube-oblique-roots",))
d.step("cube-edge-axis-factor", (sp.Matrix([2 * (1 - s) ** 2 - (6 * s * (1 - s) - 1), 2 * s ** 2 - (6 * s * (1 - s) - 1)]),
                                 sp.Matrix([1 - 2 * (1 - s) * (4 * s - 1), 1 - 2 * s * (3 - 4 * s)]),
                                 sp.Matrix([(2 * s - 1) * (4 * s - 3), (2 * s - 1) * (4 * s - 1)])), "algebra",
       uses=("limit-omega", "cube-oblique-tilt"),
       note="(82) at omega = 0 (sin^2 45 deg = 1/2) holds iff these are >= 0 (denominator 6s(1-s) - 1 > 0 in the "
            "unstable range): for s > 1/2 iff s >= 3/4, for s < 1/2 iff s <= 1/4 (and at s = 1/2)")
d.step("cube-edge-threshold-upper", Eq(sedhi, sp.Rational(3, 4)), "definition", result=sedhi,
       uses=("cube-edge-axis-factor",), note="least s > 1/2 with an oblique equilibrium of the first domain")
d.step("cube-edge-threshold-lower", Eq(sedlo, sp.Rational(1, 4)), "definition", result=sedlo,
       uses=("cube-edge-axis-factor",), note="greatest s < 1/2 with an oblique equilibrium of the first domain")
# s = 1/2: the cube turned about its main axis at phi = 45 deg (exact clipped columns)
cdel = (sp.sin(om) + sp.cos(om) - 1) / 2
col = lambda c, w: (-w * (c + a / 2) + (c ** 2 - a ** 2 / 4) / 2) / sp.sqrt(2)  # noqa: E731
d.step("half-cube-column-top", (col(a / 2, X) - col(X, X), (X - a / 2) ** 2 / (2 * sp.sqrt(2))), "algebra",
       note="s = 1/2, phi = 45 deg, edge a: the column over a base point with xi = X > a/2 is capped at the top face; "
            "its contribution to int u.p over the submerged part changes by this amount (central symmetry: the "
            "plane stays through the centre, the cap at the bottom, xi < -a/2, is the mirror image)")
d.step("half-cube-corner-triangle", (Jtri, sp.Integral(sp.Integral(
    (a * cdel * (1 - al_ - be_)) ** 2 * (a * cdel / sp.sin(om)) * (a * cdel / sp.cos(om)), (be_, 0, 1 - al_)), (al_, 0, 1)),
    a ** 4 * cdel ** 4 / (12 * sp.sin(om) * sp.cos(om))), "integration", result=Jtri,
       note="J = int (xi - a/2)^2 over the corner triangle where xi > a/2: legs a d/sin(omega), a d/cos(omega) along "
            "the two edges from the corner (-a/2, a/2), xi - a/2 = a d (1 - alpha - beta), d = (sin w + cos w - 1)/2")
d.step("half-cube-potential-change", (Dlt, -(2 / a ** 3) * 2 * Jtri / (2 * sp.sqrt(2)),
                                      -sp.sqrt(2) * a * cdel ** 4 / (12 * sp.sin(om) * sp.cos(om))), "algebra",
       uses=("half-cube-column-top", "half-cube-corner-triangle"), result=Dlt,
       note="Delta(omega) = E(45 deg, omega) - E(45 deg, 0) = -(1/V) x (both caps), V = a^3/2: negative for "
            "every 0 < omega < 90 deg; to lowest order -sqrt(2) a omega^3/192")
d.step("half-cube-order", (sp.Limit(Dlt / om ** 3, om, 0, "+"), -sp.sqrt(2) * a / 192), "limit",
       uses=("half-cube-potential-change",))
d.step("waterplane-area", (AII, over_square(sp.sqrt(1 + sp.tan(phi) ** 2)), F1 / sp.cos(phi)), "integration",
       result=AII, note="area of the plane z = xi tan(phi) over the base: element sqrt(1 + tan^2 phi) dx dy")

cube = {a: b}
d.quote("cube-78", "VI.D", r"$$1 > 6s(1-s)$$", reading=(1 - 6 * s * (1 - s), 12 * s / b * GMc))
d.quote("cube-from-78", "VI.D", r"$\frac{a}{b} = 1$ , so erhält man aus 78:",
        reading=(sp.Subs(12 * s / b * GM, a, b), 12 * s / b * GMc),
        note="the margin of (78) at a = b is that of the cube: the reference is right")
d.quote("cube-78-square", "VI.D", r"$$\left(s - \frac{1}{2}\right)^2 > \frac{1}{12}$$",
        reading=((s - half) ** 2 - sp.Rational(1, 12), 2 * s / b * GMc))
d.quote("79", "(79)", r"s > \frac{1}{2} + \sqrt{\frac{1}{12}} \text{ d. h. } s > 0,7887 \\ \text{oder} \\ s < "
                      r"\frac{1}{2} - \sqrt{\frac{1}{12}} \text{ d. h. } s < 0,2113",
        reading=(sp.Matrix([shi, slo]), sp.Matrix([half + sp.sqrt(sp.Rational(1, 12)), half - sp.sqrt(sp.Rational(1, 12))])))
d.quote("79-upper-number", "(79)", r"s > \frac{1}{2} + \sqrt{\frac{1}{12}} \text{ d. h. } s > 0,7887",
        reading=(shi, sp.Rational("0.7887")), tolerance=PRINTED_DIGITS)
d.quote("79-lower-number", "(79)", r"s < \frac{1}{2} - \sqrt{\frac{1}{12}} \text{ d. h. } s < 0,2113",
        reading=(slo, sp.Rational("0.2113")), tolerance=PRINTED_DIGITS)
d.quote("cube-78a", "VI.D",
        r"$$\left\{ \begin{array}{l} s > \frac{1}{2} \text{ und } 1 \geq (1-s)(7s-1) \\ s < \frac{1}{2} \text{ und } "
        r"1 \geq s(6-7s) \end{array} \right.$$",
        reading=(1 - PW((1 - s) * (7 * s - 1), s * (6 - 7 * s)), Qc),
        note="(78a) with a = b; sign identity as in (77)")
d.quote("cube-78a-square", "VI.D",
        r"$$\left\{ \begin{array}{l} s > \frac{1}{2} \text{ und } \left(s - \frac{4}{7}\right)^2 > \frac{2}{49} \\ s "
        r"< \frac{1}{2} \text{ und } \left(s - \frac{3}{7}\right)^2 > \frac{2}{49} \end{array} \right.$$",
        reading=(PW((s - sp.Rational(4, 7)) ** 2, (s - sp.Rational(3, 7)) ** 2) - sp.Rational(2, 49),
                 Qc / 7),
        note="'>' where the line before has '>=': the boundary case is dropped, harmless")
d.quote("80", "(80)", r"s > \frac{1}{2} \text{ und } s > \frac{1}{7}(4 + \sqrt{2}) \text{ d. i. } > 0,7735 \\ s < "
                      r"\frac{1}{2} \text{ und } s < \frac{1}{7}(3 - \sqrt{2}^1) \text{ d. i. } < 0,2265",
        reading=(sp.Matrix([s80hi, s80lo]), sp.Matrix([(4 + sp.sqrt(2)) / 7, (3 - sp.sqrt(2) ** 1) / 7])),
        note="'sqrt{2}^1': a stray mark of the scan; read literally it is sqrt(2) anyway")
d.quote("80-upper-number", "(80)", r"s > \frac{1}{7}(4 + \sqrt{2}) \text{ d. i. } > 0,7735",
        reading=(s80hi, sp.Rational("0.7735")), tolerance=PRINTED_DIGITS)
d.quote("80-lower-number", "(80)", r"s < \frac{1}{7}(3 - \sqrt{2}^1) \text{ d. i. } < 0,2265",
        reading=(s80lo, sp.Rational("0.2265")), tolerance=PRINTED_DIGITS)
d.quote("80-roots", "VI.D",
        r"ist die erste dieser Bedingungen nur erfüllbar für  $s > \frac{4}{7}$  und die zweite nur für  "
        r"$s < \frac{3}{7}$",
        reading=(sp.Matrix([s80hi - sp.Rational(4, 7), sp.Rational(3, 7) - s80lo]), sp.Matrix([sp.sqrt(2) / 7] * 2)),
        note="the admissible root lies sqrt(2)/7 above 4/7 (below 3/7); the other root contradicts s > 1/2 (s < 1/2)")
d.quote("81-upper", "(81)",
        r"Ein Würfel schwimmt in aufrechter Lage stabil, wenn sein spec. Gewicht  $s > 0,7887$",
        reading=(shi, sp.Rational("0.7887")), tolerance=PRINTED_DIGITS)
d.quote("81-lower", "(81)", r"$s > 0,7887$  oder  $s < 0,2113$  ist.",
        reading=(slo, sp.Rational("0.2113")), tolerance=PRINTED_DIGITS)
# the cube's upright position named stable or unstable: the stability at phi = 0 (the metacentric height, the same
# for every turning axis by stability-upright, read for mu = 0) on the density ranges the sentences give, bounded by
# the closed forms the printed decimals round (79-*, 80-*)
UPRIGHT_CUBE = {a: b, phi: 0, mu: 0}
LAW_81 = "Ein Würfel schwimmt in aufrechter Lage stabil, wenn sein spec. Gewicht  $s > 0,7887$  oder  $s < 0,2113$  ist."
d.says("81-stable-heavy", "(81)", LAW_81, "stabil", Called(at=UPRIGHT_CUBE, domain={s: (rp, 1)}),
       note="Read on s > 1/2 + sqrt(1/12) = 0.78868 (79), which the printed 0.7887 rounds.")
d.says("81-stable-light", "(81)", LAW_81, "stabil", Called(at=UPRIGHT_CUBE, domain={s: (0, rm)}),
       note="Read on s < 1/2 - sqrt(1/12) = 0.21132 (79), which the printed 0.2113 rounds.")
d.says("81a-unstable-heavy", "VI.D", "so schwimmt er in aufrechter Lage labil",
       "labil", Called(at=UPRIGHT_CUBE, domain={s: (r8p, rp)}),
       note="Read between (4 + sqrt 2)/7 = 0.7735 (80) and 1/2 + sqrt(1/12) = 0.7887 (79), the first range of the "
            "sentence ('zwischen 0,7735 und 0,7887').")
d.says("81a-unstable-light", "VI.D", "so schwimmt er in aufrechter Lage labil",
       "labil", Called(at=UPRIGHT_CUBE, domain={s: (rm, r8m)}),
       note="Read between 1/2 - sqrt(1/12) = 0.2113 (79) and (3 - sqrt 2)/7 = 0.2265 (80), the second range of the "
            "sentence ('oder zwischen 0,2113 und 0,2265').")
d.says("82-unstable", "VI.D", "so gelangt er ebenfalls aus der labilen aufrechten Lage in eine schiefe",
       "labilen", Called(at=UPRIGHT_CUBE, domain={s: (r8m, r8p)}),
       note="Read between (3 - sqrt 2)/7 = 0.2265 and (4 + sqrt 2)/7 = 0.7735 (80), the range of the sentence "
            "('zwischen 0,2265 und 0,7735').")
d.quote("81-oblique-upper", "VI.D", "zwischen 0,7735 und 0,7887",
        reading=(s80hi, sp.Rational("0.7735")), tolerance=PRINTED_DIGITS,
        note="the range of the claim 'aufrecht labil, ... durch Drehung um eine beliebige horizontale Achse in eine "
             "schiefe stabile Lage, in der weder seine obere noch seine untere Fläche ... durchschnitten wird': (78a) "
             "with a = b, whose conclusions are derived and tested on the clipped cube")
d.quote("81-oblique-lower", "VI.D", "oder zwischen 0,2113 und 0,2265,",
        reading=(s80lo, sp.Rational("0.2265")), tolerance=PRINTED_DIGITS)
d.quote("81a", "(81a)", r"$$\operatorname{tg}^2 \varphi_1 = 2 \cdot \left\{ b s (1 - s) - 1 \right\} \quad (81 a)$$",
        reading=(tan2c, 2 * (b * s * (1 - s) - 1)),
        erratum=Erratum(
            "transcription", "high", r"\operatorname{tg}^2 \varphi_1 = 2 \cdot \left\{ 6 s (1 - s) - 1 \right\}",
            (r"(78b) with $a = b$ gives $\tan^2\varphi_1 = 12 s(1-s) - 2 = 2\{6 s(1-s) - 1\}$. The printed '$b$' "
             "makes the formula depend on a length, which a cube's angle cannot; '$b$' for '$6$' is a typical "
             "confusion of the scan, and the same '$b s (1 - s) - 1$' recurs in (82), where $6s(1-s) - 1$ is again "
             "required."),
            corrected_reading=(tan2c, 2 * (6 * s * (1 - s) - 1)),
                        objection=("$b$ may be the prism's height, kept by the author in a formula written for the "
                                   "cube before setting $a = b$."),
                        answer=(r"(78b) with $a = b$ gives $12 s(1 - s) - 2 = 2\{6 s(1 - s) - 1\}$, free of lengths; "
                                "an angle of the cube cannot depend on its size, and (82) needs the same $6$ (its "
                                r"value $\tfrac12$ at $s = \tfrac12$ follows only with it). $b$ for $6$ is the scan's "
                                "usual confusion.")))
d.quote("edge-axis-range", "VI.D",
        "zwischen 0,2265 und 0,7735,  \n so gelangt er ebenfalls aus der labilen aufrechten Lage in eine schiefe "
        "stabile (die auch aus Gleichung 81 zu bestimmen ist), wenn die Drehungsachse entweder mit einer Grundkante "
        "parallel ist oder mit ihr einen Winkel  $\\omega$  bildet, dessen Grenze der Bedingung (s. 78 d)",
        reading=(sp.Matrix([sedhi, sedlo]), sp.Matrix([half, half])),
        note="read as: the densities on each side of 1/2 at which the oblique position of the first domain exists "
             "for an axis parallel to an edge reach up to s = 1/2 from both sides (the claimed range is one "
             "interval through 1/2)",
        erratum=Erratum(
            "claim", "high",
            r"only for $3/4 < s < 0.7735$ and $0.2265 < s < 1/4$ (at $s = 3/4$, $1/4$ and $1/2$ the edge-parallel "
            r"position touches a face: an equilibrium but not stable, see the claim at $s = 1/2$; on the clipped unit "
            r"cube at $s = 3/4$ turning by $0.1$ about the main axis lowers the potential by "
            r"$6.4 \times 10^{-7}$); for $1/4 < s < 3/4$, $s \ne 1/2$, the first domain holds no oblique equilibrium "
            r"for any axis direction",
            r"(82) at $\omega = 0$ ($\sin^2 45^\circ = \tfrac12$) needs $2(1-s)^2 \ge 6s(1-s) - 1$, i.e. "
            r"$(2s-1)(4s-3) \ge 0$ for $s > \tfrac12$ and $(2s-1)(4s-1) \ge 0$ for $s < \tfrac12$: only $s \ge "
            r"\tfrac34$ or $s \le \tfrac14$. Counterexample $s = 0.6$: the bound of (82) is $0.16/0.44 = 0.364 < "
            r"\tfrac12 = \sin^2(45^\circ + \omega)$ for $\omega = 0$, so no axis works; on the clipped cube the root "
            r"of $GZ$ at $43.2^\circ$ lies beyond the tilt $38.7^\circ$ at which the top face reaches the water for "
            r"an edge-parallel axis ($GZ$ there is $-0.0104$ for the unit cube). Scheeffer's own case $s = \tfrac12$ "
            r"($\omega = 0$ only) is the isolated root $s = \tfrac12$.",
            corrected_reading=(sp.Matrix([sedhi, sedlo]), sp.Matrix([sp.Rational(3, 4), sp.Rational(1, 4)])),
                        objection="The range 0.2265 < s < 0.7735 may be meant for the existence of an oblique stable"
                                  " position by some rotation, 'ebenfalls' pointing back to the second region, not "
                                  "to the first domain alone.",
                        answer="The sentence bounds the axis angle by (78d), (82), which are conditions of the first "
                               r"domain, and (82) itself at $\omega = 0$ holds only for $s \ge \tfrac34$ or $s \le "
                               r"\tfrac14$; at $s = 0.6$ the edge-parallel tilt reaches the top face at $38.7^\circ$ "
                               r"before the root of $GZ$ at $43.2^\circ$."))
d.quote("82", "(82)",
        r"$$\sin^2 (45^\circ + \omega) \leq \begin{cases} \frac{(1 - s)^2}{b s (1 - s) - 1} & \text{für } s > "
        r"\frac{1}{2} \\ \frac{s^2}{b s (1 - s) - 1} & \text{für } s < \frac{1}{2} \end{cases} \quad (82)$$",
        reading=(Swc, PW((1 - s) ** 2 / (b * s * (1 - s) - 1), s ** 2 / (b * s * (1 - s) - 1))),
        erratum=Erratum(
            "transcription", "high",
            r"\sin^2 (45^\circ + \omega) \leq \begin{cases} \frac{(1 - s)^2}{6 s (1 - s) - 1} & \text{für } s > "
            r"\frac{1}{2} \\ \frac{s^2}{6 s (1 - s) - 1} & \text{für } s < \frac{1}{2} \end{cases}",
            r"(78d) with a/b = 1 has the denominator $6s(1-s) - 1$; the text's own evaluation at $s = \tfrac12$, "
            r"$\sin^2 = \tfrac12$, follows only with 6 (with the letter b it would depend on the cube's size). The "
            "same '6' read as 'b' as in (81a).",
            corrected_reading=(Swc, PW((1 - s) ** 2 / (6 * s * (1 - s) - 1),
                                                     s ** 2 / (6 * s * (1 - s) - 1))),
                        objection="b may be the prism's height kept in the formula, as for (81a).",
                        answer="(78d) with a/b = 1 has the denominator $6 s(1 - s) - 1$, and the text's own value "
                               r"$\sin^2 = \tfrac12$ at $s = \tfrac12$ follows only with 6 (with b it would depend on "
                               "the size). The same 6 read as b as in (81a)."))
d.quote("82-half", "VI.D", r"$$\sin^2 (45^\circ + \omega) = \frac{1}{2}$$",
        reading=(sp.Subs(Sw, (a, s), (b, half)), half))
d.quote("82-half-omega", "VI.D", r"$$\text{woraus } \sin (45^\circ + \omega) = \frac{1}{2} \sqrt{2}$$",
        reading=as_printed(lambda: (sp.sqrt(sp.Subs(Sw, (a, s), (b, half))), sp.sqrt(2) / 2, sp.sin(pi / 4 + 0))),
        note="hence omega = 0")
d.quote("82-half-zero", "VI.D", "also  $\\omega = 0$  folgt.",
        reading=as_printed(lambda: (sp.asin(sp.sqrt(sp.Subs(Sw, (a, s), (b, half)))) - pi / 4, 0)),
        note="sin(45 deg + omega) grows on 0 <= omega <= 45 deg: the one solution of sin(45 deg + omega) = "
             "sqrt(2)/2 there is omega = 0")
HALF_CUBE = {a: b, s: half, phi: pi / 4, mu: pi / 2}      # the 45-deg position, turned about the axis G_2 H_2
d.says("half-stable", "VI.D",
       r"D. h. ein Würfel vom spec. Gew.  $\frac{1}{2}$  kann aus der aufrechten labilen Lage nur durch Drehung um "
       r"eine horizontale Achse, die einer Kante parallel ist, in eine schiefe stabile Lage gelangen.",
       "schiefe stabile Lage", Called(at=HALF_CUBE),
       note="Read at the position the sentence names (a = b, s = 1/2, phi_1 = 45 deg, the tilt axis parallel to an "
            "edge) for the turn about the axis G_2 H_2 across the tilt axis (mu = 90 deg), the one direction in "
            "which the second variation can vanish ((51)); for the tilt axis itself (mu = 0) it is positive "
            "(stability-oblique).",
       erratum=Erratum(
           "claim", "high",
           r"\text{in eine schiefe Gleichgewichtslage, die in zweiter Ordnung indifferent und in dritter labil ist}",
           (r"The position is neutral to second order and unstable at the third: its stability for the turn about "
            r"$G_2 H_2$ vanishes, and the turn about the main axis, which leaves the first domain at once, lowers "
            r"the potential as $|\omega|^3$. At $a = b$, $s = \tfrac12$, $\varphi_1 = 45^\circ$ the waterplane's "
            r"moment about $G_2 H_2$ over the volume, $T_1/(V_1 \cos\varphi_1) = \sqrt2\, a/6$, equals the height "
            r"of $G$ above $B$, so the second variation of the potential is $0$ and 'stabil' is refuted as neutral, "
            r"as at every oblique position of the first domain ((51)). There the neutral turn about the main axis leads through equilibria at constant potential; here "
            r"the allowed range of $\omega$ shrinks to the single value $0$ (82), so the turn leaves the first domain "
            r"at once: the columns over the two corner triangles with $|\xi| > a/2$ are capped by the faces, and "
            r"with the plane still through the centre the potential changes by $\Delta = -2\sqrt2\, J/a^3 = "
            r"-\sqrt2\, a\, d^4/(12 \sin\omega \cos\omega) < 0$, $d = (\sin\omega + \cos\omega - 1)/2$, "
            r"about $-\sqrt2\, a\, |\omega|^3/192$ for either sign of $\omega$ (the steps on the cube at $s = "
            r"\tfrac12$). On the clipped unit cube: $\Delta(0.1) = -6.0 \times 10^{-6}$, $\Delta(0.3) = -1.03 "
            r"\times 10^{-4}$ (potential in units of the edge), agreeing with the closed form. Neutral to second "
            r"order, unstable at the third: the equilibrium tilt $\varphi_1 = 45^\circ$ and $\omega = 0$ are "
            r"right, the word 'stabile' is not."),
           corrected_reading=(Dlt, -sp.Abs(Dlt)),
           objection=(r"Scheeffer calls every oblique position of the first domain stable although its stability "
                      r"vanishes for the axis $G_2 H_2$ ((51): 'nur für die ... Achse $G_2 H_2$ ... ist es Null, "
                      r"folglich das Gleichgewicht stabil'): a position neutral in one direction counts as stable in "
                      r"his usage, so the cube at $s = \tfrac12$ is stable in his sense, or at worst neutral, and "
                      r"the sentence is right by the same standard as (78a)."),
           answer=(r"His neutral direction is harmless because the turn about the main axis leads through new "
                   r"equilibria at the same potential (the law of V, the potential independent of $\omega$ in the "
                   r"first domain); at $s = \tfrac12$ it leaves the first domain at once and the third-order term "
                   r"decides: the potential falls by about $\sqrt2\, a\, |\omega|^3/192$ for every turn $\omega "
                   r"\ne 0$ ($-6.0 \times 10^{-6}$ at $\omega = 0.1$ on the unit cube). So the position is neither "
                   r"stable in his sense nor merely neutral: neutral to second order (the stability $0$, which refutes "
                   r"'stabile' as printed), unstable at the third (the potential's fall, which the correction "
                   r"reads).")))
d.quote("half-tilt", "VI.D", r"$\varphi_1 = 45^\circ$",
        reading=(sp.atan(sp.sqrt(sp.Subs(tan2, (a, s), (b, half)))), pi / 4))
E_TILT = sp.tan(phi) ** 2 - tan2c                 # the oblique cube's tilt equation, zero at phi_1
E_81A = sp.tan(phi) ** 2 - 2 * (6 * s * (1 - s) - 1)   # (81a) as left minus right side, with the 6 of its erratum
d.quote("81-reference", "VI.D", "(die auch aus Gleichung 81 zu bestimmen ist)",
        reading=(sp.Derivative(GMc, phi), sp.Derivative(E_TILT, phi)),
        erratum=Erratum(
            "misprint", "low", r"\text{(die auch aus Gleichung 81 a zu bestimmen ist)}",
            ("(81) is the law of the upright cube, 'Ein Würfel schwimmt in aufrechter Lage stabil, wenn sein spec. "
             "Gewicht s > 0,7887 oder s < 0,2113 ist', its number standing alone after the closing quotation mark: a "
             r"condition on $s$ (the upright metacentric height $b(1 - 6s(1-s))/(12 s)$ positive) that holds no angle "
             r"and determines no oblique position. The tilt of the oblique position is (81a), $\operatorname{tg}^2 "
             r"\varphi_1 = 2\{6 s(1-s) - 1\}$, (78b) with $a = b$, displayed a few lines before; with it $s = 1/2$ "
             r"gives the $45^\circ$ of the second place, '(nach 81) $\varphi_1 = 45^\circ$'. The same number twice "
             "for (81a) is no fault a scan makes twice: the print's (or the author's), low since the number may cite "
             "the group of (81) and (81a)."),
            corrected_reading=(E_81A, E_TILT),
            objection="(81) may number the whole law of the cube, its three cases with (81a) among them, as (66) "
                      "numbers the whole law of the triangular prism after its closing quotation mark, so that "
                      "'Gleichung 81' cites the law that contains (81a).",
            answer="The transcription sets '(81)' after the closing quotation mark of the first case alone, and the "
                   "two cases after it stand outside the quotation, with (81a) numbered on its own; but the page "
                   "layout of the print is lost and (66) shows the author numbering a whole law, so the reference "
                   "may be loose rather than wrong: low."),
        note="read as: the equation cited determines the tilt of the oblique position: as left minus right side it "
             "varies with phi as the cube's tilt equation tg^2 phi - tg^2 phi_1 does; (81) read as its condition, "
             "the upright metacentric height of the cube, which contains no angle")
d.quote("81-reference-half", "VI.D", r"(nach 81)  $\varphi_1 = 45^\circ$",
        reading=(sp.Subs(sp.Derivative(GMc, phi), s, half), sp.Subs(sp.Derivative(E_TILT, phi), s, half)),
        erratum=Erratum(
            "misprint", "low", r"\text{(nach 81 a) } \varphi_1 = 45^\circ",
            (r"The second place of 'Gleichung 81' for (81a): at $s = 1/2$, (81a) gives $\operatorname{tg}^2\varphi_1 "
             r"= 2(6/4 - 1) = 1$, $\varphi_1 = 45^\circ$; (81), the law of the upright cube, gives no angle."),
            corrected_reading=(sp.Subs(E_81A, s, half), sp.Subs(E_TILT, s, half)),
            same_as="scheeffer-vi-cf/81-reference",
            objection="As at the first place, (81) may number the whole law of the cube, (81a) among its cases.",
            answer="As at the first place: the transcription numbers the upright law alone, but the layout of the "
                   "print is lost, so low."),
        note="read at s = 1/2 as the first place is read: the equation cited determines the tilt")
d.quote("half-waterplane", "VI.D",
        "der Wasserschnitt fällt also mit einem rechteckigen Diagonalschnitt des Würfels zusammen",
        reading=(sp.Subs(AII, (a, phi), (b, pi / 4)), b * sp.sqrt(2) * b),
        note="the waterplane of area F_1/cos 45 deg = a * a sqrt(2) through the centre: the rectangle through two "
             "opposite edges")

# ==== E. the regular n-gon prism ======================================================================
d.step("central-angle", Eq(alph, 2 * pi / n), "definition", result=alph, note="the angle AOB = BOC = ...")
d.step("side", Eq(aE, 2 * r * sp.sin(pi / n)), "definition", result=aE,
       note="the side a is the chord of the central angle 2 pi/n in the circumcircle of radius r")
d.step("apothem", Eq(h_, r * sp.cos(pi / n)), "definition", result=h_,
       note="the height OQ of the triangle BOC from the centre to the midpoint of its side")
d.step("apothem-from-side", (h_, aE / 2 * sp.cot(pi / n)), "algebra", uses=("side", "apothem"))


def over_triangle(f):
    """The isosceles triangle BOC: apex O at the origin, height h along X (the axis OQ), base a at X = h."""
    return sp.Integral(sp.Integral(f, (Y, -aE * X / (2 * h_), aE * X / (2 * h_))), (X, 0, h_))


d.step("triangle-area", (A_, over_triangle(1), aE * h_ / 2), "integration", result=A_)
d.step("triangle-Tx", (Tx, over_triangle(Y ** 2), A_ * aE ** 2 / 24), "integration", result=Tx,
       note="about the symmetry axis OQ")
d.step("triangle-Ty", (Ty, over_triangle(X ** 2), A_ * h_ ** 2 / 2), "integration", result=Ty,
       note="about the axis OR through the apex O perpendicular to OQ")
d.step("triangle-product", (over_triangle(X * Y), 0), "integration", note="OQ is a symmetry axis")
d.step("triangle-TL", (TL, over_triangle((-X * sp.sin(psi) + Y * sp.cos(psi)) ** 2),
                       Ty * sp.sin(psi) ** 2 + Tx * sp.cos(psi) ** 2), "integration", result=TL,
       uses=("triangle-Tx", "triangle-Ty", "triangle-product"),
       note="about the axis L through O at the angle psi (the text's phi) to OQ")
k_ = sp.Symbol("k", integer=True, positive=True)
d.step("cosine-sums", (sp.Matrix([sp.Sum(sp.cos(2 * k_ * al_), (k_, 1, m)).doit()
                                  - sp.sin(m * al_) * sp.cos((m + 1) * al_) / sp.sin(al_) for m in range(3, 7)]),
                       sp.zeros(4, 1)), "series",
       note="Lagrange's sum cos 2x + cos 4x + ... + cos 2mx = sin(mx) cos((m+1)x)/sin x, checked for m = 3..6 with "
            "x = alpha_t arbitrary")
d.step("cosine-sum", Eq(Sc, sp.sin(n * alph) * sp.cos((n + 1) * alph) / sp.sin(alph)), "definition", result=Sc,
       uses=("cosine-sums",), note="Sigma_c = cos 2 alpha + cos 4 alpha + ... + cos 2 n alpha (n terms)")
d.step("cosine-sum-zero", (Sc, 0), "algebra", uses=("cosine-sum", "central-angle"), note="sin(n alpha) = sin 2 pi = 0")
d.step("polygon-moment-def", Eq(T1n, n / 2 * (Tx + Ty) + (Tx - Ty) / 2 * Sc), "definition", result=T1n,
       uses=("triangle-TL",),
       note="sum of T_L over the n triangles, the k-th turned by psi = k alpha against the symmetry axis MN")
d.step("polygon-moment", (T1n, n / 2 * (Tx + Ty), n * A_ / 4 * (aE ** 2 / 12 + h_ ** 2)), "algebra",
       uses=("polygon-moment-def", "cosine-sum-zero", "triangle-Tx", "triangle-Ty"))
d.step("polygon-perpendicular", (sp.Matrix([n / 2 * (Tx + Ty) + (Tx - Ty) / 2 * sum(
    sp.cos(pi + 2 * j * 2 * pi / m) for j in range(1, m + 1)) for m in range(3, 9)]),
    n / 2 * (Tx + Ty) * sp.ones(6, 1)), "algebra",
       note="the same moment about the axis perpendicular to MN (psi = 90 deg + k alpha): cos(pi + p alpha) = "
            "-cos(p alpha), the sum vanishes as well (shown for n = 3..8)")
d.step("polygon-area", (F1n, n * A_, n * r ** 2 / 2 * sp.sin(2 * pi / n)), "algebra", result=F1n,
       uses=("triangle-area", "side", "apothem"))
d.step("largest-ordinate-n", Eq(umn, r * sp.cos(pi / n - om)), "definition", result=umn,
       note="omega from the direction of a side: the vertex B at the end of that side, on the sinking half, lies at "
            "the angle 90 deg - pi/n + omega from the axis; for 0 <= omega <= 2 pi/n it is the farthest vertex "
            "there (checked on the clipped polygons)")

PSI = "VI.E reuses phi for the angle of the axis L with OQ; the module's varphi is the tilt, so that angle is psi"
d.quote("triangle-axis", "VI.E", r"$$T = T_y \cdot \sin^2 \varphi + T_x \cdot \cos^2 \varphi$$",
        reading=(TL, Ty * sp.sin(psi) ** 2 + Tx * sp.cos(psi) ** 2), note="the text's phi is psi here",
        symbols={r"\varphi": (psi, PSI)})
d.quote("triangle-symmetric", "VI.E",
        "(da O Q eine Symmetrieachse ist und folglich die Summe  $\\int x y d f$ , bezogen auf die Dreiecksfläche, "
        "Null ist).", reading=(over_triangle(X * Y), 0))
d.quote("83", "(83)", r"$$T = \frac{1}{2} (T_x + T_y) + \frac{1}{2} (T_x - T_y) \cos 2 \varphi. \quad (83)$$",
        reading=(TL, (Tx + Ty) / 2 + (Tx - Ty) / 2 * sp.cos(2 * psi)), note="the text's phi is psi here",
        symbols={r"\varphi": (psi, PSI)})
# Fig. 15 (lost): the vertices on the circle of radius r at the angles (k - 1/2) alpha from MN, so that M, the
# middle of AB, lies on MN: B at alpha/2, C at 3 alpha/2; Q, the foot of the height OQ of BOC, is the middle of BC
Q_BOC = (sp.Matrix([sp.cos(alph / 2), sp.sin(alph / 2)]) + sp.Matrix([sp.cos(3 * alph / 2), sp.sin(3 * alph / 2)])) * r / 2
d.quote("height-OV", "VI.E",
        r"so bildet für das Dreieck B O C die Achse M N mit der Höhe O V den Winkel  $\varphi = \alpha$",
        unreadable="V names no point of VI.E: the height of the triangle BOC is OQ (defined before (83), whose angle "
                   r"$\varphi$ is measured from OQ); no point V is introduced",
        erratum=Erratum("misprint", "low", r"\text{mit der Höhe } O Q \text{ den Winkel } \varphi = \alpha",
                        "The paragraph defines the height of the isosceles triangle BCO as $OQ = h$ and measures the "
                        r"angle $\varphi$ of (83) between the axis L and OQ; the sentence applies (83) to BOC with $L "
                        "= MN$, so the height meant is OQ, the only height of BOC the text names (the line OV occurs "
                        r"nowhere else in the section). With the vertices at the angles $(k - \tfrac12)\alpha$ from "
                        r"MN, OQ (Q the middle of BC) lies at the angle $\alpha$ from MN, as the sentence says. A Q "
                        "printed as V (a letter of another drawing of Fig. 15, or the typesetter's); low, since the "
                        "figure is lost and the scan may have misread the letter.",
                        corrected_reading=(sp.Matrix([Q_BOC[0] * sp.sin(alph) - Q_BOC[1] * sp.cos(alph),
                                                      Q_BOC[0] * sp.cos(alph) + Q_BOC[1] * sp.sin(alph)]),
                                           sp.Matrix([0, h_])),
                        objection="OV may be the name of the height in the lost Fig. 15, V the foot on BC that the "
                                  "text elsewhere calls Q.",
                        answer="The paragraph names the height of BCO OQ = h and the line OV nowhere else; whether "
                               "the figure, the typesetter or the scan wrote V cannot be told, so it stays low."),
        note="read as: OQ lies at the angle alpha from MN (its component across the direction alpha vanishes, along "
             "it is the apothem OQ = h)")
d.quote("84", "(84)",
        r"$$T_1 = \frac{n}{2} (T_x + T_y) + \frac{1}{2} (T_x - T_y) \left( \cos 2 \alpha + \cos 4 \alpha + \dots "
        r"\right) \quad (84)$$", reading=(T1n, n / 2 * (Tx + Ty) + (Tx - Ty) / 2 * Sc))
d.quote("85", "(85)",
        r"$$T_1 = \frac{n}{2} (T_x + T_y) + \frac{1}{2} (T_x - T_y) \left\{ \cos (\pi + 2 \alpha) + \cos (\pi + 4 "
        r"\alpha) + \dots \right\} \quad (85)$$", reading=(T1n, n / 2 * (Tx + Ty) + (Tx - Ty) / 2 * (-Sc)),
        note="cos(pi + p alpha) = -cos(p alpha): the braces hold -Sigma_c")
p_ = sp.Symbol("p", positive=True)
d.domain[p_] = (1, 12)
d.quote("cos-pi", "(86)", r"$\cos (\pi + p \alpha) = - \cos p \alpha$",
        reading=as_printed(lambda: (sp.cos(pi + p_ * alph), -sp.cos(p_ * alph))))
d.quote("cos-pi-sum", "(86)", r"$\cos p \alpha + \cos (\pi + p \alpha) = 0$",
        reading=as_printed(lambda: (sp.cos(p_ * alph) + sp.cos(pi + p_ * alph), 0)))
d.quote("86", "(86)",
        r"$$2 T_1 = n (T_x + T_y) \quad \text{oder} \quad T_1 = \frac{n}{2} (T_x + T_y) \quad (86)$$",
        reading=(sp.Matrix([2 * T1n, T1n]), sp.Matrix([n * (Tx + Ty), n / 2 * (Tx + Ty)])))
d.quote("triangle-moments", "VI.E", r"$$T_x = A \cdot \frac{a^2}{24}, \quad T_y = A \cdot \frac{h^2}{2}$$",
        reading=(sp.Matrix([Tx, Ty]), sp.Matrix([A_ * aE ** 2 / 24, A_ * h_ ** 2 / 2])))
d.quote("86-nA", "VI.E", r"$$T_1 = \frac{n A}{4} \left( \frac{a^2}{12} + h^2 \right)$$",
        reading=(T1n, n * A_ / 4 * (aE ** 2 / 12 + h_ ** 2)))
d.quote("apothem", "VI.E", r"$h = \frac{a}{2} \omega \operatorname{tg} \left( \frac{\pi}{n} \right)$",
        reading=(h_, aE / 2 * om * sp.tan(pi / n)),
        erratum=Erratum("transcription", "high", r"h = \frac{a}{2} \operatorname{cotg} \left( \frac{\pi}{n} \right)",
                        r"The apothem of the regular n-gon of side a is $(a/2) \cot(\pi/n)$ (half the side over the "
                        r"tangent of half the central angle). '$\operatorname{cotg}$' read as '$\omega "
                        r"\operatorname{tg}$' is a known confusion of the scan; $\omega$ (the axis angle) has no "
                        "place here.",
                        corrected_reading=(h_, aE / 2 * sp.cot(pi / n)),
                        objection=r"'$\omega \operatorname{tg}$' may be read as printed, the product of the axis "
                                  r"angle $\omega$ and $\operatorname{tg}(\pi/n)$.",
                        answer=r"$\omega$, the angle of the axis, has no place in the apothem of the n-gon, $(a/2) "
                               r"\cot(\pi/n)$; the examples after (86a) use $\cot^2 60^\circ = \tfrac13$ and $\cot^2 "
                               r"45^\circ = 1$, which only $\operatorname{cotg}$ gives. '$\operatorname{cotg}$' read "
                               r"as '$\omega \operatorname{tg}$' is the scan's."))
d.quote("86a", "(86a)",
        r"$$T_1 = \frac{F_1 a^2}{16} \left\{ \frac{1}{3} + \omega \operatorname{tg}^2 \left( \frac{\pi}{n} \right) "
        r"\right\} \quad (86a)$$",
        reading=(T1n, F1n * aE ** 2 / 16 * (sp.Rational(1, 3) + om * sp.tan(pi / n) ** 2)),
        erratum=Erratum("transcription", "high",
                        r"T_1 = \frac{F_1 a^2}{16} \left\{ \frac{1}{3} + \operatorname{cotg}^2 \left( \frac{\pi}{n} "
                        r"\right) \right\}",
                        r"With $h = (a/2) \cot(\pi/n)$, $n A (a^2/12 + h^2)/4 = F_1 a^2 (\tfrac13 + "
                        r"\cot^2(\pi/n))/16$; the examples that follow use $\cot^2 60^\circ = \tfrac13$ and $\cot^2 "
                        r"45^\circ = 1$, and (87) follows only with $\cot$. The same '$\operatorname{cotg}$' read as "
                        r"'$\omega \operatorname{tg}$' of the scan as in $h$.",
                        corrected_reading=(T1n, F1n * aE ** 2 / 16 * (sp.Rational(1, 3) + sp.cot(pi / n) ** 2)),
                        objection=r"As for h: '$\omega \operatorname{tg}^2$' read as the product of the axis angle "
                                  r"and $\operatorname{tg}^2(\pi/n)$.",
                        answer=r"$n A (a^2/12 + h^2)/4$ with $h = (a/2) \cot(\pi/n)$ gives the $\operatorname{cotg}$; "
                               r"the examples' values $\tfrac13$ and $1$ and (87) follow only from it."))
d.quote("side", "VI.E", r"$$a = 2 r \cdot \sin \left( \frac{\pi}{n} \right)$$", reading=(aE, 2 * r * sp.sin(pi / n)))
d.quote("87", "(87)",
        r"$$T_1 = \frac{1}{12} \cdot F_1 r^2 \left\{ 1 + 2 \cos^2 \left( \frac{\pi}{n} \right) \right\} \quad (87)$$",
        reading=(T1n, F1n * r ** 2 / 12 * (1 + 2 * sp.cos(pi / n) ** 2)))
d.quote("87-cos2", "(87)",
        r"$$\text{oder} \quad T_1 = \frac{1}{12} \cdot F_1 r^2 \left\{ 2 + \cos \left( \frac{2 \pi}{n} \right) \right\}$$",
        reading=(T1n, F1n * r ** 2 / 12 * (2 + sp.cos(2 * pi / n))))
d.quote("triangle-data", "VI.E",
        r"$$n = 3, F_1 = \frac{a^2}{4} \sqrt{3}, \quad \frac{\pi}{n} = 60^\circ, \quad \omega \operatorname{tg}^2 "
        r"\left( \frac{\pi}{n} \right) = \frac{1}{3}$$",
        reading=(sp.Matrix([sp.Subs(F1n, n, 3), sp.Subs(om * sp.tan(pi / n) ** 2, n, 3)]),
                 sp.Matrix([sp.Subs(aE ** 2 / 4 * sp.sqrt(3), n, 3), sp.Rational(1, 3)])),
        note="pi/3 = 60 deg needs no check",
        erratum=Erratum("transcription", "high",
                        r"\operatorname{cotg}^2 \left( \frac{\pi}{n} \right) = \frac{1}{3}",
                        r"$\cot^2 60^\circ = \tfrac13$, whereas $\tan^2 60^\circ = 3$; '$\operatorname{cotg}$' read "
                        r"as '$\omega \operatorname{tg}$' as in (86a).",
                        corrected_reading=(sp.Matrix([sp.Subs(F1n, n, 3), sp.Subs(sp.cot(pi / n) ** 2, n, 3)]),
                                           sp.Matrix([sp.Subs(aE ** 2 / 4 * sp.sqrt(3), n, 3), sp.Rational(1, 3)])),
                        objection=r"'$\omega \operatorname{tg}^2(\pi/n) = \tfrac13$' may be read as printed, fixing "
                                  r"$\omega$ for the triangle.",
                        answer=r"$\operatorname{tg}^2 60^\circ = 3$ and $\cot^2 60^\circ = \tfrac13$; the value is "
                               r"the cotangent's, and $\omega$ is free in the section (the law of V)."))
d.quote("triangle-T1", "VI.E",
        r"$$T_1 = F_1 \cdot \frac{a^2}{24} = \frac{a^4}{96} \cdot \sqrt{3} = \frac{F_1^2}{6 \sqrt{3}}$$",
        reading=tuple(sp.Subs(e_, n, 3) for e_ in (T1n, F1n * aE ** 2 / 24, aE ** 4 / 96 * sp.sqrt(3),
                                                   F1n ** 2 / (6 * sp.sqrt(3)))),
        note="'aus 86' means (86a)")
d.quote("square-data", "VI.E",
        r"$n = 4, F_1 = a^2, \frac{\pi}{n} = 45^\circ, \omega \operatorname{tg}^2 \left( \frac{\pi}{n} \right) = 1$",
        reading=(sp.Matrix([sp.Subs(F1n, n, 4), sp.Subs(om * sp.tan(pi / n) ** 2, n, 4)]),
                 sp.Matrix([sp.Subs(aE ** 2, n, 4), 1])),
        erratum=Erratum("transcription", "high", r"\operatorname{cotg}^2 \left( \frac{\pi}{n} \right) = 1",
                        r"$\cot^2 45^\circ = 1$; as printed the value would depend on the axis angle $\omega$. "
                        r"'$\operatorname{cotg}$' read as '$\omega \operatorname{tg}$' as in (86a).",
                        corrected_reading=(sp.Matrix([sp.Subs(F1n, n, 4), sp.Subs(sp.cot(pi / n) ** 2, n, 4)]),
                                           sp.Matrix([sp.Subs(aE ** 2, n, 4), 1])),
                        objection=r"'$\omega \operatorname{tg}^2(\pi/n) = 1$' may be read as printed, fixing $\omega "
                                  "= 1$ for the square.",
                        answer=r"$\operatorname{tg}^2 45^\circ = \cot^2 45^\circ = 1$, so the value is the "
                               "cotangent's, as in (86a); an axis angle of one radian has no role in the section."))
d.quote("square-T1", "VI.E", r"$$T_1 = \frac{F_1 a^2}{12} = \frac{a^4}{12} = \frac{F_1^2}{12}$$",
        reading=tuple(sp.Subs(e_, n, 4) for e_ in (T1n, F1n * aE ** 2 / 12, aE ** 4 / 12, F1n ** 2 / 12)))
d.quote("circle-data", "VI.E",
        r"$$F_1 = \pi r^2, \quad n = \infty, \quad \frac{2 \pi}{n} \rightarrow 0, \quad \cos \frac{2 \pi}{n} = 1$$",
        reading=(sp.Matrix([sp.Limit(F1n, n, sp.oo), sp.Limit(alph, n, sp.oo), sp.Limit(sp.cos(alph), n, sp.oo)]),
                 sp.Matrix([pi * r ** 2, 0, 1])))
d.quote("circle-T1", "VI.E",
        r"$$T_1 = \frac{1}{12} \cdot \pi r^4 \cdot 3 = \frac{\pi r^4}{4} = \frac{F_1^2}{4 \pi}$$",
        reading=as_printed(lambda: (sp.Limit(T1n, n, sp.oo), pi * r ** 4 * 3 / 12, pi * r ** 4 / 4, (pi * r ** 2) ** 2 / (4 * pi))),
        note="the limit n -> infinity at fixed r; it agrees with T_1 = pi r^4/4 of section B")
_w3 = (r - Y) * 2 / sp.sqrt(3)           # the width at height Y of the equilateral triangle of circumradius r
d.quote("agree-known", "VI.E", "Alle drei Werte stimmen mit den bekannten und oben benutzten überein.",
        reading=(sp.Matrix([sp.Subs(T1n, n, 3), sp.Subs(T1n, n, 4), sp.Limit(T1n, n, sp.oo)]),
                 sp.Matrix([sp.Integral(Y ** 2 * _w3, (Y, -r / 2, r)),
                            sp.Integral(Y ** 2 * r * sp.sqrt(2), (Y, -r / sp.sqrt(2), r / sp.sqrt(2))),
                            sp.Integral(Y ** 2 * 2 * sp.sqrt(r ** 2 - Y ** 2), (Y, -r, r))])),
        note="the known moments, integrated directly over the equilateral triangle, the square (circumradius r) and "
             "the circle: 3 sqrt3 r^4/32 = sqrt3 a^4/96 (VI.A), r^4/3 = a^4/12 (VI.C), pi r^4/4 (VI.B)")
d.quote("88", "(88)", r"$$u_m = r \cdot \sin \left( \frac{n-2}{2n} \cdot \pi + \omega \right) \quad (88)$$",
        reading=(umn, r * sp.sin((n - 2) / (2 * n) * pi + om)))

# ==== F. comparison at equal base area =================================================================
npos = sp.Integral(2 * sp.sin(t_) * (t_ - sp.sin(t_)), (t_, 0, 2 * pi / n))
d.step("area-radius", (r ** 2, 2 * F1n / (n * sp.sin(2 * pi / n))), "algebra", uses=("polygon-area",))
d.step("moment-at-area", (T1F, (F * r ** 2 / 12 * (2 + sp.cos(2 * pi / n))).subs(r ** 2, 2 * F / (n * sp.sin(2 * pi / n))),
                          as_printed(lambda: F ** 2 / (12 * pi) * (2 * pi / n) / sp.sin(2 * pi / n) * (2 + sp.cos(2 * pi / n)))),
       "algebra", result=T1F, uses=("area-radius",),
       note="T_1 of the regular n-gon of area F (87 with r^2 from the area)")
d.step("moment-derivative", (sp.Derivative(T1F, n), -F ** 2 / (12 * pi) * 2 * pi / n ** 2 * npos / sp.sin(2 * pi / n) ** 2),
       "integration", uses=("moment-at-area",),
       note="d/dalpha [alpha (2 + cos alpha)/sin alpha] = N(alpha)/sin^2 alpha with N(alpha) = 2 sin alpha + "
            "sin(2 alpha)/2 - alpha(1 + 2 cos alpha) = int_0^alpha 2 sin t (t - sin t) dt > 0 for 0 < alpha <= "
            "2pi/3; alpha = 2 pi/n decreases with n")
d.step("oblique-equilibrium-general", (tan2g, 2 * (Fg * b * s * e1 / Tg - 1), Fg * b ** 2 * s * (1 - s) / Tg - 2),
       "algebra", result=tan2g, uses=("oblique-equilibrium", "e1"),
       note="(54) for a prism whose base F_g has the same moment T_g about every axis through its centroid (V_1 = F_g b s)")

d.quote("area", "VI.F", r"$F_1 = n \cdot \frac{r^2}{2} \sin \frac{2 \pi}{n}$",
        reading=(F1n, n * r ** 2 / 2 * sp.sin(2 * pi / n)))
d.quote("radius", "VI.F",
        r"$$r^2 = \frac{2 F_1}{n \cdot \sin \frac{2 \pi}{n}} = \frac{F_1}{\pi} \frac{\frac{2 \pi}{n}}{\sin \frac{2 \pi}{n}}$$",
        reading=as_printed(lambda: (r ** 2, 2 * F1n / (n * sp.sin(2 * pi / n)), F1n / pi * (2 * pi / n) / sp.sin(2 * pi / n))))
d.quote("89", "(89)",
        r"$$T_1 = \frac{F_1^2}{12 \pi} \cdot \frac{\frac{2 \pi}{n}}{\sin \frac{2 \pi}{n}} \cdot \left( 2 + \cos "
        r"\frac{2 \pi}{n} \right) \quad (89)$$",
        reading=(T1n, F1n ** 2 / (12 * pi) * (2 * pi / n) / sp.sin(2 * pi / n) * (2 + sp.cos(2 * pi / n))))
d.quote("89a", "(89a)",
        r"$$T_1 = \frac{F_1^2}{12 \pi} \cdot \frac{\alpha}{\sin \alpha} \cdot (2 + \cos \alpha) \quad (89a)$$",
        reading=(T1n, F1n ** 2 / (12 * pi) * alph / sp.sin(alph) * (2 + sp.cos(alph))))
d.quote("decreasing", "VI.F",
        "Alle regelmässigen Polygone von gleichem Flächeninhalt haben ein um so kleineres Trägheitsmoment, je grösser "
        "ihre Seitenzahl ist",
        reading=(sp.Derivative(T1F, n), -F ** 2 / (12 * pi) * 2 * pi / n ** 2 * npos / sp.sin(2 * pi / n) ** 2),
        note="the derivative in n at fixed area equals a manifestly negative expression (integrand 2 sin t (t - sin t) "
             "> 0 on (0, 2pi/3])")
d.quote("triangle-largest", "VI.F", r"Das grösste Trägheitsmoment hat hiernach das Dreieck, nämlich  "
                                    r"$\frac{F_1^2}{6\sqrt{3^1}}$",
        reading=(sp.Subs(T1F, n, 3), F ** 2 / (6 * sp.sqrt(3 ** 1))),
        note="'3^1': a stray mark of the scan, read literally it is 3")
d.quote("circle-smallest", "VI.F", r"das kleinste der Kreis, nämlich  $\frac{F_1^2}{4\pi}$",
        reading=(sp.Limit(T1F, n, sp.oo), F ** 2 / (4 * pi)), note="the infimum over n, reached only in the limit")
d.quote("duhamel-decreasing", "VI.F", "$$T_1 - V_1 e_1$$\n\nauch um so kleiner, je grösser die Seitenzahl ist.",
        reading=(sp.Derivative(T1F - F * b * s * e1, n), -F ** 2 / (12 * pi) * 2 * pi / n ** 2 * npos / sp.sin(2 * pi / n) ** 2),
        note="V_1 e_1 = F b s e_1 does not depend on n")
d.quote("duhamel-fewer-sides", "VI.F",
        "Folglich wird auch nach dem Duhamel'schen Satze die Möglichkeit der aufrechten Stabilität (und ihre Grösse) "
        "mit zunehmender Seitenzahl abnehmen.",
        reading=(sp.Derivative(T1F / (F * b * s) - e1, n),
                 -F / (12 * pi * b * s) * 2 * pi / n ** 2 * npos / sp.sin(2 * pi / n) ** 2),
        note="the metacentric height T_1/V_1 - e_1 (V_1 = F b s, e_1 independent of n) decreases with n: its derivative "
             "is a manifestly negative expression")
tanF = F * b ** 2 * s * (1 - s) / T1F - 2
d.quote("54-again", "VI.F", r"$$\operatorname{tg}^2 \varphi_1 = \frac{F b^2 s (1 - s)}{T_1} - 2$$",
        reading=(sp.Subs(tan2g, (Fg, Tg), (F, T1F)), tanF),
        note="'Nach 55' of the text: the equation is (54) (erratum 55-reference)")
d.quote("55-reference", "VI.F", r"Nach 55 ist ferner",
        reading=(tanF, (sp.Min(b * (1 - s), b * s) / sp.Subs(umn, r, sp.sqrt(2 * F / (n * sp.sin(2 * pi / n))))) ** 2),
        erratum=Erratum("misprint", "low", r"\text{Nach 54 ist ferner}",
                        r"The formula quoted after the words, $\operatorname{tg}^2\varphi_1 = F b^2 s(1-s)/T_1 - 2$, "
                        "is (54), the oblique equilibrium of a prism whose base has equal moments about all central "
                        r"axes; (55) is the bound $\operatorname{tg}\varphi_1 \le b(1-s)/u_m$ ($s > \tfrac12$), $b "
                        r"s/u_m$ ($s < \tfrac12$) of the first rotation region, which limits the tilt and does not "
                        "determine it. A wrong equation number; 4 and 5 are close in print and in the scan alike "
                        "(low).",
                        corrected_reading=(tanF, sp.Subs(tan2g, (Fg, Tg), (F, T1F))),
                        objection="55 may be the scan's reading of a 54, the fault being the transcription's and not"
                                  " the print's.",
                        answer="The formula quoted after the words is (54), not the bound (55), so the reference is "
                               "wrong; but 4 and 5 are close in print and in the scan alike and nothing in the text "
                               "tells which erred, so the kind cannot be fixed: lowered to low."),
        note="read as: the equation cited gives the tg^2 phi_1 written next; (55) read at its bound for the regular "
             "n-gon of area F (u_m of (88) with r^2 = 2F/(n sin 2pi/n))")
d.quote("tilt-increasing", "VI.F",
        r"dass der Winkel  $\varphi_1$ , der die schiefe Stabilitätslage bestimmt, mit wachsender Seitenzahl zunehmen "
        r"muss",
        reading=(sp.Derivative(tanF, n),
                 F * b ** 2 * s * (1 - s) / T1F ** 2 * F ** 2 / (12 * pi) * 2 * pi / n ** 2 * npos / sp.sin(2 * pi / n) ** 2),
        note="d tan^2 phi_1/dn equals a manifestly positive expression")
d.quote("cylinder-most-oblique", "VI.F",
        "Von allen oben erwähnten Prismen schwimmt also der Cylinder in der schiefesten Lage stabil, das dreiseitige "
        "Prisma ist der aufrechten Lage am nächsten.",
        reading=(sp.Limit(tanF, n, sp.oo) - sp.Subs(tanF, n, 3), b ** 2 * s * (1 - s) * (4 * pi - 6 * sp.sqrt(3)) / F),
        note="with the monotony in n, the extremes are the triangle (n = 3) and the cylinder (n -> infinity); "
             "4 pi > 6 sqrt 3")

d.provides("thresholds", (slo, shi, s80lo, s80hi, sedlo, sedhi))   # phase diagrams name these closed forms
