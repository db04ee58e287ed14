"""What Scheeffer's section X says and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import PRINTED_DIGITS, Derivation, Eq, Erratum, Holds, Iff, RealRoots
from symfloat.model.claim import as_printed
from symfloat.model.symbol_names import symbol

a, om, rho, rho1, k, s, L = sp.symbols("a omega rho rho_1 k s L", positive=True)
x, y, X, Y, Z, w, xl = sp.symbols("x y X Y Z w x_l", real=True)
half, r2, pi = sp.Rational(1, 2), sp.sqrt(2), sp.pi
co, si = sp.cos(om), sp.sin(om)
tg, ctg = si / co, co / si                      # tg, cotg of the text

# quantities established by steps
u_, v_, h_, h1_, IH, IG, P, P1, rs = sp.symbols("u v h h_1 J_HPB J_GPB P P_1 rho_*")
Tb, Td, M2, Ar = sp.symbols("J_top J_bot M_2 A_BHG")
Sq = symbol("J_sq", r"J_{\text{square}}")
Tq, zq, V3, kq, MX, Mz, dE, F0, F1v = sp.symbols("T z V_3 k_171 M_X M_z E_theta f_0 f_1")
s172, Sw45, Vt, s56, It, GMt, Ih, Bh, GMh, k3, Me, NVp, NVd = sp.symbols(
    "s_172 S_45 V_t s_56 I_t GM_t I_h BG_h GM_h k_3 M_e N_p N_d")
uD = symbol("uD_t", r"u_{D,t}")             # the dry tetrahedron's centroid D along the up vector u

DERIVATION = d = Derivation(
    id="scheeffer-x",
    source="scheeffer",
    title="The equilibrium positions of a floating cube",
    locator="X",
    summary="Pentagonal and triangular waterplanes need the axis along a face diagonal (168)-(170); the pentagon's "
            "second condition (171) and its root range (172); the wrong conclusion that every unstable upright "
            "cube with 1/2 < s < 0.7735 has a stable pentagonal position; the triangle (s > 5/6, unstable) and "
            "the hexagon (symmetric, stable at s = 1/2).",
    requires=("scheeffer-vi-cf",),
    domain={a: (1, 2), om: (0.05, 0.75), rho: (0.1, 0.95), rho1: (0.1, 0.95), k: (0.1, 2), s: (0.55, 0.95),
            L: (0.1, 0.99), x: (0, 1), y: (-1, 1), X: (-1, 1), Y: (-1, 1), Z: (-1, 1), w: (-1.5, 1.5),
            xl: (0.02, 0.98), u_: (0.1, 1), v_: (0.1, 1), h_: (0.1, 1)},
    constraints=(),
    assumptions=("the cube of edge a (a = 1 from (171) on), homogeneous, density 0 < s < 1 relative to the water",
                 "one face cut (second domain): the top face loses the corner triangle BHG, BH = rho < a, "
                 "BG = rho tan(omega) < a, 0 < omega < 45 deg (the other half by the symmetry H <-> G); sampled "
                 "with a >= 1 > rho so that both hold",
                 "two parallel faces cut (third domain): the bottom face loses the triangle LDM with LD = rho_1, "
                 "its water line parallel to GH; the water plane passes through both water lines",
                 "(171): omega = 45 deg, a = 1, leg x of the cut triangle, s > 1/2, the bottom face uncut; "
                 "s < 1/2 follows by the duality s <-> 1 - s (turn the cube over, exchange wet and dry)",
                 "the potential of a floating body is u.(G - B) (height of G above B); its derivative along a "
                 "turn of the up vector u is (du).(G - B), since u.dB = 0 (the waterplane is tangent to the "
                 "surface of buoyancy; checked on the clipped cube in the tests)",
                 "sign identities: a printed inequality L > R is read as L - R = (positive factor) × (the "
                 "quantity whose sign decides); the factor is stated in the note"),
)

# ==== one face cut: the first condition (167)-(170) ==================================================
Hp = sp.Matrix([a / 2 - rho, a / 2])          # body frame of the top face, O the origin, B = (a/2, a/2)
Gp = sp.Matrix([a / 2, a / 2 - rho * tg])
Bp = sp.Matrix([a / 2, a / 2])
e_ = sp.Matrix([co, -si])                      # along GH, from H towards G
n_ = sp.Matrix([si, co])                       # across GH, towards B
d.step("NH", (u_, -Hp.dot(e_), (rho - a / 2) * co + a / 2 * si), "geometry", result=u_,
       note="N = H + u e is the foot of the perpendicular from O (e·N = 0)")
d.step("NG", (v_, as_printed(lambda: Gp.dot(e_)), a / 2 * co - (a / 2 - rho * tg) * si), "geometry", result=v_)
d.step("height", (h_, as_printed(lambda: n_.dot(Bp - Hp)), rho * si), "geometry", result=h_, note="h = BP, the distance of B from GH")
d.step("HPB", (IH, sp.Integral(x * y, (y, -u_ + x * ctg, -u_ + h_ * ctg), (x, 0, h_)),
               h_ ** 4 / 8 * ctg ** 2 - u_ * h_ ** 3 / 6 * ctg), "integration", result=IH,
       note="origin N: H = (0, -u), P = (0, -u + h cot w), B = (h, -u + h cot w); HB is y = -u + x cot w")
d.step("GPB", (IG, sp.Integral(x * y, (y, v_ - h_ * tg, v_ - x * tg), (x, 0, h_)),
               v_ * h_ ** 3 / 6 * tg - h_ ** 4 / 8 * tg ** 2), "integration", result=IG,
       note="G = (0, v), P = (0, v - h tan w); GB is y = v - x tan w")
d.step("167", (P, IH + IG, h_ ** 3 / 6 * (v_ * tg - u_ * ctg) + h_ ** 4 / 8 * (ctg ** 2 - tg ** 2)), "algebra",
       uses=("HPB", "GPB"), result=P)
FAC = 2 * a * co - rho * (co + si)
P168 = h_ ** 3 * (co - si) / (24 * si * co ** 2) * FAC
d.step("168", (P, h_ ** 3 / 6 * (v_ * tg - u_ * ctg) + h_ ** 4 / 8 * (ctg ** 2 - tg ** 2), P168), "algebra",
       uses=("167", "NH", "NG", "height"), result=P)
d.step("factor-positive", (FAC, co * ((a - rho) + (a - rho * tg))), "algebra",
       note="positive whenever rho < a and rho tan w < a: the second factor of (168) never vanishes")
d.step("rho-star", Eq(rs, 2 * a * co / (co + si)), "definition", result=rs,
       note="the zero of the second factor of (168)")
d.step("second-root", (FAC.subs(rho, rs), 0), "algebra", uses=("rho-star",))
d.step("169a-margin", (a - rs, a * (si - co) / (co + si)), "algebra", uses=("rho-star",))
d.step("169b-margin", (a - rs * tg, a * (co - si) / (co + si)), "algebra", uses=("rho-star",))
d.step("169-exclusive", ((a - rs) * (a - rs * tg), -a ** 2 * (co - si) ** 2 / (co + si) ** 2), "algebra",
       uses=("169a-margin", "169b-margin"), note="never positive: rho_* < a and rho_* tan w < a exclude each other")
d.step("sign-of-P", (P, h_ ** 3 * (co - si) * ((a - rho) + (a - rho * tg)) / (24 * si * co)), "algebra",
       uses=("168", "factor-positive"),
       note="every factor but cos w - sin w is positive: P = 0 only at w = 45 deg, P > 0 for 0 < w < 45 deg")

POS = h_ ** 3 * ((a - rho) + (a - rho * tg)) / (24 * si * co)
d.quote("HPB", "X (167)",
        r"$$\int x y \, d f = \frac{h^4}{8} \cotg^2 \omega - u \cdot \frac{h^3}{6} \cotg \omega^*)$$",
        reading=(IH, h_ ** 4 / 8 * ctg ** 2 - u_ * h_ ** 3 / 6 * ctg),
        note="the asterisk is a footnote mark; the formula is about N (the origin 'nach H' of the text is where the "
             "integral is set up, -u h^3 cot(w)/6 the shift to N)")
d.quote("GPB", "X (167)", r"$$\int x y \, d f = v \cdot \frac{h^3}{6} \tg \omega - \frac{h^4}{8} \tg^2 \omega$$",
        reading=(IG, v_ * h_ ** 3 / 6 * tg - h_ ** 4 / 8 * tg ** 2))
d.quote("167-sum", "X (167)",
        r"$$\int x y \, d f = \frac{h^3}{6} (v \tg \omega - u \cotg \omega) + \frac{h^4}{8} (\cotg^2 \omega - "
        r"\tg^2 \omega) = 0$$",
        reading=(P, h_ ** 3 / 6 * (v_ * tg - u_ * ctg) + h_ ** 4 / 8 * (ctg ** 2 - tg ** 2)),
        note="'= 0' is the condition (98) imposed on this value")
d.quote("167", "(167)",
        r"$$\int x y \cdot d f = h^3 \left\{ \frac{1}{6} (v \tg \omega - u \cotg \omega) + \frac{h}{8} (\cotg^2 "
        r"\omega - \tg^2 \omega) \right\} = 0 \quad (167)$$",
        reading=(P, h_ ** 3 * ((v_ * tg - u_ * ctg) / 6 + h_ / 8 * (ctg ** 2 - tg ** 2))))
d.quote("u", "X", r"$$u = \left( \varrho - \frac{a}{2} \right) \cos \omega + \frac{a}{2} \sin \omega$$",
        reading=(u_, (rho - a / 2) * co + a / 2 * si))
d.quote("v", "X", r"$$v = \frac{a}{2} \cos \omega - \left( \frac{a}{2} - \varrho \tg \omega \right) \sin \omega$$",
        reading=(v_, a / 2 * co - (a / 2 - rho * tg) * si))
d.quote("168", "(168)",
        r"$$\int x y \, d f = \frac{h^3 (\cos \omega - \sin \omega)}{24 \sin \omega \cdot \cos^2 \omega} \cdot "
        r"\left\{ 2 a \cdot \cos \omega - \varrho (\cos \omega + \sin \omega) \right\} = 0 \quad (168)$$",
        reading=(P, h_ ** 3 * (co - si) / (24 * si * co ** 2) * (2 * a * co - rho * (co + si))),
        note="the values go into (167), not (104) as the words say (erratum 104-reference)")
Tm104, Ve104 = sp.Symbol("T_m", positive=True), symbol("V_3e_3", r"V_{3} e_{3}", positive=True)   # the members of (104), T_m - V_3 e_3 > 0, as printed
Ul, Vl = sp.symbols("u_l v_l", real=True)                 # the letters u, v into which the values are inserted
d.domain.update({Tm104: (0.1, 1), Ve104: (0.1, 1)})
U_VAL, V_VAL = (rho - a / 2) * co + a / 2 * si, a / 2 * co - (a / 2 - rho * tg) * si     # the printed u, v
d.quote("104-reference", "X", r"Setzt man diese Werte in 104 ein",
        reading=(h_ ** 3 * (co - si) / (24 * si * co ** 2) * (2 * a * co - rho * (co + si)),
                 sp.Subs(Tm104 - Ve104, (Ul, Vl), (U_VAL, V_VAL))),
        erratum=Erratum("misprint", "medium", r"\text{Setzt man diese Werte in 167 ein}",
                        (r"$u$ and $v$, just computed, are the letters of (167), $\int x y\, df = h^3 \{(v "
                         r"\operatorname{tg} w - u \operatorname{cotg} w)/6 + h (\operatorname{cotg}^2 w - "
                         r"\operatorname{tg}^2 w)/8\}$; inserted there they give (168) (derived in the step of "
                         "(168)). (104) is the stability condition $T_m - V_3 e_3 > 0$ of section VII, which "
                         "contains neither $u$ nor $v$ and is no first equilibrium condition: inserting $u$, $v$ "
                         "into it leaves $T_m - V_3 e_3$, not (168). A wrong equation number; the scan would hardly "
                         "turn 167 into 104, so the print's (medium)."),
                        corrected_reading=(h_ ** 3 * (co - si) / (24 * si * co ** 2) * (2 * a * co - rho * (co + si)),
                                           sp.Subs(h_ ** 3 * ((Vl * tg - Ul * ctg) / 6 + h_ / 8 * (ctg ** 2 - tg ** 2)),
                                                   (Ul, Vl), (U_VAL, V_VAL))),
                        objection=("(104) may be meant as printed: Scheeffer may refer back to the condition of "
                                   "section VII that the second region's formulas are built on, the values of $u$ "
                                   "and $v$ entering it through its moment $T_m$."),
                        answer=("(104) is $T_m - V_3 e_3 > 0$, an inequality without $u$ and $v$, and inserting them "
                                "leaves it unchanged; only (167), the integral written in $u$ and $v$ just before, "
                                "turns into (168). A scan does not read 167 as 104 (two digits of three), so the "
                                "slip is the print's; medium, since the author may have had an earlier numbering in "
                                "mind.")),
        note="read as: (168) is the cited equation's left member with u, v inserted; (104)'s members T_m, V_3 e_3 "
             "are quantities of their own (not of u, v)")
d.step("half-range", (P168.subs(h_, rho * si).subs({om: pi / 2 - om, rho: rho * tg}, simultaneous=True),
                      -P168.subs(h_, rho * si)), "algebra", uses=("168", "height"),
       note="the same triangle seen from G (angle 90 deg - w, leg rho tan w) gives -P: the zeros for "
            "45 deg < w < 90 deg are those of 0 < w < 45 deg")
d.quote("half-range", "X", r"$$0 < \omega \leq \frac{\pi}{4}$$",
        reading=(P168.subs(h_, rho * si).subs({om: pi / 2 - om, rho: rho * tg}, simultaneous=True),
                 -P168.subs(h_, rho * si)),
        note="'angenommen werden kann': read as the symmetry that allows it")
d.quote("168-two", "X", "Unter dieser Voraussetzung hat die Gleichung 168 nur zwei Lösungen",
        reading=(P, h_ ** 3 * (co - si) / (24 * si * co ** 2) * (2 * a * co - rho * (co + si))),
        note="(168) is a positive factor h^3/(24 sin w cos^2 w) times two factors that can vanish: the two solutions "
             "(169)")
d.step("triangle-area", (Ar, sp.Integral(1, (Y, a / 2 - (X - a / 2 + rho) * tg, a / 2), (X, a / 2 - rho, a / 2)),
                         rho ** 2 * tg / 2), "integration", result=Ar)
d.quote("area", "X", r"$$\left( \int d f = B H G \right)$$", reading=(Ar, rho * (rho * tg) / 2),
        note="the integration runs over the triangle BHG, legs rho and rho tan w")
d.quote("169a-bound", "X", r"$$\frac{2 a \cos \omega}{\cos \omega + \sin \omega} < a$$",
        reading=(a - 2 * a * co / (co + si), a / (co + si) * (si - co)),
        note="rho_* < a: sign identity, factor a/(cos w + sin w) > 0")
d.quote("169", "(169)",
        r"\cos \omega - \sin \omega = 0 \text{ also } \omega = \frac{\pi}{4} \\ \text{und } 2 a \cos \omega - "
        r"\varrho (\cos \omega + \sin \omega) = 0 \end{aligned} \right\} \quad (169)$$",
        reading=(sp.Matrix([sp.cos(pi / 4) - sp.sin(pi / 4), FAC.subs(rho, rs)]), sp.zeros(2, 1)),
        note="the two factors of (168) that can vanish (h > 0); each read at its zero")
d.quote("rho-star", "X", r"$$\varrho = \frac{2 a \cos \omega}{\cos \omega + \sin \omega}$$",
        reading=(rs, 2 * a * co / (co + si)))
d.quote("legs-in-face", "X",
        r"$BH < a$  und  $BG < a$  oder  $\varrho < a$  und  $\varrho \cdot \tg \omega < a$",
        reading=(sp.Matrix([a - rs, a - rs * tg]), sp.Matrix([a / (co + si) * (si - co), a / (co + si) * (co - si)])),
        note="the legs BH = rho and BG = rho tg w of the triangle at the corner B must be shorter than the edge; at "
             "the second solution rho_* of (169) the two margins are the conditions (169a), (169b) that follow. The "
             "sentence cites Fig. 19 (the waterplane of VII); the triangle BHG of the cube's face is Fig. 23 - the "
             "figures are lost; the reference is booked in fig19-reference")
phi19 = sp.Symbol("varphi_19", positive=True)     # the tilt of the water plane about GH against the top face
d.domain.update({phi19: (0.1, 1.4)})
d.quote("fig19-reference", "X", "Da nun (s. Fig. 19)",
        reading=(sp.Matrix([n_.dot(Q - Hp) * sp.sin(phi19) for Q in (Bp, Hp, Gp)]), sp.zeros(3, 1)),
        erratum=Erratum("misprint", "low", r"\text{Da nun (s. Fig. 23)}",
                        ("The legs BH, BG are those of the corner triangle BHG that the top face loses: 'Es stelle "
                         "Fig. 23 die obere Würfelfläche vor, von der das Dreieck BHG eintaucht'. Fig. 19 is the "
                         "waterplane of section VII ('Fig. 19 stelle den Wasserschnitt dar'): it holds the water "
                         r"line GH but not the immersed corner B, which lies $h \sin\varphi$ below it ($h = BP = \rho "
                         r"\sin w$, $\varphi$ the tilt about $GH$), so neither leg is in the figure cited. The figure "
                         "that shows them is Fig. 23 (by analogy with VII, the top face of Fig. 18). The figures are "
                         "lost and an 18 read as 19 cannot be excluded, hence low."),
                        corrected_reading=(sp.Matrix([sp.Subs(n_.dot(Q - Hp) * sp.sin(phi19), phi19, 0)
                                                      for Q in (Bp, Hp, Gp)]), sp.zeros(3, 1)),
                        objection="Fig. 19 may be right: the lost Fig. 19 (the waterplane of VII) may also draw the "
                                  "corner triangle of the top face, so that the legs BH, BG can be read off it.",
                        answer="The sentence before names Fig. 23 as the top face from which the triangle BHG dips, "
                               "and B lies below the waterplane that Fig. 19 shows; but the figures are lost and a "
                               "scan reading 23 or 18 as 19 cannot be told from the print's slip, so it stays low."),
        note="read as: the corners B, H, G of the triangle whose legs the sentence bounds lie in the plane of the "
             "figure cited (their heights above it vanish); Fig. 19 is the water plane through GH, tilted by phi "
             "against the top face, Fig. 23 the top face itself (tilt 0 about GH)")
d.quote("169a", "(169a)", r"$$\cos \omega < \sin \omega \quad (169a)$$",
        reading=(a - 2 * a * co / (co + si), a / (co + si) * (si - co)),
        note="from rho_* < a: sign identity, factor a/(cos w + sin w) > 0")
d.quote("169b", "(169b)",
        r"\text{und} \quad & \frac{2 a \cos \omega \cdot \operatorname{tg} \omega}{\cos \omega + \sin \omega} < a "
        r"\\ \text{woraus} \quad & \sin \omega < \cos \omega \end{aligned} \quad (169b)$$",
        reading=(a - 2 * a * co * tg / (co + si), a / (co + si) * (co - si)),
        note="from rho_* tan w < a: sign identity, factor a/(cos w + sin w) > 0; with (169a) unsatisfiable")
d.quote("169-unsatisfiable", "X", r"Die beiden Bedingungen 169 a, b sind aber unerfüllbar",
        reading=((a - rs) * (a - rs * tg), -a ** 2 * (co - si) ** 2 / (co + si) ** 2),
        note="sign identity (169-exclusive): the two margins a - rho_*, a - rho_* tan w never are both positive")
d.quote("170", "(170)", r"$$\omega = \frac{\pi}{4} \quad (170)$$", reading=(sp.Subs(P, om, pi / 4), 0),
        note="the first condition holds at w = 45 deg for every triangle")
d.quote("diagonal-claim", "X",
        "Es kann also für einen fünfeckigen oder dreieckigen Wasserschnitt nur Gleichgewicht stattfinden, wenn die "
        "Drehungsachse der Diagonale einer Fläche parallel ist",
        reading=(P, (co - si) * POS),
        note="sign identity (sign-of-P): P = (cos w - sin w) × (a positive factor), zero only for the axis along a "
             "face diagonal")

# ==== pentagonal waterplane: the second condition (171), (172) ========================================
xi = (X + Y - (1 - xl)) / r2                    # signed distance from GH in the top face, towards B


def over_F(f):
    """Integral over the dry part F of the top face: the unit square without the corner triangle at B."""
    return (sp.Integral(f, (X, -half, half), (Y, -half, half))
            - sp.Integral(f, (Y, 1 - xl - X, half), (X, half - xl, half)))


col = -k * xi                                   # dry column height over F at the tilt tan(phi) = k
d.step("z", (zq, r2 * over_F(-xi), 1 - xl + xl ** 3 / 6), "integration", result=zq,
       note="z = sqrt 2 F x_s: sqrt 2 times the first moment of F about GH")
d.step("T", (Tq, over_F(xi ** 2), (sp.Rational(1, 6) + (1 - xl) ** 2 - xl ** 4 / 12) / 2), "integration",
       result=Tq, note="T: moment of inertia of F about GH")
d.step("dry-volume", (V3, over_F(col), k * zq / r2), "integration", result=V3, uses=("z",),
       note="the dry part: columns over F from the top face down to the water plane z = 1/2 + k xi")
d.step("tilt", Eq(kq, r2 * (1 - s) / zq), "definition", result=kq, uses=("dry-volume",),
       note="the tilt at which the dry volume is 1 - s")
d.step("tilt-check", (over_F(col.subs(k, kq)), 1 - s), "integration", uses=("tilt", "dry-volume"))
d.step("tilt-grows", (sp.Derivative(r2 * (1 - s) / (1 - xl + xl ** 3 / 6), xl),
                      r2 * (1 - s) * (1 - xl ** 2 / 2) / (1 - xl + xl ** 3 / 6) ** 2), "algebra",
       note="positive: at fixed s the leg x grows with the tilt")
d.step("mirror", (over_F(Y * col), over_F(X * col)), "integration",
       note="the dry part is symmetric in X <-> Y: its centroid lies in the diagonal plane")
MXc = -r2 * k * (xl ** 4 - 2 * xl ** 3 + 2) / 48
Mzc = k * (k * (xl ** 4 - 12 * xl ** 2 + 24 * xl - 14) + 2 * r2 * (xl ** 3 - 6 * xl + 6)) / 48
d.step("moment-X", (MX, over_F(X * col), MXc), "integration", result=MX)
d.step("moment-z", (Mz, over_F((col - col ** 2) / 2), Mzc), "integration", result=Mz,
       note="int_{1/2 - c}^{1/2} z dz = (c - c^2)/2 over each column")
d.step("gradient", Eq(dE, (-(r2 * MXc + k * Mzc) / (s * sp.sqrt(1 + k ** 2))).subs(k, kq)), "definition", result=dE,
       uses=("moment-X", "moment-z", "tilt"),
       note="u = (-sin t/sqrt 2, -sin t/sqrt 2, cos t), tan t = k: dE/dt = (du/dt).(G - B), G - B = M/s with "
            "M = (M_X, M_X, M_z) the first moment of the dry part about G (total moment zero, volume 1), at the "
            "tilt k_171")
F171 = lambda T2, zz, xx, ss: T2 * (zz ** 2 + (1 - ss) ** 2) - zz ** 3 * (1 - xx) - zz ** 2 * (1 - ss)  # noqa: E731
KF = r2 * s * zq ** 3 * sp.sqrt(1 + kq ** 2) / (1 - s)
d.step("171-derived", (F171(2 * Tq, zq, xl, s), KF * dE), "algebra",
       uses=("gradient", "T", "z"),
       note="the left side of (171) minus its right side is dE/dt times a positive factor: (171) is B below G")
d.quote("171", "(171)",
        r"2 T \left\{ z^2 + (1 - s)^2 \right\} &= z^3 (1 - x) + z^2 (1 - s) \\ \text{wo} \quad 2 T &= \frac{1}{6} + "
        r"(1 - x)^2 - \frac{x^4}{12} \\ \text{und} \quad z &= 1 - x + \frac{x^3}{6} \end{aligned} \right\} \quad "
        r"(171)$$",
        reading=(sp.Matrix([2 * Tq, zq, F171(2 * Tq, zq, xl, s)]),
                 sp.Matrix([sp.Rational(1, 6) + (1 - xl) ** 2 - xl ** 4 / 12, 1 - xl + xl ** 3 / 6,
                            F171(sp.Rational(1, 6) + (1 - xl) ** 2 - xl ** 4 / 12, 1 - xl + xl ** 3 / 6, xl, s)]),
                 sp.Matrix([2 * Tq, zq, KF * dE])),
        note="x of the text is x_l here; the equation read as left minus right side = (positive factor) × dE/dt")

# the cut faces: which corners of the unit cube lie above a water plane (dry); a face loses a triangle when an odd
# number (1 or 3) of its four corners is dry, and the waterplane has as many vertices as edges join a dry corner
# to a wet one
CORNERS = [sp.Matrix([sx, sy, sz]) * half for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]


def _dry(height):
    """Per corner 1 if height(corner) > 0 (above the water plane), else 0, as unevaluated steps."""
    return [(1 + sp.sign(height(q))) / 2 for q in CORNERS]


def _face_counts(height):
    """Dry corners of the faces X = +-1/2, Y = +-1/2, Z = +-1/2 (in this order), unevaluated sums."""
    dry = _dry(height)
    return [sp.Add(*[dry[i] for i, q in enumerate(CORNERS) if q[ax] == sg_ * half], evaluate=False)
            for ax in range(3) for sg_ in (1, -1)]


def _waterplane_vertices(height):
    """Edges of the cube from a dry to a wet corner: the vertices of the waterplane polygon."""
    dry = _dry(height)
    pairs = [(i, j) for i in range(8) for j in range(i + 1, 8) if sum(abs(CORNERS[i][k] - CORNERS[j][k])
                                                                          for k in range(3)) == 1]
    return sp.Add(*[(dry[i] - dry[j]) ** 2 for i, j in pairs], evaluate=False)


def _top_dry(xx):
    """Dry corners of the top face when the water line GH cuts off the corner triangle with legs xx at B (xi < 0)."""
    return sp.Add(*[(1 - sp.sign(xi.subs({X: q[0], Y: q[1], xl: xx}))) / 2 for q in CORNERS if q[2] > 0],
                  evaluate=False)


def _three(count):
    """1 if count is 3, 0 for 1, 2, 4."""
    return (count - 1) * (count - 2) * (4 - count) / 2


X_IN = (-sp.Rational(1, 10), sp.Rational(1, 10), sp.Rational(9, 10), sp.Rational(11, 10))
d.quote("x-range", "X (171)", r"und  $x$  zwischen 0 und 1 liegen muss.",
        reading=as_printed(lambda: (sp.Matrix([_three(_top_dry(xx)) for xx in X_IN]), sp.Matrix([0, 1, 1, 0]))),
        note="read as: the top face has exactly three dry corners (the water line cuts off the corner triangle at B "
             "alone, the pentagon of (171)) for 0 < x < 1 and not beyond: at x = -1/10, 1/10, 9/10, 11/10 it has 4, "
             "3, 3, 1 dry corners (a corner is dry where xi < 0, xi its signed distance from GH towards B)")

f_at = lambda xx, ss: F171(sp.Rational(1, 6) + (1 - xx) ** 2 - xx ** 4 / 12, 1 - xx + xx ** 3 / 6, xx, ss)  # noqa
d.step("end-0", (F0, f_at(sp.Integer(0), s), *as_printed(lambda: ((7 * (1 - s) ** 2 - 6 * (1 - s) + 1) / 6,
                                                          7 * (s - (4 + r2) / 7) * (s - (4 - r2) / 7) / 6))),
       "algebra", result=F0,
       uses=("T", "z"))
d.step("end-1", (F1v, f_at(sp.Integer(1), s), (6 * (1 - s) - 1) ** 2 / 432), "algebra", result=F1v,
       uses=("T", "z"))
d.step("172-root", Eq(s172, (4 + r2) / 7), "definition", result=s172, uses=("end-0",),
       note="f(0, s) = 0 on s > 1/2: a root of (171) enters 0 < x through x = 0 (the corner B just touching)")
d.step("172-check", (f_at(sp.Integer(0), s172), 0), "algebra", uses=("172-root",))
COUNT_171 = lambda lo, hi: RealRoots(F171(2 * Tq, zq, xl, s), xl, lo, hi)  # noqa: E731  (T, z of (171) inserted)
d.quote("172", "(172)",
        r"Die Gleichung 171 hat (zwischen  $x = 0$  und  $x = 1$ ) eine reelle Wurzel, wenn" "\n\n" r"$$s < "
        r"\frac{4 + \sqrt{2}}{7} \quad \text{oder} < 0,7735. \quad (172)$$",
        reading=Holds(sp.Implies(s < s172, COUNT_171(0, 1) >= 1), {s: (half, 1)}),
        note="read on 1/2 < s < 1 as the existence statement it is ('eine reelle Wurzel', a real root; Sturm counts, "
             "T and z inserted): where s < (4 + sqrt 2)/7, (171) has a root in 0 < x < 1. The bound is where the "
             "sign change f(0) < 0 <= f(1) ends (steps end-0, end-1): a root enters through x = 0 there. The "
             "sentence counts no roots: one up to the fold of (171) (0.7623 < s < 0.7624), three from there to "
             "(4 + sqrt 2)/7, two up to 5/6. That the root is a pentagonal equilibrium only above the fold is "
             "the fault of the conclusion drawn from it ('so hat er sicher eine im zweiten Gebiet')")
d.quote("172-number", "(172)", r"\frac{4 + \sqrt{2}}{7} \quad \text{oder} < 0,7735",
        reading=(s172, sp.Rational("0.7735")), tolerance=PRINTED_DIGITS)
d.step("first-domain-82", Eq(Sw45, (1 - s) ** 2 / (6 * s * (1 - s) - 1)), "lemma",
       uses=("scheeffer-vi-cf:cube-limit-omega",), result=Sw45,
       note="(82) of VI.D for s > 1/2: the oblique position stays in the first domain iff sin^2(45 deg + w) <= S")
d.quote("first-domain-82", "X",
        r"$$1 \leq \frac{(1 - s)^2}{6s(1 - s) - 1}$$",
        reading=(Sw45 - 1, (7 * s ** 2 - 8 * s + 2) / (6 * s * (1 - s) - 1)),
        note="w = 45 deg, sin^2 90 deg = 1; sign identity: S - 1 has the sign of 7s^2 - 8s + 2 where the "
             "upright cube is unstable (6 s(1-s) > 1)")
d.quote("first-domain-bound", "X", r"woraus  $s > \frac{4 + \sqrt{2}}{7}$  oder  $> 0,7735$  folgt",
        reading=(7 * s ** 2 - 8 * s + 2, 7 * (s - s172) * (s - (4 - r2) / 7)),
        note="for s > 1/2 the second factor is positive: S >= 1 iff s >= s_172 (the text's '>' drops the boundary)")

# the roots of (171) at chosen densities: exact algebraic numbers
def roots_171(sv):
    """The real roots 0 < x < 1 of (171) at the rational density sv, as CRootOf."""
    poly = sp.Poly(sp.expand(432 * f_at(x, sp.nsimplify(sv))), x)
    return [r for r in poly.real_roots() if 0 < r < 1]


def beta(xx, ss):
    """(2 - x)(1 - s)/z: below 1 while the bottom corner D = (-1/2, -1/2, -1/2) stays under water."""
    return (2 - xx) * (1 - ss) / (1 - xx + xx ** 3 / 6)


S_COUNTER = sp.Rational(3, 5)
X_COUNTER = roots_171(S_COUNTER)[0]
d.step("bottom-corner", ((half - kq * (2 - xl) / r2) - (-half), 1 - beta(xl, s)), "algebra", uses=("tilt",),
       note="height of the water plane above D: positive (D wet, pentagon) iff beta < 1, else D is dry and the "
            "waterplane a hexagon")
d.step("pentagon-vertices", Eq(NVp, sp.Rational(11, 2) + sp.sign(beta(X_COUNTER, S_COUNTER) - 1) / 2),
       "definition", result=NVp, uses=("bottom-corner",),
       note="vertices of the waterplane at the only root of (171) in (0, 1) at s = 3/5 (x = 0.5498): 5 if beta < 1, "
            "6 if beta > 1; beta = 1.214 there")

# the position of (171) at s = 3/5, x = 0.5498 (beta > 1, the hexagon): the water plane z = 1/2 + k_171 xi
_hex_height = lambda q: q[2] - half - (r2 * (1 - S_COUNTER) / (1 - X_COUNTER + X_COUNTER ** 3 / 6)) * (  # noqa: E731
    xi.subs({X: q[0], Y: q[1], xl: X_COUNTER}))
d.quote("hex-two-faces", "X", "In diesem Falle wird von je zwei parallelen Flächen ein Dreieck abgeschnitten.",
        reading=(sp.Matrix([_waterplane_vertices(_hex_height)] + _face_counts(_hex_height)),
                 sp.Matrix([6, 1, 3, 1, 3, 3, 1])),
        note="read at the position of (171) at s = 3/5, x = 0.5498 (tilt k_171, beta = 1.214): the waterplane has six "
             "vertices and every face an odd number of dry corners (X+, X-, Y+, Y-, top, bottom: 1, 3, 1, 3, 3, 1): "
             "the top loses the immersed triangle at B, the bottom the dry triangle at D (Fig. 21: GBH, DLM), and so "
             "does each pair of side faces")
# the four waterplanes of the second and third domains at exact planes n.p = d (dry where n.p > d)
SHAPES = (("pentagon", (1, 1, 4), sp.Rational(6, 5)), ("triangle", (1, 1, 1), 1), ("hexagon", (1, 1, 1), 0),
          ("trapezoid", (sp.Rational(1, 10), 1, 1), half))
_plane = lambda nn, dd: (lambda q: sum(nn[k] * q[k] for k in range(3)) - dd)  # noqa: E731


def _pair_triangles(nn, dd):
    """The most faces with a triangle cut off in one pair of parallel faces (0, 1 or 2)."""
    cnt = _face_counts(_plane(nn, dd))
    odd = [(1 - (-1) ** c_) / 2 for c_ in cnt]
    return sp.Max(*[odd[2 * k] + odd[2 * k + 1] for k in range(3)], evaluate=False)


d.quote("one-or-both-faces", "X",
        "In allen Fällen wird von einer oder von beiden Grundflächen je ein Dreieck abgeschnitten und es soll nun "
        "zunächst die erste Gleichgewichtsbedingung dafür untersucht werden.",
        reading=(sp.Matrix([_waterplane_vertices(_plane(nn, dd)) for _, nn, dd in SHAPES]
                           + [_pair_triangles(nn, dd) for _, nn, dd in SHAPES]),
                 sp.Matrix([5, 3, 6, 4, 1, 1, 2, 2])),
        note="read at four exact planes, one per waterplane the text names (pentagon: three top corners dry; "
             "triangle: one; hexagon: a corner and its three neighbours; trapezoid: one top edge): the number of "
             "waterplane vertices, and the most faces of one parallel pair from which a triangle is cut off. The "
             "cube's faces are alike, so the 'Grundflächen' are that pair: for the trapezoid (a dry edge) the two "
             "faces at the ends of the edge, not the top and bottom of the turn, whose cuts are trapezoids")
PENT_EVIDENCE = (
    (r"(171) describes an equilibrium only while the bottom face stays uncut, $\beta = (2 - x)(1 - s)/z < 1$. For "
     r"$\tfrac12 < s < 0.7623$ the root of (171) has $\beta > 1$: at $s = \tfrac35$ it is $x = 0.5498$, $\beta = "
     "1.214$, the bottom corner is dry and the waterplane a hexagon, so (171) does not apply; the clipped cube has "
     "no pentagonal equilibrium there (a search over all orientations finds as its only stable position the "
     r"symmetric hexagon, the corner up). Pentagonal equilibria exist only for $0.7623 < s < \tfrac56$ ($0.7623$: the "
     r"fold of (171), $f = df/dx = 0$ at $x = 0.358$); the one that starts at $x = 0$ at $s = (4 + \sqrt2)/7$ and "
     r"exists for $0.7623 < s < 0.7735$ is stable, the other ($0.7623 < s < \tfrac56$) unstable. Scheeffer omitted "
     "the discussion of (171) for want of space; the check of the bottom face is what is missing."))
d.quote("pentagon-exists", "X",
        "Hat also ein in aufrechter Lage labil schwimmender Würfel im ersten Drehungsgebiet keine neue "
        "Gleichgewichtslage, so hat er sicher eine im zweiten Gebiet (Fünfeckiger Wasserschnitt), wenn die obere "
        "Fläche mit einer Ecke eintaucht.",
        reading=(NVp, 5),
        erratum=Erratum("claim", "high",
                        r"a pentagonal equilibrium exists only for $0.7623 < s < 5/6$ (and $1/6 < s < 0.2377$); for "
                        r"$1/2 < s \le 0.7623$ the root of (171) lies beyond the second domain (hexagonal waterplane)",
                        PENT_EVIDENCE, corrected_reading=(NVp, 6),
                        objection="The hypothesis 'keine neue Gleichgewichtslage im ersten Drehungsgebiet' may "
                                  "exclude exactly the densities where the root of (171) leaves the second domain, "
                                  "so that the claim is right within its hypothesis.",
                        answer=(r"For $\tfrac14 < s < \tfrac34$ the first domain holds no oblique equilibrium "
                                r"(Scheeffer VI.D), so $s = \tfrac35$ meets the hypothesis; there the root $x = "
                                r"0.5498$ of (171) has $\beta = 1.214 > 1$, the waterplane is a hexagon, and the "
                                "clipped cube has no pentagonal equilibrium. The word 'sicher' admits no exception.")),
        note="read at s = 3/5 (upright unstable, no oblique position in the first domain): the print says the "
             "root of (171) is a pentagonal equilibrium")

S_STAB = sp.Rational(77, 100)
XS = roots_171(S_STAB)           # three roots: 0.0858, 0.5684 (pentagons) and 0.8768 (beta > 1)
fx = sp.diff(f_at(x, S_STAB), x)
SIG = sp.Symbol("sigma")
d.step("stiffness-sign", (SIG, sp.Matrix([sp.sign(fx.subs(x, XS[0]), evaluate=False), sp.sign(fx.subs(x, XS[1]), evaluate=False)])),
       "definition", uses=("171-derived", "tilt-grows"), result=SIG,
       note="at a root of (171) d^2 E/dt^2 has the sign of df/dx (f = dE/dt times a positive factor, x grows with t); "
            "the first two roots at s = 0.77 (both with beta < 1)")
d.quote("pentagon-stable", "X", "Es lässt sich auch zeigen, dass dieses Gleichgewicht stabil ist",
        reading=(SIG, sp.Matrix([1, 1])),
        erratum=Erratum("claim", "medium",
                        r"of the two pentagonal equilibria for $0.7623 < s < 0.7735$ only the one with the smaller leg "
                        r"($x \to 0$ as $s \to 0.7735$) is stable; the other is unstable",
                        (r"At $s = 0.77$ (171) has the pentagonal roots $x = 0.0858$ and $x = 0.5684$ ($\beta = "
                         "0.48$, $0.71$). $d^2E/dt^2$ along the diagonal plane has the sign of $df/dx$: $+$ at "
                         r"$0.0858$, $-$ at $0.5684$; the clipped cube confirms both equilibria ($\tan t = 0.3557$, "
                         "$0.7038$), the second with a negative second derivative of the potential. The text proves "
                         "nothing here ('worauf ich jedoch hier ebenfalls nicht näher eingehen kann'); medium, since "
                         "'dieses' may mean the small-leg branch alone."),
                        corrected_reading=(SIG, sp.Matrix([1, -1])),
                        objection=("'dieses Gleichgewicht' may mean only the branch that enters at $x = 0$ as $s$ "
                                   r"passes $(4 + \sqrt2)/7$, the one (172) points to, which is stable."),
                        answer="The sentence before speaks of the pentagonal equilibrium of the whole range s < "
                               "0.7735, and on 0.7623 < s < 0.7735 it is two equilibria of which the larger-leg one "
                               "is unstable (df/dx < 0 at x = 0.5684, s = 0.77). The narrow reading of 'dieses' is "
                               "left open, hence medium."),
        note="read at s = 0.77 for the two pentagonal roots of (171): stiffness signs along the diagonal plane")
d.quote("dual-threshold", "X", r"wenn  $s > \frac{3 - \sqrt{2}}{7}$  d. i.  $> 0,2265$  ist.",
        reading=(1 - s172, (3 - r2) / 7), note="the duality s <-> 1 - s")
d.quote("dual-number", "X", r"$> 0,2265$", reading=(1 - s172, sp.Rational("0.2265")), tolerance=PRINTED_DIGITS)
d.step("dual-vertices", Eq(NVd, NVp), "definition", result=NVd, uses=("pentagon-vertices",),
       note="the cube turned over at density 1 - s: wet and dry exchanged, the same waterplane")
d.quote("dual-exists", "X",
        r"Für  $s < \frac{1}{2}$  tritt dieses stabile Gleichgewicht im zweiten Drehungsgebiet ein,",
        reading=(NVd, 5),
        erratum=Erratum("consequential", "high", "only for $0.2265 < s < 0.2377$ (stable) and $1/6 < s < 0.2377$",
                        "The mirror image of pentagon-exists (s <-> 1 - s): at s = 2/5 the root of (171) at "
                        "1 - s = 3/5 "
                        "gives a hexagonal waterplane.",
                        corrected_reading=(NVd, 6),
                        objection="For the cube the exchange s <-> 1 - s (turning the cube upside down) is an exact "
                                  "symmetry, so the statement for s < 1/2 follows from that for s > 1/2 and cannot "
                                  "be wrong on its own.",
                        answer="The symmetry holds and carries the fault over with it: s = 2/5 mirrors s = 3/5, "
                               "where the root of (171) lies beyond the second domain (hexagonal waterplane). The "
                               "erratum is booked as consequential of pentagon-exists for that reason."),
        note="read at s = 2/5")

# ==== triangle ===========================================================================================
d.step("tetra-volume", (Vt, sp.Integral(1, (Z, 0, a - X - Y), (Y, 0, a - X), (X, 0, a)), a ** 3 / 6), "integration",
       result=Vt, note="the corner tetrahedron cut off by the three face diagonals at a corner")
d.step("triangle-bound", Eq(s56, 1 - Vt / a ** 3), "definition", result=s56,
       note="density at which the dry part is that tetrahedron")
d.quote("tetra", "X", r"$$\frac{a^3}{6} = a^3 (1 - s)$$", reading=(Vt, a ** 3 * (1 - s56)))
d.quote("diagonal-plane-bound", "X",
        r"Die untere Grenze für  $s$  tritt ein, wenn der Wasserschnitt aus drei Flächendiagonalen gebildet wird.",
        reading=(s56, 1 - sp.Integral(1, (Z, 0, a - X - Y), (Y, 0, a - X), (X, 0, a)) / a ** 3),
        note="the dry part is then the corner tetrahedron cut off by the three face diagonals")
d.quote("five-sixths", "X", r"$$s = \frac{5}{6}$$", reading=(s56, sp.Rational(5, 6)))
ut = sp.Matrix([1, 1, 1]) / sp.sqrt(3)
d.step("tri-symmetric", (as_printed(lambda: sp.Matrix([-L, L, 0]).cross(sp.Matrix([-L, 0, L]))), L ** 2 * sp.sqrt(3) * ut),
       "geometry",
       note="legs of equal length L on the three edges at the dry corner (170 on every face): the water plane is "
            "normal to the diagonal (1, 1, 1)")
d.quote("tri-symmetric", "X",
        "so muss der dreieckige Wasserschnitt eine symmetrische Lage (senkrecht zu einer Würfeldiagonale) haben",
        reading=as_printed(lambda: (sp.Matrix([-L, L, 0]).cross(sp.Matrix([-L, 0, L])).cross(ut), sp.zeros(3, 1))))
cT = r2 * L
d.step("tri-inertia", (It, sp.Integral((Y - sp.sqrt(3) * cT / 6) ** 2, (X, Y / sp.sqrt(3), cT - Y / sp.sqrt(3)),
                                       (Y, 0, sp.sqrt(3) * cT / 2)), sp.sqrt(3) * L ** 4 / 24), "integration",
       result=It, note="equilateral triangle of side sqrt 2 L about a central axis (isotropic)")
d.step("tri-dry-centroid", (uD, as_printed(lambda: ut.dot(sp.Matrix([half, half, half]) - L / 4 * sp.Matrix([1, 1, 1]))),
                            sp.sqrt(3) * (half - L / 4)), "geometry", result=uD,
       note="centroid of the dry tetrahedron, legs L at the corner (1/2, 1/2, 1/2), along the up vector")
sT = 1 - L ** 3 / 6
d.step("tri-GM", (GMt, It / sT - (1 - sT) / sT * uD, sp.sqrt(3) * L ** 3 * (L - 1) / (12 * sT)), "algebra",
       uses=("tri-inertia", "tri-dry-centroid"), result=GMt,
       note="Duhamel: GM = I/V - BG, V = s = 1 - L^3/6, G - B = (1 - s) D/s; negative for every L < 1 (s > 5/6)")
d.quote("tri-unstable", "X", "Die Bedingungen ergeben, dass dieses Gleichgewicht stets labil ist.",
        reading=(sp.sign(GMt), -1))
d.quote("hex-follows", "X",
        r"Wenn  $s < \frac{5}{6}$  (bzw.  $> \frac{1}{6}$ ) ist, so geht der fünfeckige Wasserschnitt bei weiterem",
        reading=as_printed(lambda: (sp.sign((1 - s) - (1 - s56)), sp.sign(s56 - s))),
        note="turning on towards the diagonal, the dry part reaches the bottom face before the top face loses the "
             "two corners next to B iff its volume 1 - s exceeds the tetrahedron's 1/6")

# ==== two parallel faces: (173)-(175) ====================================================================
XI = si * X + co * Y - (si * (a / 2 - rho) + co * a / 2)     # distance from GH towards B (top face)
ETA = co * X - si * Y                                         # along GH, from the plane through O
xM = {X: -a / 2 + rho1, Y: -a / 2}                            # M: the bottom water line on the side y = -a/2
d.step("third-tilt", Eq(k3, -a / XI.subs(xM)), "definition", result=k3,
       note="the water plane z = a/2 + k xi passes through the bottom water line ML (the triangle LDM, legs "
            "rho_1, rho_1 tan w at D, projected on the top face) at depth a")
sq_ = sp.Integral(ETA * XI, (X, -a / 2, a / 2), (Y, -a / 2, a / 2))
triB = sp.Integral(ETA * XI, (Y, a / 2 - (X - a / 2 + rho) * tg, a / 2), (X, a / 2 - rho, a / 2))
triD = sp.Integral(ETA * (XI - XI.subs(xM)), (Y, -a / 2, -a / 2 + (-a / 2 + rho1 - X) * tg), (X, -a / 2, -a / 2 + rho1))
d.step("h1", (h1_, as_printed(lambda: (-sp.Matrix([-a / 2 + rho1, -a / 2]) + sp.Matrix([-a / 2, -a / 2])).dot(-n_)), rho1 * si),
       "geometry",
       result=h1_, note="h_1: the distance of D = (-a/2, -a/2) from the projected bottom water line through M")
d.step("bottom-triangle", Eq(P1, P168.subs({h_: h1_, rho: rho1})), "definition", uses=("168", "h1"), result=P1,
       note="(168) for LDM: turned by 180 deg it is a triangle like BHG with rho_1, h_1 (checked by third-bottom)")
d.step("third-square", (Sq, sq_, 0), "integration", result=Sq,
       note="the square's product moment about N, axes along and across GH")
d.step("third-top", (Tb, triB, P168.subs(h_, rho * si)), "integration", uses=("168",), result=Tb,
       note="the triangle BHG in body coordinates: (168) again")
d.step("third-bottom", (Td, triD, P168.subs({h_: rho1 * si, rho: rho1})), "integration", result=Td,
       note="int eta (xi - xi_M) over LDM, xi - xi_M = xi + a/k the distance from ML: (168) for rho_1")
d.step("third-moment", (Me, -k3 * Sq + k3 * Tb + k3 * Td, k3 * (P + P1)), "algebra",
       uses=("third-tilt", "third-square", "third-top", "third-bottom", "bottom-triangle"), result=Me,
       note="moment of the dry part about the vertical plane through G across the axis: columns over the dry part "
            "of the top face of height -k xi, cut to the full height a (k xi + a = k (xi - xi_M)) over LDM")
d.step("second-moment", (M2, k * (-Sq + Tb), k * P), "algebra", uses=("third-square", "third-top", "168"), result=M2,
       note="second domain (one face cut): the moment of the dry part about the vertical plane through G across the "
            "axis, columns of height -k xi over the dry part of the top face")
d.quote("98", "X (98)", r"$$\int x y \, d f = 0$$", reading=(M2 / k, P),
        note="the first condition (98): B below G needs this moment to vanish, i.e. P = 0")
COND = ("the first condition of equilibrium imposed on the moment of the dry part over the tilt, P + P_1 (the two "
        "integrals run over the triangles G B H and L D M the prose names)")
d.quote("118-form", "X", r"$$\int x y \, d f - \int x y \, d f = 0$$", reading=(Me / k3, P + P1),
        note="with the x axes of the two triangles opposite the second integral is -P_1; (173) turns its y axis too",
        condition=COND)
d.quote("173", "(173)", r"$$\int x y \cdot d f + \int x y \, d f = 0 \quad (173)$$",
        reading=(Me / k3, P + P1), note="the first condition: the moment of the dry part, over the tilt",
        condition=COND, symbols={r"\int x y \cdot d f": (P, "the first sum, over G B H: P by (174)"),
                                 r"\int x y \, d f": (P1, "the second, over L D M, both axes turned: P_1 (175)")})
d.quote("174", "(174)",
        r"$$\int x y \, d f = \frac{h^3 (\cos \omega - \sin \omega)}{24 \sin \omega \cdot \cos^2 \omega} \cdot "
        r"\left\{ 2 a \cos \omega - \varrho (\cos \omega + \sin \omega) \right\} \quad (174)$$",
        reading=(P, P168))
d.quote("175", "(175)",
        r"$$\int x y \cdot d f = \frac{h_1^3 \cdot (\cos \omega - \sin \omega)}{24 \cdot \sin \omega \cdot \cos^2 "
        r"\omega} \cdot \left\{ 2 a \cos \omega - \varrho_1 (\cos \omega + \sin \omega) \right\} \quad (175)$$",
        reading=(P1, h1_ ** 3 * (co - si) / (24 * si * co ** 2) * (2 * a * co - rho1 * (co + si))))
d.quote("factor-positive", "X", "man sieht leicht ein, dass er stets positiv ist",
        reading=(FAC, co * ((a - rho) + (a - rho * tg))),
        note="a sum of positive terms when rho < a and rho tan w < a")
d.quote("174-positive", "X",
        r"Die Summe  $\int x y \cdot d f$  ist also positiv und nur für  $\omega = 45^\circ$  gleich Null.",
        reading=(P, (co - si) * POS),
        note="sign identity (sign-of-P): P = (cos w - sin w) × (a positive factor) for 0 < w <= 45 deg")
d.quote("175-positive", "X",
        r"und dieser Ausdruck ist ebenfalls (wie 174) für alle Werte von  $\omega$  zwischen  $0$  und  $45^\circ$  "
        r"positiv und nur für  $\omega = 45^\circ$  gleich Null.",
        reading=(P1, (co - si) * h1_ ** 3 * ((a - rho1) + (a - rho1 * tg)) / (24 * si * co)),
        note="sign identity: (175) is (168) for LDM, the factor positive for rho_1 < a, rho_1 tan w < a")
d.quote("173-only-45", "X", r"Daher ist  $\omega = 45^\circ$  die einzige Lösung der Gleichung 173.",
        reading=(P + P1, (co - si) * (POS + POS.subs({h_: h1_, rho: rho1}))),
        note="sign identity: both terms are cos w - sin w times a positive factor (sign-of-P)")
d.quote("hex-symmetric", "X",
        "In der Gleichgewichtslage hat der sechseckige, wie der dreieckige Wasserschnitt stets eine symmetrische Lage",
        reading=(sp.Matrix([P + P1, P]), (co - si) * sp.Matrix([POS + POS.subs({h_: h1_, rho: rho1}), POS])),
        note="w = 45 deg on every pair of faces makes |u_x| = |u_y| = |u_z|; the search for all equilibria of the "
             "clipped cube in the tests finds no other hexagonal or triangular one")

# ==== the regular hexagon at s = 1/2 =====================================================================
cH = 1 / r2
d.quote("hex-six", "X", "Da dies aber für alle sechs Dreiecke der Fall sein muss, so ergibt sich:",
        reading=(sp.Matrix([P + P1, P]), (co - si) * sp.Matrix([POS + POS.subs({h_: h1_, rho: rho1}), POS])),
        note="as hex-symmetric: on every pair of parallel faces the first condition is a positive factor times "
             "(cos w - sin w), so w = 45 deg on each")
d.quote("hex-range", "X",
        r"ebenso über den sechseckigen (wenn  $s$  zwischen  $\frac{1}{6}$  und  $\frac{5}{6}$  liegt)",
        reading=(sp.Matrix([Vt / a ** 3, s56]), sp.Matrix([sp.Rational(1, 6), sp.Rational(5, 6)])),
        note="the bounds are the corner tetrahedron's share of the cube, 1/6 (dry or wet): beyond them the water "
             "plane cuts three faces only (triangle)")
d.step("hex-inertia", (Ih, 2 * sp.Integral(Y ** 2 * 2 * (cH - Y / sp.sqrt(3)), (Y, 0, sp.sqrt(3) * cH / 2)),
                       5 * sp.sqrt(3) / 64), "integration", result=Ih,
       note="the regular hexagon of side 1/sqrt 2 (midpoints of six edges) about a central axis")
IH3 = sp.Piecewise(((w + sp.Rational(3, 2)) ** 2 / 2, w < -half), (sp.Rational(3, 4) - w ** 2, True))
d.step("hex-buoyancy", (Bh, -2 * sp.Integral(w * IH3, (w, -sp.Rational(3, 2), 0)) / sp.sqrt(3), 13 * sp.sqrt(3) / 96),
       "integration", result=Bh,
       note="depth of B below G along the diagonal: w = X + Y + Z has the density (w + 3/2)^2/2, 3/4 - w^2 on "
            "the cube (Irwin-Hall, centred); BG = -E[w; w < 0]/(V sqrt 3), V = 1/2")
d.step("hex-GM", (GMh, 2 * Ih - Bh, sp.sqrt(3) / 48), "algebra", uses=("hex-inertia", "hex-buoyancy"), result=GMh)
d.quote("hex-half", "X",
        r"Für  $s = \frac{1}{2}$  ist das Sechseck ein regelmässiges und Schülen\*) hat bereits gezeigt, dass das "
        r"Gleichgewicht in diesem Falle stabil ist.",
        reading=(sp.sign(GMh), 1))

# the heading of X, read on the diagonal family of (171): the tilt fixed by the volume 1 - s (the cube displaces its
# weight at every leg x), the bottom face uncut (4/5 < s < 5/6, x < 4/5)
HEADING_FAMILY = {s: (sp.Rational(4, 5), sp.Rational(5, 6)), xl: (0, sp.Rational(4, 5))}
d.quote("heading", "X", "Die Gewichtslagen eines schwimmenden Würfels.",
        reading=Holds(sp.Eq(dE, 0), HEADING_FAMILY),
        erratum=Erratum(
            "misprint", "medium", r"\text{Die Gleichgewichtslagen eines schwimmenden Würfels.}",
            "The section determines the positions in which the floating cube is in equilibrium: the first condition "
            "of equilibrium (98), int x y df = 0, gives (170), the second gives (171), and its sentences speak of "
            "'keine neue Gleichgewichtslage'; the parallel heading of IX reads 'Die Gleichgewichtslagen eines "
            "rechtwinkligen Parallelepipeds'. The text writes 'Gleichgewichtslage' 56 times and 'Gewichtslage' "
            "nowhere but here and in the contents line of X. Read as it stands, a position of the weight is one in "
            "which the cube displaces its weight, as it does at every leg x of the diagonal family (the tilt fixed "
            "by the volume 1 - s), where the potential is not stationary; the equilibrium positions are its roots "
            "of (171). The same word in the heading and in the contents, which the compositor set from the "
            "heading, is no fault a scan repeats: the print's (or the author's) dropped syllable.",
            corrected_reading=Iff(sp.Eq(dE, 0), sp.Eq(F171(2 * Tq, zq, xl, s), 0), HEADING_FAMILY),
            fault="Gewichtslagen", places=("Inhalt",),
            objection="'Gewichtslage' may be the author's own short word for an equilibrium position, used in a "
                      "heading where the meaning is plain.",
            answer="The author writes 'Gleichgewichtslage' in the sentences of this section and in the heading of "
                   "IX, and 'Gewichtslage' nowhere else; a short word found only in one heading and in the contents "
                   "line copied from it is a dropped syllable. That the author may have written it so keeps it "
                   "medium."),
        note="read as the positions the heading names, on the diagonal family of (171) where the cube displaces its "
             "weight at every leg x: as printed, positions of the weight, at which the potential would be "
             "stationary throughout (dE/dt = 0 at every x); corrected, the equilibrium positions, at which it is "
             "stationary: the roots of (171)")
