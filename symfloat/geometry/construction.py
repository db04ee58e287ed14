"""Measurements of straightedge constructions in space, in mpmath at the working precision: the area of a
triangle from its side lengths alone (Heron's formula) and the meeting point of two lines (least squares on
the three coordinates).  Witnesses of constructions a text describes measure with these instead of the
formulas under test.

>>> import mpmath
>>> p, q, r = (mpmath.matrix(v) for v in ([0, 0, 0], [3, 0, 0], [0, 4, 0]))
>>> heron_area(p, q, r)
mpf('6.0')
>>> [float(c) for c in line_meet(p, mpmath.matrix([2, 2, 0]), q, r)]     # y = x meets 4x + 3y = 12
[1.7142857142857142, 1.7142857142857142, 0.0]
"""
from __future__ import annotations

import mpmath

__all__ = ["heron_area", "line_meet"]


def heron_area(p, q, r):
    """The area of the triangle p q r (mpmath column vectors) by Heron's formula from its three side lengths."""
    x, y, w = mpmath.norm(p - q), mpmath.norm(q - r), mpmath.norm(r - p)
    half = (x + y + w) / 2
    return mpmath.sqrt(half * (half - x) * (half - y) * (half - w))


def line_meet(p1, p2, q1, q2):
    """The meeting point of the lines p1 p2 and q1 q2 (assumed to meet): p1 + t (p2 - p1) with t from the least
    squares solution of p1 + t (p2 - p1) = q1 + t' (q2 - q1) in the three coordinates."""
    M = mpmath.matrix([[p2[k] - p1[k], q1[k] - q2[k]] for k in range(3)])
    t = mpmath.qr_solve(M, q1 - p1)[0]
    return p1 + t[0] * (p2 - p1)
