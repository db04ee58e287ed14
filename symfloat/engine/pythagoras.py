"""The proof strategy ``pythagoras``: trigonometric identities without SymPy's general ``simplify``.

The difference of the members, its tangents and cotangents written as sines over cosines and its multiple angles
and angle sums expanded (``sin 2x = 2 sin x cos x``), is brought over one denominator; its numerator, a polynomial
in the sine ``s_k`` and cosine ``c_k`` of each angle, is divided by ``s_k^2 + c_k^2 - 1`` (these divisors are a
Groebner basis: their leading terms share no variable).  A remainder 0 proves the identity.  The notebooks run
this very function (:func:`symfloat.report.notebook_code.strategy_helper` copies its source into their first
cell), so it uses SymPy's names only.

>>> from sympy import symbols
>>> x = symbols("x")
>>> pythagoras(tan(x) * cos(x) ** 3 + sin(x) ** 3 - sin(x)), pythagoras(sin(2 * x) - sin(x) * cos(x)) == 0
(0, False)
"""
from sympy import Dummy, cos, cot, default_sort_key, expand, expand_trig, fraction, reduced, sin, tan, together

__all__ = ["pythagoras"]


def pythagoras(d):
    """*d* with tan and cot as quotients of sin and cos, multiple angles expanded, over one denominator: its
    numerator reduced by sin(x)**2 + cos(x)**2 - 1 for each angle x (0 when *d* is 0)."""
    d = d.replace(lambda f: isinstance(f, (tan, cot)),
                  lambda f: sin(f.args[0]) / cos(f.args[0]) if isinstance(f, tan) else cos(f.args[0]) / sin(f.args[0]))
    numerator = expand(fraction(together(expand_trig(d)))[0])
    angles = sorted({f.args[0] for f in numerator.atoms(sin, cos)}, key=default_sort_key)
    if numerator == 0 or not angles:
        return numerator
    s, c = [Dummy() for _ in angles], [Dummy() for _ in angles]
    p = numerator.xreplace({**{sin(x): u for x, u in zip(angles, s)}, **{cos(x): v for x, v in zip(angles, c)}})
    return expand(reduced(p, [u ** 2 + v ** 2 - 1 for u, v in zip(s, c)], *s, *c, order="lex")[1])
