"""Graefe §1's witnesses: random tetrahedra, pyramids and prismatoids measured by hull and slices, the
mid-section by Heron's formula, the side faces of exact hulls counted."""
import random
from fractions import Fraction

import sympy as sp

from symfloat.engine.construction_witness import Area, ConstructionWitness, Mid, Sum
from symfloat.engine.witness import Case, HullWitness, SideFaces
from symfloat.geometry.prismatoid import prismatoid_parameters, random_prismatoid

from .statements import D, G, XA, XB, XC, XD, d, g, h, kp, n, ps, qs

# ---- witnesses -----------------------------------------------------------------


def _prismatoid_case(seed):
    pts = random_prismatoid(seed)
    Gv, gv, Dv, hv = (sp.Rational(x.numerator, x.denominator) for x in prismatoid_parameters(pts))
    return Case({G: Gv, g: gv, D: Dv, h: hv}, pts, f"random prismatoid #{seed}")


def _tetrahedron_case(seed):
    rng = random.Random(seed)
    while True:
        pts = [tuple(Fraction(rng.randint(-6, 6)) for _ in range(3)) for _ in range(4)]
        values = {c: sp.Integer(v) for X, p in zip((XA, XB, XC, XD), pts) for c, v in zip(X, p)}
        if (XB - XA).dot((XC - XA).cross(XD - XA)).xreplace(values) != 0 and n.xreplace(values) != sp.zeros(3, 1):
            return Case(values, pts, f"random tetrahedron #{seed}")


def _pyramid_case(seed):
    pts = random_prismatoid(seed, apex_top=True)
    Gv, _, _, hv = prismatoid_parameters(pts)
    apex_down = [(x, y, hv - zz) for x, y, zz in pts]   # base g on top, apex O in the lower plane
    return Case({g: sp.Rational(Gv.numerator, Gv.denominator), h: sp.Rational(hv.numerator, hv.denominator)},
                apex_down, f"random pyramid #{seed}")


d.witness(HullWitness("tetrahedra", "volume of random tetrahedra (hull and slices)",
                      ("lemma-conclusion",), tuple(_tetrahedron_case(s) for s in range(3)), quantity="volume"))
d.witness(HullWitness("pyramids", "volume of random pyramids (hull and slices)",
                      ("pyramid-over-g",), tuple(_pyramid_case(s) for s in range(3)), quantity="volume"))
d.witness(HullWitness("prismatoids", "volume of random convex prismatoids (hull and slices)",
                      ("volume-sum", "volume-collected", "prismatoid-volume"),
                      tuple(_prismatoid_case(s) for s in range(4)), quantity="volume"))


def _pyramid_on_G_case(seed):
    pts = random_prismatoid(seed, apex_top=True)
    Gv, _, _, hv = prismatoid_parameters(pts)
    return Case({G: sp.Rational(Gv.numerator, Gv.denominator), h: sp.Rational(hv.numerator, hv.denominator)},
                pts, f"random pyramid #{seed} standing on G")


d.witness(HullWitness("pyramids-on-G", "volume of random pyramids standing on G (hull and slices)",
                      ("pyramids-over-G",), tuple(_pyramid_on_G_case(s) for s in range(3)), quantity="volume"))


# the parallelogram abcd (a, b, c, d the midpoints of AC, BC, BD, AD) as the triangles abc and acd, each by Heron's
# formula from its side lengths
d.witness(ConstructionWitness("mid-section-heron", "the mid-section abcd of random tetrahedra by Heron's formula",
                              ("parallelogram-half-triangle",), tuple(_tetrahedron_case(s) for s in range(3)),
                              names=("A", "B", "C", "D"),
                              points=(("a", Mid("A", "C")), ("b", Mid("B", "C")), ("c", Mid("B", "D")),
                                      ("d", Mid("A", "D"))),
                              quantity=Sum(Area("a", "b", "c"), Area("a", "c", "d"))))


def _prismatoid(lower, upper):
    """The vertices of the prismatoid with the base *lower* at height 0 and the top *upper* at height 1."""
    return [(x_, y_, 0) for x_, y_ in lower] + [(x_, y_, 1) for x_, y_ in upper]


PENTAGON = [(0, 0), (4, 0), (5, 3), (2, 5), (-1, 3)]
SQUARE = [(0, 0), (4, 0), (4, 4), (0, 4)]
FACE_CASES = (Case({ps: 5, qs: 4, kp: 0}, _prismatoid(PENTAGON, [(1, 1), (3, "3/2"), (3, 3), ("3/2", "7/2")]),
                   "pentagon under a quadrilateral, no sides parallel (Fig. 1: 5 + 4)"),
              Case({ps: 5, qs: 3, kp: 0}, _prismatoid(PENTAGON, [(1, 1), (3, 2), (2, 3)]), "pentagon under a triangle"))
d.witness(SideFaces("side-faces-hull", "the side faces of the convex hull of the two bases, counted",
                    ("side-faces",), FACE_CASES))
d.witness(SideFaces("parallel-sides-hull", "the side faces of the convex hull when one pair of sides is parallel",
                    ("parallel-sides",),
                    (Case({ps: 4, qs: 4, kp: 1}, _prismatoid(SQUARE, [(1, 1), (3, 1), ("5/2", 3), ("3/2", "5/2")]),
                          "square under a quadrilateral with its front side parallel"),)))
