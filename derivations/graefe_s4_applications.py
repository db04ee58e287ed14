"""Graefe 1866, §4: applications of the centroid formula of the prismatoid.

Every body of §4 (except the ship's displacement, treated separately) has a
section area ``A(u)`` that is a polynomial of degree at most 2 in the height
``u`` above the base ``G``.  For such bodies the prismatoid formula of §3,

    X = h (g/2 + D) / ((G + g)/2 + 2 D),   G = A(0), D = A(h/2), g = A(h),

is exact.  For each body ``A(u)`` is built from its own geometry (the
generating circle, parabola or ellipse, similar sections, ...), ``G``, ``D``,
``g`` are read off, the formula is applied and its value is compared with the
direct integral ``∫ u A du / ∫ A du``; the printed lines are then checked.
Bodies: sphere, cone and pyramid frustum, hemisphere, spherical segments with
one and two bases, paraboloids with one and two bases, ellipsoid segment,
half and truncated ellipsoid of revolution, the elliptic body with triangular
sections, triaxial ellipsoid stump and half triaxial ellipsoid.

Notation: ``x``, ``x'`` are abscissae from the centre (spheres, ellipsoids,
``x < x'``: ``G`` is the larger base); for the paraboloid with two bases the
abscissae from the vertex are written ``x_v > x'_v``.
"""
import sympy as sp

from symfloat import Derivation, Erratum
from symfloat.engine.witness import Case, SectionIntegral

u, t, xi = sp.symbols("u t xi", real=True)
r, R, h, m, a, b, c, p, k, S, s = sp.symbols("r R h m a b c p k S s", positive=True)
x, xp = sp.symbols("x x'", positive=True)
xv, xvp = sp.symbols("x_v x'_v", positive=True)
y, yp, n = sp.symbols("y y' n", positive=True)
pi = sp.pi

S3 = "graefe-s3-prismatoid-centroid"
QUADRATIC = ("A(u) is a polynomial of degree <= 2 in u, so the prismatoid formula of §3 is exact "
             "for this body (§3, centroid-quadratic-sections)")

DERIVATION = d = Derivation(
    id="graefe-s4-applications",
    source="graefe",
    title="Applications of the centroid formula of the prismatoid",
    locator="§4",
    summary="Centroids of the sphere, frusta of cone and pyramid, spherical, parabolic and "
            "ellipsoidal segments, an elliptic body with triangular sections and the triaxial "
            "ellipsoid stump, each from X = h (g/2 + D)/((G+g)/2 + 2D) and by direct integration.",
    requires=(S3,),
    domain={r: (4, 6), R: (1, 5), h: (1, 5), m: (1, 4), a: (4, 6), b: (1, 5), c: (1, 5), p: (1, 5),
            k: (1, 3), S: (1, 5), s: (1, 5), x: (0, 2), xp: (2, 4), xv: (3, 5), xvp: (1, 3), u: (0, 1)},
    constraints=(x < xp, xp < r, xp <= a, x < a, m < r, xvp < xv),
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
    A, G, D, g, X = sp.symbols(f"A_{{{key}}} G_{{{key}}} D_{{{key}}} g_{{{key}}} X_{{{key}}}")
    d.step(f"{slug}-section", sp.Eq(A, area), "definition", note=note, result=A)
    sec = (f"{slug}-section",)
    d.step(f"{slug}-G", (G, area.subs(u, 0), G_val), "substitution", uses=sec, result=G)
    d.step(f"{slug}-D", (D, area.subs(u, height / 2), D_val), "substitution", uses=sec, result=D)
    d.step(f"{slug}-g", (g, area.subs(u, height), g_val), "substitution", uses=sec, result=g)
    d.step(f"{slug}-centroid", sp.Eq(X, height * (g / 2 + D) / ((G + g) / 2 + 2 * D)), "lemma",
           uses=(f"{S3}:centroid", f"{S3}:centroid-quadratic-sections", f"{slug}-G", f"{slug}-D", f"{slug}-g"),
           note=QUADRATIC, result=X)
    d.step(f"{slug}-centroid-by-integration",
           (X, sp.Integral(u * A, (u, 0, height)) / sp.Integral(A, (u, 0, height))), "integration",
           uses=(f"{slug}-centroid", f"{slug}-section"),
           note="the formula agrees with the centroid by its definition")
    return G, D, g, X


def sections_witness(slug, description, targets, area, height, *cases):
    """Quadrature of the body's own section area: the centroid height above G."""
    d.witness(SectionIntegral(f"{slug}-sections", description, tuple(targets),
                              tuple(Case(params, label=label) for label, params in cases),
                              area=area, z=u, bounds=(0, height), quantity="centroid"))


# ---- sphere ------------------------------------------------------------------------
h_sp = sp.Symbol("h_{sp}")
d.step("sphere-height", sp.Eq(h_sp, 2 * r), "definition", note="from pole to pole", result=h_sp)
area_sp = pi * (r ** 2 - (u - r) ** 2)
G_sp, D_sp, g_sp, X_sp = body("sphere", "sp", area_sp, h_sp, 0, pi * r ** 2, 0,
                              "circle of radius sqrt(r^2 - (u - r)^2), u measured from the lower pole")
d.quote("sphere-sections", "§4 sphere", r"Für die Kugel ist  $G$  und  $g = 0$ ,  $D = r^2\pi$ ,  $h = 2r$",
        reading=(sp.Matrix([G_sp, g_sp, D_sp, h_sp]), sp.Matrix([0, 0, r ** 2 * pi, 2 * r])))
d.quote("sphere", "§4 sphere", r"$$X = 2r \frac{r^2\pi}{2r^2\pi} = r.$$",
        reading=(X_sp, 2 * r * (r ** 2 * pi / (2 * r ** 2 * pi)), r))
sections_witness("sphere", "centroid of the sphere from its circular sections", ("sphere",), area_sp, 2 * r,
                 ("r = 3", {r: 3}), ("r = 7/2", {r: sp.Rational(7, 2)}))

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
        reading=sp.Eq(X_cf, h * ((r ** 2 / 2 + (R + r) ** 2 / 4) / (R ** 2 + r ** 2 + (R + r) ** 2 / 2))),
        erratum=Erratum(
            "transcription", "low",
            r"X = h \left\{ \frac{\frac{r^2}{2} + \frac{(R+r)^2}{4}}{\frac{R^2 + r^2}{2} + \frac{(R+r)^2}{2}} "
            r"\right\}",
            "The denominator of the formula is (G+g)/2 + 2D; with G = R^2, g = r^2 (pi omitted) its first part is "
            "(R^2 + r^2)/2, not R^2 + r^2. The next printed line (h/2 times a fraction whose denominator is "
            "R^2 + r^2 + R^2 + 2Rr + r^2) follows only from the corrected form, so the author had the half. A "
            "lost fraction bar under R^2 + r^2, as in the first line of the truncated ellipsoid; from the "
            "transcription alone a misprint of the 1866 print cannot be excluded, hence low confidence.",
            corrected_reading=sp.Eq(X_cf, h * ((r ** 2 / 2 + (R + r) ** 2 / 4)
                                               / ((R ** 2 + r ** 2) / 2 + (R + r) ** 2 / 2)))))
d.quote("cone-frustum-2", "§4 cone frustum",
        r"$$X = \frac{h}{2} \left\{ \frac{2r^2 + R^2 + 2Rr + r^2}{R^2 + r^2 + R^2 + 2Rr + r^2} \right\}, "
        r"\text{ also}$$",
        reading=sp.Eq(X_cf, h / 2 * ((2 * r ** 2 + R ** 2 + 2 * R * r + r ** 2)
                                     / (R ** 2 + r ** 2 + R ** 2 + 2 * R * r + r ** 2))))
d.quote("cone-frustum-3", "§4 cone frustum",
        r"$$X = \frac{h}{4} \left\{ \frac{3r^2 + 2Rr + R^2}{r^2 + Rr + R^2} \right\}.$$",
        reading=sp.Eq(X_cf, h / 4 * ((3 * r ** 2 + 2 * R * r + R ** 2) / (r ** 2 + R * r + R ** 2))))
sections_witness("cone-frustum", "centroid of the cone frustum from its circular sections",
                 ("cone-frustum-1", "cone-frustum-2", "cone-frustum-3"), area_cf, h,
                 ("R = 3, r = 1, h = 4", {R: 3, r: 1, h: 4}),
                 ("R = 5/2, r = 2, h = 3/2", {R: sp.Rational(5, 2), r: 2, h: sp.Rational(3, 2)}))

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
        reading=(sp.sqrt(G_pf) + sp.sqrt(g_pf), 2 * sp.sqrt(D_pf) * (S + s) / (S + s)))
d.quote("pyramid-frustum-D", "§4 pyramid frustum",
        r"$$D = \frac{G + 2\sqrt{Gg} + g}{4} \text{ also:}$$",
        reading=sp.Eq(D_pf, (G_pf + 2 * sp.sqrt(G_pf * g_pf) + g_pf) / 4))
D_pf_printed = (G_pf + 2 * sp.sqrt(G_pf * g_pf) + g_pf) / 4
d.quote("pyramid-frustum-1", "§4 pyramid frustum",
        r"$$X = h \left\{ \frac{\frac{g}{2} + \frac{G + 2\sqrt{Gg} + g}{4}}{\frac{G+g}{2} + "
        r"\frac{G + 2\sqrt{Gg} + g}{2}} \right\} \text{ oder}$$",
        reading=sp.Eq(X_pf, h * ((g_pf / 2 + D_pf_printed) / ((G_pf + g_pf) / 2 + 2 * D_pf_printed))))
d.quote("pyramid-frustum-2", "§4 pyramid frustum",
        r"$$X = \frac{h}{4} \left\{ \frac{3g + G + 2\sqrt{Gg}}{g + G + \sqrt{Gg}} \right\} . -$$",
        reading=sp.Eq(X_pf, h / 4 * ((3 * g_pf + G_pf + 2 * sp.sqrt(G_pf * g_pf))
                                     / (g_pf + G_pf + sp.sqrt(G_pf * g_pf)))))
sections_witness("pyramid-frustum", "centroid of the pyramid frustum from its similar sections",
                 ("pyramid-frustum-1", "pyramid-frustum-2"), area_pf, h,
                 ("square frustum S = 3, s = 1, h = 2", {k: 1, S: 3, s: 1, h: 2}),
                 ("k = 3/2, S = 2, s = 5/4, h = 3", {k: sp.Rational(3, 2), S: 2, s: sp.Rational(5, 4), h: 3}))

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
        reading=(X_hs, r * ((3 * r ** 2 * pi / 4) / (r ** 2 * pi / 2 + 3 * r ** 2 * pi / 2)),
                 r / 2 * sp.Rational(3, 4), 3 * r / 8))
sections_witness("hemisphere", "centroid of the hemisphere from its circular sections", ("hemisphere",),
                 area_hs, r, ("r = 2", {r: 2}), ("r = 5/3", {r: sp.Rational(5, 3)}))

# ---- spherical segment, one base ---------------------------------------------------------------
h_s1 = sp.Symbol("h_{s1}")
d.step("segment-1-height", sp.Eq(h_s1, r - m), "definition", note="from the base to the pole", result=h_s1)
area_s1 = pi * (r ** 2 - (m + u) ** 2)
G_s1, D_s1, g_s1, X_s1 = body("segment-1", "s1", area_s1, h_s1, pi * (r ** 2 - m ** 2),
                              pi * (3 * r ** 2 - 2 * r * m - m ** 2) / 4, 0,
                              "circle of radius sqrt(r^2 - (m + u)^2): the base is at distance m from the centre")
d.step("segment-1-factors", (sp.Matrix([3 * r ** 2 - 2 * r * m - m ** 2, 2 * r ** 2 - r * m - m ** 2]),
                             sp.Matrix([(r - m) * (3 * r + m), (r - m) * (2 * r + m)])), "algebra",
       note="numerator and denominator share the factor r - m")
d.step("segment-1-reduced", (X_s1, (r - m) / 4 * (3 * r + m) / (2 * r + m)), "algebra",
       uses=("segment-1-centroid", "segment-1-factors"))
d.quote("segment-1-D", "§4 spherical segment, one base",
        r"$D = \pi \left\{ r^2 - \frac{(r+m)^2}{4} \right\} = \pi \left\{ \frac{3r^2 - 2rm - m^2}{4} \right\}$",
        reading=(D_s1, pi * (r ** 2 - (r + m) ** 2 / 4), pi * (3 * r ** 2 - 2 * r * m - m ** 2) / 4))
d.quote("segment-1-G", "§4 spherical segment, one base", r"$$G = \pi \{ r^2 - m^2 \}, g = 0, h = r - m,$$",
        reading=(sp.Matrix([G_s1, g_s1, h_s1]), sp.Matrix([pi * (r ** 2 - m ** 2), 0, r - m])))
num_s1 = 3 * r ** 2 - 2 * r * m - m ** 2
d.quote("segment-1-1", "§4 spherical segment, one base",
        r"$$X = (r - m) \left\{ \frac{\frac{3r^2 - 2rm - m^2}{4}}{\frac{r^2 - m^2}{2} + "
        r"\frac{3r^2 - 2rm - m^2}{2}} \right\}$$",
        reading=sp.Eq(X_s1, (r - m) * ((num_s1 / 4) / ((r ** 2 - m ** 2) / 2 + num_s1 / 2))))
d.quote("segment-1-2", "§4 spherical segment, one base",
        r"$$X = \frac{r - m}{4} \left\{ \frac{3r^2 - 2rm - m^2}{2r^2 - rm - m^2} \right\}$$",
        reading=sp.Eq(X_s1, (r - m) / 4 * (num_s1 / (2 * r ** 2 - r * m - m ** 2))))
d.quote("segment-1-3", "§4 spherical segment, one base",
        r"$$X = \frac{r - m}{4} \left\{ \frac{r - m}{r - m} \right\} \left\{ \frac{3r + m}{2r + m} \right\}$$",
        reading=sp.Eq(X_s1, (r - m) / 4 * sp.Mul(r - m, 1 / (r - m), evaluate=False) * ((3 * r + m) / (2 * r + m))))
d.quote("segment-1-4", "§4 spherical segment, one base",
        r"$$X = \frac{r - m}{4} \left\{ \frac{3r + m}{2r + m} \right\}.$$",
        reading=sp.Eq(X_s1, (r - m) / 4 * ((3 * r + m) / (2 * r + m))))
sections_witness("segment-1", "centroid of the spherical segment from its circular sections",
                 ("segment-1-1", "segment-1-2", "segment-1-3", "segment-1-4"), area_s1, r - m,
                 ("r = 3, m = 3/2", {r: 3, m: sp.Rational(3, 2)}), ("r = 5, m = 2", {r: 5, m: 2}))
