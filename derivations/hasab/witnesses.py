"""The Hasáb solution's witnesses: the prism clipped exactly (:mod:`symfloat.engine.floating_witness`)."""
import sympy as sp

from symfloat.engine.floating_witness import (QUANTITIES, Body, Combined, FloatingRootWitness,
                                              FloatingWitness, Marked, Root, SeriesWitness, crossing)
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case

from .statements import R1, R2, Ru, al, d, g, half, l, rho

# ---- witnesses: the prism clipped exactly (symfloat.engine.floating_witness) -----------------------------------
# The prism is the box 1 x 1 x l, the y axis of the box up when it lies on a face (eta = y + 1/2); heeled with
# tg alpha the side xi = +1/2 dips.  Marked with its upright up, its immersed part splits at the lower end of the
# water line (the side xi = -1/2) into the rectangle ABG1I and the triangle IG1H1.  Energies: weight times the height
# of the centre of gravity above the water, or weight of a part of the displaced water times its depth (its moment).
LYING = Body.box(1, 1, l)
HEELED = Marked.of(LYING, (0, 1, 0))
UPRIGHT_UP, UP = (0, 1, 0), (-sp.tan(al), 1, 0)
PRISM = g * l * rho * measured("G above water")               # the prism's weight l g rho times the height of G
WATER = g * measured("immersed volume") * measured("B below water")  # the displaced water's weight times the depth of B
SIDE_X = crossing(UP, (half, -half, 0), (0, 1, 0))     # the water line on the dipping side, above the bottom
SIDE_Y = crossing(UP, (-half, -half, 0), (0, 1, 0))    # on the rising side
ECASES = tuple(Case({rho: r, l: 4, g: sp.Rational(981, 100), al: sp.atan(q)},
                    label=f"rho = {r}, l = 4, g = 9.81, tg alpha = {q}")
               for r, q in ((sp.Rational(1, 2), sp.Rational(1, 5)), (sp.Rational(1, 10), sp.Rational(1, 10)),
                            (sp.Rational(17, 20), sp.Rational(1, 4))))
UPRIGHT = tuple(Case({rho: r, l: 4, g: sp.Rational(981, 100)}, label=f"rho = {r}, l = 4, g = 9.81, upright")
                for r in (sp.Rational(1, 2), sp.Rational(1, 10), sp.Rational(17, 20)))
for name, description, targets, cases, up, quantity in (
        ("prism-energy-upright", "prism weight times the height of G above the water, clipped prism", ("E0-prism",),
         UPRIGHT, UPRIGHT_UP, PRISM),
        ("prism-energy", "prism weight times the height of G above the water, clipped heeled prism", ("E1-prism",),
         ECASES, UP, PRISM),
        ("water-energy", "displaced water's weight times the depth of the clipped immersed part's centroid",
         ("E0-water",), UPRIGHT, UPRIGHT_UP, WATER),
        ("water-rectangle", "g times the moment of the clipped immersed part below the lower end of the water line",
         ("E1-water",), ECASES, UP, g * measured("lower part moment")),
        ("water-triangle", "g times the moment of the clipped immersed part above the lower end of the water line",
         ("E2-water",), ECASES, UP, g * measured("upper part moment")),
        ("total-energy", "prism and water energies of the clipped upright prism", ("E0-total",), UPRIGHT, UPRIGHT_UP,
         PRISM + WATER),
        ("side-x", "immersed length of the dipping side, clipped plane", ("x",), ECASES, UP, SIDE_X),
        ("side-y", "immersed length of the rising side, clipped plane", ("y",), ECASES, UP, SIDE_Y),
        ("sides-mean", "mean immersed side length, clipped plane", ("x+y",), ECASES, UP, (SIDE_X + SIDE_Y) / 2),
        ("sides-difference", "difference of the immersed side lengths, clipped plane", ("x-y",), ECASES, UP,
         SIDE_X - SIDE_Y)):
    d.witness(FloatingWitness(name, description, targets, cases, body=HEELED, up=up, density=rho, quantity=quantity))
DENSITIES = tuple(Case({rho: r, l: 4}, label=f"rho = {r}, l = 4")          # none at a threshold
                  for r in (sp.Rational(1, 2), sp.Rational(1, 10), sp.Rational(17, 20)))
for lying_name, lying_targets, named in (("draught", ("s",), "draught"), ("G-above-water", ("OF",), "G above water"),
                                        ("stability-sign", ("condition",), "stability sign"),
                                        ("stable-upright", ("ranges",), "stable")):
    d.witness(FloatingWitness(lying_name, f"{QUANTITIES[named][0]}, clipped prism lying", lying_targets, DENSITIES,
                              body=LYING, up=UPRIGHT_UP, density=rho, quantity=measured(named)))
d.witness(FloatingWitness("G-height-heeled", "height of G above the heeled water plane, clipped prism",
                          ("G-height",), ECASES, body=LYING, up=UP, density=rho, quantity=measured("G above water")))
d.witness(FloatingWitness("stability-sign-energy", "sign of the clipped lying prism's metacentric height",
                          ("energy-principle",), DENSITIES, body=LYING, up=UPRIGHT_UP, density=rho,
                          quantity=measured("stability sign")))

# the energy per l g is rho times the height of G above B (weight times it, Scheeffer's V1 n): its value upright and
# its coefficient of psi^2 interpolated at small heels psi
psi = sp.Symbol("psi", real=True)
ENERGY = rho * measured("G above B")
C0 = FloatingWitness("", "", (), (), body=LYING, up=UPRIGHT_UP, density=rho, quantity=ENERGY)
C2 = SeriesWitness("", "", (), (), body=LYING, up=(-sp.sin(psi), sp.cos(psi), 0), density=rho, quantity=ENERGY,
                   series=(psi, 2))
d.witness(Combined("second-order-energy", "c0 + c2 alpha^2: the clipped prism's energy upright and its alpha^2 "
                   "coefficient interpolated at small heels", ("E1-total",), ECASES, parts=(C0, C2),
                   values=(measured("part 1") + measured("part 2") * al ** 2,)))
d.witness(Combined("energy-change", "c2 alpha^2: the alpha^2 coefficient of the clipped prism's energy, interpolated "
                   "at small heels", ("Delta-E",), ECASES, parts=(C2,), values=(measured("part 1") * al ** 2,)))

# the density thresholds: zeros in rho of the clipped metacentric height, lying (heel about the long axis) and
# standing upright (the remark)
def gm_zero(lo, hi, which):
    """The first or last zero in rho of the clipped metacentric height, scanned from lo to hi in 18 steps."""
    return Root.scan(measured("metacentric height"), rho, lo, hi, 18, which=which)


d.witness(FloatingRootWitness("thresholds-lying", "zeros of the clipped metacentric height of the lying prism in rho",
                              ("thresholds",), (Case({l: 4}, label="lying prism 1 x 1 x 4"),), body=LYING,
                              up=UPRIGHT_UP, density=rho, quantity=(R1, R2),
                              roots=((R1, gm_zero(sp.Rational(1, 20), sp.Rational(19, 20), "first")),
                                     (R2, gm_zero(sp.Rational(1, 20), sp.Rational(19, 20), "last")))))
d.witness(FloatingRootWitness("threshold-upright", "upper zero of the clipped metacentric height of the upright prism",
                              ("remark", "remark-position"), (Case({l: 2}, label="upright prism, l = 2"),
                                                              Case({l: 5}, label="upright prism, l = 5")),
                              body=LYING, up=(0, 0, 1), density=rho, quantity=Ru,
                              roots=((Ru, gm_zero(sp.Rational(1, 2), sp.Rational(999, 1000), "last")),)))
