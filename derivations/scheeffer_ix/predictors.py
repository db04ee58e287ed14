"""Scheeffer IX's printed tables as a predictor: any box turned about any edge, decided with the readings."""
import functools
import math
from fractions import Fraction

import mpmath
import sympy as sp

from symfloat.engine.roots import polynomial_at, polynomial_roots, polynomial_terms
from symfloat.model.prediction import Prediction

from .statements import ROWS_162, a, b, c, d, phi, s, t, z


# ==== the printed tables as a predictor ================================================================
# The readings the tables decide with (Derivation.evaluator: the quoted readings, derived quantities replaced,
# so a reading that changes changes the prediction).  A printed condition L > R is read as the margin L - R;
# every one is evaluated exactly, the float inputs taken by their binary value.
UPRIGHT_132A = d.evaluator("132a", (a, b, s), 0)        # (a/b)^2 - 6 s(1-s): the upright position stable
OBLIQUE_132B = d.evaluator("132b", (a, b, s), 0)        # 6 s(1-s) - (a/b)^2, (a/b)^2 - rho: oblique in region 1
TAN2_125 = d.evaluator("125", (a, b, s), 1)             # tg^2 phi_1
BELOW_140 = d.evaluator("140", (s,), 0)                 # 23/32 - s
ROOT_162A = d.evaluator("162a", (a, b, s), 0, row=0)    # rho - n: VI (one root, stable), else VII (none)
ENDS_162 = d.evaluator("162", (a, b, s), 0)             # n - rho, n - 1/rho
T_147 = d.evaluator("t-of-s", (s,), 1)                  # t = (119 - 128 s)/27
N1_156 = d.evaluator("156", (t,), 1, row=0)             # n_1, the upper sign of (156)
F_136 = d.evaluator("136", (z, a, b, s), 1)             # F(z) with n = (a/b)^2, sigma = 1 - s
UNSTABLE_3 = d.evaluator("unstable-3", (a, b, s), 0)    # (a/b)^2 - 1/(6 s(1-s))
COT2_166 = d.evaluator("166", (a, b, s), 1)             # cotg^2 phi_3
UPRIGHT_3 = d.evaluator("upright-3", (a, b, s), 0)      # (b/a)^2 - 6 s(1-s): the other upright position stable
FACE_123 = d.evaluator("123", (a, b, s), 0)             # (a/b)^2 - 6 s(1-s) for a face down, a horizontal
HG_163 = d.evaluator("163", (a, b, c, s, z), 0)         # (c/b)^2 - HG^2/b^2
PERP_127 = d.evaluator("127", (a, c), 0, row=2)         # T_1^1 - T_1: the oblique position stable across the axis


def _case_above_half(name, symbols, member, derivation=d):
    """The case s > 1/2 of a reading that writes the text's two cases (s < 1/2 is read with 1 - s for s, where
    the reading holds 0), continued to s = 1/2, where the tables' two cases meet: exact for exact (int, Fraction)
    arguments, symbolic for symbolic ones, a float when one is a float."""
    expr = derivation.evaluator(name, symbols, member)(*symbols)
    expr = expr.replace(lambda e: isinstance(e, sp.Piecewise), lambda e: e.args[0].expr)
    numeric = sp.lambdify(symbols, expr, "math")

    def value(*args):
        if any(isinstance(v, float) for v in args):
            return numeric(*args)
        return expr.xreplace({q: sp.Rational(v.numerator, v.denominator) if isinstance(v, Fraction) else sp.sympify(v)
                              for q, v in zip(symbols, args)})
    return value


BOUND_165 = _case_above_half("165", (a, b, s), 0)       # 1/rho - (a/b)^2: the oblique position in region 3


def _tan_134(derivation=d):
    """tg phi_2 at z = x/b, solved from (134), x^2 = 2 a b (1 - s) tg phi_2 as read (linear in tg phi_2)."""
    tau = sp.Symbol("tau", positive=True)
    (tan_z,) = sp.solve(sp.Eq((b * z) ** 2, derivation.evaluator("134", (a, b, s, phi), 1)(a, b, s, sp.atan(tau))), tau)
    return sp.lambdify((z, a, b, s), tan_z, "math")


TAN_134 = _tan_134()


def _exact(*values):
    """Floats, ints and Fractions as Fractions (a float by its binary value)."""
    return tuple(Fraction(v) for v in values)


NEAR = 1e-9     # a margin this close to zero in float64 is decided exactly (float64 rounds the margins met here,
                # terms up to a few hundred, by less than 1e-12)


def _decided(margin, *args):
    """The value(s) of *margin* (an evaluator, or a function of evaluators) at the exact *args*, with exact signs:
    the float64 values where every one lies beyond NEAR of zero, else the exact SymPy numbers."""
    v = margin(*(float(x) for x in args))
    if all(abs(x) > NEAR for x in (v if isinstance(v, tuple) else (v,))):
        return v
    return margin(*args)


def _n1_printed(sv):
    """n_1 by (156), upper sign, with t of (147) (the form of (156) has no removable singularity at t = 0): exact
    for an exact s, else a float."""
    return N1_156(T_147(sv))


def _case_162(row):
    """A row of (162) as read: (n < rho, n > 1/rho, n > n_1) from its signs, and its stabilities in the order of the
    tilt."""
    read = TABLE_162[row]
    return (bool(read[0] < 0), bool(read[1] > 0), bool(read[2] > 0)), ["stable" if v > 0 else "unstable" for v in read[4:]]


TABLE_162 = {row: d.evaluator(f"162-{row}", (), 1)() for row, *_ in ROWS_162}


def _second_region(sv, nn):
    """Stabilities about the axis, in the order of growing tilt, and the printed names, from (162), (162a); s = sv,
    n = nn exact."""
    ratio = sp.sqrt(sp.Rational(nn))
    if _decided(BELOW_140, sv) >= 0:
        return (["stable"], ("162a", "143")) if _decided(ROOT_162A, ratio, 1, sv) > 0 else ([], ("162a", "144"))
    to_rho, to_inverse = _decided(ENDS_162, ratio, 1, sv)
    case = (bool(to_rho < 0), bool(to_inverse > 0), bool(_decided(lambda s_, n_: n_ - _n1_printed(s_), sv, nn) > 0))
    return next((stab for key, stab in map(_case_162, TABLE_162) if key == case), []), ("162", "161", "156")


@functools.cache
def _terms_136(quartic_read):
    """The terms ((exponents of z, n, s), coefficient) of F(z) of (136) as read (*quartic_read*, its evaluator), with
    n = (a/b)^2 for a/b: built once, evaluated in Fractions by :func:`_region2_roots`."""
    nu_ = sp.Symbol("n", positive=True)
    return polynomial_terms(sp.expand(quartic_read(z, sp.sqrt(nu_), 1, s)), z, (nu_, s))


def _region2_roots(sv, nn, k):
    """The k roots of the printed F (136) that the table speaks of: those in [2 sigma, 1], completed by the
    positive roots nearest that interval if the count differs; s = sv, n = nn taken exactly.  The real roots with
    their multiplicity (at s = 23/32, n = 1 the triple root 3/4), isolated exactly by SymPy (square-free factors)
    and refined at 30 digits (to 1e-24), as floats."""
    sv, nn = _exact(sv, nn)
    poly = polynomial_at(_terms_136(F_136), z, (nn, sv))
    rts = []
    with mpmath.workdps(30):
        for factor, multiplicity in poly.sqf_list()[1]:
            rts += [float(r_) for r_ in polynomial_roots(factor, mpmath.mpf(10) ** -24) if r_ > 0
                    for _ in range(multiplicity)]
    sig = float(1 - sv)
    dist = lambda r_: max(2 * sig - r_, r_ - 1, 0)  # noqa: E731
    return sorted(sorted(sorted(rts), key=dist)[:k])


def tables_prediction(s, ratio):
    """What the printed tables of IX say for the section a x b (ratio = a/b; the larger edge is taken as a, the
    text's a > b) at density s: one dict per equilibrium with the region (1, 2, 3), the tilt phi from the
    position with b vertical (radians), the stability about the axis ('stable'/'unstable'), the printed names,
    and for the second region the root z of F.  s < 1/2 is read with 1 - s (the text's rule).  The conditions
    are the readings of the printed formulas with exact signs (floats taken by their binary value, :func:`_decided`),
    the roots of F isolated exactly."""
    s, ratio = _exact(s, ratio)
    ratio = max(ratio, 1 / ratio)
    sv = max(s, 1 - s)
    fr, fs = float(ratio), float(sv)
    out = [dict(region=1, phi=0.0, stability="stable" if _decided(UPRIGHT_132A, ratio, 1, sv) > 0 else "unstable",
                printed=("132a", "table-first"))]
    upright, inside = _decided(OBLIQUE_132B, ratio, 1, sv)
    if upright > 0 and inside >= 0:
        out.append(dict(region=1, phi=math.atan(math.sqrt(TAN2_125(fr, 1.0, fs))), stability="stable",
                        printed=("125", "132b", "table-first")))
    if sv > Fraction(1, 2):
        stab, names = _second_region(sv, ratio * ratio)
        for zr, st in zip(_region2_roots(sv, ratio * ratio, len(stab)) if stab else (), stab):
            out.append(dict(region=2, phi=math.atan(TAN_134(zr, fr, 1.0, fs)), stability=st,
                            printed=names + ("136", "134"), z=zr))
    if _decided(UNSTABLE_3, ratio, 1, sv) > 0 and _decided(BOUND_165, ratio, 1, sv) >= 0:
        out.append(dict(region=3, phi=math.atan(1 / math.sqrt(COT2_166(fr, 1.0, fs))), stability="stable",
                        printed=("165", "166", "table-third")))
    out.append(dict(region=3, phi=math.pi / 2,
                    stability="stable" if _decided(UPRIGHT_3, ratio, 1, sv) > 0 else "unstable",
                    printed=("upright-3", "table-third")))
    return out


def _key(dims, up):
    nrm = math.sqrt(sum(u_ * u_ for u_ in up))
    return tuple(sorted((round(dims[k], 12), round(abs(up[k]) / nrm, 7)) for k in range(3)))


def predict(scene):
    """Equilibria with the axis of rotation along an edge of the box (up perpendicular to it) as the printed
    tables give them: the three positions with a face down (123), and for each edge as axis the oblique
    positions of the three regions.  Stability in every direction: upright by (123) with the smaller horizontal
    edge; oblique in the first region by (126)/(127) (the edge along the axis longer than the horizontal edge
    across it), in the third likewise with b, in the second by the table and (163) (HG < edge along the axis, as
    printed: sufficient, not necessary, erratum HG-complete).  Exact dimensions and density."""
    exact = _exact(*scene.dims)
    dims = [float(v) for v in exact]
    sv = Fraction(scene.density)
    preds, seen = [], set()

    def add(up, stability, printed, note):
        k = _key(dims, up)
        if k not in seen:
            seen.add(k)
            preds.append(Prediction(printed=printed, up=tuple(up), stability=stability, note=note))

    for k in range(3):
        hor = min(exact[j] for j in range(3) if j != k)
        up = tuple(1.0 if j == k else 0.0 for j in range(3))
        add(up, "stable" if _decided(FACE_123, hor, exact[k], sv) > 0 else "unstable", ("123", "132a"),
            "face down, (123)")
    for ax in range(3):
        i, j = [k for k in range(3) if k != ax]
        if exact[i] < exact[j]:
            i, j = j, i                      # dims[i] is the text's a (larger), dims[j] its b
        L, A_, B_ = exact[ax], exact[i], exact[j]
        for eq in tables_prediction(sv, A_ / B_):
            if eq["region"] != 2 and eq["phi"] in (0.0, math.pi / 2):
                continue
            up = [0.0, 0.0, 0.0]
            up[j], up[i] = math.cos(eq["phi"]), math.sin(eq["phi"])
            if eq["region"] == 2:
                if eq["stability"] == "stable":
                    hg = _decided(HG_163, A_, B_, L, max(sv, 1 - sv), Fraction(eq["z"]))
                    st = "stable" if hg > 0 else "unstable"
                    names = eq["printed"] + ("163",)
                else:
                    st, names = "unstable", eq["printed"]
            else:
                margin = _decided(PERP_127, A_ if eq["region"] == 1 else B_, L)
                st = None if margin == 0 else ("stable" if margin > 0 else "unstable")
                names = eq["printed"] + ("127",)
            add(up, st, names, f"axis along edge {ax}, region {eq['region']}")
    return preds


d.predicts(("box", "cube"), predict)

d.provides("tables", tables_prediction)                 # the atlas compares its long boxes with the tables
