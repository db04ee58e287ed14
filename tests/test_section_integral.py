"""SectionIntegral measures several bodies at once (a tuple of section areas, or of bounds): each component
against its exact integral, with every method within its tolerance, and a wrong reading is caught."""
import mpmath
import sympy as sp

from symfloat.engine.measured import measured
from symfloat.engine.witness import Case, SectionIntegral

z, h, r = sp.symbols("z h r", positive=True)
# exact references (by hand): ∫_0^h (1 - z/h)^2 dz = h/3, ∫_0^h z (h - z) dz = h^3/6; ∫_0^{k r} (r^2 + z^2) dz =
# k r^3 + k^3 r^3/3
AREAS = ((1 - z / h) ** 2, z * (h - z))
CASE = Case({h: sp.Rational(5, 2), r: sp.Rational(3, 2)}, label="h = 5/2, r = 3/2")


def _exact(params, *values):
    return [sp.N(v.xreplace(params), 60) for v in values]


def test_a_tuple_of_areas_gives_one_volume_per_area():
    w = SectionIntegral("two", "two bodies", ("t",), (CASE,), area=AREAS, z=z, bounds=(0, h))
    expected = _exact(CASE.params, h / 3, h ** 3 / 6)
    for method in w.methods:
        got = w.measure(CASE, method)
        assert len(got) == 2
        assert all(abs(mpmath.mpf(g) - mpmath.mpf(str(e))) <= max(method.tolerance, 1e-45) * abs(mpmath.mpf(str(e)))
                   for g, e in zip(got, expected)), method.name


def test_a_tuple_of_bounds_gives_one_value_per_pair_and_the_witness_refutes_a_wrong_reading():
    w = SectionIntegral("prefixes", "prefix volumes", ("t",), (CASE,), area=r ** 2 + z ** 2, z=z,
                        bounds=tuple((0, k * r) for k in (1, 2, 3)))
    right = sp.Matrix([k * r ** 3 + k ** 3 * r ** 3 / 3 for k in (1, 2, 3)])
    wrong = sp.Matrix([k * r ** 3 + k ** 3 * r ** 3 / 4 for k in (1, 2, 3)])
    assert w.run({"t": (right, right)})["t"].agrees
    assert not w.run({"t": (wrong, wrong)})["t"].agrees
    # one area and one pair: a number, as before
    single = SectionIntegral("one", "one", ("t",), (CASE,), area=r ** 2 + z ** 2, z=z, bounds=(0, r))
    assert not isinstance(single.measure(CASE, single.methods[0]), tuple)


def test_plane_sections_combined_by_an_expression_in_the_areas():
    # the disc of radius r cut at the heights 0 and r/2 of a sphere of radius r: areas pi r^2 and 3 pi r^2/4 (by
    # hand); the combination sqrt(A_0/pi), A_1/A_0 is the radius r and 3/4, and 2 r a parameter carried through
    from symfloat.engine.witness import PlaneSections
    P, eta = sp.symbols("P eta", real=True)
    w = PlaneSections("discs", "two sections", ("t",), (CASE,), width=2 * (r ** 2 - P ** 2) * sp.cos(eta) ** 2,
                      position=P, across=eta, chord=(-sp.pi / 2, sp.pi / 2), planes=(0, r / 2),
                      combine=(sp.sqrt(measured("section 1") / sp.pi), measured("section 2") / measured("section 1"),
                               2 * r))
    for method in w.methods:
        got = w.measure(CASE, method)
        assert all(abs(g - e) < max(method.tolerance, 1e-45) for g, e in zip(got, (1.5, 0.75, 3.0))), method.name
    assert w.run({"t": (sp.Symbol("q"), sp.Matrix([r, sp.Rational(3, 4), 2 * r]))})["t"].agrees
    assert not w.run({"t": (sp.Symbol("q"), sp.Matrix([r, sp.Rational(2, 3), 2 * r]))})["t"].agrees   # mutation
