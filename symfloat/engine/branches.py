"""The proof strategy ``branches``: an identity between piecewise members, case by case, without ``simplify``.

The difference of the members, its piecewise parts folded into one ``Piecewise`` (SymPy's ``piecewise_fold``: the
cases of both members combined, a case inside a case joined to it), is brought over one denominator in each case
and cancelled.  Every case 0 proves the identity: on each part of the domain its difference is the zero rational
function of its symbols and functions.  A difference that folds into no ``Piecewise`` is left as it is (0 only if
it already was).  The notebooks run this very function (:func:`symfloat.report.notebook_code.strategy_helper`
copies its source into their first cell), so it uses SymPy's names only.

>>> from sympy import Rational, symbols
>>> s = symbols("s", positive=True)
>>> half = Rational(1, 2)
>>> branches(Piecewise((6 * s * (1 - s), s > half), (0, True)) - Piecewise((s * (6 - 6 * s), s > half), (0, True)))
0
>>> branches(Piecewise((1 / (1 - s), s > half), (0, True)) - Piecewise((1 / (s - 1), s > half), (0, True))) == 0
False
"""
from sympy import Piecewise, cancel, piecewise_fold, together

__all__ = ["branches"]


def branches(d):
    """*d* folded into one ``Piecewise`` and each case's expression over one denominator, cancelled (0 when every
    case is 0); *d* itself where it folds into no ``Piecewise``."""
    folded = piecewise_fold(d)
    if not isinstance(folded, Piecewise):
        return folded
    return Piecewise(*[(cancel(together(x)), c) for x, c in folded.args])
