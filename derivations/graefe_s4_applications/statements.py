"""What Graefe's §4 says of the bodies other than the ship and how each formula is derived (see the package's
docstring)."""
import sympy as sp

from symfloat import Derivation, Eq, Erratum
from symfloat.model.claim import as_printed
from symfloat.model.symbol_names import symbol

from ..graefe_s3_prismatoid_centroid.statements import D as S3_D
from ..graefe_s3_prismatoid_centroid.statements import DERIVATION as PRISMATOID_CENTROID
from ..graefe_s3_prismatoid_centroid.statements import G as S3_G
from ..graefe_s3_prismatoid_centroid.statements import g as S3_g
from ..graefe_s3_prismatoid_centroid.statements import h as S3_h

u, t, xi, P, eta = sp.symbols("u t xi P eta", real=True)
r, R, h, m, a, b, c, p, k, S, s = sp.symbols("r R h m a b c p k S s", positive=True)
x, xp = sp.symbols("x x'", positive=True)
xv, xvp = sp.symbols("x_v x'_v", positive=True)
y, yp, n = sp.symbols("y y' n", positive=True)
pi = sp.pi

S3 = "graefe-s3-prismatoid-centroid"
# the prismatoid centroid X = h (g/2 + D)/((G + g)/2 + 2D) above G at given (G, g, D, h): the reading of §3's print
centroid = PRISMATOID_CENTROID.evaluator("centroid", (S3_G, S3_g, S3_D, S3_h), 1)
QUADRATIC = (r"$A(u)$ is a polynomial of degree at most 2 in $u$, so the prismatoid formula of §3 is exact "
             f"for this body ({S3}:centroid-quadratic-sections)")

DERIVATION = d = Derivation(
    id="graefe-s4-applications",
    source="graefe",
    title="Applications of the centroid formula of the prismatoid",
    locator="§4",
    summary="Centroids of the sphere, frusta of cone and pyramid, spherical, parabolic and "
            "ellipsoidal segments, an elliptic body with triangular sections and the triaxial "
            "ellipsoid stump, each from X = h (g/2 + D)/((G+g)/2 + 2D) and by direct integration.",
    requires=("graefe-s3-prismatoid-centroid",),
    domain={r: (4, 6), R: (1, 5), h: (1, 5), m: (1, 4), a: (4, 6), b: (1, 5), c: (1, 5), p: (1, 5),
            k: (0.5, 3), S: (1, 5), s: (1, 5), x: (0, 2), xp: (2, 4), xv: (3, 5), xvp: (1, 3), u: (0, 1)},
    constraints=(x < xp, xp < r, xp <= a, m < r, xvp < xv),
    assumptions=("all lengths positive; u is the height above the base G",
                 "spherical segments: 0 < m < r and 0 < x < x' < r (G nearer the centre, the larger base)",
                 "ellipsoids: 0 < x < x' <= a, rotation about the major axis a",
                 "paraboloid with two bases: x'_v < x_v (G farther from the vertex)",
                 "elliptic body: m > 1, so that the section at height h/m lies inside the body",
                 "pyramid frustum: bases similar, area k S^2 and k s^2 for corresponding sides S, s"),
)


def body(slug, key, area, height, G_val, D_val, g_val, note):
    """The steps every body shares: its section area ``A(u)``, the sections
    ``G = A(0)``, ``D = A(h/2)``, ``g = A(h)``, the centroid by the prismatoid
    formula and the same centroid by direct integration.  Returns the symbols
    ``(G, D, g, X)``."""
    words = slug.replace("-", " ")
    A, G, D, g, X = (symbol(f"{q}_{{{key}}}", rf"{q}_{{\text{{{words}}}}}") for q in "AGDgX")
    d.step(f"{slug}-section", Eq(A, area), "definition", note=note, result=A)
    sec = (f"{slug}-section",)
    d.step(f"{slug}-G", (G, sp.Subs(area, u, 0), G_val), "substitution", uses=sec, result=G)
    d.step(f"{slug}-D", (D, sp.Subs(area, u, height / 2), D_val), "substitution", uses=sec, result=D)
    d.step(f"{slug}-g", (g, sp.Subs(area, u, height), g_val), "substitution", uses=sec, result=g)
    d.step(f"{slug}-centroid", Eq(X, centroid(G, g, D, height)), "lemma",
           uses=(f"{S3}:centroid", f"{S3}:centroid-quadratic-sections", f"{slug}-G", f"{slug}-D", f"{slug}-g"),
           note=QUADRATIC, result=X)
    d.step(f"{slug}-centroid-by-integration",
           (X, sp.Integral(u * A, (u, 0, height)) / sp.Integral(A, (u, 0, height))), "integration",
           uses=(f"{slug}-centroid", f"{slug}-section"),
           note="the formula agrees with the centroid by its definition")
    return G, D, g, X


# ---- sphere ------------------------------------------------------------------------
h_sp = symbol("h_{sp}", r"h_{\text{sphere}}")
d.step("sphere-height", Eq(h_sp, 2 * r), "definition", note="from pole to pole", result=h_sp)
area_sp = pi * (r ** 2 - (u - r) ** 2)
G_sp, D_sp, g_sp, X_sp = body("sphere", "sp", area_sp, h_sp, 0, pi * r ** 2, 0,
                              "circle of radius sqrt(r^2 - (u - r)^2), u measured from the lower pole")
d.quote("sphere-sections", "§4 sphere", r"Für die Kugel ist  $G$  und  $g = 0$ ,  $D = r^2\pi$ ,  $h = 2r$",
        reading=(sp.Matrix([G_sp, g_sp, D_sp, h_sp]), sp.Matrix([0, 0, r ** 2 * pi, 2 * r])))
d.quote("sphere", "§4 sphere", r"$$X = 2r \frac{r^2\pi}{2r^2\pi} = r.$$",
        reading=as_printed(lambda: (X_sp, 2 * r * (r ** 2 * pi / (2 * r ** 2 * pi)), r)))

# ---- cone frustum --------------------------------------------------------------------
area_cf = pi * (R + (r - R) * u / h) ** 2
G_cf, D_cf, g_cf, X_cf = body("cone-frustum", "cf", area_cf, h, pi * R ** 2, pi * (R + r) ** 2 / 4, pi * r ** 2,
                              "circle whose radius runs linearly from R (base G) to r (top g)")
d.step("cone-frustum-reduced", (X_cf, h / 4 * (3 * r ** 2 + 2 * R * r + R ** 2) / (r ** 2 + R * r + R ** 2)),
       "algebra", uses=("cone-frustum-centroid",))
d.quote("cone-frustum-D", "§4 cone frustum", r"$\frac{R+r}{2}$  der von  $D$",
        reading=(sp.sqrt(D_cf / pi), (R + r) / 2))
d.quote("cone-frustum-1", "§4 cone frustum",
        r"$$X = h \left\{ \frac{\frac{r^2}{2} + \frac{(R+r)^2}{4}}{R^2 + r^2 + \frac{(R+r)^2}{2}} \right\} "
        r"\text{ oder}$$",
        reading=Eq(X_cf, h * ((r ** 2 / 2 + (R + r) ** 2 / 4) / (R ** 2 + r ** 2 + (R + r) ** 2 / 2))),
        erratum=Erratum(
            "transcription", "medium",
            r"X = h \left\{ \frac{\frac{r^2}{2} + \frac{(R+r)^2}{4}}{\frac{R^2 + r^2}{2} + \frac{(R+r)^2}{2}} "
            r"\right\}",
            (r"The denominator of the formula is $(G+g)/2 + 2D$; with $G = R^2$, $g = r^2$ ($\pi$ omitted) its first "
             "part is $(R^2 + r^2)/2$, not $R^2 + r^2$. The next printed line ($h/2$ times a fraction whose "
             "denominator is $R^2 + r^2 + R^2 + 2Rr + r^2$) follows only from the corrected form, so the author had "
             "the half. A lost fraction bar under $R^2 + r^2$, as in the first line of the truncated ellipsoid: the "
             "first fraction of a denominator inside a larger fraction, the nesting a scan flattens. The correction "
             "is proved and the printed line reads unambiguously; only the cause is open (a misprint of the 1866 "
             "print cannot be excluded from the transcription alone), hence medium."),
            corrected_reading=Eq(X_cf, h * ((r ** 2 / 2 + (R + r) ** 2 / 4)
                                               / ((R ** 2 + r ** 2) / 2 + (R + r) ** 2 / 2))),
                        objection=("The print itself may have lacked the half under $R^2 + r^2$, the fault being the "
                                   "author's and not the scan's."),
                        answer="The next printed line follows only from the corrected form, so the author had the "
                               "half, and the same bar is lost at the same place of the truncated ellipsoid's first "
                               "line, a nested fraction each time; whether the 1866 print or the scan lost it cannot "
                               "be told from the transcription, hence medium, not high."))
d.quote("cone-frustum-2", "§4 cone frustum",
        r"$$X = \frac{h}{2} \left\{ \frac{2r^2 + R^2 + 2Rr + r^2}{R^2 + r^2 + R^2 + 2Rr + r^2} \right\}, "
        r"\text{ also}$$",
        reading=Eq(X_cf, h / 2 * ((2 * r ** 2 + R ** 2 + 2 * R * r + r ** 2)
                                     / (R ** 2 + r ** 2 + R ** 2 + 2 * R * r + r ** 2))))
d.quote("cone-frustum-3", "§4 cone frustum",
        r"$$X = \frac{h}{4} \left\{ \frac{3r^2 + 2Rr + R^2}{r^2 + Rr + R^2} \right\}.$$",
        reading=Eq(X_cf, h / 4 * ((3 * r ** 2 + 2 * R * r + R ** 2) / (r ** 2 + R * r + R ** 2))))

# ---- pyramid frustum -------------------------------------------------------------------
area_pf = k * (S + (s - S) * u / h) ** 2
G_pf, D_pf, g_pf, X_pf = body("pyramid-frustum", "pf", area_pf, h, k * S ** 2, k * ((S + s) / 2) ** 2, k * s ** 2,
                              "sections similar to the bases: a side runs linearly from S to s, the area is "
                              "k times its square (k fixed by the shape of the base)")
d.step("pyramid-frustum-D-from-bases", (D_pf, (G_pf + 2 * sp.sqrt(G_pf * g_pf) + g_pf) / 4), "algebra",
       uses=("pyramid-frustum-G", "pyramid-frustum-D", "pyramid-frustum-g"))
d.step("pyramid-frustum-reduced",
       (X_pf, h / 4 * (3 * g_pf + G_pf + 2 * sp.sqrt(G_pf * g_pf)) / (g_pf + G_pf + sp.sqrt(G_pf * g_pf))),
       "algebra", uses=("pyramid-frustum-centroid", "pyramid-frustum-D-from-bases"))
d.quote("pyramid-frustum-side-D", "§4 pyramid frustum",
        r"so ist die ähnlich liegende Seite von  $D$ ,  $\frac{S+s}{2}$",
        reading=(sp.sqrt(D_pf / k), (S + s) / 2), note="the side of D: the square root of D/k")
d.quote("pyramid-frustum-ratio-G", "§4 pyramid frustum",
        r"$$G : D = S^2 : \frac{(S+s)^2}{4}, \sqrt{G} : \sqrt{D} = S : \frac{S+s}{2} \text{ und}$$",
        reading=(sp.Matrix([G_pf / D_pf, sp.sqrt(G_pf) / sp.sqrt(D_pf)]),
                 sp.Matrix([S ** 2 / ((S + s) ** 2 / 4), S / ((S + s) / 2)])))
d.quote("pyramid-frustum-ratio-g", "§4 pyramid frustum",
        r"$$g : D = s^2 : \frac{(S+s)^2}{4}, \sqrt{g} : \sqrt{D} = s : \frac{S+s}{2}, \text{ also}$$",
        reading=(sp.Matrix([g_pf / D_pf, sp.sqrt(g_pf) / sp.sqrt(D_pf)]),
                 sp.Matrix([s ** 2 / ((S + s) ** 2 / 4), s / ((S + s) / 2)])))
d.quote("pyramid-frustum-roots", "§4 pyramid frustum",
        r"$$\sqrt{G} = \frac{2S\sqrt{D}}{S+s}, \sqrt{g} = \frac{2s\sqrt{D}}{S+s}$$",
        reading=(sp.Matrix([sp.sqrt(G_pf), sp.sqrt(g_pf)]),
                 sp.Matrix([2 * S * sp.sqrt(D_pf) / (S + s), 2 * s * sp.sqrt(D_pf) / (S + s)])))
d.quote("pyramid-frustum-root-sum", "§4 pyramid frustum",
        r"$$\sqrt{G} + \sqrt{g} = \frac{2\sqrt{D}(S+s)}{S+s} \text{ woraus:}$$",
        reading=(sp.sqrt(G_pf) + sp.sqrt(g_pf), sp.Mul(2 * sp.sqrt(D_pf) * (S + s), 1 / (S + s), evaluate=False)))
d.quote("pyramid-frustum-D", "§4 pyramid frustum",
        r"$$D = \frac{G + 2\sqrt{Gg} + g}{4} \text{ also:}$$",
        reading=Eq(D_pf, (G_pf + 2 * sp.sqrt(G_pf * g_pf) + g_pf) / 4))
D_pf_printed = (G_pf + 2 * sp.sqrt(G_pf * g_pf) + g_pf) / 4
d.quote("pyramid-frustum-1", "§4 pyramid frustum",
        r"$$X = h \left\{ \frac{\frac{g}{2} + \frac{G + 2\sqrt{Gg} + g}{4}}{\frac{G+g}{2} + "
        r"\frac{G + 2\sqrt{Gg} + g}{2}} \right\} \text{ oder}$$",
        reading=Eq(X_pf, h * ((g_pf / 2 + D_pf_printed) / ((G_pf + g_pf) / 2 + 2 * D_pf_printed))))
d.quote("pyramid-frustum-2", "§4 pyramid frustum",
        r"$$X = \frac{h}{4} \left\{ \frac{3g + G + 2\sqrt{Gg}}{g + G + \sqrt{Gg}} \right\} . -$$",
        reading=Eq(X_pf, h / 4 * ((3 * g_pf + G_pf + 2 * sp.sqrt(G_pf * g_pf))
                                     / (g_pf + G_pf + sp.sqrt(G_pf * g_pf)))))

# ---- hemisphere --------------------------------------------------------------------------
area_hs = pi * (r ** 2 - u ** 2)
G_hs, D_hs, g_hs, X_hs = body("hemisphere", "hs", area_hs, r, pi * r ** 2, 3 * pi * r ** 2 / 4, 0,
                              "circle of radius sqrt(r^2 - u^2), u measured from the centre")
d.quote("hemisphere-sections", "§4 hemisphere",
        r"Für die Halbkugel ist  $g = 0$ ,  $G = r^2\pi$ ,  $D = \frac{3r^2\pi}{4}$",
        reading=(sp.Matrix([g_hs, G_hs, D_hs]), sp.Matrix([0, r ** 2 * pi, 3 * r ** 2 * pi / 4])))
d.quote("hemisphere", "§4 hemisphere",
        r"$$X = r \left\{ \frac{\frac{3r^2\pi}{4}}{\frac{r^2\pi}{2} + \frac{3r^2\pi}{2}} \right\} = "
        r"\frac{r}{2} \cdot \frac{3}{4} = \frac{3r}{8} . -$$",
        reading=as_printed(lambda: (X_hs, r * ((3 * r ** 2 * pi / 4) / (r ** 2 * pi / 2 + 3 * r ** 2 * pi / 2)),
                 r / 2 * sp.Rational(3, 4), 3 * r / 8)))

# ---- spherical segment, one base ---------------------------------------------------------------
h_s1 = symbol("h_{s1}", r"h_{\text{segment 1}}")
d.step("segment-1-height", Eq(h_s1, r - m), "definition", note="from the base to the pole", result=h_s1)
area_s1 = pi * (r ** 2 - (m + u) ** 2)
G_s1, D_s1, g_s1, X_s1 = body("segment-1", "s1", area_s1, h_s1, pi * (r ** 2 - m ** 2),
                              pi * (3 * r ** 2 - 2 * r * m - m ** 2) / 4, 0,
                              "circle of radius sqrt(r^2 - (m + u)^2): the base is at distance m from the centre")
d.step("segment-1-factors", (sp.Matrix([3 * r ** 2 - 2 * r * m - m ** 2, 2 * r ** 2 - r * m - m ** 2]),
                             sp.Matrix([(r - m) * (3 * r + m), (r - m) * (2 * r + m)])), "algebra",
       note="numerator and denominator share the factor r - m")
d.step("segment-1-reduced", (X_s1, (r - m) / 4 * (3 * r + m) / (2 * r + m)), "algebra",
       uses=("segment-1-centroid", "segment-1-factors"))
d.quote("segment-1-D-distance", "§4 spherical segment, one base",
        r"ist die Entfernung von  $D$  vom Mittelpunct  $\frac{r+m}{2}$", reading=(m + h_s1 / 2, (r + m) / 2),
        note="D lies halfway between the base (distance m) and the pole")
d.quote("segment-1-D", "§4 spherical segment, one base",
        r"$D = \pi \left\{ r^2 - \frac{(r+m)^2}{4} \right\} = \pi \left\{ \frac{3r^2 - 2rm - m^2}{4} \right\}$",
        reading=(D_s1, pi * (r ** 2 - (r + m) ** 2 / 4), pi * (3 * r ** 2 - 2 * r * m - m ** 2) / 4))
d.quote("segment-1-G", "§4 spherical segment, one base", r"$$G = \pi \{ r^2 - m^2 \}, g = 0, h = r - m,$$",
        reading=(sp.Matrix([G_s1, g_s1, h_s1]), sp.Matrix([pi * (r ** 2 - m ** 2), 0, r - m])))
num_s1 = 3 * r ** 2 - 2 * r * m - m ** 2
d.quote("segment-1-1", "§4 spherical segment, one base",
        r"$$X = (r - m) \left\{ \frac{\frac{3r^2 - 2rm - m^2}{4}}{\frac{r^2 - m^2}{2} + "
        r"\frac{3r^2 - 2rm - m^2}{2}} \right\}$$",
        reading=Eq(X_s1, (r - m) * ((num_s1 / 4) / ((r ** 2 - m ** 2) / 2 + num_s1 / 2))))
d.quote("segment-1-2", "§4 spherical segment, one base",
        r"$$X = \frac{r - m}{4} \left\{ \frac{3r^2 - 2rm - m^2}{2r^2 - rm - m^2} \right\}$$",
        reading=Eq(X_s1, (r - m) / 4 * (num_s1 / (2 * r ** 2 - r * m - m ** 2))))
d.quote("segment-1-3", "§4 spherical segment, one base",
        r"$$X = \frac{r - m}{4} \left\{ \frac{r - m}{r - m} \right\} \left\{ \frac{3r + m}{2r + m} \right\}$$",
        reading=Eq(X_s1, (r - m) / 4 * sp.Mul(r - m, 1 / (r - m), evaluate=False) * ((3 * r + m) / (2 * r + m))))
d.quote("segment-1-4", "§4 spherical segment, one base",
        r"$$X = \frac{r - m}{4} \left\{ \frac{3r + m}{2r + m} \right\}.$$",
        reading=Eq(X_s1, (r - m) / 4 * ((3 * r + m) / (2 * r + m))))

# ---- spherical segment, two bases ----------------------------------------------------------------
area_s2 = pi * (r ** 2 - (x + u) ** 2)
G_s2, D_s2, g_s2, X_s2 = body("segment-2", "s2", area_s2, xp - x, pi * (r ** 2 - x ** 2),
                              pi * (r ** 2 - (xp + x) ** 2 / 4), pi * (r ** 2 - xp ** 2),
                              "circle of radius sqrt(r^2 - (x + u)^2): G at abscissa x, g at x' > x")
num_s2 = 6 * r ** 2 - 3 * xp ** 2 - 2 * xp * x - x ** 2
den_s2 = 3 * r ** 2 - xp ** 2 - xp * x - x ** 2
d.step("segment-2-reduced", (X_s2, (xp - x) / 4 * num_s2 / den_s2), "algebra", uses=("segment-2-centroid",))
d.quote("segment-2-radii", "§4 spherical segment, two bases",
        r"$y^2 = r^2 - x^2$ ,  $y'^2 = r^2 - x'^2$ ,  $y''^2 = r^2 - \frac{(x' + x)^2}{4}$",
        reading=(sp.Matrix([G_s2, g_s2, D_s2]) / pi,
                 sp.Matrix([r ** 2 - x ** 2, r ** 2 - xp ** 2, r ** 2 - (xp + x) ** 2 / 4])),
        note="y, y', y'' are the radii of G, g, D: y^2 = G/pi etc.")
d.quote("segment-2-1", "§4 spherical segment, two bases",
        r"$$X = \{x' - x\} \left\{ \frac{\frac{r^2 - x'^2}{2} + r^2 - \frac{(x' + x)^2}{4}}{\frac{r^2 - x^2 + "
        r"r^2 - x'^2}{2} + \frac{4r^2 - (x' + x)^2}{2}} \right\}$$",
        reading=Eq(X_s2, (xp - x) * (((r ** 2 - xp ** 2) / 2 + r ** 2 - (xp + x) ** 2 / 4)
                                        / ((r ** 2 - x ** 2 + r ** 2 - xp ** 2) / 2
                                           + (4 * r ** 2 - (xp + x) ** 2) / 2))))
frac_s2 = ((2 * r ** 2 - 2 * xp ** 2 + 4 * r ** 2 - xp ** 2 - 2 * xp * x - x ** 2)
           / (6 * r ** 2 - x ** 2 - xp ** 2 - xp ** 2 - 2 * xp * x - x ** 2))
d.quote("segment-2-2", "§4 spherical segment, two bases",
        r"$$X = \frac{x' - x}{4} \left\{ \frac{2r^2 - 2x'^2 + 4r^2 - x'^2 - 2x'x - x^2}{6r^2 - x^2 - x'^2 - "
        r"x'^2 - 2x'x - x^2} \right\}$$",
        reading=Eq(X_s2, (xp - x) / 4 * frac_s2),
        erratum=Erratum(
            "misprint", "medium",
            r"X = \frac{x' - x}{2} \left\{ \frac{2r^2 - 2x'^2 + 4r^2 - x'^2 - 2x'x - x^2}{6r^2 - x^2 - x'^2 - "
            r"x'^2 - 2x'x - x^2} \right\}",
            ("The numerator of the preceding line was multiplied by $4$ and its denominator by $2$ to reach this "
             "fraction, so the prefactor must be $2(x' - x)/4 = (x' - x)/2$; as printed the line is half the "
             "centroid distance. The next line, whose denominator $3r^2 - x'^2 - x'x - x^2$ is half of this one, "
             "again carries $(x' - x)/4$ and is right, so the slip did not propagate: a fault of the printed line "
             "(the factor $4$ anticipates the next line), not of the scan, which renders the other factors "
             "faithfully. The same value results if instead the denominator is halved."),
            corrected_reading=Eq(X_s2, (xp - x) / 2 * frac_s2),
                        objection="The 4 may be the scan's reading of a 2, a fault of the transcription rather than "
                                  "of the print.",
                        answer="The scan renders every other factor of this display and of the next faithfully, and "
                               "the next line's (x' - x)/4 is right with its halved denominator: the 4 anticipates "
                               "that line, a compositor's or author's slip. The same value follows if the "
                               "denominator is halved instead, so medium."))
d.quote("segment-2-3", "§4 spherical segment, two bases",
        r"$$X = \frac{x' - x}{4} \left\{ \frac{6r^2 - 3x'^2 - 2x'x - x^2}{3r^2 - x'^2 - x'x - x^2} \right\}.$$",
        reading=Eq(X_s2, (xp - x) / 4 * (num_s2 / den_s2)))

# ---- paraboloid, one base ------------------------------------------------------------------------------
area_p1 = pi * 2 * p * (x - u)
G_p1, D_p1, g_p1, X_p1 = body("paraboloid-1", "p1", area_p1, x, 2 * pi * p * x, pi * p * x, 0,
                              r"circle of radius $\sqrt{2p (x - u)}$ (vertex equation $y^2 = 2 p \xi$, the vertex at "
                              r"height $x$ above the base)")
d.quote("paraboloid-1-radii", "§4 paraboloid, one base",
        r"$$y^2 = 2px, \quad y'^2 = px \quad \text{und da } g = 0 \text{ mit Weglassung von } \pi:$$",
        reading=(sp.Matrix([G_p1 / pi, D_p1 / pi, g_p1]), sp.Matrix([2 * p * x, p * x, 0])),
        note="y, y' are the radii of G, D: y^2 = G/pi, y'^2 = D/pi")
d.quote("paraboloid-1", "§4 paraboloid, one base",
        r"$$X = x \left\{ \frac{px}{px + 2px} \right\} = \frac{x}{3}.$$",
        reading=as_printed(lambda: (X_p1, x * (p * x / (p * x + 2 * p * x)), x / 3)))

# ---- paraboloid, two bases -----------------------------------------------------------------------------
area_p2 = pi * 2 * p * (xv - u)
G_p2, D_p2, g_p2, X_p2 = body("paraboloid-2", "p2", area_p2, xv - xvp, 2 * pi * p * xv, pi * p * (xvp + xv),
                              2 * pi * p * xvp,
                              r"circle of radius $\sqrt{2p (x_v - u)}$: $G$ at abscissa $x_v$ from the vertex, "
                              r"$g$ at $x'_v$")
d.step("paraboloid-2-reduced", (X_p2, (xv - xvp) / 3 * (2 * xvp + xv) / (xvp + xv)), "algebra",
       uses=("paraboloid-2-centroid",))
d.quote("paraboloid-2-radii", "§4 paraboloid, two bases",
        r"$$y^2 = 2 p x, y'^2 = 2 p x', y''^2 = 2 p \left\{ \frac{x' + x}{2} \right\} = p \{ x' + x \}$$",
        reading=as_printed(lambda: (sp.Matrix([G_p2, g_p2, D_p2]) / pi, sp.Matrix([2 * p * xv, 2 * p * xvp, 2 * p * (xvp + xv) / 2]),
                 sp.Matrix([2 * p * xv, 2 * p * xvp, p * (xvp + xv)]))),
        note="y, y', y'' are the radii of G, g, D; x, x' of the print are x_v, x'_v here")
d.quote("paraboloid-2-1", "§4 paraboloid, two bases",
        r"$$X = \{ x - x' \} \left\{ \frac{p x' + p \{ x' + x \}}{p \{ x + x' \} + 2 p \{ x + x' \}} \right\} "
        r"\text{ oder}$$",
        reading=Eq(X_p2, (xv - xvp) * ((p * xvp + p * (xvp + xv)) / (p * (xv + xvp) + 2 * p * (xv + xvp)))))
d.quote("paraboloid-2-2", "§4 paraboloid, two bases",
        r"$$X = \{ x - x' \} \left\{ \frac{2 x' + x}{3 x' + 3 x} \right\} = \frac{x - x'}{3} \left\{ "
        r"\frac{2 x' + x}{x' + x} \right\}$$",
        reading=(X_p2, (xv - xvp) * ((2 * xvp + xv) / (3 * xvp + 3 * xv)),
                 (xv - xvp) / 3 * ((2 * xvp + xv) / (xvp + xv))))

# ---- ellipsoid of revolution: segment with one base, half ellipsoid -------------------------------------
h_es = symbol("h_{es}", r"h_{\text{ellipsoid segment}}")
d.step("ellipsoid-segment-height", Eq(h_es, a - x), "definition", note="from the base to the vertex",
       result=h_es)
area_es = pi * b ** 2 / a ** 2 * (a ** 2 - (x + u) ** 2)
G_es, D_es, g_es, X_es = body("ellipsoid-segment", "es", area_es, h_es, pi * b ** 2 / a ** 2 * (a ** 2 - x ** 2),
                              pi * b ** 2 / a ** 2 * (3 * a ** 2 - 2 * a * x - x ** 2) / 4, 0,
                              r"circle of radius $\frac{b}{a} \sqrt{a^2 - (x + u)^2}$ (centre equation of the "
                              r"generating ellipse), the base at abscissa $x$")
num_es = 3 * a ** 2 - 2 * a * x - x ** 2
d.step("ellipsoid-segment-reduced", (X_es, (a - x) / 4 * num_es / (2 * a ** 2 - a * x - x ** 2),
                                     num_es / (4 * (2 * a + x))), "algebra", uses=("ellipsoid-segment-centroid",))
d.quote("ellipsoid-segment-height", "§4 ellipsoid segment", r"$h = a - x$", reading=(h_es, a - x))
d.quote("ellipsoid-segment-radii", "§4 ellipsoid segment",
        r"$$y^2 = \frac{b^2}{a^2} \left\{ a^2 - x^2 \right\}, y'^2 = \frac{b^2}{a^2} \left\{ a^2 - "
        r"\frac{(a + x)^2}{4} \right\}$$",
        reading=(sp.Matrix([G_es, D_es]) / pi,
                 sp.Matrix([b ** 2 / a ** 2 * (a ** 2 - x ** 2), b ** 2 / a ** 2 * (a ** 2 - (a + x) ** 2 / 4)])),
        note="y, y' are the radii of G and D")
d.quote("ellipsoid-segment-D", "§4 ellipsoid segment",
        r"$y'^2 = \frac{b^2}{a^2} \left\{ \frac{3 a^2 - 2 a x - x^2}{4} \right\}$",
        reading=(D_es / pi, b ** 2 / a ** 2 * (num_es / 4)))
d.quote("ellipsoid-segment-1", "§4 ellipsoid segment",
        r"$$X = \{ a - x \} \left\{ \frac{\frac{3 a^2 - 2 a x - x^2}{4}}{\frac{a^2 - x^2}{2} + "
        r"\frac{3 a^2 - 2 a x - x^2}{2}} \right\} \text{ oder}$$",
        reading=Eq(X_es, (a - x) * ((num_es / 4) / ((a ** 2 - x ** 2) / 2 + num_es / 2))))
d.quote("ellipsoid-segment-2", "§4 ellipsoid segment",
        r"$$X = \frac{a - x}{4} \left\{ \frac{3 a^2 - 2 a x - x^2}{2 a^2 - a x - x^2} \right\} = "
        r"\frac{3 a^2 - 2 a x - x^2}{4 (2 a + x)}$$",
        reading=(X_es, (a - x) / 4 * (num_es / (2 * a ** 2 - a * x - x ** 2)), num_es / (4 * (2 * a + x))))

area_he = pi * b ** 2 / a ** 2 * (a ** 2 - u ** 2)
X_he = body("half-ellipsoid", "he", area_he, a, pi * b ** 2, 3 * pi * b ** 2 / 4, 0,
            r"circle of radius $\frac{b}{a} \sqrt{a^2 - u^2}$, $u$ from the centre")[-1]
d.step("half-ellipsoid-from-segment", (X_he, sp.Subs(X_es, x, 0), 3 * a / 8), "substitution",
       uses=("half-ellipsoid-centroid", "ellipsoid-segment-reduced"),
       note="the segment with x = 0 is the half ellipsoid")
d.quote("half-ellipsoid", "§4 half ellipsoid", r"$$X = \frac{3a}{8}, \text{ wie für die Halbkugel.}$$",
        reading=(X_he, 3 * a / 8, sp.Subs(X_hs, r, a)),
        note="'wie für die Halbkugel': the hemisphere of radius a has the same centroid height")

# ---- truncated ellipsoid of revolution --------------------------------------------------------------------
area_te = pi * b ** 2 / a ** 2 * (a ** 2 - (x + u) ** 2)
G_te, D_te, g_te, X_te = body("truncated-ellipsoid", "te", area_te, xp - x,
                              pi * b ** 2 / a ** 2 * (a ** 2 - x ** 2),
                              pi * b ** 2 / a ** 2 * (a ** 2 - (xp + x) ** 2 / 4),
                              pi * b ** 2 / a ** 2 * (a ** 2 - xp ** 2),
                              r"circle of radius $\frac{b}{a} \sqrt{a^2 - (x + u)^2}$: $G$ at abscissa $x$, "
                              r"$g$ at $x' > x$")
num_te = 6 * a ** 2 - 3 * xp ** 2 - 2 * xp * x - x ** 2
den_te = 3 * a ** 2 - xp ** 2 - xp * x - x ** 2
d.step("truncated-ellipsoid-reduced", (X_te, (xp - x) / 4 * num_te / den_te), "algebra",
       uses=("truncated-ellipsoid-centroid",))
d.quote("truncated-ellipsoid-radii-1", "§4 truncated ellipsoid",
        r"$$y^2 = \frac{b^2}{a^2} \left\{ a^2 - x^2 \right\}, y'^2 = \frac{b^2}{a^2} \left\{ a^2 - x'^2 \right\},$$",
        reading=(sp.Matrix([G_te, g_te]) / pi,
                 sp.Matrix([b ** 2 / a ** 2 * (a ** 2 - x ** 2), b ** 2 / a ** 2 * (a ** 2 - xp ** 2)])),
        note="y, y' are the radii of G and g")
d.quote("truncated-ellipsoid-radii-2", "§4 truncated ellipsoid",
        r"$$y''^2 = \frac{b^2}{a^2} \left\{ a^2 - \frac{(x' + x)^2}{4} \right\}, \text{ also, wenn wir diese "
        r"Werthe in unse-}$$",
        reading=(D_te / pi, b ** 2 / a ** 2 * (a ** 2 - (xp + x) ** 2 / 4)), note="y'' is the radius of D")
num_te_1 = (a ** 2 - xp ** 2) / 2 + a ** 2 - (xp + x) ** 2 / 4
d.quote("truncated-ellipsoid-1", "§4 truncated ellipsoid",
        r"$$X = \left\{ x' - x \right\} \left\{ \frac{\frac{a^2 - x'^2}{2} + a^2 - \frac{(x' + x)^2}{4}}{a^2 - "
        r"x^2 + a^2 - x'^2 + \frac{4a^2 - (x' + x)^2}{2}} \right\}$$",
        reading=Eq(X_te, (xp - x) * (num_te_1 / (a ** 2 - x ** 2 + a ** 2 - xp ** 2
                                                    + (4 * a ** 2 - (xp + x) ** 2) / 2))),
        erratum=Erratum(
            "transcription", "medium",
            r"X = \left\{ x' - x \right\} \left\{ \frac{\frac{a^2 - x'^2}{2} + a^2 - \frac{(x' + x)^2}{4}}"
            r"{\frac{a^2 - x^2 + a^2 - x'^2}{2} + \frac{4a^2 - (x' + x)^2}{2}} \right\}",
            ("The first part of the denominator is $(G+g)/2$ and needs the half: the same line for the spherical "
             "zone prints $(r^2 - x^2 + r^2 - x'^2)/2$, and the triaxial stump, which the text calls 'derselbe "
             "Ausdruck', prints $(a^2 - x^2 + a^2 - x'^2)/2$. The final line of this body is right, so the half was "
             "there when it was reduced. A fraction bar lost by the transcription, as in the first line of the cone "
             "frustum (the first fraction of a denominator inside a larger fraction). The correction is proved and "
             "the printed line reads unambiguously; a misprint cannot be excluded from the transcription alone, "
             "hence medium."),
            corrected_reading=Eq(X_te, (xp - x) * (num_te_1 / ((a ** 2 - x ** 2 + a ** 2 - xp ** 2) / 2
                                                                  + (4 * a ** 2 - (xp + x) ** 2) / 2))),
                        objection="The print itself may have lacked the half, the fault being the author's.",
                        answer="The spherical zone's line and the triaxial stump ('derselbe Ausdruck') print the "
                               "half, and this body's final line is right; print or scan cannot be told apart, hence"
                               " medium, not high."))
d.quote("truncated-ellipsoid-2", "§4 truncated ellipsoid",
        r"$$X = \frac{x' - x}{4} \left\{ \frac{6a^2 - 3x'^2 - 2x'x - x^2}{3a^2 - x'^2 - x'x - x^2} \right\}.$$",
        reading=Eq(X_te, (xp - x) / 4 * (num_te / den_te)))

# ---- the elliptic body with isosceles triangular sections --------------------------------------------------
# Base: the ellipse with semi-axes a, b; EF of length 2a at height h above the major axis.  The generator cb
# runs from the base ellipse (ordinate y at abscissa x) to EF (ordinate 0, height h).
d.step("elliptic-body-ordinate", Eq(y, b / a * sp.sqrt(a ** 2 - x ** 2)), "definition",
       note="centre equation of the base ellipse: ordinate ab = y at abscissa x", result=y)
d.step("elliptic-body-generator", Eq(yp, (y * (1 - u / h)).subs(u, h / m)), "definition",
       note="the straight generator from b (ordinate y, height 0) to c (ordinate 0, height h) has ordinate "
            "y (1 - u/h) at height u; a'b' = y' is taken at the height h/m", result=yp)
d.step("elliptic-body-n", Eq(n, 1 - 1 / m), "definition", note="Graefe's abbreviation", result=n)
d.step("elliptic-body-section-ellipse", (yp ** 2, (n * b) ** 2 / a ** 2 * (a ** 2 - x ** 2)), "algebra",
       uses=("elliptic-body-ordinate", "elliptic-body-generator", "elliptic-body-n"),
       note="the section at height h/m is the ellipse with semi-axes a and n b")
d.step("elliptic-body-section-area",
       (sp.Integral(2 * b / a * sp.sqrt(a ** 2 - xi ** 2) * (1 - u / h), (xi, -a, a)), pi * a * b * (1 - u / h)),
       "integration", uses=("elliptic-body-section-ellipse",),
       note="area of the section at height u: the ellipse with semi-axes a and b (1 - u/h)")
area_eb = pi * a * b * (1 - u / h)
G_eb, D_eb, g_eb, X_eb = body("elliptic-body", "eb", area_eb, h, a * b * pi, a * b * pi / 2, 0,
                              "ellipse with semi-axes a and b (1 - u/h) (elliptic-body-section-area)")
d.step("elliptic-body-triangles",
       (sp.Integral(t * 2 * y * (1 - t / h), (t, 0, h)) / sp.Integral(2 * y * (1 - t / h), (t, 0, h)), h / 3, X_eb),
       "integration", uses=("elliptic-body-ordinate", "elliptic-body-centroid"),
       note="Graefe's second argument: every section perpendicular to the major axis is an isosceles "
            "triangle of height h, whose centroid lies at h/3")
X_pc = symbol("X_{pc}", r"X_{\text{paraboloid}}")
d.step("elliptic-body-paraboloid", Eq(X_pc, sp.Integral(u * 2 * p * pi * (h - u), (u, 0, h))
                                         / sp.Integral(2 * p * pi * (h - u), (u, 0, h))), "definition",
       note="centroid of a paraboloid of revolution of height h standing on its base (vertex equation "
            "y^2 = 2 p xi from the vertex)", result=X_pc)
d.step("elliptic-body-as-paraboloid", (X_eb, X_pc), "integration",
       uses=("elliptic-body-centroid", "elliptic-body-paraboloid"))

# the generator through b (ordinate y at the abscissa x, height 0), b' (ordinate y', height h/m) and c (on EF)
gen_b, gen_bp, gen_c = sp.Matrix([x, y, 0]), sp.Matrix([x, yp, h / m]), sp.Matrix([x, 0, h])
d.quote("elliptic-body-generator", "§4 elliptic body, triangular sections",
        r"so ist  $b'b'c$  eine grade Linie, laut Voraussetzung",
        unreadable="b'b'c names the point b' twice: a 'line' through b', b' and c says nothing",
        erratum=Erratum("transcription", "medium", r"b b' c \text{ eine grade Linie}",
                        "The sentence joins b with b' and extends the line to c; the straight line of the "
                        "hypothesis (the generator cb of the body) is b b' c, which the similar triangles of "
                        "the next line use (ab = y at height 0, a'b' = y' at h/m, c at h). The doubled b' "
                        "names no line: a b read as b' next to the b' that follows; medium, since the print "
                        "cannot be seen. Checked: b, b', c collinear in the coordinates of the construction "
                        "(abscissa, ordinate, height).",
                        corrected_reading=((gen_bp - gen_b).cross(gen_c - gen_b), sp.zeros(3, 1)),
                        objection="'b'b'c' may be a notation of the lost figure (a point b' twice, or a double prime"
                                  " lost), not a slip.",
                        answer="The sentence joins b with b' and extends the line to c; the similar triangles of the"
                               " next line use b, b' and c on one line (the generator cb of the hypothesis). No "
                               "point is named b'b'."))
gen_a, gen_ap = sp.Matrix([x, 0, 0]), sp.Matrix([x, 0, h / m])     # a, a': the feet of the ordinates on GH's plane
d.quote("elliptic-body-triangle", "§4 elliptic body, triangular sections", r"Nun ist im Dreieck  $ab'c$ ,",
        unreadable="a triangle a b' c has neither ordinate as a side (ab = y lies at the height 0, a'b' = y' at "
                   "h/m), so the proportion $y : y' = h : (h - h/m)$ that follows is not one between its sides",
        erratum=Erratum("transcription", "low", r"\text{Nun ist im Dreieck } abc",
                        "The proportion that follows compares the ordinate ab = y (height 0) with a'b' = y' "
                        "(height h/m) as the heights of c above them, h and h - h/m: the similar triangles abc and "
                        "a'b'c, a'b' parallel to ab. Read in the triangle abc (its leg ab, its side bc through b' "
                        "by the preceding line): ab (h - h/m) = a'b' h, checked with the coordinates of the "
                        "construction. A stray prime on the a, like the doubled b' of 'b'b'c' one line before "
                        "(elliptic-body-generator): the scan's; low, since the print cannot be seen.",
                        corrected_reading=((gen_b - gen_a).norm() * (h - h / m), (gen_bp - gen_ap).norm() * h),
                        objection="The triangle ab'c may be meant: the lost figure may draw it.",
                        answer="The proportion that follows compares ab with a'b' as the heights of c above them, h "
                               "and h - h/m, which is the similar-triangle relation of abc and a'b'c; in ab'c the "
                               "leg ab and the parallel a'b' do not stand as the proportion needs. A stray prime, as"
                               " in the line before; low, since the print cannot be seen."),
        note="a, a' are the feet of the ordinates ab, a'b' on the major axis and on GH")
d.quote("elliptic-body-ratio", "§4 elliptic body, triangular sections",
        r"$$y : y' = h : h - \frac{h}{m} \text{ also}$$", reading=(y / yp, h / (h - h / m)))
d.quote("elliptic-body-y", "§4 elliptic body, triangular sections", r"$y = \frac{y'}{1 - \frac{1}{m}}$",
        reading=(y, yp / (1 - 1 / m)))
d.quote("elliptic-body-base", "§4 elliptic body, triangular sections",
        r"$$y^2 = \frac{y'^2}{n^2} = \frac{b^2}{a^2} (a^2 - x^2) \text{ daher:}$$",
        reading=(y ** 2, yp ** 2 / n ** 2, b ** 2 / a ** 2 * (a ** 2 - x ** 2)))
d.quote("elliptic-body-section", "§4 elliptic body, triangular sections",
        r"$y'^2 = \frac{(nb)^2}{a^2} (a^2 - x^2)$", reading=(yp ** 2, (n * b) ** 2 / a ** 2 * (a ** 2 - x ** 2)))
d.quote("elliptic-body-n-half", "§4 elliptic body, triangular sections",
        r"$m = 2$ , so ist  $n = 1 - \frac{1}{2} = \frac{1}{2}$", reading=(sp.Subs(n, m, 2), sp.Rational(1, 2)))
d.quote("elliptic-body-D-axis", "§4 elliptic body, triangular sections",
        r"die kleine Halbaxe von  $D$  ist  $\frac{b}{2}$", reading=(D_eb / (pi * a), b / 2),
        note="D is an ellipse with semi-axes a and (its small one) D/(pi a)")
d.quote("elliptic-body-sections", "§4 elliptic body, triangular sections",
        r"$G = a b \pi$ ,  $D = \frac{a b \pi}{2}$ ,  $g = 0$",
        reading=(sp.Matrix([G_eb, D_eb, g_eb]), sp.Matrix([a * b * pi, a * b * pi / 2, 0])))
d.quote("elliptic-body", "§4 elliptic body, triangular sections",
        r"$$X = h \left\{ \frac{\frac{a b \pi}{2}}{\frac{a b \pi}{2} + a b \pi} \right\} = \frac{h}{3}$$",
        reading=as_printed(lambda: (X_eb, h * ((a * b * pi / 2) / (a * b * pi / 2 + a * b * pi)), h / 3)))
d.quote("elliptic-body-triangles", "§4 elliptic body, triangular sections",
        r"Der Schwerpunct des Körpers liegt mithin in der Linie, welche alle jene Schwerpuncte verbindet, also "
        r"auf  $\frac{h}{3}$",
        reading=(X_eb, h / 3))
d.quote("elliptic-body-paraboloid", "§4 elliptic body, triangular sections",
        r"Der Körper hat also die Eigenschaft, dass sein Schwerpunct mit dem eines mit ihm concentrischen "
        r"Paraboloids von gleicher Höhe zusammen fällt.",
        reading=(X_eb, X_pc))

# ---- triaxial ellipsoid: stump and half ----------------------------------------------------------------------
# Semi-axes: a along the axis of the stump (nM), c (nR) and b (Sn) across it.  The section at abscissa xi from
# the centre is an ellipse with half axes c sqrt(a^2 - xi^2)/a and b sqrt(a^2 - xi^2)/a.


def half_axes(abscissa):
    return c / a * sp.sqrt(a ** 2 - abscissa ** 2), b / a * sp.sqrt(a ** 2 - abscissa ** 2)


ts_mid = (x + xp) / 2
area_ts = pi * half_axes(x + u)[0] * half_axes(x + u)[1]
G_ts, D_ts, g_ts, X_ts = body("triaxial-stump", "ts", area_ts, xp - x,
                              b * c / a ** 2 * (a ** 2 - x ** 2) * pi,
                              b * c / a ** 2 * (a ** 2 - (x + xp) ** 2 / 4) * pi,
                              b * c / a ** 2 * (a ** 2 - xp ** 2) * pi,
                              "ellipse with the half axes c sqrt(a^2 - xi^2)/a and b sqrt(a^2 - xi^2)/a, "
                              "xi = x + u (the ordinates of the principal ellipses NMR and SMV)")
num_ts = 6 * a ** 2 - 3 * xp ** 2 - 2 * xp * x - x ** 2
den_ts = 3 * a ** 2 - xp ** 2 - xp * x - x ** 2
d.step("triaxial-stump-reduced", (X_ts, (xp - x) / 4 * num_ts / den_ts), "algebra",
       uses=("triaxial-stump-centroid",))
d.step("triaxial-stump-same-expression", (X_ts, X_te, sp.Subs(X_s2, r, a)), "algebra",
       uses=("triaxial-stump-centroid", "truncated-ellipsoid-centroid", "segment-2-centroid"),
       note="the factor b c/a^2 (pi b^2/a^2, pi) of the section areas cancels")

d.quote("triaxial-stump-mid", "§4 triaxial ellipsoid stump", r"$n p = \frac{x + x'}{2}$",
        reading=as_printed(lambda: (x + (xp - x) / 2, ts_mid)), note="PQ lies halfway between AB (at x) and CD (at x')")
d.quote("triaxial-stump-axes-G", "§4 triaxial ellipsoid stump",
        r"(m A)^2 &= \frac{c^2}{a^2} \{ a^2 - x^2 \}, (m G)^2 = \frac{b^2}{a^2} \{ a^2 - x^2 \}",
        reading=as_printed(lambda: (sp.Matrix(half_axes(x)).applyfunc(lambda e: e ** 2),
                 sp.Matrix([c ** 2 / a ** 2 * (a ** 2 - x ** 2), b ** 2 / a ** 2 * (a ** 2 - x ** 2)]))))
A_point, p_point = sp.Matrix([x, half_axes(x)[0]]), sp.Matrix([ts_mid, 0])   # A and p in the plane NMR
d.quote("triaxial-stump-axes-D", "§4 triaxial ellipsoid stump",
        r"(A p)^2 &= \frac{c^2}{a^2} \left\{ a^2 - \frac{(x + x')^2}{4} \right\}, (p E)^2 = \frac{b^2}{a^2} "
        r"\left\{ a^2 - \frac{(x + x')^2}{4} \right\}",
        reading=(sp.Matrix([(A_point - p_point).dot(A_point - p_point), half_axes(ts_mid)[1] ** 2]),
                 sp.Matrix([c ** 2 / a ** 2 * (a ** 2 - (x + xp) ** 2 / 4),
                            b ** 2 / a ** 2 * (a ** 2 - (x + xp) ** 2 / 4)])),
        erratum=Erratum("misprint", "medium",
                        r"(Q p)^2 = \frac{c^2}{a^2} \left\{ a^2 - \frac{(x + x')^2}{4} \right\}",
                        ("The half great axes are named $m A$, $p Q$, $o D$ in the text before the display, and the "
                         r"middle section is $D = Q p \cdot E p \cdot \pi$ after it: the first member of the middle "
                         "line is $(Q p)^2$, the ordinate of the ellipse $NMR$ at $n p = (x + x')/2$. $A$ is the end "
                         "of the half axis $m A$ of the base $AB$, at the abscissa $x$: as printed, $(A p)^2$ is the "
                         r"squared slant distance from $A$ to $p$, $((x' - x)/2)^2 + c^2/a^2\, (a^2 - x^2)$ (read in "
                         "the plane $NMR$), not the value printed. The value is right, the label contradicts both "
                         "neighbours. Booked as the print's: the rest of the display is letter-perfect, and an "
                         "existing letter of the figure in the wrong place (the A of '(m A)' in the line above) is a "
                         "compositor's kind of slip; the scan cannot be excluded: medium."),
                        corrected_reading=(sp.Matrix(half_axes(ts_mid)).applyfunc(lambda e: e ** 2),
                                           sp.Matrix([c ** 2 / a ** 2 * (a ** 2 - (x + xp) ** 2 / 4),
                                                      b ** 2 / a ** 2 * (a ** 2 - (x + xp) ** 2 / 4)])),
                        objection="A may be another label of the same point as Q in the lost figure.",
                        answer=("The text names the half axes $mA$, $pQ$, $oD$ and defines $A$ as the end of $mA$ at "
                                r"the abscissa $x$ of the base $AB$; the middle section $D = Qp \cdot Ep \cdot \pi$ "
                                "after the display uses $Qp$. $(Ap)^2$ as printed is the slant distance from $A$ to "
                                "$p$, not the value printed.")),
        note="read with the printed label: A = (x, mA) and p = ((x + x')/2, 0) in the plane of the ellipse NMR")
d.quote("triaxial-stump-axes-g", "§4 triaxial ellipsoid stump",
        r"(o D)^2 &= \frac{c^2}{a^2} \{ a^2 - x'^2 \}, (o F)^2 = \frac{b^2}{a^2} \{ a^2 - x'^2 \}.",
        reading=as_printed(lambda: (sp.Matrix(half_axes(xp)).applyfunc(lambda e: e ** 2),
                 sp.Matrix([c ** 2 / a ** 2 * (a ** 2 - xp ** 2), b ** 2 / a ** 2 * (a ** 2 - xp ** 2)]))))
for name, sym, at, val, excerpt in (
        ("G", G_ts, x, a ** 2 - x ** 2, r"G &= A m. G m. \pi = \frac{b c}{a^2} \{ a^2 - x^2 \} \pi"),
        ("D", D_ts, ts_mid, a ** 2 - (x + xp) ** 2 / 4,
         r"D &= Q p. E p. \pi = \frac{b c}{a^2} \left\{ a^2 - \frac{(x + x')^2}{4} \right\} \pi"),
        ("g", g_ts, xp, a ** 2 - xp ** 2, r"g &= D o. F o. \pi = \frac{b c}{a^2} \{ a^2 - x'^2 \} \pi.")):
    d.quote(f"triaxial-stump-{name}", "§4 triaxial ellipsoid stump", excerpt,
            reading=as_printed(lambda: (sym, half_axes(at)[0] * half_axes(at)[1] * pi, b * c / a ** 2 * val * pi)),
            note="an ellipse's area is pi times the product of its half axes")
d.quote("triaxial-stump-1", "§4 triaxial ellipsoid stump",
        r"$$X = \{x' - x\} \left\{ \frac{\frac{a^2 - x'^2}{2} + a^2 - \frac{(x + x')^2}{4}}{\frac{a^2 - x^2 + "
        r"a^2 - x'^2}{2} + 2 \left\{ a^2 - \frac{(x + x')^2}{4} \right\}} \right\}.$$",
        reading=Eq(X_ts, (xp - x) * (((a ** 2 - xp ** 2) / 2 + a ** 2 - (x + xp) ** 2 / 4)
                                        / ((a ** 2 - x ** 2 + a ** 2 - xp ** 2) / 2
                                           + 2 * (a ** 2 - (x + xp) ** 2 / 4)))))
d.quote("triaxial-stump-same-expression", "§4 triaxial ellipsoid stump",
        "Dies ist derselbe Ausdruck, den wir bei dem abgestumpften Rotations-Ellipsoid und dem Kugelsegment mit "
        "2 Oberflächen fanden",
        reading=(X_ts, X_te, sp.Subs(X_s2, r, a)), note="the sphere's radius r plays the part of a")
d.quote("triaxial-stump-2", "§4 triaxial ellipsoid stump",
        r"$$X = \frac{x' - x}{4} \left\{ \frac{6a^2 - 3x'^2 - 2x'x - x^2}{3a^2 - x'^2 - x'x - x^2} \right\}$$",
        reading=Eq(X_ts, (xp - x) / 4 * (num_ts / den_ts)))

area_ht = pi * half_axes(u)[0] * half_axes(u)[1]
X_ht = body("half-triaxial", "ht", area_ht, a, b * c * pi, 3 * b * c * pi / 4, 0,
            "ellipse with the half axes c sqrt(a^2 - u^2)/a and b sqrt(a^2 - u^2)/a, u from the centre")[-1]
d.step("half-triaxial-from-stump", (X_ht, sp.Subs(X_ts, (x, xp), (0, a)), 3 * a / 8), "substitution",
       uses=("half-triaxial-centroid", "triaxial-stump-reduced"),
       note="the stump with x = 0, x' = a is the half triaxial ellipsoid")
d.quote("half-triaxial", "§4 half triaxial ellipsoid",
        r"$$X = \frac{a}{4} \left\{ \frac{6a^2 - 3a^2}{3a^2 - a^2} \right\} = \frac{3a}{8}.$$",
        reading=as_printed(lambda: (X_ht, a / 4 * ((6 * a ** 2 - 3 * a ** 2) / (3 * a ** 2 - a ** 2)), 3 * a / 8)))
d.quote("three-eighths", "§4 half triaxial ellipsoid",
        "Mithin liegen die Schwerpunkte einer Halbkugel, eines halben Rotations-Ellipsoids und eines halben "
        "dreiaxigen Ellipsoids von gleicher Höhe in demselben Punkte, nämlich auf drei Achtel ihrer Höhe von der "
        "Basis aus.",
        reading=(X_hs / r, X_he / a, X_ht / a, sp.Rational(3, 8)),
        note="centroid height over the height r (hemisphere) or a (half ellipsoids)")
d.quote("half-ellipsoid-from-segment", "§4 half ellipsoid",
        r"Setzt man hierin  $x = 0$ , so findet sich für den Abstand des Schwerpunktes des halben Ellipsoids",
        reading=(sp.Subs(X_es, x, 0), X_he), note="the ellipsoid segment from x = 0 to the vertex is the half ellipsoid")
d.quote("half-triaxial-from-stump", "§4 half triaxial ellipsoid", r"Setzt man hierin  $x' = a$  und  $x = 0$",
        reading=(sp.Subs(X_ts, (x, xp), (0, a)), X_ht), note="the stump from the centre to the vertex")


d.quote("ellipsoid-segment-factor", "§4 ellipsoid segment",
        r"Weglassung von  $\frac{\pi b^2}{a^2}$  im Zähler und Nenner",
        reading=(X_es, centroid(a ** 2 - x ** 2, 0, (3 * a ** 2 - 2 * a * x - x ** 2) / 4, a - x)),
        note="the factor π b²/a² common to G, D, g cancels: the centroid from the bare brackets")
d.quote("triaxial-stump-factor", "§4 triaxial ellipsoid stump",
        r"Demnach erhalten wir mit Fortlassung von  $\frac{b c}{a^2}$  für den Abstand des Schwerpunktes von  $G$",
        reading=(X_ts, centroid((a ** 2 - x ** 2) * pi, (a ** 2 - xp ** 2) * pi, (a ** 2 - (x + xp) ** 2 / 4) * pi,
                                xp - x)),
        note="the factor b c/a² cancels (π is left in the brackets, as in D = Q p. E p. π)")
