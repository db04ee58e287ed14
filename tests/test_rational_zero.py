"""FLINT decides that an expression is 0 as a rational function of its generators; "no" leaves it to SymPy."""
import sympy as sp
from hypothesis import given, settings, strategies as st

from symfloat.engine.rational_zero import is_zero_rational_function

x, y, b, t = sp.symbols("x y b t")


def test_partial_fractions_are_zero_and_a_changed_coefficient_is_not():
    e = 1 / (x - y) - 1 / (x + y) - 2 * y / (x**2 - y**2)
    assert is_zero_rational_function(e)
    assert not is_zero_rational_function(e + sp.Rational(1, 10**30) / (x + y))


def test_a_root_squared_is_its_radicand():
    """The replays SymPy's ``cancel`` proved and the generators alone did not (Scheeffer IV–V's chords)."""
    assert is_zero_rational_function((y - b) * (b + y) / sp.sqrt(b**2 - y**2) + sp.sqrt(b**2 - y**2))
    assert is_zero_rational_function(sp.sqrt(3) * (1 + sp.sqrt(3)) - (3 + sp.sqrt(3)))
    assert not is_zero_rational_function(sp.sqrt(3) * (1 + sp.sqrt(3)) - (4 + sp.sqrt(3)))
    r = sp.sqrt(1 + sp.sqrt(2))     # a root of a sum holding a root: reduced outside in
    assert is_zero_rational_function(r * (r + sp.sqrt(2)) - (1 + sp.sqrt(2) + sp.sqrt(2) * r))


def test_roots_of_one_base_share_a_generator():
    assert is_zero_rational_function(sp.sqrt(x) / (x + sp.sqrt(x)) - 1 / (sp.sqrt(x) + 1))
    assert is_zero_rational_function(x ** sp.Rational(1, 2) * x ** sp.Rational(1, 3) * (1 + x ** sp.Rational(1, 6))
                                     - x ** sp.Rational(5, 6) - x)


def test_what_is_not_a_polynomial_identity_is_no():
    assert not is_zero_rational_function(sp.sin(t) ** 2 + sp.cos(t) ** 2 - 1)
    assert not is_zero_rational_function(sp.Float("0.5") * x * y - x / 2 * (y + 1) + x / 2)   # 0 but inexact
    assert not is_zero_rational_function(sp.zoo * x - 1)
    assert is_zero_rational_function(sp.sin(t) / (1 + sp.sin(t)) - 1 + 1 / (1 + sp.sin(t)))


_terms = st.lists(st.tuples(st.integers(-3, 3), st.integers(0, 2), st.integers(0, 2), st.integers(0, 1)),
                  min_size=1, max_size=4)


def _polynomial(terms):
    return sp.Add(*(c * x**i * y**j * sp.sqrt(x + 1) ** k for c, i, j, k in terms))


@settings(max_examples=60, deadline=None)
@given(_terms, _terms, _terms, st.integers(1, 5))
def test_agrees_with_sympy_on_random_rational_functions(p, q, s, c):
    """A sum of fractions against the same sum over a common denominator (zero), and shifted by c/q (not)."""
    P, Q, S = _polynomial(p), _polynomial(q), _polynomial(s)
    if Q == 0 or S == 0 or sp.cancel(sp.together(Q * S)) == 0:
        return
    combined = sp.together(P / Q + 1 / S)
    assert is_zero_rational_function(P / Q + 1 / S - combined)
    shifted = P / Q + 1 / S - combined + c / Q
    assert not is_zero_rational_function(shifted)
    assert sp.cancel(sp.together(shifted)) != 0


def test_a_power_above_the_bound_is_left_to_sympy():
    """FLINT's expansion cannot be stopped by a search's time limit, so a large power goes to SymPy."""
    def zero_with_power(k):
        return (x + y) ** k * (x + 1) - (x + y) ** k * x - (x + y) ** k      # 0, not folded by SymPy
    assert is_zero_rational_function(zero_with_power(64))
    assert not is_zero_rational_function(zero_with_power(65))
