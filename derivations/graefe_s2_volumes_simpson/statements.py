"""What Graefe's §2 says and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import Derivation, Eq, Erratum

from ..graefe_s1_prismatoid_volume.statements import DERIVATION as PRISMATOID_VOLUME

G, g, D, h, z, t = sp.symbols("G g D h z t", positive=True)
r, p, x, m = sp.symbols("r p x m", positive=True)
# a, b: the semi-axes of the ellipse; a, b, …, g also name the section areas of
# Simpson's rule, as in the print (the two uses never meet in one claim)
a, b, c, dd, e, f = sp.symbols("a b c d e f", positive=True)
k = sp.symbols("k_0:4", real=True)
I_s, I_p, I_e, I_h = sp.symbols("I_sphere I_paraboloid I_ellipsoid I_half", positive=True)
I1, I2, I3, I = sp.symbols("I' I'' I''' I", positive=True)
pi = sp.pi


# Graefe's §1 formula I = h/3 ((G + g)/2 + 2 D) at given (G, g, D, h): the reading of §1's print
prismatoid = PRISMATOID_VOLUME.evaluator("prismatoid-volume", (G, g, D, h), 1)


Rb, rt, ng = sp.symbols("R rho N", positive=True)   # radii of the frustum's bases, number of sides


DERIVATION = d = Derivation(
    id="graefe-s2-volumes-simpson",
    source="graefe",
    title="Sphere, paraboloid, ellipsoid and Simpson's rule from the prismatoid formula",
    locator="§2",
    summary="The prismatoid formula is exact for every cubic section area; the volumes of the sphere, "
            "the paraboloid and the ellipsoid segment; Simpson's rule I = m/3 (a + 4b + 2c + … + g) "
            "(printed without the factor 1/3).",
    requires=("graefe-s1-prismatoid-volume",),
    domain={**{s: (1, 20) for s in (G, g, D, h, t, r, p, x, a, b, c, dd, e, f, m)},
            **{s: (-5, 5) for s in k}, Rb: (1, 5), rt: (1, 5)},
    constraints=(x <= 2 * a,),
    assumptions=("the bodies are solids of revolution about the z axis, z measured from the plane G",
                 "the ellipsoid segment is not higher than the ellipsoid: x <= 2a",
                 "the section areas a, b, …, g of Simpson's rule are positive and equidistant (spacing m)"),
)

# ---- the prismatoid formula for cubic section areas ---------------------------------
A3 = k[0] + k[1] * z + k[2] * z ** 2 + k[3] * z ** 3
d.step("cubic-sections", (sp.Integral(A3, (z, 0, h)), prismatoid(A3.subs(z, 0), A3.subs(z, h), A3.subs(z, h / 2), h)),
       "integration", uses=("graefe-s1-prismatoid-volume:volume-collected",),
       note="for every section area that is a polynomial of degree <= 3 in z, the prismatoid formula with "
            "G = A(0), g = A(h), D = A(h/2) is the exact volume: curved bodies of this kind are "
            "'Specialitäten des Prismatoids', and Simpson's rule is exact for cubics")

# ---- the sphere -----------------------------------------------------------------------
A_s = pi * (r ** 2 - (z - r) ** 2)        # section at height z above the lowest point: Pythagoras
d.step("sphere-sections", (sp.Matrix([sp.Subs(A_s, z, 0), sp.Subs(A_s, z, 2 * r), sp.Subs(A_s, z, r)]),
                           sp.Matrix([0, 0, r ** 2 * pi])), "substitution",
       note="A(z) = π (r² - (z - r)²); G = A(0), g = A(2r), D = A(r)")
d.step("sphere-volume", Eq(I_s, prismatoid(0, 0, r ** 2 * pi, 2 * r)), "lemma",
       uses=("graefe-s1-prismatoid-volume:volume-collected", "sphere-sections", "cubic-sections"), result=I_s)
d.step("sphere-volume-integral", (I_s, sp.Integral(A_s, (z, 0, 2 * r))), "integration", uses=("sphere-volume",),
       note="the same volume by direct integration of the section areas")
with sp.evaluate(False):   # the print's arithmetic, kept for the engine to carry out
    sphere_printed = 2 * r / 3 * (2 * r ** 2 * pi)
    paraboloid_printed = x / 3 * (p * x * pi + 2 * p * x * pi)
d.step("sphere-volume-value", (I_s, sphere_printed, 4 * r ** 3 * pi / 3), "algebra",
       uses=("sphere-volume",))

d.quote("sphere-sections", "§2 sphere", r"$G$  und  $g$  Null setzen,  $h = 2r$ ,  $D = r^2\pi$",
        reading=(sp.Matrix([sp.Subs(A_s, z, 0), sp.Subs(A_s, z, 2 * r), sp.Subs(A_s, z, r)]), sp.Matrix([0, 0, r ** 2 * pi])))
d.quote("sphere-volume", "§2 sphere", r"$$I = \frac{2r}{3} \times 2r^2\pi = \frac{4r^3\pi}{3}.$$",
        reading=(I_s, sphere_printed, 4 * r ** 3 * pi / 3))

# ---- the paraboloid -----------------------------------------------------------------------
# y² = 2 p t at distance t from the vertex; the base G (radius y) lies at t = x, i.e. z = 0
A_p = pi * 2 * p * (x - z)
d.step("paraboloid-sections", (sp.Matrix([sp.Subs(A_p, z, 0), sp.Subs(A_p, z, x), sp.Subs(A_p, z, x / 2)]),
                               sp.Matrix([2 * p * x * pi, 0, p * x * pi])), "substitution",
       note="vertex equation y² = 2pt, t = x - z: G = 2pxπ, g = 0 (the vertex), D = pxπ (y'² = px)")
d.step("paraboloid-volume", Eq(I_p, prismatoid(2 * p * x * pi, 0, p * x * pi, x)), "lemma",
       uses=("graefe-s1-prismatoid-volume:volume-collected", "paraboloid-sections", "cubic-sections"), result=I_p)
d.step("paraboloid-volume-integral", (I_p, sp.Integral(A_p, (z, 0, x))), "integration", uses=("paraboloid-volume",))
d.step("paraboloid-volume-value", (I_p, paraboloid_printed, p * x ** 2 * pi), "algebra",
       uses=("paraboloid-volume",))

d.quote("paraboloid-base-radius", "§2 paraboloid", r"$y^2 = 2px$", reading=(sp.Subs(A_p, z, 0) / pi, 2 * p * x))
d.quote("paraboloid-mid-radius", "§2 paraboloid", r"$y'^2 = px$", reading=(sp.Subs(A_p, z, x / 2) / pi, p * x))
d.quote("paraboloid-volume", "§2 paraboloid",
        r"$$I = \frac{x}{3} \left\{ px\pi + 2px\pi \right\} = px^2\pi.$$",
        reading=(I_p, paraboloid_printed, p * x ** 2 * pi))

# ---- the ellipsoid ---------------------------------------------------------------------------
d.step("ellipse-vertex-equation", (b ** 2 * (1 - (t - a) ** 2 / a ** 2), b ** 2 / a ** 2 * (2 * a * t - t ** 2)),
       "geometry", note="the centre equation (t - a)²/a² + y²/b² = 1 with t measured from the vertex")
A_e = pi * b ** 2 / a ** 2 * (2 * a * (x - z) - (x - z) ** 2)   # base G at t = x (z = 0), vertex at z = x
d.step("ellipsoid-sections", (sp.Matrix([sp.Subs(A_e, z, 0), sp.Subs(A_e, z, x), sp.Subs(A_e, z, x / 2)]),
                              sp.Matrix([pi * b ** 2 / a ** 2 * (2 * a * x - x ** 2), 0,
                                         pi * b ** 2 / a ** 2 * (a * x - x ** 2 / 4)])), "substitution",
       uses=("ellipse-vertex-equation",))
d.step("ellipsoid-volume", Eq(I_e, prismatoid(pi * b ** 2 / a ** 2 * (2 * a * x - x ** 2), 0,
                                                 pi * b ** 2 / a ** 2 * (a * x - x ** 2 / 4), x)), "lemma",
       uses=("graefe-s1-prismatoid-volume:volume-collected", "ellipsoid-sections", "cubic-sections"), result=I_e)
d.step("ellipsoid-volume-integral", (I_e, sp.Integral(A_e, (z, 0, x))), "integration", uses=("ellipsoid-volume",))
with sp.evaluate(False):   # the printed forms, as printed
    ell_1 = x / 3 * (b ** 2 * pi / a ** 2) * ((2 * a * x - x ** 2) / 2 + 2 * a * x - x ** 2 / 2)
    ell_2 = x / 3 * (b ** 2 * pi / a ** 2) * ((2 * a * x - x ** 2 + 4 * a * x - x ** 2) / 2)
    ell_3 = x / 3 * (b ** 2 * pi / a ** 2) * (3 * a * x - x ** 2)
    ell_4 = b ** 2 * pi * x ** 2 / (3 * a ** 2) * (3 * a - x)
d.step("ellipsoid-volume-value", (I_e, ell_1, ell_2, ell_3, ell_4), "algebra", uses=("ellipsoid-volume",))
d.step("half-ellipsoid", Eq(I_h, sp.Integral(pi * b ** 2 / a ** 2 * (2 * a * t - t ** 2), (t, 0, a))),
       "definition", note="half the ellipsoid: the segment of height a, from the vertex to the centre",
       result=I_h)
d.step("half-ellipsoid-value", (I_h, sp.Subs(ell_4, x, a), 2 * a * b ** 2 * pi / 3), "substitution",
       uses=("half-ellipsoid", "ellipsoid-volume-value"))

d.quote("ellipsoid-radii", "§2 ellipsoid",
        r"$$y^2 = \frac{b^2}{a^2} \left\{ 2ax - x^2 \right\}, y'^2 = \frac{b^2}{a^2} \left\{ ax - \frac{x^2}{4} \right\},$$",
        reading=(sp.Matrix([sp.Subs(A_e, z, 0) / pi, sp.Subs(A_e, z, x / 2) / pi]),
                 sp.Matrix([b ** 2 / a ** 2 * (2 * a * x - x ** 2), b ** 2 / a ** 2 * (a * x - x ** 2 / 4)])))
d.quote("ellipsoid-volume-1", "§2 ellipsoid",
        r"$$I = \frac{x}{3} \frac{b^2 \pi}{a^2} \left\{ \frac{2ax - x^2}{2} + 2ax - \frac{x^2}{2} \right\}$$",
        reading=Eq(I_e, ell_1))
d.quote("ellipsoid-volume-2", "§2 ellipsoid",
        r"$$I = \frac{x}{3} \frac{b^2 \pi}{a^2} \left\{ \frac{2ax - x^2 + 4ax - x^2}{2} \right\}$$",
        reading=Eq(I_e, ell_2))
d.quote("ellipsoid-volume-3", "§2 ellipsoid",
        r"$$I = \frac{x}{3} \frac{b^2 \pi}{a^2} \left\{ 3ax - x^2 \right\} = \frac{b^2 \pi x^2}{3a^2} \left\{ 3a - x \right\}.$$",
        reading=(I_e, ell_3, ell_4))
d.quote("half-ellipsoid", "§2 half ellipsoid", r"$$I = \frac{2ab^2\pi}{3}. —$$",
        reading=(I_h, 2 * a * b ** 2 * pi / 3))

d.quote("half-ellipsoid-x-a", "§2 half ellipsoid", r"Setzt man hierin  $x = a$ , so kommt für das halbe Ellipsoid",
        reading=(sp.Subs(ell_4, x, a), I_h), note="the segment of height x = a is the half ellipsoid")

# ---- Simpson's rule ------------------------------------------------------------------------------
d.step("slab-a-c", Eq(I1, prismatoid(a, c, b, 2 * m)), "lemma",
       uses=("graefe-s1-prismatoid-volume:volume-collected",), result=I1,
       note="the body between the sections a and c as a prismatoid: G = a, D = b, g = c, h = 2m")
d.step("slab-a-c-value", (I1, 2 * m / 3 * ((a + c) / 2 + 2 * b)), "algebra", uses=("slab-a-c",))
d.step("slab-c-e", Eq(I2, prismatoid(c, e, dd, 2 * m)), "lemma",
       uses=("graefe-s1-prismatoid-volume:volume-collected",), result=I2)
d.step("slab-c-e-value", (I2, 2 * m / 3 * ((c + e) / 2 + 2 * dd)), "algebra", uses=("slab-c-e",))
d.step("slab-e-g", Eq(I3, prismatoid(e, g, f, 2 * m)), "lemma",
       uses=("graefe-s1-prismatoid-volume:volume-collected",), result=I3)
d.step("slab-e-g-value", (I3, 2 * m / 3 * ((e + g) / 2 + 2 * f)), "algebra", uses=("slab-e-g",))
d.step("sum", Eq(I, I1 + I2 + I3), "definition", uses=("slab-a-c", "slab-c-e", "slab-e-g"), result=I,
       note="the whole body is the union of the three slabs")
with sp.evaluate(False):   # the three printed forms of the sum, as printed
    simp_1 = 2 * m / 3 * ((a + c) / 2 + 2 * b + (c + e) / 2 + 2 * dd + (e + g) / 2 + 2 * f)
    simp_2 = 2 * m / 3 * ((a + c + 4 * b + c + e + 4 * dd + e + g + 4 * f) / 2)
    simp_3 = m / 3 * (a + 4 * b + 2 * c + 4 * dd + 2 * e + 4 * f + g)
d.step("simpson-7", (I, simp_1, simp_2, simp_3), "algebra", uses=("sum",))


def simpson_weights(panels):
    return [1 if i in (0, panels) else (4 if i % 2 else 2) for i in range(panels + 1)]


def simpson(A, panels):
    """Composite Simpson rule of the sections A(0), A(m), …, A(panels m)."""
    return m / 3 * sum(w * A.subs(z, i * m) for i, w in enumerate(simpson_weights(panels)))


for n_slabs in range(1, 5):
    d.step(f"simpson-cubic-{2 * n_slabs + 1}-sections",
           (sp.Integral(A3, (z, 0, 2 * n_slabs * m)), simpson(A3, 2 * n_slabs)), "integration",
           uses=("cubic-sections",),
           note=f"{2 * n_slabs + 1} sections ({n_slabs} slabs of thickness 2m): the composite rule is exact "
                f"for every cubic section area")

A_sec = [a, b, c, dd, e, f, g]
TOTAL = sum(w * s for w, s in zip(simpson_weights(6), A_sec))

MISSING_THIRD = ("The prismatoid formula I = h/3 ((G+g)/2 + 2D) with G = a, D = b, g = c and h = 2m gives "
                 "2m/3 {...}; the print has 2m {...}. The factor 1/3 is missing from all three slabs, from both "
                 "sums and from the final I = m {...}, and §4 divides by the same V = m {...} (its printed "
                 "centroid carries m/3 instead of m), while §4 itself writes v' = 2m/3 {...} correctly: the "
                 "omission is the author's (or the printer's), not the scan's. I'' and I''' ('Ebenso') apply the "
                 "prismatoid formula anew to their own slabs, not I', and print the same 2m {...}: further places of "
                 "this fault, booked as its repeats; the sums below follow from the three wrong slabs.")
CONSEQUENTIAL = ("Follows from the misprinted slabs I', I'', I''' (factor $2m$ instead of $2m/3$, see 'slab-a-c'); "
                 "the algebra from line to line is right.")
REPEAT = ("The omission of the factor 1/3 of I' again. This slab is the prismatoid formula applied anew ('Ebenso'), "
          "with its own sections for $G, D, g$ and $h = 2m$, not a result computed from I': the same misprint at a "
          "further place (booked as a repeat of slab-a-c), not a consequence of I'.")
REPEAT_OBJECTION = ("The slab follows I' with 'Ebenso' and copies its pattern: a consequence of the first slip, "
                    "hence consequential.")
REPEAT_ANSWER = ("A consequential fault uses an earlier wrong result; this slab uses none, only the prismatoid formula "
                 "with its own sections, which the print applies wrongly again. As for I', m is the spacing and §4 "
                 "writes the same slabs with 2m/3.")
d.quote("slab-a-c", "§2 Simpson's rule", r"$$I' = 2m \left\{ \frac{a+c}{2} + 2b \right\}.$$",
        reading=Eq(I1, 2 * m * ((a + c) / 2 + 2 * b)),
        erratum=Erratum("misprint", "high", r"I' = \frac{2m}{3} \left\{ \frac{a+c}{2} + 2b \right\}",
                        MISSING_THIRD, corrected_reading=Eq(I1, 2 * m / 3 * ((a + c) / 2 + 2 * b)),
                        objection="Graefe may absorb the 1/3 into a unit of his own (m standing for a third of the "
                                  "spacing), a convention under which 2m {...} is right.",
                        answer="m is the spacing of the sections (each slab has the height 2m), and §4 writes the "
                               "same slab v' = 2m/3 {...} with the same m; with m as defined the printed slab is "
                               "three times the prismatoid formula's value."))
d.quote("slab-c-e", "§2 Simpson's rule", r"$$I'' = 2m \left\{ \frac{c+e}{2} + 2d \right\}.$$",
        reading=Eq(I2, 2 * m * ((c + e) / 2 + 2 * dd)),
        erratum=Erratum("misprint", "high", r"I'' = \frac{2m}{3} \left\{ \frac{c+e}{2} + 2d \right\}",
                        REPEAT, corrected_reading=Eq(I2, 2 * m / 3 * ((c + e) / 2 + 2 * dd)),
                        same_as="graefe-s2-volumes-simpson/slab-a-c", objection=REPEAT_OBJECTION,
                        answer=REPEAT_ANSWER))
d.quote("slab-e-g", "§2 Simpson's rule", r"$$I''' = 2m \left\{ \frac{e+g}{2} + 2f \right\}.$$",
        reading=Eq(I3, 2 * m * ((e + g) / 2 + 2 * f)),
        erratum=Erratum("misprint", "high", r"I''' = \frac{2m}{3} \left\{ \frac{e+g}{2} + 2f \right\}",
                        REPEAT, corrected_reading=Eq(I3, 2 * m / 3 * ((e + g) / 2 + 2 * f)),
                        same_as="graefe-s2-volumes-simpson/slab-a-c", objection=REPEAT_OBJECTION,
                        answer=REPEAT_ANSWER))
d.quote("sum-1", "§2 Simpson's rule",
        r"$$I = 2m \left\{ \frac{a+c}{2} + 2b + \frac{c+e}{2} + 2d + \frac{e+g}{2} + 2f \right\}$$",
        reading=Eq(I, 3 * simp_1),
        erratum=Erratum("consequential", "high",
                        r"I = \frac{2m}{3} \left\{ \frac{a+c}{2} + 2b + \frac{c+e}{2} + 2d + \frac{e+g}{2} + 2f \right\}",
                        CONSEQUENTIAL, corrected_reading=Eq(I, simp_1),
                        objection="As for I': a convention absorbing the 1/3.",
                        answer="The sum of the three slabs carries their factor; the algebra is right and the fault "
                               "is that of the slabs I', I'', I'''."))
d.quote("sum-2", "§2 Simpson's rule",
        r"$$I = 2m \left\{ \frac{a+c+4b+c+e+4d+e+g+4f}{2} \right\}$$",
        reading=Eq(I, 3 * simp_2),
        erratum=Erratum("consequential", "high",
                        r"I = \frac{2m}{3} \left\{ \frac{a+c+4b+c+e+4d+e+g+4f}{2} \right\}",
                        CONSEQUENTIAL, corrected_reading=Eq(I, simp_2),
                        objection="As for I': a convention absorbing the 1/3.",
                        answer="The sum of the three slabs carries their factor; the algebra is right and the fault "
                               "is that of the slabs I', I'', I'''."))
d.quote("simpson-rule", "§2 Simpson's rule", r"$$I = m \{ a + 4b + 2c + 4d + 2e + 4f + g \}.$$",
        reading=Eq(I, 3 * simp_3),
        erratum=Erratum("consequential", "high", r"I = \frac{m}{3} \{ a + 4b + 2c + 4d + 2e + 4f + g \}",
                        CONSEQUENTIAL + " With m/3 it is Simpson's rule, as the following sentence says; with "
                        "m it overstates every volume threefold (all sections equal to A: 6mA is the volume, "
                        "the print gives 18mA).",
                        corrected_reading=Eq(I, simp_3),
                        objection="As for I': a convention absorbing the 1/3; then I = m{a + 4b + ... + g} would be "
                                  "Simpson's rule in Graefe's unit.",
                        answer="With m the spacing the printed rule overstates every volume threefold (equal "
                               "sections A over the length 6m: 6mA, the print 18mA), and Simpson's rule carries the "
                               "m/3."))

# the claims in words
Y = [sp.Symbol(f"y_{i}", positive=True) for i in range(7)]
SIMPSON_AREAS = (m / 3 * sum(w * y for w, y in zip(simpson_weights(6), Y))).xreplace(dict(zip(Y, A_sec)))
d.quote("simpson-identical", "§2 Simpson's rule",
        r"Diese Formel ist mit der Simpson'schen Formel zur Berechnung von Flächen, die von einer Curve "
        r"eingeschlossen sind, identisch, mit dem Unterschiede, dass dort die Grössen a, b, c etc. die Ordinaten "
        r"der begränzenden Curve bedeuten, während sie hier die Areale der Theilungsebenen bezeichnen.",
        reading=(3 * simp_3, SIMPSON_AREAS),
        erratum=Erratum("claim", "medium",
                        r"I = \frac{m}{3}\{a + 4b + 2c + 4d + 2e + 4f + g\} \text{ is identical with Simpson's rule; "
                        r"the printed } I = m\{\dots\} \text{ is three times it}",
                        (r"'Diese Formel' is the one printed just above, $I = m \{a + 4b + 2c + 4d + 2e + 4f + g\}$. "
                         r"Simpson's rule for the ordinates $y_0, \dots, y_6$ at the spacing $m$ is $\tfrac{m}{3} "
                         "(y_0 + 4y_1 + 2y_2 + 4y_3 + 2y_4 + 4y_5 + y_6)$; with the ordinates replaced by the "
                         "section areas the printed formula is three times it, not identical with it ($y = x^2$ on "
                         "$[0, 6]$, $m = 1$: the area is $72$, Simpson's rule gives $216/3 = 72$, the printed form "
                         "$216$; a prism of constant section $A$ and length $6m$: $6mA$, printed $18mA$). The "
                         r"sentence holds for the formula derived with the factor $\tfrac13$ of the prismatoid "
                         "formula, which the print lost at $I'$ (an erratum of its own, misprint, high) and carried "
                         "down to Simpson's rule; the claim fails only through that factor, so it is the author's "
                         "statement about his misprinted line, not a fault of the scan. High: the printed factor $m$ "
                         "and Simpson's $m/3$ are both unambiguous."),
                        corrected_reading=(I, simp_3, SIMPSON_AREAS),
                        objection="'identisch' may mean identical in form (the weights 1, 4, 2, 4, ..., 4, 1 that "
                                  "define Simpson's rule), not equal in value, the factor in front being a matter of"
                                  " units.",
                        answer="The weights are Simpson's, and the sentence is true of the formula derived with the "
                               "factor 1/3; of the formula printed just above, which it calls 'Diese Formel', it is "
                               "not: its value is three times Simpson's. The form-only reading is defensible, so the"
                               " claim is lowered to medium."),
        note="Simpson's rule for the area under a curve with the ordinates y_0, …, y_6 at spacing m, "
             "m/3 (y_0 + 4y_1 + 2y_2 + … + y_6), with the ordinates replaced by the section areas, is the "
             "derived volume; the printed formula m {…} is three times it.")
d.quote("odd-number-of-sections", "§2 Simpson's rule",
        r"Das Gesetz der Coefficienten ist einleuchtend und kann die Formel beliebig ausgedehnt werden, nur muss "
        r"die Zahl der Theilungsebenen immer eine ungrade sein, damit man eine grade Zahl von Körpertheilen erhält.",
        reading=(sp.Matrix([sp.Integral(A3, (z, 0, 2 * n * m)) for n in range(1, 5)]),
                 sp.Matrix([simpson(A3, 2 * n) for n in range(1, 5)])),
        note="read as: for 2n + 1 equidistant sections (n = 1..4; the slabs pair off) the weights "
             "1, 4, 2, 4, …, 2, 4, 1 times m/3 give the volume, exactly when the section area is a cubic "
             "polynomial of the height. The factor m/3 (printed m) is the erratum of 'simpson-rule'.")

# "so kann die eine oder auch beide Null sein": a pyramid (g = 0, D = G/4) and a body whose section area
# 4 D z (h - z)/h² vanishes at both ends (G = g = 0)
ZERO_BASE_AREAS = (G * (1 - z / h) ** 2, 4 * D * z * (h - z) / h ** 2)
d.quote("zero-bases", "§2 prismatoid formula",
        r"so kann die eine oder auch beide Null sein.",
        reading=(sp.Matrix([sp.Integral(A_, (z, 0, h)) for A_ in ZERO_BASE_AREAS]),
                 sp.Matrix([prismatoid(G, 0, G / 4, h), prismatoid(0, 0, D, h)])),
        note="read on a pyramid over G (g = 0) and on a body with G = g = 0 and quadratic sections")

# ---- infinitely many sides: curved bodies as prismatoids -------------------------------------------------
def _ngon(radius):
    """The area of the regular N-gon of circumradius *radius*."""
    return ng / 2 * radius ** 2 * sp.sin(2 * pi / ng)


d.quote("infinitely-many-sides", "§2 curved surfaces",
        "Ferner können wir die Zahl der Seiten der beiden Grundflächen, von der die Formel ebenfalls unabhängig "
        "entwickelt, unendlich setzen, so wie die Seiten selbst unendlich klein, so dass dieselben krumme Linien "
        "werden",
        reading=(sp.Limit(prismatoid(_ngon(Rb), _ngon(rt), _ngon((Rb + rt) / 2), h), ng, sp.oo),
                 sp.Integral(pi * (Rb + (rt - Rb) * z / h) ** 2, (z, 0, h))),
        note="the formula holds for any number of sides, so also in the limit of infinitely many: the "
             "prismatoids between regular N-gons of circumradii R and ρ (their mid-section the N-gon of "
             "radius (R + ρ)/2) tend, as N → ∞, to the frustum of a cone, and the formula's limit is the "
             "frustum's volume ∫π r(z)² dz")
