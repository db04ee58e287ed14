"""Scheeffer VI.C-F's closed forms pushed to their ends, for the float64 study (docs/numerics.md, §4)."""
import math

import mpmath
import numpy as np
import sympy as sp

from symfloat.numerics.forms import Form, ends, near, ngon_excess_series, reading, split

from .statements import d


def _stiff_forms():
    """Closed forms of this section pushed to their ends, for the float64 study (docs/numerics.md, §4): the
    n-gon's moment (89a) up to 10^6 sides, the cube's criterion (78) near its roots, the upright GM of VI.C at
    extreme aspect ratios and densities, the turned-axis moment (83) near 0 and 90 deg."""
    s_, a_, b_, n_ = sp.symbols("s a b n", positive=True)
    F1n, alph = sp.Symbol("F_1n"), sp.Symbol("alpha")
    out = []

    # (89a): T_1 / F^2 over n = 3 .. 10^6, alpha = 2 pi / n
    t89 = reading(d, "89a").subs(F1n, 1).subs(alph, 2 * sp.pi / n_)
    ns = tuple((float(v),) for v in np.unique(np.round(np.logspace(np.log10(3), 6, 40))))
    out.append(Form("n-gon moment at equal area, (89a)", f"{d.id}/89a", t89, (n_,), ((r"$n = 3 \ldots 10^6$", ns),)))

    # the decrease of T_1 towards the circle: T_1 / (F^2/(4 pi)) - 1
    coeffs = ngon_excess_series()

    def excess_stable(nv):
        al = 2 * math.pi / nv
        if al > 1:
            return al * (2 + math.cos(al)) / (3 * math.sin(al)) - 1
        x2 = al * al
        return sum(c * x2 ** (k + 2) for k, c in enumerate(coeffs))
    out.append(Form("excess of the n-gon's moment over the circle's, (89a) over (89c) less one", f"{d.id}/89a",
                    sp.simplify(t89 * 4 * sp.pi) - 1, (n_,), ((r"$n = 3 \ldots 10^6$", ns),), excess_stable,
                    r"$\alpha^4/180 + \ldots$ (Taylor series to $\alpha^{28}$) for $\alpha = 2 \pi/n \le 1$"))

    # (78): 1 - 6 s (1 - s) near its roots 1/2 -+ sqrt(1/12) (0.2113, 0.7887; hasab: the same thresholds)
    with mpmath.workdps(40):
        lo_hi, lo_lo = split(mpmath.mpf(1) / 2 - mpmath.sqrt(mpmath.mpf(1) / 12))
        up_hi, up_lo = split(mpmath.mpf(1) / 2 + mpmath.sqrt(mpmath.mpf(1) / 12))
    deltas = ends()
    out.append(Form(r"cube upright criterion $1 - 6s(1 - s)$, (78)", f"{d.id}/cube-78", reading(d, "cube-78", 0), (s_,),
                    ((r"$s$ within $10^{-15} \ldots 10^{-1}$ of $0.2113$", near(lo_hi, deltas)),
                     (r"$s$ within $10^{-15} \ldots 10^{-1}$ of $0.7887$", near(up_hi, deltas)),
                     (r"$s \to 0^+$ and $s \to 1^-$", tuple((v,) for v in deltas) + tuple((1 - v,) for v in deltas))),
                    lambda sv: 6 * ((sv - lo_hi) - lo_lo) * ((sv - up_hi) - up_lo),
                    r"$6 (s - s_-)(s - s_+)$, each root a sum of two doubles"))

    # VI.C upright metacentric height a^2/(12 b s) - b(1 - s)/2: s -> 0+, 1-, aspect ratios 1e-6 .. 1e6
    grid = tuple((float(av), 1.0, float(sv)) for av in np.logspace(-6, 6, 13)
                 for sv in (1e-15, 1e-10, 1e-5, 0.5, 1 - 1e-5, 1 - 1e-10, 1 - 1e-15))
    out.append(Form(r"square prism upright: metacentric height $a^2/(12bs) - b(1 - s)/2$",
                    f"{d.id}/upright-condition", reading(d, "upright-condition", 0), (a_, b_, s_),
                    ((r"$a/b = 10^{-6} \ldots 10^6$ ($b = 1$), $s \to 0^+$ and $s \to 1^-$", grid),)))

    # (83): T = (Tx + Ty)/2 + (Tx - Ty)/2 cos 2 psi near 0 and 90 deg, Tx = 1, Ty = k^2 (aspect k)
    Txs, Tys = sp.Symbol("T_x"), sp.Symbol("T_y")
    psis = sp.Symbol("psi", positive=True)
    t83 = reading(d, "83")
    t83 = t83.xreplace({sym: {"T_x": Txs, "T_y": Tys, "psi": psis}.get(sym.name, sym) for sym in t83.free_symbols})
    angles = tuple(math.pi / 2 - dl for dl in ends(-15, -1, 1)) + tuple(ends(-15, -1, 1))
    grid83 = tuple((1.0, float(kv) ** 2, ang) for kv in np.logspace(-6, 0, 7) for ang in angles)
    out.append(Form(r"moment about a turned axis, (83), $T_x = 1$, $T_y = k^2$", f"{d.id}/83",
                    t83, (Txs, Tys, psis),
                    ((r"$k = 10^{-6} \ldots 1$, $\psi$ within $10^{-15} \ldots 0.1$ of $0$ and $90^\circ$", grid83),),
                    lambda tx, ty, ps: ty * math.sin(ps) ** 2 + tx * math.cos(ps) ** 2,
                    r"$T_y \sin^2 \psi + T_x \cos^2 \psi$ (the text's own equivalent, VI.E)"))
    return out


d.provides("forms", _stiff_forms)
