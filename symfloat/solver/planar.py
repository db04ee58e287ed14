"""Critical points of a potential of one angle: the long prism's cross-section, the cylinder's meridian.

Given ``f(theta) = U'(theta)`` and ``f'(theta) = U''(theta)`` (both measured,
not taken from a source), every root of ``f`` on an interval is bracketed by
cubic Hermite interpolation between grid points (which also catches two
roots close together, where ``f`` does not change sign on the grid) and
polished by safeguarded Newton steps.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Root", "roots"]


@dataclass(frozen=True)
class Root:
    """A root ``theta`` of ``f`` with ``fprime`` there and the residual ``f``."""
    theta: float
    f: float
    fprime: float


def _hermite_roots(t0, t1, f0, d0, f1, d1) -> list[float]:
    """Real roots in ``[t0, t1]`` of the cubic Hermite interpolant of ``f``."""
    h = t1 - t0
    # p(x) = f0 h00 + h d0 h10 + f1 h01 + h d1 h11, x in [0, 1]
    c3 = 2 * f0 + h * d0 - 2 * f1 + h * d1
    c2 = -3 * f0 - 2 * h * d0 + 3 * f1 - h * d1
    c1 = h * d0
    c0 = f0
    out = []
    for x in np.roots([c3, c2, c1, c0]) if any((c3, c2, c1)) else []:
        if abs(x.imag) <= 1e-9 and -1e-9 <= x.real <= 1 + 1e-9:
            out.append(t0 + h * min(max(x.real, 0.0), 1.0))
    return out


def _polish(evaluate, theta, lo, hi, scale) -> Root | None:
    """Newton from *theta*, kept inside ``[lo, hi]``; bisection when the bracket has a sign change."""
    f_lo, f_hi = evaluate(lo)[0], evaluate(hi)[0]
    bracket = f_lo * f_hi < 0
    best = None
    for _ in range(60):
        f, fp = evaluate(theta)
        if best is None or abs(f) < abs(best.f):
            best = Root(theta, f, fp)
        if abs(f) <= 1e-15 * scale:
            break
        if bracket:
            if (f < 0) == (f_lo < 0):
                lo, f_lo = theta, f
            else:
                hi = theta
        step = -f / fp if fp != 0 else math.inf
        new = theta + step
        if not lo <= new <= hi:
            if not bracket:
                return best if abs(best.f) <= 1e-12 * scale else None
            new = (lo + hi) / 2
        if abs(new - theta) <= 1e-16 * max(1.0, abs(theta)):
            break
        theta = new
    return best if abs(best.f) <= 1e-12 * scale else None


def roots(evaluate, lo: float, hi: float, points: int, scale: float, include_ends: bool = False) -> list[Root]:
    """Every root of ``f`` on ``[lo, hi]``; ``evaluate(theta) -> (f, f')``.  With *include_ends*
    the ends are roots by symmetry and are returned as they are."""
    grid = np.linspace(lo, hi, points + 1)
    values = [evaluate(float(t)) for t in grid]
    candidates = []
    for i in range(points):
        (f0, d0), (f1, d1) = values[i], values[i + 1]
        for t in _hermite_roots(grid[i], grid[i + 1], f0, d0, f1, d1):
            candidates.append((t, max(lo, grid[i] - (grid[1] - grid[0])), min(hi, grid[i + 1] + (grid[1] - grid[0]))))
    found: list[Root] = []
    if include_ends:
        found += [Root(lo, *values[0]), Root(hi, *values[-1])]
    for t, a, b in candidates:
        r = _polish(evaluate, t, a, b, scale)
        if r is None:
            continue
        if include_ends and (abs(r.theta - lo) < 1e-7 or abs(r.theta - hi) < 1e-7):
            continue
        if any(abs(r.theta - q.theta) <= 1e-9 + _distance(q, scale) + _distance(r, scale) for q in found):
            continue
        found.append(r)
    found.sort(key=lambda r: r.theta)
    return found


def _distance(r: Root, scale: float) -> float:
    """Estimated distance of *r* from the true root (first order, or the cube-root bound near a
    degenerate root)."""
    f = abs(r.f)
    return min(f / abs(r.fprime) if r.fprime else math.inf, (f / scale) ** (1 / 3))
