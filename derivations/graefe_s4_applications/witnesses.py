"""Graefe §4's witnesses: each body's centroid integrated over its sections, the sections named by the text
measured across their chords, the triaxial stump's half axes found as roots on the principal ellipses."""
import sympy as sp

from symfloat.engine.declare import declarer, rational_cases
from symfloat.engine.figure_witness import CurveRoot
from symfloat.engine.floating_witness import Combined
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case, PlaneSections, SectionIntegral

from .statements import (P, R, S, a, area_cf, area_eb, area_es, area_he, area_hs, area_ht, area_p1, area_p2, area_pf,
                        area_s1, area_s2, area_sp, area_te, area_ts, b, c, d, eta, h, k, m, p, pi, r, s, t, u, x, xp,
                        xv, xvp)


# the centroid's height above G by quadrature of the body's own section area (``area``, ``bounds``), and the
# sections named by the text measured across their chords (``planes``, ``combine``, a width and chord)
sections = declarer(d, SectionIntegral, z=u, quantity="centroid")
planes = declarer(d, PlaneSections, position=P, across=eta)


def round_sections(rho2):
    """Width and chord of the circular section of radius^2 ``rho2`` (a function of ``P``),
    the chord coordinate written rho sin(eta) so that the integrand stays smooth."""
    return {"width": 2 * rho2 * sp.cos(eta) ** 2, "chord": (-pi / 2, pi / 2)}


sections("sphere-sections", "centroid of the sphere from its circular sections", ("sphere",),
         rational_cases(("r = 3", {r: 3}), ("r = 7/2", {r: sp.Rational(7, 2)})), area=area_sp, bounds=(0, 2 * r))
sections("cone-frustum-sections", "centroid of the cone frustum from its circular sections",
         ("cone-frustum-1", "cone-frustum-2", "cone-frustum-3"),
         rational_cases(("R = 3, r = 1, h = 4", {R: 3, r: 1, h: 4}),
                ("R = 5/2, r = 2, h = 3/2", {R: sp.Rational(5, 2), r: 2, h: sp.Rational(3, 2)})),
         area=area_cf, bounds=(0, h))
sections("pyramid-frustum-sections", "centroid of the pyramid frustum from its similar sections",
         ("pyramid-frustum-1", "pyramid-frustum-2"),
         rational_cases(("square frustum S = 3, s = 1, h = 2", {k: 1, S: 3, s: 1, h: 2}),
                ("k = 3/2, S = 2, s = 5/4, h = 3", {k: sp.Rational(3, 2), S: 2, s: sp.Rational(5, 4), h: 3})),
         area=area_pf, bounds=(0, h))

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
    planes(f"{target}-sections", "sections G, D, g of trapezoid frusta by quadrature of their widths", (target,),
           rational_cases(*pyramid_cases), planes=(0, h / 2, h), combine=combine, **pyramid_sections)
sections("hemisphere-sections", "centroid of the hemisphere from its circular sections", ("hemisphere",),
         rational_cases(("r = 2", {r: 2}), ("r = 5/3", {r: sp.Rational(5, 3)})), area=area_hs, bounds=(0, r))
sections("segment-1-sections", "centroid of the spherical segment from its circular sections",
         ("segment-1-1", "segment-1-2", "segment-1-3", "segment-1-4"),
         rational_cases(("r = 3, m = 3/2", {r: 3, m: sp.Rational(3, 2)}), ("r = 5, m = 2", {r: 5, m: 2})), area=area_s1,
         bounds=(0, r - m))

planes("segment-1-G-sections", "sections of the sphere at distances m and r from the centre", ("segment-1-G",),
       rational_cases(("r = 3, m = 3/2", {r: 3, m: sp.Rational(3, 2)}), ("r = 5, m = 2", {r: 5, m: 2})), planes=(m, r),
       combine=(measured("section 1"), measured("section 2"), r - m), **round_sections(r ** 2 - P ** 2))
sections("segment-2-sections", "centroid of the spherical zone from its circular sections",
         ("segment-2-1", "segment-2-2", "segment-2-3"),
         rational_cases(("r = 5, x = 1, x' = 3", {r: 5, x: 1, xp: 3}),
                ("r = 4, x = 1/2, x' = 7/2", {r: 4, x: sp.Rational(1, 2), xp: sp.Rational(7, 2)})),
         area=area_s2, bounds=(0, xp - x))
sections("paraboloid-1-sections", "centroid of the paraboloid from its circular sections", ("paraboloid-1",),
         rational_cases(("p = 1, x = 2", {p: 1, x: 2}), ("p = 5/2, x = 3/2", {p: sp.Rational(5, 2), x: sp.Rational(3, 2)})),
         area=area_p1, bounds=(0, x))

planes("paraboloid-1-radii-sections", "sections of the paraboloid y^2 = 2 p P (P from the vertex)",
       ("paraboloid-1-radii",),
       rational_cases(("p = 1, x = 2", {p: 1, x: 2}), ("p = 5/2, x = 3/2", {p: sp.Rational(5, 2), x: sp.Rational(3, 2)})),
       planes=(x, x / 2, 0), combine=(measured("section 1") / pi, measured("section 2") / pi, measured("section 3")),
       **round_sections(2 * p * P))
sections("paraboloid-2-sections", "centroid of the paraboloid frustum from its circular sections",
         ("paraboloid-2-1", "paraboloid-2-2"),
         rational_cases(("p = 1, x = 4, x' = 1", {p: 1, xv: 4, xvp: 1}),
                ("p = 3/2, x = 3, x' = 2", {p: sp.Rational(3, 2), xv: 3, xvp: 2})),
         area=area_p2, bounds=(0, xv - xvp))

planes("paraboloid-2-radii-sections", "sections of the paraboloid y^2 = 2 p P (P from the vertex)",
       ("paraboloid-2-radii",),
       rational_cases(("p = 1, x = 4, x' = 1", {p: 1, xv: 4, xvp: 1}),
              ("p = 3/2, x = 3, x' = 2", {p: sp.Rational(3, 2), xv: 3, xvp: 2})),
       planes=(xv, xvp, (xv + xvp) / 2),
       combine=(measured("section 1") / pi, measured("section 2") / pi, measured("section 3") / pi),
       **round_sections(2 * p * P))
sections("ellipsoid-segment-sections", "centroid of the ellipsoidal segment from its circular sections",
         ("ellipsoid-segment-1", "ellipsoid-segment-2"),
         rational_cases(("a = 5, b = 3, x = 1", {a: 5, b: 3, x: 1}), ("a = 4, b = 1, x = 2", {a: 4, b: 1, x: 2})), area=area_es,
         bounds=(0, a - x))

ellipsoid_sections = round_sections(b ** 2 / a ** 2 * (a ** 2 - P ** 2))
planes("ellipsoid-segment-radii-sections", "sections of the ellipsoid of revolution", ("ellipsoid-segment-radii",),
       rational_cases(("a = 5, b = 3, x = 1", {a: 5, b: 3, x: 1}), ("a = 4, b = 1, x = 2", {a: 4, b: 1, x: 2})),
       planes=(x, (a + x) / 2), combine=(measured("section 1") / pi, measured("section 2") / pi), **ellipsoid_sections)
sections("half-ellipsoid-sections", "centroid of the half ellipsoid of revolution from its circular sections",
         ("half-ellipsoid",), rational_cases(("a = 5, b = 3", {a: 5, b: 3}), ("a = 2, b = 7/2", {a: 2, b: sp.Rational(7, 2)})),
         area=area_he, bounds=(0, a))
sections("truncated-ellipsoid-sections", "centroid of the truncated ellipsoid from its circular sections",
         ("truncated-ellipsoid-1", "truncated-ellipsoid-2"),
         rational_cases(("a = 5, b = 2, x = 1, x' = 4", {a: 5, b: 2, x: 1, xp: 4}),
                ("a = 6, b = 3, x = 1/2, x' = 3", {a: 6, b: 3, x: sp.Rational(1, 2), xp: 3})),
         area=area_te, bounds=(0, xp - x))

truncated_cases = (("a = 5, b = 2, x = 1, x' = 4", {a: 5, b: 2, x: 1, xp: 4}),
                   ("a = 6, b = 3, x = 1/2, x' = 3", {a: 6, b: 3, x: sp.Rational(1, 2), xp: 3}))
planes("truncated-ellipsoid-radii-1-sections", "sections of the ellipsoid of revolution",
       ("truncated-ellipsoid-radii-1",), rational_cases(*truncated_cases), planes=(x, xp),
       combine=(measured("section 1") / pi, measured("section 2") / pi), **ellipsoid_sections)
planes("truncated-ellipsoid-radii-2-sections", "sections of the ellipsoid of revolution",
       ("truncated-ellipsoid-radii-2",), rational_cases(*truncated_cases), planes=((x + xp) / 2,),
       combine=measured("section 1") / pi, **ellipsoid_sections)
sections("elliptic-body-sections", "centroid of the elliptic body from its elliptic sections", ("elliptic-body",),
         rational_cases(("a = 5, b = 3, h = 4", {a: 5, b: 3, h: 4}),
                ("a = 2, b = 1, h = 7/2", {a: 2, b: 1, h: sp.Rational(7, 2)})),
         area=area_eb, bounds=(0, h))

elliptic_cases = (("a = 5, b = 3, h = 4, m = 2, x = 1", {a: 5, b: 3, h: 4, m: 2, x: 1}),
                  ("a = 2, b = 1, h = 7/2, m = 3, x = 3/2", {a: 2, b: 1, h: sp.Rational(7, 2), m: 3,
                                                             x: sp.Rational(3, 2)}))
# horizontal section at height P: chord 2 b/a sqrt(a^2 - xi^2) (1 - P/h) across the major axis, xi = a sin(eta)
planes("elliptic-body-ratio-sections", "sections of the elliptic body at the heights 0 and h/m",
       ("elliptic-body-ratio",), rational_cases(*elliptic_cases), planes=(0, h / m),
       combine=measured("section 1") / measured("section 2"),
       **{"width": 2 * a * b * sp.cos(eta) ** 2 * (1 - P / h), "chord": (-pi / 2, pi / 2)})
# the triangle perpendicular to the major axis at abscissa P: width 2 b/a sqrt(a^2 - P^2) (1 - eta/h) at height
# eta; its area is y h
planes("elliptic-body-base-sections", "the triangular section at abscissa x", ("elliptic-body-base",),
       rational_cases(*elliptic_cases), planes=(x,), combine=(measured("section 1") / h) ** 2,
       **{"width": 2 * b / a * sp.sqrt(a ** 2 - P ** 2) * (1 - eta / h), "chord": (0, h)})
sections("triaxial-stump-sections", "centroid of the triaxial ellipsoid stump from its elliptic sections",
         ("triaxial-stump-1", "triaxial-stump-2"),
         rational_cases(("a = 5, b = 3, c = 2, x = 1, x' = 4", {a: 5, b: 3, c: 2, x: 1, xp: 4}),
                ("a = 4, b = 1, c = 3, x = 1/2, x' = 4", {a: 4, b: 1, c: 3, x: sp.Rational(1, 2), xp: 4})),
         area=area_ts, bounds=(0, xp - x))
sections("half-triaxial-sections", "centroid of the half triaxial ellipsoid from its elliptic sections",
         ("half-triaxial",),
         rational_cases(("a = 5, b = 3, c = 2", {a: 5, b: 3, c: 2}), ("a = 3, b = 2, c = 1", {a: 3, b: 2, c: 1})), area=area_ht,
         bounds=(0, a))

# ---- the section areas themselves, by quadrature of their chords (sections named by the text) ------------------
# each section at distance P from the centre (or height P above the base) is measured across its chords; the
# positions are those of the construction (poles, centre, the midpoint between base and pole)
SPHERE_CASES = (("r = 3", {r: 3}), ("r = 7/2", {r: sp.Rational(7, 2)}))
planes("sphere-sections-areas", "sections of the sphere at both poles and at the centre", ("sphere-sections",),
       rational_cases(*SPHERE_CASES), planes=(0, r, -r),
       combine=(measured("section 2"), measured("section 3"), measured("section 1"), 2 * r),
       **round_sections(r ** 2 - P ** 2))
planes("hemisphere-sections-areas", "sections of the sphere at the pole, the centre and half the radius",
       ("hemisphere-sections",), rational_cases(*SPHERE_CASES), planes=(0, r, r / 2),
       combine=(measured("section 2"), measured("section 1"), measured("section 3")), **round_sections(r ** 2 - P ** 2))
SEGMENT_CASES = (("r = 3, m = 3/2", {r: 3, m: sp.Rational(3, 2)}), ("r = 5, m = 2", {r: 5, m: 2}))
planes("segment-1-D-area", "section of the sphere halfway between the base (distance m) and the pole", ("segment-1-D",),
       rational_cases(*SEGMENT_CASES), planes=((r + m) / 2,), combine=measured("section 1"), **round_sections(r ** 2 - P ** 2))
SEGMENT2_CASES = (("r = 5, x = 1, x' = 3", {r: 5, x: 1, xp: 3}),
                  ("r = 9/2, x = 1/2, x' = 4", {r: sp.Rational(9, 2), x: sp.Rational(1, 2), xp: 4}))
planes("segment-2-radii-areas", "sections of the sphere at x, x' and halfway between", ("segment-2-radii",),
       rational_cases(*SEGMENT2_CASES), planes=(x, xp, (x + xp) / 2),
       combine=(measured("section 1") / pi, measured("section 2") / pi, measured("section 3") / pi),
       **round_sections(r ** 2 - P ** 2))
ELLIPSOID_SEGMENT_CASES = (("a = 5, b = 3, x = 1", {a: 5, b: 3, x: 1}), ("a = 4, b = 1, x = 2", {a: 4, b: 1, x: 2}))
planes("ellipsoid-segment-D-area", "section of the ellipsoid of revolution halfway between x and the vertex",
       ("ellipsoid-segment-D",), rational_cases(*ELLIPSOID_SEGMENT_CASES), planes=((a + x) / 2,),
       combine=measured("section 1") / pi, **ellipsoid_sections)
# the elliptic body: the section at height P is bounded by the generators, chord 2 b/a sqrt(a^2 - xi^2) (1 - P/h)
ELLIPTIC_BODY_CASES = (("a = 5, b = 3, h = 4", {a: 5, b: 3, h: 4}), ("a = 2, b = 1, h = 7/2", {a: 2, b: 1, h: sp.Rational(7, 2)}))
elliptic_body_width = {"width": 2 * a * b * sp.cos(eta) ** 2 * (1 - P / h), "chord": (-pi / 2, pi / 2)}
planes("elliptic-body-sections-areas", "sections of the elliptic body at the heights 0, h/2 and h",
       ("elliptic-body-sections",), rational_cases(*ELLIPTIC_BODY_CASES), planes=(0, h / 2, h),
       combine=(measured("section 1"), measured("section 2"), measured("section 3")), **elliptic_body_width)
planes("elliptic-body-D-axis-area", "the section at h/2 over pi a: its small half axis", ("elliptic-body-D-axis",),
       rational_cases(*ELLIPTIC_BODY_CASES), planes=(h / 2,), combine=measured("section 1") / (pi * a), **elliptic_body_width)
# the triaxial ellipsoid P^2/a^2 + t^2/c^2 + s^2/b^2 <= 1: at the abscissa P the chord in s over t = c sqrt(1 -
# P^2/a^2) sin(eta) is 2 b sqrt(1 - P^2/a^2) cos(eta), times dt
TRIAXIAL_CASES = (("a = 5, b = 3, c = 2, x = 1, x' = 4", {a: 5, b: 3, c: 2, x: 1, xp: 4}),
                  ("a = 4, b = 1, c = 3, x = 1/2, x' = 4", {a: 4, b: 1, c: 3, x: sp.Rational(1, 2), xp: 4}))
triaxial_width = {"width": 2 * b * c * (1 - P ** 2 / a ** 2) * sp.cos(eta) ** 2, "chord": (-pi / 2, pi / 2)}
for plane_name, plane_at in (("G", x), ("D", (x + xp) / 2), ("g", xp)):
    planes(f"triaxial-stump-{plane_name}-area", f"section of the triaxial ellipsoid at the abscissa of {plane_name}",
           (f"triaxial-stump-{plane_name}",), rational_cases(*TRIAXIAL_CASES), planes=(plane_at,),
           combine=measured("section 1"), **triaxial_width)


# the half axes of the section at an abscissa: the ordinates there of the principal ellipses NMR (half axes a, c)
# and SMV (a, b), each a root of the ellipse's equation on [0, semi-axis]
for axes_name, axes_at in (("G", x), ("D", (x + xp) / 2), ("g", xp)):
    d.witness(Combined(f"triaxial-stump-axes-{axes_name}-roots",
                       f"half axes of the section at {axes_name} by root-finding on the principal ellipses",
                       (f"triaxial-stump-axes-{axes_name}",),
                       rational_cases(*TRIAXIAL_CASES),
                       parts=tuple(CurveRoot(f"{axes_name}-ordinate-{semi}", "", (), (), equation=(axes_at / a) ** 2
                                             + (t / semi) ** 2 - 1, variable=t, bracket=(0, semi))
                                   for semi in (c, b)),
                       values=(measured("part 1") ** 2, measured("part 2") ** 2)))
planes("pyramid-frustum-side-D-section", "the mid-section of trapezoid frusta by quadrature of its widths",
       ("pyramid-frustum-side-D",), rational_cases(*pyramid_cases), planes=(h / 2,), combine=sp.sqrt(measured("section 1") / k),
       **pyramid_sections)
sections("half-ellipsoid-as-segment-sections", "centroid of the half ellipsoid from its circular sections",
         ("half-ellipsoid-from-segment",), rational_cases(("a = 5, b = 3", {a: 5, b: 3}), ("a = 3, b = 2", {a: 3, b: 2})),
         area=area_he, bounds=(0, a))
sections("half-triaxial-as-stump-sections", "centroid of the half triaxial ellipsoid from its elliptic sections",
         ("half-triaxial-from-stump",),
         rational_cases(("a = 5, b = 3, c = 2", {a: 5, b: 3, c: 2}), ("a = 3, b = 2, c = 1", {a: 3, b: 2, c: 1})), area=area_ht,
         bounds=(0, a))
planes("cone-frustum-D-section", "the mid-section of the cone frustum across its chords", ("cone-frustum-D",),
       rational_cases(("R = 3, r = 1, h = 4", {R: 3, r: 1, h: 4}),
              ("R = 5/2, r = 2, h = 3/2", {R: sp.Rational(5, 2), r: 2, h: sp.Rational(3, 2)})),
       planes=(h / 2,), combine=sp.sqrt(measured("section 1") / pi), **round_sections((R + (r - R) * P / h) ** 2))
sections("elliptic-body-claims-sections", "centroid of the elliptic body from its elliptic sections",
         ("elliptic-body-triangles", "elliptic-body-paraboloid"),
         rational_cases(("a = 5, b = 3, h = 4, p = 2", {a: 5, b: 3, h: 4, p: 2}),
                ("a = 2, b = 1, h = 7/2, p = 1/2", {a: 2, b: 1, h: sp.Rational(7, 2), p: sp.Rational(1, 2)})),
         area=area_eb, bounds=(0, h))


HALF_CASES = tuple(Case({r: sp.Rational(rv), a: sp.Rational(av), b: sp.Rational(bv), c: sp.Rational(cv)},
                        label=f"r = {rv}, a = {av}, b = {bv}, c = {cv}")
                   for rv, av, bv, cv in (("2", "5", "3", "2"), ("5/3", "3", "2", "1")))
fraction = sp.Symbol("w", positive=True)         # the height above G as a fraction of the body's height: u = w height
for half_name, area_, height_ in (("hemisphere", area_hs, r), ("half-ellipsoid", area_he, a), ("half-triaxial", area_ht, a)):
    d.witness(SectionIntegral(f"three-eighths-{half_name}", f"centroid of the {half_name} over its height, by quadrature",
                              ("three-eighths",), HALF_CASES, area=area_.subs(u, height_ * fraction), z=fraction,
                              bounds=(0, 1), quantity="centroid"))
sections("ellipsoid-segment-factor-sections", "centroid of the ellipsoidal segment from its circular sections",
         ("ellipsoid-segment-factor",), rational_cases(*ELLIPSOID_SEGMENT_CASES), area=area_es, bounds=(0, a - x))
sections("triaxial-stump-factor-sections", "centroid of the triaxial ellipsoid stump from its elliptic sections",
         ("triaxial-stump-factor",), rational_cases(*TRIAXIAL_CASES), area=area_ts, bounds=(0, xp - x))
