"""The ship centroid's witnesses: bodies with quadratic section areas, every slab exactly a prismatoid,
integrated (volumes, centroids, moments)."""
import sympy as sp

from symfloat.engine.witness import Case, SectionIntegral

from .statements import D, G, a, b, c, d, dd, e, f, g, h, k, m, z

# ---- witnesses ----------------------------------------------------------------------------------------
# Bodies whose section area is a quadratic polynomial of the distance from ABC: every slab is then
# exactly a prismatoid in the sense of §3 (its z·A(z) is cubic), and so is the whole body.
A2 = k[0] + k[1] * z + k[2] * z ** 2
SEC = (a, b, c, dd, e, f, g)
QUADRATICS = ((sp.Rational(2), sp.Rational(1, 2), sp.Rational(-1, 9), sp.Rational(1, 2)),
              (sp.Rational(1, 3), sp.Rational(3), sp.Rational(-2, 5), sp.Rational(1, 3)),
              (sp.Rational(5), sp.Rational(-1, 2), sp.Rational(1, 7), sp.Rational(3, 4)))


def _case(coeffs):
    *ks, mv = coeffs
    values = dict(zip(k, ks))
    area = A2.xreplace(values)
    assert all(area.subs(z, mv * j / 10) > 0 for j in range(61)), "section areas must be positive"
    sections = {s: area.subs(z, i * mv) for i, s in enumerate(SEC)}
    return Case({**values, m: mv, **sections}, label=f"A(z) = {area}, m = {mv}")


CASES = tuple(_case(q) for q in QUADRATICS)
PRISMATOID_CASES = tuple(Case({**c_.params, G: c_.params[a], D: c_.params[b], g: c_.params[c], h: 2 * c_.params[m]},
                              label=c_.label + ", the slab a to c") for c_ in CASES)

d.witness(SectionIntegral("prismatoid-centroid", "centroid of bodies with quadratic A(z) above G",
                          ("prismatoid-centroid",), PRISMATOID_CASES, area=A2, z=z, bounds=(0, h),
                          quantity="centroid"))
d.witness(SectionIntegral("prismatoid-volume", "volume of bodies with quadratic A(z)",
                          ("prismatoid-volume",), PRISMATOID_CASES, area=A2, z=z, bounds=(0, h)))
for n, (lo, tc, tv, tm) in enumerate(((0, ("x1",), ("v1",), ("m1",)),
                                      (2, ("x2-a", "x2-b"), ("v2",), ("m2",)),
                                      (4, ("x3-a", "x3-b"), ("v3",), ("m3",))), 1):
    bounds = (lo * m, (lo + 2) * m)
    d.witness(SectionIntegral(f"slab-{n}-centroid", f"centroid of slab {n} from the plane ABC",
                              tc, CASES, area=A2, z=z, bounds=bounds, quantity="centroid", origin=0))
    d.witness(SectionIntegral(f"slab-{n}-volume", f"volume of slab {n}", tv, CASES, area=A2, z=z, bounds=bounds))
    d.witness(SectionIntegral(f"slab-{n}-moment", f"moment of slab {n} about the plane ABC",
                              tm, CASES, area=A2, z=z, bounds=bounds, quantity="moment", origin=0))
d.witness(SectionIntegral("slab-2-local-centroid", "centroid of slab 2 from the plane c",
                          ("substitution", "x2-local"), CASES, area=A2, z=z, bounds=(2 * m, 4 * m),
                          quantity="centroid"))
d.witness(SectionIntegral("slab-3-local-centroid", "centroid of slab 3 from the plane e",
                          ("x3-local",), CASES, area=A2, z=z, bounds=(4 * m, 6 * m), quantity="centroid"))
d.witness(SectionIntegral("body-moment", "moment of the whole body about the plane ABC",
                          ("moment-theorem", "moment-1", "moment-2", "moment-3"), CASES, area=A2, z=z,
                          bounds=(0, 6 * m), quantity="moment", origin=0))
d.witness(SectionIntegral("body-centroid", "centroid of the whole body from the plane ABC",
                          ("centroid",), CASES, area=A2, z=z, bounds=(0, 6 * m), quantity="centroid", origin=0))
