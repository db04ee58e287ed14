"""The certified method of the generic witness kinds (issue 29): readings and quantities enclosed in Arb balls,
each formula decided by the ball of the difference, a print refuted by one unit in its last digit, an exact
reading agreeing, an enclosure too wide undecided (never passed).

References (by hand): the ball of radius r has the volume 4/3 pi r^3 and its section at height z above the
lowest point the area pi (r^2 - (z - r)^2); at r = 1 the volume is 4.18879020478639... (4 pi / 3);
∫_{-1}^{1} sqrt(1 - x^2) dx = pi / 2; ∫_{-1}^{1} |x| dx = 1; the tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) has
the volume 1/6 and the centroid height 1/4; the prismatoid of a square under a smaller square has 4 side faces,
none of them triangles (each joins a side of the base to the parallel side of the top).
"""
from dataclasses import dataclass, replace
from fractions import Fraction

import pytest
import sympy as sp
from flint import arb

from symfloat.engine.check import FormulaReport, judge
from symfloat.engine.construction_witness import Area, Centroid, ConstructionWitness, Coordinates
from symfloat.engine.enclosure import Unsupported, ball, integral, iterated_integral, working_precision
from symfloat.engine.figure_witness import CurveRoot, Figure, FigureWitness
from symfloat.engine.measured import measured
from symfloat.engine.witness import (CERTIFIED, Case, HullWitness, MeasuredWitness, PlaneSections, SectionIntegral,
                                     SideFaces, record_decision)

x, z, r, P, eta = sp.symbols("x z r P eta", real=True)
UNIT = Case({r: 1}, label="r = 1")
SPHERE = SectionIntegral("ball", "the ball by its sections", ("v",), (UNIT,), area=sp.pi * (r ** 2 - (z - r) ** 2),
                         z=z, bounds=(0, 2 * r))


def chain(value):
    """A reading: the quantity's name equal to *value*."""
    return (sp.Symbol("q"), value)


def _certified(outcome):
    record = outcome.records[0]
    assert record["method"] == CERTIFIED and record["certified"]
    return record


# ---- the enclosure module ------------------------------------------------------------------------------------

def test_a_ball_contains_the_value_and_is_as_narrow_as_the_precision():
    b = ball(sp.sqrt(2) * sp.atan(sp.Rational(1, 3)) + sp.log(3) * sp.E ** 2, 200)
    with working_precision(200):
        exact = arb(2).sqrt() * (arb(1) / 3).atan() + arb(3).log() * arb(1).exp() ** 2
        assert b.overlaps(exact) and b.rad() < arb(2) ** -190


def test_a_float_is_its_exact_binary_value():
    # 0.1 in binary is 0.1000000000000000055511151231257827...: the ball holds that number, not 1/10
    b = ball(sp.Float(0.1), 128)
    with working_precision(128):
        assert not b.overlaps(arb(1) / 10)
        assert b.overlaps(arb("0.1000000000000000055511151231257827021181583404541015625"))


def test_a_float_of_60_digits_is_a_ball_of_its_60_digits():
    # a root a case gives at 60 digits (Scheeffer X's slope at the root of (171)): its 202-bit binary value at
    # 160 bits, not rounded to a double where the expression was compiled (a ball 1.1e-16 wide before)
    v = sp.Float("0.837010147138576977603184974107131203016108675526823193618151", 60)
    b = ball(-v, 160)
    with working_precision(256):
        assert b.rad() < arb(2) ** -150 and b.overlaps(-arb("0.837010147138576977603184974107131203016108675526823193618151"))


def test_an_unsupported_node_is_named():
    with pytest.raises(Unsupported, match="Piecewise"):
        integral(sp.Piecewise((x, x > 0), (0, True)), x, -1, 1, 64)
    with pytest.raises(Unsupported, match="erf"):
        ball(sp.erf(sp.Rational(1, 3)), 64)
    with pytest.raises(Unsupported, match="symbol r"):
        ball(r + 1, 64)


def test_rigorous_quadrature_with_a_branch_point_and_a_kink():
    with working_precision(128):
        half_disc = integral(sp.sqrt(1 - x ** 2), x, -1, 1, 128)
        assert half_disc.overlaps(arb.pi() / 2) and half_disc.rad() < arb(2) ** -100
        assert integral(sp.Abs(x), x, -1, 1, 128).overlaps(arb(1))


# ---- the decision by the ball ----------------------------------------------------------------------------------

def test_an_exact_reading_agrees_and_a_coefficient_one_unit_off_is_refuted():
    assert SPHERE.run({"v": chain(sp.Rational(4, 3) * sp.pi * r ** 3)})["v"].agrees
    # the coefficient 1.333 (4/3 to three digits) changed by one unit in its last digit, 1.334: refuted
    out = SPHERE.run({"v": chain(sp.Rational(1334, 1000) * sp.pi * r ** 3)})["v"]
    assert not out.agrees and not out.undecided
    assert record_decision(_certified(out)) == "refuted"


def test_a_printed_decimal_is_held_to_its_own_rounding():
    # 4 pi / 3 = 4.18879020...; printed 4.18879 (half a unit in the last digit: 5e-6) agrees, 4.18880 is refuted,
    # and the same 4.18880 printed with one digit fewer (4.1888, 5e-5) agrees
    half_unit = {"v": sp.Rational(5, 10 ** 6)}
    assert SPHERE.run({"v": chain(sp.Rational("4.18879"))}, half_unit)["v"].agrees
    refuted = SPHERE.run({"v": chain(sp.Rational("4.18880"))}, half_unit)["v"]
    assert record_decision(_certified(refuted)) == "refuted"
    assert SPHERE.run({"v": chain(sp.Rational("4.1888"))}, {"v": sp.Rational(5, 10 ** 5)})["v"].agrees


def test_the_methods_errors_are_proven_bounds_against_the_enclosure():
    out = SPHERE.run({"v": chain(sp.Rational(4, 3) * sp.pi * r ** 3)})["v"]
    for record in out.records[1:]:
        assert record["proven"]
        method = next(m for m in SPHERE.methods if m.name == record["method"])
        with working_precision(256):
            true_error = abs(arb(float(SPHERE.measure(UNIT, method))) - 4 * arb.pi() / 3) if method.dps <= 15 \
                else None
        if true_error is not None:        # the bound holds the float64 methods' actual error
            assert arb(record["abs_error"]) >= true_error.lower()
        assert record["rel_error"] <= record["rel_tolerance"]      # each method within its accuracy


_MEASURED = []      # the methods a _CountedBall measured, in order


@dataclass(frozen=True)
class _CountedBall(SectionIntegral):
    """The ball of :data:`SPHERE` noting each method it measures; ``blur`` widens its enclosure by that much."""

    blur: float = 0.0

    def measure(self, case, method):
        _MEASURED.append(method.name)
        return super().measure(case, method)

    def enclose(self, case, bits):
        with working_precision(bits):
            return super().enclose(case, bits) + arb(0, self.blur)


def _counted(blur=0.0):
    return _CountedBall("ball", "the ball by its sections", ("v",), (UNIT,), area=sp.pi * (r ** 2 - (z - r) ** 2),
                        z=z, bounds=(0, 2 * r), blur=blur)


def test_a_decided_formula_measures_only_the_cheapest_method_beside_the_ball():
    # agreeing (4/3 pi r^3) and refuted (4.18880, one unit off in the last of six digits): the ball decides, so
    # the finer methods (tanh-sinh at 50 digits, Gauss-Legendre) are not measured; the first of the least digits
    # (tanh-sinh at 15) is, once for both formulas, and its proven error stands beside the certified record
    w = _counted()
    _MEASURED.clear()
    out = w.run({"v": chain(sp.Rational(4, 3) * sp.pi * r ** 3), "v#off": chain(sp.Rational("4.18880"))},
                {"v": sp.Rational(5, 10 ** 6)})
    assert w.cheapest == (SPHERE.methods[0],) and _MEASURED == [SPHERE.methods[0].name]
    assert out["v"].agrees and record_decision(_certified(out["v#off"])) == "refuted"
    for o in out.values():
        assert [r["method"] for r in o.records] == [CERTIFIED, SPHERE.methods[0].name] and o.records[1]["proven"]


def test_an_undecided_formula_measures_every_method():
    # an enclosure 10^-3 wide at every precision cannot decide 4/3 pi r^3: every method's proven error is recorded
    _MEASURED.clear()
    out = _counted(1e-3).run({"v": chain(sp.Rational(4, 3) * sp.pi * r ** 3)})["v"]
    assert out.undecided and _MEASURED == [m.name for m in SPHERE.methods]
    assert [r["method"] for r in out.records] == [CERTIFIED] + [m.name for m in SPHERE.methods]


def test_plane_sections_decide_by_the_ball():
    # the sphere of radius r cut at the heights 0 and r/2 (areas pi r^2, 3 pi r^2 / 4): the radius and the ratio
    w = PlaneSections("discs", "two sections", ("t",), (Case({r: sp.Rational(3, 2)}),),
                      width=2 * (r ** 2 - P ** 2) * sp.cos(eta) ** 2, position=P, across=eta,
                      chord=(-sp.pi / 2, sp.pi / 2), planes=(0, r / 2),
                      combine=(sp.sqrt(measured("section 1") / sp.pi), measured("section 2") / measured("section 1")))
    assert w.run({"t": chain(sp.Matrix([r, sp.Rational(3, 4)]))})["t"].agrees
    out = w.run({"t": chain(sp.Matrix([r, sp.Rational(751, 1000)]))})["t"]       # 0.750 one unit off
    assert record_decision(_certified(out)) == "refuted"


TETRAHEDRON = Case({}, [(Fraction(0),) * 3, (Fraction(1), Fraction(0), Fraction(0)),
                        (Fraction(0), Fraction(1), Fraction(0)), (Fraction(0), Fraction(0), Fraction(1))])


def test_exact_geometry_stays_exact():
    volume = HullWitness("tet", "a tetrahedron", ("v",), (TETRAHEDRON,), quantity="volume")
    record = _certified(volume.run({"v": chain(sp.Rational(1, 6))})["v"])
    assert record["abs_error"] == 0.0 and record_decision(record) == "agrees"     # a ball of radius 0
    height = HullWitness("tet", "a tetrahedron", ("h",), (TETRAHEDRON,), quantity="height")
    # 1/4 printed as 0.2500000000000000001 (a difference of 1e-19): exact arithmetic refutes it
    off = height.run({"h": chain(sp.Rational(2500000000000000001, 10 ** 19))})["h"]
    assert record_decision(_certified(off)) == "refuted"


def test_a_count_one_off_is_refuted():
    square = [(0, 0), (4, 0), (4, 4), (0, 4)]
    top = [(1, 1), (3, 1), (3, 3), (1, 3)]
    case = Case({}, [(Fraction(a), Fraction(b), Fraction(0)) for a, b in square]
                + [(Fraction(a), Fraction(b), Fraction(1)) for a, b in top])
    w = SideFaces("faces", "side faces", ("n",), (case,))
    assert w.run({"n": chain(sp.Matrix([4, 0]))})["n"].agrees
    assert record_decision(_certified(w.run({"n": chain(sp.Matrix([5, 0]))})["n"])) == "refuted"


class _Blurred(MeasuredWitness):
    """A witness whose enclosure never narrows: 1/3 within 10^-3 at every precision."""

    methods = ()

    def measure(self, case, method):  # pragma: no cover - it has no methods
        raise AssertionError

    def enclose(self, case, bits):
        with working_precision(bits):
            return arb(1) / 3 + arb(0, 1e-3)


def test_an_enclosure_too_wide_is_undecided_and_never_passed():
    w = _Blurred("blur", "a blurred third", ("t",), (Case({}),))
    out = w.run({"t": chain(sp.Rational(1, 3))})["t"]
    record = _certified(out)
    assert record_decision(record) == "undecided" and out.undecided and not out.agrees
    assert record["bits"] == 8 * 128                      # raised to the cap before giving up
    assert "undecided" in out.note
    # far enough off, the same wide ball refutes: the difference excludes 0
    assert record_decision(_certified(w.run({"t": chain(sp.Rational(1, 2))})["t"])) == "refuted"
    # the judge neither fails a verified formula for it nor counts it as agreement
    identity = {"status": "proved"}
    f = FormulaReport("d/t", "s", "l", "verified", "symbolic", [record], "", "", identity=identity)
    verdict, evidence, failures = judge(f, False)
    assert (verdict, failures) == ("verified", [])
    f.identity = {"status": "refuted"}
    assert "the print is refuted but the witnesses agree with it" not in judge(f, True)[2]


def test_the_cheapest_method_is_the_first_of_the_least_digits():
    hull = HullWitness("tet", "a tetrahedron", ("v",), (TETRAHEDRON,))
    assert [m.name for m in hull.cheapest] == ["slices, Gauss-Legendre n=3, 15 digits"]    # not the exact hull
    assert SideFaces("f", "faces", ("n",), ()).cheapest == (SideFaces.methods[0],)      # both exact: the first
    assert _Blurred("blur", "a blurred third", ("t",), ()).cheapest == ()


def test_a_construction_is_enclosed_point_by_point():
    # the right triangle (0,0,0), (3,0,0), (0,4,0): area 6 by Heron, centroid (1, 4/3, 0) where two medians meet
    w = ConstructionWitness("s", "a right triangle", ("t",), (Case({}, [(0, 0, 0), (3, 0, 0), (0, 4, 0)]),),
                            names=("P", "Q", "R"), points=(("S", Centroid("P", "Q", "R")),),
                            quantity=(Area("P", "Q", "R"), Coordinates("S")))
    assert w.run({"t": chain(sp.Matrix([6, 1, sp.Rational(4, 3), 0]))})["t"].agrees
    off = w.run({"t": chain(sp.Matrix([6, 1, sp.Rational(1334, 1000), 0]))})["t"]     # 1.333 one unit off
    assert record_decision(_certified(off)) == "refuted"


def test_plane_figures_polygons_exact_strips_by_rigorous_quadrature():
    X, Y, a, b = sp.symbols("X Y a b", positive=True)
    case = Case({a: 3, b: 2})
    ellipse = Figure.strips(Y, X, -a, a, (-b * sp.sqrt(1 - X ** 2 / a ** 2), b * sp.sqrt(1 - X ** 2 / a ** 2)))
    # ∫∫ x² over the ellipse: pi a³ b / 4 (= 27 pi / 2 here); the coefficient 1/4 read 0.251 is refuted
    w = FigureWitness("e", "the ellipse", ("m",), (case,), coords=(X, Y), figure=ellipse,
                      quantity=measured("integral", of=X ** 2))
    assert w.run({"m": chain(sp.pi * a ** 3 * b / 4)})["m"].agrees
    assert record_decision(_certified(w.run({"m": chain(sp.Rational(251, 1000) * sp.pi * a ** 3 * b)})["m"])) \
        == "refuted"
    # the triangle (0,0), (a,0), (0,b): centroid (a/3, b/3), exact: the difference is a ball of radius 0
    tri = FigureWitness("t", "a triangle", ("c",), (case,), coords=(X, Y),
                        figure=Figure.polygon([(0, 0), (a, 0), (0, b)]),
                        quantity=(measured("centroid, 1"), measured("centroid, 2")))
    record = _certified(tri.run({"c": chain(sp.Matrix([a / 3, b / 3]))})["c"])
    assert record_decision(record) == "agrees" and record["abs_error"] == 0.0


def test_a_curve_root_is_proven_by_a_sign_change():
    X, Y, a, b = sp.symbols("X Y a b", positive=True)
    w = CurveRoot("y", "the ellipse's ordinate", ("y",), (Case({a: 2, b: 1, X: sp.Rational(1, 2)}),),
                  equation=X ** 2 / a ** 2 + Y ** 2 / b ** 2 - 1, variable=Y, bracket=(0, b))
    assert w.run({"y": chain(b * sp.sqrt(1 - X ** 2 / a ** 2))})["y"].agrees       # sqrt(15) / 4
    assert record_decision(_certified(w.run({"y": chain(sp.Rational(9683, 10000))})["y"])) == "refuted"  # 0.9682 + 1


def test_a_root_that_touches_zero_is_exact():
    # the ordinate of the ellipse at X = a is 0, a double root of the equation (no sign change to prove): exact
    # where the equation vanishes at the float64 root in exact arithmetic (Graefe's triaxial stump cut at x' = a)
    X, Y, a, b = sp.symbols("X Y a b", positive=True)
    w = CurveRoot("y", "the ellipse's ordinate at its vertex", ("y",), (Case({a: 2, b: 1, X: 2}),),
                  equation=X ** 2 / a ** 2 + Y ** 2 / b ** 2 - 1, variable=Y, bracket=(0, b))
    assert w.enclose(w.instances[0], 128) == 0
    record = _certified(w.run({"y": chain(b * sp.sqrt(1 - X ** 2 / a ** 2))})["y"])
    assert record_decision(record) == "agrees" and record["abs_error"] == 0.0
    assert record_decision(_certified(w.run({"y": chain(sp.Rational(1, 10 ** 12))})["y"])) == "refuted"


def test_cot_is_enclosed():
    # cot(1/2) = cos(1/2)/sin(1/2) = 1.8304877217124519...; Scheeffer IX's (cot) prints cot phi_2
    with working_precision(128):
        by_sine = (arb(1) / 2).cos() / (arb(1) / 2).sin()
        assert ball(sp.cot(sp.Rational(1, 2)), 128).overlaps(by_sine)
        assert not ball(sp.cot(sp.Rational(1, 2)) + sp.Rational(1, 10 ** 12), 128).overlaps(by_sine)
    assert not ball(sp.cot(x), 128, {x: arb(0, 1e-3)}).is_finite()         # a ball holding the pole at 0


def test_a_reading_without_a_rigorous_rule_is_undecided_and_still_compared():
    # Lambert's W is not on the enclosure's whitelist: 4/3 pi r^3 written with W(1) e^W(1) = 1 (W(1) is the omega
    # constant, e^-W(1) = W(1))
    omega = sp.LambertW(1)
    out = SPHERE.run({"v": chain(omega * sp.exp(omega) * sp.pi * sp.Rational(4, 3) * r ** 3)})["v"]
    record = _certified(out)
    assert "LambertW" in record["unsupported"] and record_decision(record) == "undecided" and out.undecided
    assert out.note.endswith("undecided, no finite enclosure of the difference at 128 bits")    # not 'too wide'
    assert record["bits"] == 128                  # no precision raised for a node no precision can enclose
    assert [record_decision(r) for r in out.records[1:]] == ["agrees"] * len(SPHERE.methods)    # the former route


# ---- functions of a derivation: enclosed by the closed form their rewrite in Γ gives ------------------------------

class _Beta(sp.Function):
    """∫₀¹ y^p (1 − y²)^q dy, rewritten as Γ((p + 1)/2) Γ(q + 1) / (2 Γ((p + 1)/2 + q + 1)) (Euler's Ib at n = 2, b = 1)."""
    nargs = 2

    def _eval_rewrite_as_gamma(self, p, q, **hints):
        return sp.gamma((p + 1) / 2) * sp.gamma(q + 1) / (2 * sp.gamma((p + 1) / 2 + q + 1))


def test_a_function_of_a_derivation_is_enclosed_by_its_gamma_form():
    y = sp.Symbol("y")
    by_gamma = ball(_Beta(sp.Integer(2), sp.Rational(1, 2)), 128)
    by_quadrature = integral(y ** 2 * sp.sqrt(1 - y ** 2), y, 0, 1, 128)     # the independent route: pi / 16
    with working_precision(128):
        assert by_gamma.overlaps(by_quadrature) and by_gamma.overlaps(arb.pi() / 16)
        assert not ball(_Beta(sp.Integer(3), sp.Rational(1, 2)), 128).overlaps(by_quadrature)   # mutated exponent
    assert by_gamma.rad() < arb(2) ** -120
    with pytest.raises(Unsupported):
        ball(sp.Function("F")(sp.Integer(1)), 128)        # a function with no closed form: no guess

    class _Looping(sp.Function):                           # its gamma form still contains itself
        def _eval_rewrite_as_gamma(self, *args, **kwargs):
            return 2 * _Looping(*args)
    with pytest.raises(Unsupported, match="_Looping"):
        ball(_Looping(sp.Integer(1)), 128)


def test_euler_s_own_functions_enclosed_as_the_quadrature_of_their_integrals():
    from symfloat.derivations.euler_229_243.statements import IY, Ib
    y = sp.Symbol("y")
    # Ib(p, q, n, b) = ∫₀ᵇ yᵖ (1 − yⁿ/bⁿ)^q dy; IY(j, p, q, 0, n, b, c1, c2) = ∫₀ᵇ Y^j yᵖ (1 − yⁿ/bⁿ)^q dy, Y = c1 yⁿ/bⁿ + c2 y²ⁿ/b²ⁿ
    b, c1, c2 = sp.Rational(3, 4), sp.Rational(-1, 4), sp.Rational(1, 8)
    Y = c1 * y ** 2 / b ** 2 + c2 * y ** 4 / b ** 4
    for value, integrand in ((Ib(sp.Integer(2), sp.Rational(1, 2), 2, b), y ** 2 * sp.sqrt(1 - y ** 2 / b ** 2)),
                             (IY(2, 0, sp.Rational(1, 2), 0, 2, b, c1, c2), Y ** 2 * sp.sqrt(1 - y ** 2 / b ** 2))):
        enclosed, quadrature = ball(value, 128), integral(integrand, y, 0, b, 128)
        assert enclosed.overlaps(quadrature) and enclosed.rad() < arb(2) ** -100, value


# ---- integrands unbounded at an end: the substitution that removes the singularity ---------------------------------

@pytest.mark.parametrize("integrand, lo, hi, exact", [
    # ∫₀ᵇ y²/√(b² − y²) dy = π b²/4 (y = b sin θ); Euler §222's V2 at b = 3/2
    (lambda y: y ** 2 / sp.sqrt(sp.Rational(9, 4) - y ** 2), 0, sp.Rational(3, 2), sp.pi * sp.Rational(9, 16)),
    # ∫₋₁¹ dy/√(1 − y²) = π: singular at both ends
    (lambda y: 1 / sp.sqrt(1 - y ** 2), -1, 1, sp.pi),
    # ∫₀¹ (1 − √y)^(−1/2) dy = 8/3 (y = w²: 2w/√(1 − w), then w = 1 − t²): a root of var in the base
    (lambda y: (1 - sp.sqrt(y)) ** sp.Rational(-1, 2), 0, 1, sp.Rational(8, 3)),
])
def test_an_integrand_unbounded_at_an_end_is_enclosed(integrand, lo, hi, exact):
    y = sp.Symbol("y", positive=True)
    value = integral(integrand(y), y, lo, hi, 128)
    with working_precision(128):
        assert value.is_finite() and value.overlaps(ball(exact, 128)) and value.rad() < arb(2) ** -100
        assert not value.overlaps(ball(exact * (1 + sp.Rational(1, 10 ** 12)), 128))     # mutated: refuted


def test_a_singularity_it_cannot_remove_stays_undecided():
    y = sp.Symbol("y", positive=True)
    # log(1 - y) is unbounded at y = 1 but is no power: no substitution, no finite enclosure, no guess
    assert not integral(sp.log(1 - y), y, 0, 1, 64).is_finite()


# ---- iterated integrals: a multiple integral as nested ones ---------------------------------------------------

_y = sp.Symbol("y", real=True)


@pytest.mark.parametrize("integrand, limits, exact", [
    # the right triangle 0 <= x <= 2, |y| <= x/2: its area 2 and its moment of inertia about the x axis,
    # int_0^2 2 (x/2)^3 / 3 dx = 1/3 (the inner ends depend on the outer variable)
    (1, ((_y, -x / 2, x / 2), (x, 0, 2)), Fraction(2)),
    (_y ** 2, ((_y, -x / 2, x / 2), (x, 0, 2)), Fraction(1, 3)),
    # the unit tetrahedron's volume, three deep: 1/6
    (1, ((z, 0, 1 - x - _y), (_y, 0, 1 - x), (x, 0, 1)), Fraction(1, 6)),
])
def test_an_iterated_integral_is_enclosed_and_a_value_off_by_1e_12_refuted(integrand, limits, exact):
    v = iterated_integral(integrand, limits, 128)
    with working_precision(128):
        assert v.overlaps(arb(exact.numerator) / exact.denominator) and v.rad() < arb(2) ** -100
        assert not v.overlaps(arb(exact.numerator) / exact.denominator * (1 + arb(10) ** -12))


def test_an_iterated_integral_not_holomorphic_in_its_outer_variable_has_no_finite_enclosure():
    # the inner end sqrt(1 - x^2) has a branch point at the outer end x = 1: the outer integrator asks for
    # holomorphy there, the inner integrand is asked too, and the enclosure is not finite (never a guess)
    v = iterated_integral(1, ((_y, 0, sp.sqrt(1 - x ** 2)), (x, 0, 1)), 128)
    assert not v.is_finite()


def test_an_iterated_integral_stops_at_its_budget_of_evaluations(monkeypatch):
    # an inner integrand that is never finite: every outer evaluation would integrate anew until the outer
    # integrator's own limit; past the budget (a count) the inner integrals stop at once
    import symfloat.engine.enclosure as enclosure
    calls, depth = [], [0]
    real = enclosure._compile

    def counted(e, variables):         # the integrand's evaluations, not its nodes'
        depth[0] += 1
        try:
            f = real(e, variables)
        finally:
            depth[0] -= 1
        return (lambda v, a: calls.append(1) or f(v, a)) if depth[0] == 0 else f
    monkeypatch.setattr(enclosure, "_compile", counted)
    v = iterated_integral(1 / sp.sqrt(sp.Abs(_y - sp.Rational(1, 2))), ((_y, 0, 1), (x, 0, 1)), 64)
    assert not v.is_finite() and len(calls) <= enclosure.ITERATED_EVALUATIONS * 64 + 2     # and its two ends' balls


# ---- Min and Max: a reading clipped to bounds ------------------------------------------------------------------

def test_min_and_max_are_enclosed_and_in_an_integrand_only_where_one_side_is_proven_the_extreme():
    # min(max(√2, 6), 12) = 6 exactly; max(1/3, π/10) = 1/3 (π/10 = 0.314...)
    assert ball(sp.Min(sp.Max(sp.sqrt(2), 6), 12), 128) == 6
    with working_precision(128):
        assert ball(sp.Max(sp.Rational(1, 3), sp.pi / 10), 128).overlaps(arb(1) / 3)
        # ∫₀¹ min(x, 1 − x) dx = 1/4: the kink at 1/2 is bisected around, each piece one side
        tent = integral(sp.Min(x, 1 - x), x, 0, 1, 128)
        assert tent.overlaps(arb(1) / 4) and tent.rad() < arb(2) ** -60


def test_euler_mu_bounds_clipped_by_min_and_max_is_decided_and_a_mutated_bound_refuted():
    # §237: μ clipped to [6, 12] is μ on the admissible family; the member n = 1, κ = 1 (the rhombus: half area
    # ab, moment of the half about AB ab³/6) has μ_AB = (2b)² ab / (2 ab³/6) = 12 exactly, so the bound 12
    # changed to 11.9 clips it: refuted by the ball, not undecided
    from symfloat.registry import load
    derivation, _ = load("euler-229-243")
    witness = next(w for w in derivation.witnesses if w.name == "mu-bounds")
    clipped, mu = next(p for p in derivation.printed if p.name == "mu-bounds").reading
    assert record_decision(_certified(witness.run({"mu-bounds": (clipped, mu)})["mu-bounds"])) == "agrees"
    lowered = clipped.xreplace({sp.Integer(12): sp.Rational(119, 10)})
    out = witness.run({"mu-bounds": (lowered, mu)})["mu-bounds"]
    assert record_decision(_certified(out)) == "refuted" and not out.agrees and not out.undecided


# ---- the floating witnesses: the clipped body in ball arithmetic --------------------------------------------------
# References (by hand): the box a x b x c floating upright at the density ratio s has the draught s c and, for a
# ≥ b, the metacentric height b²/(12 s c) - (1 - s) c / 2 (I = a b³/12 over V = a b s c, G - B = (c - s c)/2): at
# 2 x 1 x 1 and s = 1/2, 1/6 - 1/4 = -1/12.  The unit square log lying flat has the metacentric height
# 1/(12 s) - (1 - s)/2, zero at s² - s + 1/6 = 0: the lower threshold s = (3 - √3)/6 = 0.21132486540518...  The
# unit cube cut by the plane x + y = 0 (through four of its vertices) has half its volume below.

def _floating():
    from symfloat.engine.floating_witness import (Body, Combined, CutWitness, FloatingRootWitness, FloatingWitness,
                                                  Joined, Root)
    return Body, Combined, CutWitness, FloatingRootWitness, FloatingWitness, Joined, Root


def test_a_floating_box_is_enclosed_and_a_quantity_off_by_1e_12_refuted():
    Body, _, _, _, FloatingWitness, _, _ = _floating()
    s = sp.Symbol("s", positive=True)
    box = FloatingWitness("box", "the clipped box", ("draught", "gm"), (Case({s: sp.Rational(1, 2)}, label="s = 1/2"),),
                          body=Body.box(2, 1, 1), up=(0, 0, 1), density=s, quantity=(measured("draught"), measured("metacentric height")))
    assert isinstance(box.enclose(box.instances[0], 128)[1], arb)
    out = box.run({"draught": chain(sp.Matrix([s, -sp.Rational(1, 12)]))})["draught"]
    assert record_decision(_certified(out)) == "agrees" and out.agrees
    off = box.run({"draught": chain(sp.Matrix([s, -sp.Rational(1, 12) + sp.Rational(1, 10 ** 12)]))})["draught"]
    assert record_decision(_certified(off)) == "refuted" and not off.agrees and not off.undecided
    # the methods' errors are proven against the ball
    assert all(r.get("proven") for r in out.records[1:])


def test_a_density_threshold_is_a_proven_sign_change_and_its_last_printed_digit_counts():
    Body, _, _, FloatingRootWitness, _, _, Root = _floating()
    rho, s0 = sp.symbols("rho s0", positive=True)
    threshold = FloatingRootWitness(
        "threshold", "the lower zero of the clipped log's metacentric height", ("s0",), (Case({}, label="unit log"),),
        body=Body.box(1, 1, 4), up=(0, 1, 0), density=rho, quantity=s0,
        roots=((s0, Root.scan(measured("metacentric height"), rho, sp.Rational(1, 20), sp.Rational(1, 2), 9)),))
    exact_root = (3 - sp.sqrt(3)) / 6
    assert record_decision(_certified(threshold.run({"s0": chain(exact_root)})["s0"])) == "agrees"
    assert record_decision(_certified(threshold.run({"s0": chain(exact_root + sp.Rational(1, 10 ** 12))})["s0"])) \
        == "refuted"
    # printed 0.2113 (half a unit in the last digit allowed): agrees; 0.2114, one unit off, refuted
    half_unit = {"s0": sp.Rational(5, 10 ** 5)}
    assert record_decision(_certified(threshold.run({"s0": chain(sp.Rational(2113, 10 ** 4))}, half_unit)["s0"])) \
        == "agrees"
    assert record_decision(_certified(threshold.run({"s0": chain(sp.Rational(2114, 10 ** 4))}, half_unit)["s0"])) \
        == "refuted"


def test_a_cut_through_vertices_joins_both_sides_and_stays_exact_enough():
    Body, Combined, CutWitness, _, FloatingWitness, Joined, _ = _floating()
    one = Case({}, label="unit cube")
    cut = CutWitness("cut", "the unit cube below x + y = 0", ("half",), (one,), body=Body.box(1, 1, 1), up=(1, 1, 0),
                     through=(sp.Rational(1, 2), -sp.Rational(1, 2), 0), quantity=measured("immersed volume"))
    assert record_decision(_certified(cut.run({"half": chain(sp.Rational(1, 2))})["half"])) == "agrees"
    assert record_decision(_certified(cut.run({"half": chain(sp.Rational(1, 2) + sp.Rational(1, 10 ** 12))})["half"])) \
        == "refuted"
    # parts joined and combined: the draughts of the cube at 1/3 and 2/3, and their difference 1/3
    parts = tuple(FloatingWitness("", "", (), (), body=Body.box(1, 1, 1), density=sp.Rational(k, 3)) for k in (1, 2))
    joined = Joined("both", "both draughts", ("both",), (one,), parts=parts)
    assert record_decision(_certified(joined.run({"both": chain(sp.Matrix([sp.Rational(1, 3),
                                                                            sp.Rational(2, 3)]))})["both"])) == "agrees"
    difference = Combined("diff", "their difference", ("diff",), (one,), parts=parts,
                          values=(measured("part 2") - measured("part 1"),))
    assert record_decision(_certified(difference.run({"diff": chain(sp.Rational(1, 3) - sp.Rational(1, 10 ** 12))})
                                      ["diff"])) == "refuted"


# The circular cylinder (radius r, length L, axis z) against closed forms derived by hand (as in
# tests/test_floating_witness.py): upright at density s the draught is s L from the bottom (Archimedes), the
# waterplane a disc (area pi r^2, second moment pi r^4/4), so the metacentric height is r^2/(4 L s) - (1 - s) L/2;
# it vanishes where s (1 - s) = r^2/(2 L^2), at r = 1/2, L = 1 where s = (2 - sqrt 2)/4 (the lower root).  Tilted
# by psi with no base cut, B - G = (-tan(psi) r^2/(4 s L), 0, -(1 - s) L/2 + tan^2(psi) r^2/(8 s L)) (the column
# over the disc up to the tilted plane, int x^2 dA = pi r^4/4), so the arm, -cos(psi) (B - G)_x + sin(psi)
# (B - G)_z up to a factor sin(psi), vanishes where tan^2(psi) = 4 s (1 - s) L^2/r^2 - 2: 11/32 at r = 8/5,
# L = 5/2, s = 3/5 (the water line's ends (s - 1/2) L +- r tan(psi) = 0.25 +- 0.94 stay between the bases); the
# upper base meets the water where (s - 1/2) L + r tan(psi) = L/2, tan(psi) = (1 - s) L/r = 5/8 there (the lower
# end, 0.25 - 1, still above the lower base): a root where the plane passes through the rim.  The
# waterplane of that tilt is an ellipse with semi-axes r/cos(psi), r: I max = pi r^4/(4 cos^3 psi).  Lying at
# s = 1/2 the waterplane is the rectangle L x 2r (I min = L (2r)^3/12), B the centroid of a half disc, 4r/(3 pi)
# below the water, and the metacentric height 0.
def _cylinder(name, up, s, radius=1, length=4, **kw):
    Body, _, _, _, FloatingWitness, _, _ = _floating()
    return FloatingWitness("cylinder", "the floating cylinder", ("q",), (Case({}, label="cylinder"),),
                           body=Body.cylinder(radius, length), up=up, density=s, quantity=measured(name), **kw)


PSI_C = sp.Symbol("psi", positive=True)


@pytest.mark.parametrize("quantity, up, s, exact", [
    ("draught", (0, 0, 1), sp.Rational(3, 10), sp.Rational(6, 5)),
    ("metacentric height", (0, 0, 1), sp.Rational(3, 10), sp.Rational(1, 16) / sp.Rational(3, 10) - sp.Rational(7, 5)),
    ("metacentric height", (0, 0, -1), sp.Rational(3, 10), sp.Rational(1, 16) / sp.Rational(3, 10) - sp.Rational(7, 5)),
    ("I max", (sp.sin(sp.atan(sp.Rational(1, 4))), 0, sp.cos(sp.atan(sp.Rational(1, 4)))), sp.Rational(1, 2),
     sp.pi / (4 * sp.cos(sp.atan(sp.Rational(1, 4))) ** 3)),
    ("B - G, x", (sp.sin(sp.atan(sp.Rational(1, 4))), 0, sp.cos(sp.atan(sp.Rational(1, 4)))), sp.Rational(1, 2),
     -sp.Rational(1, 4) / (4 * sp.Rational(1, 2) * 4)),
    ("I min", (1, 0, 0), sp.Rational(1, 2), 4 * sp.Integer(2) ** 3 / 12),
    ("B below water", (1, 0, 0), sp.Rational(1, 2), 4 / (3 * sp.pi)),
    ("metacentric height", (0, 1, 0), sp.Rational(1, 2), sp.Integer(0)),
])
def test_the_cylinder_upright_tilted_and_lying_is_enclosed_about_its_closed_forms(quantity, up, s, exact):
    w = _cylinder(quantity, up, s)
    value = w.enclose(w.instances[0], 128)
    with working_precision(160):
        assert isinstance(value, arb) and value.overlaps(ball(exact, 160)) and value.rad() < arb(2) ** -100


def test_a_cylinder_s_draught_is_bracketed_about_a_density_ball_wider_than_the_precision():
    # lying at s = 1/2 +- 2^-70 (a density found as a root): the bracket holds the axis's draught 0 at s = 1/2
    from symfloat.engine.cylinder_enclosure import cylinder_state
    with working_precision(160):
        s = (arb(1) / 2).union(arb(1) / 2 + arb(2) ** -70).union(arb(1) / 2 - arb(2) ** -70)
        st = cylinder_state(arb(1), Fraction(2), (arb(1), arb(0), arb(0)), s, 128)
        assert st.t.overlaps(arb(0)) and st.t.rad() < arb(2) ** -60


def test_a_cylinder_quantity_is_enclosed_and_a_value_off_by_1e_12_refuted():
    w = _cylinder("metacentric height", (0, 0, 1), sp.Rational(3, 10))
    gm = sp.Rational(1, 16) / sp.Rational(3, 10) - sp.Rational(7, 5)
    out = w.run({"q": chain(gm)})["q"]
    assert record_decision(_certified(out)) == "agrees" and out.agrees
    off = w.run({"q": chain(gm + sp.Rational(1, 10 ** 12))})["q"]
    assert record_decision(_certified(off)) == "refuted" and not off.agrees and not off.undecided


def test_a_cylinder_s_density_threshold_and_tilted_equilibrium_are_proven_roots():
    Body, _, _, FloatingRootWitness, _, _, Root = _floating()
    rho, s0 = sp.symbols("rho s0", positive=True)
    threshold = FloatingRootWitness(
        "threshold", "the lower zero of the upright cylinder's metacentric height", ("s0",), (Case({}, label="2r = L"),),
        body=Body.cylinder(sp.Rational(1, 2), 1), up=(0, 0, 1), density=rho, quantity=s0,
        roots=((s0, Root.scan(measured("metacentric height"), rho, sp.Rational(1, 100), sp.Rational(49, 100), 24)),))
    lower = (2 - sp.sqrt(2)) / 4
    assert record_decision(_certified(threshold.run({"s0": chain(lower)})["s0"])) == "agrees"
    assert record_decision(_certified(threshold.run({"s0": chain(lower + sp.Rational(1, 10 ** 12))})["s0"])) \
        == "refuted"
    arm = -sp.cos(PSI_C) * measured("B - G, x") + sp.sin(PSI_C) * measured("B - G, z")
    tilt = FloatingRootWitness(
        "tilt", "tan^2 of the cylinder's tilted equilibrium", ("t2",), (Case({}, label="example 10"),),
        body=Body.cylinder(sp.Rational(8, 5), sp.Rational(5, 2)), up=(sp.sin(PSI_C), 0, sp.cos(PSI_C)),
        density=sp.Rational(3, 5), quantity=sp.tan(PSI_C) ** 2,
        roots=((PSI_C, Root.scan(arm, PSI_C, sp.Rational(1, 50), sp.Rational(3, 2), 30)),))
    assert record_decision(_certified(tilt.run({"t2": chain(sp.Rational(11, 32))})["t2"])) == "agrees"
    assert record_decision(_certified(tilt.run({"t2": chain(sp.Rational(11, 32) - sp.Rational(1, 10 ** 12))})
                                      ["t2"])) == "refuted"
    # at the contact the water plane passes through the upper rim: the branches of a cut base are joined
    contact = replace(tilt, name="contact", targets=("tc",), quantity=sp.tan(PSI_C),
                      roots=((PSI_C, Root.scan(measured("upper base above water"), PSI_C, sp.Rational(1, 50),
                                               sp.Rational(3, 2), 30)),))
    assert record_decision(_certified(contact.run({"tc": chain(sp.Rational(5, 8))})["tc"])) == "agrees"
    assert record_decision(_certified(contact.run({"tc": chain(sp.Rational(5, 8) + sp.Rational(1, 10 ** 12))})
                                      ["tc"])) == "refuted"


def test_vertices_of_one_height_reach_the_water_together():
    # the unit cube heeled by phi = 1/3 about its z-axis (up (sin phi, cos phi, 0), no rational direction) at the
    # density 1 - tan(phi)/2 floats with the edge x = -1/2, y = 1/2 in the water plane: its two ends have one height
    # for every up vector of the balls (the z-component an exact 0), so they lie on one side together; split, the
    # crossing on that edge divided by a ball holding 0 and nothing was enclosed.  The waterplane: 1/cos(phi) by 1.
    Body, _, _, _, FloatingWitness, _, _ = _floating()
    phi = sp.Rational(1, 3)
    edge = FloatingWitness("edge", "the heeled cube with an edge at the water", ("a",), (Case({}, label="unit cube"),),
                           body=Body.box(1, 1, 1), up=(sp.sin(phi), sp.cos(phi), 0), density=1 - sp.tan(phi) / 2,
                           quantity=measured("waterplane area"))
    out = edge.run({"a": chain(1 / sp.cos(phi))})["a"]
    assert record_decision(_certified(out)) == "agrees" and out.agrees and not out.undecided
    assert record_decision(_certified(edge.run({"a": chain(1 / sp.cos(phi) + sp.Rational(1, 10 ** 12))})["a"])) \
        == "refuted"


# Irrational vertices, by hand.  The regular hexagonal prism of side 1 and length 3 (axis z, a corner on the x-axis,
# so its flat sides lie at y = +-sqrt(3)/2) floating at s = 1/2 with y up: the water plane y = 0 passes through the
# corners (+-1, 0), the waterplane is 2 by 3 (I min = 3 * 2^3/12 = 2), the volume below half the prism's,
# 3 * (3 sqrt(3)/2)/2 = 9 sqrt(3)/4, and B the centroid of the half hexagon, a trapezoid of parallel sides 2 (at
# the water) and 1 (at depth h = sqrt(3)/2), h (2 + 2 * 1)/(3 (2 + 1)) = 2 sqrt(3)/9 below the water, G at it: so
# the metacentric height is 2/(9 sqrt(3)/4) - 2 sqrt(3)/9 = 2 sqrt(3)/27.  The box sqrt(2) x 1 x 1 with y up at
# s = 3/10: the waterplane sqrt(2) x 1, I min = sqrt(2)/12, V = 3 sqrt(2)/10, B G = (1 - s)/2, so the metacentric
# height is 1/(12 s) - (1 - s)/2 = -13/180.
@pytest.mark.parametrize("body, s, exact", [(("regular", 6, 1, 3), sp.Rational(1, 2), 2 * sp.sqrt(3) / 27),
                                            (("box", sp.sqrt(2), 1, 1), sp.Rational(3, 10), -sp.Rational(13, 180))])
def test_irrational_vertices_are_enclosed_and_a_value_off_by_1e_12_refuted(body, s, exact):
    Body, _, _, _, FloatingWitness, _, _ = _floating()
    kind, *dims = body
    gm = FloatingWitness("gm", "the metacentric height", ("gm",), (Case({}, label="the prism"),),
                         body=getattr(Body, kind)(*dims), up=(0, 1, 0), density=s,
                         quantity=measured("metacentric height"))
    out = gm.run({"gm": chain(exact)})["gm"]
    assert record_decision(_certified(out)) == "agrees" and out.agrees and not out.undecided
    assert record_decision(_certified(gm.run({"gm": chain(exact + sp.Rational(1, 10 ** 12))})["gm"])) == "refuted"


def test_a_dimension_that_a_root_sets_is_enclosed_at_the_root_s_ball():
    # the box Q x 1 x 1 upright (z up) at s = 1/10, Q < 1: the waterplane Q x 1 (I min = Q^3/12), V = Q s,
    # B G = (1 - s)/2, so the metacentric height Q^2/(12 s) - (1 - s)/2 vanishes at Q^2 = 6 s (1 - s) = 27/50; the
    # waterplane's area there is Q = sqrt(27/50)
    Body, _, _, FloatingRootWitness, _, _, Root = _floating()
    Q = sp.Symbol("Q", positive=True)
    edge = FloatingRootWitness(
        "edge", "the waterplane where the box's metacentric height vanishes", ("A",), (Case({}, label="box"),),
        body=Body.box(Q, 1, 1), up=(0, 0, 1), density=sp.Rational(1, 10), quantity=measured("waterplane area"),
        roots=((Q, Root.scan(measured("metacentric height"), Q, sp.Rational(1, 2), sp.Rational(19, 20), 9)),))
    exact_area = sp.sqrt(sp.Rational(27, 50))
    assert record_decision(_certified(edge.run({"A": chain(exact_area)})["A"])) == "agrees"
    assert record_decision(_certified(edge.run({"A": chain(exact_area + sp.Rational(1, 10 ** 12))})["A"])) == "refuted"


Q_EDGE, S0 = sp.symbols("Q s0", positive=True)


def _nested_edge():
    """The box 1 x Q x 1 upright (z up, Q < 1) at density rho: the metacentric height Q^2/(12 rho) - (1 - rho)/2
    has its lower zero s0 where s0 (1 - s0) = Q^2/6 (the inner search, at every trial Q); s0 = 1/5 where
    Q^2/6 = 4/25, Q = 2 sqrt(6)/5 (the outer search; the case's rho, which the inner search sets, is nominal)."""
    Body, _, _, FloatingRootWitness, _, _, Root = _floating()
    rho = sp.Symbol("rho", positive=True)
    lower_zero = Root.scan(measured("metacentric height"), rho, sp.Rational(1, 20), sp.Rational(1, 2), 9)
    return FloatingRootWitness(
        "edge", "the edge at which the box's lower zero is 1/5", ("Q",), (Case({rho: sp.Rational(1, 2)}, label="box"),),
        body=Body.box(1, Q_EDGE, 1), up=(0, 0, 1), density=rho, quantity=Q_EDGE,
        roots=((Q_EDGE, Root.scan(S0 - sp.Rational(1, 5), Q_EDGE, sp.Rational(4, 5), sp.Rational(99, 100), 5,
                                  roots=((S0, lower_zero),))),))


def test_a_nested_root_search_is_enclosed_trial_by_trial():
    edge = _nested_edge()
    exact_edge = 2 * sp.sqrt(6) / 5
    assert record_decision(_certified(edge.run({"Q": chain(exact_edge)})["Q"])) == "agrees"
    assert record_decision(_certified(edge.run({"Q": chain(exact_edge + sp.Rational(1, 10 ** 12))})["Q"])) == "refuted"


def test_a_nested_search_seeks_each_trial_s_roots_from_the_last_ones(monkeypatch):
    # the edge of the test above: the float64 search is asked for the inner zero at the first trial edge alone;
    # at every later trial the zero is sought from the one before (the trial edges lie within 2^-20 of the
    # float64 root), and the enclosure is the same edge's
    FloatingRootWitness = _floating()[3]
    edge = _nested_edge()
    case = edge.cases[0]
    searched, depth = [], [0]
    solve = FloatingRootWitness._solve

    def counted(self, params, body, roots, dps, reads=()):
        if not depth[0]:            # a search the ball method asks for, not one inside the float64 search
            searched.append(tuple(symbol for symbol, _ in roots))
        depth[0] += 1
        try:
            return solve(self, params, body, roots, dps, reads)
        finally:
            depth[0] -= 1
    monkeypatch.setattr(FloatingRootWitness, "_solve", counted)
    with working_precision(160):
        value = edge.enclose(case, 128)
        assert value.contains(2 * arb(6).sqrt() / 5) and value.rad() < arb(2) ** -100
    assert searched == [(Q_EDGE,), (S0,)], searched


def test_a_root_known_to_a_ball_is_bracketed_as_wide_as_the_ball_asks_at_once():
    # f(x) = x^2 - 2 known only to +-2^-100 (a nested root's ball widens every value): the bracket about the
    # secant's last point is first tried as wide as twice that radius over the slope (about 2^-101) calls for, and
    # holds sqrt 2; a bracket 2^(4 - 128) wide, widened by 2^8 at a time, would take four tries (eight values)
    from symfloat.engine.floating_enclosure import _secant_root
    counted = []

    def f(x):
        counted.append(x)
        return x * x - 2 + arb(0, arb(2) ** -100)
    found = _secant_root(f, 1.4, 1.5, 128, start=2 ** 0.5)
    with working_precision(160):
        assert found.contains(arb(2).sqrt()) and found.rad() < arb(2) ** -96
    assert len(counted) <= 2 + 3 + 2, counted    # the start and a point 2^-40 from it, three secant steps, two ends


def test_the_waterplanes_corners_are_counted_in_balls_where_no_vertex_may_lie_on_the_plane():
    # the unit cube, corner up (1, 1, 1): the plane of s = 1/2 through the centre cuts six edges (the regular
    # hexagon), that of s = 1/48 three (a triangle round the lowest corner: volume h^3 sqrt 3 / 2 below it);
    # at s = 1/6 the plane passes through three vertices exactly: no count, undecided
    Body, _, _, _, FloatingWitness, _, _ = _floating()
    corners = FloatingWitness("corners", "corners of the waterplane, corner up", ("n",),
                              (Case({}, label="s = 1/2"), Case({}, label="s = 1/48")), body=Body.box(1, 1, 1),
                              up=(1, 1, 1), density=sp.Symbol("s"), quantity=measured("waterplane corners"))
    at = [Case({sp.Symbol("s"): sp.Rational(1, 2)}, label="s = 1/2"),
          Case({sp.Symbol("s"): sp.Rational(1, 48)}, label="s = 1/48")]
    assert [corners.enclose(case, 128) for case in at] == [6, 3]
    with pytest.raises(Unsupported, match="may pass through a vertex"):
        corners.enclose(Case({sp.Symbol("s"): sp.Rational(1, 6)}, label="s = 1/6"), 128)


def test_a_floating_kind_without_a_rigorous_method_keeps_its_former_comparison():
    Body, _, _, _, FloatingWitness, _, _ = _floating()
    psi = sp.Symbol("psi", real=True)
    from symfloat.engine.floating_witness import LIMIT_METHODS, potential_slope
    heel = (0, sp.sin(psi), sp.cos(psi))
    limit = FloatingWitness("arm", "the arm over the heel, extrapolated", ("m",), (Case({}, label="unit cube"),),
                            body=Body.box(2, 1, 1), up=heel, density=sp.Rational(1, 2),
                            quantity=potential_slope(heel, psi), limit=(psi, 1), methods=LIMIT_METHODS)
    assert limit.enclose(limit.instances[0], 128) is None
    out = limit.run({"m": chain(-sp.Rational(1, 12))})["m"]
    assert out.agrees and not any(r.get("certified") for r in out.records)


def test_an_up_vector_of_a_rational_direction_is_made_rational_and_a_trial_value_s_is_left():
    # (sin 45°, cos 45°, 0) is (1, 1, 0) scaled, so vertex heights are exact; at an exact trial angle of a nested
    # search (a dyadic with a long denominator) no ratio is rational and SymPy's simplification is not asked
    from symfloat.engine.floating_enclosure import _rational_direction
    phi = sp.Symbol("phi")
    up = (sp.sin(phi), sp.cos(phi), 0)
    assert _rational_direction(up, {phi: sp.pi / 4}, {}) == (1, 1, 0)
    assert _rational_direction(up, {phi: sp.pi / 6}, {}) == up        # tan 30° = 1/sqrt 3: irrational
    trial = sp.Rational(3602879701896397, 2 ** 55)                    # 0.1 as a double, exactly
    assert _rational_direction(up, {phi: trial}, {}) == up


def test_a_derivation_s_enclosures_do_not_depend_on_what_the_process_computed_before():
    # FLINT keeps pi and its Gauss-Legendre nodes at the highest precision asked so far and rounds later requests
    # from them; a check empties those caches first, so Graefe §2's certified records come out the same after a
    # computation at 4096 bits as before it (a test worker runs other tests first)
    from flint import acb, arb, ctx
    from symfloat.engine.check import check_derivation
    from symfloat.registry import load

    def certified_records():
        d, _ = load("graefe-s2-volumes-simpson")
        report = check_derivation(d)
        return [(f["id"], r) for f in report.to_json()["formulas"] for r in f.get("numeric", ())
                if r.get("certified")]
    before = certified_records()
    with ctx.workprec(4096):
        acb.integral(lambda x, _: (1 - x * x).sqrt(), 0, 1)
        arb.pi()
    after = certified_records()
    assert before and [(n, {k: v for k, v in r.items() if k != "seconds"}) for n, r in before] == \
        [(n, {k: v for k, v in r.items() if k != "seconds"}) for n, r in after]


def test_a_root_is_narrowed_from_the_float64_root_and_proven_by_a_sign_change():
    # f(x) = x^2 - 2 on [1.4, 1.5]: from the float64 root the secant needs no values at the bracket's ends, and
    # the ball it returns is proven (a sign change at its own ends) to hold sqrt(2), as the one from the ends does
    from symfloat.engine.floating_enclosure import _secant_root
    counted = []

    def f(x):
        counted.append(x)
        return x * x - 2
    from_ends = _secant_root(f, 1.4, 1.5, 128)
    ends = len(counted)
    from_root = _secant_root(f, 1.4, 1.5, 128, start=2 ** 0.5)
    with working_precision(160):
        root = arb(2).sqrt()
        for found in (from_ends, from_root):
            assert found.contains(root) and found.rad() < arb(2) ** -110
    assert len(counted) - ends < ends
    # a start the secant leaves (a point where f is far from 0) still ends in a proven bracket about the root
    far = _secant_root(f, 1.4, 1.5, 128, start=1.4000001)
    with working_precision(160):
        assert far.contains(arb(2).sqrt()) and far.rad() < arb(2) ** -110
