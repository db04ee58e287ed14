"""Graefe §3's witnesses: centroids, heights and moments of random tetrahedra, pyramids and prismatoids by
hull and slice quadrature; Graefe's construction done numerically (Heron's formula, intersecting lines)."""
import random
from fractions import Fraction

import sympy as sp

from symfloat.engine.construction_witness import (Along, Area, Centroid, ConstructionWitness, Coordinates, Length,
                                                  Meet, Mid, Ratio)
from symfloat.engine.witness import Case, HullSlices, HullWitness
from symfloat.geometry.prismatoid import prismatoid_parameters, random_prismatoid

from .statements import D, G, L, PA, PB, PC, PD, d, g, h, o

# ---- witnesses ---------------------------------------------------------------------


def _tetrahedron_case(seed):
    rng = random.Random(seed)
    while True:
        pts = [tuple(Fraction(rng.randint(-6, 6)) for _ in range(3)) for _ in range(4)]
        pts = [tuple(x - y for x, y in zip(p, pts[0])) for p in pts]
        values = {s: sp.Integer(int(v)) for P, p in zip((PB, PC, PD), pts[1:]) for s, v in zip(P, p)}
        if (PB - PA).dot((PC - PA).cross(PD - PA)).xreplace(values) != 0:
            try:
                if not any(e.has(sp.zoo, sp.nan) for e in o.xreplace(values)) and \
                        not any(e.has(sp.zoo, sp.nan) for e in L.xreplace(values)):
                    return Case(values, pts, f"random tetrahedron #{seed}")
            except ZeroDivisionError:
                pass


def _prismatoid_case(seed):
    pts = random_prismatoid(seed)
    Gv, gv, Dv, hv = (sp.Rational(x.numerator, x.denominator) for x in prismatoid_parameters(pts))
    return Case({G: Gv, g: gv, D: Dv, h: hv}, pts, f"random prismatoid #{seed}")


SLICES = (HullSlices(3, 15, 1e-12), HullSlices(3, 40, 1e-35))
# The exact hull method sums tetrahedron centroids, i.e. it assumes the lemma:
# for the lemma only the slice quadratures are independent witnesses.
d.witness(HullWitness("tetrahedron-centroid", "centroid of random tetrahedra by slice quadrature",
                      ("lemma", "diagonals"), tuple(_tetrahedron_case(s) for s in range(3)),
                      quantity="centroid", methods=SLICES))
d.witness(HullWitness("prismatoid-centroid", "centroid height of random convex prismatoids",
                      ("centroid",), tuple(_prismatoid_case(s) for s in range(4)), quantity="height"))
d.witness(HullWitness("prismatoid-moment", "moment about G of random convex prismatoids",
                      ("moment-1", "moment-2", "moment-3"), tuple(_prismatoid_case(s) for s in range(4)),
                      quantity="moment"))
d.witness(HullWitness("prismatoid-volume", "volume of random convex prismatoids",
                      ("volume",), tuple(_prismatoid_case(s) for s in range(4)), quantity="volume"))


# Graefe's construction done numerically: c the midpoint of BD, F and G a third of the way from c to C and A, o the
# meeting point of CG and AF; the triangles measured by Heron's formula from their side lengths
TRISECTED = (("c", Mid("B", "D")), ("F", Along("c", "C", sp.Rational(1, 3))), ("G", Along("c", "A", sp.Rational(1, 3))),
             ("o", Meet("C", "G", "A", "F")))
RATIOS = {"Coc:CoA": Ratio(Area("C", "o", "c"), Area("C", "o", "A")),
          "coA:Coc": Ratio(Area("c", "o", "A"), Area("C", "o", "c")),
          "coA:CoA": Ratio(Area("c", "o", "A"), Area("C", "o", "A"))}
for target, ratio in (("ratio-1", "Coc:CoA"), ("ratio-2", "coA:Coc"), ("ratio-3", "coA:CoA"), ("ratio-4", "coA:CoA")):
    d.witness(ConstructionWitness(f"triangles-{target}", f"the ratio {ratio} of triangles by Heron's formula",
                                  (target,), tuple(_tetrahedron_case(s) for s in range(3)), names=("A", "B", "C", "D"),
                                  points=TRISECTED, quantity=RATIOS[ratio]))

# Graefe's points by intersecting lines only: F, G the centroids of BCD and ABD as meeting points of medians,
# o = CG ∩ AF, a = co ∩ AC, L = ac ∩ FG
CONSTRUCTED = (("c", Mid("B", "D")), ("F", Centroid("B", "C", "D")), ("G", Centroid("A", "B", "D")),
               ("o", Meet("C", "G", "A", "F")), ("a", Meet("c", "o", "A", "C")), ("L", Meet("a", "c", "F", "G")))
CONSTRUCTION_MEASURES = {
    "construction": (Coordinates("F"), Coordinates("G")),
    "quarters": (Length("o", "F"), Length("o", "G")),
    "a-midpoint": Length("a", "A"),
    "oL-ratio": Ratio(Length("L", "o"), Length("o", "a")),
    "aL": Length("L", "a"),
    "CF": Length("F", "C"),
    "oL": Length("L", "o"),
    "oc": Length("c", "o"),
}
for measured, measure in CONSTRUCTION_MEASURES.items():
    d.witness(ConstructionWitness(f"lines-{measured}", "Graefe's construction by intersecting lines (least squares)",
                                  (measured,), tuple(_tetrahedron_case(s) for s in range(3)), names=("A", "B", "C", "D"),
                                  points=CONSTRUCTED, quantity=measure))


def _pyramid_case(seed, apex_down):
    """A random pyramid: base G at z = 0 and apex at h, or (apex_down) base g at z = h and apex O at z = 0."""
    pts = random_prismatoid(seed, apex_top=True)
    Gv, _, _, hv = prismatoid_parameters(pts)
    area_, height = sp.Rational(Gv.numerator, Gv.denominator), sp.Rational(hv.numerator, hv.denominator)
    if apex_down:
        return Case({g: area_, h: height}, [(x_, y_, hv - z_) for x_, y_, z_ in pts], f"random pyramid #{seed}, apex in G")
    return Case({G: area_, h: height}, pts, f"random pyramid #{seed}, base G")


d.witness(HullWitness("arm-1-moment", "moment about G of random pyramids with the apex in G",
                      ("arm-1",), lambda: tuple(_pyramid_case(s, True) for s in range(3)), quantity="moment"))
d.witness(HullWitness("arm-2-moment", "moment about G of random pyramids standing on G",
                      ("arm-2",), lambda: tuple(_pyramid_case(s, False) for s in range(3)), quantity="moment"))


def _edge_pair_case(seed):
    """A random tetrahedron with one edge in the plane z = 0 and the opposite edge in z = h (the tetrahedra of
    group 3)."""
    rng = random.Random(seed)
    while True:
        hv = Fraction(rng.randint(2, 9), rng.randint(1, 3))
        pts = [(Fraction(rng.randint(-6, 6)), Fraction(rng.randint(-6, 6)), zz) for zz in (0, 0, hv, hv)]
        (x0, y0, _), (x1, y1, _), (x2, y2, _), (x3, y3, _) = pts
        if (x1 - x0) * (y3 - y2) - (y1 - y0) * (x3 - x2) != 0:      # the two edges not parallel: a solid
            return Case({h: sp.Rational(hv.numerator, hv.denominator)}, pts, f"random tetrahedron #{seed}, edges in G and g")


d.witness(HullWitness("height-1-hull", "centroid height of random pyramids with the apex in G",
                      ("height-1",), lambda: tuple(_pyramid_case(s, True) for s in range(3)), quantity="height"))
d.witness(HullWitness("height-2-hull", "centroid height of random pyramids standing on G",
                      ("height-2",), lambda: tuple(_pyramid_case(s, False) for s in range(3)), quantity="height"))
d.witness(HullWitness("height-3-hull", "centroid height of random tetrahedra with an edge in G and one in g",
                      ("height-3",), lambda: tuple(_edge_pair_case(s) for s in range(3)), quantity="height",
                      methods=SLICES))
d.witness(HullWitness("tetrahedron-centroid-2", "centroid of random tetrahedra by slice quadrature",
                      ("quarter-line", "lemma-restated"), lambda: tuple(_tetrahedron_case(s) for s in range(3)),
                      quantity="centroid", methods=SLICES))
