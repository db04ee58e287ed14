"""The exact sampler's rational arithmetic gives what SymPy's substitution gives, or leaves the point to SymPy."""
import sympy as sp
from hypothesis import given, settings, strategies as st

from symfloat.engine.identity import Domain, check_identity
from symfloat.engine.rational import rational_value

a, b, c = sp.symbols("a b c", positive=True)
RATIONAL_FUNCTIONS = [(a + b) ** 3 / (a - 2 * c) - sp.Rational(7, 3) * a * b ** -2, (a * b - c) ** -1 + 1,
                      a ** 5 - 4 * a ** 3 * b ** 2 / c, sp.Rational(-1, 12) * (a - b) ** 2 * (a + b)]
rationals = st.fractions(min_value=-20, max_value=20, max_denominator=50).map(
    lambda f: sp.Rational(f.numerator, f.denominator))


@settings(max_examples=200, deadline=None)
@given(st.sampled_from(RATIONAL_FUNCTIONS), rationals, rationals, rationals)
def test_the_value_is_sympys_at_every_rational_point(expr, va, vb, vc):
    point = {a: va, b: vb, c: vc}
    value, sympys = rational_value(expr, point), expr.xreplace(point)
    if sympys.has(sp.zoo, sp.nan):
        assert value is None                    # a zero denominator is left to SymPy to say
    else:
        assert value == sympys and isinstance(value, sp.Rational)


def test_what_is_not_a_rational_function_at_a_rational_point_is_left_to_sympy():
    half = sp.Rational(1, 2)
    assert rational_value(sp.sqrt(a) + b, {a: sp.Integer(4), b: half}) is None
    assert rational_value(a ** half, {a: sp.Integer(4)}) is None
    assert rational_value(sp.sin(a), {a: sp.Integer(0)}) is None
    assert rational_value(a + b, {a: sp.sqrt(2), b: half}) is None          # an irrational point
    assert rational_value(a + b, {a: half}) is None                         # b has no value
    assert rational_value(a * sp.pi, {a: half}) is None


def test_sampling_through_it_is_exact_and_refutes_a_coefficient_changed_by_one():
    domain = Domain({a: (1, 5), b: (1, 5), c: (1, 3)})
    right = check_identity((a + b) ** 2 / c, (a ** 2 + 2 * a * b + b ** 2) / c, domain, "r1", prove=False)
    assert right.status == "sampled" and right.exact and right.samples > 0
    wrong = check_identity((a + b) ** 2 / c, (a ** 2 + 3 * a * b + b ** 2) / c, domain, "r1", prove=False)
    assert wrong.status == "refuted" and wrong.exact
    lhs, rhs = (sp.Rational(wrong.counterexample[k]) for k in ("lhs", "rhs"))     # exact rationals, shown so
    assert lhs != rhs
