"""The Poincaré–Hopf index of a one-parameter family of equilibria (an arc or a ring on the sphere).

The index of a connected set of critical points is the winding number of the gradient on a closed
curve that encloses it and no other critical point (Poincaré; its sum over the sphere is 2).

* An **arc** (a segment of equilibria, contractible): the curve is a *stadium*, the walked points of
  the arc (:func:`~symfloat.solver.critical.trace_family`) offset by ``rho`` to either side and joined
  by half circles round its ends.  Transversally stable, it counts +1 where the potential rises past both
  ends, -1 where it falls past both (the box 1 x 3/2 x 1 at s = 0.081949: the arcs round the faces'
  directions, each -1, with the stable diagonal class between them), 0 where it rises past one end only.
* A closed **ring** (Morse–Bott: a circle, Euler characteristic 0): the curves ``rho`` to either side of
  it bound an annulus, and its index is the winding on the outer one less that on the inner one (both
  counter-clockwise), measured rather than assumed (0 for a ring that is non-degenerate across).

``rho`` is a third of the distance from the family's walked points to the nearest other equilibrium (every
copy of every other class, and the other copies of the family), at most :data:`MAX_RADIUS` (and half a
closed ring's radius); the gradient is
projected onto the tangent plane at the family's middle (an arc: its mean point; a ring: its axis), which
needs the whole curve within 84 degrees of it; on the curve the gradient must exceed rounding
(:data:`~symfloat.solver.degenerate.NOISE`).  Otherwise the index is None: the check cannot be made.
Cost: one batched evaluation of the floating states at the curve's points (two to three per walked point,
more where the gradient turns fast), 4 to 13 ms of processor time a family in tests/test_solver_families.py.
"""
from __future__ import annotations

import math

import numpy as np

from .degenerate import MAX_RADIUS, NOISE, turning
from .edgewise import states
from .local import tangent_step

__all__ = ["family_index", "family_seeds", "contour_winding", "stadium", "offset"]

CAP = 12            # points on each half circle round an arc's end
REACH = 0.1         # the least cosine between the projection's centre and a point of the curve (84 degrees)


def _frame(path, closed: bool):
    """Unit tangents ``t`` and normals ``n = p x t`` (so ``(t, n)`` is positive seen from outside) at the
    walked points *path* (central differences; one-sided at an arc's ends)."""
    p = np.asarray(path, dtype=float)
    if closed:
        d = np.roll(p, -1, axis=0) - np.roll(p, 1, axis=0)
    else:
        d = np.gradient(p, axis=0) if len(p) > 2 else np.repeat([p[-1] - p[0]], len(p), axis=0)
    d -= np.sum(d * p, axis=1)[:, None] * p
    t = d / np.linalg.norm(d, axis=1)[:, None]
    return t, np.cross(p, t)


def offset(path, rho: float, closed: bool) -> np.ndarray:
    """The walked points moved by *rho* radians along their normals (negative: to the other side)."""
    p = np.asarray(path, dtype=float)
    _, n = _frame(p, closed)
    return np.array([tangent_step(q, rho * v) for q, v in zip(p, n)])


def stadium(path, rho: float) -> np.ndarray:
    """The closed curve round an arc (its walked points *path*, in order) at distance *rho*,
    counter-clockwise seen from outside the sphere: along the right side (``-n``) from the first point
    to the last, half round the last, back along the left side, half round the first."""
    p = np.asarray(path, dtype=float)
    t, n = _frame(p, False)
    angles = [math.pi * k / CAP for k in range(1, CAP)]
    ahead = [tangent_step(p[-1], rho * (-math.cos(a) * n[-1] + math.sin(a) * t[-1])) for a in angles]
    behind = [tangent_step(p[0], rho * (math.cos(a) * n[0] - math.sin(a) * t[0])) for a in angles]
    right = [tangent_step(q, -rho * v) for q, v in zip(p, n)]
    left = [tangent_step(q, rho * v) for q, v in zip(p, n)]
    return np.array(right + ahead + left[::-1] + behind)


def contour_winding(curve, centre, gradient):
    """:func:`~symfloat.solver.degenerate.turning` on the closed polygon *curve* (unit vectors,
    counter-clockwise seen from outside; between them the chords, normalised), the gradient projected onto
    the tangent plane at *centre*; ``gradient(points)`` gives the gradients (3-vectors) and potentials at an
    array of points.  None where a point lies more than 84 degrees from the centre."""
    curve = np.asarray(curve, dtype=float)
    if np.min(curve @ centre) < REACH:
        return None
    helper = np.eye(3)[int(np.argmin(np.abs(centre)))]
    f1 = np.cross(helper, centre)
    f1 /= np.linalg.norm(f1)
    frame = np.stack([f1, np.cross(centre, f1)], axis=1)       # f1 x f2 = centre: positive seen from outside
    closed = np.vstack([curve, curve[:1]])
    lengths = np.linalg.norm(np.diff(closed, axis=0), axis=1)
    params = np.concatenate([[0.0], np.cumsum(lengths)])
    period = float(params[-1])

    def at(t):
        k = min(int(np.searchsorted(params, t, side="right")) - 1, len(curve) - 1)
        w = (t - params[k]) / lengths[k] if lengths[k] > 0 else 0.0
        q = (1 - w) * closed[k] + w * closed[k + 1]
        return q / np.linalg.norm(q)

    def evaluate(ts):
        g, potentials = gradient(np.array([at(t % period) for t in ts]))
        g = np.asarray(g) @ frame
        return [(math.atan2(b, a), math.hypot(a, b), float(U)) for (a, b), U in zip(g, potentials)]

    return turning(evaluate, list(params[:-1]), period)


def _gradient(poly, s):
    """The gradients (3-vectors) and potentials of *poly* at density *s* at an array of up vectors, evaluated
    together (:func:`~symfloat.solver.edgewise.states`), up to a positive factor.  Above s = 1/2 they are
    those of the dual body: the part below the waterplane at 1 - s with up ``-u`` is the complement of the part
    at s with up ``u``, so ``grad U_s(u) = -(s' / s) grad U_s'(-u)`` and ``U_s(u) = (s' / s) U_s'(-u)`` with
    ``s' = 1 - s`` (exact; checked in tests/test_solver_families.py).  At s near 1 the float64 gradient is the
    small difference of two centroids that nearly coincide, at 1 - s it is not: the long square log at
    1 - 0.0105465 has a gradient 100 times smaller than at 0.0105465, with the same rounding, and the winding
    round its arcs was rounding there."""
    dual = s > 0.5

    def gradient(points):
        points = -np.asarray(points, dtype=float) if dual else points
        st = states(poly, points, 1 - s if dual else s)
        g = np.einsum("mkj,mj->mk", st.basis, np.einsum("mkj,mk->mj", st.basis, st.G - st.B))
        return (-g if dual else g), st.potential
    return gradient


def _distance(path, points) -> float:
    """The least angle between a walked point of a family and one of *points*."""
    if not len(points):
        return math.pi
    return float(np.arccos(np.clip(np.max(np.asarray(path) @ np.asarray(points).T), -1.0, 1.0)))


def family_index(poly, s, c, others, scale: float) -> tuple[int | None, float]:
    """``(index, rho)`` of the family *c* (a :class:`~symfloat.solver.critical.Critical` with its walked
    ``path``; ``shape`` "arc" or "closed", a closed ring with its ``axis``) from the curves at ``rho``
    round it (module docstring); *others*: unit vectors of every other equilibrium and of the other copies
    of the family.  The index is None where the gradient on a curve is rounding or a curve reaches too far
    from its centre."""
    path = np.asarray(c.path, dtype=float)
    if len(path) < 3 or np.min(np.linalg.norm(np.diff(path, axis=0), axis=1)) == 0:
        return None, 0.0            # too few distinct walked points for a curve round it
    rho = min(MAX_RADIUS, _distance(path, others) / 3)
    if c.shape == "closed":
        rho = min(rho, c.length / (4 * math.pi))       # the inner curve stays on its side of the axis, found or not
        # walked along t, the annulus lies left of the curve on the right (-n) and right of the one on the left
        right, left = (contour_winding(offset(path, sign * rho, True), c.axis, _gradient(poly, s)) for sign in (-1, 1))
        if right is None or left is None or not min(right[1], left[1]) > NOISE * scale:
            return None, rho
        return right[0] - left[0], rho
    centre = path.mean(axis=0)
    turns = contour_winding(stadium(path, rho), centre / np.linalg.norm(centre), _gradient(poly, s))
    if turns is None or not turns[1] > NOISE * scale:
        return None, rho
    return turns[0], rho


def family_seeds(c, steps=(1e-3, 3e-3, 1e-2, 3e-2), samples: int = 24) -> list[np.ndarray]:
    """Seeds for the search next to the family *c* when the index sum fails: from up to *samples* of its
    walked points, *steps* radians to either side along the normal; past an arc's ends along its tangent
    (a class in a gap of the family narrower than the walk's step, or beyond its end); a closed ring's
    axis (the position it was born from, which it surrounds)."""
    path = np.asarray(c.path, dtype=float)
    closed = c.shape == "closed"
    t, n = _frame(path, closed)
    pick = np.unique(np.linspace(0, len(path) - 1, min(samples, len(path))).round().astype(int))
    seeds = [tangent_step(path[k], sign * h * n[k]) for k in pick for h in steps for sign in (1, -1)]
    if closed:
        return seeds + [np.asarray(c.axis, dtype=float)]
    return seeds + [tangent_step(path[k], sign * h * t[k]) for k, sign in ((-1, 1), (0, -1))
                    for h in steps + (6e-2,)]
