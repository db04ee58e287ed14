"""Graefe §2's witnesses: the volumes integrated over their section areas, the sections measured across
their chords, composite Simpson's order of convergence measured."""
import mpmath
import sympy as sp

from symfloat.engine.measured import measured
from symfloat.engine.quadrature import composite_simpson
from symfloat.engine.witness import Case, ConvergenceOrder, PlaneSections, SectionIntegral

from .statements import A3, A_sec, D, G, ZERO_BASE_AREAS, a, b, d, h, k, m, p, pi, r, x, z

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


d.witness(ConvergenceOrder("simpson-order-exp", "composite Simpson on ∫₀¹ exp",
                           ("simpson-identical", "odd-number-of-sections"), composite_simpson, mpmath.exp,
                           (mpmath.mpf(0), mpmath.mpf(1)), mpmath.e - 1, 4))
# (not 1/(1+z²) on [0, 1]: its third derivative vanishes at both ends, which cancels the h⁴ term
# of the error and makes the measured order 6)
d.witness(ConvergenceOrder("simpson-order-reciprocal", "composite Simpson on ∫₀¹ 1/(1+z)",
                           ("simpson-identical", "odd-number-of-sections"), composite_simpson, _reciprocal,
                           (mpmath.mpf(0), mpmath.mpf(1)), mpmath.log(2), 4))

# the sections named by the text, measured across their chords (the circle of radius² ρ²(z) written with the
# chord coordinate ρ sin η, so that the integrand 2ρ² cos²η stays smooth)
eta, zp = sp.symbols("eta z_P", real=True)


def _round(rho2):
    return {"width": 2 * rho2 * sp.cos(eta) ** 2, "chord": (-pi / 2, pi / 2), "position": zp, "across": eta}


d.witness(PlaneSections("sphere-section-areas", "sections of the sphere at both poles and the centre",
                        ("sphere-sections",), SPHERE_CASES, planes=(r, 0, 2 * r),   # a non-empty section first
                        combine=(measured("section 2"), measured("section 3"),
                                 measured("section 1")), **_round(r ** 2 - (zp - r) ** 2)))
for radius_name, plane in (("paraboloid-base-radius", 0), ("paraboloid-mid-radius", x / 2)):
    d.witness(PlaneSections(f"{radius_name}-section", "section of the paraboloid y² = 2pt (t from the vertex, t = x - z)",
                            (radius_name,), PARABOLOID_CASES, planes=(plane,),
                            combine=measured("section 1") / pi, **_round(2 * p * (x - zp))))
d.witness(PlaneSections("ellipse-chords", "the ellipsoid's sections at the base and the mid-section, over pi",
                        ("ellipsoid-radii",), ELLIPSOID_CASES, planes=(0, x / 2),
                        combine=(measured("section 1") / pi, measured("section 2") / pi),
                        **_round(A_e_centre.subs(z, zp) / pi)))
d.witness(SectionIntegral("half-ellipsoid-segment", "∫ π b² (1 - (t - a)²/a²) dt over the segment of height a",
                          ("half-ellipsoid-x-a",), tuple(Case({a: c_.params[a], b: c_.params[b], x: c_.params[a]},
                                                               label=f"a = {c_.params[a]}, b = {c_.params[b]}")
                                                          for c_ in ELLIPSOID_CASES),
                          area=A_e_centre, z=z, bounds=(0, a)))


d.witness(SectionIntegral("zero-bases-volumes", "∫ A dz of a pyramid and of a body with both bases zero",
                          ("zero-bases",), (Case({G: 3, D: 2, h: sp.Rational(5, 2)}, label="G = 3, D = 2, h = 5/2"),
                                            Case({G: sp.Rational(7, 3), D: sp.Rational(1, 2), h: 4},
                                                 label="G = 7/3, D = 1/2, h = 4")),
                          area=ZERO_BASE_AREAS, z=z, bounds=(0, h)))
