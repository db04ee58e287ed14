"""Convergence orders measured and compared with theory.

* Composite Simpson (error ~ h^4, exact for cubics) and trapezoid (~ h^2, exact
  for linear functions) applied to the section-area integrand of every
  quadrature witness of the registry, at 40 digits so that rounding does not
  hide the truncation error; the order is the least-squares slope of
  log(error) against log(h).  A square-root zero of the integrand at an end
  of the interval (a sphere or ellipsoid chord) lowers both orders to 3/2.
* Gauss–Legendre with n nodes: the highest degree of monomial it integrates
  exactly on [0, 1] (theory: 2n - 1).
* Kinks: the section area of a heeled cube is piecewise quadratic in the
  height.  Heeled about an axis parallel to an edge (the long prism of the
  sources) an edge passes the water plane and A'(z) jumps: Simpson over the
  whole draught falls to order 2.  Heeled about a general axis single
  vertices pass the plane and only A''(z) jumps (the section grows by a small
  similar triangle): Simpson falls to order 3.  Splitting at the vertex
  heights (the remedy) makes Simpson with two panels per piece exact, and
  fixed-order Gauss–Legendre exact to rounding.
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from ..engine.quadrature import composite_simpson, composite_trapezoid
from ..engine.witness import ConvergenceOrder, PlaneSections, SectionIntegral
from ..geometry.convex import hull_volume_centroid, section_area, section_polygon
from ..model.symbol_names import latex
from ..registry import load, select

__all__ = ["OrderRow", "fit_order", "registry_orders", "convergence_witnesses", "gauss_legendre_degrees",
           "Kink", "kink_study", "PANELS", "HEELS", "KINK_PANELS"]

PANELS = (4, 8, 16, 32, 64, 128)
KINK_PANELS = (4, 8, 16, 32, 64, 128, 256, 512)
HEELS = {"heeled about an edge direction (A' jumps)": (2, 1, 0, 0),
         "heeled about a general axis (A'' jumps)": (5, 1, 2, 3)}
DPS = 40
EXACT_BELOW = mpmath.mpf(10) ** -(DPS - 5)


def fit_order(panels, errors) -> float | None:
    """Least-squares slope of log(error) against log(1/panels) over the errors
    above the rounding floor; ``None`` (exact) when fewer than three remain."""
    pts = [(mpmath.log(mpmath.mpf(1) / n), mpmath.log(e)) for n, e in zip(panels, errors) if e > EXACT_BELOW]
    if len(pts) < 3:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    return float(sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts))


@dataclass
class OrderRow:
    """Measured orders of Simpson and trapezoid on one witness's integrand."""

    derivation: str
    witness: str
    integrand: str                # TeX
    simpson: float | None
    trapezoid: float | None
    theory: str
    simpson_errors: list
    trapezoid_errors: list
    measures: str = ""            # what the witness measures, in words


def _theory(expr, var, lo, hi):
    if expr.is_polynomial(var):
        deg = sp.degree(expr, var)
        return (f"polynomial of degree {deg}: Simpson exact" + ("" if deg <= 3 else " only up to degree 3")
                + (", trapezoid exact" if deg <= 1 else ", trapezoid $h^2$"))
    period = sp.periodicity(expr, var)
    if period and ((hi - lo) / period).is_integer:
        return "periodic over whole periods: both rules converge geometrically"
    roots = any(p.exp == sp.Rational(1, 2) for p in expr.atoms(sp.Pow))
    ends = [sp.simplify(expr.subs(var, v)) for v in (lo, hi)]
    if roots and any(e == 0 for e in ends):
        return "square-root zero at an end: $h^{1.5}$ for both rules"
    return "smooth: Simpson $h^4$, trapezoid $h^2$"


def _integrand(w, case):
    """(expression, variable, lo, hi) of the first integral a witness evaluates."""
    if isinstance(w, SectionIntegral):
        area, bounds = w.parts[0]
        lo, hi = (sp.sympify(b).xreplace(case.params) for b in bounds)
        return area.xreplace(case.params), w.z, lo, hi
    at = {**case.params, w.position: sp.sympify(w.planes[0]).xreplace(case.params)}
    lo, hi = (sp.sympify(e).xreplace(at) for e in w.chord)
    return w.width.xreplace(at), w.across, lo, hi


def _order_row(did, name, expr, var, lo, hi, panels, measures=""):
    with mpmath.workdps(DPS):
        f = sp.lambdify(var, expr, "mpmath")
        a, b = (mpmath.mpf(sp.N(v, DPS + 10)) for v in (lo, hi))
        exact = mpmath.quad(f, [a, b], method="tanh-sinh")
        errs = {rule: [abs(rule(f, a, b, n) - exact) / abs(exact) for n in panels]
                for rule in (composite_simpson, composite_trapezoid)}
    return OrderRow(did, name, latex(expr), fit_order(panels, errs[composite_simpson]),
                    fit_order(panels, errs[composite_trapezoid]), _theory(expr, var, lo, hi),
                    [float(e) for e in errs[composite_simpson]], [float(e) for e in errs[composite_trapezoid]],
                    measures or name)


def registry_orders(selector=None, panels=PANELS) -> list[OrderRow]:
    """Measured Simpson and trapezoid orders on every quadrature witness's integrand (first case), and on
    two references: exp on [0, 1] (smooth) and the chord width of a circle (a square-root zero at both ends)."""
    rows = []
    for did in select(selector):
        d, _ = load(did)
        for w in d.witnesses:
            if isinstance(w, (SectionIntegral, PlaneSections)):
                rows.append(_order_row(d.id, w.name, *_integrand(w, w.instances[0]), panels, w.description))
    y = sp.Symbol("y")
    rows.append(_order_row("(reference)", "exponential", sp.exp(y), y, 0, 1, panels))
    rows.append(_order_row("(reference)", "circle chord", 2 * sp.sqrt(1 - y ** 2), y, -1, 1, panels))
    return rows


def convergence_witnesses(selector=None) -> list[tuple]:
    """(derivation, witness, description, expected order, measured order, measured trapezoid order on the
    same integrand) of the registry's ConvergenceOrder witnesses."""
    out = []
    for did in select(selector):
        d, _ = load(did)
        for w in d.witnesses:
            if isinstance(w, ConvergenceOrder):
                outcome = next(iter(w.run({t: None for t in w.targets}).values()))
                with mpmath.workdps(w.dps):
                    errs = [abs(composite_trapezoid(w.integrand, *w.interval, n) - w.exact) for n in w.panels]
                    trap = fit_order(w.panels, errs)
                out.append((d.id, w.name, w.description, w.order, outcome.records[0]["order"], trap))
    return out


def _leggauss(n):
    """Nodes and weights of n-point Gauss–Legendre at the working precision (Newton from float64)."""
    x0, _ = np.polynomial.legendre.leggauss(n)
    nodes, weights = [], []
    for t in x0:
        t = mpmath.mpf(float(t))
        for _ in range(8):
            p, q = mpmath.legendre(n, t), mpmath.legendre(n - 1, t)
            dp = n * (t * p - q) / (t * t - 1)
            t -= p / dp
        p, q = mpmath.legendre(n, t), mpmath.legendre(n - 1, t)
        dp = n * (t * p - q) / (t * t - 1)
        nodes.append(t)
        weights.append(2 / ((1 - t * t) * dp * dp))
    return nodes, weights


def gauss_legendre_degrees(orders=range(1, 11)) -> list[tuple[int, int]]:
    """(n, highest degree k such that n-node Gauss–Legendre integrates x^k on [0, 1] exactly at 50 digits)."""
    out = []
    with mpmath.workdps(50):
        for n in orders:
            x, w = _leggauss(n)
            k = 0
            while abs(sum(wi * ((xi + 1) / 2) ** (k + 1) for xi, wi in zip(x, w)) / 2
                      - mpmath.mpf(1) / (k + 2)) < mpmath.mpf(10) ** -40:
                k += 1
            out.append((n, k))     # x^0 .. x^k are integrated exactly
    return out


@dataclass
class Kink:
    """The kink study: a heeled unit cube, its displacement below ``draught``
    by quadrature of the section area A(z) from the lowest vertex."""

    heel: str
    vertices: list
    draught: Fraction
    exact: Fraction
    kinks: list
    panels: tuple
    simpson: list        # relative errors, whole interval
    trapezoid: list
    simpson_split: list  # Simpson, the same panels spread over the pieces between kinks
    gauss: list          # (n, error whole interval, error split), float64
    simpson_order: float | None
    trapezoid_order: float | None


def _heeled_cube(q):
    """The unit cube turned by the rational rotation of the quaternion *q* (any length)."""
    q0, q1, q2, q3 = q
    n = q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3
    R = [[q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3, 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
         [2 * (q1 * q2 + q0 * q3), q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3, 2 * (q2 * q3 - q0 * q1)],
         [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3]]
    cube = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    return [tuple(Fraction(sum(R[i][j] * p[j] for j in range(3)), n) for i in range(3)) for p in cube]


def _split_simpson(f, cuts, panels):
    """Simpson with about *panels* panels spread over the pieces (at least two each, even)."""
    total = cuts[-1] - cuts[0]
    return sum(composite_simpson(f, a, b, max(2, 2 * round(panels * (b - a) / total / 2)))
               for a, b in zip(cuts, cuts[1:]))


def _gauss64(f, cuts, n):
    x, w = np.polynomial.legendre.leggauss(n)
    total = 0.0
    for a, b in zip(cuts, cuts[1:]):
        a, b = float(a), float(b)
        total += (b - a) / 2 * sum(wi * float(f(Fraction((b + a) / 2 + (b - a) / 2 * xi))) for xi, wi in zip(x, w))
    return total


def kink_study(heel, panels=KINK_PANELS, gauss=(2, 3, 4, 8, 16)) -> Kink:
    """Simpson, trapezoid and Gauss–Legendre across the kinks and split at them (exact rational arithmetic
    for the Newton–Cotes rules, so the errors are pure truncation); *heel* is a key of ``HEELS``."""
    pts = _heeled_cube(HEELS[heel])
    heights = sorted({p[2] for p in pts})
    draught = heights[0] + (heights[1] - heights[0]) * Fraction(3, 2)   # first kink at 2/3 of the draught
    below = [p for p in pts if p[2] <= draught] + [(x, y, draught) for x, y in section_polygon(pts, 2, draught)]
    exact = hull_volume_centroid(below)[0]

    def area(z):
        return section_area(pts, 2, z)
    cuts = [heights[0]] + [h for h in heights if heights[0] < h < draught] + [draught]
    whole = [heights[0], draught]

    def rel(v):
        return abs(Fraction(v) - exact) / exact
    simpson = [float(rel(composite_simpson(area, heights[0], draught, n))) for n in panels]
    trapezoid = [float(rel(composite_trapezoid(area, heights[0], draught, n))) for n in panels]
    split = [float(rel(_split_simpson(area, cuts, n))) for n in panels]
    gl = [(n, float(rel(_gauss64(area, whole, n))), float(rel(_gauss64(area, cuts, n)))) for n in gauss]
    with mpmath.workdps(DPS):
        s_order = fit_order(panels, [mpmath.mpf(e) for e in simpson])
        t_order = fit_order(panels, [mpmath.mpf(e) for e in trapezoid])
    return Kink(heel, pts, draught, exact, cuts[1:-1], tuple(panels), simpson, trapezoid, split, gl, s_order, t_order)
