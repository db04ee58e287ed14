"""Floating states of a convex polyhedron in float64, many up vectors at once: the solver's fast path.

The part of a convex body below the plane ``u . p = t`` is bounded by its faces clipped to
``u . p <= t`` and by the cap (the waterplane polygon).  The boundary of a clipped face is the part
below the plane of each directed edge ``(p, q)`` of its ring (``(p, q)``, ``(p, x)``, ``(x, q)`` or
nothing, ``x`` the crossing point) and, where the plane crosses the face, the water-line segment from
its exit point to its entry point; the cap's boundary is those water-line segments reversed.  Every
integral is a sum over boundary segments in which the segments need no order:

* volume and centroid: signed tetrahedra ``(o, r_f, a, b)`` over the segments ``(a, b)`` of face ``f``,
  ``V = sum (r_f - o) . ((a - o) x (b - o)) / 6``, moment ``sum V_k (o + r_f + a + b) / 4``, with the apex
  ``o`` the mean of the crossing points and ``r_f`` the exit point of a crossed face (else the mean of its
  vertices): ``o`` lies in the water plane and ``r_f`` on the water line, so the cap's and the water-line
  segments' tetrahedra vanish, and every tetrahedron is as small as the submerged part, however thin;
* the waterplane: Green's sums over the cap's segments in the coordinates along ``e1, e2``, as
  :func:`symfloat.geometry.floating._polygon_moments` (area, centroid, central second moments).

So each quantity is one numpy reduction over the directed edges of all the up vectors asked for, with
no polygon to put in order.  Between two consecutive vertex heights the crossing points move linearly
with ``t`` (by ``(q - p) / (u . q - u . p)``), so the cap's area is a quadratic ``A0 + A1 h + A2 h^2``
in ``h = t - t0`` and the submerged volume the cubic ``V(t0) + A0 h + A1 h^2 / 2 + A2 h^3 / 3``: the
draught is that cubic's root (Newton's method on it) in the interval between vertex heights that holds
it (one evaluation where the first guess ``lo + s (hi - lo)`` is in it), and the state is evaluated
once more there.

The arithmetic is that of :mod:`symfloat.geometry.floating` (float64 sums of products of coordinates),
and the two agree to rounding (``tests/test_edgewise.py``).  No draught bracket is certified here
(:func:`~symfloat.geometry.floating.draught` certifies one); the solver's errors are bounded from the
gradient re-evaluated at 30 digits by :mod:`~symfloat.geometry.floating` itself.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from ..geometry.floating import Polyhedron, body_volume_centroid

__all__ = ["EdgeBody", "edge_body", "States", "states"]


class EdgeBody:
    """A float64 convex polyhedron as arrays: vertices shifted to their mean ``c`` (``verts``), the
    directed edges of every face ring (``p``, ``q``: vertex indices), the face points ``r`` of each
    edge's face and of each face (shifted), the face-edge incidence matrix, and the body's volume and
    centroid ``G`` (:func:`~symfloat.geometry.floating.body_volume_centroid`: the clipping module's)."""

    def __init__(self, poly: Polyhedron):
        if poly.dps is not None:
            raise ValueError("the edge-wise states are float64 only")
        points = poly.vertices
        index = {p: i for i, p in enumerate(points)}
        verts = np.array(points, dtype=float)
        self.c = verts.mean(axis=0)
        self.verts = verts - self.c
        p, q, face = [], [], []
        for f, ring in enumerate(poly.faces):
            for i in range(len(ring)):
                p.append(index[ring[i]])
                q.append(index[ring[(i + 1) % len(ring)]])
                face.append(f)
        self.p, self.q, self.face = np.array(p), np.array(q), np.array(face)
        self.vp, self.vq = self.verts[self.p], self.verts[self.q]
        self.incidence = np.zeros((len(poly.faces), len(p)))
        self.incidence[face, np.arange(len(p))] = 1.0
        self.r_face = np.array([np.mean([self.verts[index[v]] for v in ring], axis=0) for ring in poly.faces])
        volume, G = body_volume_centroid(poly)
        self.volume, self.G = float(volume), np.array([float(x) for x in G])


@functools.lru_cache(maxsize=64)
def edge_body(poly: Polyhedron) -> EdgeBody:
    """The :class:`EdgeBody` of *poly*, kept for the bodies used last (a scene asks for it at every step)."""
    return EdgeBody(poly)


@dataclass(frozen=True)
class States:
    """Floating states of one body at ``n`` up vectors: ``u`` (n x 3, unit), ``t`` (the water plane
    ``u . p = t``), ``volume``, ``B`` (n x 3), ``G`` (3), ``basis`` (n x 3 x 2: columns ``e1, e2`` as
    :func:`~symfloat.geometry.floating.waterplane_basis`), ``area``, ``tensor`` (n x 2 x 2, the central
    second moments of the waterplane along ``e1, e2``; zero without a waterplane) and ``potential``
    ``u . (G - B)``."""
    u: np.ndarray
    t: np.ndarray
    volume: np.ndarray
    B: np.ndarray
    G: np.ndarray
    basis: np.ndarray
    area: np.ndarray
    tensor: np.ndarray
    potential: np.ndarray


def _cross(a, b):
    return np.stack([a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1], a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2],
                     a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]], axis=-1)


def _dot(a, b):
    return (a * b).sum(axis=-1)


def _basis(u):
    """``(e1, e2)`` for unit vectors *u* (n x 3): ``e1`` the axis least aligned with ``u`` (the first on
    ties) made orthogonal to it, ``e2 = u x e1`` (:func:`~symfloat.geometry.floating.waterplane_basis`)."""
    n = len(u)
    k = np.argmin(np.abs(u), axis=1)            # the first of equal minima, as min(range(3), key=...)
    e1 = -u[np.arange(n), k][:, None] * u
    e1[np.arange(n), k] += 1.0
    e1 /= np.sqrt(_dot(e1, e1))[:, None]
    return e1, _cross(u, e1)


def _cut(body: EdgeBody, heights, u, t, e1, e2, full: bool):
    """The submerged parts below ``u . p = t`` (shifted frame; one row per up vector).  Returns the volume
    and the cap area's quadratic ``(A0, A1, A2)`` in ``t``; with *full*, also the moment ``int (p - c) dV``,
    the cap's area and its central second moments along ``e1, e2`` (n x 2 x 2)."""
    hp, hq = heights[:, body.p], heights[:, body.q]
    tt = t[:, None]
    below_p, below_q = hp <= tt, hq <= tt
    crossing = below_p != below_q
    # from the point below to the point above, so that the two faces sharing an edge get the same point
    first = below_p[..., None]
    a, b = np.where(first, body.vp, body.vq), np.where(first, body.vq, body.vp)
    ha = np.where(below_p, hp, hq)
    rise = np.where(crossing, np.where(below_p, hq, hp) - ha, 1.0)
    d = (b - a) / rise[..., None]                   # dx/dt along the edge
    x = a + (tt - ha)[..., None] * d
    exits, entries = (below_p & ~below_q)[..., None], (~below_p & below_q)[..., None]
    x_out, x_in = body.incidence @ (x * exits), body.incidence @ (x * entries)       # n x faces x 3
    crossed = (body.incidence @ exits[..., 0].T).T > 0                               # n x faces
    count = crossed.sum(axis=1)
    # the apex: the mean of the crossing points (on the water plane, so the cap's tetrahedra vanish); the
    # point of a crossed face: its exit point (so its water-line segment's vanish); tetrahedra stay as small
    # as the submerged part, however thin
    o = ((x_in + x_out) * crossed[..., None]).sum(axis=1) / np.maximum(2 * count, 1)[:, None]
    r = np.where(crossed[..., None], x_out, body.r_face)[:, body.face] - o[:, None]
    start = (np.where(first, body.vp, x) - o[:, None]) * (below_p | below_q)[..., None]
    end = np.where(below_q[..., None], body.vq, x) - o[:, None]
    tets = _dot(r, _cross(start, end)) / 6
    V = tets.sum(axis=1)
    # the cap in 2-D: its segments entry -> exit (faces not crossed give zero segments)
    d_out, d_in = body.incidence @ (d * exits), body.incidence @ (d * entries)
    E = np.stack([e1, e2], axis=-1)[:, None]            # n x 1 x 3 x 2
    xi, xo = (x_in[..., None] * E).sum(axis=2), (x_out[..., None] * E).sum(axis=2)      # n x faces x 2
    di, do = (d_in[..., None] * E).sum(axis=2), (d_out[..., None] * E).sum(axis=2)
    cross2 = lambda m, k: m[..., 0] * k[..., 1] - m[..., 1] * k[..., 0]
    A0 = cross2(xi, xo).sum(axis=1) / 2
    A1 = (cross2(xi, do) + cross2(di, xo)).sum(axis=1) / 2
    A2 = cross2(di, do).sum(axis=1) / 2
    if not full:
        return V, (A0, A1, A2)
    moment = (tets[..., None] * (start + end + r)).sum(axis=1) / 4 + V[:, None] * o
    m = ((xi + xo) * crossed[..., None]).sum(axis=1) / np.maximum(2 * count, 1)[:, None]   # the crossing points' mean
    xi, xo = (xi - m[:, None]) * crossed[..., None], (xo - m[:, None]) * crossed[..., None]
    X1, Y1, X2, Y2 = xi[..., 0], xi[..., 1], xo[..., 0], xo[..., 1]
    w = X1 * Y2 - X2 * Y1
    area = w.sum(axis=1) / 2
    safe = np.where(area != 0, area, 1.0)
    cx, cy = ((X1 + X2) * w).sum(axis=1) / 6 / safe, ((Y1 + Y2) * w).sum(axis=1) / 6 / safe
    Sxx = ((X1 * X1 + X1 * X2 + X2 * X2) * w).sum(axis=1)
    Syy = ((Y1 * Y1 + Y1 * Y2 + Y2 * Y2) * w).sum(axis=1)
    Sxy = ((2 * X1 * Y1 + X1 * Y2 + X2 * Y1 + 2 * X2 * Y2) * w).sum(axis=1)
    J = np.stack([np.stack([Sxx / 12 - area * cx * cx, Sxy / 24 - area * cx * cy], axis=-1),
                  np.stack([Sxy / 24 - area * cx * cy, Syy / 12 - area * cy * cy], axis=-1)], axis=-2)
    return V, (A0, A1, A2), moment, area, J


def _cubic(V0, A, h):
    """``V0 + A0 h + A1 h^2 / 2 + A2 h^3 / 3``: the submerged volume at ``t0 + h`` inside the interval."""
    A0, A1, A2 = A
    return V0 + h * (A0 + h * (A1 / 2 + h * A2 / 3))


def _cubic_root(V0, A, target, lo, hi):
    """The root ``h`` in ``[lo, hi]`` of the increasing cubic :func:`_cubic` ``= target`` (its value at ``lo``
    at most *target*, at ``hi`` at least): Newton's method from the secant's root, kept in ``[lo, hi]``."""
    A0, A1, A2 = A
    f_lo, f_hi = _cubic(V0, A, lo) - target, _cubic(V0, A, hi) - target
    rise = f_hi - f_lo
    h = np.where(rise > 0, lo - f_lo * (hi - lo) / np.where(rise > 0, rise, 1.0), (lo + hi) / 2)
    for _ in range(12):
        slope = A0 + h * (A1 + h * A2)
        step = np.where(slope > 0, (_cubic(V0, A, h) - target) / np.where(slope > 0, slope, 1.0), 0.0)
        h = np.clip(h - step, lo, hi)
        if not np.any(np.abs(step) > 1e-15 * (hi - lo)):
            break
    return h


def states(poly: Polyhedron, up, s, guess=None) -> States:
    """The floating states of the float64 convex *poly* at density ratio *s* (``0 < s < 1``) with each row
    of *up* (n x 3, normalised here) up, computed edge by edge (module docstring); *guess*: first guesses
    of the draughts ``t`` (else ``lo + s (hi - lo)``), which choose the first interval between vertex heights."""
    body = edge_body(poly)
    u = np.array(up, dtype=float).reshape(-1, 3)
    u = u / np.sqrt(_dot(u, u))[:, None]
    s = float(s)
    if not 0 < s < 1:
        raise ValueError("the density ratio s must lie strictly between 0 and 1")
    n, rows = len(u), np.arange(len(u))
    heights = u @ body.verts.T
    levels = np.sort(heights, axis=1)
    lo, hi = levels[:, 0], levels[:, -1]
    target = s * body.volume
    e1, e2 = _basis(u)
    # the interval [levels[k], levels[k+1]] that holds the root: the cubic is V itself inside it, so the root
    # lies below it where the cubic exceeds the target at its lower end, above it where it falls short at its
    # upper end; the next interval is the one that holds the linear estimate of the root, among those left
    top = levels.shape[1] - 1
    first = lo + s * (hi - lo) if guess is None else np.asarray(guess, dtype=float) - u @ body.c
    k = np.clip((levels <= first[:, None]).sum(axis=1) - 1, 0, top - 1)
    kmin, kmax = np.zeros(n, dtype=int), np.full(n, top - 1)
    todo = np.ones(n, dtype=bool)
    t = np.empty(n)
    for _ in range(levels.shape[1]):
        i = rows[todo]
        a, b = levels[i, k[i]], levels[i, k[i] + 1]
        t0 = (a + b) / 2
        V0, A = _cut(body, heights[i], u[i], t0, e1[i], e2[i], False)
        down = (_cubic(V0, A, a - t0) > target) & (k[i] > kmin[i])
        up_ = (_cubic(V0, A, b - t0) < target) & (k[i] < kmax[i])
        done = ~(down | up_)
        t[i[done]] = t0[done] + _cubic_root(V0[done], [x[done] for x in A], target, a[done] - t0[done],
                                            b[done] - t0[done])
        todo[i[done]] = False
        if not todo.any():
            break
        kmax[i[down]] = (levels[i[down]] < a[down, None]).sum(axis=1) - 1
        kmin[i[up_]] = (levels[i[up_]] <= b[up_, None]).sum(axis=1) - 1
        with np.errstate(divide="ignore", invalid="ignore"):
            estimate = t0 + (target - V0) / A[0]
        j = i[~done]
        k[j] = np.clip((levels[j] <= np.nan_to_num(estimate[~done])[:, None]).sum(axis=1) - 1, kmin[j], kmax[j])
    V, _, moment, area, J = _cut(body, heights, u, t, e1, e2, True)
    B = moment / V[:, None] + body.c
    potential = _dot(u, body.G - B)
    return States(u, t + u @ body.c, V, B, body.G, np.stack([e1, e2], axis=-1), area, J, potential)
