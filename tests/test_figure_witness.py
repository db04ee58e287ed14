"""The plane-figure witness of the witness library against closed forms it must not use.

References (moments of plane figures, any table of second moments of area): the rectangle [x1, x2] x [y1, y2]
has the area (x2 - x1)(y2 - y1), ∫∫ x² = (x2³ - x1³)(y2 - y1)/3, ∫∫ xy = (x2² - x1²)(y2² - y1²)/4; the triangle
(0, 0), (a, 0), (0, h) has the centroid (a/3, h/3) and ∫∫ y² = a h³/12; the ellipse with semi-axes a, b has
the area π a b and ∫∫ x² = π a³ b/4; the quarter disc of radius r has ∫∫ y² dA = π r⁴/16; ∫_0^1 sqrt(1 - t²) dt
= π/4 and ∫_0^1 (1 - t²)^(1/4) dt = Γ(1/2)Γ(5/4)/(2Γ(7/4)).
"""
import mpmath
import pytest
import sympy as sp

from symfloat.engine.figure_witness import CurveRoot, Figure, FigureWitness
from symfloat.engine.floating_witness import Combined
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case

x, y, t = sp.symbols("x y t", real=True)
a, b, h, r = sp.symbols("a b h r", positive=True)
X1, X2, Y1, Y2 = sp.symbols("x_1 x_2 y_1 y_2", real=True)
RECT = Figure.polygon([(X1, Y1), (X2, Y1), (X2, Y2), (X1, Y2)])
RECT_CASE = Case({X1: -1, X2: 2, Y1: sp.Rational(1, 2), Y2: 3})


def _measure(figure, quantity, case):
    w = FigureWitness("w", "", (), (case,), figure=figure, coords=(x, y), quantity=quantity)
    return [(m, w.measure(case, m)) for m in w.methods]


def _close(value, exact, method, scale=1):
    with mpmath.workdps(60):
        return abs(value - mpmath.mpf(sp.N(exact, 60))) <= method.tolerance * max(scale, abs(float(exact)))


@pytest.mark.parametrize("quantity, exact", [
    (measured("integral", of=1), sp.Rational(3 * 5, 2)),
    (measured("integral", of=x ** 2), sp.Rational(8 + 1, 3) * sp.Rational(5, 2)),
    (measured("integral", of=x * y), sp.Rational(4 - 1, 2) * (9 - sp.Rational(1, 4)) / 2),
    (measured("integral", of=(x - measured("centroid, 1")) ** 2),
     3 ** 3 * sp.Rational(5, 2) / 12),                                       # about the centroidal axis
    (measured("centroid, 2"), (sp.Rational(1, 2) + 3) / 2),
])
def test_the_rectangle_off_the_origin(quantity, exact):
    for method, value in _measure(RECT, quantity, RECT_CASE):
        assert _close(value, exact, method), (quantity, method.name, value)


def test_a_clockwise_triangle_is_the_same_figure():
    case = Case({a: 3, h: 2})
    for ring in ([(0, 0), (a, 0), (0, h)], [(0, 0), (0, h), (a, 0)]):
        quantity = (measured("integral", of=y ** 2), measured("centroid, 1"))
        for method, (yy, cx) in _measure(Figure.polygon(ring), quantity, case):
            assert _close(yy, sp.Rational(3 * 8, 12), method) and _close(cx, 1, method)


def test_a_polygon_refuses_an_integrand_of_degree_three():
    with pytest.raises(ValueError, match="degree 2"):
        _measure(RECT, measured("integral", of=x ** 3), RECT_CASE)


def test_the_ellipse_by_its_chords():
    E = Figure.strips(y, x, -a, a, (-b * sp.sqrt(1 - x ** 2 / a ** 2), b * sp.sqrt(1 - x ** 2 / a ** 2)))
    case = Case({a: 3, b: 2})
    for method, (area, kxx) in _measure(E, (measured("integral", of=1), measured("integral", of=x ** 2)), case):
        assert _close(area, 6 * sp.pi, method) and _close(kxx, sp.pi * 27 * 2 / 4, method)
    # mutation: the rectangle's divisor (AB² D/6 instead of /8) is refuted
    assert not _close(kxx, sp.pi * 27 * 2 / 4 * 8 / 6, method)


def test_the_quarter_disc_along_y_with_a_square_root_end():
    Q = Figure.strips(x, y, 0, r, (0, sp.sqrt(r ** 2 - y ** 2)))
    for method, value in _measure(Q, measured("integral", of=y ** 2), Case({r: sp.Rational(3, 2)})):
        assert _close(value, sp.pi * sp.Rational(3, 2) ** 4 / 16, method)


@pytest.mark.parametrize("integrand, smooth, exact", [
    (sp.sqrt(1 - t ** 2), 2, sp.pi / 4),
    (t ** 2 / sp.sqrt(1 - t ** 2), 2, sp.pi / 4),
    ((1 - t ** 2) ** sp.Rational(1, 4), 4,
     sp.gamma(sp.Rational(1, 2)) * sp.gamma(sp.Rational(5, 4)) / (2 * sp.gamma(sp.Rational(7, 4)))),
])
def test_an_interval_with_an_algebraic_end(integrand, smooth, exact):
    for method, value in _measure(Figure.interval(t, 0, 1, smooth=smooth), measured("integral", of=integrand),
                                  Case({})):
        assert _close(value, exact, method), (integrand, method.name)


def test_two_figures_combined():
    rect = FigureWitness("", "", (), (), figure=Figure.polygon([(-a, -b), (a, -b), (a, b), (-a, b)]), coords=(x, y),
                         quantity=measured("integral", of=y ** 2))
    rhomb = FigureWitness("", "", (), (), figure=Figure.polygon([(-a, 0), (0, -b), (a, 0), (0, b)]), coords=(x, y),
                          quantity=measured("integral", of=y ** 2))
    w = Combined("ratio", "", (), (Case({a: 2, b: 1}),), parts=(rect, rhomb),
                 values=(measured("part 1") / measured("part 2"),),
                 methods=FigureWitness.methods)
    for method in w.methods:
        assert _close(w.measure(w.instances[0], method), 4, method)      # 4ab³/3 over ab³/3


def test_a_point_of_an_implicit_curve():
    w = CurveRoot("y", "", (), (Case({a: 2, b: 1, x: sp.Rational(1, 2)}),), equation=x ** 2 / a ** 2 + y ** 2 / b ** 2 - 1,
                  variable=y, bracket=(0, b))
    for method in w.methods:
        assert _close(w.measure(w.instances[0], method), sp.sqrt(15) / 4, method)
