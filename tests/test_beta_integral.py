"""The Beta rule for integrals over a quarter or a half of a circle or an ellipse (symfloat.engine.beta_integral)
against quadrature, and the integrals it leaves to SymPy."""
import mpmath
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from symfloat.engine.beta_integral import beta_closed
from symfloat.engine.check import carried_out

y, b, a, p, q = sp.symbols("y b a p q", positive=True)


def _quadrature(integral, point):
    f = sp.lambdify(y, integral.function.subs(point), "mpmath")
    start, end = (e.subs(point) for e in integral.limits[0][1:])
    with mpmath.workdps(40):
        return mpmath.quad(f, [mpmath.mpf(start.p) / start.q, 0, mpmath.mpf(end.p) / end.q], method="tanh-sinh")


# Euler's integrands (Scientia navalis §§220-228: the ellipse's quarter, its ordinate a + p y + q y^2 beside it)
EULER = [
    y ** 4 * (a + p * y + q * y ** 2) ** 2 / sp.sqrt(b ** 2 - y ** 2),
    -y ** 4 * (-b + y) * (b + y) / sp.sqrt(b ** 2 - y ** 2),
    y * (a * y / (b * sp.sqrt(b ** 2 - y ** 2)) + p + 2 * q * y) * (a + p * y + q * y ** 2),
    2 * a * sp.sqrt(1 - y ** 2 / b ** 2) * y ** 2,
    (b ** 2 - y ** 2) ** sp.Rational(3, 2) * y ** 3,
]


@pytest.mark.parametrize("integrand", EULER, ids=range(len(EULER)))
def test_the_rule_agrees_with_quadrature_and_with_sympy(integrand):
    integral = sp.Integral(integrand, (y, 0, b))
    closed = beta_closed(integral)
    assert closed is not None and not closed.has(sp.Integral, sp.gamma)
    point = {a: sp.Rational(3, 7), b: sp.Rational(5, 3), p: sp.Rational(-2, 9), q: sp.Rational(4, 11)}
    value = sp.N(closed.subs(point), 40)
    assert abs(value - _quadrature(integral, point)) < 1e-15 * max(1, abs(value))     # the end singular: 18 digits
    by_sympy = integral.doit()
    if by_sympy.has(sp.Integral):   # SymPy 1.14 leaves the ellipse's 2 a y^2 sqrt(1 - y^2/b^2) unevaluated:
        assert integrand == EULER[3] and closed == sp.pi * a * b ** 3 / 8     # int_0^b y^2 sqrt(b^2 - y^2) = pi b^4/16
    else:
        assert sp.expand(closed - by_sympy) == 0                          # SymPy's own result, exactly


@settings(max_examples=30, deadline=None)
@given(k=st.integers(0, 6), twice_a=st.sampled_from([-1, 1, 3, 5]))
def test_every_power_and_exponent_in_range(k, twice_a):
    integral = sp.Integral(y ** k * (b ** 2 - y ** 2) ** sp.Rational(twice_a, 2), (y, 0, b))
    point = {b: sp.Rational(7, 5)}
    assert abs(sp.N(beta_closed(integral).subs(point), 40) - _quadrature(integral, point)) < 1e-15


@settings(max_examples=30, deadline=None)
@given(k=st.integers(0, 6), twice_a=st.sampled_from([-1, 1, 3]), c=st.integers(1, 5))
def test_over_the_whole_chord_an_even_power_doubles_and_an_odd_one_vanishes(k, twice_a, c):
    # the half circle's (Scheeffer VI's cylinder: int_{-r}^{r} 2 Y^2 sqrt(r^2 - Y^2) dY); an odd power's 0 is
    # quadrature's too, to its rounding (both ends singular for a = -1/2: 15 digits of the larger value)
    integral = sp.Integral(c * y ** k * (b ** 2 - y ** 2) ** sp.Rational(twice_a, 2), (y, -b, b))
    point = {b: sp.Rational(7, 5)}
    closed = beta_closed(integral)
    assert (closed == 0) == (k % 2 == 1)
    value = sp.N(closed.subs(point), 40)
    assert abs(value - _quadrature(integral, point)) < 1e-15 * max(c, abs(value))


def test_a_changed_exponent_or_end_gives_another_value():
    # the mutants of the rule's inputs: the exponent of y one higher, the upper end not the radicand's root
    base = sp.Integral(y ** 2 / sp.sqrt(b ** 2 - y ** 2), (y, 0, b))
    assert beta_closed(base) == sp.pi * b ** 2 / 4
    assert beta_closed(sp.Integral(y ** 3 / sp.sqrt(b ** 2 - y ** 2), (y, 0, b))) == 2 * b ** 3 / 3
    assert beta_closed(sp.Integral(y ** 2 / sp.sqrt(b ** 2 - y ** 2), (y, 0, b / 2))) is None


@pytest.mark.parametrize("integral", [
    sp.Integral(sp.sqrt(y), (y, 0, b)),                                  # a root of y, not of b^2 - y^2
    sp.Integral(1 / (b ** 2 - y ** 2), (y, 0, b)),                        # diverges: a = -1
    sp.Integral(sp.sqrt(b ** 2 - y ** 2) / y, (y, 0, b)),                 # diverges: k = -1
    sp.Integral(sp.sqrt(b ** 2 + y ** 2), (y, 0, b)),                     # g < 0: no root at the end
    sp.Integral(sp.sqrt(b ** 2 - y ** 2), (y, -b, b / 2)),                # neither from 0 nor over the chord
    sp.Integral(sp.sqrt(b ** 2 - y ** 2) * sp.sqrt(a ** 2 - y ** 2), (y, 0, b)),   # two radicands
    sp.Integral(sp.sqrt(sp.Symbol("c") ** 2 - y ** 2), (y, 0, sp.Symbol("c"))),    # an end not known positive
    sp.Integral(y ** 2, (y, 0, b)),                                       # no root at all: SymPy's
    sp.Integral(sp.sin(y) * sp.sqrt(b ** 2 - y ** 2), (y, 0, b)),         # a factor not a power of y
    sp.Integral(sp.sqrt(b ** 2 - y ** 2) / (1 + y), (y, 0, b)),
    sp.Integral(y ** p * sp.sqrt(b ** 2 - y ** 2), (y, 0, b)),            # a power not a whole number
], ids=range(11))
def test_what_is_not_of_its_form_is_left_to_sympy(integral):
    assert beta_closed(integral) is None


def test_the_check_carries_integrals_out_by_the_rule():
    claim = sp.Integral(y ** 2 / sp.sqrt(b ** 2 - y ** 2), (y, 0, b)) + sp.Integral(y, (y, 0, a))
    assert carried_out(claim) == sp.pi * b ** 2 / 4 + a ** 2 / 2


def test_a_vector_is_carried_out_component_by_component():
    # a centroid's components met as a Matrix: each by the rule (SymPy's own integration took seconds)
    from symfloat.engine.check import _evaluated
    vector = sp.Matrix([sp.Integral(2 * y ** 2 * sp.sqrt(b ** 2 - y ** 2), (y, -b, b)), sp.Integral(y, (y, 0, a))])
    assert _evaluated(vector) == sp.Matrix([sp.pi * b ** 4 / 4, a ** 2 / 2])
