"""Scenes and the equilibria a source predicts for them.

A *scene* is one concrete question: a body, its dimensions and its density
(water = 1).  A derivation that says where a body floats registers a
*predictor* (``Derivation.predicts``): given a scene it covers, it returns the
equilibria its printed formulas predict, each naming those formulas.  The
solver (:mod:`symfloat.solver`) finds every equilibrium independently and
reports, per equilibrium, which predictions match and whether they agree.

Body frame (the design brief's contract): the centroid is at the origin; the
box has edges ``dims = (a, b, c)`` along x, y, z; the prism over a regular
n-gon (side ``a``, length ``b``) and the cylinder (radius ``r``, length ``b``)
have their axis along z, the n-gon one vertex on the +x axis; a ``section``
is the cross-section of a long prism in the x-y plane (a 2-D problem: every
``up`` lies in that plane).  ``up`` is the unit vector, in the body frame,
that points vertically upwards.
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from ..manifest import KINDS

__all__ = ["BODIES", "STABILITIES", "FAMILIES", "Scene", "Prediction", "Predictor", "box_uprights"]

BODIES = ("cube", "box", "prism", "cylinder", "section")
STABILITIES = ("stable", "unstable", "indifferent")
FAMILIES = ("isolated", "ring")


@dataclass(frozen=True)
class Scene:
    """A validated scene: exact (rational) dimensions and density.

    ``dims``: cube ``(1, 1, 1)`` or ``(a, a, a)``; box ``(a, b, c)``; prism
    ``(a, b)`` with ``sides = n``; cylinder ``(r, b)``; section ``()`` with
    ``polygon`` the counter-clockwise vertices of a convex polygon.
    """

    body: str
    density: Fraction
    dims: tuple[Fraction, ...] = ()
    sides: int | None = None
    polygon: tuple[tuple[Fraction, Fraction], ...] = ()


@dataclass(frozen=True)
class Prediction:
    """One equilibrium as the printed formulas ``printed`` (names in the module) predict it.

    ``up`` is one representative (body frame, need not be normalised);
    ``family`` is ``ring`` for a one-parameter family of equal potential.
    ``stability`` is the source's claim; ``None`` when it claims none.
    """

    printed: tuple[str, ...]
    up: tuple[float, float, float]
    stability: str | None
    family: str = "isolated"
    note: str = ""

    def __post_init__(self):
        if not self.printed:
            raise ValueError("a prediction names at least one printed formula")
        if self.stability is not None and self.stability not in STABILITIES:
            raise ValueError(f"unknown stability {self.stability!r}")
        if self.family not in FAMILIES:
            raise ValueError(f"unknown family {self.family!r}")


@dataclass(frozen=True)
class Predictor:
    """The bodies a derivation speaks about and its prediction function ``predict(scene)``."""

    bodies: tuple[str, ...]
    predict: object

    def __post_init__(self):
        unknown = [b for b in self.bodies if b not in KINDS]
        if unknown:
            raise ValueError(f"unknown bodies {unknown}; known: {KINDS}")


def box_uprights(dims):
    """The upright positions of a box, one per class of equal shape: ``(k, i, j)`` with edge ``k``
    vertical and the base spanned by edges ``i < j``."""
    seen = set()
    for k in range(3):
        i, j = [m for m in range(3) if m != k]
        key = (dims[k], tuple(sorted((dims[i], dims[j]))))
        if key not in seen:
            seen.add(key)
            yield k, i, j
