"""Graefe 1866, §2: consequences of the prismatoid formula.

For every body whose section area ``A(z)`` is a polynomial of degree at most
three in the height ``z``, ``∫_0^h A dz = h/3 ((A(0) + A(h))/2 + 2 A(h/2))``:
the prismatoid formula ``I = h/3 ((G + g)/2 + 2 D)`` of §1 holds with
``G = A(0)``, ``g = A(h)``, ``D = A(h/2)``.  This is why bodies with curved
surfaces are "Specialitäten des Prismatoids".  Graefe applies it to

* the sphere (``G = g = 0``, ``h = 2 r``, ``D = r² π``): ``I = 4 r³ π / 3``;
* the paraboloid of height ``x`` (``y² = 2 p x``): ``I = p x² π``;
* the segment of height ``x`` of the prolate ellipsoid
  (``y² = b²/a² (2 a x - x²)``): ``I = b² π x² (3 a - x) / (3 a²)``, and for
  ``x = a`` the half ellipsoid ``2 a b² π / 3``;

and derives Simpson's rule for volumes from equidistant sections ``a, b, …, g``
at spacing ``m``: ``I = m/3 (a + 4b + 2c + 4d + 2e + 4f + g)``.

The print drops the factor 1/3 from the first slab ``I' = 2m/3 (…)`` on, and
carries the omission through to ``I = m (a + 4b + … + g)``; §4 relies on the
wrong factor (see ``graefe-s4-ship-centroid``).
"""

import mpmath
import sympy as sp

from symfloat import Derivation, Eq, Erratum
from symfloat.engine.quadrature import composite_simpson
from symfloat.engine.witness import SECTION, Case, ConvergenceOrder, PlaneSections, SectionIntegral
from symfloat.registry import load

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
prismatoid = load("graefe-s1-prismatoid-volume")[0].evaluator("prismatoid-volume", (G, g, D, h), 1)


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
                 "omission is the author's (or the printer's), not the scan's.")
CONSEQUENTIAL = ("Follows from the misprint of I' (factor 2m instead of 2m/3, see 'slab-a-c'); the algebra "
                 "from line to line is right.")
d.quote("slab-a-c", "§2 Simpson's rule", r"$$I' = 2m \left\{ \frac{a+c}{2} + 2b \right\}.$$",
        reading=Eq(I1, 2 * m * ((a + c) / 2 + 2 * b)),
        erratum=Erratum("misprint", "high", r"I' = \frac{2m}{3} \left\{ \frac{a+c}{2} + 2b \right\}",
                        MISSING_THIRD, corrected_reading=Eq(I1, 2 * m / 3 * ((a + c) / 2 + 2 * b))))
d.quote("slab-c-e", "§2 Simpson's rule", r"$$I'' = 2m \left\{ \frac{c+e}{2} + 2d \right\}.$$",
        reading=Eq(I2, 2 * m * ((c + e) / 2 + 2 * dd)),
        erratum=Erratum("consequential", "high", r"I'' = \frac{2m}{3} \left\{ \frac{c+e}{2} + 2d \right\}",
                        "The same omission of the factor 1/3 as in I' ('Ebenso').",
                        corrected_reading=Eq(I2, 2 * m / 3 * ((c + e) / 2 + 2 * dd))))
d.quote("slab-e-g", "§2 Simpson's rule", r"$$I''' = 2m \left\{ \frac{e+g}{2} + 2f \right\}.$$",
        reading=Eq(I3, 2 * m * ((e + g) / 2 + 2 * f)),
        erratum=Erratum("consequential", "high", r"I''' = \frac{2m}{3} \left\{ \frac{e+g}{2} + 2f \right\}",
                        "The same omission of the factor 1/3 as in I'.",
                        corrected_reading=Eq(I3, 2 * m / 3 * ((e + g) / 2 + 2 * f))))
d.quote("sum-1", "§2 Simpson's rule",
        r"$$I = 2m \left\{ \frac{a+c}{2} + 2b + \frac{c+e}{2} + 2d + \frac{e+g}{2} + 2f \right\}$$",
        reading=Eq(I, 3 * simp_1),
        erratum=Erratum("consequential", "high",
                        r"I = \frac{2m}{3} \left\{ \frac{a+c}{2} + 2b + \frac{c+e}{2} + 2d + \frac{e+g}{2} + 2f \right\}",
                        CONSEQUENTIAL, corrected_reading=Eq(I, simp_1)))
d.quote("sum-2", "§2 Simpson's rule",
        r"$$I = 2m \left\{ \frac{a+c+4b+c+e+4d+e+g+4f}{2} \right\}$$",
        reading=Eq(I, 3 * simp_2),
        erratum=Erratum("consequential", "high",
                        r"I = \frac{2m}{3} \left\{ \frac{a+c+4b+c+e+4d+e+g+4f}{2} \right\}",
                        CONSEQUENTIAL, corrected_reading=Eq(I, simp_2)))
d.quote("simpson-rule", "§2 Simpson's rule", r"$$I = m \{ a + 4b + 2c + 4d + 2e + 4f + g \}.$$",
        reading=Eq(I, 3 * simp_3),
        erratum=Erratum("consequential", "high", r"I = \frac{m}{3} \{ a + 4b + 2c + 4d + 2e + 4f + g \}",
                        CONSEQUENTIAL + " With m/3 it is Simpson's rule, as the following sentence says; with "
                        "m it overstates every volume threefold (all sections equal to A: 6mA is the volume, "
                        "the print gives 18mA).",
                        corrected_reading=Eq(I, simp_3)))

# the claims in words
Y = [sp.Symbol(f"y_{i}", positive=True) for i in range(7)]
SIMPSON_AREAS = (m / 3 * sum(w * y for w, y in zip(simpson_weights(6), Y))).xreplace(dict(zip(Y, A_sec)))
d.quote("simpson-identical", "§2 Simpson's rule",
        r"Diese Formel ist mit der Simpson'schen Formel zur Berechnung von Flächen, die von einer Curve "
        r"eingeschlossen sind, identisch, mit dem Unterschiede, dass dort die Grössen a, b, c etc. die Ordinaten "
        r"der begränzenden Curve bedeuten, während sie hier die Areale der Theilungsebenen bezeichnen.",
        reading=(3 * simp_3, SIMPSON_AREAS),
        erratum=Erratum("claim", "high",
                        r"I = \frac{m}{3}\{a + 4b + 2c + 4d + 2e + 4f + g\} \text{ is identical with Simpson's rule; "
                        r"the printed } I = m\{\dots\} \text{ is three times it}",
                        "'Diese Formel' is the one printed just above, I = m {a + 4b + 2c + 4d + 2e + 4f + g}. "
                        "Simpson's rule for the ordinates y_0, ..., y_6 at the spacing m is "
                        "m/3 (y_0 + 4y_1 + 2y_2 + 4y_3 + 2y_4 + 4y_5 + y_6); with the ordinates replaced by the "
                        "section areas the printed formula is three times it, not identical with it (y = x^2 "
                        "on [0, 6], m = 1: the area is 72, Simpson's rule gives 216/3 = 72, the printed form "
                        "216; a prism of constant section A and length 6m: 6mA, printed 18mA). The sentence "
                        "holds for the formula derived with the factor 1/3 of the prismatoid formula, which "
                        "the print lost at I' (erratum 'slab-a-c', misprint, high) and carried down to "
                        "'simpson-rule'; the claim fails only through that factor, so it is the author's "
                        "statement about his misprinted line, not a fault of the scan. High: the printed "
                        "factor m and Simpson's m/3 are both unambiguous.",
                        corrected_reading=(I, simp_3, SIMPSON_AREAS)),
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

# ---- witnesses -----------------------------------------------------------------------------------------


def _q(v):
    return sp.Rational(v)


SPHERE_CASES = tuple(Case({r: _q(v)}, label=f"r = {v}") for v in ("1", "3/2", "7/3"))
PARABOLOID_CASES = tuple(Case({p: _q(pv), x: _q(xv)}, label=f"p = {pv}, x = {xv}")
                         for pv, xv in (("1", "2"), ("5/2", "3/4"), ("1/3", "7")))
ELLIPSOID_CASES = tuple(Case({a: _q(av), b: _q(bv), x: _q(xv)}, label=f"a = {av}, b = {bv}, x = {xv}")
                        for av, bv, xv in (("2", "1", "3/2"), ("5/2", "3/2", "4"), ("1", "1/3", "1/5")))
A_e_centre = pi * b ** 2 * (1 - ((x - z) - a) ** 2 / a ** 2)   # from the centre equation, t = x - z

d.witness(SectionIntegral("sphere-volume", "∫ π (r² - (z - r)²) dz over the diameter", ("sphere-volume",),
                          SPHERE_CASES, area=pi * (r ** 2 - (z - r) ** 2), z=z, bounds=(0, 2 * r)))
d.witness(SectionIntegral("paraboloid-volume", "∫ π 2p (x - z) dz over the height", ("paraboloid-volume",),
                          PARABOLOID_CASES, area=pi * 2 * p * (x - z), z=z, bounds=(0, x)))
d.witness(SectionIntegral("ellipsoid-volume", "∫ π b² (1 - (t - a)²/a²) dt over the segment (centre equation)",
                          ("ellipsoid-volume-1", "ellipsoid-volume-2", "ellipsoid-volume-3"), ELLIPSOID_CASES,
                          area=A_e_centre, z=z, bounds=(0, x)))
d.witness(SectionIntegral("half-ellipsoid-volume", "∫ π b² (1 - (t - a)²/a²) dt from the vertex to the centre",
                          ("half-ellipsoid",), tuple(Case({a: c_.params[a], b: c_.params[b], x: c_.params[a]},
                                                          label=f"a = {c_.params[a]}, b = {c_.params[b]}")
                                                     for c_ in ELLIPSOID_CASES),
                          area=A_e_centre, z=z, bounds=(0, a)))

# bodies with cubic section areas (exact for the prismatoid formula and for Simpson's rule)
CUBICS = ((sp.Rational(3), sp.Rational(1, 2), sp.Rational(-1, 5), sp.Rational(1, 40), sp.Rational(1, 2)),
          (sp.Rational(1), sp.Rational(2), sp.Rational(1, 3), sp.Rational(-1, 30), sp.Rational(3, 4)),
          (sp.Rational(5, 2), sp.Rational(-1, 3), sp.Rational(1, 7), sp.Rational(1, 11), sp.Rational(1, 3)))


def _cubic_case(coeffs):
    *ks, mv = coeffs
    values = {kk: v for kk, v in zip(k, ks)}
    area = A3.xreplace(values)
    sections = {s: area.subs(z, i * mv) for i, s in enumerate(A_sec)}
    assert all(area.subs(z, mv * j / 10) > 0 for j in range(61)), "section areas must be positive"
    return Case({**values, m: mv, **sections}, label=f"A(z) = {area}, m = {mv}")


CUBIC_CASES = tuple(_cubic_case(cf) for cf in CUBICS)
for name, targets, lo in (("slab-a-c", ("slab-a-c",), 0), ("slab-c-e", ("slab-c-e",), 2),
                          ("slab-e-g", ("slab-e-g",), 4)):
    d.witness(SectionIntegral(name, f"∫ A dz over the slab {name[5:]} of bodies with cubic section areas",
                              targets, CUBIC_CASES, area=A3, z=z, bounds=(lo * m, (lo + 2) * m)))
d.witness(SectionIntegral("whole-body", "∫ A dz over 6m for bodies with cubic section areas",
                          ("sum-1", "sum-2", "simpson-rule", "simpson-identical"), CUBIC_CASES,
                          area=A3, z=z, bounds=(0, 6 * m)))


d.witness(SectionIntegral("odd-number-of-sections", "∫ A dz over 2m, 4m, 6m, 8m for bodies with cubic section areas",
                          ("odd-number-of-sections",), CUBIC_CASES, area=A3, z=z,
                          bounds=tuple((0, 2 * n * m) for n in range(1, 5))))


def _reciprocal(u):
    return 1 / (1 + u)


d.witness(ConvergenceOrder("simpson-order-exp", "composite Simpson on ∫_0^1 exp",
                           ("simpson-identical", "odd-number-of-sections"), composite_simpson, mpmath.exp,
                           (mpmath.mpf(0), mpmath.mpf(1)), mpmath.e - 1, 4))
# (not 1/(1+z²) on [0, 1]: its third derivative vanishes at both ends, which cancels the h⁴ term
# of the error and makes the measured order 6)
d.witness(ConvergenceOrder("simpson-order-reciprocal", "composite Simpson on ∫_0^1 1/(1+z)",
                           ("simpson-identical", "odd-number-of-sections"), composite_simpson, _reciprocal,
                           (mpmath.mpf(0), mpmath.mpf(1)), mpmath.log(2), 4))

# the sections named by the text, measured across their chords (the circle of radius² ρ²(z) written with the
# chord coordinate ρ sin η, so that the integrand 2ρ² cos²η stays smooth)
eta, zp = sp.symbols("eta z_P", real=True)


def _round(rho2):
    return {"width": 2 * rho2 * sp.cos(eta) ** 2, "chord": (-pi / 2, pi / 2), "position": zp, "across": eta}


d.witness(PlaneSections("sphere-section-areas", "sections of the sphere at both poles and the centre",
                        ("sphere-sections",), SPHERE_CASES, planes=(r, 0, 2 * r),   # a non-empty section first
                        combine=(SECTION[1], SECTION[2], SECTION[0]), **_round(r ** 2 - (zp - r) ** 2)))
for name, plane in (("paraboloid-base-radius", 0), ("paraboloid-mid-radius", x / 2)):
    d.witness(PlaneSections(f"{name}-section", "section of the paraboloid y² = 2pt (t from the vertex, t = x - z)",
                            (name,), PARABOLOID_CASES, planes=(plane,),
                            combine=SECTION[0] / pi, **_round(2 * p * (x - zp))))
d.witness(PlaneSections("ellipse-chords", "the ellipsoid's sections at the base and the mid-section, over pi",
                        ("ellipsoid-radii",), ELLIPSOID_CASES, planes=(0, x / 2),
                        combine=(SECTION[0] / pi, SECTION[1] / pi), **_round(A_e_centre.subs(z, zp) / pi)))
d.witness(SectionIntegral("half-ellipsoid-segment", "∫ π b² (1 - (t - a)²/a²) dt over the segment of height a",
                          ("half-ellipsoid-x-a",), tuple(Case({a: c_.params[a], b: c_.params[b], x: c_.params[a]},
                                                               label=f"a = {c_.params[a]}, b = {c_.params[b]}")
                                                          for c_ in ELLIPSOID_CASES),
                          area=A_e_centre, z=z, bounds=(0, a)))

# "so kann die eine oder auch beide Null sein": a pyramid (g = 0, D = G/4) and a body whose section area
# 4 D z (h - z)/h² vanishes at both ends (G = g = 0)
ZERO_BASE_AREAS = (G * (1 - z / h) ** 2, 4 * D * z * (h - z) / h ** 2)
d.quote("zero-bases", "§2 prismatoid formula",
        r"so kann die eine oder auch beide Null sein.",
        reading=(sp.Matrix([sp.Integral(A_, (z, 0, h)) for A_ in ZERO_BASE_AREAS]),
                 sp.Matrix([prismatoid(G, 0, G / 4, h), prismatoid(0, 0, D, h)])),
        note="read on a pyramid over G (g = 0) and on a body with G = g = 0 and quadratic sections")


d.witness(SectionIntegral("zero-bases-volumes", "∫ A dz of a pyramid and of a body with both bases zero",
                          ("zero-bases",), (Case({G: 3, D: 2, h: sp.Rational(5, 2)}, label="G = 3, D = 2, h = 5/2"),
                                            Case({G: sp.Rational(7, 3), D: sp.Rational(1, 2), h: 4},
                                                 label="G = 7/3, D = 1/2, h = 4")),
                          area=ZERO_BASE_AREAS, z=z, bounds=(0, h)))


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
