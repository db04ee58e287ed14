"""symfloat.engine.construction_witness: straightedge constructions measured numerically.

References are exact values worked by hand for the points named in each test."""
import mpmath
import sympy as sp

from symfloat.engine.construction_witness import (Along, Area, Centroid, ConstructionWitness, Coordinates, Length,
                                                  Meet, Mid, Ratio, Sum)
from symfloat.engine.witness import CERTIFIED, Case, record_decision

TETRAHEDRON = [(0, 0, 0), (4, 0, 0), (0, 6, 0), (0, 0, 8)]      # A B C D
NAMES = ("A", "B", "C", "D")


def measured(points, quantity, data=TETRAHEDRON):
    w = ConstructionWitness("t", "test", ("t",), (Case({}, data),), names=NAMES, points=points, quantity=quantity)
    return [w.measure(w.instances[0], m) for m in w.methods]


def close(value, exact, digits):
    """*value* (a number or tuple) agrees to *digits* with *exact* (SymPy numbers), compared at 60 digits."""
    values = value if isinstance(value, tuple) else (value,)
    with mpmath.workdps(60):
        return len(values) == len(exact) and all(
            abs(mpmath.mpf(v) - mpmath.mpf(sp.Float(sp.N(sp.sympify(e), 60), 60)._mpf_)) < mpmath.mpf(10) ** -digits
            for v, e in zip(values, exact))


def test_points_and_measurements_against_exact_values():
    # c = (B + D)/2 = (2, 0, 4); F = c + (C - c)/3 = (4/3, 2, 8/3); the centroid of BCD is (4/3, 2, 8/3) too
    points = (("c", Mid("B", "D")), ("F", Along("c", "C", sp.Rational(1, 3))), ("S", Centroid("B", "C", "D")))
    f15, f50 = measured(points, (Coordinates("F"), Coordinates("S")))
    exact = (sp.Rational(4, 3), 2, sp.Rational(8, 3)) * 2
    assert close(f15, exact, 14) and close(f50, exact, 48)
    # the right triangle ABC has the legs 4 and 6: area 12, hypotenuse sqrt(52); ABC : ABD = 12 : 16
    for value, digits in zip(measured((), (Area("A", "B", "C"), Length("B", "C"), Ratio(Area("A", "B", "C"),
                                       Area("A", "B", "D")), Sum(Area("A", "B", "C"), Area("A", "B", "D")))),
                             (14, 48)):
        assert close(value, (12, sp.sqrt(52), sp.Rational(3, 4), 28), digits)


def test_lines_meet_where_they_cross():
    # the medians of the face ABC from A and from B meet at its centroid (4/3, 2, 0)
    points = (("m", Mid("B", "C")), ("n", Mid("A", "C")), ("o", Meet("A", "m", "B", "n")))
    for value, digits in zip(measured(points, Coordinates("o")), (14, 48)):
        assert close(value, (sp.Rational(4, 3), 2, 0), digits)


def test_a_wrong_reading_disagrees():
    # mutation: the area of ABC read as 13 instead of 12 is refuted by the enclosure; the float64 measurement's own
    # error (proven against it) stays within its accuracy, and the 50-digit one is not needed
    w = ConstructionWitness("t", "test", ("t",), (Case({}, TETRAHEDRON),), names=NAMES, points=(),
                            quantity=Area("A", "B", "C"))
    assert w.run({"t": (sp.Symbol("S"), sp.Integer(12))})["t"].agrees
    out = w.run({"t": (sp.Symbol("S"), sp.Integer(13))})["t"]
    assert not out.agrees and [r["method"] for r in out.records] == [CERTIFIED, "float64"]
    assert [record_decision(r) for r in out.records] == ["refuted", "agrees"]
