"""Degenerate critical points on the sphere: their index and stability from the higher-order terms.

Where the second variation of the potential has a zero eigenvalue (to its error, after the
equilibrium has been polished at 30 digits), the Hessian decides nothing: a quartic minimum
(``y^2 + x^4``), a saddle-node (``y^2 + x^3``) and a monkey saddle (``Re (x + iy)^3``, both
eigenvalues zero: the cube's corner up at s = 1/6) all have singular Hessians.  Their index is the
winding number of the gradient on a small circle around the point (Poincaré): +1, 0, -2 for these
three, and in general the sum of the indices of whatever critical points the circle encloses, so
a cluster of equilibria closer together than their errors counts correctly as one.  Their stability
is read off the potential on the same circle: stable when it rises all the way round, unstable
when it falls somewhere.

The circle's radius is a third of the distance to the nearest other critical point found (no other
point inside it) and at most 3e-2 rad; on it the gradient must exceed the rounding of float64.
"""
from __future__ import annotations

import math

import numpy as np

from .local import local, tangent_step

__all__ = ["symmetric_point", "turning", "winding", "degenerate_class", "flat_cluster"]

MAX_RADIUS = 3e-2
NOISE = 1e-12           # relative to the size of the body: a gradient smaller than this is rounding


def symmetric_point(u, group, tol: float) -> np.ndarray:
    """The point of highest symmetry within *tol* of *u*: the mean of the images ``g u`` that lie
    within *tol* of *u* (the projection onto the fixed set of the symmetries that *u* has to within
    its error), repeated until that set of symmetries no longer grows."""
    u = np.asarray(u, dtype=float)
    v, count = u, 0
    for _ in range(4):
        near = [g @ v for g in group if np.linalg.norm(g @ v - v) <= tol]
        if len(near) == count:
            break
        count = len(near)
        mean = np.sum(near, axis=0)
        v = mean / np.linalg.norm(mean)
    return v if np.linalg.norm(v - u) <= tol else u


def _on_circle(poly, u, s, frame, rho, phi):
    loc = local(poly, tangent_step(u, rho * (math.cos(phi) * frame[:, 0] + math.sin(phi) * frame[:, 1])), s)
    g = frame.T @ (loc.basis @ loc.gradient)        # the gradient in the centre's tangent frame
    return math.atan2(g[1], g[0]), float(np.linalg.norm(g)), loc.U


def turning(evaluate, params, period: float, depth: int = 6):
    """``(winding number, least |grad U|, least and largest U)`` of the gradient around a closed contour
    with parameter ``t`` from ``params[0]`` to ``params[0] + period`` (counter-clockwise seen from outside
    the sphere), first at *params*: the turning of its direction, each piece divided at its middle
    wherever the direction turns by more than 45 degrees between its ends (at most *depth* times).
    ``evaluate(ts)`` gives ``(angle, |grad U|, U)`` at the contour's points for a list of parameters, the
    angle in one tangent frame for the whole contour (the centre's: the projection onto it is a
    trivialisation of the tangent bundle over the disc the contour bounds)."""
    values = evaluate(list(params))
    pieces = [(params[i], params[i + 1] if i + 1 < len(params) else params[0] + period,
               values[i], values[(i + 1) % len(params)], 0) for i in range(len(params))]
    turn, least, potentials = 0.0, math.inf, []
    while pieces:
        split = []
        for a, b, va, vb, level in pieces:
            delta = (vb[0] - va[0] + math.pi) % (2 * math.pi) - math.pi
            if abs(delta) > math.pi / 4 and level < depth:
                split.append((a, b, va, vb, level))
                continue
            turn += delta
            least = min(least, va[1])
            potentials.append(va[2])
        middles = evaluate([(a + b) / 2 for a, b, *_ in split]) if split else []
        pieces = [piece for (a, b, va, vb, level), vm in zip(split, middles)
                  for piece in ((a, (a + b) / 2, va, vm, level + 1), ((a + b) / 2, b, vm, vb, level + 1))]
    return round(turn / (2 * math.pi)), least, (min(potentials), max(potentials))


def winding(poly, u, s, rho: float, points: int = 24, depth: int = 6):
    """``(winding number, least |grad U|, least and largest U)`` of the gradient on the circle of radius
    *rho* around *u* (:func:`turning`, from *points* equally spaced points)."""
    frame = local(poly, u, s).basis
    return turning(lambda phis: [_on_circle(poly, u, s, frame, rho, phi) for phi in phis],
                   [2 * math.pi * k / points for k in range(points)], 2 * math.pi, depth)


def degenerate_class(poly, u, s, scale: float, others) -> tuple[int | None, str, float]:
    """``(index, stability, radius)`` of the degenerate critical point *u* from the circle around it
    whose radius is a third of the distance to the nearest of *others* (unit vectors: every copy of
    every other critical point, and the other copies of *u*), at most :data:`MAX_RADIUS`.  The index is
    None (and the stability ``indifferent``) where the gradient on that circle is rounding."""
    u = np.asarray(u, dtype=float)
    nearest = min((math.acos(max(-1.0, min(1.0, float(np.dot(u, v))))) for v in others), default=math.pi)
    rho = min(MAX_RADIUS, nearest / 3)
    turns, least, (low, high) = winding(poly, u, s, rho)
    if not least > NOISE * scale:
        return None, "indifferent", rho
    centre = local(poly, u, s).U
    floor = 1e-14 * scale
    if low < centre - floor:
        return turns, "unstable", rho
    return turns, ("stable" if low > centre + floor else "indifferent"), rho


def flat_cluster(c, points, group, scale: float, reach: float, flat: float):
    """The degenerate points of one short flat family around *c* (an arc of equilibria shorter than the
    solver reports as a family: the arc's ends and its middle, found as separate points): every other
    degenerate point of *points*, and every copy of *c* or of them, within *reach* radians of *c* whose
    potential equals c's to ``flat * scale``.  Returns ``(members, centre, extent)``: the points absorbed
    (not *c*), the most symmetric position within the cluster's extent (:func:`symmetric_point`; the
    middle of an arc cut by a mirror), the largest distance from it to a point of the cluster, and the
    cluster's length on the sphere ``2 asin(d / 2)``, ``d`` the largest distance between two of its points
    (the arc's ends: about ``16 delta sin theta`` for the cube at ``1/4 - delta``).  A
    circle around the centre wider than the extent encloses the whole family, and its winding is the
    family's index; a circle around one of its points cuts the family, where the gradient vanishes."""
    u = np.asarray(c.u, dtype=float)
    near = [g @ u for g in group]
    members = []
    for o in points:
        if o is c or abs(o.U - c.U) > flat * scale:
            continue
        images = [g @ np.asarray(o.u, dtype=float) for g in group]
        close = [v for v in images if np.linalg.norm(v - u) <= reach]
        if close:
            members.append(o)
            near += close
    near = [v for v in near if np.linalg.norm(v - u) <= reach]
    if len(near) < 2:
        return [], u, 0.0, 0.0
    extent = max(np.linalg.norm(v - u) for v in near)
    centre = symmetric_point(u, group, 2 * extent)
    extent = max(float(np.linalg.norm(v - centre)) for v in near)
    chord = max(float(np.linalg.norm(v - w)) for v in near for w in near)
    return members, centre, extent, 2 * math.asin(min(chord / 2, 1.0))
