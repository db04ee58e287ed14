"""Extrapolation to h = 0 of a quantity with a power series in its step h (Richardson's, by Neville's table).

The value at 0 of the polynomial through (h_0, f_0), ..., (h_k, f_k) is built one node at a time:
:func:`neville_row` extends the table by a node, :func:`extrapolated_limit` adds nodes until two successive
estimates agree (the definition route's limits that SymPy cannot take), and a floating witness's limit
in its tilt takes a fixed number of halvings (:mod:`symfloat.engine.floating_witness`).
"""
from __future__ import annotations

import contextlib

__all__ = ["neville_row", "at_zero", "extrapolated_limit", "UnsettledLimit", "LIMIT_STEPS"]


def neville_row(nodes: list, row: list, value) -> list:
    """Neville's table at 0 one node further: *row* holds the estimates through ``nodes[:-1]`` (``row[j]`` the
    polynomial through the last j + 1 of them), *value* is f at ``nodes[-1]``; returns the row through *nodes*,
    its last entry the polynomial through all of them at 0."""
    h = nodes[-1]
    new = [value]
    for j in range(1, len(row) + 1):        # nodes k - j .. k, from nodes k - j + 1 .. k and k - j .. k - 1
        new.append(new[j - 1] + (new[j - 1] - row[j - 1]) * h / (nodes[-1 - j] - h))
    return new


def at_zero(nodes: list, values: list):
    """The polynomial through (*nodes*, *values*) at 0."""
    row = []
    for k, value in enumerate(values):
        row = neville_row(nodes[:k + 1], row, value)
    return row[-1]


class UnsettledLimit(ArithmeticError):
    """The extrapolation of a limit did not settle at the working precision."""


LIMIT_STEPS = 30            # h down to 1/(2^30 + 1), about 1e-9


def extrapolated_limit(ctx, f, z0, direction):
    """lim f(z) as z -> z0 from the side of *direction* (z0 = +-inf: z -> +-inf) in mpmath's context *ctx*:
    f at z = z0 + direction h (at infinity z = +-1/h) for h = 1/(2^k + 1), k = 1, 2, ..., extrapolated to
    h = 0 by Neville's table (for a quantity with a power series in h: a collapsing section's integrals in
    its tilt, the regular n-gon's in 1/n).  It stops when two successive estimates agree to 10^(5 - dps) of
    the larger of the estimate and the last value, at least four values in; values near the limit cancel
    (0/0), so in mpmath's numbers they are taken at twice the digits.  Raises :class:`UnsettledLimit` if
    the estimates have not settled at h = 1/(2^30 + 1) (in float64: the caller takes mpmath's numbers)."""
    fixed = not hasattr(ctx, "extradps")
    dps = 15 if fixed else ctx.dps
    tol = ctx.mpf(10) ** (5 - dps)
    with (contextlib.nullcontext() if fixed else ctx.extradps(dps)):
        nodes, row = [], []
        for k in range(1, LIMIT_STEPS + 1):
            h = ctx.mpf(1) / (2 ** k + 1)
            value = f(z0 + direction * h if not ctx.isinf(z0) else (1 if z0 > 0 else -1) / h)
            nodes.append(h)
            new = neville_row(nodes, row, value)
            if k >= 4 and abs(new[-1] - row[-1]) <= tol * max(abs(new[-1]), abs(value)):
                return +new[-1]
            row = new
    raise UnsettledLimit(f"the extrapolated limit did not settle to 1e{5 - dps} by h = 1/(2^{LIMIT_STEPS} + 1)")
