"""All equilibria of a floating homogeneous body at one density, classified.

* cube, box, regular prism: Newton's method on the sphere from seeds covering
  the symmetry group's fundamental domain (:mod:`symfloat.solver.critical`),
  completeness checked by the Poincaré–Hopf index sum, a ring or an arc of
  equilibria counted with the winding round it (:mod:`symfloat.solver.families`);
* section (long prism): the heel angle in the cross-section's plane, every
  root of ``U'`` (:mod:`symfloat.solver.planar`);
* cylinder: the tilt in the meridian plane (the rotations about the axis are
  a continuous symmetry), from slice quadrature (:mod:`symfloat.geometry.cylinder`).

Stability: ``stable`` when every eigenvalue of the metacentric matrix
``T/V - U`` (the second variation of the potential) is positive,
``unstable`` when one is negative, ``indifferent`` when the smallest is zero to
the working accuracy and the equilibrium is not a ring.  A ring is reported
once; its stability is that of the direction across it.

At a position a symmetry of the body fixes (face, edge, corner or axis up) the stability is decided
exactly (:mod:`~symfloat.solver.exact`), and a family born there is located from the local expansion
(:mod:`~symfloat.solver.born`); the float64 search's view of both gives way to them.

Next to a bifurcation a position whose smallest eigenvalue float64 cannot
decide is polished at 30 digits (:func:`~symfloat.solver.refine.polish`);
where even that decides nothing the higher orders do
(:mod:`~symfloat.solver.degenerate`: the winding of the gradient and the
potential on a circle around it), and the position carries that index into
the check.  A check that still fails is an error (:class:`IndexCheckError`).
"""
from __future__ import annotations

import functools
import math
import time
from dataclasses import dataclass, field
from fractions import Fraction

import mpmath
import numpy as np

from ..model.prediction import Scene
from .bodies import centred_polygon, polyhedron
from .born import SOFT_AXIS, born_families
from .critical import Critical, critical_points, distinct_seeds, more_seeds, poincare_hopf_sum, sphere_seeds
from .errors import ROUNDING, STEP, eigenvalue_error, equilibrium_error
from .exact import symmetric_positions
from .critical import FLAT, MIN_FAMILY
from .degenerate import degenerate_class, flat_cluster
from .families import family_index, family_seeds
from .local import local, waterplane_polygon
from .planar import roots
from .refine import planar_potential, planar_residual, planar_slope, polish_planar
from .selfcheck import IndexCheckError
from .symmetry import box_group, orbit, planar_group, prism_group, representative, same_class
from .vertex import EVENT_DIGITS, event_digits, lateral_arc, vertex_depths

__all__ = ["Equilibrium", "Solution", "solve", "stability_of", "body_scale"]

SOFT = 1e-4     # relative to the size of the body: an eigenvalue this small means a bifurcation is near


@dataclass
class Equilibrium:
    """One symmetry class of equilibria (see the design brief's scene contract)."""
    up: tuple
    tilt_deg: float
    stability: str
    family: str
    potential: float
    waterplane: str
    eigenvalues: tuple
    error_rad: float
    error_method: str
    copies: int | None          # symmetric copies of the position; None for a continuous orbit
    ring_shape: str = ""        # a ring: "closed" (all the way round) or "arc" (a piece of one)
    ring_length: float = 0.0    # its length on the unit sphere of up vectors (radians)
    ring_length_error: float = 0.0  # the error of that length (the brackets of its ends: bisected on the body where
                                    # it is a piece of a ring round a prism's axis, else the walk's last step, chords)
    stability_evidence: str = "second variation"     # or "higher orders", or "undecided"
    digits: tuple = ()          # the up vector at 30 digits (mpf) where the solver polished it (next to a bifurcation)
    decided: str = ""           # how the second variation's signs were decided where not in float64 (exact, digits)
    formulas: list = field(default_factory=list)
    predictions: list = field(default_factory=list)
    certificate: object = None  # what ball arithmetic proved (symfloat.solver.certificate), where it was asked


@dataclass
class Solution:
    scene: Scene
    equilibria: list
    checks: dict
    seconds: float


def body_scale(scene: Scene) -> float:
    if scene.body == "section":
        return float(max(max(abs(x), abs(y)) for x, y in centred_polygon(scene)))
    return float(max(scene.dims))


def stability_of(eigenvalues, tolerance: float, ring: bool = False) -> str:
    """``stable`` / ``unstable`` when the smallest eigenvalue of the second variation (across a
    ring: the larger one) exceeds *tolerance* in size, else ``indifferent``."""
    values = sorted(eigenvalues, key=abs)[1:] if ring else list(eigenvalues)
    if min(values) > tolerance:
        return "stable"
    if min(values) < -tolerance:
        return "unstable"
    return "indifferent"


def null_sides(change, scale: float, rounding: float = 1e-13) -> tuple:
    """How the potential behaves on each side of a null direction of the second variation, from its
    change ``change(eps)`` at eps = +-1e-3, +-3e-3, +-1e-2 rad: per side +1 when it rises at every
    step, -1 when it falls at every step, None when it is flat to *rounding* (relative to *scale*:
    float64's, or a smaller one where the change is evaluated in mpmath) or mixed."""
    floor = rounding * scale
    sides = []
    for sign in (1, -1):
        changes = [change(sign * eps) for eps in (1e-3, 3e-3, 1e-2)]
        sides.append(1 if min(changes) > floor else -1 if max(changes) < -floor else None)
    return tuple(sides)


def null_index(sides) -> int | None:
    """+1 for a minimum along the null direction, -1 for a maximum, 0 for an inflection (odd
    order), None when a side is flat to rounding."""
    if None in sides:
        return None
    return sides[0] if sides[0] == sides[1] else 0


def higher_order(sides, others) -> str:
    """Stability where the second variation vanishes in one direction (*sides* from
    :func:`null_sides`): unstable when the potential falls along it on either side or another
    eigenvalue is negative, stable when it rises on both sides and the others are positive, else
    indifferent (flat to rounding: the higher orders decide nothing at these steps)."""
    if -1 in sides or any(e < 0 for e in others):
        return "unstable"
    return "stable" if sides == (1, 1) else "indifferent"


def _clean(u) -> tuple:
    """The unit vector with rounding noise below 1e-14 set to zero (exact zeros of symmetric
    positions print as zeros)."""
    return tuple(float(x) if abs(x) > 1e-14 else 0.0 for x in u)


def _tilt(u) -> float:
    """The angle from +z (degrees), as ``atan2(|(x, y)|, z)``: ``acos z`` loses ``1e-16 / sin(tilt)`` to the
    rounding of ``z`` (1e-12 rad at a ring of tilt 1e-4)."""
    return math.degrees(math.atan2(math.hypot(float(u[0]), float(u[1])), float(u[2])))


def _shape(vertices: list, scale: float) -> str:
    """Name of a convex waterplane polygon from its distinct, non-collinear vertices."""
    pts = []
    for p in vertices:
        if not pts or np.linalg.norm(p - pts[-1]) > 1e-9 * scale:
            pts.append(p)
    if len(pts) > 1 and np.linalg.norm(pts[0] - pts[-1]) <= 1e-9 * scale:
        pts.pop()
    corners = []
    n = len(pts)
    for i in range(n):
        a, b, c = pts[i - 1], pts[i], pts[(i + 1) % n]
        if np.linalg.norm(np.cross(b - a, c - b)) > 1e-9 * scale * scale:
            corners.append(b)
    k = len(corners)
    names = {3: "triangle", 5: "pentagon", 6: "hexagon", 7: "heptagon", 8: "octagon"}
    if k == 4:
        edges = [corners[(i + 1) % 4] - corners[i] for i in range(4)]
        right = all(abs(np.dot(edges[i], edges[(i + 1) % 4])) <= 1e-9 * scale * scale for i in range(4))
        equal = abs(np.linalg.norm(edges[0]) - np.linalg.norm(edges[1])) <= 1e-9 * scale
        if right:
            return "square" if equal else "rectangle"
        parallel = [np.linalg.norm(np.cross(edges[i], edges[i + 2])) <= 1e-9 * scale * scale for i in range(2)]
        if all(parallel):
            return "rhombus" if equal else "parallelogram"
        return "trapezoid" if any(parallel) else "quadrilateral"
    return names.get(k, f"{k}-gon")


def _classified(poly, points, s, scale, group):
    """Stability, its evidence and (for degenerate points) the index of every isolated point: from the
    second variation at the polished point (:func:`~symfloat.solver.critical.critical_points`) or,
    where an eigenvalue is zero to its error, from the higher orders (:mod:`~symfloat.solver.degenerate`).
    Degenerate points of one flat arc too short to be reported as a family (next to its birth or end:
    the box 1 x 3/2 x 1 at s = 1/12 - 1e-6, Scheeffer VI (78d)) are one class, an arc
    (:func:`~symfloat.solver.degenerate.flat_cluster`); the points returned are the classes."""
    out, absorbed = [], []
    for c in points:
        if any(c is a for a in absorbed):
            continue
        stability, evidence = stability_of(c.eigen, c.eigen_error, c.ring), "second variation"
        across = "indifferent"
        if stability == "indifferent" and not c.ring:
            others = [g @ o.u for o in points if o is not c for g in group]
            others += [v for v in orbit(c.u, group) if np.linalg.norm(v - c.u) > 1e-9]
            c.index, stability, _ = degenerate_class(poly, c.u, s, scale, others)
            members, centre, extent, length = flat_cluster(c, [o for o in points if not o.ring and o.exact is None],
                                                           group, scale, 2 * MIN_FAMILY, FLAT)
            if extent:
                # a flat arc shorter than a reported family, found as several points: one class, its index
                # from a circle around its symmetric middle enclosing all of it, its stability (as a
                # family's) that of the direction across it, where the second variation decides it
                rest = [g @ o.u for o in points if o is not c and not any(o is m for m in members) for g in group]
                rest += [v for v in orbit(centre, group, 2 * extent + 1e-12) if np.linalg.norm(v - centre) > 2 * extent]
                index, family, rho = degenerate_class(poly, centre, s, scale, rest)
                if rho > 3 * extent:
                    absorbed += members
                    across = stability_of(c.eigen, c.eigen_error, ring=True)
                    c.index, stability = index, family if across == "indifferent" else across
                    # reported as the arc it is (the cube at 1/4 - delta: 16 delta sin(theta) long): it holds the
                    # points found and lies inside the circle of radius rho round its middle (the gradient winds
                    # there without vanishing), so its length lies between their distance and about 2 rho (the
                    # circle's diameter, rho far below the radius of the ring the arc lies on); below float64's
                    # resolution the points found need not be its ends (the cube at 1/4 - 1e-9: 2.4e-11 apart); an
                    # arc of a ring round a prism's axis is then located on the body (:func:`lateral_arc`)
                    c.shape, c.length = "arc", length
                    c.length_error = max(2 * rho - length, 2 * max([c.error_rad] + [m.error_rad for m in members]))
                    c.digits = c.digits if np.linalg.norm(centre - c.u) == 0 else ()
                    c.u, c.error_rad = centre, max(c.error_rad, extent)
                    c.orbit = len(orbit(centre, group, 2 * extent + 1e-12))
            evidence = "second variation" if across != "indifferent" else \
                "higher orders" if c.index is not None else "undecided"
            c.flat = c.index is None
        out.append((c, stability, evidence))
    return [x for x in out if not any(x[0] is a for a in absorbed)]


def _searched(poly, s, seeds, group, scale, fixed=(), event_dps: int = 0):
    """Critical points from *seeds*; when the Poincaré–Hopf sum fails, a second search (separatrices,
    soft directions, small gradient: :func:`more_seeds`; next to every family, across it and past its ends:
    :func:`family_seeds`), then continuation from the neighbouring densities ``s +- 1e-4 s(1 - s)`` (every
    critical point there, tracked to *s* by Newton's method) and from the dual scene (the equilibria at
    ``1 - s``, turned upside down: ``u -> -u``); *event_dps*: the digits that decide a class beside a ring just
    past a vertex event (:func:`~symfloat.solver.vertex.event_digits`).  Returns the points with their classification, the
    searches made and the index sum (None where it cannot be made)."""
    searches = ["seeds"]
    points = _symmetric(critical_points(poly, s, seeds, group, scale, event_dps=event_dps), fixed, poly, s, group,
                        scale)
    classified = _classified(poly, points, s, scale, group)
    points = [c for c, _, _ in classified]
    index = _index_sum(poly, s, points, group, scale)
    if _holds(index, points, scale):
        return classified, searches, index
    extra = [c.u for c in points] + more_seeds(poly, s, points, group, scale) + _near_families(points)
    points = _symmetric(critical_points(poly, s, extra, group, scale, event_dps=event_dps), fixed, poly, s, group,
                        scale)
    classified = _classified(poly, points, s, scale, group)
    points = [c for c, _, _ in classified]
    index = _index_sum(poly, s, points, group, scale)
    searches.append("separatrices, soft directions, small gradient and next to families")
    if _holds(index, points):
        return classified, searches, index
    step = Fraction(1, 10 ** 4) * min(s, 1 - s)
    for near in (s + step, s - step) + ((1 - s,) if 1 - s != s else ()):
        there = critical_points(poly, near, seeds, group, scale)
        found = [c.u for c in there] + more_seeds(poly, near, there, group, scale) + _near_families(there)
        extra += [-u for u in found] if near == 1 - s else found
    points = _symmetric(critical_points(poly, s, extra, group, scale, event_dps=event_dps), fixed, poly, s, group,
                        scale)
    classified = _classified(poly, points, s, scale, group)
    points = [c for c, _, _ in classified]
    index = _index_sum(poly, s, points, group, scale)
    searches.append("continuation from s +- 1e-4 s(1 - s) and from the dual scene at 1 - s")
    return classified, searches, index


def _symmetric(points, fixed, poly, s, group, scale) -> list:
    """*points* with every position a symmetry fixes (*fixed*: ``(u, exact, born, prism)`` from
    :func:`~symfloat.solver.exact.symmetric_positions` and :func:`~symfloat.solver.born.born_families`) in
    place of the isolated points found within their error of it (at most 1e-6: a float64 point there, or one polished
    onto a family being born beside it, whose eigenvalues were not the position's: the cube 1e-9 past its
    face-up pitchfork at 1/2 - sqrt(3)/6), carrying its exact second variation; and the equilibria born
    there, located at 30 digits or more, in place of what the search found of them (a ring around it
    closer than float64 resolves is seen as points, arcs or nothing)."""
    out = list(points)
    for u, exact, born, prism in fixed:
        # next to a soft position (its eigenvalue small but decided) float64 points within 1e-6 of it are its
        # rounding (the hexagonal prism 1 x 1 1e-9 below its lateral face's threshold 0.0689685: a copy 1e-8 off
        # both mirrors, counted 12 times); the equilibria born there are the scan's (born_families)
        soft = min(abs(e) for e in exact.eigenvalues) < SOFT_AXIS * scale
        out = [c for c in out if c.ring or not same_class(c.u, u, group, 1e-6 if soft else
                                                          min(max(2 * c.error_rad, 1e-9), 1e-6))]
        out.append(Critical(representative(u, group), local(poly, u, s).U, exact.eigenvalues, 0.0, 0.0,
                            len(orbit(u, group)), error_method="exact", exact=exact))
        for b in born:
            if not b.ring and any(same_class(b.u, v, group, 2 * b.error_rad + 1e-6) for v, _, _, _ in fixed):
                # a change of sign that is another position symmetry fixes, whose exact second variation stands:
                # the neighbour within reach of a soft one (the prism over a regular 32-gon lying, its face down
                # and its edge down pi/32 apart, each found born at the other and counted twice)
                continue
            # the float64 search's view of a family born here (points on it, pieces of it, or the ring walked
            # at float64's resolution) gives way to the family located at its exact radius
            if b.ring:
                # a point within a quarter of its radius of it and inside the disc where the waterplane meets
                # the lateral faces only (the potential depends on the tilt alone there, so nothing but circles
                # of equilibria lies there, and the next is not that close), a family that meets it there (a
                # connected set of equilibria meeting the ring is part of it)
                radius, (R, L) = b.length / (2 * math.pi), prism
                lateral = math.atan(L * float(min(s, 1 - s)) / R)
                out = [c for c in out if c.exact is not None
                       or not any(abs(_angle_to(p, b.axis, group) - radius) <= radius / 4
                                  and _angle_to(p, b.axis, group) < lateral for p in (c.path if c.ring else [c.u]))]
            else:
                out = [c for c in out if c.ring or c.exact is not None
                       or not same_class(c.u, b.u, group, 2 * c.error_rad + 1e-6)]
            out.append(b)
    out.sort(key=lambda c: (round(c.U / scale, 12), -c.u[2], -c.u[0], -c.u[1]))
    return out


def _angle_to(u, axis, group) -> float:
    """The least angle between *u* and a copy of *axis*."""
    return float(np.arccos(np.clip(np.max(np.asarray(group, dtype=float) @ np.asarray(axis, dtype=float) @ np.asarray(u)),
                                   -1.0, 1.0)))


def _near_families(points) -> list:
    """Seeds next to every family among *points* (:func:`~symfloat.solver.families.family_seeds`)."""
    return [v for c in points if c.ring for v in family_seeds(c)]


def _index_sum(poly, s, points, group, scale):
    """The Poincaré–Hopf sum, a family counted with the winding of the gradient round it
    (:func:`~symfloat.solver.families.family_index`), or None where it cannot be made: a degenerate point
    whose gradient on every circle around it is rounding (:attr:`Critical.flat`), a family whose curve
    meets rounding or reaches too far."""
    if any(c.flat for c in points):
        return None
    for c in points:
        if c.ring and c.index is None:
            c.index, _ = family_index(poly, s, c, _around(c, points, group), scale)
    if any(c.ring and c.index is None for c in points):
        return None
    return poincare_hopf_sum(points)


def _around(c, points, group) -> np.ndarray:
    """Unit vectors of the equilibria round the family *c*: every copy of every other class (of a family,
    its walked points), and the copies of *c* that are other families (their ends, or a closed ring's
    axis, elsewhere)."""
    G = np.asarray(group, dtype=float)
    out = [np.einsum("kij,mj->kmi", G, np.asarray(o.path if o.ring else [o.u], dtype=float)).reshape(-1, 3)
           for o in points if o is not c]
    key = np.array([c.axis] if c.shape == "closed" else [c.path[0], c.path[-1]], dtype=float)
    path = np.asarray(c.path, dtype=float)
    for g in G:
        image = key @ g.T
        same = np.linalg.norm(image - key) <= 1e-3 or (
            len(key) == 2 and np.linalg.norm(image[::-1] - key) <= 1e-3)
        if not same:
            out.append(path @ g.T)
    return np.vstack(out) if out else np.zeros((0, 3))


def _holds(index, points, scale: float = 0.0) -> bool:
    """Whether the index check passes: the sum (families included) is 2.  With *scale*, also whether no
    isolated point is nearly degenerate (its smallest eigenvalue below ``SOFT * scale`` but decided: next to
    a bifurcation, not at it) and none on an axis of order >= 3 is soft (:func:`_isotropic_soft`), where a
    ring of index 0 may be born beside it, which no index sum sees: the search goes on there (soft
    directions, small gradient)."""
    if scale and any(not c.ring and c.index is None and min(abs(e) for e in c.eigen) < SOFT * scale for c in points):
        return False
    if scale and any(not c.ring and _isotropic_soft(c, scale) for c in points):
        return False
    return index == 2


def _isotropic_soft(c, scale: float) -> bool:
    """An isolated point on an axis of order >= 3 (its two eigenvalues equal) that is soft (below ``1e-2 *
    scale``): a ring born there has index 0 and radius ~ sqrt(lambda), beyond the first seeds (the long
    square log at 0.01054, a ring of radius 0.048 rad around its end face, lambda = -0.0023, was missed
    with the sum closing without it)."""
    a, b = c.eigen
    return abs(a - b) <= 1e-9 * scale and abs(a) < 1e-2 * scale


def _polyhedral(scene: Scene, seeds, group):
    poly = polyhedron(scene)
    scale = body_scale(scene)
    s = scene.density
    seeds = distinct_seeds(seeds, group)
    fixed = [(u, exact, born_families(scene, poly, u, exact, group, scale, _prism_axis(scene, n)), _prism_axis(scene, n))
             for u, n, exact in symmetric_positions(scene, group)]
    digits = event_digits(scene, scale)
    if digits > EVENT_DIGITS:
        raise IndexCheckError(f"{_name(scene)}: a ring of equilibria is past the density where a vertex reaches its "
                              f"waterplane by less than {EVENT_DIGITS} digits resolve: the class between its arcs "
                              f"cannot be decided")
    classified, searches, index = _searched(poly, s, seeds, group, scale, fixed, digits)
    _unbroken(scene, [c for c, _, _ in classified], group)
    if index is None and any(c.flat for c, _, _ in classified):
        flat = next(c for c, _, _ in classified if c.flat)
        raise IndexCheckError(f"{_name(scene)}: the index of the degenerate equilibrium at up "
                              f"{tuple(round(float(x), 9) for x in flat.u)} cannot be decided (its gradient is "
                              f"rounding on the largest circle around it that encloses no other equilibrium) after {len(searches)} searches "
                              f"({'; '.join(searches)}): the Poincaré–Hopf check cannot be made")
    families = [c for c, _, _ in classified if c.ring]
    named = "; families: " + ", ".join(
        f"{'ring' if c.shape == 'closed' else 'arc'} through up {tuple(round(float(x), 6) for x in c.u)} x{c.orbit} "
        f"(length {c.length:.4g} rad, index {'undecided' if c.index is None else c.index})"
        for c in families) if families else ""
    if index is None:
        raise IndexCheckError(f"{_name(scene)}: the index of a family cannot be made (the gradient is rounding on "
                              f"the curve round it, or the curve reaches more than 84 degrees from its middle) "
                              f"after {len(searches)} searches ({'; '.join(searches)}): the Poincaré–Hopf check "
                              f"cannot be made{named}")
    if index != 2:
        soft = [c for c, _, _ in classified if not c.ring and min(abs(e) for e in c.eigen) < 1e-2 * scale]
        near = "; next to a bifurcation (smallest eigenvalue below 1e-2 of the size): " + ", ".join(
            f"up {tuple(round(float(x), 6) for x in c.u)} x{c.orbit} (eigenvalues "
            f"{', '.join(f'{float(e):.2e}' for e in c.eigen)})" for c in soft) if soft else ""
        raise IndexCheckError(f"{_name(scene)}: the Poincaré–Hopf index sum of the equilibria found is {index}, "
                              f"not 2, after {len(searches)} searches ({'; '.join(searches)}): an equilibrium is "
                              f"missing or mis-classified{near}{named}")
    out = []
    for c, stability, evidence in classified:
        # from the middle of the walk (its start, the representative, may lie past an end by more than the walk's
        # last step: the potential falls there by the cut corner's cube, below float64; the cube at 1/4 - 1e-3)
        middle = c.path[len(c.path) // 2] if len(c.path) > 2 else c.u
        located = lateral_arc(scene, middle, 2 * c.error_rad + 1e-9) if c.shape == "arc" else None
        if located:
            c.length, c.length_error = located      # its ends located on the body, not by the walk's last step
        loc = local(poly, c.u, s)
        out.append(Equilibrium(_clean(c.u), _tilt(c.u), stability,
                               "ring" if c.ring or c.shape == "arc" else "isolated", c.U, _shape(waterplane_polygon(poly, loc.state), scale),
                               tuple(float(e) for e in c.eigen), c.error_rad, c.error_method, c.orbit,
                               c.shape, c.length, c.length_error, evidence, digits=c.digits, decided=_decided(c)))
    return out, {"poincare_hopf_index_sum": index, "expected_index_sum": 2, "seeds": len(seeds),
                 "searches": searches,
                 **({"family_indices": [c.index for c in families]} if families else {})}


def _unbroken(scene: Scene, points, group) -> None:
    """A self-check: past a vertex event (:mod:`~symfloat.solver.vertex`) the ring round that axis at its tilt
    ``theta*`` is arcs, so a closed ring there (its length ``2 pi sin theta*`` to 1e-3) is a class between the arcs
    that the digits did not decide (an error, exit status 1)."""
    G = np.asarray(group, dtype=float)
    for axis, depth, theta in vertex_depths(scene):
        if depth <= 0:
            continue
        images = G @ np.asarray(axis, dtype=float)
        for c in points:
            if c.ring and c.shape == "closed" and np.min(np.linalg.norm(images - c.axis, axis=1)) <= 1e-6 \
                    and abs(c.length - 2 * math.pi * math.sin(float(theta))) <= 1e-3:
                raise IndexCheckError(f"{_name(scene)}: the ring round up {axis} is walked closed, but a vertex lies "
                                      f"{float(depth):.3g} beyond its waterplane (past the vertex event): the arcs "
                                      f"and the class between them are not resolved")


def _decided(c) -> str:
    """How the signs of the second variation of *c* were decided, where float64 did not: exactly at a position
    symmetry fixes (its draught rational or algebraic), at 30 digits or more (a prism lying), or from the
    change of sign of the slope along a mirror (a family born at such a position)."""
    if c.exact is not None:
        kind = c.exact.draught
        return f"at {kind}" if kind.endswith("digits") else f"exactly (draught {kind})"
    return "change of sign along a mirror, at 30 digits or more" if c.error_method == "sign change" else ""


def _prism_axis(scene: Scene, n) -> tuple | None:
    """``(R, L)`` where the integer direction *n* is the axis of the body as a right prism (a prism's axis,
    a box's face normal): the circumradius of its base and its length; else None."""
    if scene.body == "prism":
        return (float(scene.dims[0]) / (2 * math.sin(math.pi / scene.sides)), float(scene.dims[1])) if n == (0, 0, 1) else None
    if n is None or sum(1 for x in n if x) != 1:
        return None
    k = next(i for i, x in enumerate(n) if x)
    base = [float(scene.dims[i]) for i in range(3) if i != k]
    return math.hypot(*base) / 2, float(scene.dims[k])


def _name(scene: Scene) -> str:
    dims = ",".join(str(d) for d in scene.dims) if scene.dims else " ".join(f"{x},{y}" for x, y in scene.polygon)
    return f"{scene.body} ({dims}) at density {scene.density}"


def _section(scene: Scene):
    """The 2-D problem: ``u = (cos theta, sin theta, 0)``, ``U'' = I/V - U``."""
    poly = polyhedron(scene)
    scale = body_scale(scene)
    s = scene.density
    group = planar_group(centred_polygon(scene))

    def evaluate(theta):
        u = np.array([math.cos(theta), math.sin(theta), 0.0])
        e = np.array([-math.sin(theta), math.cos(theta), 0.0])
        loc = local(poly, u, s)
        g3, H3 = loc.basis @ loc.gradient, loc.basis @ loc.hessian @ loc.basis.T
        return float(e @ g3), float(e @ H3 @ e)

    corners = np.array([[float(x) for x in v] for v in poly.vertices])

    def submerged_corners(theta):
        """Which corners lie under the water at heel *theta*: ``U'`` is smooth while they stay the same."""
        state = local(poly, np.array([math.cos(theta), math.sin(theta), 0.0]), s).state
        return tuple(corners @ np.array([float(x) for x in state.u]) < float(state.t))

    @functools.cache
    def at_digits():
        return polyhedron(scene, dps=30)

    def precise(theta):
        """``U'`` and ``U''`` at 30 digits (beside a symmetric end, where float64 cannot tell)."""
        return planar_slope(at_digits(), theta, s)

    lo, hi, ends = _fundamental_arc(group)
    base = max(48, round(360 * (hi - lo) / (2 * math.pi)))
    searches = []
    for points in (base, 8 * base, 64 * base):      # a finer grid when minima - maxima fails
        searches.append(f"grid of {points}")
        out, index = _section_roots(scene, poly, group, evaluate, roots(evaluate, lo, hi, points, scale,
                                                                         include_ends=ends,
                                                                         regime=submerged_corners,
                                                                         precise=precise), scale)
        if index == 0:
            break
    else:
        found = f"is {index}, not 0" if index is not None else "cannot be made (a degenerate root's index is undecided)"
        raise IndexCheckError(f"{_name(scene)}: minima - maxima of the heel angle {found}, after "
                              f"{len(searches)} searches ({'; '.join(searches)}): an equilibrium is missing "
                              f"or mis-classified")
    return out, {"minima_minus_maxima": index, "expected_index_sum": 0, "grid": points, "searches": searches,
                 "arc_deg": [math.degrees(lo), math.degrees(hi)]}


ON_MIRROR = 1e-13   # radians: a section's images closer than this are one position (float64 rounds a unit vector turned
                    # by the group's matrices by about 1e-16; a pitchfork's partner can lie 1e-12 from its mirror)


def _section_roots(scene, poly, group, evaluate, found, scale):
    """The equilibria of a section from the roots of ``U'`` on the fundamental arc, one per class,
    and minima - maxima over the whole circle (a degenerate root counts by its higher orders)."""
    s = scene.density
    out, index = [], 0
    for r in found:
        u = np.array([math.cos(r.theta), math.sin(r.theta), 0.0])
        lipschitz = abs(evaluate(r.theta + STEP)[1] - evaluate(r.theta - STEP)[1]) / (2 * STEP)
        err, method = _off_mirror(equilibrium_error(planar_residual(scene, r.theta), abs(r.fprime), lipschitz, scale),
                                  u, group)
        # a copy of a class found already: within both errors of it (a pitchfork's partner can lie 1e-9 rad from
        # the position on the mirror it was born from, and is another class)
        if any(np.linalg.norm(g @ u - np.array(e.up)) <= min(1e-7, 2 * (err + e.error_rad) + 1e-12)
               for e in out for g in group):
            continue
        loc = local(poly, u, s)
        rep = representative(u, group)
        tol = eigenvalue_error(lipschitz, err, scale)
        stability, evidence = stability_of((r.fprime,), tol), "second variation"
        side, fprime, digits = (1 if r.fprime > 0 else -1), r.fprime, ()
        if stability == "indifferent":
            # next to a bifurcation: the root polished at 30 digits decides where float64 does not
            theta, residual, second = polish_planar(scene, r.theta, scale)
            err30, method30 = _off_mirror(equilibrium_error(float(residual), abs(float(second)), lipschitz, scale),
                                          u, group)
            stability = stability_of((float(second),), lipschitz * max(err30 - ROUNDING, 0.0) + 1e-25 * scale)
            if stability != "indifferent":
                u = np.array([float(mpmath.cos(theta)), float(mpmath.sin(theta)), 0.0])
                loc, rep, fprime = local(poly, u, s), representative(u, group), float(second)
                err, method, side = err30, method30, (1 if second > 0 else -1)
                digits = (mpmath.cos(theta), mpmath.sin(theta), mpmath.mpf(0))
                if any(np.linalg.norm(g @ u - np.array(e.up)) <= 2 * (err + e.error_rad) + 1e-12
                       for e in out for g in group):
                    continue            # a float64 root next to a flat one: polished, it is that one
        if stability == "indifferent":
            heel = planar_potential(scene)
            centre = heel(r.theta)
            sides = null_sides(lambda eps: float(heel(r.theta + eps) - centre), scale, rounding=1e-25)
            side = null_index(sides)
            stability = higher_order(sides, [])
            evidence = "higher orders" if stability != "indifferent" else "undecided"
        if side is None:
            return out, None            # a root whose index cannot be decided: the check cannot be made
        index += len(orbit(u, group, ON_MIRROR)) * side
        out.append(Equilibrium(_clean(rep), 90.0, stability, "isolated",
                               loc.U, "rectangle", (fprime,),
                               err, method, len(orbit(u, group, ON_MIRROR)), stability_evidence=evidence, digits=digits))
    out.sort(key=lambda e: (round(e.potential / scale, 12), e.up))
    return out, index


def _off_mirror(error: tuple[float, str], u, group) -> tuple[float, str]:
    """*error* of a section's root at *u*, where a residual of 0 at 30 digits off every mirror is float64's
    rounding of the heel angle, not an exact position (only a mirror fixes one exactly)."""
    if error[1] == "exact" and len(orbit(u, group, ON_MIRROR)) == len(group):
        return ROUNDING, "rounding"
    return error


def _fundamental_arc(group) -> tuple[float, float, bool]:
    """An arc of heel angles that meets every symmetry class of a section: between two adjacent
    mirror lines when the polygon has mirrors (the ends, on mirrors, are equilibria by symmetry),
    else one period of its rotations."""
    rotations = sum(1 for g in group if np.linalg.det(g) > 0)
    mirrors = [g for g in group if np.linalg.det(g) < 0]
    if not mirrors:
        return 0.0, 2 * math.pi / rotations, False
    m = mirrors[0][:2, :2]
    axis = 0.5 * math.atan2(m[1, 0], m[0, 0])       # a mirror fixes the line at half its rotation angle
    return axis, axis + math.pi / rotations, True


def _folded_potential(r, L, theta, s, dps=None):
    """The cylinder's potential at tilt *theta* (float64, or *dps* digits) for a tilt outside 0 … 90° too, by its
    symmetries: turned about its axis by a half turn (tilt −θ) or end over end (tilt 180° − θ) it is the same
    body.  The meridian's formulas hold on 0 … 90° only (beyond it the potential read 0: the lying cylinder at a
    density where its second variation vanishes was called unstable)."""
    from ..geometry.cylinder import cylinder_slice
    theta = abs(theta)
    return cylinder_slice(r, L, min(theta, math.pi - theta), s, dps=dps).U


def _cylinder(scene: Scene):
    from ..geometry.cylinder import cylinder_slice      # its quadrature nodes are computed on import: cylinders only
    r, L = (float(x) for x in scene.dims)
    s = float(scene.density)
    scale = max(r, L)

    @functools.lru_cache(maxsize=None)
    def slice_at(theta):
        return cylinder_slice(r, L, theta, s)

    def evaluate(theta):
        c = slice_at(theta)
        return float(c.f), float(c.fprime)

    def waterplane_shape(theta):
        """The waterplane's shape at tilt *theta* (circle, ellipse, truncated ellipse, ...): ``U'`` is smooth while
        it stays the same."""
        return slice_at(theta).shape

    with mpmath.workdps(40):
        exact_s = mpmath.mpf(scene.density.numerator) / scene.density.denominator

    def precise(theta):
        """``U'`` and ``U''`` at 30 digits at the scene's exact density (beside upright or lying)."""
        c = cylinder_slice(r, L, theta, exact_s, dps=30)
        return c.f, c.fprime

    found = roots(evaluate, 0.0, math.pi / 2, 180, scale, include_ends=True, regime=waterplane_shape,
                  precise=precise)
    out = []
    for q in found:
        c = cylinder_slice(r, L, q.theta, s)
        if 0 < q.theta < math.pi / 2:
            lipschitz = abs(evaluate(q.theta + STEP)[1] - evaluate(q.theta - STEP)[1]) / (2 * STEP)
            residual = abs(float(cylinder_slice(r, L, q.theta, s, dps=30).f))
            err, method = equilibrium_error(residual, abs(q.fprime), lipschitz, scale)
        else:
            err, method, lipschitz = 0.0, "exact", 0.0     # upright and lying: equilibria by symmetry
        up = _clean((math.sin(q.theta), 0.0, math.cos(q.theta)))
        tol = eigenvalue_error(lipschitz, err, scale)
        stability, evidence = stability_of((q.fprime,), tol), "second variation"
        if stability == "indifferent":          # the potential beside it decides, or nothing does
            # upright and lying are equilibria exactly (by symmetry), so the change beside them is read at 30
            # digits; a tilted root is a float64 one, whose position's error float64's rounding floor covers
            dps, rounding = (30, 1e-25) if q.theta in (0.0, math.pi / 2) else (None, 1e-13)
            at = _folded_potential(r, L, q.theta, s, dps)
            stability = higher_order(null_sides(lambda eps: float(_folded_potential(r, L, q.theta + eps, s, dps) - at),
                                                scale, rounding), [])
            evidence = "higher orders" if stability != "indifferent" else "undecided"
        out.append(Equilibrium(up, math.degrees(q.theta), stability, "isolated", float(c.U),
                               c.shape, (q.fprime,), err, method, 2 if q.theta == 0.0 else None,
                               stability_evidence=evidence))
    out.sort(key=lambda e: (round(e.potential / scale, 12), e.tilt_deg))
    index = _cylinder_index(out)
    if index != 0:
        found = f"is {index}, not 0" if index is not None else "cannot be made (a position's stability is undecided)"
        raise IndexCheckError(f"{_name(scene)}: minima - maxima of the tilt {found}: an equilibrium is missing or "
                              f"mis-classified")
    return out, {"note": "rotations about the axis are a continuous symmetry: each tilt is one class "
                         "(a circle of positions when tilted); stability is across the tilt",
                 "grid": 180, "minima_minus_maxima": index, "expected_index_sum": 0}


def _cylinder_index(equilibria) -> int | None:
    """Minima − maxima of the cylinder's potential over a whole turn of the tilt in its meridian plane, which
    must be 0 (a function on a circle): the tilts 0 … 90° are a quarter of it, upright and lying its mirrors'
    fixed points (each met twice in a turn), a tilted position four times; ``None`` when a position's stability
    is undecided."""
    index = 0
    for e in equilibria:
        if e.stability not in ("stable", "unstable"):
            return None
        index += (2 if e.tilt_deg in (0.0, 90.0) else 4) * (1 if e.stability == "stable" else -1)
    return index


def solve(scene: Scene) -> Solution:
    """Every equilibrium of *scene*, one per symmetry class, sorted by potential."""
    start = time.perf_counter()
    if scene.body in ("cube", "box"):
        group = box_group(scene.dims)
        equilibria, checks = _polyhedral(scene, sphere_seeds(10, math.pi / 2, 10), group)
    elif scene.body == "prism":
        group = prism_group(scene.sides)
        equilibria, checks = _polyhedral(scene, sphere_seeds(12, math.pi / scene.sides, 4), group)
    elif scene.body == "section":
        equilibria, checks = _section(scene)
    else:
        equilibria, checks = _cylinder(scene)
    return Solution(scene, equilibria, checks, time.perf_counter() - start)
