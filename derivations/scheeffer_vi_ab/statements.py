"""What Scheeffer's VI (opening), VI.A and VI.B say and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import PRINTED_DIGITS, Derivation, Eq, Erratum
from symfloat.model.claim import as_printed
from symfloat.model.relation import Holds
from symfloat.model.vocabulary import StableIff


def printed_fraction(p, q):
    """The printed fraction p/q (a decimal d,dd as dd../100), kept as a quotient: the engine
    divides when it compares, so a printed number is checked, not identical on building."""
    return sp.Mul(p, sp.Pow(q, -1, evaluate=False), evaluate=False)


x, y, X, Y, th = sp.symbols("x y X Y theta", real=True)
a, b, s, r = sp.symbols("a b s r", positive=True)
om = sp.Symbol("omega", real=True)
tp = sp.Symbol("tau", positive=True)            # tan(phi) of a tilted position
bs_ = sp.Symbol("b_s", positive=True)           # the scan's "b_s" for the draught b s (Example 10)
Tx, Ty, Pxy = sp.symbols("T_x T_y P_xy", real=True)
u = sp.Symbol("u", real=True)
T = sp.Symbol("T")
pi = sp.pi
deg = pi / 180
sq3 = sp.sqrt(3)

DERIVATION = d = Derivation(
    id="scheeffer-vi-ab",
    source="scheeffer",
    title="The regular prism: isotropy of regular polygons, the triangular prism and the circular cylinder",
    locator="VI, VI.A, VI.B",
    summary="Inertia of a regular polygon about every central axis (56); upright stability, tilted "
            "equilibrium and the limits of the first rotation region of the regular triangular prism (57)-(68) and of "
            "the circular cylinder (69)-(73), with the worked examples 1-10 recomputed.",
    requires=(),
    domain={x: (-1, 1), y: (-1, 1), om: (0, 1), Tx: (1, 2), Ty: (1, 2), Pxy: (-1, 1),
            a: (sp.Rational(1, 2), 2), b: (1, 2), s: (sp.Rational(1, 20), sp.Rational(19, 20)),
            r: (sp.Rational(1, 2), 2), tp: (sp.Rational(1, 10), 2), bs_: (sp.Rational(1, 10), 4)},
    constraints=(),
    assumptions=("the body is a homogeneous right prism (or cylinder) of height b and density s (0 < s < 1) "
                 "in water of density 1; the bases are perpendicular to the axis",
                 "omega in radians, 0 <= omega <= pi/3 for the triangle (30 degrees written pi/6)",
                 "first rotation region: the tilted water plane cuts no base",
                 "inequalities are read through their margins (right side minus left side, or a product "
                 "with a positive factor) and compared with the derived margin, e.g. the metacentric "
                 "height; boundary values are compared where the margin is not linear"),
)


def full(expr):
    """*expr* with every quantity established so far replaced by its derived value."""
    res = d.results()
    for _ in range(12):
        new = sp.sympify(expr).xreplace(res)
        if new == expr:
            return new
        expr = new
    return expr


# =====================================================================================================
# VI opening: inertia of a polygon about an axis at angle omega, regular polygons
# =====================================================================================================
d.step("ordinate", Eq(u, y * sp.sin(om) + x * sp.cos(om)), "definition",
       note="(44): u is the distance of the point (x, y) from the axis FE through O that makes the angle "
            "omega with the symmetry axis OB (the Y axis); x, y from the centre O", result=u)
d.step("ordinate-squared", (u ** 2, y ** 2 * sp.sin(om) ** 2 + x ** 2 * sp.cos(om) ** 2 + x * y * sp.sin(2 * om)),
       "algebra", uses=("ordinate",))
Tg = sp.Symbol("T_{gen}")
d.step("moment-any-axis", Eq(Tg, sp.sin(om) ** 2 * Tx + sp.cos(om) ** 2 * Ty + sp.sin(2 * om) * Pxy),
       "definition", uses=("ordinate-squared",),
       note="T = int u^2 df integrated term by term with ordinate-squared; T_x = int y^2 df, T_y = int x^2 df, "
            "P_xy = int x y df (the names of section V)", result=Tg)
d.step("moment-symmetric", Eq(T, sp.sin(om) ** 2 * Tx + sp.cos(om) ** 2 * Ty), "definition",
       uses=("moment-any-axis",),
       note="the Y axis is a symmetry axis, so P_xy = int x y df = 0: the mirror images (x, y), (-x, y) "
            "contribute opposite x y (checked by integration for the triangle: triangle-product-moment)",
       result=T)

d.quote("ordinate", "VI",
        r"\begin{aligned} u &= y \sin \omega + x \cos \omega \\ u^2 &= y^2 \sin^2 \omega + x^2 \cos^2 \omega "
        r"+ x y \sin 2 \omega \end{aligned}",
        reading=(sp.Matrix([u, u ** 2]),
                 sp.Matrix([y * sp.sin(om) + x * sp.cos(om),
                            y ** 2 * sp.sin(om) ** 2 + x ** 2 * sp.cos(om) ** 2 + x * y * sp.sin(2 * om)])))
d.quote("moment-any-axis", "VI",
        r"$$T = \int u^2 df = \sin^2 \omega \int y^2 df + \cos^2 \omega \int x^2 df + \sin 2 \omega \cdot "
        r"\int x y df$$",
        reading=Eq(Tg, sp.sin(om) ** 2 * Tx + sp.cos(om) ** 2 * Ty + sp.sin(2 * om) * Pxy),
        note="before the symmetry is used: P_xy = int x y df is any value")
d.quote("56", "(56)", r"$$T = T_x \cdot \sin^2 \omega + T_y \cos^2 \omega \quad (56)$$",
        reading=Eq(T, Tx * sp.sin(om) ** 2 + Ty * sp.cos(om) ** 2))
d.quote("other-symmetry-axis", "VI",
        r"\begin{aligned} T_y &= T_x \sin^2 \omega + T_y \cos^2 \omega \\ T_y \sin^2 \omega &= T_x \sin^2 "
        r"\omega \\ T_y &= T_x \end{aligned}",
        reading=(Ty - (Tx * sp.sin(om) ** 2 + Ty * sp.cos(om) ** 2), Ty * sp.sin(om) ** 2 - Tx * sp.sin(om) ** 2,
                 (Ty - Tx) * sp.sin(om) ** 2),
        note="each line read as its residual (left minus right side): the residuals are equal, so each line is "
             "equivalent to the one before; the last step divides by sin^2(omega) != 0, true for the angle "
             "2 pi/n between two equivalent symmetry axes (n >= 3)")
d.quote("isotropic", "VI", r"also aus 56:  $T = T_x = T_y$",
        reading=(Tx * sp.sin(om) ** 2 + Tx * sp.cos(om) ** 2, Tx), note="(56) with T_y = T_x")


def fan_triangles(n, side):
    """The fan triangles (O, V_k, V_k+1) of the regular n-gon of edge ``side`` (vertex on the +x axis): for each,
    its area and its two vertices' coordinates (u across the axis with normal (cos omega, sin omega), v along it)."""
    R = side / (2 * sp.sin(pi / n))
    V = [(R * sp.cos(2 * pi * k / n), R * sp.sin(2 * pi * k / n)) for k in range(n)]
    for k in range(n):
        (x1, y1), (x2, y2) = V[k], V[(k + 1) % n]
        yield ((x1 * y2 - x2 * y1) / 2,
               *((x * sp.cos(om) + y * sp.sin(om), -x * sp.sin(om) + y * sp.cos(om)) for x, y in ((x1, y1), (x2, y2))))


def ngon_moment(n, side):
    """Exact second moment of the regular n-gon of edge ``side`` about the central axis with normal
    (cos omega, sin omega): sum over the fan triangles of area/6 (u_k^2 + u_k u_k+1 + u_k+1^2)."""
    return sum(area / 6 * (u1 ** 2 + u1 * u2 + u2 ** 2) for area, (u1, _), (u2, _) in fan_triangles(n, side))


NGONS = (3, 4, 6)
ngon_T = sp.Matrix([ngon_moment(n, a) for n in NGONS])
d.step("regular-polygons-isotropic", (ngon_T, ngon_T.subs(om, 0)), "geometry",
       note="for n = 3, 4, 5, 6 the moment does not depend on the direction of the axis")
d.quote("regular-polygon-theorem", "VI",
        "In jedem regelmässigen Polygon haben die Trägheitsmomente für alle durch seinen Schwerpunkt "
        "(Mittelpunkt) gehenden Achsen denselben Wert",
        reading=(ngon_T, ngon_T.subs(om, 0)),
        note="read for the regular triangle, square and hexagon of edge a; the general n follows "
             "from other-symmetry-axis")



def ngon_product(n, side):
    """Exact product moment int u v df of the regular n-gon of edge ``side``, u across the axis with normal
    (cos omega, sin omega), v along it: over each fan triangle area/12 (2 u_k v_k + u_k v_k+1 + u_k+1 v_k + 2 u_k+1 v_k+1)."""
    return sum(area / 12 * (2 * u1 * v1 + u1 * v2 + u2 * v1 + 2 * u2 * v2)
               for area, (u1, v1), (u2, v2) in fan_triangles(n, side))


d.quote("regular-prism-law", "VI",
        "„Schwimmt ein regelmässiges gerades Prisma in schiefer Lage stabil und zwar so, dass seine obere Grundfläche "
        "über, die untere unter dem Wasserspiegel sich befindet, und wird es um seine (zu den Grundflächen senkrechte) "
        "Hauptachse gedreht, so bleibt es in allen Lagen im stabilen Gleichgewicht, so lange keine der Grundflächen "
        "den Wasserspiegel durchschneidet“.",
        reading=(sp.Matrix([ngon_product(n, a) for n in NGONS] + [sp.Derivative(ngon_T[k], om) for k in range(3)]),
                 sp.zeros(6, 1)),
        note="read for the regular triangle, square and hexagon of edge a turned by omega about the main axis: the "
             "product moment int_1 u v df of the base, whose vanishing is the second equilibrium condition (45), is "
             "0 for every omega, and the moment T_1 (hence the tilt (52) and the stability (51)) does not change; "
             "the general law of section V (an erratum there) holds for these bases")

def at_data(printed, derived, data):
    """A worked example's inequality at its data: the printed margin (positive when the printed relation holds)
    equals the derived margin there, and is positive."""
    keys, values = tuple(data), tuple(data.values())
    pm = sp.Subs(printed, keys, values)
    return sp.Matrix([pm, sp.sign(pm)]), sp.Matrix([sp.Subs(derived, keys, values), 1])


# =====================================================================================================
# A. The regular triangular prism
# =====================================================================================================
F1, T1, V1, e1, hA = sp.symbols("F_1 T_1 V_1 e_1 h_A")
half_w = (a / sq3 - Y) / sq3                       # half width of the triangle at height Y
y_lo, y_hi = -a / (2 * sq3), a / sq3
tri = ((X, -half_w, half_w), (Y, y_lo, y_hi))
d.step("triangle-area", (F1, sp.Integral(1, *tri), sq3 * a ** 2 / 4), "integration", result=F1,
       note="the equilateral triangle of edge a with centre O at the origin, BC parallel to the X axis: "
            "B = (-a/2, -a/(2 sqrt 3)), C = (a/2, -a/(2 sqrt 3)), A = (0, a/sqrt 3); the Y axis is a "
            "symmetry axis")
d.step("triangle-Ty", (sp.Integral(X ** 2, *tri), sq3 * a ** 4 / 96), "integration")
d.step("triangle-Tx", (sp.Integral(Y ** 2, *tri), sq3 * a ** 4 / 96), "integration")
d.step("triangle-product-moment", (sp.Integral(X * Y, *tri), 0), "integration")
d.step("triangle-moment", (T1, sp.Integral((Y * sp.sin(om) + X * sp.cos(om)) ** 2, *tri), F1 * a ** 2 / 24),
       "integration", uses=("triangle-area",),
       note="the same for every axis through O (isotropy, checked here directly)", result=T1)
d.step("displacement", Eq(V1, F1 * b * s), "definition",
       note="Archimedes: the upright prism is submerged to the height b s (weight F_1 b s)", result=V1)
d.step("centre-distance", Eq(e1, b / 2 - b * s / 2), "definition",
       note="G at half the height b, the centre of buoyancy at half the draught b s", result=e1)
d.step("metacentric-height", (hA, T1 / V1 - e1, (a ** 2 - 12 * b ** 2 * s * (1 - s)) / (24 * b * s)), "algebra",
       uses=("triangle-moment", "displacement", "centre-distance"),
       note="the upright position is stable when h_A > 0 (Duhamel, (18))", result=hA)

# the stability the text names in words (symfloat/model/vocabulary.json): Duhamel's (18) for the upright prism,
# T/V - e_1 with the moment T and the displacement V of the body a sentence speaks of (at=TRIANGLE, CYLINDER)
Tb, Vb = sp.symbols("T_b V_b", positive=True)
d.defines("stability", Tb / Vb - e1)
TRIANGLE = {Tb: T1, Vb: V1}
d.quote("triangle-data", "VI.A",
        r"$$T_1 = F_1 \cdot \frac{a^2}{24} \quad V_1 = F_1 b \cdot s \quad e_1 = \frac{b(1-s)}{2}$$",
        reading=(sp.Matrix([T1, V1, e1]), sp.Matrix([F1 * a ** 2 / 24, F1 * b * s, b * (1 - s) / 2])))
d.quote("triangle-condition", "VI.A",
        r"$$F_1 \cdot \frac{a^2}{24} - F_1 \cdot \frac{b^2}{2} s (1-s) > 0$$",
        reading=(F1 * a ** 2 / 24 - F1 * b ** 2 / 2 * s * (1 - s), V1 * hA),
        note="the left side is V_1 h_A, V_1 > 0")
d.says("duhamel-VA-words", "VI.A", "Nach dem Duhamelschen Satze schwimmt das Prisma in der aufrechten Lage stabil, wenn",
       "Lage stabil", StableIff(T1 - V1 * e1 > 0, at=TRIANGLE),
       note="Read as: the upright triangular prism is stable exactly when T_1 - V_1 e_1 > 0 (the display after the "
            "words), Duhamel's (18) times V_1 > 0.")
d.quote("duhamel-VA", "VI.A", r"$$T_1 - V_1 e_1 > 0$$", reading=(T1 - V1 * e1, V1 * hA),
        note="Duhamel (18) times V_1 > 0: the margin is V_1 h_A")
d.quote("57", "(57)", r"$$\left(\frac{a}{b}\right)^2 > 12 s \cdot (1-s) \tag{57}$$",
        reading=((a / b) ** 2 - 12 * s * (1 - s), 24 * s / b * hA), note="margin = (24 s / b) h_A")
d.quote("58", "(58)",
        r"\frac{1}{12} \left(\frac{a}{b}\right)^2 &> s - s^2 \\ s^2 - s &> -\frac{1}{12} \left(\frac{a}{b}\right)^2 "
        r"\\ \left(s - \frac{1}{2}\right)^2 &> \frac{1}{4} \left\{1 - \frac{1}{3} \left(\frac{a}{b}\right)^2\right\}",
        reading=as_printed(lambda: ((a / b) ** 2 / 12 - (s - s ** 2), s ** 2 - s + (a / b) ** 2 / 12,
                 (s - sp.Rational(1, 2)) ** 2 - sp.Rational(1, 4) * (1 - (a / b) ** 2 / 3), 2 * s / b * hA)),
        note="each line read as its margin (left minus right side); all equal (2 s / b) h_A")
d.step("largest-product", (12 * s * (1 - s), 3 - 12 * (s - sp.Rational(1, 2)) ** 2), "algebra",
       note="12 s (1 - s) <= 3 with equality only at s = 1/2: for (a/b)^2 > 3 every density is stable")
d.quote("sqrt3", "VI.A", r"$$\left(\frac{a}{b}\right)^2 > 3 \text{ oder } \frac{a}{b} > 1,7321$$",
        reading=(sp.sqrt((12 * s * (1 - s)).subs(s, sp.Rational(1, 2))), sp.Rational("1.7321")),
        tolerance=PRINTED_DIGITS, note="the largest value of 12 s (1 - s), at s = 1/2, and its root")

d.quote("every-density", "VI.A", "Gew. zwischen 0 und 1 die aufrechte Lage stabil.",
        reading=(24 * s / b * hA, ((a / b) ** 2 - 3) + 12 * (s - sp.Rational(1, 2)) ** 2),
        note="for (a/b)^2 > 3 the margin of (57) is a sum of positive terms for every s: stable")
d.quote("sqrt3-below", "VI.A", r"$\frac{a}{b} < 1,7321$",
        reading=(sp.sqrt((12 * s * (1 - s)).subs(s, sp.Rational(1, 2))), sp.Rational("1.7321")),
        tolerance=PRINTED_DIGITS, note="the same bound sqrt 3, from below")
# the two roots of 12 s (1 - s) = (a/b)^2, the smaller first (the step density-factor checks both)
_roots = ((b / 2 - sp.sqrt(-3 * a ** 2 + 9 * b ** 2) / 6) / b, (b / 2 + sp.sqrt(-3 * a ** 2 + 9 * b ** 2) / 6) / b)
S_lo, S_hi = sp.symbols("s_-^A s_+^A")
d.step("density-roots", Eq(S_hi, _roots[1]), "definition",
       note="the larger root of 12 s (1 - s) = (a/b)^2", result=S_hi)
d.step("density-roots-lower", Eq(S_lo, _roots[0]), "definition", note="the smaller root", result=S_lo)
d.step("density-factor", ((a / b) ** 2 - 12 * s * (1 - s), 12 * (s - S_hi) * (s - S_lo)), "algebra",
       uses=("density-roots", "density-roots-lower"),
       note="the margin of (57) is positive exactly outside [s_-, s_+]")
d.quote("density-range", "VI.A",
        r"$$s \begin{cases} \text{entweder} > \frac{1}{2} \left( 1 + \sqrt{1 - \frac{1}{3} \left( \frac{a}{b} "
        r"\right)^2} \right) \\ \text{oder} < \frac{1}{2} \left( 1 - \sqrt{1 - \frac{1}{3} \left( \frac{a}{b} "
        r"\right)^2} \right) \end{cases}$$",
        reading=(sp.Matrix([(1 + sp.sqrt(1 - (a / b) ** 2 / 3)) / 2, (1 - sp.sqrt(1 - (a / b) ** 2 / 3)) / 2]),
                 sp.Matrix([S_hi, S_lo])))

# ---- Examples 1 and 2 ------------------------------------------------------------------------------
ex1_ratio = 4 * sp.sqrt(3) / 5          # sqrt(12 * 0.8 * 0.2): the step example-1-threshold checks it
d.step("example-1-threshold", (sp.Subs(full(hA), (s, a), (sp.Rational(4, 5), ex1_ratio * b)), 0), "substitution",
       uses=("metacentric-height",), note="a/b at which h_A = 0 for s = 0.8")
d.quote("ex1-root", "Example 1", r"$$\frac{a}{b} > \sqrt{12 \cdot 0,8 \cdot 0,2}$$",
        reading=as_printed(lambda: (sp.sqrt(12 * sp.Rational(8, 10) * sp.Rational(2, 10)), ex1_ratio)))
d.quote("ex1-value", "Example 1", r"$$\frac{a}{b} > \frac{139}{100}$$",
        reading=(ex1_ratio, sp.Rational(139, 100)), tolerance=sp.Rational(1, 200),
        note="'angenaehert': two decimals")
s_hi_1, s_lo_1 = (e.subs({a: 1, b: 1}) for e in (_roots[1], _roots[0]))
d.quote("ex2-root", "Example 2",
        r"\sqrt{1 - \frac{1}{3} \left( \frac{a}{b} \right)^2} = \sqrt{\frac{2}{3}}",
        reading=as_printed(lambda: (sp.sqrt(1 - (a / b) ** 2 / 3).subs(a, b), sp.sqrt(sp.Rational(2, 3)))), note="a/b = 1")
d.quote("ex2-from-58", "Example 2", r"Auflösung. In 58 ist  $\frac{a}{b} = 1$  zu setzen.",
        reading=((s - sp.Rational(1, 2)) ** 2 - sp.Rational(1, 4) * (1 - sp.Rational(1, 3)), sp.Subs(2 * s / b * hA, a, b)),
        note="the last line of (58) at a = b is the margin (2 s / b) h_A of the equilateral prism: the reference is "
             "right, and its root sqrt(2/3) follows")
d.quote("ex2-two-thirds", "Example 2", r"\sqrt{\frac{2}{3}} = \sqrt{0,6667}",
        reading=(sp.sqrt(sp.Rational(2, 3)), sp.sqrt(sp.Rational("0.6667"))), tolerance=sp.Rational(1, 20000),
        note="the root 2 s_+ - 1 at a = b, as the roots of the radicand (2 s_+ - 1)^2 and its four printed digits: "
             "the tolerance is half a unit of the radicand's last digit (the root moves by less)")
d.quote("ex2-root-value", "Example 2", r"\sqrt{0,6667} = 0,8165",
        reading=(2 * s_hi_1 - 1, sp.Rational("0.8165")), tolerance=PRINTED_DIGITS,
        note="the root is 2 s_+ - 1 at a = b")
d.quote("ex2-upper", "Example 2", r"s &> 0,908", reading=(s_hi_1, sp.Rational("0.908")),
        tolerance=PRINTED_DIGITS)
d.quote("ex2-lower", "Example 2", r"\text{oder } s &< 0,092", reading=(s_lo_1, sp.Rational("0.092")),
        tolerance=PRINTED_DIGITS)

# ---- the tilted prism in the first rotation region ---------------------------------------------------
# The rotation axis PQ through O has the direction p = (-cos w, sin w): it makes the angle w with DE || BC,
# and B lies on the side n = (-sin w, -cos w), which dips (s > 1/2).  xi = coordinate along n, eta along p.
Bv, Cv, Av = (-a / 2, -a / (2 * sq3)), (a / 2, -a / (2 * sq3)), (0, a / sq3)
nvec, pvec = (-sp.sin(om), -sp.cos(om)), (-sp.cos(om), sp.sin(om))
xi = X * nvec[0] + Y * nvec[1]
eta = X * pvec[0] + Y * pvec[1]
Vt, Mx, My, Mz, mA, tan1 = sp.symbols("V_t M_xi M_eta M_z m_A t_1")
cphi, sphi = 1 / sp.sqrt(1 + tp ** 2), tp / sp.sqrt(1 + tp ** 2)
col = b * s + xi * tp                                 # submerged height over the point (X, Y) of the base
d.step("tilted-volume", (Vt, sp.Integral(col, *tri), V1), "integration", uses=("displacement",),
       note="water plane z = b s + xi tan(phi) through O (it keeps the volume since int xi df = 0), "
            "tau = tan(phi); no base cut", result=Vt)
d.step("tilted-moment-xi", (Mx, sp.Integral(xi * col, *tri), T1 * tp), "integration",
       uses=("triangle-moment",), result=Mx)
d.step("tilted-moment-eta", (My, sp.Integral(eta * col, *tri), 0), "integration",
       note="(31): the centre of buoyancy stays in the plane of tilt for every omega, since int xi eta df = 0",
       result=My)
d.step("tilted-moment-z", (Mz, sp.Integral(col ** 2 / 2, *tri), F1 * b ** 2 * s ** 2 / 2 + T1 * tp ** 2 / 2),
       "integration", uses=("triangle-moment",), result=Mz)
d.step("righting-arm", Eq(mA, (cphi * Mx + sphi * (Mz - Vt * b / 2)) / Vt), "definition",
       note="horizontal distance of B = (M_xi, M_eta, M_z)/V_t from G = (0, 0, b/2) toward the dipping side, "
            "w = (cos phi, sin phi) in the (xi, z) plane; positive = restoring", result=mA)
d.step("righting-moment", (V1 * mA, sphi * ((1 + tp ** 2 / 2) * T1 - V1 * e1)), "algebra",
       uses=("righting-arm", "tilted-volume", "tilted-moment-xi", "tilted-moment-z"), note="(12)")
BOUNDARY = b * sp.sqrt(12 * s * (1 - s))              # a on the boundary of (57): the stability T_1/V_1 - e_1 is 0
d.step("boundary-restoring", (sp.Subs(V1 * mA, a, BOUNDARY), sp.Subs(sphi * T1 * tp ** 2 / 2, a, BOUNDARY)),
       "algebra", uses=("righting-moment", "metacentric-height"),
       note="on the boundary (a/b)^2 = 12 s (1 - s) the second variation vanishes, but the moment (12) is "
            "sin(phi) T_1 tg^2(phi)/2 > 0 for every tilt of the first region: the upright position turns back "
            "(at third order), stable, not neutral, as (65) I counts it with '>='")
d.step("tilted-equilibrium", Eq(tan1, sp.sqrt(-2 * a ** 2 - 24 * b ** 2 * s ** 2 + 24 * s * b ** 2) / a), "definition",
       note="the positive root tau of the bracket of righting-moment (tau > 0 was assumed; the step "
            "tilted-equilibrium-check puts it back)",
       result=tan1)
d.step("tilted-equilibrium-check", ((1 + tan1 ** 2 / 2) * T1 - V1 * e1, 0), "algebra",
       uses=("tilted-equilibrium", "righting-moment"))
d.step("tilted-equilibrium-54", (tan1 ** 2, F1 * b ** 2 * s * (1 - s) / T1 - 2, 24 * (b / a) ** 2 * s * (1 - s) - 2),
       "algebra", uses=("tilted-equilibrium",), note="(54) for the triangle")
d.step("tilted-stable-in-phi", (sp.Derivative((1 + tp ** 2 / 2) * T1 - V1 * e1, tp), T1 * tp), "algebra",
       note="the bracket grows with tau: the moment changes from - to + at tau = t_1, so the tilted position "
            "is stable against a change of phi (against a turn about the prism axis it is indifferent: (51))")

um, umr, Ltop, Lbot = sp.symbols("u_m u_m' L_top L_bot")
d.quote("57-fails", "VI.A",
        "Ist die Bedingung 57 (oder 58) aber nicht erfüllt, so ist die aufrechte Lage labil",
        reading=((a / b) ** 2 - 12 * s * (1 - s), 24 * s / b * hA),
        note="the margin of (57) is (24 s / b) h_A: where it is negative, so is h_A (Duhamel, (18))")
d.quote("BS", "VI.A", r"$B S = \frac{a}{3} \sqrt{3}$", reading=as_printed(lambda: (sp.sqrt(Bv[0] ** 2 + Bv[1] ** 2), a / 3 * sq3)))
d.quote("BSD", "VI.A", r"$B S D = 30^\circ$", reading=as_printed(lambda: (sp.atan2(-Bv[1], -Bv[0]), 30 * deg)),
        note="SB makes 30 deg with the parallel DE to BC through the centre S")
d.step("dipping-distance", Eq(um, Bv[0] * nvec[0] + Bv[1] * nvec[1]), "definition",
       note="distance of the vertex B from the axis PQ, on the dipping side n", result=um)
d.step("dipping-distance-value", (um, a / sq3 * sp.sin(pi / 6 + om)), "geometry", uses=("dipping-distance",))

def _reach(w):
    """The largest distance of a vertex of ABC from the axis PQ at the angle w, on the dipping side."""
    n = (-sp.sin(w), -sp.cos(w))
    return sp.Max(*(V[0] * n[0] + V[1] * n[1] for V in (Av, Bv, Cv)))


d.quote("omega-60", "VI.A",
        r"Die Achse P Q nimmt offenbar alle nur möglichen relativen Lagen an, wenn  $\omega$  von 0 bis  "
        r"$60^\circ$  zunimmt",
        reading=(sp.Matrix([_reach(om + 2 * pi / 3) - _reach(om), _reach(pi / 3 + om) - _reach(pi / 3 - om)]),
                 sp.zeros(2, 1)),
        note="read as: what the triangle shows to the axis (here the reach u_m of its dipping side) repeats with the "
             "period 120 deg (the turn that maps ABC onto itself) and is mirrored about omega = 60 deg (hence about "
             "0): every direction is one of 0 <= omega <= 60 deg")
d.step("dipping-vertex-farthest", (as_printed(lambda: (Bv[0] - Cv[0]) * nvec[0] + (Bv[1] - Cv[1]) * nvec[1]), a * sp.sin(om)),
       "geometry", note="B is at least as far as C on the dipping side for 0 <= omega <= 60 degrees (A lies on "
                        "the other side)")
d.step("rising-distance", Eq(umr, -(Av[0] * nvec[0] + Av[1] * nvec[1])), "definition",
       note="the vertex A is the farthest point on the rising side n' = -n (C, at the distance "
            "(a/sqrt 3) sin(omega - 30 deg), is no farther than A for omega <= 60 deg)", result=umr)
d.step("rising-distance-value", (umr, a / sq3 * sp.cos(om)), "geometry", uses=("rising-distance",))
d.quote("59", "(59)", r"$$u_m = \frac{a}{3} \sqrt{3} \cdot \sin(30^\circ + \omega) \quad (59)$$",
        reading=Eq(um, a / 3 * sq3 * sp.sin(30 * deg + om)))
d.step("top-limit", Eq(Ltop, b * (1 - s) / um), "definition",
       note="(53): the water height b s + u_m tan(phi) at the dipping vertex reaches the top base b",
       result=Ltop)
d.step("top-limit-check", (b * s + um * Ltop, b), "algebra", uses=("top-limit",))
d.step("bottom-limit", Eq(Lbot, b * s / umr), "definition",
       note="(53a): the water height b s - u_m' tan(phi) at the rising vertex A reaches the bottom base 0",
       result=Lbot)
d.step("bottom-limit-check", (b * s - umr * Lbot, 0), "algebra", uses=("bottom-limit",))
d.step("bottom-limit-relabelled", (sp.Subs(full(Lbot), om, pi / 3 - om), b * s * sq3 / (a * sp.sin(pi / 6 + om))),
       "geometry", uses=("bottom-limit", "rising-distance-value"),
       note="for s < 1/2 Scheeffer measures omega on the lower base from its rising vertex: omega -> 60 deg - "
            "omega turns the bottom limit into b s sqrt3 / (a sin(30 deg + omega))")

d.quote("60-from-54", "(60)",
        "Wir erhalten also aus 54 und 55 für den Drehungswinkel  $\\varphi_1$  der stabilen Gleichgewichtslage die "
        "Bedingungen:", reading=(tan1 ** 2, F1 * b ** 2 * s * (1 - s) / T1 - 2),
        note="(54) with the triangle's F_1, T_1 gives the tilt; (55) with (59) the bound")
d.quote("60-tan", "(60)", r"\text{tg } \varphi_1 &= \sqrt{24 \cdot \frac{b^2}{a^2} s (1-s) - 2}",
        reading=Eq(tan1, sp.sqrt(24 * b ** 2 / a ** 2 * s * (1 - s) - 2)))
d.quote("60-bound", "(60)",
        r"\text{tg } \varphi_1 &\leq \frac{b}{a} \cdot \frac{(1-s) \sqrt{3}}{\sin(30^\circ + \omega)}",
        reading=Eq(Ltop, b / a * (1 - s) * sq3 / sp.sin(30 * deg + om)),
        note="read as its bound: the tangent of the tilt at which the upper base meets the water")
# the claim that one base decides: a counterexample with a = b, s = 3/5, omega = 0
cx = {a: 1, b: 1, s: sp.Rational(3, 5), om: 0}
Ltop_cx = (b * (1 - s) / (a / sq3 * sp.sin(pi / 6 + om))).subs(cx)
Lbot_cx = (b * s / (a / sq3 * sp.cos(om))).subs(cx)
d.quote("60-one-base", "(60)",
        r"In der zweiten Bedingung ist  $s$  statt  $1-s$  zu setzen, wenn  $s < \frac{1}{2}$  ist.",
        reading=(sp.Min(Ltop_cx, Lbot_cx), Ltop_cx),
        note="read at a = b, s = 3/5, omega = 0: the first-region limit tan(phi) is min(top, bottom limit); "
             "the text takes the top limit alone for s > 1/2",
        erratum=Erratum(
            "claim", "high",
            r"The first rotation region needs both conditions: $\operatorname{tg}\varphi_1 \le \frac{b}{a}"
            r"\frac{(1-s)\sqrt3}{\sin(30^\circ+\omega)}$ (upper base, vertex B dipping) and $\operatorname{tg}"
            r"\varphi_1 \le \frac{b}{a}\frac{s\sqrt3}{\cos\omega}$ (lower base, vertex A rising). For $s > 1/2$ "
            r"the lower one is the sharper when $s \sin(30^\circ+\omega) < (1-s)\cos\omega$, i.e. for "
            r"$1/2 < s < 2/3$ and $\omega < \operatorname{arctg}\frac{2-3s}{\sqrt3\, s}$ (and symmetrically for "
            r"$1/3 < s < 1/2$); only for $s \ge 2/3$ ($s \le 1/3$) does one base decide for every $\omega$.",
            (r"Section V derived (53)/(55) assuming the upper base is cut first when $s > \tfrac12$, which holds when "
             "the farthest points on both sides of the axis are equally far (circle, square, centrally symmetric "
             r"bases). In the triangle they are not: the rising side holds the vertex A at $(a/\sqrt{3}) \cos "
             r"\omega$, up to twice the distance ($a/(2\sqrt3)$ at $\omega = 0$) of the dipping edge BC. At $a = b$, "
             r"$s = \tfrac35$, $\omega = 0$ the lower base meets the water at $\tan(\varphi) = 3 \sqrt{3}/5 = 1.039$, "
             r"before the upper one ($4 \sqrt{3}/5 = 1.386$); the clipped prism confirms it."),
            corrected_reading=as_printed(lambda: (sp.Min(Ltop_cx, Lbot_cx), Lbot_cx)),
                        objection="The sentence only mirrors (55) of section V for s < 1/2, which is right as an "
                                  "instruction; and since the sense of the tilt is free, the prism may be turned so "
                                  "that the side whose base is cut later dips.",
                        answer=("With either sense of the tilt one base limits the tilt before (60) does: at $a = "
                                r"b$, $s = \tfrac35$, $\omega = 0$ the lower base meets the water at "
                                r"$\operatorname{tg} \varphi = 3 \sqrt{3}/5 = 1.039$ (BC dipping) and the upper at "
                                r"$\sqrt3 \cdot 2/5 = 0.693$ (A dipping), both below the $4 \sqrt{3}/5 = 1.386$ that "
                                r"(60) allows, as the clipped prism confirms; the text's own $BS = (a/3) \sqrt{3}$ of "
                                r"(59) puts the vertex A at $(a/\sqrt{3}) \cos \omega$ on the rising side. Letting "
                                r"$s$ alone choose the base fails for $\tfrac13 < s < \tfrac23$: high stands.")))

# ---- (61)-(65): limits of omega and of a/b ---------------------------------------------------------


def boundary(limit, at, name, value, note):
    """(a/b)^2 at which the tilted equilibrium t_1 meets a first-region limit, stated as *value*; the step
    <name>-check puts it back into t_1^2 = limit^2."""
    sym = sp.Symbol(name)
    d.step(name, Eq(sym, value), "definition", note=note, result=sym)
    d.step(name + "-check", (full(tan1 ** 2 - limit ** 2).subs(om, at).subs(a, b * sp.sqrt(sym)), 0),
           "substitution", uses=(name,))
    return sym


L_top_S = b / a * (1 - s) * sq3 / sp.sin(pi / 6 + om)       # Scheeffer's bound for s > 1/2
L_bot_S = b / a * s * sq3 / sp.sin(pi / 6 + om)             # and for s < 1/2 (omega on the lower base)
# the four values, -(3/2)(s - 1)(9s - 1) and so on, kept in the factored form the certificates were made for
Q60 = boundary(Ltop, pi / 3, "Q60", sp.Mul(-1, sp.Rational(3, 2), s - 1, 9 * s - 1, evaluate=False),
               "(a/b)^2 at which t_1 = top limit at omega = 60 deg (vertex B straight across the axis): below it "
               "the upper base is cut for some axis")
Q60l = boundary(L_bot_S, pi / 3, "Q60-lower", sp.Mul(-1, sp.Rational(3, 2), s, 9 * s - 8, evaluate=False),
                "the same for s < 1/2 with the lower base")
Q0 = boundary(Ltop, 0, "Q0", sp.Mul(-1, 6, s - 1, 3 * s - 1, evaluate=False),
              "(a/b)^2 at which t_1 = top limit at omega = 0 (edge BC across the axis)")
Q0l = boundary(L_bot_S, 0, "Q0-lower", sp.Mul(-1, 6, s, 3 * s - 2, evaluate=False),
               "the same for s < 1/2 with the lower base")

d.quote("60-deg-limit", "VI.A",
        "Ist der Grenzwert von  $\\omega = 60^\\circ$ , so kann das Prisma in der schiefen stabilen Gleichgewichtslage "
        "um seine Hauptachse beliebig weit gedreht werden",
        reading=(Ltop - sp.Subs(Ltop, om, pi / 3), b * (1 - s) * sq3 / a * (1 / sp.sin(pi / 6 + om) - 1)),
        note="the top limit exceeds its value at omega = 60 deg by a non-negative amount for every omega: if the "
             "tilt is within it there, it is within it for every axis (the upper base; the lower base: 60-one-base)")
d.quote("less-satisfied", "VI.A",
        "so ist sie für grössere Werte von  $\\omega$  um so weniger erfüllt",
        reading=Holds(sp.Derivative(sp.sin(30 * deg + om), om) > 0, {om: (0, pi / 3)}),
        note="the left side sin(30 deg + omega) of (61) increases on 0 < omega < 60 deg (the sign of its derivative) "
             "and the right side does not contain omega: (61) fails for larger omega once it fails at omega = 0")
D61 = sp.sqrt(24 * s * (1 - s) - 2 * (a / b) ** 2)
d.quote("61-from-60", "VI.A",
        r"$$\sqrt{24 \cdot \frac{b^2}{a^2} s (1-s) - 2} \leq \frac{b}{a} \frac{(1-s) \sqrt{3}}{\sin(30^\circ + \omega)}$$",
        reading=(sp.Matrix([sp.sqrt(24 * b ** 2 / a ** 2 * s * (1 - s) - 2), b / a * (1 - s) * sq3 / sp.sin(30 * deg + om)]),
                 sp.Matrix([tan1, Ltop])), note="the two sides are t_1 and the top limit")
d.quote("61", "(61)",
        r"\sin(30^\circ + \omega) &\leq \frac{(1-s) \sqrt{3}}{\sqrt{24 s (1-s) - 2 \left(\frac{a}{b}\right)^2}} "
        r"\quad \text{für } s > \frac{1}{2} \\ \text{und } \sin(30^\circ + \omega) &\leq \frac{s \sqrt{3}}{\sqrt{24 s "
        r"(1-s) - 2 \cdot \left(\frac{a}{b}\right)^2}} \quad \text{für } s < \frac{1}{2}",
        reading=(sp.Matrix([(1 - s) * sq3 / D61, s * sq3 / D61]),
                 sp.Matrix([b * (1 - s) * sq3 / (a * tan1), b * s * sq3 / (a * tan1)])),
        note="the bound on sin(30 deg + omega) at which t_1 equals the limit (top for s > 1/2, bottom "
             "relabelled for s < 1/2)")
d.quote("sin-90", "VI.A", r"$\sin(30^\circ + \omega) = 1$", reading=(sp.Subs(sp.sin(30 * deg + om), om, pi / 3), 1),
        note="at the limit omega = 60 deg")
d.quote("61-at-60", "VI.A",
        r"$$\left( \text{für } s > \frac{1}{2} \right): \sqrt{24 s (1-s) - 2 \left(\frac{a}{b}\right)^2} \leq (1-s) \sqrt{3}$$",
        reading=(sp.Matrix([D61, (1 - s) * sq3]), sp.Matrix([a / b * tan1, sp.Subs(a / b * Ltop, om, pi / 3)])),
        note="(61) at sin(30 deg + omega) = 1: its two sides are a/b times t_1 and a/b times the top limit at "
             "omega = 60 deg")
qq = (a / b) ** 2
d.quote("62-step-1", "VI.A", r"24 s (1-s) - 2 \left(\frac{a}{b}\right)^2 \leq 3 (1-s)^2",
        reading=(3 * (1 - s) ** 2 - (24 * s * (1 - s) - 2 * qq), 2 * (qq - Q60)), note="margin")
d.quote("62-step-2", "VI.A", r"$$3 (1-s) \{8 s - (1-s)\} \leq 2 \left(\frac{a}{b}\right)^2$$",
        reading=(2 * qq - 3 * (1 - s) * (8 * s - (1 - s)), 2 * (qq - Q60)), note="margin")
d.quote("62-step-3", "VI.A", r"$$\left(\frac{a}{b}\right)^2 \geq \frac{3}{2} (1-s) (9 s - 1)$$",
        reading=(qq - sp.Rational(3, 2) * (1 - s) * (9 * s - 1), qq - Q60), note="margin")
P62u, P62l = sp.Rational(3, 2) * (1 - s) * (9 * s - 1), sp.Rational(3, 2) * s * (8 - 9 * s)
d.quote("62", "(62)",
        r"\text{also } \frac{a}{b} &\geq \sqrt{\frac{3}{2} \cdot (1-s) (9 s - 1)} \quad \text{für } s > \frac{1}{2} "
        r"\\ \text{und } \frac{a}{b} &\geq \sqrt{\frac{3}{2} \cdot s (8 - 9 s)} \quad \text{für } s < \frac{1}{2}",
        reading=(sp.Matrix([(a / b - sp.sqrt(P62u)) * (a / b + sp.sqrt(P62u)), (a / b - sp.sqrt(P62l)) * (a / b + sp.sqrt(P62l))]),
                 sp.Matrix([qq - Q60, qq - Q60l])), note="margins times the positive a/b + sqrt(...)")
d.quote("62-upper-inline", "VI.A", r"$\frac{a}{b} \geq \sqrt{\frac{3}{2} \cdot (1-s) (9 s - 1)}$",
        reading=((a / b - sp.sqrt(P62u)) * (a / b + sp.sqrt(P62u)), qq - Q60), note="margin times a/b + sqrt(...)")
d.quote("62-lower-inline", "VI.A", r"$\frac{a}{b} \geq \sqrt{\frac{3}{2} \cdot s (8 - 9 s)}$",
        reading=((a / b - sp.sqrt(P62l)) * (a / b + sp.sqrt(P62l)), qq - Q60l), note="margin times a/b + sqrt(...)")
d.quote("sin-30", "VI.A", r"$\sin 30^\circ = \frac{1}{2}$", reading=(sp.Subs(sp.sin(30 * deg + om), om, 0), sp.Rational(1, 2)),
        note="(61) at omega = 0")
D63 = 24 * s * (1 - s) - 2 * qq
d.quote("63", "(63)",
        r"\sin^2(30^\circ) &> \frac{3 (1-s)^2}{24 s (1-s) - 2 \left(\frac{a}{b}\right)^2} \quad \text{für } s > "
        r"\frac{1}{2} \\ \text{oder } \sin^2 30^\circ &> \frac{3 s^2}{24 s (1-s) - 2 \left(\frac{a}{b}\right)^2} "
        r"\quad \text{für } s < \frac{1}{2}",
        reading=(sp.Matrix([(sp.sin(30 * deg) ** 2 - 3 * (1 - s) ** 2 / D63) * D63, (sp.sin(30 * deg) ** 2 - 3 * s ** 2 / D63) * D63]),
                 sp.Matrix([(Q0 - qq) / 2, (Q0l - qq) / 2])),
        note="margins times the positive denominator 24 s(1-s) - 2 (a/b)^2 (a tilted position exists)")
d.quote("64", "(64)",
        r"\left(\frac{a}{b}\right)^2 &< 6(1-s)(3s-1) && \text{für } s > \frac{1}{2} \\ \text{und } "
        r"\left(\frac{a}{b}\right)^2 &< 6s(2-3s) && \text{für } s < \frac{1}{2}",
        reading=(sp.Matrix([6 * (1 - s) * (3 * s - 1) - qq, 6 * s * (2 - 3 * s) - qq]), sp.Matrix([Q0 - qq, Q0l - qq])))
d.quote("65-IV", "(65)",
        r"$$IV \quad \left(\frac{a}{b}\right)^2 < \begin{cases} 6(1-s)(3s-1) & \text{für } s > \frac{1}{2} \\ "
        r"6s(2-3s) & \text{für } s < \frac{1}{2} \end{cases}$$",
        reading=(sp.Matrix([6 * (1 - s) * (3 * s - 1) - qq, 6 * s * (2 - 3 * s) - qq]), sp.Matrix([Q0 - qq, Q0l - qq])),
        note="margins: below Q0 the tilted equilibrium lies beyond the limit even at omega = 0, i.e. for every axis")
d.quote("65-I-words", "(65)", "so schwimmt es in aufrechter Lage stabil.",
        reading=(24 * s / b * hA, qq - 12 * s * (1 - s)),
        note="I: the margin of (57) is (24 s/b) h_A >= 0; where it is 0 the second variation vanishes, and the "
             "exact moment (12) decides: restoring (step boundary-restoring), so 'stabil' holds there too (a "
             "StableIff reading, which counts that point neutral, would wrongly refute it)")
d.quote("65-IV-words", "(65)",
        "so hat das Prisma ausser der aufrechten labilen keine Gleichgewichtslage weiter ohne dass eine der "
        "Grundflächen vom Wasserspiegel durchschnitten wird.",
        reading=(sp.Matrix([6 * (1 - s) * (3 * s - 1) - qq, 6 * s * (2 - 3 * s) - qq]), sp.Matrix([Q0 - qq, Q0l - qq])),
        note="IV: below Q0 the tilt of (54) lies beyond the first-region limit already at omega = 0, and (61) is "
             "harder for larger omega (less-satisfied): no axis gives a tilted position in the first region")
d.quote("65-I", "(65)", r"$$I \quad \left(\frac{a}{b}\right)^2 \geq 12s(1-s)$$",
        reading=(qq - 12 * s * (1 - s), 24 * s / b * hA),
        note="at equality h_A = 0 but the moment sin(phi) T_1 tan^2(phi)/2 is still restoring (step "
             "boundary-restoring): stable, so '>=' is right")
d.quote("65-II", "(65)",
        r"$$II \quad \text{Wenn } 12s(1-s) > \left(\frac{a}{b}\right)^2 \geq \begin{cases} \frac{3}{2}(1-s)(9s-1) & "
        r"\text{für } s > \frac{1}{2} \\ \frac{3}{2}s(8-9s) & \text{für } s < \frac{1}{2} \end{cases}$$",
        reading=(sp.Matrix([12 * s * (1 - s) - qq, qq - P62u, qq - P62l]), sp.Matrix([-24 * s / b * hA, qq - Q60, qq - Q60l])),
        note="II holds for every axis also when the other base is included: over omega the top limit is "
             "smallest at omega = 60 deg and the bottom limit b s sqrt3/(a cos omega) at omega = 0, where it "
             "equals b s sqrt3 / a >= b (1-s) sqrt3 / a for s > 1/2")
d.quote("65-II-words", "(65)",
        "so schwimmt es in aufrechter Lage labil, erreicht aber durch Drehung um jede beliebige horizontale Achse eine "
        "schiefe stabile Lage", reading=(tan1 ** 2, -2 * V1 * hA / T1),
        note="upright labile (h_A < 0) exactly when the tilt of (54) is real: tg^2 phi_1 = -2 V_1 h_A / T_1 > 0")
d.quote("65-tan", "(65)", r"$$\operatorname{tg}^2 \varphi_1 = 24 \left(\frac{b}{a}\right)^2 s(1-s) - 2$$",
        reading=Eq(tan1 ** 2, 24 * (b / a) ** 2 * s * (1 - s) - 2))
d.quote("65-III", "(65)",
        r"\frac{3}{2}(1-s)(9s-1) > \left(\frac{a}{b}\right)^2 \geq 6(1-s)(3s-1) & \left(\text{für } s > "
        r"\frac{1}{2}\right) \\ \frac{3}{2}s(8-9s) > \left(\frac{a}{b}\right)^2 \geq 6s(2-3s) & \left(\text{für } s "
        r"< \frac{1}{2}\right)",
        reading=(sp.Matrix([P62u - qq, qq - 6 * (1 - s) * (3 * s - 1), P62l - qq, qq - 6 * s * (2 - 3 * s)]),
                 sp.Matrix([Q60 - qq, qq - Q0, Q60l - qq, qq - Q0l])))
d.quote("65-III-omega", "(65)",
        r"\sin^2(30^\circ + \omega) \leq \begin{cases} \frac{3(1-s)^2}{24s(1-s) - 2\left(\frac{a}{b}\right)^2} & "
        r"\text{für } s > \frac{1}{2} \\ \frac{3s^2}{24s(1-s) - 2\left(\frac{a}{b}\right)^2} & \text{für } s < "
        r"\frac{1}{2} \end{cases}",
        reading=(sp.Matrix([3 * (1 - s) ** 2 / D63, 3 * s ** 2 / D63]),
                 sp.Matrix([(b * (1 - s) * sq3 / (a * tan1)) ** 2, (b * s * sq3 / (a * tan1)) ** 2])),
        note="(61) squared; as a necessary condition it is right")
# the existence claim of III: counterexample s = 11/20, (a/b)^2 = 11/5 (inside III)
cx3 = {s: sp.Rational(11, 20), a: sp.sqrt(sp.Rational(11, 5)), b: 1}
w_cross = sp.atan((2 - 3 * s) / (sq3 * s))        # where top(omega) = bottom(omega): s sin(30+w) = (1-s) cos w
best_limit = (b / a * (1 - s) * sq3 / sp.sin(pi / 6 + w_cross)).subs(cx3)
tan1_cx3 = sp.sqrt(24 * s * (1 - s) / (a / b) ** 2 - 2).subs(cx3)
Delta3 = sp.nsimplify(0) + full(mA).subs(cx3).subs(tp, best_limit)
d.quote("65-III-claim", "(65)",
        r"so schwimmt das Prisma in aufrechter Lage labil und erreicht durch Drehung um eine horizontale Achse "
        r"(wie in II) eine schiefe stabile Lage.",
        reading=(sp.Max(Delta3, 0), Delta3),
        note="read at s = 11/20, (a/b)^2 = 11/5, b = 1 (in III: 1.755 <= 2.2 < 2.666): Delta = the righting "
             "arm m_A at the tilt where the first base meets the water, for the best axis omega = "
             "arctg((2-3s)/(sqrt3 s)) = 20.2 deg (there the top and bottom limits coincide, elsewhere the "
             "first contact comes earlier). The claim needs Delta >= 0: the equilibrium reached before a base "
             "is cut",
        erratum=Erratum(
            "claim", "high",
            r"In III a tilted position in the first region exists only if also the lower base stays under water: "
            r"for $s > 1/2$ an axis $\omega$ must satisfy both $\sin(30^\circ+\omega) \le (1-s)K$ and "
            r"$\cos\omega \le sK$, "
            r"$K = \sqrt3\,b/(a\,\operatorname{tg}\varphi_1)$. For $1/2 < s < 2/3$ such $\omega$ exist iff "
            r"$(a/b)^2 \ge 12s(1-s) - \frac{3(1-s)^2}{2\sin^2(30^\circ+\omega_\times)}$, $\omega_\times = "
            r"\operatorname{arctg}\frac{2-3s}{\sqrt3\,s}$ (the best axis); for $s \ge 2/3$ the printed III is right. "
            r"At $s = 0.55$ no axis works for $1.755 \le (a/b)^2 < 2.455$ (III as printed: $1.755 \ldots 2.666$). "
            r"For $s < 1/2$ the same with $s$ and $1-s$ exchanged.",
            (r"At $s = \tfrac{11}{20}$, $(a/b)^2 = \tfrac{11}{5}$: $t_1 = \sqrt{24 s(1-s)/(a/b)^2 - 2} = 0.8367$, but "
             r"the best axis ($\omega = 20.17^\circ$, where the top and bottom limits are equal) allows only "
             r"$\tan(\varphi) \le 0.6842$: for every axis one base is cut before the equilibrium is reached: at that "
             r"first contact the righting arm is still $-0.0109\, b$ (capsizing), in the formula of (12) and in the "
             "clipped prism alike. The lower-base condition omitted in (55)/(60) (see the erratum on (60): one base) "
             "decides here; (61) is necessary, not sufficient."),
            corrected_reading=as_printed(lambda: (sp.Min(Delta3, 0), Delta3)),
                        objection="III only says the prism reaches an oblique stable position; one that capsizes "
                                  "past the first contact of a base may still come to rest where a base is cut, and "
                                  "the claim would then hold.",
                        answer=(r"III gives the position of II ('wie in II'), whose angle is $\operatorname{tg}^2 "
                                r"\varphi_1 = 24 (b/a)^2 s(1-s) - 2$, restricts its axis by (61) so that the upper "
                                "base does not dip, and IV closes the result with 'ohne dass eine der Grundflächen "
                                "vom Wasserspiegel durchschnitten wird': the claim is of the first region. At $s = "
                                r"\tfrac{11}{20}$, $(a/b)^2 = \tfrac{11}{5}$ no axis reaches that angle before a base "
                                r"is cut, where the righting arm is still $-0.0109\, b$. High stands.")))

# ---- Examples 3 and 4 ------------------------------------------------------------------------------
s3 = sp.Rational(2, 3)
Q60_3 = sp.factor(full(Q60)).subs(s, s3)
tan1_expr = full(tan1)
phi3 = sp.atan(tan1_expr.subs({s: s3, a: sp.sqrt(Q60_3), b: 1}))
d.quote("ex3-condition", "Example 3", r"$$\left(\frac{a}{b}\right)^2 = \frac{3}{2} (1 - s) (9s - 1)$$",
        reading=(Q60, P62u), note="an upper vertex in the water: the boundary of 65 II")
d.quote("ex3-tan", "Example 3",
        r"$$\operatorname{tg} \varphi_1 = \sqrt{24 \cdot \left(\frac{b}{a}\right)^2 \cdot s (1 - s) - 2}$$",
        reading=Eq(tan1, sp.sqrt(24 * (b / a) ** 2 * s * (1 - s) - 2)))
d.quote("ex3-ratio-squared", "Example 3", r"\left(\frac{a}{b}\right)^2 = \frac{5}{2}",
        reading=(Q60_3, printed_fraction(5, 2)))
d.quote("ex3-ratio", "Example 3", r"\frac{a}{b} = 1,58 \text{ (angenähert)}",
        reading=(sp.sqrt(Q60_3), sp.Rational("1.58")), tolerance=PRINTED_DIGITS)
d.quote("ex3-ratio-fraction", "Example 3", r"$$\text{oder } \frac{a}{b} = \frac{158}{100}$$",
        reading=(sp.sqrt(Q60_3), sp.Rational(158, 100)), tolerance=sp.Rational(1, 200))
d.quote("ex3-angle", "Example 3", r"$$\varphi_1 = 20^\circ 3' 35''$$",
        reading=(phi3 * 180 / pi, 20 + sp.Rational(3, 60) + sp.Rational(35, 3600)), tolerance=sp.Rational(1, 7200),
        note="degrees; exact 20 deg 3' 34.50''")

w4, t4 = pi / 12, sp.tan(pi / 6)
beta68 = 1 / (18 * (-1 + s) ** 2)       # (b/a)^2: the step example-4-top-check puts it back
B68 = sp.Symbol("B_68")
d.step("example-4-top", Eq(B68, beta68), "definition",
       note="(b/a)^2 from: top limit at omega = 15 deg equals tan 30 deg", result=B68)
d.step("example-4-top-check", ((b * (1 - s) / (a / sq3 * sp.sin(pi / 6 + om))).subs(om, w4).subs(b, a * sp.sqrt(B68)) ** 2,
                               t4 ** 2), "substitution", uses=("example-4-top", "dipping-distance-value"))
s4 = sp.Rational(7, 11)                 # the density of t_1 = tan 30 deg there: the step example-4-density checks it
q4 = 1 / sp.sqrt(beta68.subs(s, s4))
d.step("example-4-density", (sp.Subs(full(24 * B68 * s * (1 - s) - 2), s, s4), t4 ** 2), "substitution",
       uses=("example-4-top", "tilted-equilibrium-54"), note="t_1 = tan 30 deg with (b/a)^2 = B_68")
d.quote("67", "(67)",
        r"\operatorname{tg} 30^\circ &= \sqrt{24 \cdot \frac{b^2}{a^2} s (1 - s) - 2} \\ \text{und } "
        r"\operatorname{tg} 30^\circ &= \frac{b}{a} \cdot \frac{(1 - s) \sqrt{3}}{\sin 45^\circ}",
        reading=(sp.Matrix([sp.sqrt(24 * b ** 2 / a ** 2 * s * (1 - s) - 2), b / a * (1 - s) * sq3 / sp.sin(45 * deg)]),
                 sp.Matrix([tan1, full(Ltop).subs(om, w4)])),
        note="the two sides of (60) at omega = 15 deg: t_1 and the top limit (both set to tan 30 deg)")
d.quote("ex4-from-60", "Example 4",
        r"Da hier  $\omega = 15^\circ$  und  $\varphi_1$  als Grenzwert  $= 30^\circ$  ist, so hat man aus 60",
        reading=(sp.Matrix([tan1, full(Ltop).subs(om, w4)]),
                 sp.Matrix([sp.sqrt(24 * b ** 2 / a ** 2 * s * (1 - s) - 2),
                            b / a * (1 - s) * sq3 / sp.sin(pi / 6 + pi / 12)])),
        note="the two members of (60) at omega = 15 deg (sin(30 deg + omega) = sin 45 deg); both are set to tg 30 deg "
             "in (67)")
d.quote("ex3-at-two-thirds", "Example 3", r"Aus der ersten ergibt sich für  $s = \frac{2}{3}$ :",
        reading=as_printed(lambda: (Q60_3, sp.Rational(3, 2) * (1 - s3) * (9 * s3 - 1))),
        note="(a/b)^2 = 3/2 (1 - s)(9 s - 1) at s = 2/3 (the condition of ex3-condition)")
d.quote("ex4-constants", "Example 4",
        r"$\operatorname{tg} 30^\circ = \frac{1}{3} \cdot \sqrt{3}$  und  $\sin 45^\circ = \frac{1}{2} \sqrt{2}$",
        reading=as_printed(lambda: (sp.Matrix([sp.tan(30 * deg), sp.sin(45 * deg)]), sp.Matrix([sq3 / 3, sp.sqrt(2) / 2]))))
d.quote("68", "(68)", r"$$\left(\frac{b}{a}\right)^2 = \frac{1}{18 \cdot (1 - s)^2} \quad (68)$$",
        reading=(B68, 1 / (18 * (1 - s) ** 2)))
d.quote("ex4-density", "Example 4", r"$$s = \frac{7}{11} = 0,636$$",
        reading=(s4, printed_fraction(7, 11), printed_fraction(636, 1000)), tolerance=sp.Rational(1, 2000))
d.quote("ex4-ratio", "Example 4", r"$$\frac{a}{b} = (1 - s) \sqrt{181} = \frac{4}{11} \cdot \sqrt{181}$$",
        reading=as_printed(lambda: (q4, (1 - s4) * sp.sqrt(181), sp.Rational(4, 11) * sp.sqrt(181))),
        erratum=Erratum(
            "transcription", "medium", r"\frac{a}{b} = (1 - s) \sqrt{18} = \frac{4}{11} \cdot \sqrt{18}",
            (r"From (68), $a/b = \sqrt{18} (1 - s) = 12 \sqrt{2} / 11 = 1.5428$; the text itself continues "
             r"'angenaehert a/b = 17/11' $= 1.545$, which fits $\sqrt{18}$ and not $\sqrt{181}$ ($4.89$). The same "
             "stray '1' after 18 in both places looks like a scan artefact (a footnote mark or the next line's "
             "digit) rather than the author's arithmetic; from the transcription alone a misprint cannot be excluded."),
            corrected_reading=as_printed(lambda: (q4, (1 - s4) * sp.sqrt(18), sp.Rational(4, 11) * sp.sqrt(18))),
                        objection=(r"$\sqrt{181}$ stands twice in one line, a repeat the criteria give to the print: "
                                   "the author may have copied 18 as 181 and taken his approximation from the right "
                                   "number."),
                        answer=(r"The line is (68) solved with $s = \tfrac{7}{11}$, which gives "
                                r"$\tfrac{4}{11}\sqrt{18}$, and the approximation $17/11 = 1.545$ that follows fits "
                                r"$\sqrt{18} (1.543)$ and not $\sqrt{181} (4.89)$; a digit added to the same radicand "
                                "at both places of one line is one glyph under the radical read twice the same way, "
                                "more like the scan than a compositor's slip. The print cannot be seen: medium.")))
d.quote("ex4-ratio-value", "Example 4", r"$$\text{d. i. angenähert } \frac{a}{b} = \frac{17}{11}$$",
        reading=(q4, sp.Rational(17, 11)), tolerance=sp.Rational(1, 22),
        note="a fraction with denominator 11: half a unit of the numerator, 1/22")


# =====================================================================================================
# B. The circular cylinder
# =====================================================================================================
rho = sp.Symbol("rho", positive=True)
disc = ((rho, 0, r), (th, 0, 2 * pi))
F1c, T1c, V1c, hC, tanC, LtopC, LbotC, xC = sp.symbols("F_1^C T_1^C V_1^C h_C t_C L_top^C L_bot^C x_C")
xi_c = rho * sp.cos(th)
col_c = b * s + xi_c * tp
d.step("disc-area", (F1c, sp.Integral(rho, *disc), pi * r ** 2), "integration", result=F1c)
d.step("disc-moment", (T1c, sp.Integral(xi_c ** 2 * rho, *disc), pi * r ** 4 / 4), "integration", result=T1c,
       note="about every diameter (the disc is symmetric about its centre in every direction)")
d.step("cylinder-displacement", Eq(V1c, F1c * b * s), "definition", note="Archimedes", result=V1c)
d.step("cylinder-metacentric-height", (hC, T1c / V1c - e1, (r ** 2 - 2 * b ** 2 * s * (1 - s)) / (4 * b * s)),
       "algebra", uses=("disc-moment", "cylinder-displacement", "centre-distance"), result=hC)
d.step("cylinder-tilted-volume", (sp.Integral(col_c * rho, *disc), V1c), "integration")
d.step("cylinder-tilted-moments",
       (sp.Matrix([sp.Integral(xi_c * col_c * rho, *disc), sp.Integral(rho * sp.sin(th) * col_c * rho, *disc),
                   sp.Integral(col_c ** 2 / 2 * rho, *disc)]),
        sp.Matrix([T1c * tp, 0, F1c * b ** 2 * s ** 2 / 2 + T1c * tp ** 2 / 2])), "integration",
       note="the same moments as for the triangle: righting-moment holds with T_1^C, V_1^C")
d.step("cylinder-tilted-equilibrium", Eq(tanC, sp.sqrt(-2 * r ** 2 - 4 * b ** 2 * s ** 2 + 4 * s * b ** 2) / r),
       "definition",
       note="positive root of (1 + tau^2/2) T_1 - V_1 e_1 (the next step puts it back)", result=tanC)
d.step("cylinder-tilted-equilibrium-check", ((1 + tanC ** 2 / 2) * T1c - V1c * e1, 0), "algebra",
       uses=("cylinder-tilted-equilibrium",))
d.step("cylinder-limits", (sp.Matrix([b * s + r * LtopC, b * s - r * LbotC]), sp.Matrix([b, 0])), "definition",
       note="u_m = r on both sides: the top rim dips to the water at b s + r tan(phi) = b, the bottom rim "
            "rises to it at b s - r tan(phi) = 0")
d.step("cylinder-top-limit", Eq(LtopC, b * (1 - s) / r), "definition", result=LtopC)
d.step("cylinder-bottom-limit", Eq(LbotC, b * s / r), "definition", result=LbotC)
d.step("cylinder-limits-check", (sp.Matrix([b * s + r * LtopC, b * s - r * LbotC]), sp.Matrix([b, 0])), "algebra",
       uses=("cylinder-top-limit", "cylinder-bottom-limit"),
       note="the farthest points are at r on both sides, so for s > 1/2 the top limit is the smaller")
d.step("immersion-height", Eq(xC, b * s + r * tanC), "definition",
       note="the water height on the dipping generator (xi = r) in the tilted equilibrium", result=xC)

K2 = (2 * r / b) ** 2
CYLINDER = {Tb: T1c, Vb: V1c}
d.says("cylinder-duhamel", "VI.B",
       "also nach dem Duhamelschen Satze die Bedingung für eine stabile aufrechte Gleichgewichtslage",
       "stabile aufrechte", StableIff(T1c / V1c - e1 > 0, at=CYLINDER),
       note="Read as: the upright cylinder is stable exactly when T_1/V_1 - e_1 > 0 (the first line of the display "
            "after the words), Duhamel's (18) with its T_1 and V_1.")
d.quote("cylinder-data", "VI.B", r"$$T_1 = \frac{\pi}{4} r^4 \quad F_1 = \pi r^2 \quad u_m = r \quad e_1 = \frac{b}{2} (1 - s)$$",
        reading=(sp.Matrix([T1c, F1c, e1]), sp.Matrix([pi / 4 * r ** 4, pi * r ** 2, b / 2 * (1 - s)])))
d.quote("cylinder-condition", "VI.B",
        r"\frac{T_1}{V_1} - e_1 &> 0 \\ \frac{r^2}{4 b s} - \frac{b}{2} (1 - s) &> 0 \\ \frac{r^2}{b^2} &> 2 s (1 - s)",
        reading=(T1c / V1c - e1, r ** 2 / (4 * b * s) - b / 2 * (1 - s), b / (4 * s) * (r ** 2 / b ** 2 - 2 * s * (1 - s)), hC),
        note="margins; the last line times b/(4 s) > 0")
d.quote("69", "(69)", r"$$\frac{2r}{b} > \sqrt{8 s (1 - s)} \quad (69)$$",
        reading=((2 * r / b - sp.sqrt(8 * s * (1 - s))) * (2 * r / b + sp.sqrt(8 * s * (1 - s))), 16 * s / b * hC),
        note="margin times the positive 2r/b + sqrt(8 s (1-s))")
d.quote("70", "(70)",
        r"\left(\frac{2r}{b}\right)^2 &> 8 s - 8 s^2 \\ \left(s - \frac{1}{2}\right)^2 &> \frac{1}{4} \left[1 - "
        r"\frac{1}{2} \left(\frac{2r}{b}\right)^2\right]",
        reading=(K2 - 8 * s + 8 * s ** 2, 8 * ((s - sp.Rational(1, 2)) ** 2 - (1 - K2 / 2) / 4), 16 * s / b * hC),
        note="margins, the second times 8")
d.quote("sqrt2", "VI.B",
        r"$$\frac{1}{2} \cdot \left(\frac{2r}{b}\right)^2 > 1 \text{ oder } \frac{2r}{b} > \sqrt{2} \text{ d. i. } > 1,4142.$$",
        reading=as_printed(lambda: (sp.sqrt((8 * s * (1 - s)).subs(s, sp.Rational(1, 2))), sp.sqrt(2), sp.Rational("1.4142"))),
        tolerance=PRINTED_DIGITS, note="the largest 8 s (1-s), at s = 1/2")
d.quote("cylinder-every-density", "VI.B", "Diese Bedingung ist für jeden Wert von  $s$  (zwischen 0 und 1) erfüllt, wenn",
        reading=(16 * s / b * hC, (K2 - 2) + 8 * (s - sp.Rational(1, 2)) ** 2),
        note="the margin of (69), (2r/b)^2 - 8 s (1-s), is a sum of positive terms for every s when (2r/b)^2 > 2")
d.quote("sqrt2-below", "VI.B", r"$\frac{2r}{b} < 1,4142$",
        reading=(sp.sqrt((8 * s * (1 - s)).subs(s, sp.Rational(1, 2))), sp.Rational("1.4142")),
        tolerance=PRINTED_DIGITS, note="the same bound sqrt 2, from below")
# the two roots of 8 s (1 - s) = (2r/b)^2, the smaller first (the step cylinder-density-factor checks both)
_rootsC = ((b - sp.sqrt(b ** 2 - 2 * r ** 2)) / (2 * b), (b + sp.sqrt(b ** 2 - 2 * r ** 2)) / (2 * b))
SC_lo, SC_hi = sp.symbols("s_-^C s_+^C")
d.step("cylinder-density-upper", Eq(SC_hi, _rootsC[1]), "definition", note="the larger root", result=SC_hi)
d.step("cylinder-density-lower", Eq(SC_lo, _rootsC[0]), "definition", result=SC_lo)
d.step("cylinder-density-factor", (K2 - 8 * s * (1 - s), 8 * (s - SC_hi) * (s - SC_lo)), "algebra",
       uses=("cylinder-density-upper", "cylinder-density-lower"))
d.quote("71", "(71)",
        r"\text{für } s > \frac{1}{2}: \quad s &> \frac{1}{2} \left(1 + \sqrt{1 - \frac{1}{2} \left(\frac{2r}{b}\right)^2}\right) "
        r"\\ \text{für } s < \frac{1}{2}: \quad s &< \frac{1}{2} \left(1 - \sqrt{1 - \frac{1}{2} \left(\frac{2r}{b}\right)^2}\right)",
        reading=(sp.Matrix([(1 + sp.sqrt(1 - K2 / 2)) / 2, (1 - sp.sqrt(1 - K2 / 2)) / 2]), sp.Matrix([SC_hi, SC_lo])))

# Example 5, 6
d.quote("ex5", "Example 5", r"$\frac{2r}{b} > \sqrt{2}$  oder  $> 1,4142$",
        reading=(sp.sqrt((8 * s * (1 - s)).subs(s, sp.Rational(1, 2))), sp.Rational("1.4142")),
        tolerance=PRINTED_DIGITS)
sq_ = {b: 2 * r}                                # square axial section: 2r = b
d.quote("ex6-ratio", "Example 6", r"In 71 hat man  $\frac{2}{b} = 1$  zu setzen",
        reading=((2 / b).subs(sq_), 1), note="square axial section: b = 2r",
        erratum=Erratum("transcription", "medium", r"\frac{2r}{b} = 1",
                        ("The example sets the ratio of diameter to height, $2r/b$, to $1$ (square axial section); "
                         "$2/b = 1$ would fix $b = 2$ whatever $r$ is. The r is lost here and in the next line, "
                         r"which only gives $\sqrt{0.50}$ with $2r/b = 1$. Probably the scan lost the letter; a "
                         "misprint repeated twice is less likely."),
                        corrected_reading=as_printed(lambda: ((2 * r / b).subs(sq_), 1)),
                        objection="The r is missing in two consecutive lines, a repeat the criteria give to the "
                                  "print: the author or the compositor may have written 2/b for the ratio in this "
                                  "example.",
                        answer="The example asks for the cylinder of square axial section, 2r/b = 1, and (69)-(72) "
                               "around it print 2r/b every time; the second line is (71)'s radicand with that ratio "
                               "put in, so both places are one substitution and one letter lost, at the same place "
                               "of the fraction. Print or scan lost it, with the scan the likelier: medium."))
d.quote("ex6-root", "Example 6", r"\sqrt{1 - \frac{1}{2} \cdot \left(\frac{2}{b}\right)^2} = \sqrt{0,50}",
        reading=(sp.sqrt(1 - (2 / b) ** 2 / 2).subs(sq_), sp.sqrt(sp.Rational(1, 2))),
        erratum=Erratum("transcription", "medium", r"\sqrt{1 - \frac{1}{2} \cdot \left(\frac{2r}{b}\right)^2} = \sqrt{0,50}",
                        "The same lost r as in ex6-ratio; with 2r/b = 1 the radicand is 1/2 as printed.",
                        corrected_reading=as_printed(lambda: (sp.sqrt(1 - (2 * r / b) ** 2 / 2).subs(sq_), sp.sqrt(sp.Rational(1, 2)))),
                        same_as="scheeffer-vi-ab/ex6-ratio",
                        objection="As in the line before, the print may have 2/b in both places.",
                        answer=("The radicand is (71)'s $1 - (1/2)(2r/b)^2$, and 0,50 is its value at $2r/b = 1$; "
                                "the same lost r as in the line before, whose booking this repeats: medium.")))
sC_hi1, sC_lo1 = (e.subs(sq_) for e in (_rootsC[1], _rootsC[0]))
for ex6_name, ex6_words, ex6_value, ex6_printed in (
        ("ex6-root-value", r"\sqrt{0,50} = 0,7071", 2 * sC_hi1 - 1, "0.7071"),
        ("ex6-sum", r"1 + \sqrt{0,50} = 1,7071", 2 * sC_hi1, "1.7071"),
        ("ex6-difference", r"1 - \sqrt{0,50} = 0,2929", 2 * sC_lo1, "0.2929"),
        ("ex6-upper", r"folglich entweder  $s > 0,8536$", sC_hi1, "0.8536"),
        ("ex6-lower", r"oder  $s < 0,1464$", sC_lo1, "0.1464")):
    d.quote(ex6_name, "Example 6", ex6_words, reading=(ex6_value, sp.Rational(ex6_printed)), tolerance=PRINTED_DIGITS,
            note="2r = b: the density roots s_+, s_- of (71) (and 2 s_+ - 1, 2 s_+, 2 s_-)")

d.quote("cylinder-turns", "VI.B",
        "so ist der Cylinder in der aufrechten Lage labil und dreht sich um eine horizontale Achse, bis er in eine "
        "stabile Gleichgewichtslage gelangt.", reading=(tanC ** 2, -2 * V1c * hC / T1c),
        note="labile (h_C < 0) exactly when the tilted equilibrium is real: tg^2 phi_1 = -2 V_1 h_C / T_1")
d.says("cylinder-labile-words", "VI.B",
       "so ist der Cylinder in der aufrechten Lage labil und dreht sich um eine horizontale Achse, bis er in eine "
       "stabile Gleichgewichtslage gelangt.", "aufrechten Lage labil",
       StableIff((2 * r / b) ** 2 < 8 * s * (1 - s), at=CYLINDER),
       note="Read as: the upright cylinder is labile exactly when (72) holds, 2r/b < sqrt(8 s (1 - s)), squared "
            "(both sides positive); the tilted position it turns to: cylinder-turns.")
d.quote("72", "(72)", r"$$\text{Ist aber} \quad \frac{2r}{b} < \sqrt{8s(1-s)} \quad (72)$$",
        reading=((sp.sqrt(8 * s * (1 - s)) - 2 * r / b) * (sp.sqrt(8 * s * (1 - s)) + 2 * r / b), -16 * s / b * hC))
d.quote("cylinder-data-72", "VI.B", r"$$F_1 = \pi r^2 \quad T_1 = \frac{\pi r^4}{4} \quad u_m = r$$",
        reading=(sp.Matrix([F1c, T1c]), sp.Matrix([pi * r ** 2, pi * r ** 4 / 4])))
Bc = b / (2 * r)
d.quote("72a-cited", "VI.B", "Diese ist durch die Bedingungen 55 bestimmt, wenn darin",
        reading=(tanC ** 2, sp.Piecewise(((b * (1 - s) / r) ** 2, s > sp.Rational(1, 2)), ((b * s / r) ** 2, True))),
        note="read as: the tilt the cited (55) determines with u_m = r (it bounds tg phi_1 only; read at its bound) "
             "is the tilt of the cylinder's oblique equilibrium, whose tg^2 the next display gives",
        erratum=Erratum("misprint", "low", r"\text{Diese ist durch die Bedingungen 54 und 55 bestimmt}",
                        (r"The tilt $\operatorname{tg}^2 \varphi_1 = 16 (b/2r)^2 s(1-s) - 2$ of the next display is "
                         r"(54), $\operatorname{tg}^2 \varphi_1 = F_1 b^2 s(1-s)/T_1 - 2$, with $F_1 = \pi r^2, T_1 = "
                         r"\pi r^4/4$; (55) contains neither $F_1$ nor $T_1$ and only bounds the tilt (the second "
                         "line of (72a), with $u_m = r$). For the triangular prism the text cites rightly 'aus 54 "
                         "und 55' (before (60)); here 54 is missing, and again in VI.C ('wenn die Bedingungen 55 "
                         "erfüllt sind', then $F_1 b^2 s(1-s)/T_1$). Low: the author may have meant the pair (54), "
                         "(55) by 'Bedingungen 55'; the print, not the scan (a number dropped from a reference)."),
                        corrected_reading=(tanC ** 2, F1c * b ** 2 * s * (1 - s) / T1c - 2),
                        objection="'Bedingungen 55' in the plural may be the author's name for the pair (54), (55), "
                                  "which section V introduces together ('Bestimmungsgleichung (54) mit der Bedingung"
                                  " (55)'); VI.C uses the same words, so it is his usage, not a fault.",
                        answer=("The tilt of the next display is (54) with $F_1$ and $T_1$ put in, which (55) does "
                                "not contain, and for the triangular prism the text cites 'aus 54 und 55'; the "
                                "repeat in VI.C can be usage as well as a slip, so the reading as a name of the pair "
                                "cannot be excluded: low stands.")))
d.quote("72a-tan", "(72a)", r"$$\text{tg}^2 \varphi_1 = 16 \left( \frac{b}{2r} \right)^2 \cdot s (1-s) - 2$$",
        reading=Eq(tanC ** 2, 16 * Bc ** 2 * s * (1 - s) - 2))
d.quote("72a", "(72a)",
        r"$$\text{tg} \varphi_1 \leq \begin{cases} 2(1-s) \cdot \frac{b}{2r} & \text{für } s > \frac{1}{2} \\ 2s \cdot "
        r"\frac{b}{2r} & \text{für } s < \frac{1}{2} \end{cases} \quad (72a)$$",
        reading=(sp.Matrix([2 * (1 - s) * Bc, 2 * s * Bc]), sp.Matrix([LtopC, LbotC])), note="read as its bounds")
d.quote("72a-squared", "VI.B",
        r"$$16 \left( \frac{b}{2r} \right)^2 s (1-s) - 2 \leq \begin{cases} 4(1-s)^2 \cdot \left( \frac{b}{2r} \right)^2 & "
        r"\left( s > \frac{1}{2} \right) \\ 4s^2 \cdot \left( \frac{b}{2r} \right)^2 & \left( s < \frac{1}{2} \right) "
        r"\end{cases}$$",
        reading=(sp.Matrix([4 * (1 - s) ** 2 * Bc ** 2 - (16 * Bc ** 2 * s * (1 - s) - 2), 4 * s ** 2 * Bc ** 2 - (16 * Bc ** 2 * s * (1 - s) - 2)]),
                 sp.Matrix([LtopC ** 2 - tanC ** 2, LbotC ** 2 - tanC ** 2])), note="margins")
d.quote("73", "(73)",
        r"$$8s(1-s) > \left( \frac{2r}{b} \right)^2 \geq \begin{cases} 2(1-s)(5s-1) & \text{für } s > \frac{1}{2} \\ "
        r"2s(4-5s) & \text{für } s < \frac{1}{2} \end{cases} \quad (73)$$",
        reading=(sp.Matrix([8 * s * (1 - s) - K2, K2 - 2 * (1 - s) * (5 * s - 1), K2 - 2 * s * (4 - 5 * s)]),
                 sp.Matrix([-16 * s / b * hC, (LtopC ** 2 - tanC ** 2) * K2 / 2, (LbotC ** 2 - tanC ** 2) * K2 / 2])),
        note="margins; the last two are the (positive) factor (2r/b)^2/2 times the squared-limit margins")

# Example 7: 2r = b, s < 1/2
res = d.results()
hC_e, tanC_e, LtopC_e = (full(k) for k in (hC, tanC, LtopC))
s_b = (sp.Rational(2, 5) - sp.sqrt(6) / 10, sp.Rational(2, 5) + sp.sqrt(6) / 10)     # 0.4 -+ sqrt 0.06
d.step("example-7-bottom", (full(LbotC ** 2 - tanC ** 2).subs(sq_).subs(s, s_b[0]), 0), "substitution",
       note="the density at which the tilted equilibrium meets the bottom limit, 2r = b")
d.step("example-7-bottom-upper", (full(LbotC ** 2 - tanC ** 2).subs(sq_).subs(s, s_b[1]), 0), "substitution",
       note="the other root of the same equation (s > 1/2, outside the example)")
d.quote("ex7-conditions", "Example 7", r"$$8s(1-s) > 1 > 2s(4-5s)$$",
        reading=(sp.Matrix([8 * s * (1 - s) - 1, 1 - 2 * s * (4 - 5 * s)]),
                 sp.Matrix([full(-16 * s / b * hC).subs(sq_), full((LbotC ** 2 - tanC ** 2) * K2 / 2).subs(sq_)])))
d.quote("ex7-from-73", "Example 7",
        r"Es muss  $s < \frac{1}{2}$  und  $\frac{2r}{b} = 1$  sein, also nach 73:",
        reading=(sp.Matrix([8 * s * (1 - s) - 1, 1 - 2 * s * (4 - 5 * s)]),
                 sp.Matrix([full(-16 * s / b * hC).subs(sq_), full((LbotC ** 2 - tanC ** 2) * K2 / 2).subs(sq_)])),
        note="the branch s < 1/2 of (73), read as its derived margins, at 2r/b = 1: the reference is right (73 "
             "gives >=, the example >)")
d.quote("ex7-square", "Example 7", r"$$\left(\frac{1}{2} - s\right)^2 < \frac{1}{8}$$",
        reading=(sp.Rational(1, 8) - (sp.Rational(1, 2) - s) ** 2, full(-2 * s / b * hC).subs(sq_)))
d.quote("ex7-lower", "Example 7", r"$$s > \frac{1}{2} \left(1 - \sqrt{\frac{1}{2}}\right) \text{ oder } s > 0,146.$$",
        reading=(sC_lo1, (1 - sp.sqrt(sp.Rational(1, 2))) / 2, sp.Rational("0.146")), tolerance=PRINTED_DIGITS)
d.quote("ex7-second", "Example 7", r"ergibt sich  $(s - 0,4)^2 > 0,06$",
        reading=((s - sp.Rational(2, 5)) ** 2 - sp.Rational(6, 100), full((LbotC ** 2 - tanC ** 2) * K2 / 20).subs(sq_)))
for root_name, root_words, root_value, root_printed in (
        ("ex7-root", r"$\sqrt{0,06} = 0,245$", sp.Rational(2, 5) - s_b[0], "0.245"),
        ("ex7-plus", r"$$0,4 + \sqrt{0,06} = 0,645$$", s_b[1], "0.645"),
        ("ex7-minus", r"$$0,4 - \sqrt{0,06} = 0,155$$", s_b[0], "0.155")):
    d.quote(root_name, "Example 7", root_words, reading=(root_value, sp.Rational(root_printed)),
            tolerance=PRINTED_DIGITS,
            note="roots s of (2r/b)^2 = 2 s (4 - 5 s) at 2r = b (0.4 -+ sqrt 0.06)")
for range_name, range_words, range_value, range_printed in (
        ("ex7-range-lower", "zwischen 0,146", sC_lo1, "0.146"),
        ("ex7-range-upper", "und 0,155 liegen", s_b[0], "0.155")):
    d.quote(range_name, "Example 7", range_words, reading=(range_value, sp.Rational(range_printed)),
            tolerance=PRINTED_DIGITS,
            note="'Folglich muss der Wert von s zwischen 0,146 und 0,155 liegen': right; below 0.146 the "
                 "cylinder floats upright stably, above 0.155 the lower base emerges before the tilted "
                 "equilibrium is reached")

d.quote("ex7-both", "Example 7", r"$$8s(1-s) > 1 \quad \text{und} \quad 1 > 2s(4-5s)$$",
        reading=(sp.Matrix([8 * s * (1 - s) - 1, 1 - 2 * s * (4 - 5 * s)]),
                 sp.Matrix([full(-16 * s / b * hC).subs(sq_), full((LbotC ** 2 - tanC ** 2) * K2 / 2).subs(sq_)])),
        note="margins of (73) at 2r = b, as the line before")
for side_name, side_words, side_value, side_printed in (
        ("ex7-either", r"$$\text{also entweder } s > 0,4 + \sqrt{0,06}$$", s_b[1],
         as_printed(lambda: sp.Rational(4, 10) + sp.sqrt(sp.Rational(6, 100)))),
        ("ex7-or", r"$$\text{oder } s < 0,4 - \sqrt{0,06}$$", s_b[0],
         as_printed(lambda: sp.Rational(4, 10) - sp.sqrt(sp.Rational(6, 100))))):
    d.quote(side_name, "Example 7", side_words, reading=(side_value, side_printed),
            note="the roots of 1 = 2 s (4 - 5 s) (the bottom limit met, 2r = b), between which the margin is negative")
for claim_name, claim_words, claim_value, claim_printed in (("ex7-not", r"$s > 0,645$", s_b[1], "0.645"),
                                                         ("ex7-only", r"$s < 0,155$", s_b[0], "0.155")):
    d.quote(claim_name, "Example 7", claim_words, reading=(claim_value, sp.Rational(claim_printed)),
            tolerance=PRINTED_DIGITS,
            note="the roots 0.4 -+ sqrt 0.06 rounded; s > 0.645 contradicts s < 1/2")
# Example 8
ex8 = {r: 30, b: 40, s: sp.Rational(3, 4)}
d.quote("ex8-values", "Example 8",
        r"\left(\frac{2r}{b}\right)^2 = \frac{9}{4} \text{ und } 8s(1-s) = \frac{3}{2}",
        reading=as_printed(lambda: (sp.Matrix([K2.subs(ex8), (8 * s * (1 - s)).subs(ex8)]), sp.Matrix([sp.Rational(9, 4), sp.Rational(3, 2)]))))
d.quote("ex8-data", "Example 8",
        r"$$\text{Es ist } 2r = 60 \text{ cm} \quad b = 40 \text{ cm} \quad s = \frac{3}{4}$$",
        reading=(sp.Matrix([2 * r, b, s]).subs(ex8), sp.Matrix([60, 40, printed_fraction(3, 4)])),
        note="the data of the question (line 763: diameter 60 cm, height 40 cm, spec. weight 0,75) as the example "
             "uses them (ex8)")
d.quote("ex8-test", "Example 8", r"$$\text{ob } \left(\frac{2r}{b}\right)^2 \geq 8s(1-s) \text{ ist.}$$",
        reading=(K2 - 8 * s * (1 - s), 16 * s / b * hC), note="margin of (69): 16 s/b times the metacentric height")
d.quote("ex8-therefore", "Example 8", r"$$\text{folglich } \left(\frac{2r}{b}\right)^2 > \frac{3}{2}$$",
        reading=at_data(K2 - sp.Rational(3, 2), 16 * s / b * hC, ex8),
        note="at 2r = 60, b = 40, s = 3/4 the printed margin 9/4 - 3/2 is 16 s/b h_C > 0")
d.quote("ex8-claim", "Example 8",
        "Der Cylinder schwimmt also in aufrechter Lage stabil und hat unter den angegebenen Bedingungen weiter "
        "keine Gleichgewichtslage.",
        reading=as_printed(lambda: (sp.Matrix([sp.sign(hC_e.subs(ex8)), sp.sign(full((1 + tp ** 2 / 2) * T1c - V1c * e1).subs(ex8).subs(tp, LtopC_e.subs(ex8)))]),
                 sp.Matrix([1, 1]))),
        note="h_C > 0, and the bracket (1 + tau^2/2) T_1 - V_1 e_1 = T_1 tau^2/2 + V_1 h_C stays positive up to the "
             "top limit: no tilted equilibrium in the first region")
# Example 9
ex9 = {r: 15, b: 40, s: sp.Rational(4, 5)}
d.quote("ex9-values", "Example 9",
        r"\frac{2r}{b} = \frac{3}{4}, \quad \left(\frac{2r}{b}\right)^2 = \frac{9}{16} \quad 8s(1-s) = 8 \cdot 0,8 \cdot 0,2 = \frac{32}{25}",
        reading=as_printed(lambda: (sp.Matrix([2 * r / b, K2, 8 * s * (1 - s)]).subs(ex9), sp.Matrix([sp.Rational(3, 4), sp.Rational(9, 16), sp.Rational(32, 25)]))))
d.quote("ex9-labile-margin", "Example 9", r"$$\text{also } \left(\frac{2r}{b}\right)^2 < 8s(1-s)$$",
        reading=at_data(8 * s * (1 - s) - K2, -16 * s / b * hC, ex9),
        note="at 2r = 30, b = 40, s = 0.8: 32/25 - 9/16 = -16 s/b h_C > 0")
d.quote("ex9-labile", "Example 9", "d. h. der Cylinder schwimmt aufrecht labil.",
        reading=(sp.sign(sp.Subs(hC, tuple(ex9), tuple(ex9.values()))), -1), note="h_C < 0 at the data")
d.quote("ex9-bound", "Example 9", r"$$2(1-s) \cdot (5s-1) = 2 \cdot 0,2 \cdot 3 = 1,2$$",
        reading=as_printed(lambda: ((2 * (1 - s) * (5 * s - 1)).subs(ex9), sp.Rational(6, 5))))
d.quote("ex9-beyond", "Example 9", r"$$\text{also } \left(\frac{2r}{b}\right)^2 < 2(1-s)(5s-1)$$",
        reading=at_data(2 * (1 - s) * (5 * s - 1) - K2, -(LtopC ** 2 - tanC ** 2) * K2 / 2, ex9),
        note="margin of (73): the tilted equilibrium lies beyond the top limit")
d.quote("ex9-claim", "Example 9",
        "Der Cylinder hat also bei nicht eintauchender oberer Grundfläche keine stabilen Gleichgewichtslage.",
        reading=as_printed(lambda: (sp.Matrix([sp.sign(hC_e.subs(ex9)), sp.sign((LtopC_e - tanC_e).subs(ex9))]), sp.Matrix([-1, -1]))),
        note="upright labile (h_C < 0) and the tilted equilibrium lies beyond the top limit")
# Example 10
ex10 = {r: sp.Rational(8, 5), b: sp.Rational(5, 2), s: sp.Rational(3, 5)}
d.quote("ex10-ratio", "Example 10", r"\left(\frac{2r}{b}\right)^2 = \frac{32^2}{25^2}",
        reading=as_printed(lambda: (K2.subs(ex10), sp.Rational(32 ** 2, 25 ** 2))))
d.quote("ex10-data", "Example 10", "Gew. 0,6 hat einen Durchmesser von 3,2 m und eine Höhe von 2,5 m.",
        reading=(sp.Matrix([2 * r, b, s]).subs(ex10), sp.Matrix([printed_fraction(32, 10), printed_fraction(25, 10), printed_fraction(6, 10)])),
        note="the data of the question as the solution uses them (2r/b = 32/25, s(1 - s) = 0.6 * 0.4)")
d.quote("ex10-product", "Example 10", r"8s(1-s) = 8 \cdot 0,6 \cdot 0,4 = \frac{48 \cdot 25}{25^2}",
        reading=as_printed(lambda: ((8 * s * (1 - s)).subs(ex10), sp.Rational(48 * 25, 625))))
d.quote("ex10-ratio-2", "Example 10",
        r"\left(\frac{2r}{b}\right)^2 = \frac{16 \cdot 2 \cdot 32}{25^2} = \frac{16 \cdot 64}{25^2}",
        reading=(K2.subs(ex10), *as_printed(lambda: (sp.Integer(16) * 2 * 32 / sp.Integer(25) ** 2,
                                               sp.Integer(16) * 64 / sp.Integer(25) ** 2))))
d.quote("ex10-product-2", "Example 10", r"8s \cdot (1-s) = \frac{16 \cdot 3 \cdot 25}{25^2} = \frac{16 \cdot 75}{25^2}",
        reading=((8 * s * (1 - s)).subs(ex10), *as_printed(lambda: (sp.Integer(16) * 3 * 25 / sp.Integer(25) ** 2,
                                                          sp.Integer(16) * 75 / sp.Integer(25) ** 2))))
d.quote("ex10-labile-margin", "Example 10", r"folgl.  $\left(\frac{2r}{b}\right)^2 < 8s(1-s)$",
        reading=at_data(8 * s * (1 - s) - K2, -16 * s / b * hC, ex10),
        note="at 2r = 3.2, b = 2.5, s = 0.6: 1200/625 - 1024/625 = -16 s/b h_C > 0")
d.quote("ex10-labile", "Example 10", "Der Cylinder schwimmt also aufrecht labil.",
        reading=(sp.sign(sp.Subs(hC, tuple(ex10), tuple(ex10.values()))), -1), note="h_C < 0 at the data")
d.quote("ex10-test", "Example 10", r"ob  $\left(\frac{2r}{b}\right)^2 \geq 2(1-s)(5s-1)$  ist",
        reading=at_data(K2 - 2 * (1 - s) * (5 * s - 1), (LtopC ** 2 - tanC ** 2) * K2 / 2, ex10),
        note="margin of (73) at the data: positive, the tilted equilibrium lies within the top limit")
d.quote("ex10-roots", "Example 10", r"oder  $\frac{32}{25} \geq \sqrt{1,6}$",
        reading=at_data(as_printed(lambda: sp.Rational(32, 25) - sp.sqrt(sp.Rational(16, 10))),
                        (LtopC ** 2 - tanC ** 2) * K2 / 2 / (2 * r / b + sp.sqrt(2 * (1 - s) * (5 * s - 1))), ex10),
        note="the margin of (73) over 2r/b + sqrt(2(1-s)(5s-1)) is 2r/b - sqrt(2(1-s)(5s-1)) = 32/25 - sqrt 1.6")
d.quote("ex10-within", "Example 10", r"also  $\left(\frac{2r}{b}\right)^2 > 2(1-s)(5s-1)$",
        reading=at_data(K2 - 2 * (1 - s) * (5 * s - 1), (LtopC ** 2 - tanC ** 2) * K2 / 2, ex10))
d.quote("ex10-oblique", "Example 10", "Der Cylinder hat also eine schiefe stabile Gleichgewichtslage.",
        reading=(sp.Matrix([sp.sign(sp.Subs(tanC ** 2, tuple(ex10), tuple(ex10.values()))),
                            sp.sign(sp.Subs(LtopC - tanC, tuple(ex10), tuple(ex10.values())))]), sp.Matrix([1, 1])),
        note="a real tilt (tg^2 phi_1 > 0) within the top limit; the tilted position of an isotropic base is stable "
             "(IV (43))")
d.quote("ex10-bound", "Example 10", r"\left(\frac{32}{25}\right)^2 \geq 2 \cdot 0,4 \cdot 2",
        reading=as_printed(lambda: (sp.Rational(32, 25) ** 2 - sp.Rational(8, 5), (K2 - 2 * (1 - s) * (5 * s - 1)).subs(ex10))))
d.quote("ex10-decimal", "Example 10", r"\frac{32}{25} = 1,28", reading=(printed_fraction(32, 25), printed_fraction(128, 100)))
d.quote("ex10-root", "Example 10", r"\sqrt{1,6} = 1,26 \dots", reading=(sp.sqrt(sp.Rational(8, 5)), sp.Rational("1.265")),
        tolerance=sp.Rational(1, 200), note="'1,26...': the value lies in [1.26, 1.27)")
d.quote("ex10-tan2", "Example 10",
        r"\operatorname{tg}^2 \varphi_1 = 16 \cdot \left(\frac{b}{2r}\right)^2 \cdot s(1-s) - 2 = \frac{16 \cdot 25^2}{16 \cdot 64} "
        r"\cdot \frac{3}{5} \cdot \frac{2}{5} - 2 = \frac{75}{32} - 2 = \frac{11}{32}",
        reading=as_printed(lambda: ((tanC_e ** 2).subs(ex10), (16 * Bc ** 2 * s * (1 - s) - 2).subs(ex10),
                 sp.Rational(16 * 625, 16 * 64) * sp.Rational(3, 5) * sp.Rational(2, 5) - 2,
                 sp.Rational(75, 32) - 2, sp.Rational(11, 32))))
d.quote("ex10-tan", "Example 10", r"also  $\operatorname{tg} \varphi_1 = \sqrt{\frac{11}{32}}$",
        reading=as_printed(lambda: (tanC_e.subs(ex10), sp.sqrt(sp.Rational(11, 32)))))
phi10 = sp.atan(tanC_e.subs(ex10)) * 180 / pi
DMS = lambda dg, mi, se: dg + sp.Rational(mi, 60) + sp.Rational(se, 3600)
d.quote("ex10-angle", "Example 10", r"Die Ausführung der Rechnung ergibt angenähert  $\varphi_1 = 18^\circ 58' 13''$",
        reading=(phi10, DMS(18, 58, 13)), tolerance=sp.Rational(1, 7200),
        erratum=Erratum("calculation", "high", r"\varphi_1 = 30^\circ 22' 59''",
                        (r"$\operatorname{tg} \varphi_1 = \sqrt{11/32} = 0.58630$ gives $30^\circ\, 22'\, 59.4''$. "
                         r"The printed $18^\circ\, 58'\, 13''$ is arctg(11/32) to the second ($18^\circ\, 58'\, "
                         r"13.5''$): the root was not taken. The limit $\operatorname{tg} \varphi_1 \le 2(1-s) b/(2r) "
                         "= 0.625$ still holds, so the position exists."),
                        corrected_reading=(phi10, DMS(30, 22, 59)),
                        objection="The printed angle may be a slip of the digits in copying a right result, a "
                                  "misprint, not wrong arithmetic.",
                        answer=("18° 58' 13'' is arctg(11/32) to the second (18° 58' 13.5''), which no slip of "
                                r"digits gives, and the next lines compute $r \operatorname{tg}\varphi = 1{,}6 \cdot "
                                "11/32 = 0{,}55$ with the unrooted tangent: the author's arithmetic carried on. High "
                                "stands.")))
BS_EVIDENCE = ((r"The upright draught of the cylinder is b s, height times specific gravity (Archimedes: $\pi r^2 b s "
                "= weight$; IV, after (53a): 'b s nun die Höhe des ... unter dem Wasserspiegel befindlichen "
                r"Körperteils'); '$b_s$' is defined nowhere, and the next line uses $1{,}5 = 2{,}5 \cdot 0{,}6 = b "
                "s$. The scan set the s as a subscript (medium: a printer's subscript is not excluded)."))
_ax = sp.Matrix([sp.sin(sp.atan(tp)), sp.cos(sp.atan(tp))])       # the axis of the cylinder tilted by atan(tau)
_base = sp.Matrix([sp.cos(sp.atan(tp)), -sp.sin(sp.atan(tp))])    # a diameter of its base in the drawing's plane
d.quote("ex10-angle-meaning", "Example 10",
        "Diesen Winkel bildet in der stabilen Lage die Hauptachse mit der Vertikalen oder die Grundfläche mit dem "
        "Wasserspiegel.",
        reading=(sp.Matrix([sp.acos(_ax.dot(sp.Matrix([0, 1]))), sp.acos(_base.dot(sp.Matrix([1, 0])))]),
                 sp.Matrix([sp.atan(tp), sp.atan(tp)])),
        note="the body turned by phi (tg phi = tau) about a horizontal axis: its axis makes phi with the vertical, "
             "its base phi with the horizontal water plane")
d.quote("upright-draught", "Example 10", r"In der aufrechten Schwimmlage ist diese  $b_s$",
        reading=(V1c / F1c, bs_), note="diese: the height to which the side surface is immersed; upright V_1/F_1",
        erratum=Erratum("transcription", "medium", r"b s \; (= b \cdot s)",
                        r"The same '$b_s$' for $b s$ as in the formula $x = b_s + r \operatorname{tg}\varphi$ (Example 10). " + BS_EVIDENCE,
                        corrected_reading=(V1c / F1c, b * s), same_as="scheeffer-vi-ab/x-formula",
                        objection=("$b_s$ may be the author's own name for the upright draught, introduced in this "
                                   "very sentence ('ist diese $b_s$'); a name is not a fault."),
                        answer=("The sentence states a value, not a name: section V writes the same draught 'b s', "
                                r"height times specific gravity, and the next line puts $1{,}5 = 2{,}5 \cdot 0{,}6$ for it; $b_s$ "
                                "is defined nowhere else. A product set as a subscript by the scan, as in the "
                                "formula it repeats; the print's subscript cannot be excluded: medium.")))
d.quote("x-formula", "Example 10", r"x &= b_s + r \operatorname{tg} \varphi",
        reading=Eq(xC, bs_ + r * tanC),
        note="phi: the tilt of the equilibrium, phi_1 (the formula holds for every tilt of the first region)",
        erratum=Erratum("transcription", "medium", r"x = b s + r \operatorname{tg} \varphi", BS_EVIDENCE,
                        corrected_reading=Eq(xC, b * s + r * tanC),
                        objection=("$b_s$ may be a symbol of the author's for the upright draught, and the formula "
                                   "right in his notation."),
                        answer=("No $b_s$ is defined in the text; section V calls the same height '$b s$' and the "
                                r"next line's $1{,}5$ is $2{,}5 \cdot 0{,}6 = b s$. The scan sets a lower-case $s$ "
                                "after $b$ as a subscript "
                                "where the print had a product; a printed subscript cannot be excluded: medium.")))
x10 = (b * s + r * tanC_e).subs(ex10)
cons = (r"follows from the angle of Example 10: $r \operatorname{tg}\varphi_1 = 1.6 \cdot 11/32 = 0.55$ with the "
        "unrooted tangent")
d.quote("ex10-x-sum", "Example 10", r"x &= 1,5 + 0,55", reading=(x10, sp.Rational("1.5") + sp.Rational("0.55")),
        tolerance=sp.Rational(1, 200),
        erratum=Erratum("consequential", "high", r"x = 1,5 + 0,94", cons + r"; with $\operatorname{tg}\varphi_1 = \sqrt{11/32}$ it is "
                        r"$1.6 \cdot 0.5863 = 0.938$.",
                        corrected_reading=(x10, sp.Rational("1.5") + sp.Rational("0.94")),
                        objection=(r"As printed the line is right: $0{,}55 = 1{,}6 \cdot 11/32$ is $r "
                                   r"\operatorname{tg}\varphi$ for the tangent the text has just used, so there is no "
                                   "new fault here."),
                        answer=("That is what consequential says: the line follows from the unrooted tangent of the "
                                r"angle above, and with $\operatorname{tg} \varphi_1 = \sqrt{11/32}$ the term is "
                                "0,94; the line's own 0,55 shows which tangent was used. High.")))
d.quote("ex10-x", "Example 10", r"x &= 2,05", reading=(x10, sp.Rational("2.05")), tolerance=PRINTED_DIGITS,
        erratum=Erratum("consequential", "high", r"x = 2,44", cons + r"; $x = 1.5 + 0.938 = 2.438\ \mathrm{m}$.",
                        corrected_reading=(x10, sp.Rational("2.44")),
                        objection="2,05 is the right sum of the line before, no fault of its own.",
                        answer="Consequential: it carries on the unrooted tangent of the angle above; with the root "
                               r"$x = 1{,}5 + 0{,}94 = 2{,}44$ m. High."))
d.quote("ex10-fraction", "Example 10", r"$\frac{x}{b} = \frac{2,05}{2,50} = \frac{41}{50}$",
        reading=(x10 / sp.Rational(5, 2), sp.Rational(41, 50)), tolerance=sp.Rational(1, 100),
        erratum=Erratum("consequential", "high", r"\frac{x}{b} = \frac{2,44}{2,50} = \frac{49}{50} (0.9752)",
                        cons + "; $x/b = 2.438/2.5 = 0.9752$.", corrected_reading=(x10 / sp.Rational(5, 2), sp.Rational(49, 50)),
                        objection=r"$2{,}05/2{,}50 = 41/50$ is right arithmetic.",
                        answer="Consequential: it divides the $x$ of the unrooted tangent; with the root $x/b = "
                               r"2{,}44/2{,}50 = 0{,}975$, about $49/50$. High."))
d.quote("ex10-deepest", "Example 10",
        r"Der am tiefsten eintauchende Teil der Mantelhöhe beträgt also  $\frac{41}{50}$",
        reading=(x10 / sp.Rational(5, 2), sp.Rational(41, 50)), tolerance=sp.Rational(1, 100),
        erratum=Erratum("consequential", "high", r"\frac{49}{50} \; (0{,}9752)",
                        "The $x/b = 41/50$ of the line before repeated in words; " + cons
                        + "; $x/b = 2.438/2.5 = 0.9752$.",
                        corrected_reading=(x10 / sp.Rational(5, 2), sp.Rational(49, 50)),
                        same_as="scheeffer-vi-ab/ex10-fraction",
                        objection="The sentence only repeats 41/50 of the line before in words.",
                        answer=("So it is booked as the repeat of the x/b of the line before, consequential on the "
                                r"unrooted tangent: 49/50 with $\operatorname{tg} \varphi_1 = \sqrt{11/32}$. High.")))
d.quote("ex10-dry", "Example 10", r"der kürzeste über dem Wasser befindliche Teil  $\frac{9}{50}$",
        reading=(1 - x10 / sp.Rational(5, 2), sp.Rational(9, 50)), tolerance=sp.Rational(1, 100),
        erratum=Erratum("consequential", "high", r"\frac{1}{50} (0.0248)", cons + "; $1 - 0.9752 = 0.0248$.",
                        corrected_reading=(1 - x10 / sp.Rational(5, 2), sp.Rational(1, 50)),
                        objection="$9/50 = 1 - 41/50$ is right arithmetic.",
                        answer="Consequential: the complement of the $x/b$ of the unrooted tangent; with the root it "
                               r"is $1 - 0{,}975 = 0{,}025$, about $1/50$. High."))
d.quote("ex10-dry-cm", "Example 10", "der ganzen Höhe oder 45 cm",
        reading=(250 * (1 - x10 / sp.Rational(5, 2)), 45), tolerance=sp.Rational(1, 2),
        erratum=Erratum("consequential", "high", "6 cm (6.2 cm)", cons + r"; $250\,\text{cm} \cdot 0.0248 = 6.2\,\text{cm}$.",
                        corrected_reading=(250 * (1 - x10 / sp.Rational(5, 2)), 6),
                        objection="45 cm = 9/50 of 250 cm is right arithmetic.",
                        answer="Consequential: with the root the dry part of the mantle is "
                               r"$250\,\text{cm} \cdot 0{,}0248 = 6\,\text{cm}$; "
                               "the 45 cm follows only from the unrooted tangent. High."))
