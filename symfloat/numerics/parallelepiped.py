"""Float64 evaluation of Scheeffer's closed forms for the box in the second rotation region (IX.B).

The printed route to the critical ratio n_1 = (a/b)^2 and the double root z_1 is stiff at both ends of its
range 23/32 < s < 1 (t = (119 - 128 s)/27 runs from 1 down to -1/3):

* t -> 1 (s -> 23/32, n_1 -> 1): S = (1/t){1 + t^2 - (1 - t^2)^2/(1 + 3t)} (151) tends to 2 and
  sqrt(S^2 - 4) (153) cancels catastrophically; t itself is 1 - O(s - 23/32), so 1 - t loses digits when
  formed as 1 - t;
* t -> -1/3 (s -> 1): 1 + 3t -> 0, S -> infinity and n_2 = (S - sqrt(S^2 - 4))/2 cancels; 1 - z_1 by (159)
  cancels as 7 - 3t - 3 sqrt((5-t)(1-t)) -> 0;
* t = 0 (s = 119/128): (151) is 0/0 (a removable singularity).

The stable forms are algebraically equal (derivation ``scheeffer-ix``, steps ``S`` and quotes (154), (156),
(159)-(160)): everything is written in the small quantities u = 1 - t = (128 s - 92)/27 and
v = 1 + 3t = 128 (1 - s)/9, formed directly from s, and every sum has terms of one sign:

    S - 2 = u^3/v,   sqrt(S^2 - 4) = u (2 - u) sqrt((4 + u) u)/v,
    n_1 = 1 + u^3/(2v) + u (2 - u) sqrt((4 + u) u)/(2v),     n_2 = 1/n_1,
    z_1 = 3/16 (4 - u + sqrt((4 + u) u)),   z_2 = 3 v/(4 (4 - u + sqrt((4 + u) u))),
    1 - z_1 = v/(4 (7 - 3t + 3 sqrt((5-t)(1-t)))).

``error_table`` measures the relative error of both against a 50-digit mpmath evaluation at the same
(float) input s.
"""
from __future__ import annotations

import math

import mpmath

__all__ = ["printed", "stable", "reference", "error_table", "QUANTITIES"]

QUANTITIES = ("S-2", "n1", "n2", "z1", "z2", "1-z1")


def printed(s):
    """The quantities as the text computes them: t (147), S (151), n (153), z (157), 1 - z_1 (159)."""
    t = (119 - 128 * s) / 27
    S = (1 / t) * (1 + t * t - (1 - t * t) ** 2 / (1 + 3 * t))
    root = math.sqrt(max(S * S - 4, 0.0))
    R = math.sqrt((5 - t) * (1 - t))
    z1 = 3 / 16 * (3 + t + R)
    return {"S-2": S - 2, "n1": (S + root) / 2, "n2": (S - root) / 2, "z1": z1,
            "z2": 3 / 16 * (3 + t - R), "1-z1": (7 - 3 * t - 3 * R) / 16}


def stable(s):
    """The same quantities in the small variables u = 1 - t, v = 1 + 3t formed from s (no cancellation)."""
    u = (128 * s - 92) / 27
    v = 128 * (1 - s) / 9
    q = math.sqrt((4 + u) * u)                # sqrt((5 - t)(1 - t))
    n1 = 1 + u ** 3 / (2 * v) + u * (2 - u) * q / (2 * v)
    w = 4 - u + q                             # 3 + t + sqrt((5-t)(1-t))
    return {"S-2": u ** 3 / v, "n1": n1, "n2": 1 / n1, "z1": 3 / 16 * w, "z2": 3 * v / (4 * w),
            "1-z1": v / (4 * (4 + 3 * u + 3 * q))}


def reference(s, dps=50):
    """The printed forms at ``dps`` digits from the same float input s (exact conversion)."""
    with mpmath.workdps(dps):
        sm = mpmath.mpf(s)
        t = (119 - 128 * sm) / 27
        S = 2 + (1 - t) ** 3 / (1 + 3 * t) if t == 0 else (1 / t) * (1 + t * t - (1 - t * t) ** 2 / (1 + 3 * t))
        root = mpmath.sqrt(S * S - 4)
        R = mpmath.sqrt((5 - t) * (1 - t))
        return {"S-2": S - 2, "n1": (S + root) / 2, "n2": (S - root) / 2, "z1": 3 * (3 + t + R) / 16,
                "z2": 3 * (3 + t - R) / 16, "1-z1": (7 - 3 * t - 3 * R) / 16}


def _rel(x, ref):
    with mpmath.workdps(50):
        return float(abs(mpmath.mpf(x) - ref) / abs(ref)) if ref != 0 else float(abs(mpmath.mpf(x)))


def error_table(points=None):
    """{s: {quantity: (printed relative error, stable relative error)}} against the 50-digit reference;
    by default s approaches 23/32 and 1 geometrically (10^-1 .. 10^-12) and passes t = 0 (s = 119/128)."""
    if points is None:
        points = ([23 / 32 + 10.0 ** -k for k in range(1, 13)] + [1 - 10.0 ** -k for k in range(1, 13)]
                  + [119 / 128 + d for d in (-1e-9, 1e-9, 1e-5)])
    out = {}
    for s in points:
        ref = reference(s)
        try:
            p = printed(s)
        except ZeroDivisionError:
            p = {k: math.nan for k in QUANTITIES}
        st = stable(s)
        out[s] = {k: (_rel(p[k], ref[k]) if math.isfinite(p[k]) else math.inf, _rel(st[k], ref[k])) for k in QUANTITIES}
    return out
