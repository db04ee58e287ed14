"""Euler §§220-228's witnesses: every figure declared by its chords, its areas and moments measured
(:mod:`symfloat.engine.figure_witness`); the integrals of §§225-227 by quadrature of their integrands."""
import sympy as sp

from symfloat.engine.declare import declarer, rational_cases
from symfloat.engine.figure_witness import Figure, FigureWitness
from symfloat.engine.floating_witness import Combined
from symfloat.engine.measured import measured

from .statements import R, Yc, Yg, a, b, c, d, p, q, y

# ================================================================ witnesses: the moments of each figure
# Each figure is declared by its chords, x from the left to the right boundary at the height y (the branches of
# §221, split at x_c = a + Y(b) into Ace and Bce; the whole figure takes y from -b to b with Y(|y|)), and
# measured by the figure witness (symfloat.engine.figure_witness): the chord by the three-point Gauss rule, exact
# for an integrand of degree <= 2 in x, across the chords by quadrature in float64 and at 50 digits.  The
# one-dimensional integrals of §§225-227 are integrals over the segment 0 <= y <= b.  Nothing of the formulas
# under test is used.
XC = measured("centroid, 1")
x_ = sp.Symbol("x", real=True)                    # the abscissa AP of the figures
AREA = measured("integral", of=1)                  # the figure's area
I_XX = measured("integral", of=x_ ** 2)            # its moments about the axes
I_YY = measured("integral", of=y ** 2)


def curve_figure(Y, region, whole=False):
    """The region ('Ace', 'Bce' or 'AEB') of the half y >= 0 of the figure with the function Y (of y >= 0), or
    the whole figure (y from -b to b, Y taken at |y|)."""
    at = {y: sp.Abs(y)} if whole else {}
    left, right, ce = ((a + Y - a * R / b).xreplace(at), (a + Y + a * R / b).xreplace(at), a + Y.subs(y, b))
    ends = {"Ace": (left, ce), "Bce": (ce, right), "AEB": (left, right)}[region]
    return Figure.strips(x_, y, -b if whole else 0, b, ends, breaks=(0,) if whole else ())


figure_witness = declarer(d, FigureWitness, coords=(x_, y))      # the moments of a plane figure


GEN = rational_cases(("a = 2, b = 1, Y = |y|/4 + y²/8", {a: 2, b: 1, p: "1/4", q: "1/8"}),
             ("a = 5/2, b = 3/4, Y = |y|/10 - y²/3", {a: "5/2", b: "3/4", p: "1/10", q: "-1/3"}))
CFIG = rational_cases(("a = 2, b = 1, c = 1/2", {a: 2, b: 1, c: "1/2"}),
              ("a = 5/2, b = 3/4, c = 1", {a: "5/2", b: "3/4", c: 1}))
AB_ONLY = rational_cases(("a = 2, b = 1", {a: 2, b: 1}), ("a = 5/2, b = 3/4", {a: "5/2", b: "3/4"}))

for _region in ("Ace", "Bce", "AEB"):
    figure_witness(f"area-{_region}", f"∫∫ 1 over {_region}", (f"area-{_region}",), GEN, AREA,
                   figure=curve_figure(Yg, _region))
    figure_witness(f"AB-{_region}", f"∫∫ y² over {_region}", (f"AB-{_region}",), GEN, I_YY,
                   figure=curve_figure(Yg, _region))
figure_witness("area-whole", "∫∫ 1 over the whole figure AEBF", ("area-ellipse",), GEN, AREA,
               figure=curve_figure(Yg, "AEB", whole=True))
figure_witness("AB-whole", "∫∫ y² over the whole figure AEBF", ("AB-whole",), GEN, I_YY,
               figure=curve_figure(Yg, "AEB", whole=True))
figure_witness("Aa-Ace", "∫∫ x² over Ace (moment about aAa, x = 0)", ("Aa-Ace-expanded",), GEN, I_XX,
               figure=curve_figure(Yg, "Ace"))
figure_witness("Aa-Bce", "∫∫ x² over Bce", ("Aa-Bce-expanded",), GEN, I_XX, figure=curve_figure(Yg, "Bce"))
figure_witness("Aa-AEB", "∫∫ x² over AEB", ("Aa-AEB", "Aa-AEB-value"), GEN, I_XX, figure=curve_figure(Yg, "AEB"))
figure_witness("Aa-whole", "∫∫ x² over the whole figure", ("Aa-whole",), GEN, I_XX,
               figure=curve_figure(Yg, "AEB", whole=True))
figure_witness("first-moment", "∫∫ x over AEB (D·AC)", ("DAC-definition", "DAC"), GEN, measured("integral", of=x_),
               figure=curve_figure(Yg, "AEB"))
figure_witness("centroid", "x_C of AEB", ("AC",), GEN, XC, figure=curve_figure(Yg, "AEB"))
figure_witness("moment-EF", "∫∫ (x - x_C)² over the whole figure, x_C its centroid", ("moment-EF",), GEN,
               measured("integral", of=(x_ - XC) ** 2), figure=curve_figure(Yg, "AEB", whole=True))
figure_witness("centroid-c", "x_C of AEB, Y = -cy²/b²", ("AC-c",), CFIG, XC, figure=curve_figure(Yc, "AEB"))
figure_witness("moment-EF-c", "∫∫ (x - x_C)² over the whole figure, Y = -cy²/b²", ("moment-EF-c",), CFIG,
               measured("integral", of=(x_ - XC) ** 2), figure=curve_figure(Yc, "AEB", whole=True))
figure_witness("moment-EF-half", "∫∫ (x - x_C)² over the figure with c = a/2", ("moment-EF-half",), AB_ONLY,
               measured("integral", of=(x_ - XC) ** 2), figure=curve_figure(Yc.subs(c, a / 2), "AEB", whole=True))
d.witness(Combined("sixteenth", "(K(c = a/2) - K(c = 0))/K(c = 0), both moments measured", ("sixteenth",), AB_ONLY,
                   parts=tuple(FigureWitness("", "", (), (), figure=curve_figure(Yc.subs(c, cv), "AEB", whole=True),
                                             coords=(x_, y), quantity=measured("integral", of=(x_ - XC) ** 2))
                                for cv in (a / 2, 0)),
                   values=((measured("part 1") - measured("part 2")) / measured("part 2"),)))


def line_witness(name, targets, cases, g, text):
    figure_witness(name, f"∫_0^b {text} dy by quadrature", targets, cases, measured("integral", of=g),
                   figure=Figure.interval(y, 0, b))


line_witness("U0", ("reduce-U0", "U0-value"), AB_ONLY, R, "√(b² - y²)")
line_witness("U2", ("U2-value", "reduce-U2", "U2-value-c"), AB_ONLY, y ** 2 * R, "y²√(b² - y²)")
line_witness("U4", ("U4-value",), AB_ONLY, y ** 4 * R, "y⁴√(b² - y²)")
line_witness("V2", ("reduce-V2",), AB_ONLY, y ** 2 / R, "y²/√(b² - y²)")
line_witness("S2c", ("S2c-expanded", "S2c-value"), CFIG, (a + Yc) ** 2 * R, "(a - cy²/b²)²√(b² - y²)")
line_witness("S1c", ("S1c-value",), CFIG, (a + Yc) * R, "(a - cy²/b²)√(b² - y²)")
