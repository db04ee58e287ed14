"""What Graefe's §1 says and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import Derivation, Eq, Erratum
from symfloat.model.claim import as_printed

G, g, D, h, z = sp.symbols("G g D h z", positive=True)
ps, qs, kp, Sf, Tf = sp.symbols("p q k S_f T_f", positive=True)   # sides of the bases, parallel pairs, faces
P, V1, V2, V3, I = sp.symbols("P V_1 V_2 V_3 I", positive=True)
# the tetrahedron of the lemma: vertices A, B, C, D_ (D is the mid-section)
XA, XB, XC, XD = (sp.Matrix(sp.symbols(f"x_{n} y_{n} z_{n}")) for n in "ABCD")
Vt, Ve, Pt, dist, Tri = sp.symbols("V_ABCD V_ABCE P_abcd d T_ABE", positive=True)

coords = [c for v in (XA, XB, XC, XD) for c in v]
# Fig. 3: the base G = EFGHI in the plane z = 0 with the point O, the top g = ABCD at z = h; plane
# coordinates (u, v) of every point, the mid-section D at z = h/2 (the midpoints of the lateral edges)
FIG3 = {q: sp.Matrix(sp.symbols(f"u_{q} v_{q}", real=True)) for q in "ABCDEFGHIO"}
fig3_coords = [c for v in FIG3.values() for c in v]


def _mid(p, q):
    return (FIG3[p] + FIG3[q]) / 2


def _area(*pts):
    """Signed area of the polygon with the given plane vertices (shoelace)."""
    return sum(pts[i][0] * pts[(i + 1) % len(pts)][1] - pts[(i + 1) % len(pts)][0] * pts[i][1]
               for i in range(len(pts))) / 2


def _volume_squared(p, q, r, o):
    """Squared volume of the tetrahedron p q r o with p, q in the top plane z = h and r, o in the base."""
    lift = {p: h, q: h, r: 0, o: 0}
    P3 = {t: sp.Matrix([*FIG3[t], lift[t]]) for t in (p, q, r, o)}
    return ((P3[q] - P3[p]).dot((P3[r] - P3[p]).cross(P3[o] - P3[p])) / 6) ** 2


# the points of D named in the text: k, l, m, n the midpoints of OA, OB, OC, OD; a ... i those of the lateral
# edges AE, BE, BF, BG, CG, CH, DH, DI, AI (read off the parallelograms aklb, lmde, mngf, knhi and the
# triangles mef, ngh, kia, cld of the text)
MID3 = {"k": _mid("O", "A"), "l": _mid("O", "B"), "m": _mid("O", "C"), "n": _mid("O", "D"),
        "a": _mid("A", "E"), "b": _mid("B", "E"), "c": _mid("B", "F"), "d": _mid("B", "G"), "e": _mid("C", "G"),
        "f": _mid("C", "H"), "g": _mid("D", "H"), "h": _mid("D", "I"), "i": _mid("A", "I")}


def _tri(name):
    return _area(*(MID3[q] for q in name))
DERIVATION = d = Derivation(
    id="graefe-s1-prismatoid-volume",
    source="graefe",
    title="The tetrahedron lemma and the volume of the prismatoid",
    locator="§1",
    summary="Volume of a tetrahedron from its mid-section parallelogram; the prismatoid "
            "cut into pyramids and tetrahedra; I = h/3 ((G+g)/2 + 2D).",
    domain={**{s: (1, 20) for s in (G, g, D, h)}, **{c: (-6, 6) for c in coords + fig3_coords},
            P: (1, 20), ps: (3, 8), qs: (3, 8), kp: (0, 3)},
    constraints=(D > G / 4 + g / 4,),
    assumptions=("G, g, D, h > 0",
                 "the mid-section is larger than the halved bases together (D > G/4 + g/4), "
                 "as it is for every convex prismatoid",
                 "the tetrahedron ABCD is non-degenerate"),
)

# ---- the lemma (its statement is lost; its proof survives) -------------------
n = (XB - XA).cross(XD - XC)
XE = XB + (XD - XC)                     # BE parallel to CD
mid = {"a": (XA + XC) / 2, "b": (XB + XC) / 2, "c": (XB + XD) / 2, "d": (XA + XD) / 2}


def joining(P, Q):
    """The vector from P to Q, its differences left unevaluated (so that two sides of a claim
    built from different points are compared, not made equal on construction)."""
    return sp.Matrix([sp.Add(q, -p, evaluate=False) for p, q in zip(P, Q)])


ab, dc, AB_half = joining(mid["a"], mid["b"]), joining(mid["d"], mid["c"]), (XB - XA) / 2
w = (mid["b"] - mid["a"]).cross(mid["d"] - mid["a"])
u = (XB - XA).cross(XE - XA)
triple_ABCD = (XB - XA).dot((XC - XA).cross(XD - XA))
triple_ABCE = (XB - XA).dot((XC - XA).cross(XE - XA))
# names for display (the notebook writes these sub-expressions by their names)
for X, label in ((XA, "A"), (XB, "B"), (XC, "C"), (XD, "D")):
    d.name(sp.Symbol(rf"\mathbf{{{label}}}"), X, f"the vertex ${label}$ of the tetrahedron")
d.name(sp.Symbol(r"\mathbf{E}"), XE, "$E = B + (D - C)$: $BE$ drawn parallel to $CD$")
d.name(sp.Symbol(r"\vec{ab}"), ab, "$b - a$, a side of the mid-section $abcd$ ($a, b, c, d$ the midpoints of "
       "$AC, BC, BD, AD$, so $a = (A + C)/2$ and $b = (B + C)/2$)")
d.name(sp.Symbol(r"\vec{dc}"), dc, "$c - d$, the opposite side ($d = (A + D)/2$, $c = (B + D)/2$)")
d.name(sp.Symbol(r"\tfrac{1}{2}\vec{AB}"), AB_half, "half the edge $AB$")
d.name(sp.Symbol(r"|[\vec{AB},\vec{AC},\vec{AD}]|"), sp.Abs(triple_ABCD),
       r"$|\vec{AB} \cdot (\vec{AC} \times \vec{AD})|$, the absolute triple product of the edges from $A$")
d.name(sp.Symbol(r"|[\vec{AB},\vec{AC},\vec{AE}]|"), sp.Abs(triple_ABCE),
       r"$|\vec{AB} \cdot (\vec{AC} \times \vec{AE})|$, the same with $E$ for $D$")
d.name(sp.Symbol(r"|\vec{ab}\times\vec{ad}|^2"), w.dot(w),
       r"$|(b - a) \times (d - a)|^2$, the squared area of the parallelogram $abcd$")
d.name(sp.Symbol(r"|\vec{n}|^2"), n.dot(n),
       r"$\vec{n} \cdot \vec{n}$, $\vec{n} = \vec{AB} \times \vec{CD}$ the common normal of the edges $AB$ and $CD$")
d.name(sp.Symbol(r"|\vec{AC}\cdot\vec{n}|"), sp.Abs((XC - XA).dot(n)),
       r"$|\vec{AC} \cdot \vec{n}|$, $AC$ projected on the common normal")
d.name(sp.Symbol(r"|\vec{AB}\times\vec{AE}|^2"), u.dot(u),
       r"$|\vec{AB} \times \vec{AE}|^2$, the squared double area of the triangle $ABE$")

d.step("volume-ABCD", Eq(Vt, sp.Abs(triple_ABCD) / 6), "definition",
       note="volume of a tetrahedron: one sixth of the absolute triple product", result=Vt)
d.step("mid-section-is-parallelogram", (ab, dc, AB_half), "geometry",
       note="the section through the midpoints of AC, BC, BD, AD has opposite sides equal to AB/2")
d.step("mid-section-area", Eq(Pt, sp.sqrt(w.dot(w))), "definition",
       note="area of the parallelogram abcd", result=Pt)
d.step("mid-section-area-in-edges", (Pt, sp.sqrt(n.dot(n)) / 4), "geometry", uses=("mid-section-area",))
d.step("edge-distance", Eq(dist, sp.Abs((XC - XA).dot(n)) / sp.sqrt(n.dot(n))), "definition",
       note="shortest distance of the lines AB and CD: projection of AC on their common normal",
       result=dist)
d.step("triangle-ABE", Eq(Tri, sp.sqrt(u.dot(u)) / 2),
       "definition", note="E = B + (D - C): BE drawn parallel to CD", result=Tri)
d.step("parallelogram-half-triangle", (Pt, Tri / 2), "geometry", uses=("mid-section-area", "triangle-ABE"),
       note="the mid-section parallelogram abcd is half as large as the triangle ABE")
d.step("volume-ABCE", Eq(Ve, sp.Abs(triple_ABCE) / 6), "definition", result=Ve,
       note="the second tetrahedron ABCE, with E in place of D")
d.step("equal-tetrahedra", (Vt, Ve), "geometry", uses=("volume-ABCD", "volume-ABCE"),
       note="D and E lie on a parallel to the base ABC")
d.step("lemma", (Vt, sp.Rational(1, 3) * (2 * Pt) * dist), "algebra",
       uses=("equal-tetrahedra", "parallelogram-half-triangle", "edge-distance"),
       note="the lemma: ABCD has the volume of ABCE, whose base ABE is twice the mid-section abcd and whose "
            "height is the distance d of the edges AB and CD; so V = (1/3) (2P) d")

# ---- the decomposition --------------------------------------------------------
d.step("pyramid-over-g", Eq(V1, sp.Integral(g * (z / h) ** 2, (z, 0, h))), "definition",
       note="apex O in the base plane, sections similar to g with ratio z/h", result=V1)
d.step("pyramid-over-g-value", (V1, g * h / 3), "integration", uses=("pyramid-over-g",))
d.step("pyramids-over-G", Eq(V2, sp.Integral(G * (1 - z / h) ** 2, (z, 0, h))), "definition",
       note="the triangles of G with apices on g: together base G, height h", result=V2)
d.step("pyramids-over-G-value", (V2, G * h / 3), "integration", uses=("pyramids-over-G",))
d.step("mid-sections", (g * sp.UnevaluatedExpr(sp.Rational(1, 2)) ** 2, g / 4), "algebra",
       note="the mid-section of the pyramid over g is g scaled by 1/2; likewise G/4")
d.step("parallelograms", Eq(P, D - g / 4 - G / 4), "definition", result=P,
       note="the mid-section D consists of the polygon klmn (g/4), the triangles (G/4) and the "
            "parallelograms of the tetrahedra: their sum P is what remains")
d.step("tetrahedra", Eq(V3, sp.Rational(1, 3) * 2 * P * h), "lemma", uses=("lemma", "parallelograms"),
       note="every tetrahedron has one edge in G and one in g, at distance h", result=V3)
d.step("tetrahedra-in-D", (V3, sp.Mul(sp.Rational(1, 3), 2, D - g / 4 - G / 4, h, evaluate=False),
                           h / 3 * (2 * D - (G + g) / 2)), "substitution", uses=("tetrahedra", "parallelograms"),
       note="P = D - g/4 - G/4 inserted")
d.step("volume", Eq(I, V1 + V2 + V3), "definition", uses=("pyramid-over-g", "pyramids-over-G", "tetrahedra"),
       note="the prismatoid is the union of the three groups of bodies",
       result=I)
collected_as_printed = h / 3 * sp.Add(g, G, -G / 2, -g / 2, 2 * D, evaluate=False)
collected = as_printed(lambda: h / 3 * ((G + g) / 2 + 2 * D))
d.step("volume-collected", (I, collected_as_printed, collected),
       "algebra", uses=("volume",))

# ---- printed -------------------------------------------------------------------
d.quote("lemma-statement", "§1 tetrahedron lemma",
        r"dessen Höhe gleich dem kürzesten Abstände der beiden übrigen Kanten  $AB$  und  $CD$  des ersten "
        r"Tetraeders ist.",
        lost="the statement of the lemma and the start of §1 (with Fig. 2) are missing; only the end of "
             "the statement survives. Its content is restated at the end of the proof (see 'lemma-conclusion').")
d.quote("nine-triangles", "§1 prismatoid faces", "die untere fünf Seiten und wird der Mantel demnach von neun "
        "Dreiecken gebildet.",
        reading=(sp.Add(4, 5, evaluate=False), 9),
        note="Fig. 1: one lateral triangle per side of either base, the upper base with four sides and the lower "
             "with five")
d.quote("parallelogram-half-triangle", "§1 tetrahedron lemma",
        r"ist halb so gross als das Dreieck  $ABE$",
        reading=(Pt, Tri / 2))
XM, XN, XQ = (XA + XB) / 2, (XA + XE) / 2, (XB + XE) / 2   # the midpoints m, n, q of AB, AE, BE


def _area_squared(p, q, r):
    """Squared area of the triangle p q r in space."""
    w_ = (q - p).cross(r - p)
    return w_.dot(w_) / 4


d.quote("quarter-triangles", "§1 tetrahedron lemma", r"und  $mnb$ ,  $Bnq$  diesen flächengleich sind",
        reading=(sp.Matrix([_area_squared(XM, XN, mid["b"]), _area_squared(XB, XN, XQ)]),
                 sp.Matrix([_area_squared(XA, XM, XN)] * 2)),
        erratum=Erratum("transcription", "medium", r"mnB,\ Bnq \text{ diesen flächengleich}",
                        "m, n, q are the midpoints of AB, AE, BE and n is joined with B: the median Bn cuts the "
                        "quadrilateral mBqn left between the corner triangles Amn and nqE into mnB and Bnq, each "
                        "half of ABn or BnE, i.e. a quarter of ABE like Amn. The lower-case b of the print is the "
                        "corner of the mid-section abcd (the midpoint of BC), which lies outside the plane ABE: "
                        "the triangle mnb has in general another area (read here as squared areas in the "
                        "coordinates of the lemma). The capital B read as b by the scan (it is joined with n in "
                        "the same sentence); medium, since a case slip of the compositor cannot be excluded.",
                        corrected_reading=(sp.Matrix([_area_squared(XM, XN, XB), _area_squared(XB, XN, XQ)]),
                                           sp.Matrix([_area_squared(XA, XM, XN)] * 2)),
                        objection="The lower-case b may be right: b is a point of the mid-section abcd, and the lost"
                                  " figure may show a triangle mnb of the area the text needs.",
                        answer="b, the midpoint of BC, lies outside the plane ABE, so mnb is not a part of the "
                               "quadrilateral mBqn that the sentence divides; its area differs from a quarter of ABE"
                               " in the lemma's coordinates, whatever the figure showed. The capital B is joined "
                               "with n in the same sentence."),
        note="the sentence proves that the triangle abc is a quarter of ABE: Amn and nqE are congruent to it, "
             "the two triangles between them have their area")
d.quote("height-is-edge-distance", "§1 tetrahedron lemma",
        r"so ist die Höhe desselben gleich dem kürzesten Abstand der Kanten  $CD$  und  $AB$  des Tetraeders  $ABCD$",
        reading=(3 * Ve / Tri, dist), note="the height of ABCE over the base ABE is three times its volume over "
                                           "the base's area")
d.quote("lemma-conclusion", "§1 tetrahedron lemma",
        r"Mithin ist der Inhalt des Tetraeders  $ABCD$  gleich dem des Tetraeders  $ABCE$ , dessen Basis gleich "
        r"der doppelten Durchschnittsfläche  $abcd$  und dessen Höhe gleich dem kürzesten Abstand der beiden "
        r"Kanten  $CD$  und  $AB$ .",
        reading=(Vt, Ve, sp.Rational(1, 3) * 2 * Pt * dist))
d.quote("pyramid-over-g", "§1 prismatoid volume",
        r"deren Basis  $g$ , deren Höhe  $h$ , deren Inhalt mithin  $\frac{g h}{3}$", reading=Eq(V1, g * h / 3))
d.quote("pyramids-over-G", "§1 prismatoid volume",
        r"deren Basis zusammen  $= G$ , deren Höhen  $= h$ , deren Inhalt zusammen  $= \frac{G h}{3}$",
        reading=Eq(V2, G * h / 3))
g3 = _area(*(FIG3[q] for q in "ABCD"))       # the top g of Fig. 3
d.quote("tetrahedra-list", "§1 prismatoid volume", r"nämlich ABOE, BCOG, DCOH, ADOL",
        unreadable="'L' names no point of Fig. 3: its points are the corners A-D of g, E-I of G, O and the "
                   "midpoints k, l, m, n; the fourth tetrahedron has no fourth vertex as printed",
        erratum=Erratum("transcription", "medium", r"ABOE,\ BCOG,\ DCOH,\ ADOI",
                        "One tetrahedron for each side of g, joining it with a segment from O to a corner of G: "
                        "the text pairs the edges AB/EO, BC/OG, DC/OH, AD/OI (line 'Da nun die Höhe h zugleich "
                        "der kürzeste Abstand der Kanten ...'), and the parallelogram knhi (k, n, h, i the "
                        "midpoints of OA, OD, DI, AI) is named as the mid-section of the fourth. So the fourth "
                        "is ADOI, and each tetrahedron has by the lemma the volume (1/3)(2P)h with P its "
                        "parallelogram aklb, lmde, mngf, knhi (checked as squared volumes in the plane "
                        "coordinates of Fig. 3, top at height h). An I read as L by the scan; medium (the print "
                        "cannot be seen).",
                        corrected_reading=(sp.Matrix([_volume_squared(*t) for t in ("ABEO", "BCGO", "DCHO", "ADIO")]),
                                           sp.Matrix([(sp.Rational(2, 3) * h * _area(*(MID3[q] for q in par))) ** 2
                                                      for par in ("aklb", "lmed", "mngf", "knhi")])),
                        objection="L may be a corner of G in the lost figure, so that ADOL names a tetrahedron the "
                                  "figure shows.",
                        answer="The text pairs the edges AD and OI (the shortest distance of the edges), and names "
                               "knhi, with i the midpoint of AI, as the fourth tetrahedron's mid-section; a corner L"
                               " would give another mid-section. No L joins AD anywhere else in the section."),
        note="the parallelograms' corners in their cyclic order (lmde of the text as l m e d)")
d.quote("mid-section-g", "§1 prismatoid volume",
        r"dessen Inhalt, weil auf der halben Höhe der Pyramide  $ABCO$ ,  $= \frac{g}{4}$",
        reading=(_tri("klm"), g3 / 4),
        erratum=Erratum("transcription", "low", r"\text{Pyramide } ABCDO, \ = \frac{g}{4}",
                        "The polygon klmn (k, l, m, n the midpoints of OA, OB, OC, OD) is the mid-section of "
                        "the pyramid ABCDO of group 1 (base g = ABCD, apex O), g scaled by 1/2: area g/4. The "
                        "pyramid ABCO of the print has the triangle ABC for its base; its mid-section klm has "
                        "the area ABC/4, not g/4 (read in the plane coordinates of Fig. 3). A D dropped from "
                        "the name given to the same pyramid a few lines before (ABCDO); low, since the print may "
                        "have dropped it as well as the scan.",
                        corrected_reading=(_area(*(MID3[q] for q in "klmn")), g3 / 4),
                        objection="'Pyramide ABCO' may be the author's shorthand for the pyramid over the polygon "
                                  "ABC... with apex O, naming only its first corners.",
                        answer="A few lines before, the same pyramid is named ABCDO with all its corners; the "
                               "shorthand would name a triangle's pyramid, whose mid-section is ABC/4, not g/4. "
                               "Whether the print or the scan dropped the D cannot be told: low."),
        note="read with the printed pyramid: its mid-section is the triangle of the midpoints of OA, OB, OC")
d.quote("mid-section-triangles", "§1 prismatoid volume",
        r"$mef$ ,  $ngh$ ,  $kia$ ,  $blo$ ,  $cld$  als  $G$  Dreiecke enthält",
        unreadable="'o' names no point of the mid-section D = abcdefghi nor of the construction (its midpoints "
                   "are k, l, m, n): the fourth triangle has no third vertex as printed",
        erratum=Erratum("transcription", "medium", r"mef,\ ngh,\ kia,\ blc,\ cld",
                        "The triangles are the mid-sections of the pyramids EOFB, FOGB, GOHC, HOID, IOEA: each "
                        "is the triangle of the midpoints of the three edges from the apex. For EOFB these are "
                        "b, l, c (the midpoints of BE, BO, BF; the parallelograms aklb and lmde of the text fix "
                        "b and c as the midpoints of BE and BF, d as that of BG), so the fourth triangle is blc; "
                        "the others are mef, ngh, kia, cld as printed. Together they are G/4 (checked with signed "
                        "areas in the plane coordinates of Fig. 3, for any O). A c read as o by the scan; "
                        "medium.",
                        corrected_reading=(sum(_tri(t) for t in ("mef", "ngh", "kia", "lbc", "lcd")),
                                           _area(*(FIG3[q] for q in "EFGHI")) / 4),
                        objection="o may be a point of the lost figure, making blo a triangle the figure shows.",
                        answer="The five triangles are the mid-sections of the pyramids over the faces of G, each "
                               "made of the midpoints of its three edges from the apex; the midpoint of BF is c (the"
                               " parallelograms aklb and lmde fix it), and no midpoint is called o."),
        note="the triangles' vertices are ordered as the base triangles OEF, OFG, … (blc as lbc)")

d.quote("mid-section-triangles-sum", "§1 prismatoid volume",
        r"ihr Inhalt beträgt also zusammen  $= \frac{G}{4}$",
        reading=(sum(_tri(t) for t in ("mef", "ngh", "kia", "lbc", "lcd")), _area(*(FIG3[q] for q in "EFGHI")) / 4),
        note="the five mid-sections (blc for the printed blo, see 'mid-section-triangles') together, as signed "
             "areas in the plane coordinates of Fig. 3: G/4 for any point O of the base")

MINUS_AS_EQUALS = ("The scan read the minus sign (a long dash in the print) as '='. The same term is quoted "
                   "correctly in §3 ('für deren Inhalt wir zusammen fanden h/3{2D - (G+g)/2}'), so the "
                   "print had the minus.")
d.quote("parallelogram-sum", "§1 prismatoid volume",
        r"$$D = \frac{g}{4} + \frac{G}{4}.$$",
        reading=Eq(D, g / 4 + G / 4),
        erratum=Erratum("transcription", "high", r"P = D - \frac{g}{4} - \frac{G}{4}",
                        "The sum P of the parallelograms is what remains of D after the polygon (g/4) and "
                        "the triangles (G/4). " + MINUS_AS_EQUALS,
                        corrected_reading=(P, D - g / 4 - G / 4),
                        objection="The '=' may be the print's own (a broken dash of the type), or an older notation "
                                  "that writes a remainder inside braces with '='.",
                        answer="No notation of the period writes a difference with '=', and §3 quotes this very term"
                               " with the minus ('für deren Inhalt wir zusammen fanden h/3{2D - (G+g)/2}'), so the "
                               "print had the minus; a long dash read as '=' is the scan's usual confusion, and it "
                               "recurs at all five places of §1."))
d.quote("tetrahedra-volume", "§1 prismatoid volume",
        r"$$\frac{h}{3} \times 2 \left\{ D = \frac{g}{4} + \frac{G}{4} \right\} \text{ oder}$$",
        unreadable="'=' inside the braces: the expression is not well formed",
        erratum=Erratum("transcription", "high",
                        r"\frac{h}{3} \times 2 \left\{ D - \frac{g}{4} - \frac{G}{4} \right\}",
                        "Volume of all tetrahedra by the lemma. " + MINUS_AS_EQUALS,
                        corrected_reading=(V3, h / 3 * 2 * (D - g / 4 - G / 4)),
                        objection="The '=' may be the print's own, or an older notation for a remainder.",
                        answer="§3 quotes the same term with the minus, so the print had it; the same dash read as "
                               "'=' at every place of §1 is the scan's systematic confusion, not five slips of a "
                               "compositor."))
d.quote("tetrahedra-volume-2", "§1 prismatoid volume",
        r"$$\frac{h}{3} \left\{ 2D = \frac{G+g}{2} \right\}.$$",
        unreadable="'=' inside the braces: the expression is not well formed",
        erratum=Erratum("transcription", "high", r"\frac{h}{3} \left\{ 2D - \frac{G+g}{2} \right\}",
                        MINUS_AS_EQUALS, corrected_reading=(V3, h / 3 * (2 * D - (G + g) / 2)),
                        objection="The '=' may be the print's own, or an older notation for a remainder.",
                        answer="§3 quotes this very expression, h/3{2D - (G+g)/2}, with the minus; the scan reads "
                               "the long dash as '=' throughout §1."))
d.quote("volume-sum", "§1 prismatoid volume",
        r"$$I = \frac{gh}{3} + \frac{Gh}{3} + \frac{h}{3} \left\{ 2D = \frac{G+g}{2} \right\}$$",
        unreadable="'=' inside the braces: the expression is not well formed",
        erratum=Erratum("transcription", "high",
                        r"I = \frac{gh}{3} + \frac{Gh}{3} + \frac{h}{3} \left\{ 2D - \frac{G+g}{2} \right\}",
                        MINUS_AS_EQUALS,
                        corrected_reading=Eq(I, g * h / 3 + G * h / 3 + h / 3 * (2 * D - (G + g) / 2)),
                        objection="The '=' may be the print's own, or an older notation for a remainder.",
                        answer="§3 quotes the term with the minus; the scan reads the long dash as '=' throughout "
                               "§1."))
d.quote("volume-collected", "§1 prismatoid volume",
        r"$$I = \frac{h}{3} \left\{ g + G = \frac{G}{2} + \frac{g}{2} + 2D \right\}$$",
        unreadable="'=' inside the braces: the expression is not well formed",
        erratum=Erratum("transcription", "high",
                        r"I = \frac{h}{3} \left\{ g + G - \frac{G}{2} - \frac{g}{2} + 2D \right\}",
                        MINUS_AS_EQUALS,
                        corrected_reading=Eq(I, h / 3 * (g + G - G / 2 - g / 2 + 2 * D)),
                        objection="The '=' may be the print's own, or an older notation for a remainder.",
                        answer="The result I = h/3 {(G+g)/2 + 2D} that follows needs the minus, and §3 quotes the "
                               "term with it; the scan reads the long dash as '=' throughout §1."))
d.quote("prismatoid-volume", "§1 prismatoid volume",
        r"$$I = \frac{h}{3} \left\{ \frac{G+g}{2} + 2D \right\}, \text{ welches die oben erwähnte}$$",
        reading=Eq(I, collected))

# ---- §1: the side faces counted (Fig. 1) -----------------------------------------------------------
d.step("side-faces", Eq(Sf, ps + qs - kp), "definition", result=Sf,
       note="each side of either base lies in exactly one side face of the hull, and every side face holds at "
            "least one (a plane meeting both bases in single points only is no face); a face holding a side of "
            "each base holds two parallel lines (the bases' planes are parallel), so with k pairs of parallel "
            "corresponding sides the p + q sides fill p + q - k faces")
d.step("side-triangles", Eq(Tf, Sf - kp), "definition", result=Tf,
       note="a face with one side of a base has one vertex of the other: a triangle; the k faces with two "
            "parallel sides are trapezoids")
d.quote("side-faces", "§1 prismatoid faces", "Die Seitenebenen des Prismaoids werden im Allgemeinen Dreiecke sein "
        "und zwar sind deren so viele, wie die Summe der Seiten der beiden Grundflächen",
        reading=(sp.Matrix([sp.Subs(Sf, kp, 0), sp.Subs(Tf, kp, 0)]), sp.Matrix([ps + qs, ps + qs])),
        note="in general (no side of one base parallel to a side of the other) the side faces are triangles, as "
             "many as the sides of both bases together")
d.quote("parallel-sides", "§1 prismatoid faces", "Würden aber zwei der Seiten der beiden Grundflächen parallel, so "
        "fällt die Kante zwischen zwei Dreiecken fort",
        reading=(sp.Matrix([sp.Subs(Sf, kp, 1), sp.Subs(Tf, kp, 1)]), sp.Matrix([ps + qs - 1, ps + qs - 2])),
        note="when a side of the upper base is parallel to the facing side of the lower one, the two triangles "
             "over them lie in one plane: the edge between them drops out and they make one trapezoid, so one "
             "face less and two triangles fewer (read for one such pair; parallel sides facing away from each "
             "other share no face and change nothing)")

# ---- §1: the name of the body ------------------------------------------------------------------------------
d.quote("prismatoid-name", "§1 prismatoid volume", "Ueber das Prismaoid und seinen cubischen Inhalt.",
        unreadable="'Prismaoid' names no body: the word of the title and of Wittstein's treatise is Prismatoid",
        erratum=Erratum("misprint", "medium", r"\text{Ueber das Prismatoid und seinen cubischen Inhalt.}",
                        ("The body of §1, two parallel bases of any form closed by side faces, is Wittstein's "
                         "Prismatoid, as the title ('aus der Lehre über das Wittstein'sche Prismatoid'), the preface "
                         "('über das Prisma- und Prismatoid'), §1 itself two paragraphs on ('zum Beweise der obigen "
                         "Formel für den cubischen Inhalt des Prismatoïds', 'sei ein Prismatoid') and §§2–4 "
                         "throughout write it. 'Prismaoid' stands five times, all in §1 and always so: in this "
                         "heading, in the definition ('Unter Prismaoid verstehen wir'), in 'Die Seitenebenen des "
                         "Prismaoids', in 'aus denen das Prismaoid besteht' and in 'Formel für den Inhalt des "
                         "Prismaoids'. A form repeated alike through a section is the compositor's, which a scan "
                         "does not do (the criteria of the errata's kinds): a misprint. Checked as what the "
                         "heading announces: "
                         "the cubic content of the prismatoid, the sum of its three groups of bodies, is the "
                         "formula the section derives."),
                        corrected_reading=(I, collected),
                        fault="Prismaoid",
                        places=("§1 prismatoid definition", "§1 prismatoid faces", "§1 prismatoid volume",
                                "§1 prismatoid volume"),
                        objection=("'Prismaoid' may be the author's own form of the word in §1, where he defines the "
                                   "body ('Unter Prismaoid verstehen wir'); or the scan's, which garbles the same "
                                   "word once more in §1 ('Prismaatoid')."),
                        answer=("An author who defines a term does not spell it two ways on one page: §1 writes "
                                "'Prismatoïds' and 'Prismatoid' between the places, and the title, the preface and "
                                "§§2–4 keep Wittstein's word. The scan's 'Prismaatoid' is one garbled letter at one "
                                "place; the same letter lost alike at five places, heading included, is the "
                                "printer's pattern. The scan cannot be excluded: medium.")),
        note="the heading of §1; the same name stands at four more places of §1, listed as the erratum's places")
