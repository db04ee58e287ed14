"""How far a computed equilibrium can lie from the true one.

Newton–Kantorovich: for ``F(x) = 0`` with residual ``r = |F(x0)|`` (evaluated
at 30 digits, so the float64 rounding of the solver is included),
``beta = |F'(x0)^-1|`` and ``L`` a Lipschitz constant of ``F'`` near ``x0``,
let ``eta = beta r`` and ``h = L beta eta``.  When ``h <= 1/2`` a root lies
within ``(1 - sqrt(1 - 2h)) / (L beta) = 2 eta / (1 + sqrt(1 - 2h)) <= 2 eta``
of ``x0``; the second form is the one evaluated (the first cancels to 0 in
float64 for ``h`` below 1e-16 and would claim an error smaller than ``eta``).  ``L`` is
measured by central differences of ``F'`` (an estimate, not a proof).  When
``h > 1/2`` (next to a bifurcation, where ``F'`` is nearly singular) the
theorem says nothing; then the potential is at worst quartic in the
distance, ``r ~ scale * d^3``, and ``(r / scale)^(1/3)`` is reported, flagged
as an estimate.
"""
from __future__ import annotations

import math

__all__ = ["equilibrium_error", "eigenvalue_error"]

STEP = 1e-4         # radians: the central-difference step for the Lipschitz constant
ROUNDING = 5e-16    # radians: a unit vector rounded to float64 (and turned by a symmetry) moves this much


def equilibrium_error(residual: float, slope: float, lipschitz: float, scale: float) -> tuple[float, str]:
    """``(distance bound in radians, how it was obtained)``; *slope* is ``1 / |F'^-1|``."""
    if residual == 0:
        return 0.0, "exact"
    if slope > 0:
        beta = 1 / slope
        eta = beta * residual
        if lipschitz <= 0:
            return 2 * eta + ROUNDING, "kantorovich"
        h = lipschitz * beta * eta
        if h <= 0.5:
            return 2 * eta / (1 + math.sqrt(1 - 2 * h)) + ROUNDING, "kantorovich"
    return (residual / scale) ** (1 / 3) + ROUNDING, "near-bifurcation estimate"


def eigenvalue_error(lipschitz: float, distance: float, scale: float) -> float:
    """Error of a Hessian eigenvalue computed at a point *distance* from the equilibrium: the
    Hessian changes by at most ``L * distance`` there, plus float64 rounding (``1e-14 * scale``).
    An eigenvalue smaller than this decides nothing: the position is called indifferent."""
    return lipschitz * distance + 1e-14 * scale
