"""Bracketed roots for first-principles witnesses: the Illinois method in any arithmetic.

Witnesses find tilts and densities where a measured quantity (a righting arm, a
clearance) changes sign.  :func:`illinois` refines one bracket; :func:`grid_roots`
finds every sign change on a float grid, refines it in float64 and, for
``dps > 15``, again at ``dps`` digits in a narrow bracket around the float root
(``make_f(dps)`` builds the function at that precision).  :func:`polynomial_roots` isolates the
real roots of a polynomial with rational coefficients exactly, so that roots a grid cannot part
(next to a pitchfork, a nearly triple root) stay apart; :func:`polynomial_terms` and
:func:`polynomial_at` build such a polynomial once with symbolic parameters and evaluate it at
exact values.
"""
from __future__ import annotations

from fractions import Fraction

import mpmath

__all__ = ["illinois", "grid_roots", "polynomial_roots", "polynomial_terms", "polynomial_at"]


def illinois(f, lo, hi, eps):
    """A root of *f* in ``[lo, hi]`` (a sign change required), to relative tolerance *eps*:
    regula falsi with the Illinois halving of the stale end."""
    flo, fhi = f(lo), f(hi)
    if flo == 0:
        return lo
    if fhi == 0:
        return hi
    if (flo > 0) == (fhi > 0):
        raise ValueError("no sign change in the bracket")
    side, c_old, c = 0, None, lo
    for _ in range(400):
        c = (lo * fhi - hi * flo) / (fhi - flo)
        fc = f(c)
        if fc == 0:
            return c
        if (fc > 0) == (fhi > 0):
            hi, fhi = c, fc
            if side == -1:
                flo /= 2
            side = -1
        else:
            lo, flo = c, fc
            if side == 1:
                fhi /= 2
            side = 1
        if c_old is not None and abs(c - c_old) <= eps * (1 + abs(c)):
            return c
        c_old = c
    return c


def _cells(f, grid, only):
    """The indices i of the grid cells [grid[i], grid[i + 1]] on which *f* changes sign; ``only="first"``
    (``"last"``): the first (last) of them, the grid scanned from its start (end) until it is found."""
    order = range(len(grid) - 1)
    if only == "last":
        order = reversed(order)
    values, cells = {}, []
    for i in order:
        for j in (i, i + 1):
            if j not in values:
                values[j] = f(grid[j])
        if (values[i] > 0) != (values[i + 1] > 0):
            cells.append(i)
            if only is not None:
                break
    return sorted(cells)


def grid_roots(make_f, grid, dps, only=None) -> list:
    """Every sign change of ``make_f(15)`` on *grid* (``only="first"`` or ``"last"``: just that
    one, the grid scanned until it is found), refined in float64 and, for ``dps > 15``, at *dps*
    digits (in a bracket of 1e-9 around the float root, or the grid cell) to a relative 10^(5 - dps):
    a measured function is known to about its working digits, and Illinois steps below its
    rounding only stall."""
    ff = make_f(15)
    cells = _cells(ff, grid, only)
    out = []
    for i in cells:
        x0 = illinois(ff, grid[i], grid[i + 1], 1e-15)
        if dps > 15:
            fm = make_f(dps)
            with mpmath.workdps(dps + 8):
                delta = mpmath.mpf("1e-9") * (1 + abs(x0))
                lo, hi = mpmath.mpf(x0) - delta, mpmath.mpf(x0) + delta
                if (fm(lo) > 0) == (fm(hi) > 0):
                    lo, hi = mpmath.mpf(grid[i]), mpmath.mpf(grid[i + 1])
                x0 = illinois(fm, lo, hi, mpmath.mpf(10) ** (5 - dps))
        out.append(x0)
    return out


def polynomial_roots(poly, eps) -> list:
    """The distinct real roots of the square-free SymPy ``Poly`` *poly* over QQ, ascending, as mpmath numbers
    at the working precision: isolated exactly by SymPy's isolating intervals, rational roots exact, each
    other root refined by :func:`illinois` to relative tolerance *eps* in its interval.  Rational roots are
    divided out first, so that no root lies on an interval's end and every interval has a sign change."""
    import sympy as sp                  # here, not at the top: a scene's predictors use illinois without SymPy
    mp = lambda q: mpmath.mpf(int(q.p)) / int(q.q)  # noqa: E731
    rational = [lo for (lo, hi), _ in poly.intervals() if lo == hi]
    for r in rational:
        poly = poly.quo(sp.Poly([1, -r], *poly.gens, domain=sp.QQ))
    coefficients = [mp(c) for c in poly.all_coeffs()]
    return sorted([mp(r) for r in rational] + [illinois(lambda x: mpmath.polyval(coefficients, x), mp(lo), mp(hi), eps)
                                               for (lo, hi), _ in poly.intervals()])


def polynomial_terms(expr, unknown, parameters) -> tuple:
    """The terms ``((k, e_1, ..., e_m), c)`` of *expr*, a polynomial in *unknown* and the symbols *parameters*
    with rational coefficients: ``c unknown^k p_1^e_1 ... p_m^e_m``, ``c`` a Fraction.  Built once; evaluated
    at exact parameter values by :func:`polynomial_at`."""
    import sympy as sp
    return tuple((m, Fraction(int(c.p), int(c.q))) for m, c in sp.Poly(expr, unknown, *parameters).terms())


def polynomial_at(terms, unknown, values):
    """The polynomial in *unknown* over QQ (a SymPy ``Poly``) of *terms* (:func:`polynomial_terms`) at the exact
    parameter *values* (ints or Fractions, in the order of the parameters)."""
    import sympy as sp
    coefficients = {}
    for (k, *powers), c in terms:
        for q, e in zip(values, powers):
            c *= q ** e
        coefficients[k] = coefficients.get(k, 0) + c
    return sp.Poly([sp.Rational(coefficients.get(k, 0)) for k in range(max(coefficients), -1, -1)], unknown,
                   domain=sp.QQ)
