"""Euler §§229-243's witnesses: the figures of the family measured by their chords, the tables over a grid of n and
kappa, the solids of §243 by exact hulls, the stabilities by heeling and pitching clipped prisms."""
from fractions import Fraction

import sympy as sp

from symfloat.engine.declare import declarer, part_of
from symfloat.engine.figure_witness import Figure, FigureWitness
from symfloat.engine.floating_witness import (LIMIT_METHODS, Body, Combined, FloatingWitness, Joined, Loaded,
                                              potential_slope)
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case, HullWitness
from symfloat.geometry.floating import polygon_moments

from .statements import (AB, CASES236, CD, Dw, EF, KAPPAS, M, OG, V, _label, a, al, b, c, c1, c2, d, k, k1, mu, n, n1,
                        nu, xk, y)

# ================================================================ witnesses: the moments of the figures
# Each figure is declared by its chords and measured by the figure witness (symfloat.engine.figure_witness): the
# half AEB of the family by its chords a + Y ± a(1 − yⁿ/bⁿ)^κ at the height y (three-point Gauss across, exact
# for the quadratic integrand; along y tanh-sinh at 50 digits and, in float64, Gauss–Legendre after the
# substitution of order 4, which makes (1 − yⁿ/bⁿ)^κ smooth at y = b for κ a multiple of 1/4); the whole
# figure is twice the half (AFB mirrors AEB); the rectangle and the rhombus of §237 by exact polygon integrals,
# the parabola by its chords across AB; N by quadrature of its two integrals.  Nothing of the formulas under test
# is used.
XP = sp.Symbol("x_P", real=True)                   # the abscissa AP of the figures
XC = measured("centroid, 1")
AREA = measured("integral", of=1)                  # the figure's area
I_YY = measured("integral", of=y ** 2)             # its moment about AB


def family(Y, N_=n, K_=k):
    """The half AEB of the figure of §229 with the function Y (of y) and the exponents n, κ."""
    R_ = (1 - (y / b) ** N_) ** K_
    return Figure.strips(XP, y, 0, b, (a + Y - a * R_, a + Y + a * R_), smooth=4)


figure_witness = declarer(d, FigureWitness, coords=(XP, y))      # the moments of a plane figure


part = part_of(FigureWitness, coords=(XP, y))


Y_GENERIC = c1 * (y / b) ** n + c2 * (y / b) ** (2 * n)
Y_C = -c * (y / b) ** n
K_WHOLE = 2 * measured("integral", of=(XP - XC) ** 2)    # the moment of the whole figure about EF through C
GENERIC = (Case({a: 1, b: 1, n: 2, k: sp.Rational(1, 2), c1: sp.Rational(-1, 4), c2: sp.Rational(1, 8),
                 al: sp.Rational(3, 2), xk: 2}, label="n = 2, κ = 1/2, Y = −y²/4 + y⁴/8, a = b = 1"),
           Case({a: sp.Rational(3, 2), b: sp.Rational(1, 2), n: 3, k: sp.Rational(3, 2), c1: sp.Rational(1, 3),
                 c2: sp.Rational(-1, 5), al: 2, xk: sp.Rational(1, 2)},
                label="n = 3, κ = 3/2, Y = y³/3·8 − y⁶·64/5, a = 3/2, b = 1/2"))
figure_witness("family-area", "the half area ∫∫1 over AEB", ("area",), GENERIC, AREA, figure=family(Y_GENERIC))
figure_witness("family-area-integral", "∫∫1 over AEB divided by 2a", ("area-integral",), GENERIC, AREA / (2 * a),
               figure=family(Y_GENERIC))
figure_witness("family-moment-AB", "∫∫y² over AEB", ("moment-AB",), GENERIC, I_YY, figure=family(Y_GENERIC))
figure_witness("family-moment-O", "∫∫(x − a)² over AEB", ("moment-O",), GENERIC, measured("integral", of=(XP - a) ** 2),
               figure=family(Y_GENERIC))
figure_witness("family-moment-O-whole", "∫∫(x − a)² over the whole figure (both halves)", ("moment-O-whole",), GENERIC,
               2 * measured("integral", of=(XP - a) ** 2), figure=family(Y_GENERIC))
figure_witness("family-centroid-moment", "D·CO = −∫∫(x − a) over AEB", ("centroid-moment",), GENERIC,
               -measured("integral", of=XP - a), figure=family(Y_GENERIC))
figure_witness("family-CO", "CO = a − x_C, x_C the centroid of AEB", ("CO",), GENERIC, a - XC, figure=family(Y_GENERIC))
figure_witness("family-moment-EF", "∫∫(x − x_C)² over the whole figure, x_C its centroid", ("moment-EF",), GENERIC,
               K_WHOLE, figure=family(Y_GENERIC))

CFAM = (Case({a: 1, b: 1, n: 2, k: sp.Rational(1, 2), c: sp.Rational(1, 4), al: sp.Rational(3, 2)},
             label="n = 2, κ = 1/2, c = 1/4, a = b = 1"),
        Case({a: sp.Rational(3, 2), b: sp.Rational(1, 2), n: 3, k: sp.Rational(3, 2), c: sp.Rational(1, 3), al: 2},
             label="n = 3, κ = 3/2, c = 1/3, a = 3/2, b = 1/2"))
figure_witness("c-first", "∫Y R dy = −D·CO/(2a) from ∫∫(x − a) over AEB (Y = −cyⁿ/bⁿ)", ("Y-c-first",), CFAM,
               measured("integral", of=XP - a) / (2 * a), figure=family(Y_C))
d.witness(Combined("c-second", "∫Y²R dy = (∫∫(x − a)² at c minus at c = 0)/(2a) over AEB", ("Y-c-second",), CFAM,
                   parts=(part(figure=family(Y_C), quantity=measured("integral", of=(XP - a) ** 2)),
                          part(figure=family(0), quantity=measured("integral", of=(XP - a) ** 2))),
                   values=((measured("part 1") - measured("part 2")) / (2 * a),)))
figure_witness("c-moment-EF", "∫∫(x − x_C)² over the whole figure with Y = −cyⁿ/bⁿ",
               ("moment-EF-c", "moment-EF-c-p118", "moment-EF-N"), CFAM, K_WHOLE, figure=family(Y_C))
d.witness(Combined("c-excess", "K at c minus K at c = 0, both measured", ("unequal-halves",), CFAM,
                   parts=(part(figure=family(Y_C), quantity=K_WHOLE), part(figure=family(0), quantity=K_WHOLE)),
                   values=(measured("part 1") - measured("part 2"),)))

u = sp.Symbol("u", positive=True)
for kv in KAPPAS:
    grid = tuple(Case({n: nv, a: 1, b: sp.Rational(3, 4)}, label="κ = %s, n = %s, a = 1, b = 3/4" % (kv, nv))
                 for nv in (1, 2, 3))
    figure_witness("K-table-%s" % _label(kv), "∫∫(x − x_C)² over the figure κ = %s, c = 0" % kv,
                   ("K-table-%s" % _label(kv),), grid, K_WHOLE, figure=family(0, K_=kv))
    figure_witness("N-table-%s" % _label(kv), "N for κ = %s by quadrature of its two integrals" % kv,
                   ("N-table-%s" % _label(kv),), grid,
                   measured("integral", of=(1 - u ** n) ** (3 * kv - 1)) / measured("integral", of=(1 - u ** n) ** kv),
                   figure=Figure.interval(u, 0, 1, smooth=4))

AB1 = (Case({a: 1, b: sp.Rational(3, 4)}, label="a = 1, b = 3/4"), Case({a: 2, b: 1}, label="a = 2, b = 1"))
for case_name, case_kv, case_nv, *_ in CASES236:
    figure_witness("case-" + case_name, "∫∫(x − x_C)² over the figure κ = %s, n = %s" % (case_kv, case_nv),
                   ("case-" + case_name,), AB1, K_WHOLE, figure=family(0, case_nv, case_kv))

# μ about AB and about EF, EF²D/I and AB²D/K (2D the area, EF = 2b, AB = 2a), for figures symmetric about both axes
MU_OF_FIGURE = ((2 * b) ** 2 * AREA / 2 / I_YY, (2 * a) ** 2 * AREA / 2 / measured("integral", of=XP ** 2))
MU_OF_HALF = ((2 * b) ** 2 * AREA / (2 * I_YY), (2 * a) ** 2 * AREA / K_WHOLE)   # from the half AEB
MU = (Case({a: 2, b: 1}, label="a = 2, b = 1"), Case({a: 3, b: sp.Rational(1, 2)}, label="a = 3, b = 1/2"))
PARABOLA = Figure.strips(y, XP, -a, a, (-b * (1 - XP ** 2 / a ** 2), b * (1 - XP ** 2 / a ** 2)))
figure_witness("mu-rectangle", "μ of the rectangle from its moments", ("mu-rectangle",), MU, MU_OF_FIGURE,
               figure=Figure.polygon([(-a, -b), (a, -b), (a, b), (-a, b)]))
figure_witness("mu-rhombus", "μ of the rhombus from its moments", ("mu-rhombus",), MU, MU_OF_FIGURE,
               figure=Figure.polygon([(-a, 0), (0, -b), (a, 0), (0, b)]))
figure_witness("mu-parabola-AB", "μ about AB of the parabola y = b(1 − x²/a²)", ("mu-parabola-AB",), MU,
               MU_OF_FIGURE[0], figure=PARABOLA)
figure_witness("mu-parabola-EF", "μ about EF of the parabola y = b(1 − x²/a²)", ("mu-parabola-EF",), MU,
               MU_OF_FIGURE[1], figure=PARABOLA)
figure_witness("mu-ellipse", "μ of the ellipse (the member n = 2, κ = 1/2) from its moments", ("mu-ellipse",), MU,
               MU_OF_HALF, figure=family(0, 2, sp.Rational(1, 2)))
MU_ADM = tuple(Case({a: 1, b: 1, n1: nv, k1: kv}, label="n = %s, κ = %s" % (nv, kv))
               for nv, kv in ((1, sp.Rational(1, 4)), (1, 1), (2, sp.Rational(1, 4)), (3, sp.Rational(1, 2)),
                              (4, sp.Rational(3, 4))))
figure_witness("mu-bounds", "μ about AB and EF of admissible members of the family from their moments", ("mu-bounds",),
               MU_ADM, MU_OF_HALF, figure=family(0, n1, k1))


# ---------------------------------------------------------------- §243: the three solids, exact hulls
def _hull_case(kind, A, B, H):
    """The waterplane rectangle 2A x 2B at z = 0 with the pyramid's apex, the prism's bottom or the wedge's keel
    (under the whole length AB) at the depth H, as exact rational points."""
    A, B, H = (Fraction(v) for v in (A, B, H))
    if kind == "pyramid":
        pts, Dv = [(-A, -B, 0), (A, -B, 0), (A, B, 0), (-A, B, 0), (0, 0, -H)], 2 * A * B
    elif kind == "prism":
        pts, Dv = [(u, v, z) for u in (-A, A) for v in (-B, B) for z in (0, -H)], 2 * A * B
    else:
        pts, Dv = [(u, v, 0) for u in (-A, A) for v in (-B, B)] + [(-A, 0, -H), (A, 0, -H)], 2 * A * B
    pts = [tuple(Fraction(v) for v in pt) for pt in pts]
    return Case({Dw: sp.Rational(Dv.numerator, Dv.denominator), CD: sp.Rational(H.numerator, H.denominator)},
                pts, "%s, half-axes %s, %s, CD = %s" % (kind, A, B, H))


for kind, target in (("pyramid", "V-pyramid"), ("prism", "V-prism"), ("wedge", "V-wedge")):
    d.witness(HullWitness("volume-" + kind, "volume of the %s over the waterplane (exact hull and slices)" % kind,
                          (target,), (_hull_case(kind, 2, Fraction(1, 2), Fraction(3, 2)),
                                      _hull_case(kind, 3, 1, 1)), quantity="volume"))


# ---------------------------------------------------------------- §239/§243: a heeled V-shaped prism
# The right prism over the triangle (0, 0), (W, T), (−W, T), apex down, length L along z, floats at the
# density ratio s; its submerged part is the similar triangle of depth CD = T√s: the waterplane is the
# rectangle EF × L (μ = 6), V = D·CD exactly.  G is put at the height OG above (or below) the upright centre
# of buoyancy O, two thirds of CD above the apex.  The stability per unit angle is M·GZ(φ)/φ for φ → 0, GZ the
# righting arm of the exactly clipped heeled prism, extrapolated (LIMIT_METHODS).  Nothing of M(EF²D/(μV) ∓ OG)
# is used.  ν = 8 is given to the cases only so that §241's print with ν in place of μ becomes a number (the
# prism's latitudinal μ is not needed).
phi = sp.Symbol("phi", positive=True)              # the heel of the witnesses' prisms
Wv, Tv, Lv, sv = sp.symbols("W_v T_v L_v s_v", positive=True)   # the V prism's half-width, height, length, density
HEEL = (sp.sin(phi), sp.cos(phi), 0)               # y up, heeled in the plane of x and y
TILT = (sp.sin(phi), 0, sp.cos(phi))               # z up, heeled in the plane of x and z


def heeled_stability(body, up, sign):
    """M·lim GZ/φ of *body* (G ``sign``·OG above O) heeled from the position ``up`` at φ = 0, by clipping."""
    return FloatingWitness("", "", (), (), body=body(sign * OG), up=up, density=sv, quantity=M * potential_slope(up, phi),
                           limit=(phi, 1), methods=LIMIT_METHODS)


def v_prism(og):
    return Loaded.of(Body.prism([(0, 0), (Wv, Tv), (-Wv, Tv)], Lv), (0, 2 * CD / 3 + og, 0))


def _v_case(W, T, L, s, og):
    W, T, L, s = (sp.Rational(v) for v in (W, T, L, s))
    depth = T * sp.sqrt(s)
    half = W * depth / T
    Dv, Vv = half * L, half * L * depth
    return Case({M: Vv, V: Vv, EF: 2 * half, Dw: Dv, CD: depth, mu: 6, nu: 8, OG: sp.Rational(og),
                 Wv: W, Tv: T, Lv: L, sv: s}, label="V-prism W = %s, T = %s, L = %s, s = %s, OG = %s" % (W, T, L, s, og))


V_CASES = (_v_case(1, 2, 3, "1/4", "1/10"), _v_case(1, 2, 2, "9/16", "1/20"))
d.witness(Joined("stability-V-prism", "M·GZ/φ of the heeled V-prism by exact clipping, G above O",
                 ("stability-AB", "stability-CD", "stability-AB-241"), V_CASES,
                 parts=(heeled_stability(v_prism, HEEL, 1),)))
d.witness(Joined("stability-V-prism-G-below", "M·GZ/φ of the heeled V-prism by exact clipping, G below O",
                 ("stability-G-below",), V_CASES, parts=(heeled_stability(v_prism, HEEL, -1),)))


# §239 about EF: an upright right prism over the quadrilateral of §215 (A = (0, 0), e = (1, 1), B = (3, 0),
# f = (1, −1); axis vertical, height 2) at s = 1/2: the waterplane has μ = 12 about AB and
# ν = AB²D/K = 9(a + c)²/(a² + ac + c²) = 81/7 about EF (§216, §218), so μ and ν differ; pitched about EF.  G lies
# above the kite's centroid (its polygon moments), OG above O, which is half the immersed height 1 below the water.
KITE = [(0, 0), (1, -1), (3, 0), (1, 1)]
KITE_CX = sp.Rational(polygon_moments(KITE)[1][0])


def kite_prism(og):
    return Loaded.of(Body.prism(KITE, 2), (KITE_CX, 0, og - sp.Rational(1, 2)))


KITE_CASES = tuple(Case({M: 3, V: 3, AB: 3, Dw: sp.Rational(3, 2), mu: 12, nu: sp.Rational(81, 7), OG: og,
                         sv: sp.Rational(1, 2)}, label=f"kite prism, s = 1/2, OG = {og}")
                   for og in (sp.Rational(1, 10), sp.Rational(1, 4)))
d.witness(Joined("stability-kite-prism-EF", "M·GZ/φ of the upright kite prism pitched about EF, by exact clipping, "
                 "G above O", ("stability-EF",), KITE_CASES, parts=(heeled_stability(kite_prism, TILT, 1),)))

# second pass: the moment named 'about the longitudinal axis EF' of §230 is the one about the latitudinal EF
figure_witness("family-axis-EF-named", "∫∫(x − x_C)² over the whole figure, x_C its centroid", ("axis-EF-named",),
               GENERIC, K_WHOLE, figure=family(Y_GENERIC))
figure_witness("by-parts-quadrature", "∫yⁿ(1 − yⁿ/bⁿ)^{3κ−1}dy/bⁿ by 1-D quadrature", ("by-parts-3k",),
               tuple(Case({b: sp.Rational(bv), n: nv, k: sp.Rational(kv)}, label=f"b = {bv}, n = {nv}, κ = {kv}")
                     for bv, nv, kv in (("1", 2, "1/2"), ("3/4", 3, "3/2"), ("2", 1, "1"))),
               measured("integral", of=y ** n * (1 - (y / b) ** n) ** (3 * k - 1)) / b ** n,
               figure=Figure.interval(y, 0, b, smooth=4))
figure_witness("c-zero-suffices-quadrature", "∫∫(x − x_C)² over the whole figure with Y = −cyⁿ/bⁿ",
               ("c-zero-suffices",), CFAM, K_WHOLE, figure=family(Y_C))
