"""Scheeffer VI.A's printed thresholds pushed to their ends, for the float64 study (docs/numerics.md, §4)."""
import math

import mpmath
import numpy as np
import sympy as sp

from symfloat.numerics.forms import Form, ends, reading, split

from .statements import d


def _stiff_forms():
    """The printed thresholds (1 -+ sqrt(1 - (a/b)^2/3))/2 pushed to their ends, for the float64 study
    (docs/numerics.md, §4): aspect a/b -> 0 and the double root at a/b -> sqrt 3."""
    k = sp.Symbol("k", positive=True)
    a_, b_ = sp.symbols("a b", positive=True)
    lower = reading(d, "density-range", 0)[1].subs(a_, k * b_)
    ks = tuple((float(v),) for v in np.logspace(-6, np.log10(1.7), 40))
    out = [Form(r"triangular prism: lower threshold density $\bigl(1 - \sqrt{1 - (a/b)^2/3}\bigr)/2$",
                f"{d.id}/density-range",
                lower, (k,), ((r"$k = a/b = 10^{-6} \ldots 1.7$", ks),),
                lambda kv: (kv * kv / 12) / (0.5 + 0.5 * math.sqrt(1 - kv * kv / 3)),
                r"$(k^2/12) / s_+$, $s_+$ the upper threshold (from the product of the roots)")]
    with mpmath.workdps(40):
        r3_hi, r3_lo = split(mpmath.sqrt(3))
    near3 = tuple((r3_hi * (1 - dl),) for dl in ends())
    out.append(Form(r"triangular prism: discriminant $\sqrt{1 - (a/b)^2/3}$ near $a/b = \sqrt{3}$",
                    f"{d.id}/density-range", sp.sqrt(1 - k ** 2 / 3), (k,),
                    ((r"$a/b$ within $10^{-15} \ldots 10^{-1}$ below $\sqrt{3}$", near3),),
                    lambda kv: math.sqrt(((r3_hi - kv) + r3_lo) * (r3_hi + kv) / 3),
                    r"$\sqrt{(\sqrt{3} - k)(\sqrt{3} + k)/3}$, with $\sqrt{3}$ a sum of two doubles"))
    return out


d.provides("forms", _stiff_forms)
