"""Scheeffer VII and VIII read at a scene's numbers: boxes and cubes turned about an axis parallel to an edge.

The readings are compiled (:mod:`symfloat.model.compiled`): the strip conditions' polynomials are built from the
statements once, and a scene isolates their roots exactly (FLINT) without SymPy."""
import functools
import itertools
import math
from fractions import Fraction

import mpmath

from symfloat.model.compiled import Readings, Terms, derived, reading, real_roots
from symfloat.model.prediction import Prediction


# ==== the compile step: the strip conditions as polynomials ==========================================================
def _strip_equations(st):
    """The conditions of the two strip regions as read, (103b) in the width w of the dry strip and (122) in
    t = tan phi, each as the terms of its numerator and denominator polynomials in (unknown, A, C, H, s) (base
    A x C, height H):
      second region: F = C w, x_s = w/2, T = C w^3/3, x_0 = w - A/2;
      third region: w = V_3/(C H) + H/(2t) from (121b), w_2 = w - H/t, f = C w_2, x_s^1 = w_2/2, tau = C w_2^3/3."""
    import sympy as sp

    from symfloat.engine.roots import polynomial_terms
    d, F, F1, T, b, f, s, tau, x0, xs, xs1 = (st.d, st.F, st.F1, st.T, st.b, st.f, st.s, st.tau, st.x0, st.xs, st.xs1)
    w_, t_, A, C, H, S = sp.symbols("w t A C H s", positive=True)     # the predictors' unknowns and the box
    second = d.evaluator("103b", (T, F1, b, s, F, xs, x0), 1)(C * w_ ** 3 / 3, A * C, H, S, C * w_, w_ / 2, w_ - A / 2)
    w = d.evaluator("121b", (F1, b, s), 2)(A * C, H, S) / (C * H) + H / (2 * t_)
    w2 = w - H / t_
    third = d.evaluator("122", (T, tau, F1, b, s, x0, f, xs1, F, xs), 0, row=0)(
        C * w ** 3 / 3, C * w2 ** 3 / 3, A * C, H, S, w - A / 2, C * w2, w2 / 2, C * w, w / 2)
    return {name: {part: Terms(polynomial_terms(expr_, unknown, (A, C, H, S)))
                   for part, expr_ in zip(("numerator", "denominator"), sp.fraction(sp.together(expr)))}
            for name, unknown, expr in (("w", w_, second), ("t", t_, third))}, ()


# the readings the predictions decide with: the tilt (103a), the second condition (103b) and the stability (117)
# of the second region; the dry volume (121b) and the first condition (122) of the third
READINGS = Readings(__file__, __package__, {
    "TAN_103A": reading("103a", ("F1", "b", "s", "F", "xs"), 1),
    "EQ_103B": reading("103b", ("T", "F1", "b", "s", "F", "xs", "x0"), 1),
    "STABLE_117": reading("117", ("T", "Tp", "F", "xs", "ys", "F1", "b", "s"), 0),
    "DRY_121B": reading("121b", ("F1", "b", "s"), 2),
    "EQ_122": reading("122", ("T", "tau", "F1", "b", "s", "x0", "f", "xs1", "F", "xs"), 0, row=0),
    "STRIPS": derived(_strip_equations),
})
TAN_103A, EQ_103B, STABLE_117 = READINGS["TAN_103A"], READINGS["EQ_103B"], READINGS["STABLE_117"]
DRY_121B, EQ_122, STRIPS = READINGS["DRY_121B"], READINGS["EQ_122"], READINGS["STRIPS"]


# ==== the predict step ==============================================================================================
def _real_roots(unknown, box, valid):
    """The distinct real roots in *unknown* (``"w"`` or ``"t"``) of a strip condition for *box* = (A, C, H, s)
    (Fractions), where *valid* holds, at the working precision (40 digits): the numerator without the
    denominator's roots, isolated exactly by FLINT and refined to 2^-160.  Exact isolation keeps the roots of a
    pitchfork apart: next to 9/32 the edge-up root of (103b) is nearly triple, and a sign scan on a grid missed
    it at isolated densities."""
    numerator, denominator = (STRIPS[unknown][part].at(box) for part in ("numerator", "denominator"))
    numerator = numerator // numerator.gcd(denominator)
    roots = (mpmath.mpf(r_.numerator) / r_.denominator for r_, _ in real_roots(numerator, 160))
    return [v for v in roots if v > 0 and valid(v)]


@functools.lru_cache(maxsize=1024)
def _strip2(A, C, H, sv):
    """Second region, base A x C, height H, the dry part F of the upper base a strip of width w across the side C
    (F = C w, x_s = w/2, T = C w^3/3, T^1 = w C^3/12, y_s = 0, x_0 = w - A/2): the tilt of (103a), the widths where
    (103b) vanishes, the stability of (117) (k = 0 by symmetry).  Exact arguments (int or Fraction); the roots with
    tan phi in (0.01, 100), each as (tan phi, 'stable' or 'unstable') with (117) decided at 40 digits.  Kept per
    arguments: a cube asks the same of each of its six choices of axis and edge."""
    A, C, H, sv = map(Fraction, (A, C, H, sv))
    out = []
    with mpmath.workdps(40):
        a, c, h, s_ = (mpmath.mpf(q.numerator) / q.denominator for q in (A, C, H, sv))
        tilt = lambda w: TAN_103A(a * c, h, s_, c * w, w / 2)  # noqa: E731
        for w in _real_roots("w", (A, C, H, sv), lambda w: w < a and 0.01 < tilt(w) < 100 and w * tilt(w) < h):
            lhs = STABLE_117(c * w ** 3 / 3, w * c ** 3 / 12, c * w, w / 2, mpmath.mpf(0), a * c, h, s_)
            out.append((float(tilt(w)), "stable" if lhs > 0 else "unstable"))
    return tuple(sorted(out))


@functools.lru_cache(maxsize=1024)
def _strip3(A, C, H, sv):
    """Third region, dry strips of widths w and w_2 = w - H/t in the two bases, t = tan phi from (122) with w from
    the dry volume V_3 of (121b); exact and kept as in :func:`_strip2`.  Each root as (tan phi, None): the text
    gives no stability here."""
    A, C, H, sv = map(Fraction, (A, C, H, sv))
    with mpmath.workdps(40):
        a, c, h, s_ = (mpmath.mpf(q.numerator) / q.denominator for q in (A, C, H, sv))
        w = lambda t: DRY_121B(a * c, h, s_) / (c * h) + h / (2 * t)  # noqa: E731
        valid = lambda t: 0.01 < t < 100 and w(t) - h / t > 0 and w(t) < a  # noqa: E731
        return tuple((float(t), None) for t in _real_roots("t", (A, C, H, sv), valid))


def predict(scene):
    if scene.body not in ("box", "cube"):
        return []
    dims = tuple(scene.dims)
    s0 = scene.density
    sv, flip = (s0, 1) if s0 >= Fraction(1, 2) else (1 - s0, -1)     # s < 1/2: s for 1 - s, dry and wet exchanged
    preds, seen = [], []
    perms = [pm for pm in itertools.permutations(range(3)) if all(dims[pm[m]] == dims[m] for m in range(3))]
    for k in range(3):                                   # prism axis
        for i in range(3):                               # the base edge across GH (the dry side rises towards +i)
            if i == k:
                continue
            j = 3 - i - k
            for (t, stab), names in ([(r, ("95a", "103a", "103b", "117")) for r in _strip2(dims[i], dims[j], dims[k], sv)]
                                     + [(r, ("118", "121a", "121b", "122")) for r in _strip3(dims[i], dims[j], dims[k], sv)]):
                c_, s_ = 1 / math.sqrt(1 + t * t), t / math.sqrt(1 + t * t)
                up = [0.0, 0.0, 0.0]
                up[i], up[k] = flip * s_, flip * c_
                key = [abs(q) for q in up]
                if any(max(abs(key[pm[m]] - old[m]) for m in range(3)) < 1e-9 for old in seen for pm in perms):
                    continue
                seen.append(key)
                region = "second" if names[0] == "95a" else "third"
                preds.append(Prediction(printed=names, up=tuple(up), stability=stab,
                                        note=f"{region} region, prism axis {'xyz'[k]}, turned about an edge along "
                                             f"{'xyz'[j]}: tan phi = {t:.12g}"))
    return preds


BODIES = ("box", "cube")
