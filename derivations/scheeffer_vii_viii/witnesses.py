"""Scheeffer VII and VIII's witnesses: clipped prisms (:mod:`symfloat.engine.floating_witness`)."""
import functools

import sympy as sp

from symfloat.engine.declare import declarer
from symfloat.engine.floating_witness import Body, FloatingRootWitness, FloatingWitness, Root, potential_slope
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case
from symfloat.geometry.floating import polygon_moments

from .statements import (A_, C_, F, F1, Ks, PO, Pf, Pw, R, T, T2, T21, T21g, T2g, Tp, b, d, f, kg, mu, res, s, tau,
                         th, x0, xs, xs1, ys)


# ==== witnesses ======================================================================================================
def _moments(poly):
    """Exact area moments of a counter-clockwise polygon: A, int x, int y, int x^2, int y^2, int x y (the library's
    polygon moments, moved from the centroid to the origin).  Radicals (the equilateral triangle) in closed form,
    the vertices' first, so that the moments' quotients stay small (the triangle's pieces 1.8 s before, 0.65 s)."""
    A, (cx, cy), J = polygon_moments([(sp.expand(sp.radsimp(sp.sympify(px))), sp.expand(sp.radsimp(sp.sympify(py))))
                                      for px, py in poly])
    return [v if v.is_Rational else sp.expand(sp.radsimp(sp.expand(v)))
            for v in (A, A * cx, A * cy, J[0][0] + A * cx ** 2, J[1][1] + A * cy ** 2, J[0][1] + A * cx * cy)]


def _half(poly, c, keep_above=True):
    """The part of a polygon (coordinates (X, Y)) with X >= c (or X <= c), exact."""
    out = []
    for i in range(len(poly)):
        P, Q = poly[i], poly[(i + 1) % len(poly)]
        fp, fq = (P[0] - c, Q[0] - c) if keep_above else (c - P[0], c - Q[0])
        if fp >= 0:
            out.append(P)
        if fp * fq < 0:
            lam = fp / (fp - fq)
            out.append((P[0] + lam * (Q[0] - P[0]), P[1] + lam * (Q[1] - P[1])))
    return out


def _centred(poly):
    A, Sx, Sy, *_ = _moments(poly)
    return [(px - Sx / A, py - Sy / A) for px, py in poly]


SQUARE = [(-R(1, 2), -R(1, 2)), (R(1, 2), -R(1, 2)), (R(1, 2), R(1, 2)), (-R(1, 2), R(1, 2))]
RECT = [(-1, -R(1, 2)), (1, -R(1, 2)), (1, R(1, 2)), (-1, R(1, 2))]
TRI = _centred([(0, 0), (3, 0), (1, 2)])
EQTRI = [(sp.sqrt(3) / 3 * sp.cos(2 * sp.pi * j / 3), sp.sqrt(3) / 3 * sp.sin(2 * sp.pi * j / 3)) for j in range(3)]
# the designed pentagon: the dry part beyond x = 0 (raw) has int x y df = 0 about the foot of O (see tests)
PENT = _centred([(-2, -1), (1, -R(3, 2)), (R(3, 2), R(1, 2)), (0, 2), (-R(3, 2) - R(67, 72), R(1, 2) - R(67, 48))])
PENT_X0 = -R(349, 2196)      # O from N along NE for the raw cut x = 0
N0, N1, N2 = (sp.Integer(1), sp.Integer(0)), (R(3, 5), R(4, 5)), (R(4, 5), -R(3, 5))


def _box_eq2(A, bb, t):
    """Box A x C x b, GH parallel to C: the width w of the dry strip where (103b) vanishes, and x_0 = w - A/2."""
    w = 3 * (bb * t - A) / (2 * (t ** 2 - 1))
    return w - sp.sympify(A) / 2


def _box_eq3(bb, t, w):
    """Box, third region: x_0 from (122) for the dry top strip of width w (linear in x_0)."""
    w2 = w - bb / t
    x0_ = sp.Symbol("x0_")
    eq = ((w ** 3 - w2 ** 3) / 3 * t * (1 + t ** 2 / 2) - (w ** 2 - w2 ** 2) / 2 * t * (x0_ + bb * t / 2)
          - bb * w2 ** 2 / 2 * (1 + t ** 2))
    return sp.solve(eq, x0_)[0]


def _box3(bb, t, w):
    """The base A x 1 of the third-region box equilibrium: A = 2 (w - x_0)."""
    A = 2 * (w - _box_eq3(bb, t, w))
    return [(-A / 2, -R(1, 2)), (A / 2, -R(1, 2)), (A / 2, R(1, 2)), (-A / 2, R(1, 2))]


CONFIGS = {
    # name: (polygon, direction n of NE, x_0, tan phi, b, region)
    "rect": (RECT, N1, R(1, 5), R(1, 2), R(3, 2), 2),
    "tri": (TRI, N2, R(1, 4), R(2, 3), 2, 2),
    "square": (SQUARE, N1, R(1, 10), R(3, 4), R(6, 5), 2),
    "eqtri": (EQTRI, N2, R(1, 10), R(1, 2), R(3, 2), 2),
    "pent-eq": (PENT, N0, PENT_X0, R(4, 3), R(475, 183), 2),
    "box-eq": (SQUARE, N0, _box_eq2(1, 1, R(4, 3)), R(4, 3), sp.Integer(1), 2),
    "rect-3": (RECT, N1, -R(1, 5), R(5, 2), R(1, 2), 3),
    "tri-3": (TRI, N2, -R(1, 10), sp.Integer(2), R(3, 5), 3),
    "box3-eq": (_box3(sp.Integer(1), R(5, 2), R(1, 2)), N0, _box_eq3(sp.Integer(1), R(5, 2), R(1, 2)), R(5, 2),
                sp.Integer(1), 3),
}


@functools.lru_cache(maxsize=None)
def _params(name):
    """Exact case data of a configuration: the area moments of the pieces of the base in the frame of N."""
    poly, (nx, ny), x0v, t, bb, region = CONFIGS[name]
    poly = [(sp.sympify(px), sp.sympify(py)) for px, py in poly]
    base = [(px * nx + py * ny + x0v, -px * ny + py * nx) for px, py in poly]      # (X, Y) from N
    A, _, _, _, _, _ = _moments(poly)
    PO_ = _moments([(X - x0v, Y) for X, Y in base])[5]
    Fm = _moments(_half(base, 0))
    Wm = _moments(_half(base, 0, keep_above=False))
    out = {F1: A, b: bb, F: Fm[0], xs: Fm[1] / Fm[0], ys: Fm[2] / Fm[0], T: Fm[3], Tp: Fm[4], PO: PO_, Pw: Wm[5],
           x0: x0v}
    V3v = t * Fm[1]
    if region == 3:
        dd = bb / t
        fm = _moments([(X - dd, Y) for X, Y in _half(base, dd)])
        out.update({f: fm[0], xs1: fm[1] / fm[0], tau: fm[3], Pf: fm[5]})
        V3v = t * (Fm[1] - fm[1])
    out[s] = 1 - V3v / (A * bb)
    return {k: sp.sympify(v) for k, v in out.items()}


def _generic(name):
    """The params with the waterplane's own central moments as T_2, T_2^1, k of the generic figure."""
    p = dict(_params(name))
    for sym, val in ((T2g, T2), (T21g, T21), (kg, Ks)):
        p[sym] = res(val).xreplace(p)
    return p


# the configurations measured: the prism over the case's base, tilted by tan phi = t_w towards NE = (n_x, n_y)
NX, NY, TT, AV, A1 = sp.symbols("n_x^w n_y^w t_phi^w alpha^w alpha_1^w", real=True)
CPH, SPH = 1 / sp.sqrt(1 + TT ** 2), TT / sp.sqrt(1 + TT ** 2)
NV, EV = sp.Matrix([NX, NY, 0]), sp.Matrix([-NY, NX, 0])         # NE, and the axis GH (body frame)
HV = sp.Matrix([CPH * NX, CPH * NY, -SPH])                       # the horizontal across GH, towards the dry side
UP = (TT * NX, TT * NY, sp.Integer(1))
V1M = measured("immersed volume")
BG = sp.Matrix([measured(f"B - G, {axis}") for axis in "xyz"])
V3M = F1 * b - V1M                                               # the dry volume
DRY = -V1M * BG                      # V_3 (S_3 - S): V S = V_1 S_2 + V_3 S_3 with S = G the origin
X0M = -(measured("water level") * sp.sqrt(1 + TT ** 2) - b / 2) / TT    # O from N along NE: the water line in the upper base
TW = sp.Matrix(3, 3, lambda i, j: measured(f"waterplane tensor, {'xyz'[min(i, j)]}{'xyz'[max(i, j)]}"))
CW = sp.Matrix([measured(f"waterplane centroid, {axis}") for axis in "xyz"]) - sp.Matrix([-X0M * NX, -X0M * NY, b / 2])
AW = measured("waterplane area")
turned = lambda a_: sp.cos(a_) * HV - sp.sin(a_) * EV  # noqa: E731  (the direction at a_ to the axis through S^1)
SLOPE_T = 2 * (-sp.sin(AV) * HV - sp.cos(AV) * EV).dot(TW * turned(AV))   # dT_alpha/dalpha


def quad(v, w_):
    return v.dot(TW * w_)


# quantity -> what it is on the clipped configuration
MEASURE = {
    "V3": V3M, "My": DRY.dot(EV), "Pxy": DRY.dot(EV) / TT, "x0": X0M,
    "balance": (V1M * BG.dot(HV), V1M * BG.dot(EV)),
    "M3": DRY.dot(HV), "M3sin": DRY.dot(HV) / SPH,
    "ZX": (V3M * b / 2 - DRY[2], DRY.dot(NV) + V3M * X0M),
    "V3zeta": DRY[2], "V1e2": V1M * measured("G above B"), "offsets": (DRY.dot(NV) / V3M, DRY[2] / V3M),
    "flip-product": V1M * BG.dot(EV) / TT, "flip": V1M * measured("G above B"),      # the turned body (see _w)
    # the water lines in the upper and the lower base lie b cot phi apart along NE
    "x0x01": (-(X0M - b / TT) + X0M) * TT,
    "122": (DRY.dot(HV) / SPH * TT, (-(X0M - b / TT) + X0M) * TT - b, V3M - F1 * b * (1 - s)),
    "Tmu": quad(turned(mu), turned(mu)), "T2": (quad(HV, HV), quad(EV, EV)), "Ks": quad(HV, EV),
    "dT": (SLOPE_T.subs(AV, mu), sp.tan(2 * A1)), "cos2": sp.cos(2 * A1) ** 2,
    "wp-int": (AW * CW.dot(EV), AW * CW.dot(HV)), "mnF2": (CW.dot(HV), -CW.dot(EV), AW),
    "Imin": measured("I min"), "extremes": ((measured("I min") - TW.trace() / 2) ** 2, (measured("I max") - TW.trace() / 2) ** 2),
    "D": V1M * measured("metacentric height"), "cD": CPH * V1M * measured("metacentric height"),
    "2cD": 2 * CPH * V1M * measured("metacentric height"), "Iminc": CPH * measured("I min"),
    "V3e3c": CPH * V1M * measured("G above B"),
}
PRINCIPAL = ((A1, Root(SLOPE_T.subs(AV, AV), AV, tuple(-0.8 + 0.02 * k for k in range(81)))),)   # a root of dT/dalpha


def _case(nm, extra=None, generic=False):
    poly, (nx, ny), _, t, bb, _ = CONFIGS[nm]
    p = _generic(nm) if generic else dict(_params(nm))
    return Case({**p, **(extra or {}), NX: nx, NY: ny, TT: t}, {"body": Body.prism(poly, bb)}, nm)


def _cases(names, extra=None, generic=False):
    """The cases of the named bodies, built when first measured."""
    return lambda: tuple(_case(nm, extra, generic) for nm in names)


floating = declarer(d, FloatingRootWitness, body=None, up=UP, density=s)     # a body of each case's own
UPSIDE_DOWN = tuple(-u for u in UP)     # with density 1 - s: dry and wet parts exchanged


G2 = ("rect", "tri", "square", "pent-eq", "box-eq")
E2 = ("pent-eq", "box-eq")
G3 = ("rect-3", "tri-3", "box3-eq")
floating("dry-volume", "volume of the clipped body above the water plane", ("V3-F", "100"), _cases(G2), MEASURE["V3"])
floating("dry-moment-y", "V_3 times the offset of the clipped dry part's centroid from the plane through S across GH",
         ("95", "95-moment"), _cases(G2), MEASURE["My"])
floating("dry-product", "the same over tan phi (int x y df of F by the clipped dry part)",
         ("95a", "95a-split", "96", "97", "106-projection"), _cases(G2), MEASURE["Pxy"])
floating("dry-offsets", "offsets of the clipped dry part's centroid from S along NE and along the axis",
         ("S3-offsets",), _cases(G2), MEASURE["offsets"])
floating("flip-product", "int x y df from the turned body (density 1 - s, -u up): its submerged part's offset along GH",
         ("s-below-half-95",), _cases(G2), MEASURE["flip-product"], up=UPSIDE_DOWN, density=1 - s)
floating("balance-complete", "V_1 times the horizontal offsets of the clipped centre of buoyancy from G", ("complete",),
         _cases(G2), MEASURE["balance"])
floating("dry-product-regular", "int x y df by the clipped dry part, regular bases", ("98",),
         _cases(("square", "eqtri")), MEASURE["Pxy"])
floating("balance", "V_1 times the horizontal offsets of the clipped centre of buoyancy from G", ("95-S3",), _cases(G2),
         MEASURE["balance"])
floating("M3", "V_3 times the horizontal distance of the clipped dry part's centroid from S across GH",
         ("99", "99-transformation", "102-pre", "102"), _cases(G2), MEASURE["M3"])
floating("M3-sin", "the same over sin phi", ("103b",), _cases(G2), MEASURE["M3sin"])
floating("dry-moments", "V_3 z_3 and V_3 x_3 of the clipped dry part (depth below the upper base, distance from GH)",
         ("101",), _cases(G2), MEASURE["ZX"])
floating("dry-height", "V_3 times the height of the clipped dry part's centroid above S along the axis", ("116-pre",),
         _cases(G2), MEASURE["V3zeta"])
floating("x0", "x_0 where the clipped water plane meets EF in the upper base", ("x0-sign",), _cases(G2), MEASURE["x0"])
floating("V1e2", "V_1 times the height of G above the clipped centre of buoyancy", ("104-balance",), _cases(G2),
         MEASURE["V1e2"])
floating("flip", "the same for density 1 - s with the body upside down (-u up)", ("s-below-half",), _cases(G2),
         MEASURE["flip"], up=UPSIDE_DOWN, density=1 - s)
for nm_, mv in (("rect", R(2, 5)), ("tri", R(6, 5)), ("pent-eq", R(7, 10))):
    floating(f"Tmu-{nm_}", "moment of the clipped waterplane about the centroidal axis at mu to GH", ("105", "105-def"),
             _cases((nm_,), {mu: mv}), MEASURE["Tmu"])
    floating(f"Tg-{nm_}", "the same (T_2, T_2^1, k the clipped waterplane's)", ("109",),
             _cases((nm_,), {mu: mv}, generic=True), MEASURE["Tmu"])
for nm_dt, mu_dt in (("rect", R(2, 5)), ("pent-eq", R(7, 10))):
    floating(f"dT-{nm_dt}", "dT_mu/dmu of the clipped waterplane's tensor and tan 2mu at its root (secant method)",
             ("108",), _cases((nm_dt,), {mu: mu_dt}, generic=True), MEASURE["dT"], roots=PRINCIPAL)
floating("cos2", "cos^2 2mu at the root of dT_mu/dmu of the clipped waterplane's tensor", ("109-cos",),
         _cases(G2, generic=True), MEASURE["cos2"], roots=PRINCIPAL)
floating("Tmu-eq", "moment of the clipped waterplane about the axis at mu, at the equilibria", ("107",),
         _cases(E2, {mu: R(1, 3)}), MEASURE["Tmu"])
floating("Ks", "central product moment of the clipped waterplane (axes along h and GH)", ("106-shift", "106-sum"),
         _cases(G2), MEASURE["Ks"])
floating("Ks-eq", "the same at the equilibria", ("106",), _cases(E2), MEASURE["Ks"])
floating("wp-integrals", "int_1 y df, int_1 x df of the clipped waterplane from N", ("106-moments",), _cases(G2),
         MEASURE["wp-int"])
floating("wp-mn", "distances m, n of the clipped waterplane's centroid from HN, from N along HN, and its area",
         ("112-mn",), _cases(G2), MEASURE["mnF2"])
floating("wp-T2", "moments of the clipped waterplane about the centroidal axes along GH and across it", ("111",),
         _cases(G2), MEASURE["T2"])
floating("k-eq", "central product of the clipped waterplane at the equilibria", ("112",), _cases(E2), MEASURE["Ks"])
floating("Imin", "least moment of the clipped waterplane", ("110",), _cases(G2, generic=True), MEASURE["Imin"])
floating("extremes", "squared deviations of the clipped waterplane's principal moments from their mean",
         ("109-extremes",), _cases(G2, generic=True), MEASURE["extremes"])
floating("Imin-eq", "least moment of the clipped waterplane times cos phi, equilibria", ("115",), _cases(E2),
         MEASURE["Iminc"])
floating("D", "V_1 times the metacentric height of the clipped position, equilibria", ("104",), _cases(E2),
         MEASURE["D"])
floating("cD", "cos phi times V_1 times the metacentric height, equilibria", ("114",), _cases(E2), MEASURE["cD"])
floating("2cD", "2 cos phi times V_1 times the metacentric height, equilibria", ("117",), _cases(E2), MEASURE["2cD"])
floating("e3", "V_3 e_3 cos phi of the clipped dry part, equilibria", ("116", "116-geometry"), _cases(E2),
         MEASURE["V3e3c"])
floating("dry-volume-3", "volume of the clipped body above the water plane, third region", ("121b", "121-dry"),
         _cases(G3), MEASURE["V3"])
floating("dry-product-3", "int x y df - int^1 x y df by the clipped dry part, third region", ("118",), _cases(G3),
         MEASURE["Pxy"])
floating("dry-moments-3", "V_3 z_3, V_3 x_3 of the clipped dry part, third region", ("120",), _cases(G3), MEASURE["ZX"])
floating("M3-3", "M_3 of the clipped dry part, third region", ("119",), _cases(G3), MEASURE["M3"])
floating("M3-3-sin", "M_3/sin phi of the clipped dry part, third region", ("121",), _cases(G3), MEASURE["M3sin"])
floating("x0x01", "(x_0 + x_0^1) tan phi from the clipped water lines in both bases", ("121a",), _cases(G3),
         MEASURE["x0x01"])
floating("122", "tan phi M_3/sin phi, (x_0 + x_0^1) tan phi - b and V_3 - F_1 b (1 - s), clipped", ("122",), _cases(G3),
         MEASURE["122"])


# ---- the stability remark on clipped boxes, the tilt (103a) by root finding, the moments of F (113)
BOXES = (Case({A_: 1, C_: 1, b: 1, s: R(3, 4), th: R(3, 5)}, label="cube, s = 3/4, theta = 0.6"),
         Case({A_: 1, C_: 1, b: 1, s: R(3, 4), th: R(9, 10)}, label="cube, s = 3/4, theta = 0.9"),
         Case({A_: R(3, 2), C_: R(1, 2), b: 1, s: R(4, 5), th: R(1, 2)}, label="box 3/2 x 1/2 x 1, s = 4/5"))
BOX_UP = (sp.sin(th), 0, sp.cos(th))
d.witness(FloatingRootWitness("box-slope", "V_1 dE/dtheta of clipped boxes (the slope of the clipped potential)",
                              ("stability-direction",), BOXES, body=Body.box(A_, C_, b), up=BOX_UP, density=s,
                              quantity=s * A_ * C_ * b * potential_slope(BOX_UP, th)))
# the tilt tan phi = q t_w at which the clipped water line passes through N at the case's x_0 (q within 2 % of 1)
QW = sp.Symbol("q^w", positive=True)
d.witness(FloatingRootWitness("tilt-root", "tan of the tilt at which the clipped water line passes through N",
                              ("103a",), lambda: tuple(_case(nm) for nm in ("rect", "tri")), body=None,
                              up=tuple(u.subs(TT, QW * TT) for u in UP), density=s, quantity=QW * TT,
                              roots=((QW, Root(X0M.subs(TT, QW * TT) - x0, QW,
                                               tuple(0.98 + 0.001 * k for k in range(41)))),)))


def _dry_face(nm):
    """The dry part F of the upper base (beyond GH, in the frame of N) as the base of a prism of its own."""
    poly, (nx, ny), x0v, _, _, _ = CONFIGS[nm]
    base = [(px * nx + py * ny + x0v, -px * ny + py * nx) for px, py in poly]
    return Case(_params(nm), {"body": Body.prism(_half([(sp.sympify(X), sp.sympify(Y)) for X, Y in base], 0), 1)}, nm)


d.witness(FloatingWitness("F-moments", "central moments of F (clipped upright prism over the dry part of the base)",
                          ("113", "117-T"), lambda: tuple(_dry_face(nm) for nm in ("rect", "tri", "pent-eq")),
                          body=None, up=(0, 0, 1), density=R(1, 2),
                          quantity=(measured("waterplane tensor, xx"), measured("waterplane tensor, yy"))))
