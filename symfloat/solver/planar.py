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
apart, just before they meet, fit inside one cell of the grid).  Beside a
symmetric end, where ``f`` falls below float64's rounding, a root is judged
at 30 digits (:func:`_beside_end`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath
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


def roots(evaluate, lo: float, hi: float, points: int, scale: float, include_ends: bool = False,
          regime=None, precise=None) -> list[Root]:
    """Every root of ``f`` on ``[lo, hi]``; ``evaluate(theta) -> (f, f')``.  With *include_ends*
    the ends are roots by symmetry and are returned as they are.  *regime* (``theta ->`` a hashable), where
    given, names the piece of ``f`` a tilt lies on (which vertices are under water): ``f`` is smooth within a
    piece and its higher derivatives jump between pieces, so a cell whose ends lie on different pieces is
    cut where the piece changes (:func:`_cells`) before the interpolant is fitted.  *precise* (``theta ->
    (f, f')`` at 30 digits, mpf), where given with *include_ends*, judges a root found within :data:`NEAR` of an
    end (:func:`_beside_end`)."""
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
    ends = found[:]                 # roots by symmetry, exactly where they are: no distance of their own
    for t, a, b in candidates:
        r = _polish(evaluate, t, a, b, scale)
        if r is None:
            continue
        judged = include_ends and precise is not None and min(abs(r.theta - lo), abs(r.theta - hi)) < NEAR
        if judged:
            end = lo if abs(r.theta - lo) < abs(r.theta - hi) else hi
            if any(q not in ends and (q.theta - end) * (r.theta - end) > 0
                   and abs(q.theta - end) <= 1.1 * abs(r.theta - end) for q in found):
                continue            # the root between the end and this one is judged already
            r = _beside_end(precise, r, end, scale)
            if r is None:
                continue
        elif include_ends and (abs(r.theta - lo) < 1e-7 or abs(r.theta - hi) < 1e-7):
            continue
        # a root judged beside an end is not the end (f changes sign between them at 30 digits), however close
        if any(abs(r.theta - q.theta) <= 1e-9 + (q not in ends and _distance(q, scale)) + _distance(r, scale)
               for q in found if not (judged and q in ends)):
            continue
        found.append(r)
    found.sort(key=lambda r: r.theta)
    return found


NEAR = 1e-4             # radians: beside a symmetric end, f ~ a eps^3 is at float64's rounding out to about here


def _beside_end(precise, r: Root, end: float, scale: float) -> Root | None:
    """The float64 root *r* beside the symmetric *end*, judged at 30 digits: ``None`` where no root lies between
    the end and just beyond *r*, else that root.  Beside an end whose second variation nearly vanishes,
    ``f ~ d eps + a eps^3`` (``d = f'(end)``) falls below float64's rounding long before it vanishes, and a float64
    root there may be the end itself (the cylinder 1, 3/2 at s = 1/3: ``f ~ eps^3/4``, a 'root' 6.6e-7 rad out)
    or the partner of a pitchfork (the square at 9/32 - 1e-18: the partner 1.9e-9 rad out, float64's 'root' 1e-5).
    ``f`` has the sign of ``d eps`` right beside the end, so a root lies between the end and ``1.1 eps_r`` exactly
    where ``f`` has the other sign there; it is at ``eps^2 = -d/a``, bisected where ``f`` is resolved at 30 digits
    on both sides of it, else taken from that expansion (its error then follows from its residual).  An end whose
    second variation is 0 at 30 digits has no partner that can be told from it: its higher orders decide it."""
    if abs(r.theta - end) <= 4e-16 * max(1.0, abs(end)):
        return None                 # the end itself, to float64's last digit
    with mpmath.workdps(30):
        e, noise = mpmath.mpf(end), mpmath.mpf(10) ** -25 * scale
        side = 1 if r.theta > end else -1
        d = precise(e)[1]
        if abs(d) <= noise:
            return None
        linear = 1 if d * side > 0 else -1
        reach = mpmath.mpf(1.1) * abs(mpmath.mpf(r.theta) - e)
        f_reach = precise(e + side * reach)[0]
        if abs(f_reach) <= noise or (1 if f_reach > 0 else -1) == linear:
            return None
        a = (f_reach * side - d * reach) / reach ** 3
        delta = min(mpmath.sqrt(-d / a), reach)
        lo, hi = delta / 2, min(2 * delta, reach)
        f_lo, f_hi = precise(e + side * lo)[0], precise(e + side * hi)[0]
        if min(abs(f_lo), abs(f_hi)) > noise and (1 if f_lo > 0 else -1) == linear != (1 if f_hi > 0 else -1):
            for _ in range(100):
                delta = (lo + hi) / 2
                f_m = precise(e + side * delta)[0]
                if f_m == 0 or hi - lo <= mpmath.mpf(10) ** -28:
                    break
                if (1 if f_m > 0 else -1) == linear:
                    lo = delta
                else:
                    hi = delta
        f, fprime = precise(e + side * delta)
        return Root(float(e + side * delta), float(f), float(fprime))


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
