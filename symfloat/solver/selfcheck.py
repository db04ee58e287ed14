"""The solver's self-checks that fail a command: the index sum of a scene, the duality of a phase diagram.

* On the sphere (cube, box, prism) the indices of the critical points of the
  potential add up to the Euler characteristic 2 (Poincaré–Hopf): +1 for a
  minimum or maximum, -1 for a saddle, and for a degenerate point the index of
  its higher-order terms (:func:`index_of`).
* On the circle of heel angles (a section) minima and maxima alternate, so
  their numbers are equal (the Euler characteristic of the circle is 0).
* A box is centrally symmetric: turned upside down, its stable set at ``1 - s``
  is its stable set at ``s``, so every threshold ``s*`` of a phase diagram has a
  dual at ``1 - s*`` with the opposite change.

A check that still fails after the solver has worked harder is an error, never
a footer: :class:`IndexCheckError` carries the message (a phase diagram whose
duality fails lists the thresholds without a dual and the command exits 1).
"""
from __future__ import annotations

from ..errors import CheckFailed

__all__ = ["SelfCheckError", "IndexCheckError", "index_of"]


class SelfCheckError(CheckFailed):
    """A self-check of the solver failed (exit status 1); the message says which and by how much."""


class IndexCheckError(SelfCheckError):
    """The Poincaré–Hopf sum (3-D) or minima − maxima (2-D) does not hold: an equilibrium is missing
    or mis-classified."""


def index_of(eigenvalues, along_null: int | None = None) -> int:
    """Index of a critical point on a surface from its Hessian eigenvalues (two), or, when one of
    them is zero, from the potential along the null direction: *along_null* = +1 for a local
    minimum there (even order, rising), -1 for a local maximum, 0 for an inflection (odd order).
    Then the index is ``along_null * sign(other eigenvalue)`` (+1 at a degenerate minimum or
    maximum, -1 at a degenerate saddle, 0 at a saddle-node)."""
    lam1, lam2 = eigenvalues
    if along_null is None:
        return 1 if lam1 * lam2 > 0 else -1
    other = lam1 if abs(lam1) > abs(lam2) else lam2
    return along_null * (1 if other > 0 else -1)
