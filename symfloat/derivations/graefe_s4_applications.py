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

from symfloat import Derivation, Eq, Erratum
from symfloat.engine.figure_witness import FIGURE_METHODS, CurveRoot
from symfloat.engine.floating_witness import PART, Combined
from symfloat.engine.witness import SECTION, Case, PlaneSections, SectionIntegral
from symfloat.model.claim import as_printed
from symfloat.registry import load

u, t, xi, P, eta = sp.symbols("u t xi P eta", real=True)
r, R, h, m, a, b, c, p, k, S, s = sp.symbols("r R h m a b c p k S s", positive=True)
x, xp = sp.symbols("x x'", positive=True)
xv, xvp = sp.symbols("x_v x'_v", positive=True)
y, yp, n = sp.symbols("y y' n", positive=True)
pi = sp.pi

S3 = "graefe-s3-prismatoid-centroid"
# the prismatoid centroid X = h (g/2 + D)/((G + g)/2 + 2D) above G at given (G, g, D, h): the reading of §3's print
_S3D, _S3M = load(S3)
centroid = _S3D.evaluator("centroid", (_S3M.statements.G, _S3M.statements.g, _S3M.statements.D, _S3M.statements.h), 1)
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
    A, G, D, g, X = sp.symbols(f"A_{{{key}}} G_{{{key}}} D_{{{key}}} g_{{{key}}} X_{{{key}}}")
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


def sections_witness(slug, description, targets, area, height, *cases):
    """Quadrature of the body's own section area: the centroid height above G.
    Parameter values become SymPy rationals (the witness substitutes them with xreplace)."""
    d.witness(SectionIntegral(f"{slug}-sections", description, tuple(targets),
                              tuple(Case({q: sp.Rational(v) for q, v in params.items()}, label=label)
                                    for label, params in cases),
                              area=area, z=u, bounds=(0, height), quantity="centroid"))


def round_sections(rho2):
    """Width and chord of the circular section of radius^2 ``rho2`` (a function of ``P``),
    the chord coordinate written rho sin(eta) so that the integrand stays smooth."""
    return {"width": 2 * rho2 * sp.cos(eta) ** 2, "chord": (-pi / 2, pi / 2)}


def planes_witness(name, description, targets, sections, planes, combine, *cases):
    d.witness(PlaneSections(name, description, tuple(targets),
                            tuple(Case({q: sp.Rational(v) for q, v in params.items()}, label=label)
                                  for label, params in cases),
                            planes=tuple(planes), combine=combine, position=P, across=eta, **sections))


# ---- sphere ------------------------------------------------------------------------
h_sp = sp.Symbol("h_{sp}")
d.step("sphere-height", Eq(h_sp, 2 * r), "definition", note="from pole to pole", result=h_sp)
area_sp = pi * (r ** 2 - (u - r) ** 2)
G_sp, D_sp, g_sp, X_sp = body("sphere", "sp", area_sp, h_sp, 0, pi * r ** 2, 0,
                              "circle of radius sqrt(r^2 - (u - r)^2), u measured from the lower pole")
d.quote("sphere-sections", "§4 sphere", r"Für die Kugel ist  $G$  und  $g = 0$ ,  $D = r^2\pi$ ,  $h = 2r$",
        reading=(sp.Matrix([G_sp, g_sp, D_sp, h_sp]), sp.Matrix([0, 0, r ** 2 * pi, 2 * r])))
d.quote("sphere", "§4 sphere", r"$$X = 2r \frac{r^2\pi}{2r^2\pi} = r.$$",
        reading=as_printed(lambda: (X_sp, 2 * r * (r ** 2 * pi / (2 * r ** 2 * pi)), r)))
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
        reading=Eq(X_cf, h * ((r ** 2 / 2 + (R + r) ** 2 / 4) / (R ** 2 + r ** 2 + (R + r) ** 2 / 2))),
        erratum=Erratum(
            "transcription", "low",
            r"X = h \left\{ \frac{\frac{r^2}{2} + \frac{(R+r)^2}{4}}{\frac{R^2 + r^2}{2} + \frac{(R+r)^2}{2}} "
            r"\right\}",
            "The denominator of the formula is (G+g)/2 + 2D; with G = R^2, g = r^2 (pi omitted) its first part is "
            "(R^2 + r^2)/2, not R^2 + r^2. The next printed line (h/2 times a fraction whose denominator is "
            "R^2 + r^2 + R^2 + 2Rr + r^2) follows only from the corrected form, so the author had the half. A "
            "lost fraction bar under R^2 + r^2, as in the first line of the truncated ellipsoid; from the "
            "transcription alone a misprint of the 1866 print cannot be excluded, hence low confidence.",
            corrected_reading=Eq(X_cf, h * ((r ** 2 / 2 + (R + r) ** 2 / 4)
                                               / ((R ** 2 + r ** 2) / 2 + (R + r) ** 2 / 2)))))
d.quote("cone-frustum-2", "§4 cone frustum",
        r"$$X = \frac{h}{2} \left\{ \frac{2r^2 + R^2 + 2Rr + r^2}{R^2 + r^2 + R^2 + 2Rr + r^2} \right\}, "
        r"\text{ also}$$",
        reading=Eq(X_cf, h / 2 * ((2 * r ** 2 + R ** 2 + 2 * R * r + r ** 2)
                                     / (R ** 2 + r ** 2 + R ** 2 + 2 * R * r + r ** 2))))
d.quote("cone-frustum-3", "§4 cone frustum",
        r"$$X = \frac{h}{4} \left\{ \frac{3r^2 + 2Rr + R^2}{r^2 + Rr + R^2} \right\}.$$",
        reading=Eq(X_cf, h / 4 * ((3 * r ** 2 + 2 * R * r + R ** 2) / (r ** 2 + R * r + R ** 2))))
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
sections_witness("pyramid-frustum", "centroid of the pyramid frustum from its similar sections",
                 ("pyramid-frustum-1", "pyramid-frustum-2"), area_pf, h,
                 ("square frustum S = 3, s = 1, h = 2", {k: 1, S: 3, s: 1, h: 2}),
                 ("k = 3/2, S = 2, s = 5/4, h = 3", {k: sp.Rational(3, 2), S: 2, s: sp.Rational(5, 4), h: 3}))

# a frustum over the right trapezoid with parallel sides sigma and (2k - 1) sigma and height sigma (k = 1: the
# square); sigma, the side corresponding to S, runs linearly from S to s
sigma = S + (s - S) * P / h
pyramid_sections = {"width": sigma - 2 * (1 - k) * eta, "chord": (0, sigma)}
pyramid_cases = (("square frustum S = 3, s = 1, h = 2", {k: 1, S: 3, s: 1, h: 2}),
                 ("trapezoid frustum k = 3/4, S = 2, s = 5/4, h = 3",
                  {k: sp.Rational(3, 4), S: 2, s: sp.Rational(5, 4), h: 3}))
for target, combine in (
        ("pyramid-frustum-ratio-G", (SECTION[0] / SECTION[1], sp.sqrt(SECTION[0] / SECTION[1]))),
        ("pyramid-frustum-ratio-g", (SECTION[2] / SECTION[1], sp.sqrt(SECTION[2] / SECTION[1]))),
        ("pyramid-frustum-roots", (sp.sqrt(SECTION[0]), sp.sqrt(SECTION[2]))),
        ("pyramid-frustum-root-sum", sp.sqrt(SECTION[0]) + sp.sqrt(SECTION[2])),
        ("pyramid-frustum-D", SECTION[1])):
    planes_witness(f"{target}-sections", "sections G, D, g of trapezoid frusta by quadrature of their widths",
                   (target,), pyramid_sections, (0, h / 2, h), combine, *pyramid_cases)

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
sections_witness("hemisphere", "centroid of the hemisphere from its circular sections", ("hemisphere",),
                 area_hs, r, ("r = 2", {r: 2}), ("r = 5/3", {r: sp.Rational(5, 3)}))

# ---- spherical segment, one base ---------------------------------------------------------------
h_s1 = sp.Symbol("h_{s1}")
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
sections_witness("segment-1", "centroid of the spherical segment from its circular sections",
                 ("segment-1-1", "segment-1-2", "segment-1-3", "segment-1-4"), area_s1, r - m,
                 ("r = 3, m = 3/2", {r: 3, m: sp.Rational(3, 2)}), ("r = 5, m = 2", {r: 5, m: 2}))

planes_witness("segment-1-G-sections", "sections of the sphere at distances m and r from the centre",
               ("segment-1-G",), round_sections(r ** 2 - P ** 2), (m, r), (SECTION[0], SECTION[1], r - m),
               ("r = 3, m = 3/2", {r: 3, m: sp.Rational(3, 2)}), ("r = 5, m = 2", {r: 5, m: 2}))

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
            "The numerator of the preceding line was multiplied by 4 and its denominator by 2 to reach this "
            "fraction, so the prefactor must be 2(x' - x)/4 = (x' - x)/2; as printed the line is half the "
            "centroid distance. The next line, whose denominator 3r^2 - x'^2 - x'x - x^2 is half of this one, "
            "again carries (x' - x)/4 and is right, so the slip did not propagate: a fault of the printed "
            "line (the factor 4 anticipates the next line), not of the scan, which renders the other factors "
            "faithfully. The same value results if instead the denominator is halved.",
            corrected_reading=Eq(X_s2, (xp - x) / 2 * frac_s2)))
d.quote("segment-2-3", "§4 spherical segment, two bases",
        r"$$X = \frac{x' - x}{4} \left\{ \frac{6r^2 - 3x'^2 - 2x'x - x^2}{3r^2 - x'^2 - x'x - x^2} \right\}.$$",
        reading=Eq(X_s2, (xp - x) / 4 * (num_s2 / den_s2)))
sections_witness("segment-2", "centroid of the spherical zone from its circular sections",
                 ("segment-2-1", "segment-2-2", "segment-2-3"), area_s2, xp - x,
                 ("r = 5, x = 1, x' = 3", {r: 5, x: 1, xp: 3}),
                 ("r = 4, x = 1/2, x' = 7/2", {r: 4, x: sp.Rational(1, 2), xp: sp.Rational(7, 2)}))

# ---- paraboloid, one base ------------------------------------------------------------------------------
area_p1 = pi * 2 * p * (x - u)
G_p1, D_p1, g_p1, X_p1 = body("paraboloid-1", "p1", area_p1, x, 2 * pi * p * x, pi * p * x, 0,
                              "circle of radius^2 = 2p (x - u) (vertex equation y^2 = 2 p xi, the vertex at "
                              "height x above the base)")
d.quote("paraboloid-1-radii", "§4 paraboloid, one base",
        r"$$y^2 = 2px, \quad y'^2 = px \quad \text{und da } g = 0 \text{ mit Weglassung von } \pi:$$",
        reading=(sp.Matrix([G_p1 / pi, D_p1 / pi, g_p1]), sp.Matrix([2 * p * x, p * x, 0])),
        note="y, y' are the radii of G, D: y^2 = G/pi, y'^2 = D/pi")
d.quote("paraboloid-1", "§4 paraboloid, one base",
        r"$$X = x \left\{ \frac{px}{px + 2px} \right\} = \frac{x}{3}.$$",
        reading=as_printed(lambda: (X_p1, x * (p * x / (p * x + 2 * p * x)), x / 3)))
sections_witness("paraboloid-1", "centroid of the paraboloid from its circular sections", ("paraboloid-1",),
                 area_p1, x, ("p = 1, x = 2", {p: 1, x: 2}),
                 ("p = 5/2, x = 3/2", {p: sp.Rational(5, 2), x: sp.Rational(3, 2)}))

planes_witness("paraboloid-1-radii-sections", "sections of the paraboloid y^2 = 2 p P (P from the vertex)",
               ("paraboloid-1-radii",), round_sections(2 * p * P), (x, x / 2, 0),
               (SECTION[0] / pi, SECTION[1] / pi, SECTION[2]),
               ("p = 1, x = 2", {p: 1, x: 2}), ("p = 5/2, x = 3/2", {p: sp.Rational(5, 2), x: sp.Rational(3, 2)}))

# ---- paraboloid, two bases -----------------------------------------------------------------------------
area_p2 = pi * 2 * p * (xv - u)
G_p2, D_p2, g_p2, X_p2 = body("paraboloid-2", "p2", area_p2, xv - xvp, 2 * pi * p * xv, pi * p * (xvp + xv),
                              2 * pi * p * xvp,
                              "circle of radius^2 = 2p (x_v - u): G at abscissa x_v from the vertex, g at x'_v")
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
sections_witness("paraboloid-2", "centroid of the paraboloid frustum from its circular sections",
                 ("paraboloid-2-1", "paraboloid-2-2"), area_p2, xv - xvp,
                 ("p = 1, x = 4, x' = 1", {p: 1, xv: 4, xvp: 1}),
                 ("p = 3/2, x = 3, x' = 2", {p: sp.Rational(3, 2), xv: 3, xvp: 2}))

planes_witness("paraboloid-2-radii-sections", "sections of the paraboloid y^2 = 2 p P (P from the vertex)",
               ("paraboloid-2-radii",), round_sections(2 * p * P), (xv, xvp, (xv + xvp) / 2),
               (SECTION[0] / pi, SECTION[1] / pi, SECTION[2] / pi),
               ("p = 1, x = 4, x' = 1", {p: 1, xv: 4, xvp: 1}),
               ("p = 3/2, x = 3, x' = 2", {p: sp.Rational(3, 2), xv: 3, xvp: 2}))

# ---- ellipsoid of revolution: segment with one base, half ellipsoid -------------------------------------
h_es = sp.Symbol("h_{es}")
d.step("ellipsoid-segment-height", Eq(h_es, a - x), "definition", note="from the base to the vertex",
       result=h_es)
area_es = pi * b ** 2 / a ** 2 * (a ** 2 - (x + u) ** 2)
G_es, D_es, g_es, X_es = body("ellipsoid-segment", "es", area_es, h_es, pi * b ** 2 / a ** 2 * (a ** 2 - x ** 2),
                              pi * b ** 2 / a ** 2 * (3 * a ** 2 - 2 * a * x - x ** 2) / 4, 0,
                              "circle of radius^2 = b^2/a^2 (a^2 - (x + u)^2) (centre equation of the "
                              "generating ellipse), the base at abscissa x")
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
sections_witness("ellipsoid-segment", "centroid of the ellipsoidal segment from its circular sections",
                 ("ellipsoid-segment-1", "ellipsoid-segment-2"), area_es, a - x,
                 ("a = 5, b = 3, x = 1", {a: 5, b: 3, x: 1}), ("a = 4, b = 1, x = 2", {a: 4, b: 1, x: 2}))

ellipsoid_sections = round_sections(b ** 2 / a ** 2 * (a ** 2 - P ** 2))
planes_witness("ellipsoid-segment-radii-sections", "sections of the ellipsoid of revolution",
               ("ellipsoid-segment-radii",), ellipsoid_sections, (x, (a + x) / 2),
               (SECTION[0] / pi, SECTION[1] / pi),
               ("a = 5, b = 3, x = 1", {a: 5, b: 3, x: 1}), ("a = 4, b = 1, x = 2", {a: 4, b: 1, x: 2}))

area_he = pi * b ** 2 / a ** 2 * (a ** 2 - u ** 2)
*_, X_he = body("half-ellipsoid", "he", area_he, a, pi * b ** 2, 3 * pi * b ** 2 / 4, 0,
                "circle of radius^2 = b^2/a^2 (a^2 - u^2), u from the centre")
d.step("half-ellipsoid-from-segment", (X_he, sp.Subs(X_es, x, 0), 3 * a / 8), "substitution",
       uses=("half-ellipsoid-centroid", "ellipsoid-segment-reduced"),
       note="the segment with x = 0 is the half ellipsoid")
d.quote("half-ellipsoid", "§4 half ellipsoid", r"$$X = \frac{3a}{8}, \text{ wie für die Halbkugel.}$$",
        reading=(X_he, 3 * a / 8, sp.Subs(X_hs, r, a)),
        note="'wie für die Halbkugel': the hemisphere of radius a has the same centroid height")
sections_witness("half-ellipsoid", "centroid of the half ellipsoid of revolution from its circular sections",
                 ("half-ellipsoid",), area_he, a,
                 ("a = 5, b = 3", {a: 5, b: 3}), ("a = 2, b = 7/2", {a: 2, b: sp.Rational(7, 2)}))

# ---- truncated ellipsoid of revolution --------------------------------------------------------------------
area_te = pi * b ** 2 / a ** 2 * (a ** 2 - (x + u) ** 2)
G_te, D_te, g_te, X_te = body("truncated-ellipsoid", "te", area_te, xp - x,
                              pi * b ** 2 / a ** 2 * (a ** 2 - x ** 2),
                              pi * b ** 2 / a ** 2 * (a ** 2 - (xp + x) ** 2 / 4),
                              pi * b ** 2 / a ** 2 * (a ** 2 - xp ** 2),
                              "circle of radius^2 = b^2/a^2 (a^2 - (x + u)^2): G at abscissa x, g at x' > x")
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
            "transcription", "low",
            r"X = \left\{ x' - x \right\} \left\{ \frac{\frac{a^2 - x'^2}{2} + a^2 - \frac{(x' + x)^2}{4}}"
            r"{\frac{a^2 - x^2 + a^2 - x'^2}{2} + \frac{4a^2 - (x' + x)^2}{2}} \right\}",
            "The first part of the denominator is (G+g)/2 and needs the half: the same line for the "
            "spherical zone prints (r^2 - x^2 + r^2 - x'^2)/2, and the triaxial stump, which the text calls "
            "'derselbe Ausdruck', prints (a^2 - x^2 + a^2 - x'^2)/2. The final line of this body is right, "
            "so the half was there when it was reduced. A fraction bar lost by the transcription, as in the "
            "first line of the cone frustum; a misprint cannot be excluded from the transcription alone, "
            "hence low confidence.",
            corrected_reading=Eq(X_te, (xp - x) * (num_te_1 / ((a ** 2 - x ** 2 + a ** 2 - xp ** 2) / 2
                                                                  + (4 * a ** 2 - (xp + x) ** 2) / 2)))))
d.quote("truncated-ellipsoid-2", "§4 truncated ellipsoid",
        r"$$X = \frac{x' - x}{4} \left\{ \frac{6a^2 - 3x'^2 - 2x'x - x^2}{3a^2 - x'^2 - x'x - x^2} \right\}.$$",
        reading=Eq(X_te, (xp - x) / 4 * (num_te / den_te)))
sections_witness("truncated-ellipsoid", "centroid of the truncated ellipsoid from its circular sections",
                 ("truncated-ellipsoid-1", "truncated-ellipsoid-2"), area_te, xp - x,
                 ("a = 5, b = 2, x = 1, x' = 4", {a: 5, b: 2, x: 1, xp: 4}),
                 ("a = 6, b = 3, x = 1/2, x' = 3", {a: 6, b: 3, x: sp.Rational(1, 2), xp: 3}))

truncated_cases = (("a = 5, b = 2, x = 1, x' = 4", {a: 5, b: 2, x: 1, xp: 4}),
                   ("a = 6, b = 3, x = 1/2, x' = 3", {a: 6, b: 3, x: sp.Rational(1, 2), xp: 3}))
planes_witness("truncated-ellipsoid-radii-1-sections", "sections of the ellipsoid of revolution",
               ("truncated-ellipsoid-radii-1",), ellipsoid_sections, (x, xp),
               (SECTION[0] / pi, SECTION[1] / pi), *truncated_cases)
planes_witness("truncated-ellipsoid-radii-2-sections", "sections of the ellipsoid of revolution",
               ("truncated-ellipsoid-radii-2",), ellipsoid_sections, ((x + xp) / 2,),
               SECTION[0] / pi, *truncated_cases)

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
X_pc = sp.Symbol("X_{pc}")
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
                        corrected_reading=((gen_bp - gen_b).cross(gen_c - gen_b), sp.zeros(3, 1))))
gen_a, gen_ap = sp.Matrix([x, 0, 0]), sp.Matrix([x, 0, h / m])     # a, a': the feet of the ordinates on GH's plane
d.quote("elliptic-body-triangle", "§4 elliptic body, triangular sections", r"Nun ist im Dreieck  $ab'c$ ,",
        unreadable="a triangle a b' c has neither ordinate as a side (ab = y lies at the height 0, a'b' = y' at "
                   "h/m), so the proportion y : y' = h : (h - h/m) that follows is not one between its sides",
        erratum=Erratum("transcription", "low", r"\text{Nun ist im Dreieck } abc",
                        "The proportion that follows compares the ordinate ab = y (height 0) with a'b' = y' "
                        "(height h/m) as the heights of c above them, h and h - h/m: the similar triangles abc and "
                        "a'b'c, a'b' parallel to ab. Read in the triangle abc (its leg ab, its side bc through b' "
                        "by the preceding line): ab (h - h/m) = a'b' h, checked with the coordinates of the "
                        "construction. A stray prime on the a, like the doubled b' of 'b'b'c' one line before "
                        "(elliptic-body-generator): the scan's; low, since the print cannot be seen.",
                        corrected_reading=((gen_b - gen_a).norm() * (h - h / m), (gen_bp - gen_ap).norm() * h)),
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
sections_witness("elliptic-body", "centroid of the elliptic body from its elliptic sections",
                 ("elliptic-body",), area_eb, h,
                 ("a = 5, b = 3, h = 4", {a: 5, b: 3, h: 4}),
                 ("a = 2, b = 1, h = 7/2", {a: 2, b: 1, h: sp.Rational(7, 2)}))

elliptic_cases = (("a = 5, b = 3, h = 4, m = 2, x = 1", {a: 5, b: 3, h: 4, m: 2, x: 1}),
                  ("a = 2, b = 1, h = 7/2, m = 3, x = 3/2", {a: 2, b: 1, h: sp.Rational(7, 2), m: 3,
                                                             x: sp.Rational(3, 2)}))
# horizontal section at height P: chord 2 b/a sqrt(a^2 - xi^2) (1 - P/h) across the major axis, xi = a sin(eta)
planes_witness("elliptic-body-ratio-sections", "sections of the elliptic body at the heights 0 and h/m",
               ("elliptic-body-ratio",),
               {"width": 2 * a * b * sp.cos(eta) ** 2 * (1 - P / h), "chord": (-pi / 2, pi / 2)},
               (0, h / m), SECTION[0] / SECTION[1], *elliptic_cases)
# the triangle perpendicular to the major axis at abscissa P: width 2 b/a sqrt(a^2 - P^2) (1 - eta/h) at height
# eta; its area is y h
planes_witness("elliptic-body-base-sections", "the triangular section at abscissa x",
               ("elliptic-body-base",),
               {"width": 2 * b / a * sp.sqrt(a ** 2 - P ** 2) * (1 - eta / h), "chord": (0, h)},
               (x,), (SECTION[0] / h) ** 2, *elliptic_cases)

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
                        "The half great axes are named m A, p Q, o D in the text before the display, and the "
                        "middle section is D = Q p. E p. pi after it: the first member of the middle line is "
                        "(Q p)^2, the ordinate of the ellipse NMR at n p = (x + x')/2. A is the end of the half "
                        "axis m A of the base AB, at the abscissa x: as printed, (A p)^2 is the squared slant "
                        "distance from A to p, ((x' - x)/2)^2 + c^2/a^2 (a^2 - x^2) (read in the plane NMR), "
                        "not the value printed. The value is right, the label contradicts both neighbours. "
                        "Booked as the print's: the rest of the display is letter-perfect, and an existing "
                        "letter of the figure in the wrong place (the A of '(m A)' in the line above) is a "
                        "compositor's kind of slip; the scan cannot be excluded: medium.",
                        corrected_reading=(sp.Matrix(half_axes(ts_mid)).applyfunc(lambda e: e ** 2),
                                           sp.Matrix([c ** 2 / a ** 2 * (a ** 2 - (x + xp) ** 2 / 4),
                                                      b ** 2 / a ** 2 * (a ** 2 - (x + xp) ** 2 / 4)]))),
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
sections_witness("triaxial-stump", "centroid of the triaxial ellipsoid stump from its elliptic sections",
                 ("triaxial-stump-1", "triaxial-stump-2"), area_ts, xp - x,
                 ("a = 5, b = 3, c = 2, x = 1, x' = 4", {a: 5, b: 3, c: 2, x: 1, xp: 4}),
                 ("a = 4, b = 1, c = 3, x = 1/2, x' = 4", {a: 4, b: 1, c: 3, x: sp.Rational(1, 2), xp: 4}))

area_ht = pi * half_axes(u)[0] * half_axes(u)[1]
*_, X_ht = body("half-triaxial", "ht", area_ht, a, b * c * pi, 3 * b * c * pi / 4, 0,
                "ellipse with the half axes c sqrt(a^2 - u^2)/a and b sqrt(a^2 - u^2)/a, u from the centre")
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
sections_witness("half-triaxial", "centroid of the half triaxial ellipsoid from its elliptic sections",
                 ("half-triaxial",), area_ht, a,
                 ("a = 5, b = 3, c = 2", {a: 5, b: 3, c: 2}), ("a = 3, b = 2, c = 1", {a: 3, b: 2, c: 1}))

# ---- the section areas themselves, by quadrature of their chords (sections named by the text) ------------------
# each section at distance P from the centre (or height P above the base) is measured across its chords; the
# positions are those of the construction (poles, centre, the midpoint between base and pole)
SPHERE_CASES = (("r = 3", {r: 3}), ("r = 7/2", {r: sp.Rational(7, 2)}))
planes_witness("sphere-sections-areas", "sections of the sphere at both poles and at the centre",
               ("sphere-sections",), round_sections(r ** 2 - P ** 2), (0, r, -r),   # a non-empty section first
               (SECTION[1], SECTION[2], SECTION[0], 2 * r), *SPHERE_CASES)
planes_witness("hemisphere-sections-areas", "sections of the sphere at the pole, the centre and half the radius",
               ("hemisphere-sections",), round_sections(r ** 2 - P ** 2), (0, r, r / 2),
               (SECTION[1], SECTION[0], SECTION[2]), *SPHERE_CASES)
SEGMENT_CASES = (("r = 3, m = 3/2", {r: 3, m: sp.Rational(3, 2)}), ("r = 5, m = 2", {r: 5, m: 2}))
planes_witness("segment-1-D-area", "section of the sphere halfway between the base (distance m) and the pole",
               ("segment-1-D",), round_sections(r ** 2 - P ** 2), ((r + m) / 2,), SECTION[0],
               *SEGMENT_CASES)
SEGMENT2_CASES = (("r = 5, x = 1, x' = 3", {r: 5, x: 1, xp: 3}),
                  ("r = 9/2, x = 1/2, x' = 4", {r: sp.Rational(9, 2), x: sp.Rational(1, 2), xp: 4}))
planes_witness("segment-2-radii-areas", "sections of the sphere at x, x' and halfway between",
               ("segment-2-radii",), round_sections(r ** 2 - P ** 2), (x, xp, (x + xp) / 2),
               (SECTION[0] / pi, SECTION[1] / pi, SECTION[2] / pi), *SEGMENT2_CASES)
ELLIPSOID_SEGMENT_CASES = (("a = 5, b = 3, x = 1", {a: 5, b: 3, x: 1}), ("a = 4, b = 1, x = 2", {a: 4, b: 1, x: 2}))
planes_witness("ellipsoid-segment-D-area", "section of the ellipsoid of revolution halfway between x and the vertex",
               ("ellipsoid-segment-D",), ellipsoid_sections, ((a + x) / 2,), SECTION[0] / pi,
               *ELLIPSOID_SEGMENT_CASES)
# the elliptic body: the section at height P is bounded by the generators, chord 2 b/a sqrt(a^2 - xi^2) (1 - P/h)
ELLIPTIC_BODY_CASES = (("a = 5, b = 3, h = 4", {a: 5, b: 3, h: 4}), ("a = 2, b = 1, h = 7/2", {a: 2, b: 1, h: sp.Rational(7, 2)}))
elliptic_body_width = {"width": 2 * a * b * sp.cos(eta) ** 2 * (1 - P / h), "chord": (-pi / 2, pi / 2)}
planes_witness("elliptic-body-sections-areas", "sections of the elliptic body at the heights 0, h/2 and h",
               ("elliptic-body-sections",), elliptic_body_width, (0, h / 2, h), (SECTION[0], SECTION[1], SECTION[2]),
               *ELLIPTIC_BODY_CASES)
planes_witness("elliptic-body-D-axis-area", "the section at h/2 over pi a: its small half axis",
               ("elliptic-body-D-axis",), elliptic_body_width, (h / 2,), SECTION[0] / (pi * a),
               *ELLIPTIC_BODY_CASES)
# the triaxial ellipsoid P^2/a^2 + t^2/c^2 + s^2/b^2 <= 1: at the abscissa P the chord in s over t = c sqrt(1 -
# P^2/a^2) sin(eta) is 2 b sqrt(1 - P^2/a^2) cos(eta), times dt
TRIAXIAL_CASES = (("a = 5, b = 3, c = 2, x = 1, x' = 4", {a: 5, b: 3, c: 2, x: 1, xp: 4}),
                  ("a = 4, b = 1, c = 3, x = 1/2, x' = 4", {a: 4, b: 1, c: 3, x: sp.Rational(1, 2), xp: 4}))
triaxial_width = {"width": 2 * b * c * (1 - P ** 2 / a ** 2) * sp.cos(eta) ** 2, "chord": (-pi / 2, pi / 2)}
for name, at in (("G", x), ("D", (x + xp) / 2), ("g", xp)):
    planes_witness(f"triaxial-stump-{name}-area", f"section of the triaxial ellipsoid at the abscissa of {name}",
                   (f"triaxial-stump-{name}",), triaxial_width, (at,), SECTION[0], *TRIAXIAL_CASES)


# the half axes of the section at an abscissa: the ordinates there of the principal ellipses NMR (half axes a, c)
# and SMV (a, b), each a root of the ellipse's equation on [0, semi-axis]
for name, at in (("G", x), ("D", (x + xp) / 2), ("g", xp)):
    d.witness(Combined(f"triaxial-stump-axes-{name}-roots",
                       f"half axes of the section at {name} by root-finding on the principal ellipses",
                       (f"triaxial-stump-axes-{name}",),
                       tuple(Case({q: sp.Rational(v) for q, v in params.items()}, label=label)
                             for label, params in TRIAXIAL_CASES),
                       parts=tuple(CurveRoot(f"{name}-ordinate-{semi}", "", (), (), equation=(at / a) ** 2
                                             + (t / semi) ** 2 - 1, variable=t, bracket=(0, semi))
                                   for semi in (c, b)),
                       values=(PART[0] ** 2, PART[1] ** 2), methods=FIGURE_METHODS))
planes_witness("pyramid-frustum-side-D-section", "the mid-section of trapezoid frusta by quadrature of its widths",
               ("pyramid-frustum-side-D",), pyramid_sections, (h / 2,), sp.sqrt(SECTION[0] / k),
               *pyramid_cases)
d.quote("half-ellipsoid-from-segment", "§4 half ellipsoid",
        r"Setzt man hierin  $x = 0$ , so findet sich für den Abstand des Schwerpunktes des halben Ellipsoids",
        reading=(sp.Subs(X_es, x, 0), X_he), note="the ellipsoid segment from x = 0 to the vertex is the half ellipsoid")
d.quote("half-triaxial-from-stump", "§4 half triaxial ellipsoid", r"Setzt man hierin  $x' = a$  und  $x = 0$",
        reading=(sp.Subs(X_ts, (x, xp), (0, a)), X_ht), note="the stump from the centre to the vertex")
sections_witness("half-ellipsoid-as-segment", "centroid of the half ellipsoid from its circular sections",
                 ("half-ellipsoid-from-segment",), area_he, a, ("a = 5, b = 3", {a: 5, b: 3}),
                 ("a = 3, b = 2", {a: 3, b: 2}))
sections_witness("half-triaxial-as-stump", "centroid of the half triaxial ellipsoid from its elliptic sections",
                 ("half-triaxial-from-stump",), area_ht, a, ("a = 5, b = 3, c = 2", {a: 5, b: 3, c: 2}),
                 ("a = 3, b = 2, c = 1", {a: 3, b: 2, c: 1}))
planes_witness("cone-frustum-D-section", "the mid-section of the cone frustum across its chords", ("cone-frustum-D",),
               round_sections((R + (r - R) * P / h) ** 2), (h / 2,), sp.sqrt(SECTION[0] / pi),
               ("R = 3, r = 1, h = 4", {R: 3, r: 1, h: 4}), ("R = 5/2, r = 2, h = 3/2", {R: sp.Rational(5, 2), r: 2, h: sp.Rational(3, 2)}))
sections_witness("elliptic-body-claims", "centroid of the elliptic body from its elliptic sections",
                 ("elliptic-body-triangles", "elliptic-body-paraboloid"), area_eb, h,
                 ("a = 5, b = 3, h = 4, p = 2", {a: 5, b: 3, h: 4, p: 2}),
                 ("a = 2, b = 1, h = 7/2, p = 1/2", {a: 2, b: 1, h: sp.Rational(7, 2), p: sp.Rational(1, 2)}))


HALF_CASES = tuple(Case({r: sp.Rational(rv), a: sp.Rational(av), b: sp.Rational(bv), c: sp.Rational(cv)},
                        label=f"r = {rv}, a = {av}, b = {bv}, c = {cv}")
                   for rv, av, bv, cv in (("2", "5", "3", "2"), ("5/3", "3", "2", "1")))
fraction = sp.Symbol("w", positive=True)         # the height above G as a fraction of the body's height: u = w height
for name, area_, height_ in (("hemisphere", area_hs, r), ("half-ellipsoid", area_he, a), ("half-triaxial", area_ht, a)):
    d.witness(SectionIntegral(f"three-eighths-{name}", f"centroid of the {name} over its height, by quadrature",
                              ("three-eighths",), HALF_CASES, area=area_.subs(u, height_ * fraction), z=fraction,
                              bounds=(0, 1), quantity="centroid"))


d.quote("ellipsoid-segment-factor", "§4 ellipsoid segment",
        r"Weglassung von  $\frac{\pi b^2}{a^2}$  im Zähler und Nenner",
        reading=(X_es, centroid(a ** 2 - x ** 2, 0, (3 * a ** 2 - 2 * a * x - x ** 2) / 4, a - x)),
        note="the factor π b²/a² common to G, D, g cancels: the centroid from the bare brackets")
d.quote("triaxial-stump-factor", "§4 triaxial ellipsoid stump",
        r"Demnach erhalten wir mit Fortlassung von  $\frac{b c}{a^2}$  für den Abstand des Schwerpunktes von  $G$",
        reading=(X_ts, centroid((a ** 2 - x ** 2) * pi, (a ** 2 - xp ** 2) * pi, (a ** 2 - (x + xp) ** 2 / 4) * pi,
                                xp - x)),
        note="the factor b c/a² cancels (π is left in the brackets, as in D = Q p. E p. π)")
sections_witness("ellipsoid-segment-factor", "centroid of the ellipsoidal segment from its circular sections",
                 ("ellipsoid-segment-factor",), area_es, a - x, *ELLIPSOID_SEGMENT_CASES)
sections_witness("triaxial-stump-factor", "centroid of the triaxial ellipsoid stump from its elliptic sections",
                 ("triaxial-stump-factor",), area_ts, xp - x, *TRIAXIAL_CASES)
