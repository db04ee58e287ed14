"""Completeness proved: no equilibrium but the reported ones, by an exclusion search over the sphere of up vectors.

The sphere is covered by the six charts ``u = c + a f + b g`` (``c`` a coordinate axis or its negative, ``f, g``
the other two axes, ``|a|, |b| <= 1``: every direction lies in the chart of its largest component).  A symmetry
of the body restricts the search: the mirror ``z -> -z`` (every box and prism) to ``u_z >= 0``, a box's mirrors
``x -> -x`` and ``y -> -y`` to ``u_x, u_y >= 0`` as well, a prism's mirror ``y -> -y`` (a vertex of its base on
``x``) and its rotations about its axis to the azimuths ``0 .. pi/n``, a cube's rotations to
``0 <= u_x <= u_y <= u_z``: every equilibrium has a copy there.

Each square of a chart, with the draught enclosed over it (``t(u_m) +- R |u - u_m|``: ``dt/du`` is the
waterplane's centroid, inside the body, ``R`` the largest ``|p|`` of a vertex; ``1e-9 R`` more for the float64
draught at the middle), is

* excluded where the mean-value form ``G(m) + J_G(Z) (Z - m)`` of ``G_i = F_i - k_i F3`` (``i = 1, 2``; ``F`` the
  system of :mod:`~symfloat.solver.certificate`, the gradient of the potential and the draught, in Arb balls;
  ``k_i`` the rate of ``F_i`` in ``t`` over that of ``F3`` at the middle, so that the draught's width hardly
  counts) holds no zero;
* accounted for where Krawczyk's test proves exactly one zero in the square doubled about its middle and a
  reported equilibrium (a copy of one, certified) lies there: that zero is it;
* else split in four, down to :data:`SMALLEST` and at most :data:`LIMIT` squares in all.

When every square is excluded or accounted for, every equilibrium is a reported one: the scene is complete
(certified).  A search stopped by a limit says so and claims nothing; so does one for a scene with a family
or a position not certified (a family is no isolated zero).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
from flint import arb, ctx

from ..geometry.floating import draught
from .bodies import polyhedron
from .certificate import PRECISION, evaluate, exact_ball, krawczyk, arb_body
from .symmetry import box_group, orbit, prism_group

__all__ = ["Completeness", "exclusion_search", "LIMIT", "SMALLEST"]

LIMIT = 40000           # squares examined at most
SMALLEST = 1e-5         # the smallest half-width of a square split further


@dataclass(frozen=True)
class Completeness:
    """The exclusion search's outcome: ``complete`` (proved), ``statement`` (what it says), the squares
    ``excluded`` and ``accounted`` for, ``examined`` in all, and its ``seconds``."""
    complete: bool
    statement: str
    excluded: int
    accounted: int
    examined: int
    seconds: float

    def record(self) -> dict:
        """The scene record's ``checks.completeness``."""
        return {"complete": self.complete, "statement": self.statement, "squares_excluded": self.excluded,
                "squares_accounted": self.accounted, "squares_examined": self.examined,
                "seconds": round(self.seconds, 2)}


def _charts(halves, cube: bool):
    """``(c, f, g, (a_lo, a_hi), (b_lo, b_hi))`` of the six charts, restricted to the coordinates in *halves*
    being non-negative; for a cube the chart of ``+z`` alone (its rotations permute the axes, so every
    equilibrium has a copy with ``0 <= u_x <= u_y <= u_z``: ``a <= b`` there, :func:`_in_domain`)."""
    if cube:
        return [(np.eye(3)[2], np.eye(3)[0], np.eye(3)[1], (0.0, 1.0), (0.0, 1.0))]
    out = []
    for k in range(3):
        for sign in (1, -1):
            if sign < 0 and k in halves:
                continue
            c = np.zeros(3)
            c[k] = sign
            i, j = [m for m in range(3) if m != k]
            f, g = np.eye(3)[i], np.eye(3)[j]
            out.append((c, f, g, (0.0 if i in halves else -1.0, 1.0), (0.0 if j in halves else -1.0, 1.0)))
    return out


def _squares(a, b):
    """The chart rectangle ``a x b`` as squares ``(a_mid, b_mid, half)`` (the longer side cut in two)."""
    (a0, a1), (b0, b1) = a, b
    if a1 - a0 > b1 - b0:
        m = (a0 + a1) / 2
        return [((a0 + m) / 2, (b0 + b1) / 2, (b1 - b0) / 2), ((m + a1) / 2, (b0 + b1) / 2, (b1 - b0) / 2)]
    if b1 - b0 > a1 - a0:
        m = (b0 + b1) / 2
        return [((a0 + a1) / 2, (b0 + m) / 2, (a1 - a0) / 2), ((a0 + a1) / 2, (m + b1) / 2, (a1 - a0) / 2)]
    return [((a0 + a1) / 2, (b0 + b1) / 2, (a1 - a0) / 2)]


def _in_domain(scene, c, f, g, am, bm, half) -> bool:
    """Whether the square meets the part of its chart searched: for a cube ``a <= b``; for a prism of ``n`` sides
    the azimuths ``0 .. pi/n`` (its rotations about the axis and its mirror ``y -> -y``): the azimuth along a
    side of a square is monotone (a chart's straight line), so the square's lie between its corners' unless it
    holds the axis; a box all of it."""
    if scene.body == "cube":
        return am - half <= bm + half
    if scene.body != "prism" or (c[2] > 0 and abs(am) <= half and abs(bm) <= half):
        return True
    azimuths = [math.atan2(u[1], u[0]) for u in (c + (am + da * half) * f + (bm + db * half) * g
                                                 for da in (-1, 1) for db in (-1, 1))]
    return max(azimuths) >= -1e-12 and min(azimuths) <= math.pi / scene.sides + 1e-12


def _excluded(body, s, centre, f, g, t0, half, rt) -> bool:
    """Whether the mean-value form of a component of the system holds no zero over the square."""
    middle, _ = evaluate(body, s, centre, f, g, arb(0), arb(0), arb(t0))
    over, _ = evaluate(body, s, centre, f, g, arb(0, half), arb(0, half), arb(t0, rt))
    if middle is None or over is None:
        return False
    values, Jm = middle
    _, J = over
    widths = (arb(0, half), arb(0, half), arb(0, rt))
    # the rows of the gradient less the draught's row times their rate in t over its (the waterplane's area):
    # the same zeros, and their change along t nearly cancels (the draught follows the up vector)
    for i in range(2):
        if not Jm[2][2] > 0:
            break
        k = arb(float((Jm[i][2] / Jm[2][2]).mid()))
        form = values[i] - k * values[2] + sum(((J[i][j] - k * J[2][j]) * widths[j] for j in range(3)), arb(0))
        if not form.contains(0):
            return True
    return False


def exclusion_search(solution, limit: int = LIMIT) -> Completeness:
    """Whether the equilibria of a cube, box or prism *solution* (certified: :func:`~symfloat.solver.certificate.
    certify` first) are all there are (module docstring)."""
    start = time.perf_counter()
    scene = solution.scene

    def outcome(complete, statement, excluded=0, accounted=0, examined=0):
        return Completeness(complete, statement, excluded, accounted, examined, time.perf_counter() - start)

    if scene.body not in ("cube", "box", "prism"):
        return outcome(False, "not certified: the exclusion search is made for cubes, boxes and prisms")
    if any(e.family == "ring" for e in solution.equilibria):
        return outcome(False, "not certified: a family of equilibria is no isolated zero to exclude or prove")
    if not all(e.certificate is not None and e.certificate.certified for e in solution.equilibria):
        return outcome(False, "not certified: a position has no certificate")
    group = box_group(scene.dims) if scene.body != "prism" else prism_group(scene.sides)
    halves = (0, 1, 2) if scene.body != "prism" else (1, 2)
    copies = [(v, e.certificate.radius) for e in solution.equilibria
              for v in orbit(np.asarray(e.digits if e.digits else e.up, dtype=float), group)]
    body, poly = arb_body(scene), polyhedron(scene)
    radius = body.radius
    saved = ctx.prec
    ctx.prec = PRECISION
    try:
        s = exact_ball(scene.density)
        todo = [(c, f, g, sq) for c, f, g, a, b in _charts(halves, scene.body == "cube") for sq in _squares(a, b)
                if _in_domain(scene, c, f, g, *sq)]
        excluded = accounted = examined = 0
        while todo:
            if examined >= limit:
                return outcome(False, f"not certified: the search stopped at its limit of {limit} squares "
                                      f"({len(todo)} left open)", excluded, accounted, examined)
            c, f, g, (am, bm, half) = todo.pop()
            examined += 1
            u = c + am * f + bm * g
            norm = float(np.linalg.norm(u))
            t0 = draught(poly, tuple(u / norm), scene.density)[0] * norm
            arb_f, arb_g = tuple(arb(x) for x in f), tuple(arb(x) for x in g)
            centre = tuple(arb(x) for x in u)
            rt = radius * half * 1.5 + 1e-9 * radius       # |u - u_m| <= half sqrt 2; the float draught's error
            if _excluded(body, s, centre, arb_f, arb_g, t0, half, rt):
                excluded += 1
                continue
            if _proved_reported(body, s, centre, arb_f, arb_g, t0, c, f, g, am, bm, 2 * half, radius, copies):
                accounted += 1
                continue
            if half <= SMALLEST:
                return outcome(False, f"not certified: a square of half-width {half:.1g} round up "
                                      f"{tuple(round(float(x), 6) for x in u / norm)} is neither excluded nor "
                                      f"proved to hold a reported equilibrium", excluded, accounted, examined)
            h = half / 2
            todo += [(c, f, g, (am + da * h, bm + db * h, h)) for da in (-1, 1) for db in (-1, 1)
                     if _in_domain(scene, c, f, g, am + da * h, bm + db * h, h)]
        return outcome(True, "complete (certified)", excluded, accounted, examined)
    finally:
        ctx.prec = saved


def _proved_reported(body, s, centre, f, g, t0, c, fv, gv, am, bm, half, radius, copies) -> bool:
    """Whether Krawczyk's test proves exactly one zero in the square of *half*-width about ``(am, bm)`` and a
    reported copy (with its certified box) lies inside it."""
    inside = []
    for v, r in copies:
        along = float(v @ c)
        if along <= 0:
            continue
        a, b = float(v @ fv) / along - am, float(v @ gv) / along - bm
        margin = 20 * r + 1e-12       # its certified box (within sqrt(2) r rad) in this chart: 1/along^2 <= 9 here
        if abs(a) + margin < half and abs(b) + margin < half:
            inside.append(v)
    if not inside:
        return False
    ok, _, _ = krawczyk(body, s, centre, f, g, t0, half, radius * half * 1.5 + 1e-9 * radius)
    return ok
