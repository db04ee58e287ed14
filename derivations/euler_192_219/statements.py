"""What Euler's §§192-219 say and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import Derivation, Eq, Erratum
from symfloat.model.claim import as_printed
from symfloat.model.symbol_names import symbol
from symfloat.model.vocabulary import Compares, GrowsWith, IndependentOf, Is

x, y, w, s, r = sp.symbols("x y w s r", real=True)
a, b, c = sp.symbols("a b c", positive=True)
m = sp.Symbol("m", positive=True)
n, t, u = sp.symbols("n t u", real=True)
PM, PN, Pp = sp.symbols("PM PN Pp", positive=True)
Mw, V, h = sp.symbols("M V b_{GB}", positive=True)
Iw, Kw, Q, Q2, GMlo, GMhi, GKlo, GKhi = sp.symbols("I_w K_w Q_{AB} Q_{EF} GM_- GM_+ GK_- GK_+")
Slo, Shi, SKlo, SKhi = sp.symbols("S_{AB-} S_{AB+} S_{EF-} S_{EF+}")
l = sp.Symbol("l", positive=True)  # the letter the transcription prints for I in §208
X1, Y1, X2, Y2, xe = sp.symbols("x_1 y_1 x_2 y_2 x_e", real=True)
eb, Tb, phi = sp.symbols("e T phi", positive=True)      # §§192-200: half-beam and draught of a box, heel
hb1, hb2, gneg, Qh, St = sp.symbols("b_1 b_2 g Q S", positive=True)

DERIVATION = d = Derivation(
    id="euler-192-219",
    source="euler",
    title="Stability about any horizontal axis; moments of waterplanes (Euler, Scientia navalis III §§192–219)",
    locator="§192–§219",
    summary="Stability M(I/V ± b) about any horizontal axis (§201–203); the moment about an oblique "
            "axis, the invariant sum I + K and the extreme axes (§205–209); equal principal moments "
            "(§210); square, rectangle, rhombus, the quadrilateral of two isosceles triangles with its "
            "centroid and the parallel-axis rule, and the ellipse (§212–219). Every moment is derived by "
            "integration over the figure and witnessed by two-dimensional quadrature.",
    requires=("scheeffer-vi-cf",),
    domain={a: (1, 3), b: (sp.Rational(1, 2), 2), c: (1, 3), m: (sp.Rational(1, 10), sp.Rational(9, 10)),
            x: (-2, 2), y: (-2, 2), w: (-2, 2), s: (0, 1), r: (0, 1),
            PM: (1, 3), PN: (1, 3), Pp: (sp.Rational(1, 10), 1), Mw: (1, 5), V: (1, 5), h: (0, 2),
            Iw: (1, 5), Kw: (1, 5), l: (1, 2),
            X1: (-2, -1), Y1: (-1, 1), X2: (1, 3), Y2: (2, 3), xe: (-1, 3),
            eb: (sp.Rational(1, 2), 1), Tb: (sp.Rational(1, 2), 1), phi: (sp.Rational(1, 100), sp.Rational(1, 5)),
            hb1: (0, sp.Rational(1, 20)), hb2: (0, sp.Rational(1, 20)), gneg: (sp.Rational(1, 1000), sp.Rational(1, 100)),
            Qh: (1, 5), St: (1, 5)},
    assumptions=("lengths a, b, c and the half-widths PM, PN are positive",
                 "m = sin ACP with 0 < m < 1, n = cos ACP = sqrt(1 - m^2)",
                 "b_{GB} >= 0 is Euler's distance b between the centre of gravity G and the centre of "
                 "buoyancy B (§201); the sign in front of it says whether G lies below (+) or above (-) B",
                 "the generic figure of §205 and §217 is a rectangle [x_1, x_2] x [y_1, y_2] placed anywhere; the "
                 "rules are linear in the figure, so they hold for every union of rectangles and, in the limit, "
                 "every figure",
                 "the quadrilateral of §215: A at the origin, e = (a, b), B = (a + c, 0), f = (a, -b)",
                 "the worked body of §§192-200: a long box of half-beam e and draught T heeled by phi while its "
                 "sides stay wall-sided (e tan phi < T and below the deck); e and T between 1/2 and 1, phi < 1/5"),
)

# ---------------------------------------------------------------- regions (SymPy)


def tri(f):
    """∫∫ f(x, y) over the generic figure: the rectangle x_1 <= x <= x_2, y_1 <= y <= y_2, placed
    anywhere (not centred on the origin, so that ∫xy ≠ 0)."""
    return sp.Integral(f, (y, Y1, Y2), (x, X1, X2))


h1, h2 = b * x / a, b * (a + c - x) / c          # half-widths of the quadrilateral of §215


def kite(f, lo=None):
    """∫∫ f over the quadrilateral A e B f (or its upper half when lo == 0)."""
    l1, l2 = (-h1, -h2) if lo is None else (0, 0)
    return (sp.Integral(f, (y, l1, h1), (x, 0, a)) + sp.Integral(f, (y, l2, h2), (x, a, a + c)))


def rect(f, A, B):
    return sp.Integral(f, (y, -B, B), (x, -A, A))


def rhomb(f):
    return (sp.Integral(f, (y, -b * (x + a) / a, b * (x + a) / a), (x, -a, 0))
            + sp.Integral(f, (y, -b * (a - x) / a, b * (a - x) / a), (x, 0, a)))


Yel = b * sp.sqrt(1 - x ** 2 / a ** 2)


rho, th = sp.symbols("rho theta", positive=True)


def ell(f, quadrant=False):
    """∫∫ f over the ellipse (or its quadrant ACE) in elliptic polar coordinates x = a rho cos(theta),
    y = b rho sin(theta), dx dy = a b rho drho dtheta (SymPy integrates these at once; the Cartesian
    form of the print is checked against them in the quote)."""
    g = sp.sympify(f).xreplace({x: a * rho * sp.cos(th), y: b * rho * sp.sin(th)}) * a * b * rho
    return sp.Integral(g, (rho, 0, 1), (th, 0, sp.pi / 2 if quadrant else 2 * sp.pi))


def integral_step(name, S, integral, value, note="", uses=()):
    """S is defined by an integral over the figure, stated with its closed value (factored): the engine
    checks the integral against it, and the value becomes S's for the later steps and readings."""
    return d.step(name, (S, integral, value), "integration", uses=uses, note=note, result=S)


def claim(text):
    return "The paragraph claims: " + text


# ================================================================ §§192–203: stability
d.step("stability-definition", Eq(Slo, Mw * GMlo), "definition", result=Slo,
       note="§194: the stability is the restoring moment divided by the small angle of inclination; the "
            "restoring moment is the weight M times the righting arm GM*phi; here for G at the depth b below B")
d.step("stability-definition-G-above", Eq(Shi, Mw * GMhi), "definition", result=Shi,
       note="the same for G at the height b above B")
d.step("stability-definition-EF", Eq(SKlo, Mw * GKlo), "definition", result=SKlo)
d.step("stability-definition-EF-G-above", Eq(SKhi, Mw * GKhi), "definition", result=SKhi)
d.step("metacentric-height-G-below", Eq(GMlo, Iw / V + h), "lemma",
       uses=("scheeffer-vi-cf:upright-metacentric-height",), result=GMlo,
       note="GM = T/V - e with T the moment of the waterplane about the axis and e the height of G above B; "
            "here e = -b")
d.step("metacentric-height-G-above", Eq(GMhi, Iw / V - h), "lemma",
       uses=("scheeffer-vi-cf:upright-metacentric-height",), result=GMhi, note="e = +b")
d.step("metacentric-height-EF-G-below", Eq(GKlo, Kw / V + h), "lemma",
       uses=("scheeffer-vi-cf:upright-metacentric-height",), result=GKlo,
       note="the same about the latitudinal axis EF, whose waterplane moment is K_w")
d.step("metacentric-height-EF-G-above", Eq(GKhi, Kw / V - h), "lemma",
       uses=("scheeffer-vi-cf:upright-metacentric-height",), result=GKhi)
d.step("strip-moment", (sp.Integral(Pp * w ** 2, (w, -PN, PM)), Pp * (PM ** 3 + PN ** 3) / 3), "integration",
       note="§202: the strip Pp between the ordinates PN (one side of AB) and PM (the other) has the "
            "second moment Pp ∫ w^2 dw about AB")
d.step("strip-moment-one-side", (sp.Integral(Pp * w ** 2, (w, 0, PM)), PM ** 3 * Pp / 3), "integration")
d.step("sum-of-cubes-AB", Eq(Q, 3 * Iw), "definition", uses=("strip-moment",), result=Q,
       note="Q denotes ∫(PM^3 + PN^3)Pp; summing strip-moment over all strips Pp, Q/3 is the second "
            "moment I_w of the waterplane about AB (§202)")
d.step("sum-of-cubes-EF", Eq(Q2, 3 * Kw), "definition", uses=("strip-moment",), result=Q2,
       note="the same with the ordinates QM, QN to EF")

# the quantities §§192-219 name in words (symfloat/model/vocabulary.json), by the formulas that define them:
# the stability about the axis AB (G below B; the sign of b is the sentence's), the moment I of the waterplane
d.defines("stability", Slo)
d.defines("moment", Iw)

d.quote("stability-AB", "§201",
        r"$= M \left(\frac{\int (PM^3 + PN^3) Pp}{3V} \pm b \right)$",
        reading=(sp.Matrix([Slo, Shi]), sp.Matrix([Mw * (Q / (3 * V) + h), Mw * (Q / (3 * V) - h)])),
        note=claim("the stability about the axis AB through the waterplane's centroid is "
                   "M(∫(PM³+PN³)Pp/(3V) ± b), + when the centre of gravity lies below the centre of "
                   "buoyancy. Read as the pair (G below B, G above B); b is written b_{GB}."))
d.quote("stability-EF", "§201",
        r"$= M \left(\frac{\int (QM^3 + QN^3) Qq}{3V} \pm b \right)$",
        reading=(sp.Matrix([SKlo, SKhi]), sp.Matrix([Mw * (Q2 / (3 * V) + h), Mw * (Q2 / (3 * V) - h)])),
        note=claim("the stability about the latitudinal axis EF is the same expression with the ordinates "
                   "QM, QN drawn to EF."))
d.quote("strip-moment", "§202", r"$\frac{PM^3 \cdot Pp}{3}$",
        reading=(sp.Integral(Pp * w ** 2, (w, 0, PM)), PM ** 3 * Pp / 3),
        note=claim("the particle Pp·dw at distance w from AB, times w², integrated up to M, gives PM³·Pp/3, "
                   "so ∫(PM³+PN³)Pp/3 is the sum of the particles times their squared distances from AB."))
VOL = "the volume V of §201 (the transcription writes it v here)"
d.quote("stability-I", "§203", r"$M(\frac{I}{v} + b)$",
        reading=(Slo, Mw * (Iw / V + h)), symbols={"v": (V, VOL)},
        note=claim("with I the moment of the waterplane about the longitudinal axis, the stability about it "
                   "is M(I/V + b). The transcription prints v for V and only the + of §201's ±: read as the "
                   "case of §201 with G below B (b counted positive downwards). A ± lost here was suspected and is "
                   "not booked: both formulas of §203 print the +, the transcription renders §201's ± twice a "
                   "paragraph before (so the scan did not drop it here), and read as §201's case with G below B "
                   "the formula holds; writing one case of §201 restricts the sentence, it does not make it "
                   "false, and the engine does not refute it."))
d.quote("stability-K", "§203", r"$M(\frac{K}{v} + b)$",
        reading=(SKlo, Mw * (Kw / V + h)), symbols={"v": (V, VOL)},
        note=claim("the stability about the latitudinal axis EF is M(K/V + b)."))

# ================================================================ §205–206: oblique axis, generic figure
d.step("cosine", Eq(n, sp.sqrt(1 - m ** 2)), "definition", result=n,
       note="§205: m = sin ACP, n = cos ACP, m^2 + n^2 = 1")
d.step("axis-coordinate-t", Eq(t, sp.Matrix([x, y]).dot(sp.Matrix([n, m]))), "definition", result=t,
       note="t = Cq is the projection of Cw on the axis PQ of direction (n, m)")
d.step("axis-coordinate-u", Eq(u, sp.Matrix([x, y]).dot(sp.Matrix([m, -n]))), "definition", result=u,
       note="u = wq is the signed distance of w from PQ, the projection on the unit normal (m, -n)")
d.step("pythagoras", (t ** 2 + u ** 2, x ** 2 + y ** 2), "algebra", uses=("axis-coordinate-t", "axis-coordinate-u", "cosine"))
d.step("sine-from-coordinates", ((x * u + y * t) / (x ** 2 + y ** 2), m), "algebra", uses=("axis-coordinate-t", "axis-coordinate-u", "cosine"))
d.step("cosine-from-coordinates", ((x * t - y * u) / (x ** 2 + y ** 2), n), "algebra",
       uses=("axis-coordinate-t", "axis-coordinate-u", "cosine"))
d.quote("unit-circle", "§205", r"ita ut sit $m^2 + n^2 = 1$", reading=(m ** 2 + n ** 2, 1),
        note=claim("sine and cosine of the angle ACP satisfy m² + n² = 1 (the whole sine being 1)."))
d.quote("pythagoras", "§205", r"erit tt + uu $= xx + yy$", reading=Eq(t ** 2 + u ** 2, x ** 2 + y ** 2),
        note=claim("the distances of a particle from C measured in either frame agree: t² + u² = x² + y²."))
d.quote("sine", "§205", r"$\frac{xy+yt}{xx+yy} = m$", reading=Eq((x * y + y * t) / (x ** 2 + y ** 2), m),
        erratum=Erratum(
            "transcription", "medium", r"\frac{xu+yt}{xx+yy} = m",
            ("With $t = nx + my$, $u = mx - ny$ (printed next) $x u + y t = m(x^2 + y^2)$, whereas $x y + y t$ is "
             "not $m(x^2 + y^2)$ (counterexample below). The companion formula $(xt - yu)/(xx+yy) = n$ is printed "
             "correctly with $u$; a $u$ read as $y$ by the OCR (the letters are close in the italic of 1749). A "
             "printer's slip cannot be excluded from the transcription alone, hence medium."),
            corrected_reading=Eq((x * u + y * t) / (x ** 2 + y ** 2), m),
                        objection="The y for u may be the print's, a compositor's italic y for u, or Euler's own "
                                  "slip in a line he then solves correctly; nothing shows the scan read it.",
                        answer="The formulas Euler draws from it, u = mx - ny and t = nx + my, satisfy (xu + yt)/(xx"
                               " + yy) = m and not the printed line, and the companion (xt - yu)/(xx + yy) = n is "
                               "printed with u; u and y are close in the italic, a confusion of the scan. The print "
                               "cannot be seen, so medium stands."),
        note=claim("the sine of the angle between the axes is (xu + yt)/(x² + y²)."))
d.quote("cosine", "§205", r"$\frac{xt-yu}{xx+yy} = n$", reading=Eq((x * t - y * u) / (x ** 2 + y ** 2), n),
        note=claim("the cosine of the angle between the axes is (xt − yu)/(x² + y²)."))
d.quote("rotated-coordinates", "§205", r"$u = mx - ny$ et $t = nx + my$",
        reading=Eq(sp.Matrix([u, t]), sp.Matrix([m * x - n * y, n * x + m * y])),
        note=claim("solving these relations gives u = mx − ny and t = nx + my."))

IT, KT, JT, PT, RT = sp.symbols("I_T K_T J_T P_T R_T")
integral_step("generic-I", IT, tri(y ** 2),
              (X1 - X2) * (Y1 - Y2) * (Y1 ** 2 + Y2 ** 2 + Y1 * Y2) / 3,
       note="generic figure (a rectangle off the origin): I = ∫ y^2 w, the moment about the axis AB (y = 0)")
integral_step("generic-K", KT, tri(x ** 2),
              (X1 - X2) * (Y1 - Y2) * (X1 ** 2 + X2 ** 2 + X1 * X2) / 3, note="K = ∫ x^2 w about EF (x = 0)")
integral_step("generic-J", JT, tri(x * y),
              (X1 + X2) * (X1 - X2) * (Y1 + Y2) * (Y1 - Y2) / 4, note="the product integral ∫ xy w")
integral_step("generic-PQ", PT, tri((m * x - n * y) ** 2),
              (X1 - X2) * (Y1 - Y2) * (2 * n ** 2 * Y1 ** 2 + 2 * n ** 2 * Y2 ** 2 + 2 * X1 ** 2 * m ** 2
              + 2 * X2 ** 2 * m ** 2 + 2 * X1 * X2 * m ** 2 + 2 * Y1 * Y2 * n ** 2 - 3 * n * X1 * Y1 * m
              - 3 * n * X1 * Y2 * m - 3 * n * X2 * Y1 * m - 3 * n * X2 * Y2 * m) / 6,
       note="the moment about PQ: ∫ w u^2 with u = mx - ny from axis-coordinates")
integral_step("generic-RS", RT, tri((n * x + m * y) ** 2),
              (X1 - X2) * (Y1 - Y2) * (2 * n ** 2 * X1 ** 2 + 2 * n ** 2 * X2 ** 2 + 2 * Y1 ** 2 * m ** 2
              + 2 * Y2 ** 2 * m ** 2 + 2 * X1 * X2 * n ** 2 + 2 * Y1 * Y2 * m ** 2 + 3 * n * X1 * Y1 * m
              + 3 * n * X1 * Y2 * m + 3 * n * X2 * Y1 * m + 3 * n * X2 * Y2 * m) / 6,
       note="the moment about RS ⟂ PQ: ∫ w t^2")
d.step("generic-PQ-expanded", (PT, m ** 2 * KT + n ** 2 * IT - 2 * m * n * JT), "integration",
       uses=("generic-I", "generic-K", "generic-J", "generic-PQ"))
d.step("generic-RS-expanded", (RT, n ** 2 * KT + m ** 2 * IT + 2 * m * n * JT), "integration",
       uses=("generic-I", "generic-K", "generic-J", "generic-RS"))
d.step("generic-sum", (PT + RT, IT + KT, tri(x ** 2 + y ** 2)), "integration",
       uses=("generic-PQ-expanded", "generic-RS-expanded", "cosine"),
       note="§206: the sum is the polar moment ∫ w·wC^2 about C, independent of the angle")
d.quote("moment-PQ", "§205",
        r"$= \int w \cdot u^2 = \int w (mx - ny)^2 = m^2 \int xx \cdot w + n^2 \int yy \cdot w - 2mn \int xy \cdot w$",
        reading=(PT, tri((m * x - n * y) ** 2), m ** 2 * tri(x * x) + n ** 2 * tri(y * y) - 2 * m * n * tri(x * y)),
        note=claim("the moment about the oblique axis PQ is ∫w·u² = m²∫x²w + n²∫y²w − 2mn∫xyw."))
d.quote("moment-RS", "§205",
        r"$= \int w \cdot t^2 = n^2 \int x^2 \cdot w + m^2 \int y^2 \cdot w + 2mn \int xy \cdot w$",
        reading=(RT, tri((n * x + m * y) ** 2), n ** 2 * tri(x ** 2) + m ** 2 * tri(y ** 2) + 2 * m * n * tri(x * y)),
        note=claim("the moment about the axis RS perpendicular to PQ is n²∫x²w + m²∫y²w + 2mn∫xyw."))
d.quote("moment-PQ-IK", "§206", r"$= n^2 \cdot I + m^2 \cdot K - 2mn \int xy \cdot w$",
        reading=(PT, n ** 2 * IT + m ** 2 * KT - 2 * m * n * JT),
        note=claim("with I = ∫y²w and K = ∫x²w the moment about PQ is n²I + m²K − 2mn∫xyw."))
d.quote("moment-RS-IK", "§206", r"$= m^2 I + n^2 K + 2mn \int yx \cdot w$",
        reading=(RT, m ** 2 * IT + n ** 2 * KT + 2 * m * n * JT),
        note=claim("the moment about RS is m²I + n²K + 2mn∫yxw."))
d.quote("sum-invariant", "§206", r"erit $= I + K$ ob",
        reading=(PT + RT, IT + KT),
        note=claim("the moments about any two perpendicular axes through C add up to I + K, the sum of the "
                   "particles times their squared distances from C."))

# ================================================================ §215–216: the quadrilateral (also the symmetric figure of §207)
Dk, xC, Cc, Ce, Ik, Lk, K, I = sp.symbols("D_q x_C Cc Ce I_q L_q K I")
IAce, IBce, LAce, LBce = sp.symbols("I_{Ace} I_{Bce} L_{Ace} L_{Bce}")
integral_step("quad-area", Dk, kite(1) / 2,
              b * (a + c) / 2, note="2D is the area (§212)")
d.step("quad-area-value", (Dk, (a + c) * b / 2), "integration", uses=("quad-area",))
integral_step("quad-centroid", xC, kite(x) / kite(1),
              sp.Mul(sp.Rational(1, 3), c + 2 * a, evaluate=False),
       note="abscissa of the centroid C measured from A")
d.step("quad-centroid-value", (xC, (2 * a + c) / 3), "integration", uses=("quad-centroid",))
d.step("Cc", Eq(Cc, xC - a), "definition", result=Cc, note="Cc, counted from c towards B")
d.step("Cc-value", (Cc, (c - a) / 3), "algebra", uses=("Cc", "quad-centroid-value"))
d.step("moment-balance", (kite(x - a), 2 * Dk * Cc, c * b * c / 3 - a * b * a / 3), "integration",
       uses=("quad-area", "Cc"),
       note="first moment about ef: the triangle eBf (area Bc·ce, centroid Bc/3 beyond c) minus eAf "
            "(area Ac·ce, centroid Ac/3 before c)")
d.step("Ce", Eq(Ce, sp.sqrt(Cc ** 2 + b ** 2)), "definition", result=Ce,
       note="the distance from C to the vertex e = (a, b)")
d.quote("centroid-equation", "§215",
        r"$AB \cdot ce : Cb = Bc \cdot ce : \frac{1}{3} Bc - Ac \cdot ce : \frac{1}{3} Ac$",
        reading=Eq((a + c) * b / Cc, c * b / (c / 3) - a * b / (a / 3)),
        erratum=Erratum(
            "transcription", "low", r"AB \cdot ce \cdot Cc = Bc \cdot ce \cdot \frac{1}{3} Bc - Ac \cdot ce \cdot \frac{1}{3} Ac",
            r"The balance of first moments about $ef$ (area $AB \cdot ce$ times $Cc$ equals the triangle $eBf$, "
            r"area $Bc \cdot ce$, times $Bc/3$ minus $eAf$ times $Ac/3$) is what the next printed line solves for "
            "$Cc$. Read with "
            "the colons as divisions the print is false (its right side vanishes). The colons are the "
            "multiplication dots of the print read as ':' and 'Cb' is the distance Cc (there is no point b "
            "in Tab. IX fig. 2); low, since the same Cb stands in §218.",
            corrected_reading=Eq((a + c) * b * Cc, c * b * c / 3 - a * b * a / 3),
                        objection="Cb stands again in §218 ('interuallo Cb = (c-a)/3'): the same letter in two "
                                  "paragraphs is the print's, Euler's or the compositor's, not a glyph the scan "
                                  "misread twice; and the ':' may be the print's own sign.",
                        answer="The colons are not the print's: the next line solves the equation as a balance of "
                               "products, and read as divisions its right side vanishes, so they are multiplication "
                               "points read as ':'. But b for c is no confusion of the scan, the text names no point"
                               " b, and §217's rule writes Cc: whether the print had Cb at both places cannot be "
                               "told. Lowered to low."),
        note=claim("the nature of the centroid gives the balance AB·ce·Cc = Bc·ce·Bc/3 − Ac·ce·Ac/3 "
                   "(read with Ac = a, ce = b, Bc = c, AB = a + c)."))
d.quote("centroid", "§215", r"$Ce = \frac{ce(Bc^2 - Ac^2)}{3 AB \cdot ce} = \frac{Bc - Ac}{3}$",
        reading=(Ce, b * (c ** 2 - a ** 2) / (3 * (a + c) * b), (c - a) / 3),
        erratum=Erratum(
            "transcription", "medium", r"Cc = \frac{ce(Bc^2 - Ac^2)}{3 AB \cdot ce} = \frac{Bc - Ac}{3}",
            ("The quantity solved for is the distance Cc between the centroid C and the foot c of the breadth ef "
             r"(§217 ends with $L - 2D \cdot Cc^2$, §218 uses it as the distance of EF from ef). Ce, the distance "
             r"from C to the vertex e, is $\sqrt{Cc^2 + ce^2}$, not $(Bc - Ac)/3$. An italic c read as e, as in $D "
             r"\cdot Ce^2/4$ of §218."),
            corrected_reading=(Cc, b * (c ** 2 - a ** 2) / (3 * (a + c) * b), (c - a) / 3),
                        objection=(r"Ce stands again in §218 ($D \cdot Ce^2/4$), so the letter may be the print's, "
                                   "Euler naming the distance by a letter of the lost fig. 2."),
                        answer=("e is a vertex of the figure ($ce = b$ in §216), and Ce, from C to it, is the square "
                                "root of $Cc^2 + ce^2$, not $(Bc - Ac)/3$, so no lettering of the figure makes the "
                                "print right; §217 names the distance Cc, and c read as e is a confusion of the "
                                "scan. The print cannot be seen: medium.")),
        note=claim("the centroid C lies at the distance Cc = (Bc − Ac)/3 from c, towards the longer part."))

integral_step("quad-I", Ik, kite(y ** 2),
              b ** 3 * (a + c) / 6, note="moment about AB")
integral_step("Ace-I", IAce, sp.Integral(y ** 2, (y, 0, h1), (x, 0, a)),
              a * b ** 3 / 12,
       note="triangle Ace (x from 0 to a, y from 0 to PM = bx/a) about AB")
integral_step("Bce-I", IBce, sp.Integral(y ** 2, (y, 0, h2), (x, a, a + c)),
              c * b ** 3 / 12)
d.step("Ace-I-value", (IAce, sp.Integral(h1 ** 3, (x, 0, a)) / 3, a * b ** 3 / 12), "integration", uses=("Ace-I",))
d.step("Bce-I-value", (IBce, c * b ** 3 / 12), "integration", uses=("Bce-I",))
d.step("quad-I-value", (Ik, 2 * IAce + 2 * IBce, (a + c) * b ** 3 / 6), "integration",
       uses=("quad-I", "Ace-I-value", "Bce-I-value"), note="the halves below AB mirror those above")
integral_step("Ace-L", LAce, sp.Integral((x - a) ** 2, (y, 0, h1), (x, 0, a)),
              b * a ** 3 / 12,
       note="triangle Ace about ef (x = a)")
integral_step("Bce-L", LBce, sp.Integral((x - a) ** 2, (y, 0, h2), (x, a, a + c)),
              b * c ** 3 / 12)
integral_step("quad-L", Lk, kite((x - a) ** 2),
              b * (a + c) * (a ** 2 + c ** 2 - a * c) / 6, note="moment about ef")
d.step("quad-L-value", (Lk, 2 * LAce + 2 * LBce, (a ** 3 + c ** 3) * b / 6, Dk * (a ** 2 - a * c + c ** 2) / 3),
       "integration", uses=("quad-L", "Ace-L", "Bce-L", "quad-area-value"))
Ye = sp.Symbol("y_{AE}")
d.step("edge-AE", Eq(Ye, 0 + (b - 0) * (x - 0) / (a - 0)), "definition", result=Ye,
       note="the side from A = (0, 0) to e (or E) = (a, b) (AP = x from A): two-point form of the line")
d.quote("Ace-edge", "§216", r"$PM = \frac{bx}{a} = y$", reading=(Ye, b * x / a),
        note=claim("in the triangle Ace the ordinate is PM = bx/a."))
d.quote("Ace-cubes", "§216", r"$\int y^2 dx = \frac{ab^3}{4}$",
        reading=(sp.Integral(h1 ** 2, (x, 0, a)), a * b ** 3 / 4),
        erratum=Erratum(
            "transcription", "medium", r"\int y^3 dx = \frac{ab^3}{4}",
            (r"With $y = bx/a$, $\int_0^a y^2 dx = ab^2/3$, while $\int_0^a y^3 dx = ab^3/4$, and a third of it is "
             r"the printed moment $ab^3/12$ of the next line (the moment of a quadrant about AB is $\tfrac13\int y^3 "
             r"dx$, §211). The exponent 3 read as 2, or a misprint of 1749: the transcription cannot tell which, "
             "medium (was low; the printed line itself reads without doubt)."),
            corrected_reading=(sp.Integral(h1 ** 3, (x, 0, a)), a * b ** 3 / 4),
                        objection=("The exponent 2 may be the print's, Euler's pen or the compositor dropping the 3 "
                                   r"of §214's $\int y^3 dx$."),
                        answer=(r"The value $ab^3/4$ and the moment $ab^3/12$ of the next line need $\int y^3 dx$, as "
                                "§214 has it, so the correction is proved, and the printed line reads without doubt. "
                                "A 3 read as 2 and a 3 set as 2 cannot be told apart: the cause stays open, which is "
                                "medium (low is for a reading of the print in doubt, which this is not).")),
        note=claim("for the triangle Ace, with PM = bx/a, ∫y³dx = ab³/4."))
d.quote("Ace-I", "§216", r"$= \frac{ab^3}{12}$", reading=(IAce, a * b ** 3 / 12),
        note=claim("the triangle Ace has the moment ab³/12 about AB."))
d.quote("Bce-I", "§216", r"$Bce = \frac{cb^3}{12}$", reading=(IBce, c * b ** 3 / 12),
        note=claim("the triangle Bce has the moment cb³/12 about AB."))
d.quote("quad-I", "§216", r"$= \frac{ab^3 + cb^3}{6} = \frac{Dbb}{3} = \frac{ef^2 \cdot D}{12}$",
        reading=as_printed(lambda: (Ik, (a * b ** 3 + c * b ** 3) / 6, Dk * b ** 2 / 3, (2 * b) ** 2 * Dk / 12)),
        note=claim("the whole quadrilateral has the moment (ab³ + cb³)/6 = Db²/3 = ef²·D/12 about AB, as the "
                   "rhombus (ef = 2b)."))
d.quote("Ace-L", "§216", r"$= \frac{a^3 b}{12}$", reading=(LAce, a ** 3 * b / 12),
        note=claim("about ef the triangle Ace has the moment a³b/12."))
d.quote("Bce-L", "§216", r"$Bce = \frac{c^3 b}{12}$", reading=(LBce, c ** 3 * b / 12),
        note=claim("about ef the triangle Bce has the moment c³b/12."))
d.quote("quad-L", "§216", r"$= \frac{a^3 b + c^3 b}{6} = \frac{D(ac + bc + cc)}{3}$",
        reading=(Lk, (a ** 3 * b + c ** 3 * b) / 6, Dk * (a * c + b * c + c * c) / 3),
        erratum=Erratum(
            "transcription", "high", r"= \frac{a^3 b + c^3 b}{6} = \frac{D(aa - ac + cc)}{3}",
            ("$(a^3 + c^3) b/6 = (a + c) b (a^2 - ac + c^2)/6 = D(a^2 - ac + c^2)/3$ with $2D = (a + c) b$. §218 "
             "quotes this very result as $D(aa-ac+cc)/3$: the other printing of the same expression is right, so "
             "neither Euler nor his page had it wrong (the criterion of high). '$ac + bc + cc$' is a garbled '$aa - "
             r"ac + cc$': it brings in the letter $b$, which the expression lacks and the line's $a^3 b + c^3 b$ "
             "beside it has, a recognizer's garble of a dense line."),
            corrected_reading=(Lk, (a ** 3 * b + c ** 3 * b) / 6, Dk * (a * a - a * c + c * c) / 3),
                        objection="'ac + bc + cc' differs from 'aa - ac + cc' by a letter and a sign: two changes "
                                  "are more than one glyph the scan confuses, and a compositor may have garbled the "
                                  "line.",
                        answer=("Euler had it right: $(a^3 + c^3)b/6 = D(aa - ac + cc)/3$ with $2D = (a + c)b$, and "
                                "§218 prints the same expression right, which the criteria take as settling the "
                                "cause. A compositor's slip changes a sort, it does not bring a letter of the "
                                r"neighbouring factors ($a^3 b + c^3 b$) into the bracket; that is the garble of a "
                                "recognizer, which reads a line as a whole: high (was low).")),
        note=claim("the whole quadrilateral has the moment (a³b + c³b)/6 = D(a² − ac + c²)/3 about ef."))

# ================================================================ §217: parallel axes (generic figure)
DT, xCT, LT, KTe, Nn = sp.symbols("D_T x_{CT} L_T K_{ET} Nn")
integral_step("generic-area", DT, tri(1) / 2,
              (X1 - X2) * (Y1 - Y2) / 2)
integral_step("generic-centroid", xCT, tri(x) / tri(1),
              sp.Mul(sp.S.Half, X1 + X2, evaluate=False))
integral_step("generic-L", LT, tri((x - xe) ** 2),
              (X1 - X2) * (Y1 - Y2) * (X1 ** 2 + X2 ** 2 + 3 * xe ** 2 + X1 * X2 - 3 * X1 * xe - 3 * X2 * xe) / 3,
       note="moment about a line ef: x = x_e; the distance of a particle is wn = x - x_e")
integral_step("generic-EF", KTe, tri((x - xCT) ** 2),
              (X1 - X2) * (Y1 - Y2) * (X1 ** 2 + X2 ** 2 + 3 * xCT ** 2 + X1 * X2 - 3 * xCT * X1 - 3 * xCT * X2) / 3,
       note="moment about the parallel EF through C: wN = x - x_C")
d.step("axis-distance", Eq(Nn, xe - xCT), "definition", result=Nn, note="wn = wN - Nn")
d.step("first-moment-vanishes", (tri(x - xCT), 0), "integration", uses=("generic-centroid",))
d.step("parallel-axes", (LT, KTe + 2 * DT * Nn ** 2), "integration",
       uses=("generic-L", "generic-EF", "axis-distance", "first-moment-vanishes", "generic-area"))
d.quote("parallel-expansion", "§217",
        r"$w n^2 = \int w \cdot w N^2 - 2Nn \int w \cdot w N + Nn^2 \int w$",
        reading=(LT, tri((x - xCT) ** 2) - 2 * Nn * tri(x - xCT) + Nn ** 2 * tri(1)),
        note=claim("since wn = wN − Nn, ∫w·wn² = ∫w·wN² − 2Nn∫w·wN + Nn²∫w."))
d.quote("first-moment", "§217", "$\\int w \\cdot w N$ utrinque sese de-\n struit fitque $= 0$",
        reading=(tri(x - xCT), 0),
        note=claim("because EF passes through the centroid, ∫w·wN cancels out and is 0."))
d.quote("area-2D", "§217", r"atque $\int w$ abit in aream figurae $= 2D$", reading=(tri(1), 2 * DT),
        note=claim("∫w is the area of the figure, 2D."))
d.quote("parallel-axis-rule", "§217", r"$- 2D \cdot Nn^2 = L - 2D \cdot Cc^2$",
        reading=(KTe, LT - 2 * DT * Nn ** 2, LT - 2 * DT * sp.Abs(xe - xCT) ** 2),
        note=claim("the moment about the axis EF through the centroid is L − 2D·Nn² = L − 2D·Cc², L being the "
                   "moment about the parallel axis ef and Cc their distance (the excerpt continues '= L')."))

# ================================================================ §218: the quadrilateral about EF
integral_step("quad-K", K, kite((x - xC) ** 2),
              b * (a + c) * (c ** 2 + 3 * a ** 2 + 6 * xC ** 2 - 8 * xC * a - 4 * xC * c + 3 * a * c) / 6,
              note="moment about EF through C")
d.step("quad-K-parallel", (K, Lk - 2 * Dk * Cc ** 2), "lemma", uses=("parallel-axes", "quad-L", "Cc"),
       note="§217 applied to the quadrilateral")
d.step("quad-K-value", (K, Dk * (a ** 2 + a * c + c ** 2) / 9), "integration", uses=("quad-K", "quad-area-value"))
d.step("quad-K-excess", (K - Dk * (a + c) ** 2 / 12, Dk * (c - a) ** 2 / 36), "algebra",
       uses=("quad-K-value",),
       note="D·AB^2/12 is the rhombus of the same length AB = a + c and breadth ef = 2b (same D); the excess "
            "D(c-a)^2/36 >= 0 vanishes only for Ac = Bc: Euler's claim of §218 holds")
d.quote("quad-L-again", "§218", r"inuentum sit $= \frac{D(aa-ac+cc)}{3}$",
        reading=(Lk, Dk * (a * a - a * c + c * c) / 3),
        note=claim("the moment about ef was found to be D(a² − ac + c²)/3."))
d.quote("Cc-again", "§218", r"$Cb = \frac{c-a}{3}$",
        unreadable="Cb names no distance of Tab. IX fig. 2: b is the length ce (§216), the figure has no point b",
        erratum=Erratum(
            "transcription", "low", r"Cc = \frac{c-a}{3}",
            ("The distance of the true latitudinal axis EF from ef is Cc, from the centroid C to the foot c of ef: "
             r"$Cc = (Bc - Ac)/3 = (c - a)/3$ (§215), and §217's rule $L - 2D \cdot Cc^2$ is what the paragraph "
             "applies next. The 'Cb' for Cc of the centroid equation of §215, read so by the scan at this place too."),
            corrected_reading=(Cc, (c - a) / 3), same_as="euler-192-219/centroid-equation",
                        objection="As at §215: Cb twice is the print's letter, not the scan's.",
                        answer="The distance of EF from ef is Cc = (c - a)/3 and §217's rule, applied next, writes "
                               "Cc; but which of print and scan put b for c cannot be told, as for the equation of "
                               "§215, whose booking this repeats: low."),
        note=claim("EF lies at the distance Cc = (c − a)/3 from ef."))
d.quote("quad-K", "§218",
        "EF $= \\frac{D(aa-ac+cc)}{3} -$\n $\\frac{2D(c-a)^2}{9} = \\frac{D(aa+ac+cc)}{9} = \\frac{D(a+c)^2}{12} "
        "+ \\frac{D(c-a)^2}{36} = \\frac{D \\cdot AB^2}{12} + \\frac{D \\cdot Ce^2}{4}$",
        reading=(K, Dk * (a * a - a * c + c * c) / 3 - 2 * Dk * (c - a) ** 2 / 9, Dk * (a * a + a * c + c * c) / 9,
                 Dk * (a + c) ** 2 / 12 + Dk * (c - a) ** 2 / 36, Dk * (a + c) ** 2 / 12 + Dk * Ce ** 2 / 4),
        erratum=Erratum(
            "transcription", "medium",
            r"= \frac{D \cdot AB^2}{12} + \frac{D \cdot Cc^2}{4}",
            (r"$D(c-a)^2/36 = D \cdot Cc^2/4$ with $Cc = (c-a)/3$; Ce (C to the vertex e) would add $D \cdot ce^2/4$. "
             "The same c read as e as in the centroid's distance ($Ce = (Bc - Ac)/3$ of §215); all other members are "
             "right."),
            corrected_reading=(K, Dk * (a * a - a * c + c * c) / 3 - 2 * Dk * (c - a) ** 2 / 9,
                               Dk * (a * a + a * c + c * c) / 9, Dk * (a + c) ** 2 / 12 + Dk * (c - a) ** 2 / 36,
                               Dk * (a + c) ** 2 / 12 + Dk * Cc ** 2 / 4), same_as="euler-192-219/centroid",
                        objection="As in §215, Ce may be the print's letter; or Euler may mean the distance to the "
                                  "vertex e.",
                        answer=(r"The member before, $D(c - a)^2/36$, is $D \cdot Cc^2/4$ exactly, and with Ce the "
                                r"last member would add $D \cdot ce^2/4$ to a chain of equal members; the same c read "
                                "as e as in §215, and the print cannot be seen: medium.")),
        note=claim("by the rule of §217 the moment about EF is D(a² + ac + c²)/9 = D·AB²/12 + D·Cc²/4, larger "
                   "than for equal parts Ac = Bc."))

d.quote("quad-K-larger", "§218", "Maius igitur est momentum huius figurae respectu axis\n latitudinalis EF, quam si esset $Ac = Bc$",
        reading=(K - Dk * (a + c) ** 2 / 12, Dk * (c - a) ** 2 / 36),
        note=claim("the moment about EF exceeds that of the figure with Ac = Bc (the rhombus of the same "
                   "length and breadth, D·AB²/12) by D(c − a)²/36 ≥ 0; read as this excess, a square."))

tq, Lq = sp.symbols("t_q L_q", positive=True)        # half the difference of Bc and Ac, half the length AB
d.says("unequal-parts-larger", "§218", "momentum respectu\n axis latitudinalis eo erit maius, quo magis fuerint partes\n"
       " Ac et Bc inter se inaequales.", "momentum",
       GrowsWith(tq, at={Iw: sp.Subs(K, (a, c), (Lq - tq, Lq + tq))},
             domain={tq: (sp.Rational(1, 10), 1), Lq: (sp.Rational(11, 10), 3)}),
       note=claim("among the quadrilaterals of the same length AB = Ac + Bc = 2L and breadth ef, the moment about "
                  "EF grows with the inequality of the parts: with Ac = L - t, Bc = L + t it grows with t (read for "
                  "t > 0, Bc the longer part; the figure is symmetric in the exchange of the parts)."))

# ================================================================ §207–210: symmetric figure (the quadrilateral about C)
PS, RS_, P45 = sp.symbols("P_S R_S P_{45}")
Xc = x - xC
d.step("symmetric-product", (sp.Integral(y, (y, -w ** 2 - 1, w ** 2 + 1)), 0), "integration",
       note="§207: across any chord symmetric about AB (half-width w^2 + 1 > 0 stands for any) ∫ y dy = 0, "
            "so ∫ xy w = 0 for every figure symmetric about AB")
d.step("quad-product", (kite(Xc * y), 0), "integration", uses=("symmetric-product",))
integral_step("sym-PQ", PS, kite((m * Xc - n * y) ** 2),
              b * (a + c) * (n ** 2 * b ** 2 + c ** 2 * m ** 2 + 3 * a ** 2 * m ** 2 + 6 * xC ** 2 * m ** 2
              - 8 * xC * a * m ** 2 - 4 * xC * c * m ** 2 + 3 * a * c * m ** 2) / 6,
       note="moment of the quadrilateral about PQ through C, with u = mX - ny and X = x - x_C")
integral_step("sym-RS", RS_, kite((n * Xc + m * y) ** 2),
              b * (a + c) * (n ** 2 * c ** 2 + b ** 2 * m ** 2 + 3 * n ** 2 * a ** 2 + 6 * xC ** 2 * n ** 2
              - 8 * xC * a * n ** 2 - 4 * xC * c * n ** 2 + 3 * a * c * n ** 2) / 6)
d.step("sym-PQ-value", (PS, n ** 2 * Ik + m ** 2 * K), "integration",
       uses=("sym-PQ", "quad-product", "quad-I", "quad-K", "generic-PQ-expanded"))
d.step("sym-PQ-monotone", (PS, Ik + m ** 2 * (K - Ik), K - n ** 2 * (K - Ik)), "algebra", uses=("sym-PQ-value",),
       note="§209: PQ's moment exceeds I by m^2 (K - I) and falls short of K by n^2 (K - I): for K > I every "
            "axis through C has a moment between I (axis AB, least) and K (axis EF, greatest), increasing "
            "with the angle")
d.step("sym-PQ-derivative", (sp.Derivative(Ik + m ** 2 * (K - Ik), m), 2 * m * (K - Ik)), "algebra")
d.step("equal-moments", (sp.Subs(Ik + m ** 2 * (K - Ik), K, Ik), Ik), "algebra",
       note="§210: I = K makes every axis through C equal")
integral_step("sym-45", P45, kite(((Xc - y) / sp.sqrt(2)) ** 2),
              b * (a + c) * (b ** 2 + c ** 2 + 3 * a ** 2 + 6 * xC ** 2 - 8 * xC * a - 4 * xC * c + 3 * a * c) / 12,
       note="PQ at 45 degrees: m = n = 1/sqrt(2)")
d.step("sym-45-value", (P45, (Ik + K) / 2, kite(((Xc + y) / sp.sqrt(2)) ** 2)), "integration",
       uses=("sym-45", "quad-product"), note="the arithmetic mean, equal to the moment about RS")
d.quote("moment-PQ-symmetric", "§207", r"$= n^2 \cdot I + m^2 \cdot K$,",
        reading=(PS, n ** 2 * Ik + m ** 2 * K),
        note=claim("because a waterplane is symmetric about AB, ∫yxw vanishes and the moment about PQ is "
                   "n²I + m²K (here for the quadrilateral of §215 about its centroid)."))
d.quote("moment-RS-symmetric", "§207", r"$= m^2 \cdot I + n^2 \cdot K$;",
        reading=(RS_, m ** 2 * Ik + n ** 2 * K),
        note=claim("and the moment about RS is m²I + n²K."))
d.quote("moment-PQ-restated", "§207", r"$= n^2 \cdot I + m^2 \cdot K - 2mn \int yx \cdot w$, id ex datis",
        reading=(PT, n ** 2 * IT + m ** 2 * KT - 2 * m * n * JT),
        note=claim("the moment about PQ, n²I + m²K − 2mn∫yxw, is known from I and K once ∫yxw is known "
                   "(restating §206, checked on the generic figure)."))
d.quote("cosine-squared", "§208", r"$nn = 1 - mm$", reading=Eq(n * n, 1 - m * m),
        note=claim("since nn = 1 − mm the moment can be written with m alone."))
d.quote("axis-AB", "§208", r"prodibit momentum respectu eius $= I$ ob $m = 0$",
        reading=(kite((0 * Xc - 1 * y) ** 2), Ik),
        note=claim("for m = 0 (PQ along AB) the moment is I."))
d.quote("axis-EF", "§208", r"ob $m = 1$, fiet momentum eius respectu $= K$",
        reading=(kite((1 * Xc - 0 * y) ** 2), K),
        note=claim("for m = 1 (PQ along EF) the moment is K."))
d.quote("moment-PQ-sine", "§208", r"$= l - m^2 (I - K)$",
        reading=(PS, l - m ** 2 * (Ik - K)),
        erratum=Erratum(
            "transcription", "high", r"= I - m^2 (I - K)",
            ("$n^2 I + m^2 K$ with $n^2 = 1 - m^2$ is $I - m^2 (I - K)$; the print's 'l' is the capital I read as a "
             "lower-case l (the same letter in $(l+K)/2$ below; $m = 0$ gives $I$, as the text says)."),
            corrected_reading=(PS, Ik - m ** 2 * (Ik - K)),
                        objection="A compositor's lower-case l for the capital I is a slip of the print as well; and"
                                  " the same l stands twice in the paragraph, a repeat the criteria give to the "
                                  "print.",
                        answer="In the same formula the I of (I - K) is read right, and the text fixes the letter "
                               "itself: m = 0 gives 'momentum = I', the moment about AB. A capital I at the head of "
                               "a formula read as l is the scan's confusion; two sorts of different letters taken "
                               "twice by a compositor in one paragraph are unlikely. High stands."),
        note=claim("with nn = 1 − mm the moment about PQ is I − m²(I − K): I for m = 0, K for m = 1."))
d.quote("half-right", "§208", r"$m = \frac{1}{\sqrt{2}}$", reading=as_printed(lambda: (sp.sin(sp.pi / 4), 1 / sp.sqrt(2))),
        note=claim("for the semi-right angle the sine is 1/√2."))
d.quote("moment-45", "§208", r"$= \frac{l+K}{2}$", reading=(P45, (l + K) / 2),
        erratum=Erratum(
            "transcription", "high", r"= \frac{I+K}{2}",
            (r"$I - \tfrac12(I - K) = (I + K)/2$, 'the arithmetic mean between the moments about the principal axes' "
             "as the text says; 'l' is the I read as l, as in $l - m^2(I - K)$ above."),
            corrected_reading=(P45, (Ik + K) / 2),
                        objection=("As above: the l may be the compositor's, and it repeats the l of $l - m^2(I - "
                                   "K)$."),
                        answer="The text calls the value the arithmetic mean of the moments about the principal "
                               "axes, which are I and K, and I - (1/2)(I - K) = (I + K)/2; the scan reads the same "
                               "capital I as l at both places, while the print's I stands in (I - K) between them. "
                               "High stands."),
        note=claim("at 45° the moment is (I + K)/2, the arithmetic mean, equal to the moment about RS."))
d.quote("moment-PQ-increasing", "§209", r"$= I + m^2 (K - I)$",
        reading=(PS, Ik + m ** 2 * (K - Ik)),
        note=claim("when K > I the moment about PQ is I + m²(K − I): it grows from I about AB (the least) to K "
                   "about EF (the greatest)."))
d.quote("PQ-exceeds-AB", "§209", "Quare momentum respectu axis obliqui PQ maius est, quam momentum respectu axis "
        "longitudinalis AB; atque hoc momentum continuo crescat, quoad axis PQ in latitudinalem EF incidat.",
        reading=(sp.Matrix([PS - Ik, sp.Derivative(Ik + m ** 2 * (K - Ik), m)]),
                 sp.Matrix([m ** 2 * (K - Ik), 2 * m * (K - Ik)])),
        note=claim("the moment about PQ exceeds I by m²(K − I) and grows with m (derivative 2m(K − I)) until PQ "
                   "falls on EF (m = 1): both positive for K > I and 0 < m ≤ 1."))
d.quote("AB-least-EF-greatest", "§209", "omnium est minimum, momentum vero respectu axis latitudinalis omnium maximum.",
        reading=(sp.Matrix([PS - Ik, K - PS]),
                 sp.Matrix([m ** 2 * (K - Ik), n ** 2 * (K - Ik)])),
        note=claim("I about AB is the least moment and K about EF the greatest: the moment about PQ is I + m²(K − I) "
                   "= K − n²(K − I), n² = 1 − m², both differences non-negative for K > I."))
MOMENT_PQ = n ** 2 * Iw + m ** 2 * Kw          # §207: the moment about PQ of a waterplane symmetric about AB
gm, dK = sp.Symbol("g_m", real=True), sp.Symbol("d_K", positive=True)   # §209: 1 - b/(I/V), K - I
BOTH_STABLE = {Iw: n ** 2 * Iw + m ** 2 * (Iw + dK), h: -(1 - gm) * Iw / V}
d.says("stable-about-every-axis", "§209", "Quodsi ergo nauis habeat stabilitatem respectu axium binorum principalium, "
       "ea respectu omnium omnino axium firmiter in situ aequilibrii persistet", "stabilitatem",
       Compares(">", 0, at=BOTH_STABLE, domain={gm: (sp.Rational(1, 10), 1), dK: (0, 4)}),
       note=claim("a ship stable about both principal axes is stable about every axis through C: G the height "
                  "b = (1 - g)·I/V above B (0 < g ≤ 1, so M(I/V - b) = MgI/V > 0 about AB) and K = I + d ≥ I (§209: "
                  "K > I, so the stability about EF is positive too); about PQ the moment is n²I + m²K (§207) and "
                  "the stability M((n²I + m²K)/V - b) = M(gI + m²d)/V > 0 (read for g ≥ 1/10)."))
d.says("equal-stability-all-axes", "§210", "Quare si nauis eius modi habeat figuram, ut respectu binorum axium "
       "principalium aequa sit stabilis, tum eandem stabilitatem habebit respectu aliis cuiusvis axis horizontalis.",
       "eandem stabilitatem", IndependentOf(m, at={Iw: sp.Subs(MOMENT_PQ, Kw, Iw)}),
       note=claim("a ship equally stable about the two principal axes (the same M, V and b for all axes, so K = I, "
                  "§200) has the same stability about every horizontal axis: the stability M(moment/V + b) about PQ, "
                  "with the moment n²I + m²K of §207 and K = I, does not change with m = sin ACP."))
d.quote("equal-moments-any-figure", "§210", "Eadem vero proprietas locum habebit si sectio aquae fuerit quaecunque "
        "alia figura, dummodo ea ita sit comparaata, ut eius momenta respectu binorum axium principalium sint inter "
        "se aequalia.",
        reading=(sp.Subs(n ** 2 * IT + m ** 2 * KT, KT, IT), IT),
        note=claim("for any figure with equal principal moments (K = I) the moment n²I + m²K about every axis "
                   "through C is I, since n² + m² = 1."))

# ================================================================ §212 square
Dsq, Isq, Ksq, Psq = (symbol(f"{q}_{{sq}}", rf"{q}_{{\text{{square}}}}") for q in "DIKP")
integral_step("square-area", Dsq, rect(1, a, a) / 2,
              2 * a ** 2)
integral_step("square-I", Isq, rect(y ** 2, a, a),
              4 * a ** 4 / 3)
integral_step("square-K", Ksq, rect(x ** 2, a, a),
              4 * a ** 4 / 3)
integral_step("square-PQ", Psq, rect((m * x - n * y) ** 2, a, a),
              4 * a ** 4 * (n ** 2 + m ** 2) / 3)
d.step("square-I-value", (Isq, 4 * sp.Integral(sp.Integral(y ** 2, (y, 0, a)), (x, 0, a)), 4 * a ** 4 / 3),
       "integration", uses=("square-I",), note="four equal quadrants, each (1/3)∫y^3 dx with y = a (§211)")
d.step("square-equal", (Psq, Ksq, Isq), "integration", uses=("square-PQ", "square-K", "square-I", "cosine"),
       note="§210/§212: the square has the same moment about every axis through C")
Iqs, Kqs = sp.symbols("I_{sqq} K_{sqq}")
integral_step("square-quadrant-I", Iqs, sp.Integral(y ** 2, (y, 0, a), (x, 0, a)),
              a ** 4 / 3, note="the quadrant ACE about AB")
integral_step("square-quadrant-K", Kqs, sp.Integral(x ** 2, (y, 0, a), (x, 0, a)),
              a ** 4 / 3, note="the quadrant ACE about EF")
d.quote("square-cubes", "§212", r"$\int y^3 dx = a^4$", reading=(sp.Integral(a ** 3, (x, 0, a)), a ** 4),
        note=claim("for the quadrant of the square (y = a, x from 0 to a) ∫y³dx = a⁴."))
d.quote("square-quadrant-I", "§212", r"$\frac{1}{3} \int y^3 dx = \frac{a^4}{3}$",
        reading=(Iqs, sp.Integral(a ** 3, (x, 0, a)) / 3, a ** 4 / 3),
        note=claim("the quadrant's moment about AB is (1/3)∫y³dx = a⁴/3."))
d.quote("square-quadrant-K", "§212", r"$\int y x^2 dx = \frac{ax^3}{3} = \frac{a^4}{3}$",
        reading=as_printed(lambda: (Kqs, sp.Integral(a * x ** 2, (x, 0, a)),
                 (a * x ** 3 / 3).subs(x, a), a ** 4 / 3)),
        note=claim("the quadrant's moment about EF is ∫yx²dx = ax³/3, at x = a equal to a⁴/3 (the middle "
                   "member read at the end x = a)."))
d.quote("square-I", "§212", r"$= \frac{4a^4}{3} = \frac{AB^4}{12}$",
        reading=as_printed(lambda: (Isq, 4 * a ** 4 / 3, (2 * a) ** 4 / 12)),
        note=claim("the square's moment about AB (AB = 2a) is 4a⁴/3 = AB⁴/12, and so about EF and about every "
                   "axis through C."))
d.quote("square-area", "§212", r"erit $AB^2 = 2D$", reading=Eq((2 * a) ** 2, 2 * Dsq),
        note=claim("the square's area 2D is AB²."))
SQUARE_STABILITY = r"hincque stabilitas respectu cuiusuis axis per C transversantis erit $= \frac{AB^2 \cdot D}{6} =$"
d.says("square-D", "§212", SQUARE_STABILITY, "stabilitas", Is((2 * a) ** 2 * Dsq / 6, at={Iw: Isq}),
       erratum=Erratum("claim", "medium", r"\text{hincque momentum respectu cuiusuis axis per C transversantis erit } "
                       r"= \frac{AB^2 \cdot D}{6}",
                       r"$AB^2 D/6 = 4a^4/3$ is the square's moment about every axis through C, the value of §212's "
                       "'momentum respectu axis AB' two lines before; the stability about such an axis is, by "
                       r"Euler's own definition (§194, §201, §203), $M(\text{moment}/V \pm b)$, which has the weight "
                       r"$M$, the volume $V$ and the distance $b$ in it ($a = 1$, $M = V = 1$, $b = 1/2$: stability "
                       r"$11/6$, moment $4/3$). "
                       "The next sentence goes on with 'in expressionem momenti': the word is the fault, not the "
                       "value.",
                       corrected_reading=d.reads("momentum", Is((2 * a) ** 2 * Dsq / 6, at={Iw: Isq})),
                       fault="hincque stabilitas",
                       objection="Euler may call the moment itself the stability where only ratios between figures "
                                 "matter (M/V and b the same for all axes of one ship), as a measure of it.",
                       answer="Within §§201-203 he keeps the two apart, M(I/V + b) against I, and §212 itself calls "
                              "the same value 'momentum' before and after; a loose use cannot be excluded in a "
                              "text of 1749, hence medium, not high."),
       note="The value is the square's moment about every axis through C.")

d.says("square-equally-stable", "§210", "hincque corpus aquae innatans, cuius sectio aquae est quadratum, secundum "
       "omnes plagas aequa erit stabile, atque aequali vi inclinationibus resistet.",
       "aequa erit stabile", IndependentOf(m, at={Iw: Psq}),
       note=claim("a body whose waterplane is a square is equally stable in every direction: the stability "
                  "M(moment/V + b) with the square's moment about the axis PQ at the angle ACP (sine m), integrated "
                  "over the square, does not change with m."))

# ================================================================ §213 rectangle
Dre, Ire, Kre = (symbol(f"{q}_{{re}}", rf"{q}_{{\text{{rectangle}}}}") for q in "DIK")
integral_step("rect-area", Dre, rect(1, a, b) / 2,
              2 * a * b)
integral_step("rect-I", Ire, rect(y ** 2, a, b),
              4 * a * b ** 3 / 3)
integral_step("rect-K", Kre, rect(x ** 2, a, b),
              4 * b * a ** 3 / 3)
d.step("rect-I-value", (Ire, 4 * sp.Integral(b ** 3, (x, 0, a)) / 3, 4 * a * b ** 3 / 3), "integration",
       uses=("rect-I",))
d.step("rect-ratio", (Ire / Kre, (2 * b) ** 2 / (2 * a) ** 2), "integration", uses=("rect-I", "rect-K"),
       note="§213: I : K = EF^2 : AB^2, inversely as the squares of the axes")
d.quote("rect-area", "§213", r"$2D = 4ab$", reading=Eq(2 * Dre, 4 * a * b),
        note=claim("the rectangle with AC = a, CE = b has the area 2D = 4ab."))
d.quote("rect-cubes", "§213", r"$\int y^3 dx = b^3 x$", reading=(sp.Integral(b ** 3, (s, 0, x)), b ** 3 * x),
        note=claim("with PM = y = b, ∫y³dx = b³x up to the abscissa CP = x."))
d.quote("rect-I", "§213", r"$= \frac{4ab^3}{3} = \frac{2D \cdot bb}{3} = \frac{EF^2 \cdot D}{6}$",
        reading=as_printed(lambda: (Ire, 4 * a * b ** 3 / 3, 2 * Dre * b * b / 3, (2 * b) ** 2 * Dre / 6)),
        note=claim("the rectangle's moment about AB is 4ab³/3 = 2D·b²/3 = EF²·D/6."))
d.quote("rect-K", "§213", r"latitudinalis $= \frac{AB^2 \cdot D}{6}$", reading=(Kre, (2 * a) ** 2 * Dre / 6),
        note=claim("and about EF it is AB²·D/6, so the two moments are inversely as the squares of the axes."))
d.says("rect-inverse-ratio", "§213", "ex quo momentum huius sectionis aquae respectu axis longitudinalis AB se habebit "
       "ad momentum axis latitudinalis EF inuersè vt quadratum axis longitudinalis AB ad quadratum axis "
       "latitudinalis EF.", "momentum huius sectionis aquae respectu axis longitudinalis AB",
       Is(Kre * (2 * b) ** 2 / (2 * a) ** 2, at={Iw: Ire}),
       note=claim("the rectangle's moment about AB is to its moment about EF inversely as AB² to EF²: "
                  "I = K·EF²/AB² (AB = 2a, EF = 2b), the moments integrated over the rectangle."))

# ================================================================ §214 rhombus
Drh, Irh, Krh = (symbol(f"{q}_{{rh}}", rf"{q}_{{\text{{rhombus}}}}") for q in "DIK")
integral_step("rhombus-area", Drh, rhomb(1) / 2,
              a * b)
integral_step("rhombus-I", Irh, rhomb(y ** 2),
              a * b ** 3 / 3)
integral_step("rhombus-K", Krh, rhomb(x ** 2),
              b * a ** 3 / 3)
d.step("rhombus-I-value", (Irh, 4 * sp.Integral((b * s / a) ** 3, (s, 0, a)) / 3, a * b ** 3 / 3), "integration",
       uses=("rhombus-I",), note="four quadrants, AP = s from the vertex A, PM = bs/a")
d.step("rhombus-quarter-of-rectangle", (Ire / Irh, Kre / Krh, 4), "integration",
       uses=("rect-I", "rect-K", "rhombus-I", "rhombus-K"),
       note="with the same length AB = 2a and breadth EF = 2b the rectangle's moments are four times the "
            "rhombus' (its area 2D is also twice as large)")
d.step("rhombus-half-at-equal-area", (as_printed(lambda: (2 * b) ** 2 * sp.Symbol("D") / 6 / ((2 * b) ** 2 * sp.Symbol("D") / 12)),
                                       2),
       "algebra", note="the factor 2 holds between EF^2 D/6 and EF^2 D/12 at the same D, i.e. for the same "
                       "length, breadth and area, which the two figures cannot share")
d.quote("rhombus-edge", "§214", r"erit $y = \frac{bx}{a}$", reading=(Ye, b * x / a),
        note=claim("on the side AE, with AP = x, the ordinate is PM = y = bx/a."))
d.quote("rhombus-area", "§214", r"area $2D = 2ab$", reading=Eq(2 * Drh, 2 * a * b),
        note=claim("the rhombus with diagonals 2a, 2b has the area 2D = 2ab."))
d.quote("rhombus-cubes", "§214", r"$\int y^3 dx = \frac{b^3}{a^3} \int x^3 dx = \frac{b^3 x^4}{4a^3}$",
        reading=(sp.Integral((b * s / a) ** 3, (s, 0, x)), b ** 3 / a ** 3 * sp.Integral(s ** 3, (s, 0, x)),
                 b ** 3 * x ** 4 / (4 * a ** 3)),
        note=claim("with y = bx/a (AP = x from A), ∫y³dx = b³x⁴/(4a³)."))
d.quote("rhombus-I", "§214", r"AB $= \frac{ab^3}{3} = \frac{D \cdot bb}{3} = \frac{EF^2 \cdot D}{12}$",
        reading=as_printed(lambda: (Irh, a * b ** 3 / 3, Drh * b * b / 3, (2 * b) ** 2 * Drh / 12)),
        note=claim("the rhombus' moment about AB is ab³/3 = D·b²/3 = EF²·D/12."))
d.quote("rhombus-twice", "§214",
        "Manentibus igitur eadem longitudine ac latitudine, momenta parallelogrammi rectanguli duplo sunt "
        "maiora quam rhombi.",
        reading=Eq(sp.Matrix([Ire / Irh, Kre / Krh]), sp.Matrix([2, 2])),
        erratum=Erratum(
            "claim", "medium",
            "With the same length AB and breadth EF the moments of the rectangle are four times those of "
            "the rhombus ($4ab^3/3$ against $ab^3/3$); the factor two (divisor $6$ against $12$) holds only at "
            "equal area $2D$, which a rectangle and a rhombus of the same length and breadth do not have "
            "($4ab$ against $2ab$).",
            (r"Integrating over both figures with $AC = a$, $CE = b$: $I_{\text{rect}} = 4ab^3/3$, $I_{\text{rhomb}} "
             r"= ab^3/3$, $K_{\text{rect}} = 4a^3b/3$, $K_{\text{rhomb}} = a^3b/3$. Euler compared the coefficients "
             "of $EF^2 D$ and $AB^2 D$ and forgot that $D$ itself doubles; a wrong conclusion, not a misprint."),
            corrected_reading=Eq(sp.Matrix([Ire / Irh, Kre / Krh]), sp.Matrix([4, 4])),
                        objection="Euler compares the formulas, as he says ('hic diuisum erat per 6, hic vero per "
                                  "12') and again in §219 ('excepto solo denominatore'), and §212 puts the area into"
                                  " the moment so that it can be divided by the displaced volume: per unit of area, "
                                  "which is what enters the stability, the rectangle's moment is indeed twice the "
                                  "rhombus's at the same length and breadth.",
                        answer=("The sentence says 'momenta' and keeps the length and the breadth, not the area, and "
                                "on Euler's own values ($4ab^3/3$ in §213, $ab^3/3$ in §214) the moments are in the "
                                "ratio four; the factor two needs the same area $2D$, which the two figures do not "
                                "have ($4ab$ against $2ab$). The reading per unit of area is left as one "
                                r"alternative: high $\to$ medium.")),
        note=claim("keeping the same length and breadth, the rectangle's moments are twice the rhombus'."))
d.quote("rhombus-K", "§214", r"EF erit $= \frac{AB^2 \cdot D}{12}$", reading=(Krh, (2 * a) ** 2 * Drh / 12),
        note=claim("about EF it is AB²·D/12: the denominators 12 instead of the rectangle's 6."))

# ================================================================ §219 ellipse
Del, Iel, Kel, Yq = (symbol(f"{q}_{{el}}", rf"{q}_{{\text{{ellipse}}}}") for q in "DIKY")
Kq, Aq = (symbol(f"{q}_{{qu}}", rf"{q}_{{\text{{quadrant}}}}") for q in "KA")
d.step("ellipse-ordinate", Eq(Yq, Yel), "definition", result=Yq, note="PM = y on the ellipse")
d.step("ellipse-equation", (x ** 2 / a ** 2 + Yq ** 2 / b ** 2, 1), "algebra", uses=("ellipse-ordinate",))
integral_step("ellipse-area", Del, ell(1) / 2,
              sp.pi * a * b / 2)
d.step("ellipse-area-value", (Del, sp.pi * a * b / 2), "integration", uses=("ellipse-area",))
integral_step("ellipse-quadrant-K", Kq, ell(x ** 2, quadrant=True),
              sp.pi * b * a ** 3 / 16)
integral_step("ellipse-quadrant-area", Aq, ell(1, quadrant=True),
              sp.pi * a * b / 4)
integral_step("ellipse-K", Kel, ell(x ** 2),
              sp.pi * b * a ** 3 / 4)
integral_step("ellipse-I", Iel, ell(y ** 2),
              sp.pi * a * b ** 3 / 4)
d.step("ellipse-K-quadrants", (Kel, 4 * Kq, sp.pi * a ** 3 * b / 4), "integration",
       uses=("ellipse-K", "ellipse-quadrant-K"))
d.step("ellipse-I-value", (Iel, sp.pi * a * b ** 3 / 4), "integration", uses=("ellipse-I",))
d.quote("ellipse-ordinate", "§219", r"$y = b \sqrt{1 - \frac{x^2}{a^2}}$", reading=(Yq, b * sp.sqrt(1 - x ** 2 / a ** 2)),
        note=claim("the ellipse with semi-axes AC = a, CE = b has the ordinate y = b√(1 − x²/a²)."))
d.quote("ellipse-quadrant-K", "§219",
        r"$\int b x x dx \sqrt{1 - \frac{x^2}{a^2}} = \frac{a^2 b}{4} \int dx \sqrt{1 - \frac{x^2}{a^2}}$",
        reading=(sp.Integral(b * x * x * sp.sqrt(1 - x ** 2 / a ** 2), (x, 0, a)),
                 a ** 2 * b / 4 * sp.Integral(sp.sqrt(1 - x ** 2 / a ** 2), (x, 0, a))),
        note=claim("the quadrant ACE has the moment ∫bx²√(1 − x²/a²)dx = (a²b/4)∫√(1 − x²/a²)dx about CE "
                   "(integrals from 0 to a)."))
d.quote("ellipse-quadrant-area", "§219", r"elliptici ACE = $\frac{\pi}{4}$", reading=(Aq, sp.pi / 4),
        erratum=Erratum(
            "transcription", "low", r"= \frac{\pi ab}{4} = \frac{D}{2}",
            (r"$b\int_0^a \sqrt{1 - x^2/a^2}\, dx = \pi ab/4$ is the quadrant's area; the next line (moment $a^2 D/8 "
             r"= (a^2/4)(D/2)$) uses the quadrant area $D/2 = \pi ab/4$. The factor $ab$ (or the $D/2$ Euler may have "
             "written) is missing from the transcription; what the print had cannot be told, low."),
            corrected_reading=(Aq, sp.pi * a * b / 4, Del / 2),
                        objection=r"$\pi/4$ may be what Euler printed, the quadrant of a unit circle, or with the "
                                  "factor $ab$ written on the line before.",
                        answer=("The sentence names the area of the elliptic quadrant ACE, and the next member "
                                r"$a^2D/8 = (a^2/4)(D/2)$ uses it as $\pi ab/4 = D/2$, so the factor is needed; "
                                "whether the print or the scan lost it cannot be told: low stands.")),
        note=claim("b∫dx√(1 − x²/a²) is the area of the elliptic quadrant ACE, πab/4 = D/2."))
d.quote("ellipse-quadrant-moment", "§219", r"erit = $\frac{a^2 D}{8}$", reading=(Kq, a ** 2 * Del / 8),
        note=claim("hence the quadrant's moment about EF is a²D/8."))
d.quote("ellipse-K", "§219", r"ellipsis = $\frac{AB^2 D}{8}$", reading=(Kel, (2 * a) ** 2 * Del / 8),
        note=claim("and the whole ellipse's is AB²D/8."))
d.quote("ellipse-I", "§219", r"fore = $\frac{EF^2 D}{8}$", reading=(Iel, (2 * b) ** 2 * Del / 8),
        note=claim("likewise about AB the moment is EF²D/8: the denominator is 6 for the rectangle, 12 for "
                   "the rhombus, 8 for the ellipse."))

# ---- second pass: spans of the review quoted ------------------------------------------------------------------
d.quote("I-K-definitions", "§206", r"erit $\int y^2 \cdot w = I$ et $\int x^2 \cdot w = K$",
        reading=(sp.Matrix([tri(y ** 2), tri(x ** 2)]), sp.Matrix([IT, KT])),
        note=claim("I = ∫y²w and K = ∫x²w are the moments about AB and EF (read on the generic rectangle)."))
d.quote("polar-sum", "§206",
        r"Quare pro eadem sectione aquae summa duorum momentum respectu axium inter se normalium semper est constans",
        reading=(PT + RT, tri(x ** 2 + y ** 2)),
        note=claim("the moments about two perpendicular axes through C add up to ∫w·wC², whatever the angle."))
d.quote("xy-vanishes", "§207", r"Cum ergo totalis valor formulae $\int yx \cdot w$ evanescat",
        reading=(kite(x * y), 0),
        note=claim("∫yx·w vanishes for a waterplane symmetric about AB (read on the quadrilateral of §215)."))
d.quote("equal-moments-all-axes", "§210", r"tum eidem momento aequalia erunt momenta respectu omnium axium obliquorum",
        reading=(sp.Subs(n ** 2 * Iw + m ** 2 * Kw, Kw, Iw), Iw),
        note=claim("if K = I the moment n²I + m²K about every oblique axis (§207) equals I."))
d.quote("square-all-axes", "§210",
        r"Si ergo sectio aquae fuerit quadratum AEBF, quia momenta eius respectu axium AB et EF inter se sunt "
        r"aequalia, momenta quoque respectu omnium omnino axium per C transversantium erunt aequalia",
        reading=(Psq, Ksq, Isq), note=claim("the square has the same moment about every axis through C."))
d.quote("strip-sum-of-squares", "§202",
        r"omnino congruere cum ea, quae prodit, si singulæ sectionis aquæ particulae multiplicentur per quadrata "
        r"distantiarum ab axe AB",
        reading=(sp.Integral(Pp * w ** 2, (w, -PN, PM)), (PM ** 3 + PN ** 3) * Pp / 3),
        note=claim("for the strip Pp between N and M the particles times their squared distances from AB sum to "
                   "(PM³ + PN³)Pp/3."))
d.quote("quadrants-cancel", "§207",
        r"Hinc igitur valor ipsius $\int yx \cdot w$, qui ex parte ACF oritur aequalis erit et negatus illius "
        r"valoris, quem portio ACE praebet",
        reading=(kite(x * y) - kite(x * y, lo=0), -kite(x * y, lo=0)),
        note=claim("∫yx·w over the lower half equals minus that over the upper half (read on the quadrilateral "
                   "of §215, the halves below and above AB)."))
d.quote("quad-area-2D", "§216", r"posito $2D$ pro area totius sectionis aquae",
        reading=(2 * Dk, (a + c) * b), note=claim("the quadrilateral's area is 2D = (Ac + Bc)·ce."))
d.quote("quadrant-area-integral", "§219",
        r"At $b \int dx \sqrt{1 - \frac{x^2}{a^2}}$ exprimit aream quadrantis",
        reading=(b * sp.Integral(sp.sqrt(1 - x ** 2 / a ** 2), (x, 0, a)), Aq),
        note=claim("b∫dx√(1 − x²/a²) over 0 ≤ x ≤ a is the area of the elliptic quadrant ACE."))
d.quote("L-definition", "§217", r"tum ponitur scilicet $L = \int w \cdot w n^2$", reading=(LT, tri((x - xe) ** 2)),
        note=claim("L, the moment about ef, is ∫w·wn², wn the distance of the particle from ef (read on the "
                   "generic rectangle, ef at x = x_e)."))
d.quote("EF-moment-definition", "§217", r"ctu axis EF quod quaeritur $= \int w \cdot w N^2$",
        reading=(KTe, tri((x - xCT) ** 2)),
        note=claim("the moment about EF through the centroid is ∫w·wN², wN the distance from EF."))
d.quote("sum-of-cubes", "§201", r"valor huius expressionis $\int (PM^3 + PN^3) Pp$",
        reading=((PM ** 3 + PN ** 3) * Pp, 3 * sp.Integral(Pp * w ** 2, (w, -PN, PM))),
        note=claim("the expression to be integrated is three times the second moment about AB (read for one "
                   "strip Pp between N and M)."))
d.quote("aggregate", "§202", r"ex quo manifestum est $\int \frac{(PM^3 + PN^3)Pp}{3}$ denotari aggregatum",
        reading=((PM ** 3 + PN ** 3) * Pp / 3, sp.Integral(Pp * w ** 2, (w, -PN, PM))),
        note=claim("∫(PM³ + PN³)Pp/3 is the aggregate of the particles times their squared distances from AB "
                   "(read for one strip)."))
d.quote("equal-quadrants", "§211", r"quod momenta cum quadrantum ACE et ACF, tum quadrantum BCE et BCF sint aequalia",
        reading=(kite(y ** 2, lo=0), kite(y ** 2) - kite(y ** 2, lo=0)),
        note=claim("the parts above and below AB have the same moment about AB (read on the quadrilateral of "
                   "§215, whose halves are mirror images)."))

# ================================================================ §§192–200 in words, on a worked body
# A long box of half-beam e and draught T (per unit length), G at the height b above the upright centre of
# buoyancy, heeled by phi while wall-sided: the immersed section lies between the bottom y = -T and the
# waterline y = x tan(phi) through the middle (the area 2eT is kept).  The righting arm GZ is the distance
# of B from G along the waterline; nothing of M(I/V - b) is used to build it.
Ah, xBh, yBh, GZ = sp.symbols("A_phi x_B y_B GZ")
tp = sp.tan(phi)
d.step("heeled-area", (Ah, sp.Integral(x * tp + Tb, (x, -eb, eb)), 2 * eb * Tb), "integration", result=Ah,
       note="the heeled section of the box: the waterline through the middle keeps the area 2eT")
d.step("heeled-xB", (xBh, sp.Integral(x * (x * tp + Tb), (x, -eb, eb)) / Ah, eb ** 2 * tp / (3 * Tb)),
       "integration", uses=("heeled-area",), result=xBh)
d.step("heeled-yB", (yBh, sp.Integral(((x * tp) ** 2 - Tb ** 2) / 2, (x, -eb, eb)) / Ah,
                     eb ** 2 * tp ** 2 / (6 * Tb) - Tb / 2), "integration", uses=("heeled-area",), result=yBh)
d.step("righting-arm", Eq(GZ, xBh * sp.cos(phi) + (yBh - (h - Tb / 2)) * sp.sin(phi)), "definition", result=GZ,
       note="GZ: B minus G along the waterline (cos phi, sin phi) of the body's frame, G = (0, -T/2 + b); "
            "positive GZ turns the body back")
d.step("righting-arm-value", (xBh * sp.cos(phi) + (yBh - (h - Tb / 2)) * sp.sin(phi), sp.sin(phi) * (eb ** 2 / (3 * Tb) - h + eb ** 2 * tp ** 2 / (6 * Tb))), "algebra",
       uses=("righting-arm", "heeled-xB", "heeled-yB"), result=GZ)
I_box, V_box = sp.Integral(x ** 2, (x, -eb, eb)), 2 * eb * Tb      # the box's waterplane moment and volume
S_box = sp.Subs(Shi, (Iw, V), (I_box, V_box))                       # §201's M(I/V - b) for the box
d.quote("same-vertical", "§192",
        r"si centrum grauitatis totius nauis et centrum magnitudinis partis submersae in eandem rectam "
        r"verticalem cadant", reading=(sp.Matrix([sp.Subs(xBh, phi, 0), sp.Subs(GZ, phi, 0)]), sp.zeros(2, 1)),
        note=claim("a floating body is in equilibrium when G and B lie on one vertical: upright, the box's B lies "
                   "on the middle line with G and the arm GZ of the couple (weight at G, buoyancy at B) is 0."))
d.quote("more-stable-less-heel", "§192",
        r"Quo enim stabilitas est maior eo minus nauis a viribus urgentibus inclinabitur",
        reading=(sp.Derivative(Qh / St, St), -Qh / St ** 2),
        note=claim("the greater the stability S, the smaller the heel a moment Q produces: by §194 the small heel "
                   "is Q/S, whose derivative in S is -Q/S² < 0."))
d.quote("moment-times-angle", "§194",
        r"Prodiit autem eiusmodi expressio, quae per angulum illum infinite paruum, quo nauem ex situ aequilibrii "
        r"inclinatam fuisse assumpsimus, erat multiplicata",
        reading=(sp.Limit(Mw * GZ / phi, phi, 0), S_box, Mw * (I_box / V_box - h)),
        note=claim("the restoring moment M·GZ is the small angle times an expression, the stability: for the "
                   "heeled box M·GZ/phi tends to M(I/V - b) of §201 (I = 2e³/3, V = 2eT)."))
d.quote("small-angles-only", "§194", r"manifestum est angulos tantum valde exiguos assumi debere",
        reading=(sp.Limit((Mw * GZ - phi * S_box) / phi ** 3, phi, 0), Mw * (eb ** 2 / (9 * Tb) + h / 6)),
        note=claim("S·phi gives the moment only for very small angles: for the box M·GZ - S·phi is "
                   "M(e²/(9T) + b/6)·phi³ + O(phi⁵), not zero (positive: the box rights more than S·phi)."))
d.quote("same-ratio", "§195",
        r"Perspicuum enim est quo maior sit ista expressio, eo quoque fore maiorem stabilitatem, et quidem in "
        r"eadem ratione",
        reading=(sp.Limit(sp.Subs(GZ, h, hb1) / sp.Subs(GZ, h, hb2), phi, 0),
                 sp.Subs(S_box, h, hb1) / sp.Subs(S_box, h, hb2), (I_box / V_box - hb1) / (I_box / V_box - hb2)),
        note=claim("the moments that produce an equal small heel in two states are in the ratio of their "
                   "expressions: the box with G at b_1 and at b_2 above B."))
S0_h = I_box / V_box                                                # the height b where the expression vanishes
d.quote("zero-indifferent", "§195",
        r"Quodsi ergo expressio stabilitatis evanescat, id indicio erit, situm aequilibrii esse indifferentem",
        reading=(sp.Matrix([sp.Limit(sp.Subs(GZ, h, S0_h) / phi, phi, 0), sp.Limit(sp.Subs(GZ, h, S0_h) / phi ** 3, phi, 0)]),
                 sp.Matrix([0, eb ** 2 / (6 * Tb)])),
        note=claim("a vanishing expression means an indifferent equilibrium: the box with b = I/V has no righting "
                   "arm to first order in phi (first entry), the order at which §194 defines the stability. The "
                   "second entry shows what that order hides: this box still rights with GZ = (e²/(6T))·phi³ + …, "
                   "so 'neque restitutio neque subversio' holds for the linear expression, not for the body at a "
                   "finite angle. Not booked: Euler states the criterion for infinitely small angles (§194)."))
h_neg = S0_h + gneg                                                 # G the height g above the metacentre
GZ_neg = sp.Subs(GZ, h, h_neg)
phi0 = sp.atan(sp.sqrt(2 * gneg / S0_h))
d.quote("negative-unstable", "§195",
        r"Sin autem expressio stabilitatis fiat negativa, tum situs aequilibrii adeo erit instabilis, seu labilis, "
        r"atque vel minima facta inclinatione non solum non restituetur sed etiam conuertetur, donec nauis in aliud "
        r"aequilibrii situm qui stabilitate praeditus sit, fuerit reducta",
        reading=(sp.Matrix([sp.Limit(Mw * GZ_neg / phi, phi, 0), sp.Subs(GZ_neg, phi, phi0),
                            sp.Subs(sp.Derivative(GZ_neg, phi), phi, phi0)]),
                 sp.Matrix([-Mw * gneg, 0, 2 * gneg * sp.sqrt(1 + 6 * Tb * gneg / eb ** 2)])),
        note=claim("a negative expression means an unstable upright position, and the body turns until it reaches "
                   "another, stable, equilibrium: the box with G the height g above the metacentre has the "
                   "stability -Mg < 0; its arm vanishes again at tan²phi₀ = 2g/(I/V) and grows through it "
                   "(dGZ/dphi = 2g√(1 + 6Tg/e²) > 0): a stable heeled position. The box stays wall-sided there "
                   "(e tan phi₀ = √(6gT) < T for g ≤ 1/100)."))
BOX_IK = {Iw: 2 * sp.Integral(x ** 2, (x, -sp.Rational(1, 2), sp.Rational(1, 2))),
          Kw: sp.Integral(x ** 2, (x, -1, 1))}                       # the box 1 x 1 x 2: waterplane 1 wide, 2 long
d.quote("stable-one-way", "§196", r"atque adeo ut datus aequilibrii situs in alias plagas sit stabilis",
        reading=(sp.Matrix([sp.Subs(Shi, (Mw, Iw, V, h), (1, BOX_IK[Iw], 1, sp.Rational(1, 3))),
                            sp.Subs(SKhi, (Mw, Kw, V, h), (1, BOX_IK[Kw], 1, sp.Rational(1, 3)))]),
                 sp.Matrix([-sp.Rational(1, 6), sp.Rational(1, 3)])),
        note=claim("one equilibrium can be stable about one axis and unstable about another: the box 1 × 1 × 2 "
                   "floating half immersed (V = 1, M = 1) with G 1/3 above B has the stability -1/6 about the long "
                   "axis AB and +1/3 about the cross axis EF."))
d.quote("pitch-exceeds-roll", "§196",
        r"Sic facile perspicitur naues inclinationi versus proram seu puppim magis resistere",
        reading=(sp.Subs(SKhi - Shi, (Iw, Kw), (Ire, Kre)), Mw * 4 * a * b * (a ** 2 - b ** 2) / (3 * V)),
        note=claim("a ship resists pitching more than rolling: with the rectangular waterplane of §213 (2a long "
                   "along AB, 2b wide) the stability about EF exceeds that about AB by 4Mab(a² - b²)/(3V), "
                   "positive for a > b."))
d.quote("two-axes-suffice", "§199", r"nunc ad quaestione bipartitam est reducta",
        reading=(Mw * (((1 - m ** 2) * Iw + m ** 2 * Kw) / V - h), (1 - m ** 2) * Shi + m ** 2 * SKhi),
        note=claim("the stabilities about the two principal axes suffice: with the moment n²I + m²K about an axis "
                   "PQ at the angle ACP (§207, n² = 1 - m²), the stability about PQ is n²·S_AB + m²·S_EF."))
d.quote("only-waterplane", "§200", r"Harum quatuor rerum tres priores aequaliter ingrediuntur",
        reading=(SKhi - Shi, Mw * (Kw - Iw) / V),
        note=claim("weight, volume and the distance b enter alike for every axis; only the waterplane's moment "
                   "depends on it: the stabilities about EF and AB differ by M(K - I)/V, free of b."))
d.quote("mirror-quarters", "§207",
        r"tam binae priores ACE et ACF quam posteriores BCE et BCF interf erunt similes et aequales",
        reading=(sp.Matrix([sp.Integral(1, (y, 0, h1), (x, 0, a)), sp.Integral(1, (y, 0, h2), (x, a, a + c))]),
                 sp.Matrix([sp.Integral(1, (y, -h1, 0), (x, 0, a)), sp.Integral(1, (y, -h2, 0), (x, a, a + c))])),
        note=claim("the parts of a waterplane on either side of AB are mirror images, so the fore parts ACE, ACF "
                   "and the aft parts BCE, BCF are equal: read on the quadrilateral of §215, split at ef (the "
                   "mirror argument is the same for any split across AB, EF included); 'interf' is inter se."))
Krh_half = sp.Subs(rhomb(x ** 2), a, (a + c) / 2)                    # the rhombus with the same AB = a + c and ef
d.quote("unlike-parts-larger", "§220",
        "maiora habere momenta, quam\neas, quae constant partibus similibus, seu rhombos cete-\nris paribus",
        reading=(K - Krh_half, Dk * (c - a) ** 2 / 36),
        note=claim("§220 recalls §218: a quadrilateral whose parts fore and aft of the latitudinal axis differ has "
                   "a greater moment about EF than the rhombus of the same length and breadth (so the same area): the "
                   "excess of ∫∫(x - x_C)² over the rhombus' ∫∫x² is D(c - a)²/36 ≥ 0."))
