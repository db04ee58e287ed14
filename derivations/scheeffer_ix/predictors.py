"""Scheeffer IX's printed tables as a predictor: any box turned about any edge, decided with the readings.

The readings are compiled (:mod:`symfloat.model.compiled`): the solved tilt of (134), the case s > 1/2 of (165),
the rows of (162) and the terms of the quartic (136) are built from the statements once, and a scene evaluates
them without SymPy."""
import math
from fractions import Fraction

from symfloat.model.compiled import Readings, Terms, compile_expr, derived, exact_sqrt, real_roots, reading
from symfloat.model.prediction import Prediction


# ==== the compile step: what the tables read, built from the statements =============================================
def _above_half(st, name, symbols, member, derivation=None):
    """The case s > 1/2 of a reading that writes the text's two cases (s < 1/2 is read with 1 - s for s, where
    the reading holds 0), continued to s = 1/2, where the tables' two cases meet: the expression and its
    symbols."""
    import sympy as sp
    syms = tuple(getattr(st, q) for q in symbols)
    expr = (derivation or st.DERIVATION).evaluator(name, syms, member)(*syms)
    return expr.replace(lambda e: isinstance(e, sp.Piecewise), lambda e: e.args[0].expr), syms


def _tan_134_of(st, derivation=None):
    """tg phi_2 at z = x/b, solved from (134), x^2 = 2 a b (1 - s) tg phi_2 as read (linear in tg phi_2)."""
    import sympy as sp
    tau = sp.Symbol("tau", positive=True)
    a, b, s, z = st.a, st.b, st.s, st.z
    (tan_z,) = sp.solve(sp.Eq((b * z) ** 2, (derivation or st.DERIVATION).evaluator("134", (a, b, s, st.phi), 1)(
        a, b, s, sp.atan(tau))), tau)
    return tan_z, (z, a, b, s)


def _terms_136(st, quartic_read):
    """The terms ((exponents of z, n, s), coefficient) of F(z) of (136) as read (*quartic_read*, its evaluator),
    with n = (a/b)^2 for a/b: evaluated in Fractions by :func:`_region2_roots`."""
    import sympy as sp

    from symfloat.engine.roots import polynomial_terms
    nu_ = sp.Symbol("n", positive=True)
    return Terms(polynomial_terms(sp.expand(quartic_read(st.z, sp.sqrt(nu_), 1, st.s)), st.z, (nu_, st.s))), ()


def _statements():
    from . import statements
    return statements


def _case_above_half(name, symbols, member, derivation):
    """:func:`_above_half` of another derivation (a mutated print), compiled."""
    st = _statements()
    return compile_expr(*_above_half(st, name, tuple(_names(st, symbols)), member, derivation))


def _tan_134(derivation):
    """:func:`_tan_134_of` of another derivation (a mutated print), compiled."""
    return compile_expr(*_tan_134_of(_statements(), derivation))


def _terms_of(quartic_read):
    """:func:`_terms_136` of another reading of (136) (a mutated print)."""
    return _terms_136(_statements(), quartic_read)[0]


def _names(st, symbols):
    """The attribute names of the statements' *symbols*."""
    return [next(k for k, v in vars(st).items() if v is q) for q in symbols]


READINGS = Readings(__file__, __package__, {
    # The readings the tables decide with (the quoted readings, derived quantities replaced, so a reading that
    # changes changes the prediction).  A printed condition L > R is read as the margin L - R; every one is
    # evaluated exactly (rationals, or Arb balls whose sign is certain).
    "UPRIGHT_132A": reading("132a", ("a", "b", "s"), 0),     # (a/b)^2 - 6 s(1-s): the upright position stable
    "OBLIQUE_132B": reading("132b", ("a", "b", "s"), 0),     # 6 s(1-s) - (a/b)^2, (a/b)^2 - rho: oblique, region 1
    "TAN2_125": reading("125", ("a", "b", "s"), 1),          # tg^2 phi_1
    "BELOW_140": reading("140", ("s",), 0),                  # 23/32 - s
    "ROOT_162A": reading("162a", ("a", "b", "s"), 0, row=0),  # rho - n: VI (one root, stable), else VII (none)
    "ENDS_162": reading("162", ("a", "b", "s"), 0),          # n - rho, n - 1/rho
    "T_147": reading("t-of-s", ("s",), 1),                   # t = (119 - 128 s)/27
    "N1_156": reading("156", ("t",), 1, row=0),              # n_1, the upper sign of (156)
    "UNSTABLE_3": reading("unstable-3", ("a", "b", "s"), 0),  # (a/b)^2 - 1/(6 s(1-s))
    "COT2_166": reading("166", ("a", "b", "s"), 1),          # cotg^2 phi_3
    "UPRIGHT_3": reading("upright-3", ("a", "b", "s"), 0),   # (b/a)^2 - 6 s(1-s): the other upright position stable
    "FACE_123": reading("123", ("a", "b", "s"), 0),          # (a/b)^2 - 6 s(1-s) for a face down, a horizontal
    "HG_163": reading("163", ("a", "b", "c", "s", "z"), 0),  # (c/b)^2 - HG^2/b^2
    "PERP_127": reading("127", ("a", "c"), 0, row=2),        # T_1^1 - T_1: the oblique position stable across the axis
    "BOUND_165": derived(lambda st: _above_half(st, "165", ("a", "b", "s"), 0)),   # 1/rho - (a/b)^2, region 3
    "TAN_134": derived(_tan_134_of),                         # tg phi_2 at z = x/b, from (134)
    "TABLE_162": derived(lambda st: ({row: st.d.evaluator(f"162-{row}", (), 1)() for row, *_ in st.ROWS_162}, ())),
    "TERMS_136": derived(lambda st: _terms_136(st, st.d.evaluator("136", (st.z, st.a, st.b, st.s), 1))),
})
UPRIGHT_132A, OBLIQUE_132B, TAN2_125, BELOW_140 = (READINGS[k] for k in ("UPRIGHT_132A", "OBLIQUE_132B", "TAN2_125",
                                                                        "BELOW_140"))
ROOT_162A, ENDS_162, T_147, N1_156 = (READINGS[k] for k in ("ROOT_162A", "ENDS_162", "T_147", "N1_156"))
UNSTABLE_3, COT2_166, UPRIGHT_3, FACE_123 = (READINGS[k] for k in ("UNSTABLE_3", "COT2_166", "UPRIGHT_3", "FACE_123"))
HG_163, PERP_127, BOUND_165, TAN_134 = (READINGS[k] for k in ("HG_163", "PERP_127", "BOUND_165", "TAN_134"))
TABLE_162 = {row: values() for row, values in READINGS["TABLE_162"].items()}
TERMS_136 = READINGS["TERMS_136"]


# ==== the predict step ==============================================================================================
def _exact(*values):
    """Floats, ints and Fractions as Fractions (a float by its binary value)."""
    return tuple(Fraction(v) for v in values)


def _n1_printed(sv):
    """n_1 by (156), upper sign, with t of (147) (the form of (156) has no removable singularity at t = 0): exact
    for an exact s, else a float."""
    return N1_156(T_147(sv))


def _case_162(row):
    """A row of (162) as read: (n < rho, n > 1/rho, n > n_1) from its signs, and its stabilities in the order of the
    tilt."""
    read = TABLE_162[row]
    return (bool(read[0] < 0), bool(read[1] > 0), bool(read[2] > 0)), ["stable" if v > 0 else "unstable" for v in read[4:]]


def _second_region(sv, nn):
    """Stabilities about the axis, in the order of growing tilt, and the printed names, from (162), (162a); s = sv,
    n = nn exact."""
    ratio = exact_sqrt(nn)
    if BELOW_140(sv) >= 0:
        return (["stable"], ("162a", "143")) if ROOT_162A(ratio, 1, sv) > 0 else ([], ("162a", "144"))
    to_rho, to_inverse = ENDS_162(ratio, 1, sv)
    case = (bool(to_rho < 0), bool(to_inverse > 0), bool(nn - _n1_printed(sv) > 0))
    return next((stab for key, stab in map(_case_162, TABLE_162) if key == case), []), ("162", "161", "156")


def _region2_roots(sv, nn, k):
    """The k roots of the printed F (136) that the table speaks of: those in [2 sigma, 1], completed by the
    positive roots nearest that interval if the count differs; s = sv, n = nn taken exactly.  The real roots with
    their multiplicity (at s = 23/32, n = 1 the triple root 3/4), isolated exactly by FLINT (square-free factors)
    and refined to 2^-120, as floats."""
    sv, nn = _exact(sv, nn)
    rts = [float(r_) for r_, multiplicity in real_roots(TERMS_136.at((nn, sv)), 120) if r_ > 0
           for _ in range(multiplicity)]
    sig = float(1 - sv)
    dist = lambda r_: max(2 * sig - r_, r_ - 1, 0)  # noqa: E731
    return sorted(sorted(sorted(rts), key=dist)[:k])


def tables_prediction(s, ratio):
    """What the printed tables of IX say for the section a x b (ratio = a/b; the larger edge is taken as a, the
    text's a > b) at density s: one dict per equilibrium with the region (1, 2, 3), the tilt phi from the
    position with b vertical (radians), the stability about the axis ('stable'/'unstable'), the printed names,
    and for the second region the root z of F.  s < 1/2 is read with 1 - s (the text's rule).  The conditions
    are the readings of the printed formulas with exact signs (floats taken by their binary value), the roots of F
    isolated exactly."""
    s, ratio = _exact(s, ratio)
    ratio = max(ratio, 1 / ratio)
    sv = max(s, 1 - s)
    fr, fs = float(ratio), float(sv)
    out = [dict(region=1, phi=0.0, stability="stable" if UPRIGHT_132A(ratio, 1, sv) > 0 else "unstable",
                printed=("132a", "table-first"))]
    upright, inside = OBLIQUE_132B(ratio, 1, sv)
    if upright > 0 and inside >= 0:
        out.append(dict(region=1, phi=math.atan(math.sqrt(TAN2_125(fr, 1.0, fs))), stability="stable",
                        printed=("125", "132b", "table-first")))
    if sv > Fraction(1, 2):
        stab, names = _second_region(sv, ratio * ratio)
        for zr, st in zip(_region2_roots(sv, ratio * ratio, len(stab)) if stab else (), stab):
            out.append(dict(region=2, phi=math.atan(TAN_134(zr, fr, 1.0, fs)), stability=st,
                            printed=names + ("136", "134"), z=zr))
    if UNSTABLE_3(ratio, 1, sv) > 0 and BOUND_165(ratio, 1, sv) >= 0:
        out.append(dict(region=3, phi=math.atan(1 / math.sqrt(COT2_166(fr, 1.0, fs))), stability="stable",
                        printed=("165", "166", "table-third")))
    out.append(dict(region=3, phi=math.pi / 2,
                    stability="stable" if UPRIGHT_3(ratio, 1, sv) > 0 else "unstable",
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
        add(up, "stable" if FACE_123(hor, exact[k], sv) > 0 else "unstable", ("123", "132a"),
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
                    hg = HG_163(A_, B_, L, max(sv, 1 - sv), Fraction(eq["z"]))
                    st = "stable" if hg > 0 else "unstable"
                    names = eq["printed"] + ("163",)
                else:
                    st, names = "unstable", eq["printed"]
            else:
                margin = PERP_127(A_ if eq["region"] == 1 else B_, L)
                st = None if margin == 0 else ("stable" if margin > 0 else "unstable")
                names = eq["printed"] + ("127",)
            add(up, st, names, f"axis along edge {ax}, region {eq['region']}")
    return preds


BODIES = ("box", "cube")
PROVIDES = {"tables": tables_prediction}                # the atlas compares its long boxes with the tables
