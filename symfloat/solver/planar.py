"""Critical points of a potential of one angle: the long prism's cross-section, the cylinder's meridian.

Given ``f(theta) = U'(theta)`` and ``f'(theta) = U''(theta)`` (both measured,
not taken from a source), every root of ``f`` on an interval is bracketed by
cubic Hermite interpolation between grid points (which also catches two
roots close together, where ``f`` does not change sign on the grid) and
polished by safeguarded Newton steps.  The interpolant is trusted only where
``f`` is smooth and where it shows its turns: a cell is cut where the
submerged corners (or the waterplane's shape) change, since ``f``'s higher
derivatives jump there, and where the interpolant turns near 0 ``f`` is
measured at the turn (a stable and an unstable position a tenth of a degree
apart, just before they meet, fit inside one cell of the grid).
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
    c3, c2, c1, c0 = _hermite(t0, t1, f0, d0, f1, d1)
    out = []
    for x in np.roots([c3, c2, c1, c0]) if any((c3, c2, c1)) else []:
        if abs(x.imag) <= 1e-9 and -1e-9 <= x.real <= 1 + 1e-9:
            out.append(t0 + h * min(max(x.real, 0.0), 1.0))
    return out


def _hermite(t0, t1, f0, d0, f1, d1):
    """The cubic Hermite interpolant of ``f`` on ``[t0, t1]`` as a polynomial in ``x = (t - t0) / (t1 - t0)``
    (coefficients, highest first)."""
    h = t1 - t0
    return (2 * f0 + h * d0 - 2 * f1 + h * d1, -3 * f0 - 2 * h * d0 + 3 * f1 - h * d1, h * d0, f0)


def _examined(evaluate, t0, t1, v0, v1, depth: int = 0):
    """The cell ``[t0, t1]``, cut where its interpolant cannot be trusted to show every root: where the
    interpolant turns without reaching 0 inside the cell, ``f`` is measured at the turn, and the cell is cut there
    when the measurement is of the other sign or not clear of 0 by twice the interpolant's error there (two roots
    close together, the interpolant's dip not deep enough).  Six cuts at most, each halving the error's scale."""
    c3, c2, c1, c0 = _hermite(t0, t1, *v0, *v1)
    turns = [x.real for x in (np.roots([3 * c3, 2 * c2, c1]) if any((c3, c2)) else [])
             if abs(x.imag) <= 1e-12 and 0 < x.real < 1]
    for x in sorted(turns, key=lambda x: abs(np.polyval([c3, c2, c1, c0], x))):
        p = np.polyval([c3, c2, c1, c0], x)
        if depth >= 6 or (p > 0) != (v0[0] > 0) or (p > 0) != (v1[0] > 0):
            break               # the interpolant has roots here already: they are candidates
        tm = t0 + (t1 - t0) * x
        vm = evaluate(tm)
        if (vm[0] > 0) == (p > 0) and abs(vm[0]) > 2 * abs(vm[0] - p):
            continue
        return _examined(evaluate, t0, tm, v0, vm, depth + 1) + _examined(evaluate, tm, t1, vm, v1, depth + 1)
    return [(t0, t1, v0, v1)]


def _polish(evaluate, theta, lo, hi, scale) -> Root | None:
    """Newton from *theta*, kept inside ``[lo, hi]``; bisection when the bracket has a sign change.  It goes on
    while its steps shrink, even where ``f`` is already at rounding's level: next to a root of higher order
    (a symmetric end whose second variation vanishes, ``f ~ eps^3``) ``f`` is that small far from the root, and
    stopping there left a spurious root 1e-6 rad from the end."""
    f_lo, f_hi = evaluate(lo)[0], evaluate(hi)[0]
    bracket = f_lo * f_hi < 0
    best, last = None, math.inf
    for _ in range(60):
        f, fp = evaluate(theta)
        if best is None or abs(f) < abs(best.f):
            best = Root(theta, f, fp)
        if f == 0:
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
        if abs(new - theta) <= 1e-16 * max(1.0, abs(theta)) or (abs(f) <= 1e-15 * scale
                                                                 and abs(new - theta) >= last):
            break               # converged, or the steps no longer shrink where f is at rounding's level
        theta, last = new, abs(new - theta)
    return best if abs(best.f) <= 1e-12 * scale else None


def roots(evaluate, lo: float, hi: float, points: int, scale: float, include_ends: bool = False,
          regime=None) -> list[Root]:
    """Every root of ``f`` on ``[lo, hi]``; ``evaluate(theta) -> (f, f')``.  With *include_ends*
    the ends are roots by symmetry and are returned as they are.  *regime* (``theta ->`` a hashable), where
    given, names the piece of ``f`` a tilt lies on (which vertices are under water): ``f`` is smooth within a
    piece and its higher derivatives jump between pieces, so a cell whose ends lie on different pieces is
    cut where the piece changes (:func:`_cells`) before the interpolant is fitted."""
    grid = [float(t) for t in np.linspace(lo, hi, points + 1)]
    values = [evaluate(t) for t in grid]
    width = grid[1] - grid[0]
    inside = regime and (lambda t: regime(min(max(t, lo + EDGE), hi - EDGE)))
    candidates = []
    for i in range(points):
        for piece in _cells(evaluate, inside, grid[i], grid[i + 1], values[i], values[i + 1]):
            for t0, t1, (f0, d0), (f1, d1) in _examined(evaluate, *piece):
                for t in _hermite_roots(t0, t1, f0, d0, f1, d1):
                    candidates.append((t, max(lo, t0 - width), min(hi, t1 + width)))
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


EDGE = 1e-7             # radians: an end's own piece may be degenerate (at a mirror a vertex can lie on the water;
                        # the lying cylinder's waterplane is a rectangle), so the piece at an end is read this far inside
EVENT_WIDTH = 1e-9      # radians: a change of piece is bracketed this closely; the interpolant's error from the
                        # jump of f's higher derivatives inside the bracket is then below float64's resolution


def _cells(evaluate, regime, t0, t1, v0, v1):
    """The cell ``[t0, t1]`` (values ``(f, f')`` at its ends) cut at every change of *regime* found by
    bisection, as ``(a, b, value at a, value at b)``; one cell where *regime* is None or the same at both ends."""
    if regime is None or regime(t0) == regime(t1):
        return [(t0, t1, v0, v1)]
    first, a, b, va, vb = regime(t0), t0, t1, v0, v1
    while b - a > EVENT_WIDTH:
        m = (a + b) / 2
        vm = evaluate(m)
        if regime(m) == first:
            a, va = m, vm
        else:
            b, vb = m, vm
    return [(t0, a, v0, va), (a, b, va, vb)] + _cells(evaluate, regime, b, t1, vb, v1)


def _distance(r: Root, scale: float) -> float:
    """Estimated distance of *r* from the true root (first order, or the cube-root bound near a
    degenerate root)."""
    f = abs(r.f)
    return min(f / abs(r.fprime) if r.fprime else math.inf, (f / scale) ** (1 / 3))
