"""What the end of Graefe's §4 says and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import Derivation, Eq, Erratum
from symfloat.model.claim import as_printed
from symfloat.model.vocabulary import Is

from ..graefe_s1_prismatoid_volume.statements import DERIVATION as PRISMATOID_VOLUME
from ..graefe_s3_prismatoid_centroid.statements import DERIVATION as PRISMATOID_CENTROID

G, g, D, h, z = sp.symbols("G g D h z", positive=True)
a, b, c, dd, e, f, m = sp.symbols("a b c d e f m", positive=True)
k = sp.symbols("k_0:3", real=True)
Xp, Vp = sp.symbols("X V_P", positive=True)                    # the prismatoid of §1/§3
x1, x2, x3 = sp.symbols("x' x'' x'''", positive=True)        # slab centroids from ABC
x2l, x3l = sp.symbols("xi'' xi'''", positive=True)            # the same from the planes c and e
v1, v2, v3 = sp.symbols("v' v'' v'''", positive=True)
M1, M2, M3 = sp.symbols("m' m'' m'''", positive=True)         # the moments (print: m', m'', m''')
M, V, XS = sp.symbols("M V x", positive=True)                 # the whole body: moment, volume, centroid


# the prismatoid's centroid X = h (g/2 + D) / ((G + g)/2 + 2D) above G (§3) and volume V = h/3 ((G + g)/2 + 2D) (§1)
# at given (G, g, D, h): the readings of their prints
centroid = PRISMATOID_CENTROID.evaluator("centroid", (G, g, D, h), 1)
volume = PRISMATOID_VOLUME.evaluator("prismatoid-volume", (G, g, D, h), 1)


DERIVATION = d = Derivation(
    id="graefe-s4-ship-centroid",
    source="graefe",
    title="The centroid of a ship's displacement from equidistant sections",
    locator="§4 ship displacement centroid",
    summary="Centroids and volumes of three prismatoid slabs, their moments about the first section, "
            "and x = m (0a + 4b + 4c + 12d + 8e + 20f + 6g)/(a + 4b + 2c + 4d + 2e + 4f + g) "
            "(printed with m/3).",
    requires=("graefe-s2-volumes-simpson", "graefe-s3-prismatoid-centroid"),
    domain={**{s: (1, 20) for s in (G, g, D, h, a, b, c, dd, e, f, m)}, **{s: (-3, 3) for s in k}},
    assumptions=("the section areas a, …, g are positive, at spacing m",
                 "each pair of slabs is a prismatoid (exactly so when the section area is a quadratic "
                 "polynomial of the distance on it)"),
)

# ---- the prismatoid formulas applied -----------------------------------------------------
d.step("prismatoid-centroid", Eq(Xp, centroid(G, g, D, h)), "lemma",
       uses=("graefe-s3-prismatoid-centroid:centroid-collected",), result=Xp)
d.step("prismatoid-volume", Eq(Vp, volume(G, g, D, h)), "lemma",
       uses=("graefe-s1-prismatoid-volume:volume-collected",), result=Vp)

# first slab, a to c
d.step("x1", Eq(x1, centroid(a, c, b, 2 * m)), "lemma", uses=("prismatoid-centroid",), result=x1,
       note="G = a, D = b, g = c, h = 2m")
d.step("v1", Eq(v1, volume(a, c, b, 2 * m)), "lemma", uses=("prismatoid-volume",), result=v1)
d.step("m1", Eq(M1, x1 * v1), "definition", uses=("x1", "v1"), result=M1,
       note="moment of the slab about the plane ABC")
d.step("m1-value", (M1, 4 * m ** 2 / 3 * (c / 2 + b)), "algebra", uses=("m1",))

# second slab, c to e
d.step("x2-local", Eq(x2l, centroid(c, e, dd, 2 * m)), "lemma", uses=("prismatoid-centroid",), result=x2l,
       note="distance from the plane c: G = c, D = d, g = e, h = 2m")
d.step("x2", Eq(x2, 2 * m + x2l), "definition", uses=("x2-local",), result=x2,
       note="the plane c lies 2m from ABC")
x2_b = 2 * m * (((c + e) / 2 + 2 * dd + e / 2 + dd) / ((c + e) / 2 + 2 * dd))
d.step("x2-value", (x2, x2_b), "algebra", uses=("x2",))
d.step("v2", Eq(v2, volume(c, e, dd, 2 * m)), "lemma", uses=("prismatoid-volume",), result=v2)
d.step("m2", Eq(M2, x2 * v2), "definition", uses=("x2", "v2"), result=M2)
m2_v = 4 * m ** 2 / 3 * ((c + e) / 2 + 2 * dd + e / 2 + dd)
d.step("m2-value", (M2, m2_v), "algebra", uses=("m2",))

# third slab, e to g
d.step("x3-local", Eq(x3l, centroid(e, g, f, 2 * m)), "lemma", uses=("prismatoid-centroid",), result=x3l)
d.step("x3", Eq(x3, 4 * m + x3l), "definition", uses=("x3-local",), result=x3,
       note="the plane e lies 4m from ABC")
x3_b = (4 * m * ((e + g) / 2 + 2 * f) + 2 * m * (g / 2 + f)) / ((e + g) / 2 + 2 * f)
d.step("x3-value", (x3, x3_b), "algebra", uses=("x3",))
d.step("v3", Eq(v3, volume(e, g, f, 2 * m)), "lemma", uses=("prismatoid-volume",), result=v3)
d.step("m3", Eq(M3, x3 * v3), "definition", uses=("x3", "v3"), result=M3)
m3_v = 8 * m ** 2 / 3 * ((e + g) / 2 + 2 * f) + 4 * m ** 2 / 3 * (g / 2 + f)
d.step("m3-value", (M3, m3_v), "algebra", uses=("m3",))

# the whole body
d.step("moment", Eq(M, M1 + M2 + M3), "definition", uses=("m1", "m2", "m3"), result=M,
       note="the moment theorem: the moment of the whole is the sum of the moments of the parts")
with sp.evaluate(False):   # the printed forms, as printed (the engine carries out their arithmetic)
    xv_1 = m ** 2 / 3 * (2 * c + 4 * b + 2 * c + 2 * e + 8 * dd + 2 * e + 4 * dd + 4 * e + 4 * g + 16 * f + 2 * g
                         + 4 * f)
    xv_2 = m ** 2 / 3 * (4 * b + 4 * c + 12 * dd + 8 * e + 20 * f + 6 * g)
    NUM = a * 0 + 4 * b * 1 + 2 * c * 2 + 4 * dd * 3 + 2 * e * 4 + 4 * f * 5 + g * 6
    DEN = a + 4 * b + 2 * c + 4 * dd + 2 * e + 4 * f + g
    xv_3 = m ** 2 / 3 * NUM
d.step("moment-value", (M, xv_1, xv_2, xv_3), "algebra", uses=("moment", "m1-value", "m2-value", "m3-value"))
d.step("volume", Eq(V, v1 + v2 + v3), "definition", uses=("v1", "v2", "v3"), result=V)
d.step("volume-simpson", (V, m / 3 * DEN), "lemma", uses=("volume", "graefe-s2-volumes-simpson:simpson-7"),
       note="Simpson's rule as derived in §2 (with the factor m/3)")
d.step("centroid", Eq(XS, M / V), "definition", uses=("moment", "volume"), result=XS)
d.step("centroid-value", (XS, as_printed(lambda: xv_3 / (m / 3 * DEN)), m * (NUM / DEN)), "algebra",
       uses=("centroid", "moment-value", "volume-simpson"))
d.step("centroid-equal-sections", (sp.Subs(m * NUM / DEN, (b, c, dd, e, f, g), (a,) * 6), 3 * m),
       "algebra", uses=("centroid-value",),
       note="check of the rule: with all sections equal (a prism of length 6m) the centroid lies in the "
            "middle, 3m from ABC")

# ---- the words: a slab's volume and moment about ABC by their definitions ---------------------------------------
# A slab between two sections 2m apart is a prismatoid: its section area is the quadratic in the distance xi from
# ABC through its three sections S_0, S_1, S_2 at xi_0, xi_0 + m, xi_0 + 2m.  Its volume and its moment about the
# plane ABC are the integrals of that area; a sentence names the slab by its sections and its place (at=).
xi, xi0 = sp.symbols("xi xi_0", real=True)
S0, S1, S2 = sp.symbols("S_0 S_1 S_2", positive=True)
A_sl, V_sl, M_sl = sp.symbols("A_slab V_slab M_slab", real=True)
d.domain.update({xi0: (0, 10), **{q: (1, 20) for q in (S0, S1, S2)}})
d.step("slab-section", Eq(A_sl, S0 * (xi - xi0 - m) * (xi - xi0 - 2 * m) / (2 * m ** 2)
                         - S1 * (xi - xi0) * (xi - xi0 - 2 * m) / m ** 2
                         + S2 * (xi - xi0) * (xi - xi0 - m) / (2 * m ** 2)), "definition", result=A_sl,
       note="the quadratic section area through S_0, S_1, S_2 at the distances xi_0, xi_0 + m, xi_0 + 2m from ABC")
d.step("slab-volume", (V_sl, sp.Integral(A_sl, (xi, xi0, xi0 + 2 * m)), 2 * m / 3 * ((S0 + S2) / 2 + 2 * S1)),
       "integration", result=V_sl, uses=("slab-section",))
d.step("slab-moment", (M_sl, sp.Integral(xi * A_sl, (xi, xi0, xi0 + 2 * m)),
                       xi0 * 2 * m / 3 * ((S0 + S2) / 2 + 2 * S1) + 4 * m ** 2 / 3 * (S2 / 2 + S1)),
       "integration", result=M_sl, uses=("slab-section",),
       note="each section times its distance from the plane ABC")
d.defines("volume", V_sl)
d.defines("moment", M_sl)
SLAB_1, SLAB_2, SLAB_3 = ({xi0: 0, S0: a, S1: b, S2: c}, {xi0: 2 * m, S0: c, S1: dd, S2: e},
                          {xi0: 4 * m, S0: e, S1: f, S2: g})

# ---- the hull of Fig. 9 (lost): base AUWC in the plane z = 0, the end sections ABC at x = 0 and UVW at x = L
# across the base, each symmetric about the midpoint (B', V') of its base line AC, UW at the same y = mu
mu, L_, wA, wU, dB, dV = sp.symbols("mu L w_A w_U d_B d_V", positive=True)
d.domain.update({q: (1, 5) for q in (mu, L_, wA, wU, dB, dV)})
A_, C_, B_ = sp.Matrix([0, mu - wA, 0]), sp.Matrix([0, mu + wA, 0]), sp.Matrix([0, mu, -dB])
U_, W_, V_ = sp.Matrix([L_, mu - wU, 0]), sp.Matrix([L_, mu + wU, 0]), sp.Matrix([L_, mu, -dV])


def mirrored(P, Q, R, X):
    """X reflected in the plane through P, Q, R (built unevaluated: the engine carries out the arithmetic)."""
    def build():
        nrm = (Q - P).cross(R - P)
        return X - 2 * ((X - P).dot(nrm) / nrm.dot(nrm)) * nrm
    return as_printed(build)


# ---- printed -------------------------------------------------------------------------------------
d.quote("symmetry-plane", "§4 ship displacement centroid",
        "Der Körper sei in Bezug auf eine durch die Mitten von AC und UW gelegte, zur Basis senkrechte Ebene "
        "BB'V'V' symmetrisch.",
        unreadable="BB'V'V' names the point V' twice: four letters for three points, and V, the end section's "
                   "point of UVW on the plane, is missing",
        erratum=Erratum("transcription", "low", r"\text{Ebene } B B' V' V",
                        "The plane passes through the midpoints B', V' of AC and UW and, being a plane of symmetry "
                        "of the end sections ABC and UVW, through their points B and V: B B' V' V, as the letters "
                        "of the two end sections pair up (B with B', V with V'). Checked with a hull whose end "
                        "sections are symmetric about their midpoints: the plane through B, B', V' contains V, "
                        "and the reflection in it exchanges A with C and U with W. A prime added to the last V, "
                        "as in Graefe's 'b'b'c' (§4, elliptic body); the scan's, low.",
                        corrected_reading=(sp.Matrix([*mirrored(B_, (A_ + C_) / 2, (U_ + W_) / 2, A_),
                                                      *mirrored(B_, (A_ + C_) / 2, (U_ + W_) / 2, U_),
                                                      *mirrored(B_, (A_ + C_) / 2, (U_ + W_) / 2, V_)]),
                                           sp.Matrix([*C_, *W_, *V_])),
                        objection="V' may be a point of the lost figure (the midpoint of UW is V', and the plane may"
                                  " be named by a second primed point).",
                        answer="The plane is named by four of its points; the letters pair the two end sections (B "
                               "with B', V with V'), and B B' V' V is the plane through the end sections' points of "
                               "symmetry and the midpoints of AC and UW. A second V' names the same point twice and "
                               "leaves three points. A stray prime, as in 'b'b'c' (§4, elliptic body): low, since "
                               "the print cannot be seen."),
        note="the base AUWC horizontal, the end sections vertical across it; the body's centroid then lies in "
             "the plane, and only its distances from ABC and from the base are sought")
d.quote("prismatoid-centroid", "§4 ship displacement centroid",
        r"$$X = h \left\{ \frac{\frac{g}{2} + D}{\frac{G + g}{2} + 2D} \right\}$$",
        reading=Eq(Xp, h * (g / 2 + D) / ((G + g) / 2 + 2 * D)))
d.quote("x1", "§4 ship displacement centroid",
        r"$$x' = 2m \left\{ \frac{\frac{c}{2} + b}{\frac{a + c}{2} + 2b} \right\}$$",
        reading=Eq(x1, 2 * m * ((c / 2 + b) / ((a + c) / 2 + 2 * b))))
d.quote("prismatoid-volume", "§4 ship displacement centroid",
        r"$V = \frac{h}{3} \left\{ \frac{G + g}{2} + 2D \right\}$",
        reading=Eq(Vp, h / 3 * ((G + g) / 2 + 2 * D)))
d.quote("v1", "§4 ship displacement centroid",
        r"$v' = \frac{2m}{3} \left\{ \frac{a + c}{2} + 2b \right\}$",
        reading=Eq(v1, 2 * m / 3 * ((a + c) / 2 + 2 * b)))
d.quote("m1", "§4 ship displacement centroid",
        r"$$m' = x' v' = \frac{4m^2}{3} \left\{ \frac{c}{2} + b \right\} . -$$",
        reading=(M1, x1 * v1, 4 * m ** 2 / 3 * (c / 2 + b)))

x1_expr = 2 * m * ((c / 2 + b) / ((a + c) / 2 + 2 * b))
d.quote("substitution", "§4 ship displacement centroid",
        r"wenn wir für  $a, b, c$  jetzt  $e, d, e$  setzen:",
        reading=(x2l, x1_expr.xreplace({a: e, b: dd, c: e})),
        erratum=Erratum("transcription", "medium", r"wenn wir für  $a, b, c$  jetzt  $c, d, e$  setzen",
                        "The slab from c to e has G = c, D = d, g = e: the next display, 2m{(e/2 + d)/((c+e)/2 + "
                        "2d)}, is x' with a, b, c replaced by c, d, e, not by e, d, e (which would give "
                        "2m{(e/2 + d)/(e + 2d)}). c and e are easily confused in the scan of this print; whether "
                        "the print itself had the slip cannot be told from the transcription.",
                        corrected_reading=(x2l, x1_expr.xreplace({a: c, b: dd, c: e})),
                        objection="'e, d, e' may be the print's own slip, the author's, not the scan's.",
                        answer="The next display is x' with a, b, c replaced by c, d, e, so the author had the right"
                               " letters when he computed; c and e are among the letters the scan of this print "
                               "confuses. Print or scan cannot be told apart: medium. Not high: the next display "
                               "shows what the author computed with, not who changed the letter after him, and c "
                               "for e is a slip of a compositor reading a manuscript as much as of a scan; no "
                               "second printing of this sentence settles it."))
d.quote("x2-local", "§4 ship displacement centroid",
        r"$$2m \left\{ \frac{\frac{e}{2} + d}{\frac{c+e}{2} + 2d} \right\}$$",
        reading=(x2l, 2 * m * ((e / 2 + dd) / ((c + e) / 2 + 2 * dd))))
d.quote("x2-a", "§4 ship displacement centroid",
        r"$$x'' = 2m + 2m \left\{ \frac{\frac{e}{2} + d}{\frac{c+e}{2} + 2d} \right\} \text{ oder}$$",
        reading=Eq(x2, 2 * m + 2 * m * ((e / 2 + dd) / ((c + e) / 2 + 2 * dd))))
d.quote("x2-b", "§4 ship displacement centroid",
        r"$$x'' = 2m \left\{ \frac{\frac{c+e}{2} + 2d + \frac{e}{2} + d}{\frac{c+e}{2} + 2d} \right\}$$",
        reading=Eq(x2, x2_b))
d.quote("v2", "§4 ship displacement centroid",
        r"$$v'' = \frac{2m}{3} \left\{ \frac{c+e}{2} + 2d \right\},$$",
        reading=Eq(v2, 2 * m / 3 * ((c + e) / 2 + 2 * dd)))
d.quote("m2", "§4 ship displacement centroid",
        r"$$m'' = x'' v'' = \frac{4m^2}{3} \left\{ \frac{c+e}{2} + 2d + \frac{e}{2} + d \right\}.$$",
        reading=(M2, x2 * v2, m2_v))
d.quote("x3-local", "§4 ship displacement centroid",
        r"$$2m \left\{ \frac{\frac{g}{2} + f}{\frac{e+g}{2} + 2f} \right\}$$",
        reading=(x3l, 2 * m * ((g / 2 + f) / ((e + g) / 2 + 2 * f))))
d.quote("x3-a", "§4 ship displacement centroid",
        r"$$x''' = 4m + 2m \left\{ \frac{\frac{g}{2} + f}{\frac{e+g}{2} + 2f} \right\} \text{ oder}$$",
        reading=Eq(x3, 4 * m + 2 * m * ((g / 2 + f) / ((e + g) / 2 + 2 * f))))
d.quote("x3-b", "§4 ship displacement centroid",
        r"$$x''' = \frac{4m \left\{ \frac{e+g}{2} + 2f \right\} + 2m \left\{ \frac{g}{2} + f \right\}}"
        r"{\frac{e+g}{2} + 2f}$$",
        reading=Eq(x3, x3_b))
d.quote("v3", "§4 ship displacement centroid",
        r"$$v''' = \frac{2m}{3} \left\{ \frac{e+g}{2} + 2f \right\}, \text{ so ist sein Moment in Bezug auf die}$$",
        reading=Eq(v3, 2 * m / 3 * ((e + g) / 2 + 2 * f)))
d.quote("m3", "§4 ship displacement centroid",
        r"$$m''' = x''' v''' = \frac{8m^2}{3} \left\{ \frac{e+g}{2} + 2f \right\} + \frac{4m^2}{3} "
        r"\left\{ \frac{g}{2} + f \right\}.$$",
        reading=(M3, x3 * v3, m3_v))
XBIG = ("the print names the distance of the centroid from ABC X and writes x for it in the final formula; the module "
        "keeps the final formula's x (its X is the prismatoid's, §1/§3)")
d.quote("moment-theorem", "§4 ship displacement centroid",
        r"$M = XV = x'v' + x''v'' + x'''v'''$",
        reading=(M, XS * V, x1 * v1 + x2 * v2 + x3 * v3), symbols={"X": (XS, XBIG)})
d.quote("moment-1", "§4 ship displacement centroid",
        r"$$XV = \frac{m^2}{3} \left\{ 2c + 4b + 2c + 2e + 8d + 2e + 4d + 4e + 4g + 16f + 2g + 4f \right\}$$",
        reading=Eq(XS * V, xv_1), symbols={"X": (XS, XBIG)})
d.quote("moment-2", "§4 ship displacement centroid",
        r"$$XV = \frac{m^2}{3} \left\{ 4b + 4c + 12d + 8e + 20f + 6g \right\}.$$",
        reading=Eq(XS * V, xv_2), symbols={"X": (XS, XBIG)})
d.quote("moment-3", "§4 ship displacement centroid",
        r"$$XV = \frac{m^2}{3} \left\{ a \times 0 + 4b \times 1 + 2c \times 2 + 4d \times 3 + 2e \times 4 + "
        r"4f \times 5 + g \times 6 \right\}$$",
        reading=Eq(XS * V, xv_3), symbols={"X": (XS, XBIG)})
d.quote("centroid", "§4 ship displacement centroid",
        r"$$x = \frac{m}{3} \left\{ \frac{a \times 0 + 4b \times 1 + 2c \times 2 + 4d \times 3 + 2e \times 4 + "
        r"4f \times 5 + g \times 6}{a + 4b + 2c + 4d + 2e + 4f + g} \right\}.$$",
        reading=Eq(XS, m / 3 * (NUM / DEN)),
        erratum=Erratum("consequential", "high",
                        r"x = m \left\{ \frac{a \times 0 + 4b \times 1 + 2c \times 2 + 4d \times 3 + 2e \times 4 + "
                        r"4f \times 5 + g \times 6}{a + 4b + 2c + 4d + 2e + 4f + g} \right\}",
                        r"$x = XV / V$ with $XV = m^2/3 \{\dots\}$ and $V = v' + v'' + v''' = m/3 \{a + 4b + \dots"
                        r" + g\}$; the print divides by the $V = m \{a + 4b + \dots + g\}$ printed in §2, where the "
                        "factor $1/3$ of Simpson's rule is lost (graefe-s2-volumes-simpson/simpson-rule): "
                        r"$XV / (m \{\dots\})$ is exactly the printed $m/3 \{\dots\}$. Check: with all sections "
                        "equal the body is a prism of length $6m$, its centroid lies at $3m$; the print gives $m$.",
                        corrected_reading=Eq(XS, m * (NUM / DEN)),
                        objection=r"The printed $x = m/3 \{\dots\}$ may be right in the author's own unit, if the "
                                  "factor $1/3$ lost in §2 is a convention carried consistently.",
                        answer="With all sections equal the body is a prism of length $6m$, whose centroid lies at "
                               "$3m$ from the first section; the print gives $m$. Whatever the unit, the quotient of "
                               "the moment by the volume must give $3m$ there, and it does only with the factor $m$."))

# the sentences that name a slab's volume or its moment about ABC, read from their definitions (the values are
# the displays that follow each sentence)
d.says("v1-words", "§4 ship displacement centroid",
       "Da nun das Volumen dieses Theiles nach der Formel für den Inhalt des Prismatoids", "Volumen dieses Theiles",
       Is(2 * m / 3 * ((a + c) / 2 + 2 * b), at=SLAB_1),
       note="Read as: the volume of the slab from a to c is the v' printed next, 2m/3 {(a + c)/2 + 2b}.")
d.says("m1-words", "§4 ship displacement centroid", "so ist das Moment dieses Theiles in Bezug",
       "Moment dieses Theiles", Is(4 * m ** 2 / 3 * (c / 2 + b), at=SLAB_1),
       note="Read as: the moment of the slab from a to c about the plane ABC is the m' printed next, "
            "4m²/3 {c/2 + b}.")
d.says("v2-words", "§4 ship displacement centroid", "und da das Volumen dieses Körpertheiles:",
       "Volumen dieses Körpertheiles", Is(2 * m / 3 * ((c + e) / 2 + 2 * dd), at=SLAB_2),
       note="Read as: the volume of the slab from c to e is the v'' printed next.")
d.says("m2-words", "§4 ship displacement centroid", "so ist sein Moment in Bezug auf die Ebene  $ABC$ :",
       "sein Moment", Is(m2_v, at=SLAB_2),
       note="Read as: the moment of the slab from c to e about ABC is the m'' printed next, 4m²/3 {(c + e)/2 + 2d "
            "+ e/2 + d}.")
d.says("v3-words", "§4 ship displacement centroid", "Da nun das Volumen dieses letzten Körpertheiles:",
       "Volumen dieses letzten Körpertheiles", Is(2 * m / 3 * ((e + g) / 2 + 2 * f), at=SLAB_3),
       note="Read as: the volume of the slab from e to g is the v''' printed next.")
d.says("m3-words", "§4 ship displacement centroid", r"\text{ so ist sein Moment in Bezug auf die}",
       "sein Moment", Is(m3_v, at=SLAB_3),
       note="Read as: the moment of the slab from e to g about ABC is the m''' printed after the words 'Ebene ABC'.")
