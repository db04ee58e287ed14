"""Sampling evaluates a member that is rational at the point with the compiled reading's exact arithmetic: the value
SymPy's substitution gives; anything else is left to SymPy."""
import sympy as sp
from hypothesis import given, settings, strategies as st

from symfloat.engine.identity import Domain, check_identity, value_at

a, b, c = sp.symbols("a b c", positive=True)
RATIONAL_FUNCTIONS = [(a + b) ** 3 / (a - 2 * c) - sp.Rational(7, 3) * a * b ** -2, (a * b - c) ** -1 + 1,
                      a ** 5 - 4 * a ** 3 * b ** 2 / c, sp.Rational(-1, 12) * (a - b) ** 2 * (a + b)]
rationals = st.fractions(min_value=-20, max_value=20, max_denominator=50).map(
    lambda f: sp.Rational(f.numerator, f.denominator))


@settings(max_examples=200, deadline=None)
@given(st.sampled_from(RATIONAL_FUNCTIONS), rationals, rationals, rationals)
def test_the_value_is_sympys_at_every_rational_point(expr, va, vb, vc):
    point = {a: va, b: vb, c: vc}
    value, sympys = value_at(expr, point), expr.xreplace(point)
    assert value == sympys
    assert value.is_Rational or sympys.has(sp.zoo, sp.nan)      # a zero denominator: SymPy says zoo or nan


def test_what_is_not_rational_at_the_point_is_sympys():
    half = sp.Rational(1, 2)
    for expr, point in ((sp.sqrt(a) + b, {a: sp.Integer(4), b: half}),           # rational after all: 5/2
                        (sp.sqrt(a) + b, {a: sp.Integer(2), b: half}),
                        (sp.sin(a) + a, {a: sp.Integer(1)}),
                        (a + b, {a: sp.sqrt(2), b: half}),                          # an irrational point
                        (a * sp.pi, {a: half}),
                        (sp.gamma(a), {a: half})):                                  # outside the compiled whitelist
        assert value_at(expr, point) == expr.xreplace(point)
    assert value_at(a + b, {a: half}) == half + b                                  # b has no value: kept


def test_sampling_through_it_is_exact_and_refutes_a_coefficient_changed_by_one():
    domain = Domain({a: (1, 5), b: (1, 5), c: (1, 3)})
    right = check_identity((a + b) ** 2 / c, (a ** 2 + 2 * a * b + b ** 2) / c, domain, "r1", prove=False)
    assert right.status == "sampled" and right.exact and right.samples > 0
    wrong = check_identity((a + b) ** 2 / c, (a ** 2 + 3 * a * b + b ** 2) / c, domain, "r1", prove=False)
    assert wrong.status == "refuted" and wrong.exact
    lhs, rhs = (sp.Rational(wrong.counterexample[k]) for k in ("lhs", "rhs"))     # exact rationals, shown so
    assert lhs != rhs
