"""Scheeffer VI.A-B's witnesses: clipped polyhedra and the floating cylinder (symfloat.engine.floating_witness)."""
import sympy as sp

from symfloat.engine.declare import declarer
from symfloat.engine.floating_witness import (FLOATING_METHODS, Body, Combined, FloatingRootWitness, FloatingWitness,
                                              Joined, Loaded, Root, waterplane_moment)
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case, Precision
from symfloat.geometry.floating import polygon_moments

from .statements import NGONS, Q60_3, Tx, Ty, a, b, d, om, pi, r, s, sq3

# =====================================================================================================
# Witnesses: clipped polyhedra (symfloat.geometry.floating) and the floating cylinder (Body.cylinder)
# =====================================================================================================
# ---- floating witnesses of the triangular prism (symfloat.engine.floating_witness) ------------------------
# the triangle B C A of the text (edge a, centre O at the origin, A on the +Y axis), the prism of height b along z;
# tilted by psi about the axis PQ at the angle omega with OB, the side n (vertex B's side) dipping
PSI = sp.Symbol("psi")
U_OM = sp.Matrix([sp.cos(om), sp.sin(om), 0])           # the normal of the axis at the angle omega (u of (44))
N_DIP = sp.Matrix([-sp.sin(om), -sp.cos(om), 0])
UP = sp.cos(PSI) * sp.Matrix([0, 0, 1]) - sp.sin(PSI) * N_DIP
ARM = (sp.cos(PSI) * N_DIP + sp.sin(PSI) * sp.Matrix([0, 0, 1])).dot(
    sp.Matrix([measured(f"B - G, {k}") for k in "xyz"]))  # B - G horizontally towards the dip: the righting arm
TOP, BOT = measured("upper base above water"), measured("lower base above water")
GM, VOL = measured("metacentric height"), measured("immersed volume")
HALF = sp.Rational(1, 2)


def _triangle(edge, height):
    return Body.prism(((-edge / 2, -edge / (2 * sq3)), (edge / 2, -edge / (2 * sq3)), (0, edge / sq3)), height)


def tilted(name, description, targets, cases, quantity, vanish=ARM, body=None, **kw):
    """A quantity at the first zero of *vanish* (the righting arm: the tilted equilibrium) as the tilt grows."""
    d.witness(_root_witness(name, description, targets, cases, quantity, vanish, body, **kw))


TILTS = (sp.Rational(1, 50), sp.Rational(3, 2))          # the bracket of a tilt, scanned in 30 steps


def first_tilt(vanish):
    """The first zero of *vanish* as the tilt grows (a base's contact, the tilted equilibrium)."""
    return Root.scan(vanish, PSI, *TILTS, 30)


def _root_witness(name, description, targets, cases, quantity, vanish, body=None, at=None, up=UP, density=s,
                  along=PSI, bracket=TILTS, steps=30, roots=(), **kw):
    """*quantity* at the first zero of *vanish* along *along* (scanned in *steps* steps over *bracket*), *roots*
    found at each trial value first (a zero inside a zero); *at*: values of the example (the axis omega) put into
    the up vector and the quantities."""
    put = (lambda e: e.xreplace(at) if at and isinstance(e, sp.Basic) else e)     # noqa: E731
    return FloatingRootWitness(name, description, tuple(targets), tuple(cases), body=body or _triangle(a, b),
                               up=tuple(put(c) for c in up), density=density, quantity=put(quantity),
                               roots=((along, Root.scan(put(vanish), along, *bracket, steps, roots=roots)),), **kw)


# (56): an isosceles trapezoid (symmetric about the Y axis, not regular); T_x = int y^2, T_y = int x^2 about its
# centroid (polygon_moments, exact)
TRAP = ((-2, 0), (2, 0), (1, 3), (-1, 3))
TRAP_MOMENTS = polygon_moments([(sp.Integer(x_), sp.Integer(y_)) for x_, y_ in TRAP])[2]
TRAP_TY, TRAP_TX = TRAP_MOMENTS[0][0], TRAP_MOMENTS[1][1]
upright = declarer(d, FloatingWitness, body=_triangle(a, b), up=(0, 0, 1), density=s)     # the upright prism
upright("trapezoid-moments", "moment of a symmetric trapezoid about axes through its centroid (clipped waterplane)",
        ("56",), [Case({Tx: TRAP_TX, Ty: TRAP_TY, om: w_}, label=f"omega = {w_}") for w_ in (sp.Rational(2, 5), 1)],
        waterplane_moment(U_OM, U_OM), body=Body.prism(TRAP, 1), density=HALF)
d.witness(Joined("regular-polygon-moments", "moments of regular polygons about a turned axis (clipped waterplane)",
                 ("regular-polygon-theorem",),
                 (Case({a: 1, om: sp.Rational(1, 3)}), Case({a: sp.Rational(3, 2), om: 1})),
                 parts=tuple(FloatingWitness(f"{n}-gon", "", (), (), body=Body.regular(n, a, 1), density=HALF,
                                             quantity=waterplane_moment(U_OM, U_OM)) for n in NGONS)))

up_cases = [Case({a: 1, b: 1, s: sp.Rational(1, 2)}, label="labile"), Case({a: 2, b: 1, s: sp.Rational(4, 5)}, label="stable"),
            Case({a: sp.Rational(3, 2), b: 2, s: sp.Rational(1, 4)})]
upright("triangle-upright-57", "24 s/b times the metacentric height of the clipped upright prism", ("57", "65-I"),
        up_cases, 24 * s / b * GM)
upright("triangle-upright-58", "2 s/b times the metacentric height of the clipped upright prism", ("58",), up_cases,
        2 * s / b * GM)
upright("triangle-upright-moment", "displacement times metacentric height (clipped upright prism)",
        ("triangle-condition",), up_cases, VOL * GM)

tilt_cases = [Case({a: sp.Rational(83, 50), b: 1, s: sp.Rational(11, 20), om: sp.Rational(1, 5)}, label="II, s > 1/2"),
              Case({a: sp.Rational(33, 20), b: 1, s: sp.Rational(2, 5), om: sp.Rational(9, 10)}, label="II, s < 1/2")]
tilted("triangle-tilted-equilibrium", "tan of the tilt where the righting arm of the clipped prism vanishes",
       ("60-tan", "ex3-tan"), tilt_cases, sp.tan(PSI))
tilted("triangle-tilted-equilibrium-squared", "the same, squared", ("65-tan",), tilt_cases, sp.tan(PSI) ** 2)
lim_cases = [Case({a: 1, b: 1, s: sp.Rational(3, 5), om: sp.Rational(3, 10)}),
             Case({a: sp.Rational(3, 2), b: 2, s: sp.Rational(7, 10), om: 1})]
tilted("triangle-top-contact", "tan of the tilt at which the clipped prism's top base meets the water",
       ("60-bound",), lim_cases, sp.tan(PSI), TOP)
tilted("triangle-top-contact-distance", "b(1-s) over the measured contact tangent: the distance of the dipping vertex",
       ("59",), lim_cases, b * (1 - s) / sp.tan(PSI), TOP)
tilted("triangle-first-contact", "tan of the tilt at which either base of the clipped prism meets the water",
       ("60-one-base",), [Case({}, label="a = b = 1, s = 3/5, omega = 0")], sp.tan(PSI), sp.Min(TOP, -BOT),
       body=_triangle(1, 1), density=sp.Rational(3, 5), at={om: 0})


# ---- the cylinder: Body.cylinder (quadrature of exact slices, symfloat.engine.floating_witness) --------------
# axis z, centred, tilted by psi towards +x: the side -x dips, the righting arm is B - G horizontally towards it
UP_C = (sp.sin(PSI), 0, sp.cos(PSI))
ARM_C = -sp.cos(PSI) * measured("B - G, x") + sp.sin(PSI) * measured("B - G, z")
R = sp.Symbol("R", positive=True)                   # a radius sought, b = 1


def cyl_root(name, description, targets, cases, quantity, vanish=ARM_C, body=Body.cylinder(r, b), up=UP_C,
             density=s, along=PSI, bracket=TILTS, steps=30, roots=(), **kw):
    """A quantity of the cylinder at the first zero of *vanish* (the righting arm: the tilted equilibrium) as the
    tilt grows, or along ``along``; *roots* found at each trial value first."""
    return FloatingRootWitness(name, description, tuple(targets), tuple(cases), body=body, up=up, density=density,
                               quantity=quantity,
                               roots=((along, Root.scan(vanish, along, *bracket, steps, roots=roots)),), **kw)


cyl_cases = [Case({r: 1, b: 1, s: sp.Rational(1, 2)}), Case({r: sp.Rational(3, 2), b: 2, s: sp.Rational(1, 5)}),
             Case({r: sp.Rational(1, 2), b: 2, s: sp.Rational(9, 10)})]
cylinder = declarer(d, FloatingWitness, body=Body.cylinder(r, b), density=s)     # the upright cylinder
cylinder("cylinder-upright-69", "16 s/b times the metacentric height of the upright cylinder", ("69", "70"), cyl_cases,
         16 * s / b * GM)
cylinder("cylinder-upright-72", "-16 s/b times the metacentric height", ("72",), cyl_cases, -16 * s / b * GM)
cylinder("cylinder-upright-gm", "metacentric height of the upright cylinder", ("cylinder-condition",), cyl_cases, GM)
tiltc_cases = [Case({r: sp.Rational(8, 5), b: sp.Rational(5, 2), s: sp.Rational(3, 5)}, label="example 10"),
               Case({r: sp.Rational(1, 2), b: 1, s: sp.Rational(3, 20)}, label="square section, s = 0.15")]
d.witness(cyl_root("cylinder-tilted-equilibrium", "tan^2 of the tilt where the cylinder's righting arm vanishes",
                   ("72a-tan",), tiltc_cases, sp.tan(PSI) ** 2))

# ---- worked examples: the printed numbers that are geometric quantities ------------------------------------
one = [Case({}, label="the example's data")]


# the examples' data are in the bodies: a root along the aspect ratio Q = a/b (b = 1) or along the density
Q = sp.Symbol("Q", positive=True)
tilted("example-1", "a/b at which the clipped upright prism (s = 0.8) has zero metacentric height",
       ("ex1-root", "ex1-value"), one, Q, GM, body=_triangle(Q, 1), up=(0, 0, 1), density=sp.Rational(4, 5), along=Q,
       bracket=(sp.Rational(6, 5), 2), steps=16)
for nm, description, tg, quantity, lo, hi in (
        ("example-2-upper", "density of zero metacentric height, a = b (clipped prism), upper", "ex2-upper", s,
         HALF, sp.Rational(99, 100)),
        ("example-2-lower", "the same, lower", "ex2-lower", s, sp.Rational(1, 100), HALF),
        ("example-2-root", "2 s_+ - 1 from the measured density", "ex2-root-value", 2 * s - 1, HALF,
         sp.Rational(99, 100)),
        ("example-2-radicand", "2 s_+ - 1, the root of the radicand, from the measured density", "ex2-two-thirds",
         2 * s - 1, HALF, sp.Rational(99, 100))):
    tilted(nm, description, (tg,), one, quantity, GM, body=_triangle(1, 1), up=(0, 0, 1), along=s, bracket=(lo, hi),
           steps=49)


tilted("example-3-angle", "equilibrium tilt of the clipped prism at s = 2/3, a/b = sqrt(5/2), degrees", ("ex3-angle",),
       one, 180 * PSI / pi, body=_triangle(sp.sqrt(Q60_3), 1), density=sp.Rational(2, 3), at={om: pi / 3})


EX4 = {"body": _triangle(12 * sp.sqrt(2) / 11, 1), "density": sp.Rational(7, 11), "at": {om: pi / 12}}
d.witness(Joined("example-4",
                 "clipped prism at the example's answer: equilibrium and contact tangents (omega = 15 deg)", ("67",),
                 (Case({a: 12 * sp.sqrt(2) / 11, b: 1, s: sp.Rational(7, 11)}),),
                 parts=(_root_witness("equilibrium", "", (), (), sp.tan(PSI), ARM, **EX4),
                        _root_witness("top contact", "", (), (), sp.tan(PSI), TOP, **EX4))))
d.witness(cyl_root("example-5", "2r/b at which the upright cylinder (s = 1/2) has zero metacentric height",
                   ("ex5", "sqrt2"), one, 2 * R, GM, body=Body.cylinder(R, 1), up=(0, 0, 1), density=HALF, along=R,
                   bracket=(HALF, sp.Rational(3, 2)), steps=20))
SQUARE = Body.cylinder(HALF, 1)                     # examples 6, 7: 2r = b
for root_name, root_target, root_quantity, root_lo, root_hi, steps in (
        ("example-6-root", "ex6-root-value", 2 * s - 1, HALF, sp.Rational(99, 100), 49),
        ("example-6-sum", "ex6-sum", 2 * s, HALF, sp.Rational(99, 100), 49),
        ("example-6-difference", "ex6-difference", 2 * s, sp.Rational(1, 100), sp.Rational(49, 100), 24),
        ("example-6-upper", "ex6-upper", s, HALF, sp.Rational(99, 100), 49),
        ("example-6-lower", "ex6-lower", s, sp.Rational(1, 100), sp.Rational(49, 100), 24),
        ("example-7-lower", "ex7-lower", s, sp.Rational(1, 100), sp.Rational(49, 100), 24),
        ("example-7-range-lower", "ex7-range-lower", s, sp.Rational(1, 100), sp.Rational(49, 100), 24)):
    d.witness(cyl_root(root_name, "density of zero metacentric height of the upright cylinder with 2r = b",
                       (root_target,), one, root_quantity, GM, body=SQUARE, up=(0, 0, 1), along=s,
                       bracket=(root_lo, root_hi), steps=steps))

# example 7: the density at which the tilted equilibrium reaches the lower base (2r = b, s < 1/2): the righting
# arm vanishes where the lower base meets the water (the tilt of that contact found at each trial density)
NESTED = (FLOATING_METHODS[0], Precision(30, 1e-20))   # a zero inside a zero: 30 digits (40 cost minutes)
EX7 = {"body": SQUARE, "along": s, "bracket": (sp.Rational(37, 250), sp.Rational(33, 200)), "steps": 1,
       "roots": ((PSI, first_tilt(BOT)),), "methods": NESTED}
d.witness(cyl_root("example-7-minus", "density at which the tilted equilibrium of the cylinder reaches the lower base",
                   ("ex7-minus", "ex7-range-upper"), one, s, ARM_C, **EX7))
d.witness(cyl_root("example-7-root", "0.4 minus that density", ("ex7-root",), one, sp.Rational(2, 5) - s, ARM_C,
                   **EX7))

# example 10: the tilted equilibrium of r = 1.6, b = 2.5, s = 0.6; x, the water's height on the dipping side line
# above the lower base, is b minus the upper base's lowest point above water over cos(psi)
EX10 = {"body": Body.cylinder(sp.Rational(8, 5), sp.Rational(5, 2)), "density": sp.Rational(3, 5)}
X10 = sp.Rational(5, 2) - TOP / sp.cos(PSI)
for ex10_name, ex10_description, ex10_targets, ex10_quantity in (
        ("example-10-angle", "equilibrium tilt of the cylinder, degrees", ("ex10-angle",), 180 * PSI / pi),
        ("example-10-x", "water height on the dipping side line", ("ex10-x-sum", "ex10-x"), X10),
        ("example-10-fraction", "the same over b", ("ex10-fraction", "ex10-deepest"), X10 / sp.Rational(5, 2)),
        ("example-10-dry", "the part above water, over b", ("ex10-dry",), 1 - X10 / sp.Rational(5, 2)),
        ("example-10-dry-cm", "the part above water in cm", ("ex10-dry-cm",), 100 * (sp.Rational(5, 2) - X10))):
    d.witness(cyl_root(ex10_name, ex10_description, ex10_targets, one, ex10_quantity, **EX10))


# at s = 11/20, (a/b)^2 = 11/5 (region III): the righting arm of the clipped prism at the first contact of a base,
# for the axis omega_x where both contacts coincide
tilted("region-III-counterexample", "righting arm at the first base contact, clipped prism", ("65-III-claim",),
       one, ARM, sp.Min(TOP, -BOT), body=_triangle(sp.sqrt(sp.Rational(11, 5)), 1), density=sp.Rational(11, 20),
       at={om: sp.atan((2 - 3 * sp.Rational(11, 20)) / (sq3 * sp.Rational(11, 20)))})


# =====================================================================================================
# Witnesses for the limits (61)-(65), (71)-(73) and examples 3, 4, 8, 9
# =====================================================================================================
def _boundary(s_value, quantity, which, *declared):
    """The (a/b)^2 = Q (b = 1) at which the clipped prism's tilted equilibrium reaches the contact of a base for
    the axis omega = 60 deg: the zero along Q of the righting arm read at the first contact (which = TOP: the
    upper base, vertex B dipping; BOT: the lower base, B rising).  *quantity* is read there, an expression in Q
    and the case (the upright body at that Q serves only to read it); *declared*: name, description, targets,
    cases of a witness of its own."""
    flip = {om: pi / 3} if which == TOP else {om: pi / 3 + pi}      # B rising: the axis turned half round
    return _root_witness(*(declared or ("boundary", "", (), ())), quantity, ARM, body=_triangle(sp.sqrt(Q), 1),
                         density=s_value, at=flip, along=Q, steps=8,
                         bracket=(6 * s_value * (1 - s_value), 12 * s_value * (1 - s_value) * 999 / 1000),
                         roots=((PSI, first_tilt(which)),))


q60_cases = [Case({a: sp.Rational(3, 2), b: 1, s: sp.Rational(11, 20)}, label="s = 0.55, (a/b)^2 = 2.25"),
             Case({a: 3, b: 2, s: sp.Rational(9, 20)}, label="s = 0.45, (a/b)^2 = 2.25")]
QQ = (a / b) ** 2
d.witness(Joined("triangle-omega60-boundaries", "(a/b)^2 minus the (a/b)^2 at which the clipped prism's equilibrium "
                 "reaches the upper base (B dipping) / lower base (B rising) at omega = 60 deg (righting arm zero at "
                 "the contact)", ("62", "62-step-3"), q60_cases[:1],
                 parts=(_boundary(s, QQ - Q, TOP), _boundary(s, QQ - Q, BOT))))
d.witness(_boundary(s, 2 * (QQ - Q), TOP, "triangle-omega60-boundary-twice", "twice the same margin (top base)",
                    ("62-step-1", "62-step-2"), q60_cases[:1]))
d.witness(Joined("triangle-region-II", "-24 s/b times the clipped upright metacentric height, and the two clipped "
                 "omega = 60 deg margins", ("65-II",), q60_cases[:1],
                 parts=(FloatingWitness("upright", "", (), (), body=_triangle(a, b), density=s,
                                        quantity=-24 * s / b * GM),
                        _boundary(s, QQ - Q, TOP), _boundary(s, QQ - Q, BOT))))
d.witness(_boundary(s, Q, TOP, "example-3-boundary", "(a/b)^2 at which the clipped prism (s = 2/3) has its "
                    "equilibrium at the upper-base contact, omega = 60 deg", ("ex3-ratio-squared", "ex3-condition"),
                    [Case({s: sp.Rational(2, 3)})]))
d.witness(_boundary(sp.Rational(2, 3), sp.sqrt(Q), TOP, "example-3-ratio", "its root a/b",
                    ("ex3-ratio", "ex3-ratio-fraction"), one))


# example 4: the clipped prism tilted by 30 deg about the axis omega = 15 deg, in equilibrium with the upper base
# just touching the water: nested zeros, of the righting arm along s and of the upper base's height along a/b = Q
EX4_AT = {om: pi / 12, PSI: pi / 6}
EX4_S = (sp.Rational(11, 20), sp.Rational(3, 4))
TOUCHING = Root.scan(TOP, Q, 1, 2, 10)                              # the a/b at which the upper base touches
BALANCED = Root.scan(ARM.xreplace(EX4_AT), s, *EX4_S, 10)           # the density of equilibrium at the tilt
d.witness(_root_witness("example-4-density", "density of the clipped prism in equilibrium at 30 deg with the upper "
                        "base touching (omega = 15 deg)", ("ex4-density",), one, s, ARM, body=_triangle(Q, 1),
                        at=EX4_AT, along=s, bracket=EX4_S, steps=10, roots=((Q, TOUCHING),)))
d.witness(_root_witness("example-4-ratio", "a/b of the same clipped solution", ("ex4-ratio", "ex4-ratio-value"), one,
                        Q, TOP, body=_triangle(Q, 1), at=EX4_AT, along=Q, steps=5,
                        bracket=(sp.Rational(3, 2), sp.Rational(8, 5)), roots=((s, BALANCED),)))


# ---- the first-region model of the triangle: columns over the base from the bottom to the water plane --------
# (61)-(65) let a column rise above the upper base or fall below the lower one (a negative height).  The same
# zeros: the prism extended by b on either side (length 3b, the real one its middle third) at the same water
# plane, its lower third a neutral part (weight equal to its buoyancy, always immersed): it adds F b to the
# volume and G = -b/(1 + s) (the weighted centre of the two parts), and B - G is the model's times
# V / (V + F b), so the righting arm vanishes where the model's does.  A column's height above the real bottom
# is its depth over cos(psi) minus b: the upper base's clearance at the deepest vertex and the lower base's at
# the shallowest follow from the draught and the lower base's height above water.
def _model(edge, height):
    return Loaded.of(_triangle(edge, 3 * height), (0, 0, -height / (1 + s)))


def _top(height):
    return 2 * height - measured("draught") / sp.cos(PSI)


def _bottom(height):
    return -BOT / sp.cos(PSI) - height


MODEL = {"body": _model(a, b), "density": (1 + s) / 3}
B_RISING = {om: om + pi}                            # the axis turned half round: vertex B on the rising side


def _model_sin(quantity):
    """*quantity* at the axis omega (0 ... 60 deg) at which the model's equilibrium reaches the upper base (B
    dipping) and the lower base (B rising): the righting arm at the contact vanishes there."""
    return tuple(_root_witness("sin", "", (), (), quantity, ARM.xreplace(turn), up=UP.xreplace(turn), along=om,
                               bracket=(0, pi / 3), steps=1, roots=((PSI, first_tilt(which)),), **MODEL)
                 for which, turn in ((_top(b), {}), (_bottom(b), B_RISING)))


d.witness(Joined("model-61", "sin(30 deg + omega) of the axis where the first-region model's upper-base (B dipping) "
                 "/ lower-base (B rising) contact meets its equilibrium", ("61",), q60_cases,
                 parts=_model_sin(sp.sin(pi / 6 + om))))
d.witness(Joined("model-65-III-omega", "the same, squared", ("65-III-omega",), q60_cases,
                 parts=_model_sin(sp.sin(pi / 6 + om) ** 2)))
d.witness(Joined("model-61-from-60", "the model's equilibrium tangent and upper-base contact tangent at the case's "
                 "axis", ("61-from-60",),
                 (Case({a: sp.Rational(3, 2), b: 1, s: sp.Rational(11, 20), om: sp.Rational(3, 10)}),
                  Case({a: 3, b: 2, s: sp.Rational(7, 10), om: 1})),
                 parts=(_root_witness("equilibrium", "", (), (), sp.tan(PSI), ARM, **MODEL),
                        _root_witness("contact", "", (), (), sp.tan(PSI), _top(b), **MODEL))))


def _model_boundaries(omega):
    """The (a/b)^2 = Q (b = 1) at which the model's equilibrium reaches the upper base (B dipping) and the lower
    base (B rising) for the axis *omega*: zeros along Q of the righting arm at the contact."""
    body = {"body": _model(sp.sqrt(Q), 1), "density": (1 + s) / 3}
    return tuple(_root_witness("boundary", "", (), (), Q, ARM, at={om: omega + turn}, along=Q, steps=1,
                               bracket=(12 * s * (1 - s) / 10, 12 * s * (1 - s) * 999 / 1000),
                               roots=((PSI, first_tilt(which)),), **body)
                 for which, turn in ((_top(1), 0), (_bottom(1), pi)))


Q0_M, Q60_M = _model_boundaries(0), _model_boundaries(pi / 3)
d.witness(Combined("model-omega0-63", "half of the (a/b)^2 at which the model's equilibrium meets the upper (B "
                   "dipping) / lower (B rising) base contact at omega = 0, minus half of (a/b)^2", ("63",), q60_cases,
                   parts=Q0_M, values=((measured("part 1") - QQ) / 2, (measured("part 2") - QQ) / 2)))
d.witness(Combined("model-omega0-64", "the same margins, not halved", ("64",), q60_cases, parts=Q0_M,
                   values=(measured("part 1") - QQ, measured("part 2") - QQ)))
d.witness(Combined("model-region-III", "the model's boundaries at omega = 60 deg and 0 against (a/b)^2", ("65-III",),
                   q60_cases, parts=(*Q60_M, *Q0_M),
                   values=(measured("part 1") - QQ, QQ - measured("part 3"), measured("part 2") - QQ,
                           QQ - measured("part 4"))))


# ---- the cylinder: the limits (72a), (73) and examples 8, 9 ------------------------------------------------
# the tangents at which the upper base meets the water (tilting up) and the lower base (the upper one not cut:
# the cylinder extended upwards to 2b at the same draught), and of the tilted equilibrium
CONTACTS = (cyl_root("upper", "", (), (), sp.tan(PSI), TOP),
            cyl_root("lower", "", (), (), sp.tan(PSI), BOT, body=Body.cylinder(r, 2 * b), density=s / 2))
EQUILIBRIUM = cyl_root("equilibrium", "", (), (), sp.tan(PSI))
K2_ = (2 * r / b) ** 2
d.witness(Joined("cylinder-contacts", "tangents of the tilts at which the upper and the lower base meet the water",
                 ("72a",), tiltc_cases[:1], parts=CONTACTS))
d.witness(Combined("cylinder-contact-margins", "squared contact tangents minus the squared equilibrium tangent",
                   ("72a-squared",), tiltc_cases[:1], parts=(*CONTACTS, EQUILIBRIUM),
                   values=(measured("part 1") ** 2 - measured("part 3") ** 2,
                           measured("part 2") ** 2 - measured("part 3") ** 2)))
d.witness(Combined("cylinder-73", "-16 s/b times the upright metacentric height, and (2r/b)^2/2 times the "
                   "squared-tangent margins", ("73",), tiltc_cases[:1],
                   parts=(FloatingWitness("upright", "", (), (), body=Body.cylinder(r, b), density=s, quantity=GM),
                          *CONTACTS, EQUILIBRIUM),
                   values=(-16 * s / b * measured("part 1"),
                           (measured("part 2") ** 2 - measured("part 4") ** 2) * K2_ / 2,
                           (measured("part 3") ** 2 - measured("part 4") ** 2) * K2_ / 2)))
d.witness(Joined("cylinder-71", "densities at which the upright cylinder's metacentric height vanishes", ("71",),
                 (Case({r: sp.Rational(3, 5), b: 1}), Case({r: 1, b: 3})),
                 parts=tuple(cyl_root(f"root {k}", "", (), (), s, GM, up=(0, 0, 1), along=s, bracket=bracket,
                                      steps=49)
                             for k, bracket in enumerate(((HALF, sp.Rational(99, 100)),
                                                          (sp.Rational(1, 200), sp.Rational(99, 200)))))))


def threshold(density, *values):
    """*values* and (2R)^2, at which the upright cylinder of radius R, b = 1 (the ratio 2r/b: the metacentric
    height is homogeneous of degree 1 in r, b) has zero metacentric height at *density*."""
    return dict(quantity=(*values, (2 * R) ** 2), vanish=GM, body=Body.cylinder(R, 1), up=(0, 0, 1),
                density=density, along=R, bracket=(sp.Rational(1, 100), sp.Rational(201, 100)), steps=40)


d.witness(cyl_root("example-8-values", "(2r/b)^2 of the data, and the (2r/b)^2 of zero metacentric height at s = 3/4",
                   ("ex8-values",), [Case({r: 30, b: 40}, label="the example's data")],
                   **threshold(sp.Rational(3, 4), K2_)))
d.witness(cyl_root("example-9-values", "2r/b, (2r/b)^2 of the data and the threshold (2r/b)^2 at s = 0.8",
                   ("ex9-values",), [Case({r: 15, b: 40}, label="the example's data")],
                   **threshold(sp.Rational(4, 5), 2 * r / b, K2_)))
d.witness(cyl_root("example-9-bound", "(2r/b)^2 at which the tilted equilibrium of the cylinder (s = 0.8) meets "
                   "the upper base", ("ex9-bound",), one, (2 * R) ** 2, ARM_C, body=Body.cylinder(R, 1),
                   density=sp.Rational(4, 5), along=R, bracket=(sp.Rational(1, 5), sp.Rational(7, 10)), steps=5,
                   roots=((PSI, first_tilt(TOP)),), methods=NESTED))
for claim_name, example, r_, s_ in (("example-8-claim", "ex8-claim", 30, sp.Rational(3, 4)),
                                    ("example-9-claim", "ex9-claim", 15, sp.Rational(4, 5))):
    body_ = Body.cylinder(r_, 40)
    d.witness(Joined(claim_name, "signs of the upright metacentric height and of the righting arm where the upper "
                     "base meets the water (positive: no tilted equilibrium before)", (example,), one,
                     parts=(FloatingWitness("upright", "", (), (), body=body_, density=s_, quantity=measured("stability sign")),
                            cyl_root("arm", "", (), (), sp.sign(ARM_C), TOP, body=body_, density=s_))))
