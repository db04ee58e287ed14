"""Scheeffer X's witnesses: the clipped cube (:mod:`symfloat.engine.floating_witness`)."""
import mpmath
import sympy as sp

from symfloat.engine.declare import cases_of, declarer
from symfloat.engine.floating_witness import (At, Body, CutWitness, FloatingRootWitness, Root, potential_slope)
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case
from symfloat.geometry.floating import polygon_moments

from .statements import L, a, co, d, half, om, pi, r2, rho, rho1, s, si, tg, xl

# ==== witnesses: the clipped cube ========================================================================
th = sp.Symbol("theta_w")                              # the tilt in the diagonal plane
UD = (-sp.sin(th) / r2, -sp.sin(th) / r2, sp.cos(th))  # up, turned from the top face towards the corner B
SLOPE = potential_slope(UD, th)                        # dE/dtheta of the clipped potential u.(G - B)
LEG = -r2 * measured("top clearance") / sp.sin(th)           # leg of the corner triangle cut at B: B lies u_x leg below
CUBE, UNIT = Body.box(a, a, a), Body.box(1, 1, 1)


cut = declarer(d, CutWitness, body=CUBE)    # the dry part above a water plane drawn through a point (``through``)


floating = declarer(d, FloatingRootWitness, up=UD, density=s, body=UNIT)


C = cases_of(a, om, rho, rho1, xl, s, L)


def dry_moment(K):
    """The water plane rising towards B with slope K across GH (up (-K sin w, -K cos w, 1)): the moment of the
    clipped dry part about the vertical plane through G across the axis (along (cos w, -sin w, 0)) over K, i.e.
    minus that of the submerged part, G being the origin: the witness's quantity and up vector."""
    return {"quantity": -measured("immersed volume") * (co * measured("B - G, x") - si * measured("B - G, y")) / K,
            "up": (-K * si, -K * co, 1)}


FACE = (C("a = 1, omega = 0.3, rho = 0.6", a=1, omega="0.3", rho="0.6"),
        C("a = 3/2, omega = 0.6, rho = 1/2", a="1.5", omega="0.6", rho="0.5"),
        C("a = 1, omega = 0.7, rho = 0.9", a=1, omega="0.7", rho="0.9"))
H_POINT = (a / 2 - rho, a / 2, a / 2)                  # H on the top edge, rho from the corner B
cut("dry-moment", "moment of the clipped dry part about the vertical plane across the axis / tan phi (tan phi = 1/4)",
    ("98", "167-sum", "167", "168", "174", "diagonal-claim"), FACE, **dry_moment(sp.Rational(1, 4)),
    through=H_POINT)
cut("dry-moment-45", "the same with the axis along a face diagonal", ("170",),
    (C("a = 1, rho = 0.6", a=1, rho="0.6"), C("a = 3/2, rho = 1/5", a="1.5", rho="0.2")),
    **dry_moment(sp.Rational(1, 4)), through=H_POINT, roots=((om, pi / 4),))
cut("dry-moment-third", "moment of the clipped dry part / tan phi, water plane through both water lines",
    ("173", "118-form", "173-only-45"),
    (C("a = 1, omega = 0.3, rho = 0.6, rho_1 = 0.4", a=1, omega="0.3", rho="0.6", rho_1="0.4"),
     C("a = 3/2, omega = 0.5, rho = 0.7, rho_1 = 0.9", a="1.5", omega="0.5", rho="0.7", rho_1="0.9")),
    **dry_moment(a / (a * (si + co) - (rho + rho1) * si)), through=H_POINT)


# ---- the triangle BHG of the top face in the frame of the text (origin N, x towards B, y along GH towards G), built
# from the square's corners: the upright prism over each triangle, its waterplane's moments moved to N (Steiner);
# NH and NG are the reach of the triangle BHG along -y and +y
def _frame(q):
    """A point of the top face (square coordinates) in the frame of the text."""
    e, nn, H = (co, -si), (si, co), (a / 2 - rho, a / 2)
    return (q[0] * nn[0] + q[1] * nn[1] - (H[0] * nn[0] + H[1] * nn[1]), q[0] * e[0] + q[1] * e[1])


H2, G2, B2 = (_frame(q) for q in ((a / 2 - rho, a / 2), (a / 2, a / 2 - rho * tg), (a / 2, a / 2)))
P2 = (0, B2[1])
HPB, GPB, BHG = Body.prism((H2, B2, P2), 1), Body.prism((G2, P2, B2), 1), Body.prism((H2, B2, G2), 1)  # counter-clockwise
INT_XY = (measured("waterplane tensor, xy")
          + measured("waterplane area") * measured("waterplane centroid, x") * measured("waterplane centroid, y"))
REACH = measured("freeboard") + measured("water level")
floating("frame-u", "distance NH from the square's corners (reach of BHG along -y)", ("u",), FACE, REACH, up=(0, -1, 0),
         density=half, body=BHG)
floating("frame-v", "distance NG from the square's corners (reach of BHG along +y)", ("v",), FACE, REACH, up=(0, 1, 0),
         density=half, body=BHG)
floating("xy-HPB", "int xy df over HPB (clipped waterplane of the prism over it)", ("HPB",), FACE, INT_XY,
         up=(0, 0, 1), density=half, body=HPB)
floating("xy-GPB", "int xy df over GPB (clipped waterplane of the prism over it)", ("GPB",), FACE, INT_XY,
         up=(0, 0, 1), density=half, body=GPB)
floating("area-BHG", "area of the triangle BHG (clipped waterplane of the prism over it)", ("area",), FACE,
         measured("waterplane area"), up=(0, 0, 1), density=half, body=BHG)


# ---- (171): the dry part F of the top face (exact polygon moments) and the clipped potential's slope where the
# water line cuts the leg x off the corner B
TH_GRID = tuple(0.02 * j for j in range(1, 48))       # up to the diagonal direction atan(sqrt 2) = 0.9553
T_F, z_F = sp.symbols("T_F z_F")


def _face_F(label, xv, sv):
    """The case with the moments of F, the top face less the corner triangle of leg x at B: T about the water
    line (along the diagonal through (1/2 - x, 1/2)) and z = sqrt 2 times F's moment about it (F's area times the
    distance of its centroid, on the side away from B)."""
    x_ = sp.Rational(xv)
    hf = sp.Rational(1, 2)
    area, (cx, cy), J = polygon_moments([(-hf, -hf), (hf, -hf), (hf, hf - x_), (hf - x_, hf), (-hf, hf)])
    dist = ((cx - (hf - x_)) + (cy - hf)) / r2          # from the water line towards B
    T = (J[0][0] + 2 * J[0][1] + J[1][1]) / 2 + area * dist ** 2
    return Case({xl: x_, s: sp.Rational(sv), T_F: T, z_F: -r2 * area * dist}, label=label)


floating("171-clipped", "moments of the dry face part F; clipped dE/dtheta at the orientation with leg x",
         ("171",), (_face_F("x = 3/10, s = 77/100", "0.3", "0.77"), _face_F("x = 1/2, s = 4/5", "0.5", "0.8"),
                    _face_F("x = 1/10, s = 3/4", "0.1", "0.75")),
         (2 * T_F, z_F, r2 * s * z_F ** 3 * sp.sqrt(1 + sp.tan(th) ** 2) / (1 - s) * SLOPE),
         roots=((th, Root(LEG - xl, th, TH_GRID)),))
TOUCH_B = Root(measured("top clearance"), th, tuple(0.2 + 0.05 * j for j in range(9)))     # the corner B at the water
floating("172-clipped", "density where the clipped equilibrium in the diagonal plane has its corner B at the water",
         ("172-number",), (Case({}, label="unit cube"),), s,
         roots=((s, Root(SLOPE, s, (0.765, 0.77, 0.775, 0.78), roots=((th, TOUCH_B),))),))

# (171) as read, left minus right side with the printed 2T and z, for numeric x, s (its roots are located
# with it): mpmath numbers, floats or numpy arrays alike
f_num = d.evaluator("171", (xl, s), 1, row=2)


def _root_slope(sv, flip):
    """The slope p = (1 - s)/z of the up vector (-p, -p, 1) at the root x of (171) as read, density sv (flip: the
    cube turned over at 1 - sv, up (p, p, -1)), at 60 digits."""
    q = 1 - sv if flip else sv
    with mpmath.workdps(60):
        q = mpmath.mpf(q.p) / q.q
        xr = mpmath.findroot(lambda t_: f_num(t_, q), (0.5, 0.6), solver="anderson")
        return sp.Float((1 - q) / (1 - xr + xr ** 3 / 6), 60)


p_w = sp.Symbol("p_w")
ONE = (Case({}, label="unit cube"),)
floating("pentagon-count", "vertices of the clipped waterplane at the root of (171), s = 3/5", ("pentagon-exists",),
         lambda: (Case({p_w: _root_slope(sp.Rational(3, 5), False)}, label="unit cube"),), measured("waterplane corners"),
         up=(-p_w, -p_w, 1), density=sp.Rational(3, 5))
floating("pentagon-count-dual", "vertices of the clipped waterplane at the dual root, s = 2/5", ("dual-exists",),
         lambda: (Case({p_w: _root_slope(sp.Rational(2, 5), True)}, label="unit cube"),), measured("waterplane corners"),
         up=(p_w, p_w, -1), density=sp.Rational(2, 5))
t1_, t2_, e1p, e1m, e2p, e2m = sp.symbols("theta_1w theta_2w E_1p E_1m E_2p E_2m")
EQ_GRID = tuple(0.25 + 0.05 * j for j in range(10))
STEP = sp.Rational(1, 10 ** 6)                          # the difference quotient's half step
floating("pentagon-stiffness", "signs of the clipped second derivative of the potential at the two pentagonal "
         "equilibria in the diagonal plane, s = 0.77", ("pentagon-stable",), ONE,
         (sp.sign(e1p - e1m), sp.sign(e2p - e2m)), density=sp.Rational(77, 100),
         roots=((t1_, Root(SLOPE, th, EQ_GRID, which=0)), (t2_, Root(SLOPE, th, EQ_GRID, which=1)),
                (e1p, At(SLOPE, {th: t1_ + STEP})), (e1m, At(SLOPE, {th: t1_ - STEP})),
                (e2p, At(SLOPE, {th: t2_ + STEP})), (e2m, At(SLOPE, {th: t2_ - STEP}))))

# ---- the cube turned corner up: the plane through three face diagonals, triangles and hexagons
DIAGONAL = (1, 1, 1)
cut("tetra-dry", "dry volume of the clipped cube above the plane through three face diagonals", ("tetra",),
    (C("a = 1", a=1), C("a = 3/2", a="1.5")), a ** 3 - measured("immersed volume"), up=DIAGONAL,
    through=(a / 2, a / 2, -a / 2))
cut("five-sixths", "submerged fraction of the unit cube below the plane through three face diagonals", ("five-sixths",),
    ONE, measured("immersed volume"), up=DIAGONAL, through=(half, half, -half), body=UNIT)
floating("tri-GM", "sign of the metacentric height of the clipped cube, corner up, s = 1 - L^3/6", ("tri-unstable",),
         (C("L = 1/2", L="0.5"), C("L = 4/5", L="0.8")), measured("stability sign"), up=DIAGONAL, density=1 - L ** 3 / 6)
floating("diagonal-shape", "+1 if the clipped waterplane of the cube turned corner up is a hexagon, -1 if a triangle",
         ("hex-follows",), (C("s = 4/5", s="0.8"), C("s = 9/10", s="0.9")),
         (2 * measured("waterplane corners") - 9) / 3,
         up=DIAGONAL)
floating("hex-GM", "sign of the metacentric height of the clipped cube, corner up, s = 1/2", ("hex-half",), ONE,
         measured("stability sign"), up=DIAGONAL, density=half)
