"""What Graefe's §3 says and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import Derivation, Eq, Erratum
from symfloat.model.claim import as_printed
from symfloat.model.vocabulary import Is

G, g, D, h, z = sp.symbols("G g D h z", positive=True)
al, be, ga = sp.symbols("alpha beta gamma", real=True)
V1, V2, V3, I, X, Z1, Z2, Z3 = sp.symbols("V_1 V_2 V_3 I X z_1 z_2 z_3", positive=True)
I_A, M_A, X_A = sp.symbols("I_A M_A X_A", real=True)   # volume, moment about G and centroid of a body of sections A(z)
PB, PC, PD = (sp.Matrix(sp.symbols(f"x_{n} y_{n} z_{n}", real=True)) for n in "BCD")
PA = sp.zeros(3, 1)  # A at the origin: every claim here is invariant under translation
coords = [c for v in (PB, PC, PD) for c in v]


def length(v):
    return sp.sqrt(v.dot(v))


def area(p, q, r):
    n = (q - p).cross(r - p)
    return sp.sqrt(n.dot(n)) / 2


def meet(p1, p2, q1, q2):
    """Intersection of the lines p1p2 and q1q2 (assumed to meet), by Cramer's
    rule on the x and y components."""
    u, v, w = p2 - p1, q2 - q1, q1 - p1
    t = (-w[0] * v[1] + w[1] * v[0]) / (-u[0] * v[1] + u[1] * v[0])
    return p1 + t * u


DERIVATION = d = Derivation(
    id="graefe-s3-prismatoid-centroid",
    source="graefe",
    title="The centroid of the tetrahedron and of the prismatoid",
    locator="§3",
    summary="The tetrahedron's centroid bisects every bimedian; the prismatoid's centroid lies "
            "at X = h (g/2 + D) / ((G+g)/2 + 2D) above G.",
    requires=("graefe-s1-prismatoid-volume",),
    domain={**{s: (1, 20) for s in (G, g, D, h)}, **{c: (-6, 6) for c in coords},
            al: (1, 9), be: (-2, 2), ga: (-1, 1)},
    constraints=(D > G / 4 + g / 4,),
    assumptions=("the tetrahedron ABCD is non-degenerate (coordinates in general position); A is put at the origin, which loses no generality for claims invariant under translation",
                 "G, g, D, h > 0 and D > G/4 + g/4, as for every convex prismatoid"),
)


# ---- the tetrahedron lemma, Graefe's construction in coordinates -------------
c = (PD + PB) / 2                       # c: midpoint of DB
F = c + (PC - c) / 3                    # cF = Cc/3
Gp = c + (PA - c) / 3                   # cG = Ac/3 (G is a point here, not the base)
o = meet(PC, Gp, PA, F)                 # intersection of the lines CG and AF
a = meet(c, o, PA, PC)                  # co extended meets AC in a

d.step("F-centroid-BCD", (F, as_printed(lambda: (PB + PC + PD) / 3)), "geometry", note="F divides the median Cc at 1/3 from c")
d.step("G-centroid-ABD", (Gp, as_printed(lambda: (PA + PB + PD) / 3)), "geometry")
d.step("o-on-both-lines", (o, (PA + PB + PC + PD) / 4), "geometry",
       note="the lines CG and AF meet in the mean of the vertices")
# From here on the positions just proved (o, then a and L) are used, as the
# proof itself proceeds from them; the printed claims are read with them too.
o_, a_, L_ = (PA + PB + PC + PD) / 4, (PA + PC) / 2, c + ((PA + PC) / 2 - c) / 3
d.step("oF-quarter", (length(o_ - F), length(PA - F) / 4), "geometry", uses=("o-on-both-lines",))
d.step("ratio-Coc-CoA", (area(PC, o_, c) / area(PC, o_, PA), length(Gp - c) / length(Gp - PA),
                         sp.Rational(1, 2)), "geometry")
d.step("a-midpoint", (a, (PA + PC) / 2), "geometry", note="the line co meets AC in its midpoint")
d.step("FG-parallel-AC", (Gp - F, as_printed(lambda: (PA - PC) / 3)), "geometry")
L = meet(a_, c, F, Gp)                  # ac meets FG in L (a as just proved)
d.step("L-third-of-ac", (L, c + (a_ - c) / 3), "geometry", uses=("a-midpoint",),
       note="L divides ca as F divides cC")
d.step("o-midpoint-ac", (o_, as_printed(lambda: (a_ + c) / 2)), "geometry", uses=("o-on-both-lines", "a-midpoint"))
d.step("o-midpoint-bd", (o_, as_printed(lambda: ((PA + PD) / 2 + (PB + PC) / 2) / 2)), "geometry", uses=("o-on-both-lines",),
       note="the same for the other pair of skew edges AD, BC")

d.quote("lemma", "§3 tetrahedron centroid lemma",
        "Wenn man die Mittelpunkte zweier nicht in einer Ebene liegenden Kanten eines Tetraeders verbindet, "
        "so liegt der Schwerpunkt des Körpers in der Mitte der Verbindungslinie.",
        reading=(o_, as_printed(lambda: ((PA + PC) / 2 + (PB + PD) / 2) / 2)))
d.quote("construction", "§3 tetrahedron centroid lemma",
        r"machen  $cF = \frac{C c}{3}$  und  $cG = \frac{A c}{3}$ , so sind  $F$  und  $G$  die Schwerpunkte "
        r"der Dreiecke  $BCD$  und  $ABD$",
        reading=(sp.Matrix.vstack(F, Gp), as_printed(lambda: sp.Matrix.vstack((PB + PC + PD) / 3, (PA + PB + PD) / 3))))
d.quote("quarters", "§3 tetrahedron centroid lemma",
        r"Auch ist  $oF = \frac{AF}{4}$  und  $oG = \frac{CG}{4}$",
        reading=(sp.Matrix([length(o_ - F), length(o_ - Gp)]), sp.Matrix([length(PA - F) / 4, length(PC - Gp) / 4])))
d.quote("quarter-line", "§3 tetrahedron centroid lemma",
        r"Da nun der Schwerpunkt eines Tetraeders bekanntlich auf einem Viertel der Linie von der Basis aus liegt, "
        r"welche den Schwerpunkt derselben mit der Spitze verbindet",
        reading=(o_, sp.Matrix([sp.Add(f_, sp.Mul(sp.Rational(1, 4), sp.Add(a_, -f_, evaluate=False), evaluate=False),
                                       evaluate=False) for f_, a_ in zip(F, PA)])),
        note="read for the base BCD (centroid F) and the apex A: o = F + (A - F)/4, kept unevaluated")
d.quote("ratio-1", "§3 tetrahedron centroid lemma",
        r"$$\triangle C o c : \triangle C o A = G c : G A = 1 : 2 \text{ und ebenso:}$$",
        reading=(area(PC, o_, c) / area(PC, o_, PA), length(Gp - c) / length(Gp - PA), sp.Rational(1, 2)))
d.quote("ratio-2", "§3 tetrahedron centroid lemma",
        r"$$\triangle c o A : \triangle C o c = A a : a C, \text{ woraus multiplicando:}$$",
        reading=(area(c, o_, PA) / area(PC, o_, c), length(a_ - PA) / length(PC - a_)))
d.quote("ratio-3", "§3 tetrahedron centroid lemma",
        r"$$\triangle c o A : \triangle C o A = A a : 2 a C \text{ und da ferner:}$$",
        reading=(area(c, o_, PA) / area(PC, o_, PA), length(a_ - PA) / (2 * length(PC - a_))))
d.quote("ratio-4", "§3 tetrahedron centroid lemma",
        r"$$\triangle c o A : \triangle C o A = F c : F C = 1 : 2; \text{ so ist:}$$",
        reading=(area(c, o_, PA) / area(PC, o_, PA), length(c - F) / length(PC - F), sp.Rational(1, 2)))
d.quote("a-midpoint", "§3 tetrahedron centroid lemma",
        r"$A a : 2 a C = 1 : 2$ , d. h.  $A a = a C$",
        reading=as_printed(lambda: (length(a_ - PA), length(PC - a_))))
d.quote("oL-ratio", "§3 tetrahedron centroid lemma",
        r"$o L : a o = o F : o A = 1 : 3$ , daher  $o L = \frac{a o}{3} = \frac{a L}{4}$",
        reading=(length(L_ - o_) / length(o_ - a_), length(F - o_) / length(PA - o_), sp.Rational(1, 3)))
d.quote("aL", "§3 tetrahedron centroid lemma",
        r"$a L = \frac{2 a c}{3}$", reading=(length(L_ - a_), 2 * length(c - a_) / 3))
d.quote("CF", "§3 tetrahedron centroid lemma",
        r"$C F = \frac{2 G c}{3}$", reading=(length(F - PC), 2 * length(c - Gp) / 3),
        erratum=Erratum("transcription", "medium", r"C F = \frac{2 C c}{3}",
                        "F was constructed with cF = Cc/3, so CF = 2Cc/3; 'G' for 'C' is a typical confusion "
                        "of the scan (the reason given, that L divides ac as F divides Cc, needs Cc). With "
                        "Gc = Ac/3 the printed relation would tie CF to the other median.",
                        corrected_reading=(length(F - PC), 2 * length(c - PC) / 3),
                        objection="G may be a point of the lemma (the tetrahedron's centroid, 'Schwerpunkt'), and Gc"
                                  " a segment the lost figure shows.",
                        answer="F was constructed with cF = Cc/3, so CF = 2Cc/3; the reason given (L divides ac as F"
                               " divides Cc) needs Cc, while with Gc = Ac/3 the relation would tie CF to the other "
                               "median. G elsewhere in Graefe is the base area, not a point of this lemma."))
d.quote("oL", "§3 tetrahedron centroid lemma",
        r"$o L = \frac{2 a c}{12} = \frac{a c}{6}$",
        reading=(length(L_ - o_), *as_printed(lambda: (2 * length(c - a_) / 12, length(c - a_) / 6))))
d.quote("oc", "§3 tetrahedron centroid lemma",
        r"$L c = \frac{a c}{3}$ , so ist  $o L + L c = o c = \frac{a c}{6} + \frac{a c}{3} = \frac{a c}{2}$",
        reading=(length(c - L_) + length(L_ - o_), length(c - o_), length(c - a_) / 2))
d.quote("diagonals", "§3 tetrahedron centroid lemma",
        r"der Schwerpunkt des Tetraeders liegt mithin im Durchschnittspunkte der Diagonalen der mittleren "
        r"Durchschnittsfläche  $a b c d$",
        reading=(o_, *as_printed(lambda: ((a_ + c) / 2, ((PA + PD) / 2 + (PB + PC) / 2) / 2))))

# ---- the prismatoid --------------------------------------------------------------
d.step("pyramid-over-g", Eq(V1, g * h / 3), "lemma", uses=("graefe-s1-prismatoid-volume:pyramid-over-g",),
       result=V1)
d.step("pyramids-over-G", Eq(V2, G * h / 3), "lemma", uses=("graefe-s1-prismatoid-volume:pyramids-over-G",),
       result=V2)
d.step("tetrahedra", Eq(V3, h / 3 * (2 * D - (G + g) / 2)), "lemma",
       uses=("graefe-s1-prismatoid-volume:tetrahedra-in-D",), result=V3)
d.step("arm-pyramid-over-g", Eq(Z1, sp.Integral(z * g * (z / h) ** 2, (z, 0, h)) / V1), "definition",
       note="centroid height of the pyramid with apex O in G", result=Z1)
d.step("arm-pyramid-over-g-value", (Z1, 3 * h / 4), "integration", uses=("arm-pyramid-over-g",))
d.step("arm-pyramids-over-G", Eq(Z2, sp.Integral(z * G * (1 - z / h) ** 2, (z, 0, h)) / V2), "definition",
       result=Z2)
d.step("arm-pyramids-over-G-value", (Z2, h / 4), "integration", uses=("arm-pyramids-over-G",))
d.step("arm-tetrahedra", Eq(Z3, (0 + h) / 2), "lemma", uses=("o-midpoint-ac",), result=Z3,
       note="each tetrahedron has one edge in G (height 0) and one in g (height h): the midpoint of "
            "their bimedian, its centroid, lies at h/2")
d.step("volume", Eq(I, h / 3 * ((G + g) / 2 + 2 * D)), "lemma",
       uses=("graefe-s1-prismatoid-volume:volume-collected",), result=I)
d.step("centroid", Eq(X, (V1 * Z1 + V2 * Z2 + V3 * Z3) / I), "definition", result=X,
       uses=("arm-pyramid-over-g-value", "arm-pyramids-over-G-value", "arm-tetrahedra", "volume"),
       note="moment theorem: I X is the sum of the moments of the parts about the base")
d.step("centroid-collected", (X, h * (g / 2 + D) / ((G + g) / 2 + 2 * D)), "algebra", uses=("centroid",))
A = al + be * z + ga * z ** 2
d.step("centroid-quadratic-sections",
       (sp.Integral(z * A, (z, 0, h)) / sp.Integral(A, (z, 0, h)),
        h * (A.subs(z, h) / 2 + A.subs(z, h / 2)) / ((A.subs(z, 0) + A.subs(z, h)) / 2 + 2 * A.subs(z, h / 2))),
       "integration", note="the formula is exact for every body whose section area A(z) is a quadratic "
                           "polynomial of the height: G = A(0), D = A(h/2), g = A(h)")

# ---- the words: volume, moment and centroid of the prismatoid by their definitions -------------------------
# A prismatoid's section area is a quadratic polynomial of the height (A above), so its volume, its moment about
# the base G and its centroid are the integrals of A; the sections G, g, D are A(0), A(h), A(h/2).
d.step("body-volume", (I_A, sp.Integral(A, (z, 0, h)), h / 3 * ((A.subs(z, 0) + A.subs(z, h)) / 2 + 2 * A.subs(z, h / 2))),
       "integration", result=I_A, note="the volume of the body of sections A(z): the integral of its sections")
d.step("body-moment", (M_A, sp.Integral(z * A, (z, 0, h)), h ** 2 / 3 * (A.subs(z, h) / 2 + A.subs(z, h / 2))),
       "integration", result=M_A, note="its moment about the base G (the 'Momenten-Ebene'): each section times its "
                                       "height z")
d.step("body-centroid", Eq(X_A, M_A / I_A), "definition", result=X_A, uses=("body-volume", "body-moment"),
       note="the distance of its centroid from G: the moment over the volume")
d.defines("moment", M_A)
d.defines("centre of gravity", X_A)
SECTIONS = ((G, g, D), (A.subs(z, 0), A.subs(z, h), A.subs(z, h / 2)))

d.quote("height-1", "§3 prismatoid centroid", r"a) Der Schwerpunkt von 1) liegt auf  $\frac{1}{4}$  der Höhe von  $g$  aus",
        reading=(Z1, h - h / 4), note="the pyramid ABCDO (base g at the height h, apex O in G): its centroid "
                                      "a quarter of the height below g")
d.quote("height-2", "§3 prismatoid centroid",
        r"b) Die Schwerpunkte der dreiseitigen Pyramiden von 2) liegen auf  $\frac{h}{4}$  von  $G$  aus",
        reading=(Z2, h / 4))
d.quote("height-3", "§3 prismatoid centroid",
        r"c) Die Schwerpunkte sämtlicher Tetraeder von 3) liegen auf  $\frac{h}{2}$",
        reading=(Z3, h / 2), note="each tetrahedron has one edge in G and one in g")
d.quote("moment-group-3", "§3 prismatoid centroid",
        r"das Moment von 3) ist  $\frac{h}{3} \left( 2D - \frac{G+g}{2} \right) \frac{h}{2}$",
        reading=(V3 * Z3, h / 3 * (2 * D - (G + g) / 2) * h / 2))
d.quote("lemma-restated", "§3 prismatoid centroid",
        r"Satze, dass der Schwerpunkt eines Tetraeders in der Mitte der Verbindungslinie der Mittelpunkte zweier "
        r"nicht in einer Ebene liegenden Kanten sich befindet",
        reading=(o_, as_printed(lambda: ((PA + PD) / 2 + (PB + PC) / 2) / 2)), note="read for the edges AD and BC")
d.quote("arm-1", "§3 prismatoid centroid",
        r"der Hebelarm von  $G$  aus ist mithin  $\frac{3h}{4}$  und das Moment von 1)  "
        r"$\left(\frac{gh}{3}\right) \frac{3h}{4}$",
        reading=(V1 * Z1, g * h / 3 * 3 * h / 4))
d.quote("arm-2", "§3 prismatoid centroid",
        r"mithin ist das Moment von 2)  $\left(\frac{Gh}{3}\right) \frac{h}{4}$",
        reading=(V2 * Z2, G * h / 3 * h / 4))
d.quote("tetrahedra-volume", "§3 prismatoid centroid",
        r"für deren Inhalt wir zusammen fanden  $\frac{h}{3} \left\{ 2D - \frac{G+g}{2} \right\}$",
        reading=(V3, h / 3 * (2 * D - (G + g) / 2)))
d.quote("moment-1", "§3 prismatoid centroid",
        r"$$IX = \frac{gh}{3} \cdot \frac{3h}{4} + \frac{Gh}{3} \cdot \frac{h}{4} + \frac{h}{3} \left\{ 2D - "
        r"\frac{G+g}{2} \right\} \frac{h}{2},$$",
        reading=Eq(I * X, g * h / 3 * 3 * h / 4 + G * h / 3 * h / 4 + h / 3 * (2 * D - (G + g) / 2) * h / 2))
d.quote("moment-2", "§3 prismatoid centroid",
        r"$$IX = \frac{h^2}{3} \left\{ \frac{3g}{4} + \frac{G}{4} + D - \frac{G}{4} - \frac{g}{4} \right\}, "
        r"\text{ also}$$",
        reading=Eq(I * X, h ** 2 / 3 * (3 * g / 4 + G / 4 + D - G / 4 - g / 4)))
d.quote("moment-3", "§3 prismatoid centroid",
        r"$$IX = \frac{h^2}{3} \left\{ \frac{g}{2} + D \right\} \text{ und da}$$",
        reading=Eq(I * X, h ** 2 / 3 * (g / 2 + D)))
d.quote("volume", "§3 prismatoid centroid",
        r"$$I = \frac{h}{3} \left\{ \frac{G+g}{2} + 2D \right\} \text{ war, so ist}$$",
        reading=Eq(I, h / 3 * ((G + g) / 2 + 2 * D)))
d.quote("centroid", "§3 prismatoid centroid",
        r"$$X = h \left\{ \frac{\frac{g}{2} + D}{\frac{G+g}{2} + 2D} \right\}.$$",
        reading=Eq(X, h * (g / 2 + D) / ((G + g) / 2 + 2 * D)))

d.says("moment-theorem", "§3 prismatoid centroid",
       "Nun ist nach dem bekannten Momentensatze: das Moment der Summe der einzelnen Theile gleich der Summe der "
       "Momente derselben.", "Moment der Summe der einzelnen Theile",
       Is(sp.Subs(V1 * Z1 + V2 * Z2 + V3 * Z3, *SECTIONS)),
       note="Read for the prismatoid and its three groups of bodies (a, b, c above, their moments about G): the "
            "moment of the whole, the integral of z A(z) over the height, is the sum of the three groups' moments, "
            "their volumes times the heights of their centroids, with G, g, D the sections A(0), A(h), A(h/2).")
d.says("centroid-words", "§3 prismatoid centroid",
       r"Dies ist die Formel für den senkrechten Abstand des Schwerpunktes des Prismatoids von der Grundfläche  $G$",
       "Schwerpunktes des Prismatoids", Is(sp.Subs(h * (g / 2 + D) / ((G + g) / 2 + 2 * D), *SECTIONS)),
       note="Read as: the formula just printed, X = h (g/2 + D)/((G+g)/2 + 2D), is the distance from G of the "
            "prismatoid's centroid, its moment over its volume, for every body whose section area is quadratic in "
            "the height (G = A(0), D = A(h/2), g = A(h)).")
