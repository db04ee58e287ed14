"""Scheeffer IV-V's witnesses: the clipped prism (:mod:`symfloat.engine.floating_witness`)."""
import sympy as sp

from symfloat.engine.declare import declarer
from symfloat.engine.floating_witness import Body, FloatingRootWitness, FloatingWitness, Root, waterplane_moment
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case
from symfloat.geometry.floating import polygon_moments

from .statements import F1, J, P, P3, T1, T11, Tx, Ty, b, d, mu, om, phi, s, ubot, utop

# ==== witnesses: the clipped prism ===========================================================================


R = sp.Rational
SQ3 = sp.sqrt(3)
_QUAD0 = [(R(0), R(0)), (R(3), R(0)), (R(5, 2), R(2)), (R(-1, 2), R(3, 2))]
_C = polygon_moments(_QUAD0)[1]                        # the centroid of the quadrilateral
QUAD = [(px - _C[0], py - _C[1]) for px, py in _QUAD0]
(QXX, QXY), (_QYX, QYY) = polygon_moments(QUAD)[2]    # its second moments about the centroid
Q_THETA = sp.atan(2 * QXY / (QXX - QYY)) / 2           # a principal direction of the quadrilateral
RECT_LONG = [(R(-1, 2), -1), (R(1, 2), -1), (R(1, 2), 1), (R(-1, 2), 1)]
RECT_SHORT = [(-1, R(-1, 2)), (1, R(-1, 2)), (1, R(1, 2)), (-1, R(1, 2))]
RECT_LAW = [(R(-1, 2), R(-3, 5)), (R(1, 2), R(-3, 5)), (R(1, 2), R(3, 5)), (R(-1, 2), R(3, 5))]
TRI = [(R(-1, 2), R(-2, 3)), (R(1, 2), R(-2, 3)), (0, R(4, 3))]
SQUARE = [(R(-1, 2), R(-1, 2)), (R(1, 2), R(-1, 2)), (R(1, 2), R(1, 2)), (R(-1, 2), R(1, 2))]
TRI_EQ = [(R(-1, 2), -SQ3 / 6), (R(1, 2), -SQ3 / 6), (0, SQ3 / 3)]

# name: (polygon, height b, s, axis angle alpha: EF along (cos alpha, sin alpha), the side (sin alpha, -cos alpha) dips)
BODIES = {
    "rect-long": (RECT_LONG, R(9, 10), R(2, 5), sp.pi / 2),
    "rect-short": (RECT_SHORT, R(9, 5), R(2, 5), sp.pi / 2),
    "tri": (TRI, R(3, 5), R(1, 2), sp.pi / 2),
    "quad-x": (QUAD, R(8, 5), R(1, 2), sp.Integer(0)),
    "quad-p": (QUAD, R(8, 5), R(1, 2), Q_THETA),
    "square-0": (SQUARE, R(17, 20), R(9, 20), sp.pi / 2),
    "square-30": (SQUARE, R(17, 20), R(9, 20), sp.pi / 2 + sp.pi / 6),
    "tri-eq": (TRI_EQ, R(16, 25), R(2, 5), sp.pi),
    "rect-law": (RECT_LAW, R(5, 6), R(1, 2), sp.pi / 2),
    "tri-eq-apex": (TRI_EQ, R(17, 25), R(2, 5), sp.pi),
    "tri-eq-apex-up": (TRI_EQ, R(17, 25), R(3, 5), sp.Integer(0)),
    "square-lim": (SQUARE, R(17, 20), R(9, 20), sp.pi / 2 + sp.pi / 6),
    "rect-heavy": (RECT_LONG, R(9, 10), R(3, 5), sp.pi / 2),
}


def _params(name, extra=None):
    """Exact parameters of a body: F_1, T_1, T_1^1, P about its axis EF, b, s, and the face reaches."""
    poly, bb, ss, alpha = BODIES[name]
    A, _, ((Ixx, Ixy), (_, Iyy)) = polygon_moments(poly)
    nx, ny = sp.sin(alpha), -sp.cos(alpha)               # u = n . p
    ex, ey = sp.cos(alpha), sp.sin(alpha)                # v = e . p
    t1_, t11_ = nx * nx * Ixx + 2 * nx * ny * Ixy + ny * ny * Iyy, ex * ex * Ixx + 2 * ex * ey * Ixy + ey * ey * Iyy
    p_ = nx * ex * Ixx + (nx * ey + ny * ex) * Ixy + ny * ey * Iyy
    us = [nx * px + ny * py for px, py in poly]
    simp = (lambda q: q) if name == "quad-p" else sp.simplify
    out = {F1: A, T1: simp(t1_), T11: simp(t11_), P: simp(p_), b: bb, s: ss,
           utop: simp(max(us, key=lambda q: float(q))), ubot: simp(-min(us, key=lambda q: float(q)))}
    out.update(extra or {})
    return out


# the clipped prism in the body frame (symfloat.engine.floating_witness): the axis EF along (cos alpha, sin alpha, 0),
# the side (sin alpha, -cos alpha, 0) dips; tilted by psi about EF the prism has the up vector and the horizontal
# across EF below, and reads B - G, the waterplane's moments and the bases' heights off the clipped body
ALPHA, PSI = sp.symbols("alpha_EF psi")
EV = sp.Matrix([sp.cos(ALPHA), sp.sin(ALPHA), 0])
NN = sp.Matrix([sp.sin(ALPHA), -sp.cos(ALPHA), 0])
UP = sp.cos(PSI) * sp.Matrix([0, 0, 1]) - sp.sin(PSI) * NN
HOR = sp.cos(PSI) * NN + sp.sin(PSI) * sp.Matrix([0, 0, 1])
V_, GB = measured("immersed volume"), measured("G above B")
BG = sp.Matrix([measured(f"B - G, {k}") for k in "xyz"])
TOP, BOT = measured("upper base above water"), measured("lower base above water")
ARM = HOR.dot(BG)                                       # the righting arm: B - G across EF, towards the dip
T2_, T21_, P2_ = waterplane_moment(HOR, HOR), waterplane_moment(EV, EV), waterplane_moment(HOR, EV)


def _cases(names, extra=None):
    """The cases of the named bodies (a name, or (name, argument, parameters)), built when first measured: each
    body's exact parameters and axis angle, and the clipped prism of its base and height."""
    def build():
        out = []
        for nm in names:
            arg, ex = None, {}
            if isinstance(nm, tuple):
                nm, arg, ex = nm
            poly, bb, _, alpha = BODIES[nm]
            out.append(Case({**_params(nm, {**(extra or {}), **ex}), ALPHA: alpha}, {"body": Body.prism(poly, bb)},
                            nm + (f", {arg}" if arg is not None else "")))
        return tuple(out)
    return build


def _contact(vanish):
    """The first tilt at which *vanish* (a base's height above the water, or its depth) reaches zero."""
    return ((PSI, Root.scan(vanish, PSI, R(1, 50), R(3, 2), 30)),)


# the tilted equilibrium: the first zero of the clipped righting arm as the tilt grows, no base cut there
EQUILIBRIUM = Root.scan(ARM, PSI, R(1, 50), R(7, 5), 28, guard=(TOP, -BOT))
upright = declarer(d, FloatingWitness, up=(0, 0, 1), density=s)
tilted = declarer(d, FloatingRootWitness, up=tuple(UP), density=s, roots=((PSI, EQUILIBRIUM),))    # at the equilibrium


EQ = ("rect-long", "rect-short", "tri", "quad-p", "square-0", "tri-eq")
NONISO = ("rect-long", "rect-short", "tri", "quad-p")
ISO = ("square-0", "square-30", "tri-eq")
LIM = ("tri-eq-apex", "tri-eq-apex-up", "square-lim", "rect-long", "rect-heavy")
MU_AXIS = sp.cos(mu) * HOR + sp.sin(mu) * EV            # normal of the axis at the angle mu with EF
AT_MU = (("rect-long", R(1, 3), {mu: R(1, 3)}), ("quad-p", R(6, 5), {mu: R(6, 5)}), ("tri", R(7, 10), {mu: R(7, 10)}))
ISO_AT_MU = (("square-0", R(1, 3), {mu: R(1, 3)}), ("tri-eq", R(5, 4), {mu: R(5, 4)}),
             ("square-30", R(1, 2), {mu: R(1, 2)}))
tilted("tilt", "tan of the tilt where the righting arm of the clipped prism vanishes", ("27",), _cases(EQ), sp.tan(PSI))
tilted("tilt-squared", "tan^2 of the tilt where the righting arm of the clipped prism vanishes", ("54",),
       _cases(EQ + ("square-30",)), sp.tan(PSI) ** 2)
tilted("Ve2", "V times the height of G above B at that tilt (clipped prism)", ("34", "35"), _cases(EQ), V_ * GB)
upright("Ve1", "V times the height of G above B, upright (clipped prism)", ("32-restated",), _cases(EQ), V_ * GB)
upright("upright-slope", "T about EF / V minus the height of G above B, upright clipped prism",
        ("stable-18", "unstable-18", "52-condition"), _cases(("rect-long", "tri", "quad-x")),
        waterplane_moment(NN, NN) / V_ - GB)
AT_PHI = (("quad-x", R(3, 10), {phi: R(3, 10)}), ("quad-x", R(1, 2), {phi: R(1, 2)}), ("tri", R(1, 5), {phi: R(1, 5)}))
upright("arm", "V times the righting arm of the clipped prism at a given tilt", ("moment-12",), _cases(AT_PHI),
        V_ * ARM.subs(PSI, phi), up=tuple(UP.subs(PSI, phi)))
upright("height", "V times the height of G above B of the clipped prism at a given tilt", ("13-restated",),
        _cases(AT_PHI), V_ * GB, up=tuple(UP.subs(PSI, phi)))
tilted("M2", "V times the offset of B from G along EF, clipped prism at the zero of the arm",
       ("31", "28", "M2-difference"), _cases(("quad-x", "rect-long", "tri"), {P3: R(1, 3)}), V_ * EV.dot(BG))
tilted("Q", "V times the arm over sin phi at the zero of the arm (clipped prism)", ("moment-zero",), _cases(EQ),
       V_ * ARM / sp.sin(PSI))
tilted("wp2", "second moments of the clipped waterplane II about EF, across it, and the product", ("38",),
       _cases(("quad-x", "rect-long", "tri", "quad-p")), (T2_, T21_, P2_))
tilted("wp2-ext", "the moments of the clipped waterplane II about EF and across it", ("41", "42"), _cases(EQ),
       (T2_, T21_))
tilted("P2", "product moment of the clipped waterplane II at the equilibrium tilt", ("39",),
       _cases(("rect-long", "tri", "quad-p")), P2_)
# not (37): its cases lie at the tilted equilibrium, where int_2 u_2 v_2 df_2 = 0 and the print of (37) (df for
# df_2 in that term) and its correction coincide
tilted("Tmu", "moment of the clipped waterplane II about the axis at the angle mu with EF", ("40",), _cases(AT_MU),
       waterplane_moment(MU_AXIS, MU_AXIS))
tilted("D2", "V times the metacentric height of the clipped tilted prism", ("33", "43", "43-again"), _cases(EQ),
       V_ * measured("metacentric height"))
tilted("D2-sign", "sign of the metacentric height of the clipped tilted prism", ("claim-43a",), _cases(NONISO),
       measured("stability sign"))
tilted("Tm-excess", "moment of II about EF minus V times the height of G over B (clipped)", ("43-Tm",), _cases(EQ),
       T2_ - V_ * GB)
tilted("Tm-excess-sign", "its sign", ("43-always",), _cases(EQ), sp.sign(T2_ - V_ * GB))
tilted("Tm1-excess", "moment across EF minus V times the height of G over B (clipped)", ("43a-conclusion",),
       _cases(NONISO), T21_ - V_ * GB)
tilted("iso-wp2", "moments of the clipped waterplane II, isotropic bases", ("50-Tm",), _cases(ISO), (T2_, T21_))
tilted("iso-ratio", "T_m cos^2 phi from the clipped waterplane II, isotropic bases", ("50-ratio",), _cases(ISO),
       T2_ * sp.cos(PSI) ** 2)
tilted("iso-order", "which moment of the clipped waterplane II is larger, isotropic bases", ("50",), _cases(ISO),
       sp.sign(T2_ - T21_))
tilted("iso-Tm1-value", "moment of the clipped waterplane II across EF, isotropic bases", ("Tm1-min",), _cases(ISO),
       T21_)
tilted("iso-Tm1", "moment across EF minus V e_2 of the clipped waterplane II, isotropic bases", ("51",), _cases(ISO),
       T21_ - V_ * GB)
tilted("iso-Tmu", "moment about the axis at mu minus V e_2, clipped, isotropic bases", ("51-claim",), _cases(ISO_AT_MU),
       waterplane_moment(MU_AXIS, MU_AXIS) - V_ * GB)
QUAD_OM = (("quad-x", R(1, 3), {om: R(1, 3)}), ("quad-x", R(6, 5), {om: R(6, 5)}))
SYM_OM = (("rect-long", R(1, 3), {om: R(1, 3), Tx: R(2, 3), Ty: R(1, 6)}),
          ("tri", R(6, 5), {om: R(6, 5), Tx: R(2, 9), Ty: R(1, 24)}))
EF_OM = sp.Matrix([-sp.sin(om), sp.cos(om), 0])         # EF at the angle omega with AB (the y axis), (44)
U_OM = sp.Matrix([sp.cos(om), sp.sin(om), 0])           # u across it
upright("base-T1", "moment of the clipped upright waterplane about the axis EF at the angle omega",
        ("T1-expanded", "T1-def"), _cases(QUAD_OM, {Tx: QYY, Ty: QXX, J: QXY}), waterplane_moment(U_OM, U_OM))
upright("base-T1-sym", "moment of the clipped upright waterplane about EF, symmetric bases", ("T1-symmetric",),
        _cases(SYM_OM), waterplane_moment(U_OM, U_OM))
upright("base-Iuv", "product moment of the clipped upright waterplane in the axes EF, GH", ("45", "second-condition"),
        _cases(QUAD_OM, {Tx: QYY, Ty: QXX, J: QXY}), waterplane_moment(U_OM, EF_OM))
TURNED = {ALPHA: ALPHA + om}                            # the tilt found about EF, the prism then turned by omega
LAW = (("rect-law", sp.pi / 12, {om: sp.pi / 12}), ("rect-law", sp.pi / 6, {om: sp.pi / 6}))
tilted("law", "int u v df of the stable tilt turned about the prism axis by omega (clipped)", ("law",),
       _cases(LAW, {Tx: R(18, 125), Ty: R(1, 10)}), V_ * EV.xreplace(TURNED).dot(BG) / sp.tan(PSI),
       up=tuple(UP.xreplace(TURNED)),
       roots=((PSI, Root.scan(ARM.xreplace(TURNED), PSI, R(1, 50), R(7, 5), 28, at={om: 0}, guard=(TOP, -BOT))),))
# (53) and (53a) hold for the base reached first (afterwards the water plane no longer passes through EF)
tilted("top", "tan of the tilt where the clipped prism's upper base reaches the water, reached first", ("53",),
       _cases(("tri-eq-apex", "rect-heavy")), sp.tan(PSI), roots=_contact(-TOP))
tilted("bot", "tan of the tilt where the clipped prism's lower base reaches the water, reached first", ("53a",),
       _cases(("tri-eq-apex-up", "square-lim", "rect-long")), sp.tan(PSI), roots=_contact(BOT))
tilted("first", "tan of the first contact of either base (clipped prism)", ("55",), _cases(LIM), sp.tan(PSI),
       roots=_contact(sp.Max(-TOP, BOT)))
