"""Graefe §4's witnesses: each body's centroid integrated over its sections, the sections named by the text
measured across their chords, the triaxial stump's half axes found as roots on the principal ellipses."""
import sympy as sp

from symfloat.engine.figure_witness import CurveRoot
from symfloat.engine.floating_witness import Combined
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case, PlaneSections, SectionIntegral

from .statements import (P, R, S, a, area_cf, area_eb, area_es, area_he, area_hs, area_ht, area_p1, area_p2, area_pf,
                        area_s1, area_s2, area_sp, area_te, area_ts, b, c, d, eta, h, k, m, p, pi, r, s, t, u, x, xp,
                        xv, xvp)


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
sections_witness("sphere", "centroid of the sphere from its circular sections", ("sphere",), area_sp, 2 * r,
                 ("r = 3", {r: 3}), ("r = 7/2", {r: sp.Rational(7, 2)}))
sections_witness("cone-frustum", "centroid of the cone frustum from its circular sections",
                 ("cone-frustum-1", "cone-frustum-2", "cone-frustum-3"), area_cf, h,
                 ("R = 3, r = 1, h = 4", {R: 3, r: 1, h: 4}),
                 ("R = 5/2, r = 2, h = 3/2", {R: sp.Rational(5, 2), r: 2, h: sp.Rational(3, 2)}))
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
        ("pyramid-frustum-ratio-G", (measured("section 1") / measured("section 2"),
                                     sp.sqrt(measured("section 1") / measured("section 2")))),
        ("pyramid-frustum-ratio-g", (measured("section 3") / measured("section 2"),
                                     sp.sqrt(measured("section 3") / measured("section 2")))),
        ("pyramid-frustum-roots", (sp.sqrt(measured("section 1")), sp.sqrt(measured("section 3")))),
        ("pyramid-frustum-root-sum", sp.sqrt(measured("section 1")) + sp.sqrt(measured("section 3"))),
        ("pyramid-frustum-D", measured("section 2"))):
    planes_witness(f"{target}-sections", "sections G, D, g of trapezoid frusta by quadrature of their widths",
                   (target,), pyramid_sections, (0, h / 2, h), combine, *pyramid_cases)
sections_witness("hemisphere", "centroid of the hemisphere from its circular sections", ("hemisphere",),
                 area_hs, r, ("r = 2", {r: 2}), ("r = 5/3", {r: sp.Rational(5, 3)}))
sections_witness("segment-1", "centroid of the spherical segment from its circular sections",
                 ("segment-1-1", "segment-1-2", "segment-1-3", "segment-1-4"), area_s1, r - m,
                 ("r = 3, m = 3/2", {r: 3, m: sp.Rational(3, 2)}), ("r = 5, m = 2", {r: 5, m: 2}))

planes_witness("segment-1-G-sections", "sections of the sphere at distances m and r from the centre",
               ("segment-1-G",), round_sections(r ** 2 - P ** 2), (m, r),
               (measured("section 1"), measured("section 2"), r - m),
               ("r = 3, m = 3/2", {r: 3, m: sp.Rational(3, 2)}), ("r = 5, m = 2", {r: 5, m: 2}))
sections_witness("segment-2", "centroid of the spherical zone from its circular sections",
                 ("segment-2-1", "segment-2-2", "segment-2-3"), area_s2, xp - x,
                 ("r = 5, x = 1, x' = 3", {r: 5, x: 1, xp: 3}),
                 ("r = 4, x = 1/2, x' = 7/2", {r: 4, x: sp.Rational(1, 2), xp: sp.Rational(7, 2)}))
sections_witness("paraboloid-1", "centroid of the paraboloid from its circular sections", ("paraboloid-1",),
                 area_p1, x, ("p = 1, x = 2", {p: 1, x: 2}),
                 ("p = 5/2, x = 3/2", {p: sp.Rational(5, 2), x: sp.Rational(3, 2)}))

planes_witness("paraboloid-1-radii-sections", "sections of the paraboloid y^2 = 2 p P (P from the vertex)",
               ("paraboloid-1-radii",), round_sections(2 * p * P), (x, x / 2, 0),
               (measured("section 1") / pi, measured("section 2") / pi, measured("section 3")),
               ("p = 1, x = 2", {p: 1, x: 2}), ("p = 5/2, x = 3/2", {p: sp.Rational(5, 2), x: sp.Rational(3, 2)}))
sections_witness("paraboloid-2", "centroid of the paraboloid frustum from its circular sections",
                 ("paraboloid-2-1", "paraboloid-2-2"), area_p2, xv - xvp,
                 ("p = 1, x = 4, x' = 1", {p: 1, xv: 4, xvp: 1}),
                 ("p = 3/2, x = 3, x' = 2", {p: sp.Rational(3, 2), xv: 3, xvp: 2}))

planes_witness("paraboloid-2-radii-sections", "sections of the paraboloid y^2 = 2 p P (P from the vertex)",
               ("paraboloid-2-radii",), round_sections(2 * p * P), (xv, xvp, (xv + xvp) / 2),
               (measured("section 1") / pi, measured("section 2") / pi, measured("section 3") / pi),
               ("p = 1, x = 4, x' = 1", {p: 1, xv: 4, xvp: 1}),
               ("p = 3/2, x = 3, x' = 2", {p: sp.Rational(3, 2), xv: 3, xvp: 2}))
sections_witness("ellipsoid-segment", "centroid of the ellipsoidal segment from its circular sections",
                 ("ellipsoid-segment-1", "ellipsoid-segment-2"), area_es, a - x,
                 ("a = 5, b = 3, x = 1", {a: 5, b: 3, x: 1}), ("a = 4, b = 1, x = 2", {a: 4, b: 1, x: 2}))

ellipsoid_sections = round_sections(b ** 2 / a ** 2 * (a ** 2 - P ** 2))
planes_witness("ellipsoid-segment-radii-sections", "sections of the ellipsoid of revolution",
               ("ellipsoid-segment-radii",), ellipsoid_sections, (x, (a + x) / 2),
               (measured("section 1") / pi, measured("section 2") / pi),
               ("a = 5, b = 3, x = 1", {a: 5, b: 3, x: 1}), ("a = 4, b = 1, x = 2", {a: 4, b: 1, x: 2}))
sections_witness("half-ellipsoid", "centroid of the half ellipsoid of revolution from its circular sections",
                 ("half-ellipsoid",), area_he, a,
                 ("a = 5, b = 3", {a: 5, b: 3}), ("a = 2, b = 7/2", {a: 2, b: sp.Rational(7, 2)}))
sections_witness("truncated-ellipsoid", "centroid of the truncated ellipsoid from its circular sections",
                 ("truncated-ellipsoid-1", "truncated-ellipsoid-2"), area_te, xp - x,
                 ("a = 5, b = 2, x = 1, x' = 4", {a: 5, b: 2, x: 1, xp: 4}),
                 ("a = 6, b = 3, x = 1/2, x' = 3", {a: 6, b: 3, x: sp.Rational(1, 2), xp: 3}))

truncated_cases = (("a = 5, b = 2, x = 1, x' = 4", {a: 5, b: 2, x: 1, xp: 4}),
                   ("a = 6, b = 3, x = 1/2, x' = 3", {a: 6, b: 3, x: sp.Rational(1, 2), xp: 3}))
planes_witness("truncated-ellipsoid-radii-1-sections", "sections of the ellipsoid of revolution",
               ("truncated-ellipsoid-radii-1",), ellipsoid_sections, (x, xp),
               (measured("section 1") / pi, measured("section 2") / pi), *truncated_cases)
planes_witness("truncated-ellipsoid-radii-2-sections", "sections of the ellipsoid of revolution",
               ("truncated-ellipsoid-radii-2",), ellipsoid_sections, ((x + xp) / 2,),
               measured("section 1") / pi, *truncated_cases)
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
               (0, h / m), measured("section 1") / measured("section 2"), *elliptic_cases)
# the triangle perpendicular to the major axis at abscissa P: width 2 b/a sqrt(a^2 - P^2) (1 - eta/h) at height
# eta; its area is y h
planes_witness("elliptic-body-base-sections", "the triangular section at abscissa x",
               ("elliptic-body-base",),
               {"width": 2 * b / a * sp.sqrt(a ** 2 - P ** 2) * (1 - eta / h), "chord": (0, h)},
               (x,), (measured("section 1") / h) ** 2, *elliptic_cases)
sections_witness("triaxial-stump", "centroid of the triaxial ellipsoid stump from its elliptic sections",
                 ("triaxial-stump-1", "triaxial-stump-2"), area_ts, xp - x,
                 ("a = 5, b = 3, c = 2, x = 1, x' = 4", {a: 5, b: 3, c: 2, x: 1, xp: 4}),
                 ("a = 4, b = 1, c = 3, x = 1/2, x' = 4", {a: 4, b: 1, c: 3, x: sp.Rational(1, 2), xp: 4}))
sections_witness("half-triaxial", "centroid of the half triaxial ellipsoid from its elliptic sections",
                 ("half-triaxial",), area_ht, a,
                 ("a = 5, b = 3, c = 2", {a: 5, b: 3, c: 2}), ("a = 3, b = 2, c = 1", {a: 3, b: 2, c: 1}))

# ---- the section areas themselves, by quadrature of their chords (sections named by the text) ------------------
# each section at distance P from the centre (or height P above the base) is measured across its chords; the
# positions are those of the construction (poles, centre, the midpoint between base and pole)
SPHERE_CASES = (("r = 3", {r: 3}), ("r = 7/2", {r: sp.Rational(7, 2)}))
planes_witness("sphere-sections-areas", "sections of the sphere at both poles and at the centre",
               ("sphere-sections",), round_sections(r ** 2 - P ** 2), (0, r, -r),   # a non-empty section first
               (measured("section 2"), measured("section 3"), measured("section 1"), 2 * r), *SPHERE_CASES)
planes_witness("hemisphere-sections-areas", "sections of the sphere at the pole, the centre and half the radius",
               ("hemisphere-sections",), round_sections(r ** 2 - P ** 2), (0, r, r / 2),
               (measured("section 2"), measured("section 1"), measured("section 3")), *SPHERE_CASES)
SEGMENT_CASES = (("r = 3, m = 3/2", {r: 3, m: sp.Rational(3, 2)}), ("r = 5, m = 2", {r: 5, m: 2}))
planes_witness("segment-1-D-area", "section of the sphere halfway between the base (distance m) and the pole",
               ("segment-1-D",), round_sections(r ** 2 - P ** 2), ((r + m) / 2,), measured("section 1"),
               *SEGMENT_CASES)
SEGMENT2_CASES = (("r = 5, x = 1, x' = 3", {r: 5, x: 1, xp: 3}),
                  ("r = 9/2, x = 1/2, x' = 4", {r: sp.Rational(9, 2), x: sp.Rational(1, 2), xp: 4}))
planes_witness("segment-2-radii-areas", "sections of the sphere at x, x' and halfway between",
               ("segment-2-radii",), round_sections(r ** 2 - P ** 2), (x, xp, (x + xp) / 2),
               (measured("section 1") / pi, measured("section 2") / pi, measured("section 3") / pi), *SEGMENT2_CASES)
ELLIPSOID_SEGMENT_CASES = (("a = 5, b = 3, x = 1", {a: 5, b: 3, x: 1}), ("a = 4, b = 1, x = 2", {a: 4, b: 1, x: 2}))
planes_witness("ellipsoid-segment-D-area", "section of the ellipsoid of revolution halfway between x and the vertex",
               ("ellipsoid-segment-D",), ellipsoid_sections, ((a + x) / 2,), measured("section 1") / pi,
               *ELLIPSOID_SEGMENT_CASES)
# the elliptic body: the section at height P is bounded by the generators, chord 2 b/a sqrt(a^2 - xi^2) (1 - P/h)
ELLIPTIC_BODY_CASES = (("a = 5, b = 3, h = 4", {a: 5, b: 3, h: 4}), ("a = 2, b = 1, h = 7/2", {a: 2, b: 1, h: sp.Rational(7, 2)}))
elliptic_body_width = {"width": 2 * a * b * sp.cos(eta) ** 2 * (1 - P / h), "chord": (-pi / 2, pi / 2)}
planes_witness("elliptic-body-sections-areas", "sections of the elliptic body at the heights 0, h/2 and h",
               ("elliptic-body-sections",), elliptic_body_width, (0, h / 2, h),
               (measured("section 1"), measured("section 2"), measured("section 3")),
               *ELLIPTIC_BODY_CASES)
planes_witness("elliptic-body-D-axis-area", "the section at h/2 over pi a: its small half axis",
               ("elliptic-body-D-axis",), elliptic_body_width, (h / 2,), measured("section 1") / (pi * a),
               *ELLIPTIC_BODY_CASES)
# the triaxial ellipsoid P^2/a^2 + t^2/c^2 + s^2/b^2 <= 1: at the abscissa P the chord in s over t = c sqrt(1 -
# P^2/a^2) sin(eta) is 2 b sqrt(1 - P^2/a^2) cos(eta), times dt
TRIAXIAL_CASES = (("a = 5, b = 3, c = 2, x = 1, x' = 4", {a: 5, b: 3, c: 2, x: 1, xp: 4}),
                  ("a = 4, b = 1, c = 3, x = 1/2, x' = 4", {a: 4, b: 1, c: 3, x: sp.Rational(1, 2), xp: 4}))
triaxial_width = {"width": 2 * b * c * (1 - P ** 2 / a ** 2) * sp.cos(eta) ** 2, "chord": (-pi / 2, pi / 2)}
for plane_name, plane_at in (("G", x), ("D", (x + xp) / 2), ("g", xp)):
    planes_witness(f"triaxial-stump-{plane_name}-area",
                   f"section of the triaxial ellipsoid at the abscissa of {plane_name}",
                   (f"triaxial-stump-{plane_name}",), triaxial_width, (plane_at,), measured("section 1"), *TRIAXIAL_CASES)


# the half axes of the section at an abscissa: the ordinates there of the principal ellipses NMR (half axes a, c)
# and SMV (a, b), each a root of the ellipse's equation on [0, semi-axis]
for axes_name, axes_at in (("G", x), ("D", (x + xp) / 2), ("g", xp)):
    d.witness(Combined(f"triaxial-stump-axes-{axes_name}-roots",
                       f"half axes of the section at {axes_name} by root-finding on the principal ellipses",
                       (f"triaxial-stump-axes-{axes_name}",),
                       tuple(Case({q: sp.Rational(v) for q, v in params.items()}, label=label)
                             for label, params in TRIAXIAL_CASES),
                       parts=tuple(CurveRoot(f"{axes_name}-ordinate-{semi}", "", (), (), equation=(axes_at / a) ** 2
                                             + (t / semi) ** 2 - 1, variable=t, bracket=(0, semi))
                                   for semi in (c, b)),
                       values=(measured("part 1") ** 2, measured("part 2") ** 2)))
planes_witness("pyramid-frustum-side-D-section", "the mid-section of trapezoid frusta by quadrature of its widths",
               ("pyramid-frustum-side-D",), pyramid_sections, (h / 2,), sp.sqrt(measured("section 1") / k),
               *pyramid_cases)
sections_witness("half-ellipsoid-as-segment", "centroid of the half ellipsoid from its circular sections",
                 ("half-ellipsoid-from-segment",), area_he, a, ("a = 5, b = 3", {a: 5, b: 3}),
                 ("a = 3, b = 2", {a: 3, b: 2}))
sections_witness("half-triaxial-as-stump", "centroid of the half triaxial ellipsoid from its elliptic sections",
                 ("half-triaxial-from-stump",), area_ht, a, ("a = 5, b = 3, c = 2", {a: 5, b: 3, c: 2}),
                 ("a = 3, b = 2, c = 1", {a: 3, b: 2, c: 1}))
planes_witness("cone-frustum-D-section", "the mid-section of the cone frustum across its chords", ("cone-frustum-D",),
               round_sections((R + (r - R) * P / h) ** 2), (h / 2,), sp.sqrt(measured("section 1") / pi),
               ("R = 3, r = 1, h = 4", {R: 3, r: 1, h: 4}), ("R = 5/2, r = 2, h = 3/2", {R: sp.Rational(5, 2), r: 2, h: sp.Rational(3, 2)}))
sections_witness("elliptic-body-claims", "centroid of the elliptic body from its elliptic sections",
                 ("elliptic-body-triangles", "elliptic-body-paraboloid"), area_eb, h,
                 ("a = 5, b = 3, h = 4, p = 2", {a: 5, b: 3, h: 4, p: 2}),
                 ("a = 2, b = 1, h = 7/2, p = 1/2", {a: 2, b: 1, h: sp.Rational(7, 2), p: sp.Rational(1, 2)}))


HALF_CASES = tuple(Case({r: sp.Rational(rv), a: sp.Rational(av), b: sp.Rational(bv), c: sp.Rational(cv)},
                        label=f"r = {rv}, a = {av}, b = {bv}, c = {cv}")
                   for rv, av, bv, cv in (("2", "5", "3", "2"), ("5/3", "3", "2", "1")))
fraction = sp.Symbol("w", positive=True)         # the height above G as a fraction of the body's height: u = w height
for half_name, area_, height_ in (("hemisphere", area_hs, r), ("half-ellipsoid", area_he, a), ("half-triaxial", area_ht, a)):
    d.witness(SectionIntegral(f"three-eighths-{half_name}", f"centroid of the {half_name} over its height, by quadrature",
                              ("three-eighths",), HALF_CASES, area=area_.subs(u, height_ * fraction), z=fraction,
                              bounds=(0, 1), quantity="centroid"))
sections_witness("ellipsoid-segment-factor", "centroid of the ellipsoidal segment from its circular sections",
                 ("ellipsoid-segment-factor",), area_es, a - x, *ELLIPSOID_SEGMENT_CASES)
sections_witness("triaxial-stump-factor", "centroid of the triaxial ellipsoid stump from its elliptic sections",
                 ("triaxial-stump-factor",), area_ts, xp - x, *TRIAXIAL_CASES)
