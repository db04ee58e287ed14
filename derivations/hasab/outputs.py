"""The Hasáb remark's thresholds in closed form, for the float64 study (docs/numerics.md, §4)."""
import math

import mpmath
import numpy as np
import sympy as sp

from symfloat.numerics.forms import Form, ends, split

from .statements import d, l, ru1


def _stiff_forms():
    """The remark's lower threshold (3l - sqrt(9l^2 - 6))/(6l), l up to 1e6, and the width of the unstable range
    sqrt(9l^2 - 6)/(3l) near the double root l = sqrt(2/3), for the float64 study (docs/numerics.md, §4)."""
    ls = tuple((float(v),) for v in np.logspace(np.log10(0.82), 6, 40))
    out = [Form(r"long square prism upright: lower threshold $(3l - \sqrt{9l^2 - 6})/(6l)$", f"{d.id}/upright-roots",
                ru1, (l,), ((r"$l = 0.82 \ldots 10^6$", ls),),
                lambda lv: 1 / (lv * (3 * lv + math.sqrt(9 * lv * lv - 6))),
                r"$1 / \bigl(l (3l + \sqrt{9l^2 - 6})\bigr)$ (from the product of the roots, $1/(6 l^2)$)")]
    with mpmath.workdps(40):
        r23_hi, r23_lo = split(mpmath.sqrt(mpmath.mpf(2) / 3))
    near23 = tuple((r23_hi * (1 + dl),) for dl in ends())
    out.append(Form(r"long square prism upright: width of the unstable range $\sqrt{9l^2 - 6}/(3l)$ near "
                    r"$l = \sqrt{2/3}$",
                    f"{d.id}/upright-roots", sp.sqrt(9 * l ** 2 - 6) / (3 * l), (l,),
                    ((r"$l$ within $10^{-15} \ldots 10^{-1}$ above $\sqrt{2/3}$", near23),),
                    lambda lv: math.sqrt(9 * ((lv - r23_hi) - r23_lo) * (lv + r23_hi)) / (3 * lv),
                    r"$\sqrt{9 (l - r)(l + r)}/(3l)$, with $r = \sqrt{2/3}$ a sum of two doubles"))
    return out


d.provides("forms", _stiff_forms)
