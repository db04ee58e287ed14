"""Quadrature methods for first-principles witnesses.

Each method integrates a scalar function over ``[a, b]`` (optionally split
at breakpoints, e.g. where a section area has a kink) and reports the value
and its wall time.  Methods differ in rule and precision so that one witness
yields several points of error against run time.

>>> from mpmath import mpf
>>> value, seconds = TANH_SINH_50.integrate(lambda x: x**3, [0, 2])
>>> abs(value - 4) < mpf(10) ** -45
True
"""
from __future__ import annotations

import functools
import time
from dataclasses import dataclass

import flint
import mpmath
import numpy as np
from mpmath.calculus.quadrature import GaussLegendre

__all__ = ["QuadMethod", "TanhSinh", "GaussLegendre64", "TANH_SINH_15", "TANH_SINH_50",
           "GAUSS_LEGENDRE_64_8", "DEFAULT_METHODS", "composite_simpson", "composite_trapezoid",
           "GaussLegendreMP", "Composite", "ArbGaussLegendre", "gauss_legendre"]


class ArbGaussLegendre(GaussLegendre):
    """mpmath's adaptive Gauss–Legendre rule (degree m: the 3·2^(m-1) roots x_k of P_n on [-1, 1] with the
    weights w_k = 2 / ((1 - x_k²) P_n'(x_k)²)) whose nodes come from FLINT's ``arb.legendre_p_root`` instead of
    mpmath's Newton steps on the three-term recurrence in Python: the same numbers to the working precision,
    about 45 times faster at degree 8 and 200 bits, where they were two thirds of the quadrature's time."""

    def calc_nodes(self, degree, prec, verbose=False):
        n = 3 * 2 ** (degree - 1)
        with flint.ctx.workprec(int(prec * 1.5)):        # the precision mpmath computes its own nodes at
            nodes = [flint.arb.legendre_p_root(n, k, weight=True) for k in range(n)]
        if self.ctx is mpmath.fp:                       # float64: the nodes rounded to doubles
            return [(float(x.mid()), float(w.mid())) for x, w in nodes]
        return [(_mpf(x), _mpf(w)) for x, w in nodes]


def _mpf(x) -> mpmath.mpf:
    """The midpoint of an ``arb`` as an mpf at the current precision."""
    man, exp = x.mid().man_exp()
    return mpmath.mpf((int(man), int(exp)))


@functools.lru_cache(maxsize=None)
def gauss_legendre(ctx) -> ArbGaussLegendre:
    """The rule for ``mpmath.quad(..., method=gauss_legendre)``: one instance per context, so that its nodes
    are computed once per degree and precision (``quad`` calls a rule given as a callable with its context)."""
    return ArbGaussLegendre(ctx)


@dataclass(frozen=True)
class QuadMethod:
    """A named rule at a named precision; ``tolerance`` is the relative
    accuracy it is trusted to reach on the smooth integrands of witnesses."""

    name: str
    tolerance: float
    arithmetic: str  # "mpmath" or "float64": how the integrand must be built
    dps: int = 15

    def integrate(self, f, points):
        t0 = time.perf_counter()
        value = self._integrate(f, list(points))
        return value, time.perf_counter() - t0

    def _integrate(self, f, points):
        raise NotImplementedError  # pragma: no cover - abstract


@dataclass(frozen=True)
class TanhSinh(QuadMethod):
    """mpmath's tanh-sinh (double-exponential) quadrature at ``dps`` digits."""

    def _integrate(self, f, points):
        with mpmath.workdps(self.dps):
            return +mpmath.quad(f, [mpmath.mpf(p) for p in points], method="tanh-sinh")


@dataclass(frozen=True)
class GaussLegendre64(QuadMethod):
    """Fixed-order Gauss–Legendre in float64 on each piece: exact for
    polynomials of degree ``2 n - 1`` up to rounding."""

    order: int = 8

    def _integrate(self, f, points):
        x, w = np.polynomial.legendre.leggauss(self.order)
        total = 0.0
        for a, b in zip(points, points[1:]):
            a, b = float(a), float(b)
            half, mid = (b - a) / 2, (b + a) / 2
            total += half * sum(wi * float(f(mid + half * xi)) for xi, wi in zip(x, w))
        return mpmath.mpf(total)


@dataclass(frozen=True)
class GaussLegendreMP(QuadMethod):
    """mpmath's adaptive Gauss–Legendre quadrature at ``dps`` digits."""

    def _integrate(self, f, points):
        with mpmath.workdps(self.dps):
            return +mpmath.quad(f, [mpmath.mpf(p) for p in points], method=gauss_legendre)


@dataclass(frozen=True)
class Composite(QuadMethod):
    """A composite Newton–Cotes rule (``rule`` = ``"simpson"`` or
    ``"trapezoid"``) in float64 with ``panels`` panels on each piece."""

    rule: str = "simpson"
    panels: int = 8

    def _integrate(self, f, points):
        apply = composite_simpson if self.rule.lower() == "simpson" else composite_trapezoid
        g = lambda x: float(f(x))  # noqa: E731
        return mpmath.mpf(sum(apply(g, float(a), float(b), self.panels) for a, b in zip(points, points[1:])))


TANH_SINH_15 = TanhSinh("tanh-sinh, 15 digits", 1e-12, "mpmath", 15)
TANH_SINH_50 = TanhSinh("tanh-sinh, 50 digits", 1e-45, "mpmath", 50)
GAUSS_LEGENDRE_64_8 = GaussLegendre64("Gauss-Legendre n=8, float64", 1e-12, "float64", 15, 8)
DEFAULT_METHODS = (TANH_SINH_15, TANH_SINH_50, GAUSS_LEGENDRE_64_8)


def composite_simpson(f, a, b, panels: int):
    """Composite Simpson rule with an even number of *panels* of width
    ``m = (b - a) / panels``: ``m/3 (f0 + 4 f1 + 2 f2 + ... + 4 f_{n-1} + f_n)``.

    >>> composite_simpson(lambda x: x**3, 0, 2, 2)
    4.0
    """
    if panels <= 0 or panels % 2:
        raise ValueError("Simpson's rule needs an even, positive number of panels")
    m = (b - a) / panels
    inner = sum((4 if k % 2 else 2) * f(a + k * m) for k in range(1, panels))
    return m / 3 * (f(a) + inner + f(b))



def composite_trapezoid(f, a, b, panels: int):
    """Composite trapezoid rule with *panels* panels of width ``m = (b - a) / panels``:
    ``m (f0/2 + f1 + ... + f_{n-1} + f_n/2)``.

    >>> composite_trapezoid(lambda x: x, 0, 2, 1)
    2.0
    """
    if panels <= 0:
        raise ValueError("the trapezoid rule needs a positive number of panels")
    m = (b - a) / panels
    return m * ((f(a) + f(b)) / 2 + sum(f(a + k * m) for k in range(1, panels)))
