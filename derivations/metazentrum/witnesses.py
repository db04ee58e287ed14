"""The metacentre lesson's witnesses: the box clipped exactly (:mod:`symfloat.engine.floating_witness`)."""
import sympy as sp

from symfloat.engine.floating_witness import (LIMIT_METHODS, Body, Combined, CutWitness, FloatingWitness,
                                              potential_slope)
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case

from .statements import a, b, c, d, dv, rho_w

# ---- witnesses: the box clipped exactly (symfloat.engine.floating_witness) -------------------------------------
# The hull is the box 2a x 2b x 2c (x along the length), upright at the density d/(2c) of the step density-ratio,
# heeled by psi about the long axis (up (0, sin psi, cos psi)); z up from the water surface.
HULL = Body.box(2 * a, 2 * b, 2 * c)
UPRIGHT_UP, psi = (0, 0, 1), sp.Symbol("psi", real=True)
HEEL = (0, sp.sin(psi), sp.cos(psi))
CASES = (Case({a: 4, b: 1, c: 1, d: 1, rho_w: 1}, label="a=4, b=1, c=1, d=1 (half immersed, unstable)"),
         Case({a: 5, b: sp.Rational(3, 2), c: 1, d: sp.Rational(1, 2), rho_w: 1},
              label="a=5, b=3/2, c=1, d=1/2 (stable)"),
         Case({a: 3, b: 2, c: sp.Rational(3, 2), d: sp.Rational(5, 2), rho_w: 1},
              label="a=3, b=2, c=3/2, d=5/2 (stable, deep)"))


def upright(name, description, targets, quantity):
    """A quantity of the clipped box floating upright at the density d/(2c)."""
    return FloatingWitness(name, description, targets, CASES, body=HULL, up=UPRIGHT_UP, density=d / (2 * c),
                           quantity=quantity)


for name, description, targets, quantity in (
        ("stability-sign", "sign of the clipped upright box's metacentric height I_min/V - (G - B)",
         ("criterion", "e-sign"), measured("stability sign")),
        ("metacentre-inertia", "z_M = (I_min/V - (G - B)) + z_G of the clipped upright box", ("z_M",),
         measured("metacentric height") + measured("G above water")),
        ("stability-function", "e = d/(2c^2) (I_min/V - (G - B)) of the clipped box", ("e",),
         d / (2 * c ** 2) * measured("metacentric height")),
        ("centre-of-gravity", "height of G above the water plane, clipped box", ("z_G",), measured("G above water")),
        ("centre-of-buoyancy", "height of B above the water plane, clipped box", ("z_B",), -measured("B below water")),
        ("displaced-volume", "volume of the clipped immersed part", ("V_b",), measured("immersed volume")),
        ("displaced-mass", "rho_w times the clipped immersed volume", ("M_b", "M_s", "M_b=M_s"),
         rho_w * measured("immersed volume")),
        ("section-area", "clipped immersed volume over the length 2a", ("section",),
         measured("immersed volume") / (2 * a))):
    dv.witness(upright(name, description, targets, quantity))
# the righting arm over the heel, extrapolated to psi -> 0, and a height of the upright box
ARM = FloatingWitness("", "", (), (), body=HULL, up=HEEL, density=d / (2 * c), quantity=potential_slope(HEEL, psi),
                      limit=(psi, 1), methods=LIMIT_METHODS)
dv.witness(Combined("metacentre-heel", "z_M = lim m/phi + z_G: righting arm of the clipped heeled box, extrapolated",
                    ("z_M",), CASES, parts=(ARM, upright("", "", (), measured("G above water"))),
                    values=(measured("part 1") + measured("part 2"),)))
dv.witness(Combined("radius-heel", "BM = lim m/phi + (z_G - z_B) from the clipped heeled box", ("radius",), CASES,
                    parts=(ARM, upright("", "", (), measured("G above B"))), values=(measured("part 1") + measured("part 2"),)))
# the density at which the box floats with draught d: the share of its volume below the plane d above its bottom
dv.witness(CutWitness("density-ratio", "clipped volume below depth d over the box volume", ("density",), CASES,
                      body=HULL, up=UPRIGHT_UP, through=(0, 0, d - c),
                      quantity=measured("immersed volume") / (2 * a * 2 * b * 2 * c)))
