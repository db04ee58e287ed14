"""The real roots of a polynomial in an interval, counted numerically with an inclusion bound.

An independent route to a root count (``RealRoots``, which the relation check takes exactly by Sturm
sequences): the polynomial's coefficients as numbers at the working precision, all its complex roots
by ``mpmath.polyroots`` (Durand–Kerner), and around each approximate root ``r_i`` the disc of radius

    rho_i = n |W_i|,   W_i = (|p(r_i)| + delta_i) / (|a_n| prod_{j != i} |r_i - r_j|),

``delta_i = 10^(2 - dps) sum_k |a_k| |r_i|^k`` covering the coefficients' rounding.  The union of the
discs holds every root, and a connected component of k discs holds exactly k roots (Carstensen,
"Inclusion of the roots of a polynomial based on Gerschgorin's theorem", Numer. Math. 59, 1991).
An approximate root whose disc reaches the real axis is moved onto it and the radii are taken again,
so that its disc is symmetric about the axis: a component of one such disc holds one root, which is
its own conjugate, hence real, and lies within ``rho`` of the centre.

A root is counted as real and inside ``(lo, hi)`` only when that follows from the discs:

* a component that does not reach the real axis holds non-real roots only;
* a component whose real extent lies beyond ``lo`` or ``hi`` holds no root of the interval;
* a component of one disc centred on the axis, its extent strictly inside ``(lo, hi)``, is one root.

Anything else -- two or more discs meeting on the axis inside the interval (a double root, two roots
closer than the precision can part), a root within its radius of an end, ``polyroots`` not converging
-- leaves the count undecided (``None``), never guessed:

>>> import mpmath
>>> mpmath.mp.dps = 15
>>> count_real_roots([1, 0, -1, 0], -2, 2)[0]                 # x^3 - x: -1, 0, 1 in (-2, 2)
3
>>> count_real_roots([1, 0, -1, 0], 0, 2)[0] is None          # the root 0 on an end: not decided
True
>>> count_real_roots([1, -2, 1], -5, 5)[0] is None            # (x - 1)^2: a double root
True
>>> count_real_roots([1, 0, 1], -mpmath.inf, mpmath.inf)[0]   # x^2 + 1: no real root
0
"""
from __future__ import annotations

import mpmath

__all__ = ["count_real_roots"]


def _radii(coeffs, centres, slack):
    """The inclusion radius n |W_i| of each (distinct) centre."""
    n = len(coeffs) - 1
    lead = abs(coeffs[0])
    out = []
    for i, r in enumerate(centres):
        gap = mpmath.mpf(1)
        for j, q in enumerate(centres):
            if j != i:
                gap *= abs(r - q)
        size = sum(abs(c) * abs(r) ** (n - k) for k, c in enumerate(coeffs))
        out.append(n * (abs(mpmath.polyval(coeffs, r)) + slack * size) / (lead * gap))
    return out


def _distinct(centres):
    """The centres with each repeated one moved along the real axis by k 10^(-dps/2) (1 + |c|) for its k-th
    repetition: the inclusion theorem needs distinct centres (a double root's approximations may coincide), and
    holds for any."""
    step = mpmath.mpf(10) ** (-mpmath.mp.dps // 2)
    out = []
    for c in centres:
        k = sum(1 for q in out if abs(q - c) <= step * (1 + abs(c)) / 4)
        out.append(c + k * step * (1 + abs(c)))
    return out


def _components(centres, radii):
    """The connected components of the discs, as lists of indices."""
    parent = list(range(len(centres)))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for i in range(len(centres)):
        for j in range(i + 1, len(centres)):
            if abs(centres[i] - centres[j]) <= radii[i] + radii[j]:
                parent[root(i)] = root(j)
    groups: dict = {}
    for i in range(len(centres)):
        groups.setdefault(root(i), []).append(i)
    return list(groups.values())


def count_real_roots(coeffs, lo, hi):
    """``(count, radius)``: the number of distinct real roots in the open interval ``(lo, hi)`` of the
    polynomial with the real *coeffs* (mpmath numbers, highest power first; ``lo``, ``hi`` may be
    infinite), at the current mpmath precision, and the largest inclusion radius of a root counted
    inside; ``(None, radius)`` when the discs do not decide it (see the module)."""
    dps = mpmath.mp.dps
    coeffs = [mpmath.mpf(c) for c in coeffs]
    while coeffs and coeffs[0] == 0:
        coeffs = coeffs[1:]
    if not coeffs:
        raise ValueError("the zero polynomial has no count of roots")
    if len(coeffs) == 1:
        return 0, mpmath.mpf(0)
    try:
        approx, err = mpmath.polyroots(coeffs, maxsteps=200, extraprec=2 * dps, error=True)
    except mpmath.libmp.NoConvergence:
        return None, mpmath.inf
    slack = mpmath.mpf(10) ** (2 - dps)
    centres = _distinct([mpmath.mpc(r) for r in approx])
    radii = [max(rho, err) for rho in _radii(coeffs, centres, slack)]
    centres = _distinct([mpmath.mpc(c.real) if abs(c.imag) <= rho else c for c, rho in zip(centres, radii)])
    radii = [max(rho, err) for rho in _radii(coeffs, centres, slack)]
    count, widest = 0, mpmath.mpf(0)
    for group in _components(centres, radii):
        on_axis = [i for i in group if abs(centres[i].imag) <= radii[i]]
        if not on_axis:
            continue                                        # non-real roots only
        left = min(centres[i].real - radii[i] for i in group)
        right = max(centres[i].real + radii[i] for i in group)
        if right < lo or left > hi:
            continue                                        # outside the interval, real or not
        if len(group) == 1 and centres[group[0]].imag == 0 and lo < left and right < hi:
            count += 1
            widest = max(widest, radii[group[0]])
            continue
        return None, max(radii[i] for i in group)           # a cluster on the axis, or a root at an end
    return count, widest
