"""Integrals over a quarter or a half of a circle or an ellipse, closed by the Beta function.

A moment of a waterplane bounded by a circle or an ellipse (Euler's *Scientia navalis* §§192-228) integrates
powers of the ordinate against a square root of ``L^2 - y^2``.  SymPy's ``integrate`` finds these through its
general algorithms, a third of a second each; every term is an instance of

    ``int_0^L y^k (g (L^2 - y^2))^a dy = g^a L^(k + 2a + 1) B((k + 1)/2, a + 1) / 2``

(substitute ``y = L sqrt(t)``; ``L > 0``, ``g > 0``, ``k > -1``, ``a > -1``), whose Beta function SymPy
evaluates exactly at the half-integers that occur; over ``[-L, L]`` a term is twice that for an even power ``k``
and 0 for an odd one (a half circle's moments, Scheeffer VI's cylinder: SymPy takes seconds for each).  The closed
form is checked like SymPy's would be: the definition route measures the defining integral by quadrature, never by
this rule.
"""
from __future__ import annotations

import sympy as sp

__all__ = ["beta_closed"]


def _power_of_radicand(base, exponent, y, end):
    """``(g, a)`` when ``base**exponent`` is ``(g (end^2 - y^2))^a`` with ``g > 0`` and ``a`` a half or whole
    number, else ``None``."""
    if not (exponent.is_Rational and exponent.q in (1, 2)):
        return None
    try:
        p = sp.Poly(base, y)
    except sp.PolynomialError:
        return None
    if p.degree() != 2 or p.coeff_monomial(y) != 0:
        return None
    g = -p.coeff_monomial(y ** 2)
    if g.is_positive is not True or sp.expand(p.coeff_monomial(1) - g * end ** 2) != 0:
        return None
    return g, exponent


def _term(term, y, end, symmetric=False):
    """One term ``c y^k (g (end^2 - y^2))^a`` of an expanded integrand, integrated over ``[0, end]`` (*symmetric*:
    over ``[-end, end]``), or ``None``."""
    c, k, g, a = sp.Integer(1), sp.Integer(0), sp.Integer(1), sp.Integer(0)
    for factor in sp.Mul.make_args(term):
        if not factor.has(y):
            c *= factor
            continue
        base, exponent = factor.as_base_exp()
        if base == y and exponent.is_Integer:
            k += exponent
            continue
        radicand = _power_of_radicand(base, exponent, y, end)
        if radicand is None or a != 0:
            return None
        g, a = radicand
    if k <= -1 or a <= -1:
        return None
    if symmetric and k % 2:
        return sp.Integer(0)
    half = (k + 1) / sp.Integer(2)
    factor = 1 if symmetric else 2
    return c * g ** a * end ** (k + 2 * a + 1) * sp.gamma(half) * sp.gamma(a + 1) / (factor * sp.gamma(half + a + 1))


def beta_closed(integral: sp.Integral):
    """*integral* in closed form by the Beta rule of the module docstring, term by term of its expanded
    integrand, or ``None`` where a term is not of that form (SymPy then integrates it).

    >>> import sympy as sp
    >>> y, b = sp.symbols("y b", positive=True)
    >>> beta_closed(sp.Integral(y**2 / sp.sqrt(b**2 - y**2), (y, 0, b)))
    pi*b**2/4
    >>> beta_closed(sp.Integral(2 * y**2 * sp.sqrt(b**2 - y**2), (y, -b, b)))
    pi*b**4/4
    >>> beta_closed(sp.Integral(sp.sqrt(y), (y, 0, b))) is None
    True
    """
    if len(integral.limits) != 1 or len(integral.limits[0]) != 3:
        return None
    y, start, end = integral.limits[0]
    if start not in (0, -end) or end.is_positive is not True or end.has(y):
        return None
    f = integral.function
    if f.has(sp.Integral, sp.Derivative, sp.Subs, sp.Limit, sp.Piecewise) or not any(
            (p.exp.is_Rational and p.exp.q == 2) for p in f.atoms(sp.Pow) if p.base.has(y)):
        return None
    terms = [_term(t, y, end, start != 0) for t in sp.Add.make_args(sp.expand(f))]
    return None if any(t is None for t in terms) else sp.Add(*terms)
