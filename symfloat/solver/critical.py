"""Every critical point of the potential of a floating polyhedron, by Newton's method on the sphere.

Seeds cover the symmetry group's fundamental domain; Newton's method with the
metacentric Hessian (:mod:`symfloat.solver.local`) converges from each seed to
a minimum, saddle or maximum.  Points are merged by symmetry class.  A point
whose Hessian has a (numerically) zero eigenvalue is tested for a *ring*: a
step along the null direction followed by Newton lands on another equilibrium
of the same potential.  Completeness is checked by the Poincaré–Hopf theorem:
over the whole sphere the indices of the isolated critical points (+1 for
minima and maxima, -1 for saddles) and of the families (the winding round them,
:mod:`symfloat.solver.families`: 0 for a Morse–Bott ring) add up to 2.
A point that float64 does not pin down (a nearly singular Hessian) is polished
at 30 digits and, where its error spans a mirror or an axis, tried at the
symmetric position (:func:`_error_estimate`).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import mpmath
import numpy as np

from .edgewise import states
from ..geometry.floating import Polyhedron
from .errors import ROUNDING, STEP, equilibrium_error
from .local import Local, gradient_at, local, tangent_step
from .degenerate import symmetric_point
from .refine import polish
from .selfcheck import index_of
from .symmetry import mirror_normals, orbit, representative, same_class

__all__ = ["Critical", "newton", "newton_all", "descend_all", "symmetric_newton", "critical_points", "poincare_hopf_sum", "more_seeds", "polyhedron_at", "on_family"]

MAX_STEP = 0.3          # radians: Newton steps are capped (a trust region)
MIN_FAMILY = 1e-3       # radians: an arc of equilibria shorter than this is not reported as one
MIN_RING = 5e-4         # radians: nor a closed ring (radius 8e-5: a ring born from an axis 1e-8 in s past it; a
                        # smaller "ring" lies within the float64 error of a degenerate point, flat to rounding)
FLAT = 2e-14            # relative to the size of the body: a ring's potential is constant to rounding
ZERO_EIGEN = 1e-8       # relative to the size of the body: a null direction of the Hessian


@dataclass(eq=False)
class Critical:
    """One symmetry class of critical points: representative ``u``, potential ``U``,
    Hessian eigenvalues ``eigen`` (ascending), residual gradient,
    error bound ``error_rad`` and how it was obtained, the Hessian's Lipschitz constant,
    ``orbit`` size, ``ring`` flag."""
    u: np.ndarray
    U: float
    eigen: tuple
    gradient: float
    error_rad: float
    orbit: int = 1
    ring: bool = False
    shape: str = ""             # a ring's shape: "closed" or "arc"
    length: float = 0.0         # a ring's length on the unit sphere (radians)
    length_error: float = 0.0   # and the error of that length (radians)
    error_method: str = "exact"
    lipschitz: float = 0.0
    index: int | None = None    # set where the Hessian is degenerate (from the higher orders) and for a family
    flat: bool = False          # degenerate and flat to rounding on the circle around it: no index
    digits: tuple = ()          # the up vector polished at 30 digits (mpf), when it is isolated
    eigen_error: float = 0.0    # the error of the eigenvalues (at the polished point)
    path: tuple = ()            # a family's points as walked, in order along it (unit vectors)
    axis: np.ndarray | None = None  # a closed ring's axis (the normal of its plane, towards it)
    exact: object = None        # a position symmetry fixes: its exact second variation (symfloat.solver.exact)


def newton(poly: Polyhedron, u0, s, scale: float, iterations: int = 60, null_tol: float | None = None):
    """Newton's method for ``grad U = 0`` from *u0*; returns the last :class:`Local` and
    whether the gradient fell below ``1e-13 * scale``.  Null directions of the Hessian
    (``|lambda| < null_tol``) are left alone (pseudo-inverse), so a ring is approached
    straight across."""
    null_tol = ZERO_EIGEN * scale if null_tol is None else null_tol
    u = np.asarray(u0, dtype=float)
    u = u / np.linalg.norm(u)
    best = None
    for _ in range(iterations):
        loc = local(poly, u, s)
        g = loc.gradient
        if best is None or np.linalg.norm(g) < np.linalg.norm(best.gradient):
            best = loc
        if np.linalg.norm(g) <= 1e-13 * scale:
            return loc, True
        w, vecs = np.linalg.eigh(loc.hessian)
        step2 = np.zeros(2)
        for lam, v in zip(w, vecs.T):
            if abs(lam) > null_tol:
                step2 -= np.dot(v, g) / lam * v
        if not np.linalg.norm(step2) > 0:
            step2 = -g / scale
        step = loc.basis @ step2
        norm = np.linalg.norm(step)
        if norm > MAX_STEP:
            step *= MAX_STEP / norm
        if norm < 1e-15:
            break
        u = tangent_step(loc.u, step)
    return best, np.linalg.norm(best.gradient) <= 1e-11 * scale


def newton_all(poly: Polyhedron, seeds, s, scale: float, iterations: int = 60) -> list:
    """:func:`newton` from every seed at once, the floating states of all the seeds still iterating evaluated
    together (:func:`symfloat.solver.edgewise.states`): the same steps, capped and stopped alike; returns
    ``(Local, converged)`` per seed (a :class:`Local` without its ``state``)."""
    null_tol = ZERO_EIGEN * scale
    u = np.array(seeds, dtype=float).reshape(-1, 3)
    u /= np.linalg.norm(u, axis=1)[:, None]
    n = len(u)
    out, best, best_size = [None] * n, [None] * n, np.full(n, np.inf)
    active = np.ones(n, dtype=bool)
    t = None                                        # the last draughts: each step's first guess
    for _ in range(iterations):
        i = np.flatnonzero(active)
        if not len(i):
            break
        st = states(poly, u[i], s, None if t is None else t[i])
        if t is None:
            t = np.empty(n)
        t[i] = st.t
        g = np.einsum("mkj,mk->mj", st.basis, st.G - st.B)
        H = st.tensor / st.volume[:, None, None] - st.potential[:, None, None] * np.eye(2)
        size = np.linalg.norm(g, axis=1)
        for j in np.flatnonzero(size < best_size[i]):
            best[i[j]] = Local(st.u[j], float(st.potential[j]), st.basis[j], g[j], H[j], None)
            best_size[i[j]] = size[j]
        converged = size <= 1e-13 * scale
        for j in np.flatnonzero(converged):
            out[i[j]] = (best[i[j]], True)
        w, vecs = np.linalg.eigh(H)
        along = np.einsum("mkj,mk->mj", vecs, g)                   # v . g for each eigenvector
        coef = np.where(np.abs(w) > null_tol, along / np.where(np.abs(w) > null_tol, w, 1.0), 0.0)
        step2 = -np.einsum("mkj,mj->mk", vecs, coef)
        flat = ~(np.linalg.norm(step2, axis=1) > 0)
        step2[flat] = -g[flat] / scale
        step = np.einsum("mkj,mj->mk", st.basis, step2)
        norm = np.linalg.norm(step, axis=1)
        step *= np.where(norm > MAX_STEP, MAX_STEP / np.where(norm > 0, norm, 1.0), 1.0)[:, None]
        stopped = ~converged & (norm < 1e-15)
        for j in np.flatnonzero(stopped):
            out[i[j]] = (best[i[j]], bool(best_size[i[j]] <= 1e-11 * scale))
        active[i[converged | stopped]] = False
        angle = np.linalg.norm(step, axis=1)
        moved = np.where(angle > 0, np.sin(angle) / np.where(angle > 0, angle, 1.0), 0.0)
        u[i] = np.where((angle > 0)[:, None], st.u * np.cos(angle)[:, None] + step * moved[:, None], st.u)
    for j in np.flatnonzero(active):
        out[j] = (best[j], bool(best_size[j] <= 1e-11 * scale))
    return out


def symmetric_newton(poly: Polyhedron, u0, s, scale: float, group, iterations: int = 40):
    """Newton's method for ``grad U = 0`` restricted to the positions with the symmetries of *u0*
    (the elements of *group* that fix it to 1e-9): steps only in the tangent directions those
    symmetries fix.  Along a branch of symmetric equilibria this is well conditioned where the full
    Hessian is not (the cube's diagonal positions, whose soft direction leaves the mirror, next to the
    ring they join).  Returns the last :class:`Local` and whether the gradient fell below
    ``1e-13 * scale`` (it is iterated further while it falls)."""
    u = np.asarray(u0, dtype=float)
    u = u / np.linalg.norm(u)
    P = np.mean([g for g in group if np.linalg.norm(g @ u - u) <= 1e-9], axis=0)
    best, size = None, math.inf
    for _ in range(iterations):
        loc = local(poly, u, s)
        Pt = P - np.outer(loc.u, loc.u)
        w, vecs = np.linalg.eigh((Pt + Pt.T) / 2)
        B = vecs[:, w > 0.5]                        # the fixed tangent directions (0, 1 or 2)
        F = B.T @ (loc.basis @ loc.gradient)
        if best is not None and np.linalg.norm(F) >= size:
            break
        best, size = loc, float(np.linalg.norm(F))
        if B.shape[1] == 0 or size == 0:
            break
        J = B.T @ (loc.basis @ loc.hessian @ loc.basis.T) @ B
        step = B @ np.linalg.lstsq(J, -F, rcond=None)[0]
        norm = float(np.linalg.norm(step))
        if norm > MAX_STEP:
            step *= MAX_STEP / norm
        u = tangent_step(loc.u, step)
    return best, size <= 1e-13 * scale


def _tangent_eigen(loc):
    """The two eigenpairs ``(lambda, tangent vector)`` of the Hessian, ascending."""
    w, vecs = loc.eigen()
    return list(zip(w, vecs))


def _lipschitz(poly, loc, s) -> float:
    """A Lipschitz constant of the Hessian at *loc*: central differences of ``STEP`` along its eigenvectors."""
    lipschitz = 0.0
    for v in loc.eigen()[1]:
        plus, minus = (local(poly, tangent_step(np.asarray(loc.u), sign * STEP * v), s) for sign in (1, -1))
        H = [x.basis @ x.hessian @ x.basis.T for x in (plus, minus)]
        lipschitz = max(lipschitz, float(np.linalg.norm(H[0] - H[1], 2)) / (2 * STEP))
    return lipschitz


def _error_estimate(poly, c: "Critical", s, scale, refine_dps: int, group=(), others=(),
                    event_dps: int = 0) -> tuple[float, str, float]:
    """Distance bound (radians) to the true equilibrium (:func:`equilibrium_error`, the gradient
    re-evaluated at *refine_dps* digits) and the Hessian's Lipschitz constant (central differences
    along the two eigenvectors).  Where that bound is not Kantorovich's, exceeds 1e-13 rad, or the
    smallest eigenvalue is within ten times its error of zero (next to a bifurcation), an isolated
    point is polished by Newton's
    method at *refine_dps* digits (:func:`polish`) and, if its error then spans a mirror or an axis,
    tried at the symmetric position: its up vector, gradient and eigenvalues are then those of that
    point, whose bound is the Kantorovich radius from a residual near ``10^-refine_dps`` (plus the
    float64 rounding of the vector), and its eigenvalues are exact to ``L * distance +
    10^(5 - refine_dps) * scale``, so that they still decide the stability (undecided, at twice the digits and
    then at *event_dps*, :func:`_decided`).  A ring keeps its
    float64 point (the slope across it)."""
    exact = polyhedron_at(poly, refine_dps)
    lipschitz = _lipschitz(poly, local(poly, c.u, s), s)       # eigenvectors at the representative itself
    if c.ring:
        residual = float(np.linalg.norm(gradient_at(exact, c.u, s)))
        c.eigen_error = lipschitz * residual / max(abs(e) for e in c.eigen) + 1e-14 * scale
        return (*equilibrium_error(residual, max(abs(e) for e in c.eigen), lipschitz, scale), lipschitz)
    # the error of the clipping at refine_dps digits, added to every residual but that of a position its
    # symmetries pin down exactly (an equilibrium in any arithmetic: face up)
    pinned = _pinned(c.u, group)
    arithmetic = 0.0 if pinned else 10.0 ** (5 - refine_dps) * scale
    residual = float(np.linalg.norm(gradient_at(exact, c.u, s))) + arithmetic
    err, method = equilibrium_error(residual, min(abs(e) for e in c.eigen), lipschitz, scale)
    if method == "kantorovich" and err <= 1e-13 and min(abs(e) for e in c.eigen) > 10 * (lipschitz * err + 1e-14 * scale):
        c.eigen_error = lipschitz * err + 1e-14 * scale        # decided in float64: nothing to polish
        return err, method, lipschitz
    u, residual, eigen = polish(exact, c.u, s, scale, steps=0 if pinned else 40)
    residual += arithmetic          # at 30 digits a residual below the arithmetic's error may round to 0
    err, method = equilibrium_error(float(residual), float(min(abs(e) for e in eigen)), lipschitz, scale)
    for more in (2 * refine_dps, event_dps):
        if pinned or more <= refine_dps or min(abs(float(e)) for e in eigen) > lipschitz * max(err - ROUNDING, 0.0) \
                + arithmetic:
            break
        # still undecided: once more at twice the digits (closer still to the bifurcation), and just past a
        # vertex event at its digits
        start = _symmetrised(c.u, group, more) if more == event_dps else u
        refine_dps, exact = more, polyhedron_at(poly, more)
        arithmetic = 10.0 ** (5 - refine_dps) * scale
        u, residual, eigen = polish(exact, start, s, scale)
        residual += arithmetic
        err, method = equilibrium_error(float(residual), float(min(abs(e) for e in eigen)), lipschitz, scale)
    # the most symmetric position within the error: where the polished point's error spans a mirror or
    # an axis (a degenerate point, where Newton converges slowly), the symmetric point is the candidate
    v = symmetric_point([float(x) for x in u], group, 2 * err + 1e-12)
    if any(abs(a - float(b)) > 0 for a, b in zip(v, u)) and not any(
            o is not c and same_class(o.u, v, group, 2 * o.error_rad + 1e-12) for o in others):
        # the symmetric point in mpmath (its float64 is not exactly symmetric)
        w, size, values = polish(exact, _symmetrised(v, group, refine_dps, 1e-12), s, scale, steps=0)
        size += arithmetic
        if size <= residual:
            u, residual, eigen = w, size, values
            err, method = equilibrium_error(float(residual), float(min(abs(e) for e in eigen)), lipschitz, scale)
    c.digits = u
    c.u = np.array([float(x) for x in u])
    c.u /= np.linalg.norm(c.u)
    c.eigen = tuple(float(e) for e in eigen)
    c.eigen_error = lipschitz * max(err - ROUNDING, 0.0) + 10.0 ** (5 - refine_dps) * scale
    return err, method, lipschitz


def _symmetrised(u, group, dps: int, tol: float = 1e-9) -> list:
    """The float unit vector *u* made exactly symmetric at *dps* digits: the mean of its images under the
    elements of *group* that fix it to *tol* (mpf).  A float64 point on a mirror is symmetric to its rounding only,
    and Newton's method at many digits from a point polished at fewer drifts along a soft direction off the mirror
    (the cube's diagonal class 1e-12 past its vertex event stalled at a residual 6.7e-38 at 60 and 88 digits; from
    the symmetrised point: 1.9e-60 and 4.4e-90)."""
    v = np.asarray([float(x) for x in u])
    fixing = [g for g in group if np.linalg.norm(g @ v - v) <= tol] or [np.eye(3)]
    with mpmath.workdps(dps):
        return [sum(mpmath.mpf(float(g[i, j])) * mpmath.mpf(float(v[j])) for g in fixing for j in range(3))
                / len(fixing) for i in range(3)]


def _pinned(u, group) -> bool:
    """Whether the float64 vector *u* is fixed exactly by symmetries of the body that fix no tangent
    direction (face up, corner up of a box given exactly): then it is an equilibrium by symmetry."""
    u = np.asarray(u, dtype=float)
    fixing = [g for g in group if np.array_equal(g @ u, u)]
    if not fixing:
        return False
    P = np.mean(fixing, axis=0) - np.outer(u, u)
    return not np.any(np.linalg.eigvalsh((P + P.T) / 2) > 0.5)


def polyhedron_at(poly, dps: int) -> Polyhedron:
    """*poly* (float64) as a body in mpmath at *dps* digits: made again from its exact description where it has one
    (``at_digits``; a regular polygon's float64 vertices break its mirrors by their rounding, which moves a soft
    equilibrium on a mirror off it: the octagonal prism 1 x 2 at s = 1/2, by 2e-11), else its float vertices taken
    exactly; made once per digits."""
    made = poly.__dict__.setdefault("_at_digits", {})
    if dps not in made:
        if poly.at_digits is not None:
            made[dps] = poly.at_digits(dps)
        else:
            with mpmath.workdps(dps):
                made[dps] = Polyhedron(tuple(tuple(tuple(mpmath.mpf(x) for x in p) for p in ring)
                                             for ring in poly.faces), dps)
    return made[dps]


def poincare_hopf_sum(points: list[Critical]) -> int:
    """Sum of indices over the whole sphere; 2 when no critical point is missing.  A degenerate point
    counts with the index of its higher-order terms, a family with the winding round it (``c.index``,
    :func:`~symfloat.solver.families.family_index`: 0 for a closed ring)."""
    total = 0
    for c in points:
        total += c.orbit * (c.index if c.index is not None or c.ring else index_of(c.eigen))
    return total


def descend_all(poly: Polyhedron, starts, directions, s, scale: float, iterations: int = 200) -> list:
    """Follow the potential down (*directions* 1) or up (-1) from every start by saddle-free Newton steps
    ``-direction * sum (v . g) / |lambda| v`` (``|lambda|`` floored, steps capped), then polish by
    :func:`newton_all`: from a point just off a saddle along its unstable (stable) direction this reaches
    the minimum (maximum) that the saddle's separatrix leads to, however close to the saddle it is.  The
    floating states of all the starts are evaluated together (:func:`symfloat.solver.edgewise.states`)."""
    u = np.array(starts, dtype=float).reshape(-1, 3)
    u /= np.linalg.norm(u, axis=1)[:, None]
    sign = np.asarray(directions, dtype=float)
    floor = 1e-4 * scale
    active = np.ones(len(u), dtype=bool)
    for _ in range(iterations):
        i = np.flatnonzero(active)
        if not len(i):
            break
        st = states(poly, u[i], s)
        g = np.einsum("mkj,mk->mj", st.basis, st.G - st.B)
        u[i] = st.u
        settled = np.linalg.norm(g, axis=1) <= 1e-9 * scale
        active[i[settled]] = False
        H = st.tensor / st.volume[:, None, None] - st.potential[:, None, None] * np.eye(2)
        w, vecs = np.linalg.eigh(H)
        coef = np.einsum("mkj,mk->mj", vecs, g) / np.maximum(np.abs(w), floor)
        step = -sign[i, None] * np.einsum("mkj,mj->mk", st.basis, np.einsum("mkj,mj->mk", vecs, coef))
        norm = np.linalg.norm(step, axis=1)
        step *= np.where(norm > 0.1, 0.1 / np.where(norm > 0, norm, 1.0), 1.0)[:, None]
        angle = np.linalg.norm(step, axis=1)
        moved = np.where(angle > 0, np.sin(angle) / np.where(angle > 0, angle, 1.0), 0.0)
        go = i[~settled]
        keep = ~settled
        u[go] = np.where((angle[keep] > 0)[:, None],
                         st.u[keep] * np.cos(angle[keep])[:, None] + step[keep] * moved[keep, None], st.u[keep])
    return newton_all(poly, u, s, scale)


def more_seeds(poly: Polyhedron, s, points: list[Critical], group, scale: float,
               grid: int = 20) -> list[np.ndarray]:
    """Seeds for a second search when the index sum fails: the ends of every saddle's separatrices
    (followed down and up from 1e-3 and 3e-2 rad off the saddle, :func:`descend_all`); Newton from steps
    of 1e-3 ... 3e-2 rad along the softer direction of every point whose Hessian is nearly singular
    (a branch born there lies close by), of 1e-3 ... 0.1 rad every 30 degrees around such a point with
    an isotropic Hessian (a ring born there); and the local minima of ``|grad U|`` on a grid of
    ``grid x grid`` points over the octant (where the gradient is small, a critical point is near).
    The descents, the Newton runs and the grid are each evaluated all at once (:func:`descend_all`,
    :func:`newton_all`)."""
    descents, directions, softs, order = [], [], [], []
    for c in points:
        if c.ring:
            continue
        values, vectors = local(poly, c.u, s).eigen()
        for lam, v in zip(values, vectors):
            for delta in (1e-3, 3e-2):
                for sign in (1, -1):
                    if lam < 0 < max(values) or lam > 0 > min(values):
                        descents.append(tangent_step(c.u, sign * delta * v))
                        directions.append(1 if lam < 0 else -1)
                        order.append(("descent", len(descents) - 1))
        soft = vectors[int(np.argmin(np.abs(values)))]
        if min(abs(values)) < 1e-2 * scale:
            # an isotropic point (on an axis of order >= 3) has no soft direction of its own: a ring born
            # there opens in every direction, and where it breaks, its pieces and the positions between them
            # lie off the eigenvectors: every 30 degrees, out to 0.1 rad
            isotropic = abs(values[0] - values[1]) <= 1e-9 * scale
            ways = [math.cos(a) * vectors[0] + math.sin(a) * vectors[1]
                    for a in np.arange(12) * math.pi / 6] if isotropic else [soft, -soft]
            for delta in (1e-3, 3e-3, 1e-2, 3e-2) + ((6e-2, 1e-1) if isotropic else ()):
                for v in ways:
                    softs.append(tangent_step(c.u, delta * v))
                    order.append(("soft", len(softs) - 1))
    ends = {"descent": descend_all(poly, descents, directions, s, scale) if descents else [],
            "soft": newton_all(poly, softs, s, scale) if softs else []}
    seeds = [ends[kind][k][0].u for kind, k in order]
    patch = np.array(sphere_seeds(grid, math.pi / 2, grid))
    st = states(poly, patch, s)
    size = np.linalg.norm(np.einsum("mkj,mk->mj", st.basis, st.G - st.B), axis=1)
    close = patch @ patch.T >= math.cos(1.5 * math.pi / 2 / grid)
    np.fill_diagonal(close, False)
    for i in range(len(patch)):
        if close[i].any() and size[i] <= size[close[i]].min():
            seeds.append(patch[i])
    return seeds


def _nearest_axis(u, group) -> float:
    """Angle from *u* to the nearest axis of a rotation of *group* (a ring around that axis, born from
    the position on it, has this radius: steps along it must be smaller)."""
    angles = []
    for g in group:
        if np.linalg.det(g) > 0 and not np.allclose(g, np.eye(3)):
            w, v = np.linalg.eig(g)
            axis = np.real(v[:, int(np.argmin(np.abs(w - 1)))])
            axis /= np.linalg.norm(axis)
            angles.append(math.acos(min(1.0, abs(float(np.dot(axis, u))))))
    return min(angles, default=math.pi)


def _nearest_copy(u, group, floor: float = 1e-3) -> float:
    """Angle to the nearest symmetric copy of *u* farther than *floor* (a copy closer than that is
    the same position seen through a mirror it almost lies on, not another point of a family)."""
    angles = [math.acos(max(-1.0, min(1.0, float(np.dot(g @ u, u))))) for g in group]
    return min((a for a in angles if a > floor), default=math.pi)


def on_family(u, c, group, tol: float = 5e-5) -> bool:
    """Whether the unit vector *u* lies on the family *c* or a copy of it: within an eighth of a chord of the
    chords between its walked points (a chord of a circle of radius ``R >= 4 |chord|`` strays ``|chord| / 32``
    from it) plus *tol* (by default the error of an arc's end, ``2 * 0.005 / 256``)."""
    images = np.asarray(group, dtype=float) @ np.asarray(u, dtype=float)         # every copy of u
    path = np.asarray(c.path, dtype=float)
    a = path if c.shape == "closed" else path[:-1]
    b = np.roll(path, -1, axis=0) if c.shape == "closed" else path[1:]
    d = b - a
    size = np.maximum(np.sum(d * d, axis=1), 1e-300)
    w = np.clip(np.einsum("kj,mj->km", images, d) - np.sum(a * d, axis=1), 0.0, size) / size
    gap = np.linalg.norm(images[:, None, :] - (a[None] + w[..., None] * d[None]), axis=2)
    return bool(np.any(gap <= np.sqrt(size) / 8 + tol))


def _joined(poly, a, b, s, scale, potential) -> bool:
    """Whether the equilibria *a* and *b* (unit vectors, close) lie on one family: from the middle of the
    chord between them, Newton's method (null directions left alone) settles on an equilibrium of the same
    potential (to :data:`FLAT`) within a quarter of the chord.  Across a gap in a family (the long square
    log at 1 - 0.0105466: a stable class between two arcs, its potential theirs to 1e-13) the gradient along
    the family does not vanish and Newton's method either stops short or runs to the class."""
    middle = (np.asarray(a) + np.asarray(b)) / 2
    settled, ok = newton(poly, middle / np.linalg.norm(middle), s, scale)
    return bool(ok and np.linalg.norm(settled.gradient) <= 1e-13 * scale and abs(settled.U - potential) <= FLAT * scale
                and np.linalg.norm(settled.u - middle / np.linalg.norm(middle)) <= np.linalg.norm(np.subtract(b, a)) / 4)


def _decided(poly, loc, s, scale, refine_dps: int = 30, event_dps: int = 0, group=()) -> float:
    """The soft eigenvalue of an isolated equilibrium next to *loc* where it is decided not to be zero (along a
    family of equilibria the potential is constant and that eigenvalue vanishes), else 0.0.  Decided where Newton–Kantorovich holds
    with the soft eigenvalue, ``h = L |grad| / lambda^2 <= 1/2``, and the eigenvalue exceeds ten times its error
    at the root (``L`` times the distance ``2 |grad| / lambda``, plus the rounding: 1e-12 of the size for the
    float64 Hessian of the clipped body, 10^(5 - dps) at *refine_dps* digits and at twice that, where the point
    is polished by Newton's method when float64 does not decide).  The long square log at 1 - 0.0105465, 7e-8 in s past its
    vertex event: the stable diagonal class (1.1e-8 at 30 digits, 1.2e-12 at 3.2e-9 past the event) was walked
    as a point of one closed ring; a point of a family polishes to an eigenvalue near 1e-18 with a residual
    1e-23 and decides nothing.  Where the scene is just past a vertex event, the second time at *event_dps* digits
    (:func:`~symfloat.solver.vertex.event_digits`: the cube 1e-12 past 3/7 - sqrt(2)/7, its diagonal class's soft
    eigenvalue 8.1e-33, decided at 88 digits), from the point made symmetric at them (:func:`_symmetrised`).
    Above s = 1/2 the Hessian is the dual body's at 1 - s, up ``-u``
    (:func:`~symfloat.solver.families._gradient`): the same up to the factor (1 - s) / s, with the same
    rounding in absolute terms (and its sign)."""
    if s > 0.5:
        loc, s = local(poly, -np.asarray(loc.u), 1 - s), 1 - s
    lipschitz = _lipschitz(poly, loc, s)

    def isolated(residual, soft, rounding):      # a soft eigenvalue whose square float64 cannot hold decides nothing
        soft = abs(soft)
        return soft ** 2 > 0 and lipschitz * residual / soft ** 2 <= 0.5 \
            and soft > 10 * (lipschitz * 2 * residual / soft + rounding)
    soft = float(min(loc.eigen()[0], key=abs))
    if isolated(float(np.linalg.norm(loc.gradient)), soft, 1e-12 * scale):
        return soft
    u = loc.u
    ladder = (refine_dps, event_dps) if event_dps > 2 * refine_dps else (refine_dps, 2 * refine_dps)
    for dps in ladder:      # once more at twice the digits, closer still to the event
        start = _symmetrised(loc.u, group, dps) if dps == event_dps else u
        u, residual, eigen = polish(polyhedron_at(poly, dps), start, s, scale, steps=12)
        soft = float(min(eigen, key=abs))
        if isolated(float(residual) + 10.0 ** (5 - dps) * scale, soft, 10.0 ** (5 - dps) * scale):
            return soft
    return 0.0


def _is_ring(poly, loc, pairs, s, scale, group, event_dps: int = 0) -> bool:
    """Step along the null direction (by less than the distance to the nearest symmetric copy of
    the point, so a small ring around an axis is not jumped over) and let Newton settle: on a
    ring it lands on another equilibrium of the same potential, not in the same class."""
    lam_null, v_null = min(pairs, key=lambda p: abs(p[0]))
    lam_across = max(abs(p[0]) for p in pairs)
    if abs(lam_null) > 1e-6 * scale or lam_across < max(100 * abs(lam_null), 1e-11 * scale) \
            or _nearest_axis(loc.u, group) < 1e-6:
        # not flat; or flat both ways (a neighbourhood flat to rounding next to a bifurcation, not a ring:
        # the point is classified by its higher orders); or on an axis (a ring is born around it, not through it)
        return False
    delta = min(0.03, _nearest_copy(loc.u, group) / 4, max(_nearest_axis(loc.u, group), 1e-9) / 4)
    for step in (delta, -delta):
        moved = tangent_step(loc.u, step * v_null)
        other, ok = newton(poly, moved, s, scale)
        ok = ok and np.linalg.norm(other.gradient) <= 1e-13 * scale and np.linalg.norm(loc.gradient) <= 1e-13 * scale
        if ok and np.linalg.norm(other.u - loc.u) > delta / 3 and abs(other.U - loc.U) <= FLAT * scale \
                and not same_class(other.u, loc.u, group, delta / 10) and _joined(poly, loc.u, other.u, s, scale, loc.U):
            # unless its soft eigenvalue, small as it is, is decided: a minimum just born beside the family
            return not _decided(poly, loc, s, scale, event_dps=event_dps, group=group)
    return False


def trace_family(poly, u, s, scale, group, max_steps: int = 2000, barriers=()) -> tuple[str, float, float, tuple, tuple]:
    """Walk along a ring from *u* (steps of ``delta`` along the null direction, Newton across) and
    return ``("closed", length, error, (axis,), path)`` when the walk comes back to *u*, else ``("arc",
    length, error, (end, end), path)``, the length in radians on the sphere (the chords between the points
    walked; a closed walk adds the chord back to its start) and the points walked in order along the
    family (from one end to the other; round a closed ring from *u*).  The error: a chord is shorter than its
    arc by at most ``delta^3 / (24 R^2)`` on a circle of radius ``R``; an arc's end is located by
    halving the last step eight times, so each end lies within ``delta / 256`` past the point reached.
    *barriers*: unit vectors of isolated equilibria the family cannot pass through (a step whose chord comes
    within a quarter of its length of one ends the walk there)."""
    start = local(poly, u, s)
    # a gap in the family narrower than the step is seen where the middle of a step's chord falls in it; a
    # step must go ahead by a third of itself (past an arc's end Newton's method may settle behind the point,
    # and the walk went back through its start and called the arc closed: the box 1 x 3/2 x 1 at 0.0820247)
    # (:func:`_joined`); a ring around an axis is walked in steps of a quarter of its radius at most
    axis = max(_nearest_axis(start.u, group), 1e-9)
    delta = min(0.005, _nearest_copy(start.u, group) / 4, axis / 4)
    max_steps = min(max_steps, int(8 * math.pi * axis / delta) + 16)     # twice round a circle of that radius

    def step_from(loc, v, h):
        nxt, ok = newton(poly, tangent_step(loc.u, h * v), s, scale)
        moved = float(np.linalg.norm(nxt.u - loc.u))
        good = ok and np.linalg.norm(nxt.gradient) <= 1e-13 * scale and abs(nxt.U - start.U) <= FLAT * scale \
            and float(np.dot(nxt.u - loc.u, v)) >= h / 3 \
            and min(abs(p[0]) for p in _tangent_eigen(nxt)) <= 1e-6 * scale \
            and _joined(poly, loc.u, nxt.u, s, scale, start.U) and _clear(loc.u, nxt.u, barriers, h / 4)
        return nxt, moved, good

    total, ends, visited, sides = 0.0, [], [start.u], []
    for direction in (1, -1):
        loc, previous = start, None
        walked = []
        sides.append(walked)
        for _ in range(max_steps):
            pairs = _tangent_eigen(loc)
            v = min(pairs, key=lambda p: abs(p[0]))[1]
            if previous is not None and np.dot(v, loc.u - previous) < 0:
                v = -v
            elif previous is None:
                v = direction * v
            nxt, moved, good = step_from(loc, v, delta)
            if not good:
                h = delta
                for _ in range(8):          # the end of the arc, between loc and one step past it
                    h /= 2
                    nxt, moved, good = step_from(loc, v, h)
                    if good:
                        total += 2 * math.asin(min(1.0, moved / 2))
                        loc = nxt
                        walked.append(loc.u)
                ends.append(loc.u)
                break
            previous, loc = loc.u, nxt
            visited.append(loc.u)
            walked.append(loc.u)
            total += 2 * math.asin(min(1.0, moved / 2))
            if total > 2 * math.pi:             # longer than a great circle: not a walk along one family
                ends.append(loc.u)
                break
            if total > 2 * delta and np.linalg.norm(loc.u - start.u) < delta / 2:
                # the chord back to the start, or less the part of the last step that went past it
                gap = 2 * math.asin(min(1.0, float(np.linalg.norm(loc.u - start.u)) / 2))
                total += gap if np.dot(loc.u - previous, start.u - loc.u) > 0 else -gap
                radius = total / (2 * math.pi)
                points = np.array(visited)          # a circle on the sphere: the normal of its plane, towards it
                axis = np.linalg.svd(points - points.mean(axis=0))[2][-1]
                axis = axis if np.dot(axis, points.mean(axis=0)) > 0 else -axis
                path = (start.u, *walked[:-1])      # the last point is the start again, to within delta / 2
                return "closed", total, total * (delta / radius) ** 2 / 24 + 1e-12, (axis,), path
        else:
            ends.append(loc.u)
    radius = max(total / (2 * math.pi), delta)
    path = (*sides[1][::-1], start.u, *sides[0])
    return "arc", total, 2 * delta / 256 + total * (delta / radius) ** 2 / 24 + 1e-12, tuple(ends), path


def _clear(a, b, points, distance: float) -> bool:
    """Whether the chord from *a* to *b* keeps farther than *distance* from each of *points*."""
    if not len(points):
        return True
    a, d = np.asarray(a), np.subtract(b, a)
    w = np.clip((np.asarray(points) - a) @ d / max(float(d @ d), 1e-300), 0.0, 1.0)
    return bool(np.min(np.linalg.norm(np.asarray(points) - (a + w[:, None] * d), axis=1)) > distance)


def _mirror_points(c, group) -> list[np.ndarray]:
    """Where the walked closed ring *c* crosses a mirror plane of the body (a reflection of *group*): the
    chord between two walked points on either side, cut by the plane, projected onto it."""
    out = []
    path = np.asarray(c.path, dtype=float)
    following = np.roll(path, -1, axis=0)
    for n in mirror_normals(group):
        a, b = path @ n, following @ n
        for k in np.nonzero(a * b < 0)[0]:
            q = path[k] + a[k] / (a[k] - b[k]) * (following[k] - path[k])
            q -= (q @ n) * n
            out.append(q / np.linalg.norm(q))
    return out


def _broken_rings(poly, found, s, scale, group, event_dps: int = 0) -> None:
    """A family cannot pass through a point where the potential is strictly convex or concave along it: a
    closed ring is walked again, with such points as barriers, where it passes through an isolated class found
    with a decided second variation (:func:`_decided`), or where one of its points on a mirror plane of the
    body, settled within the mirror (:func:`symmetric_newton`), is such a class (then added).  The walk
    crossed a gap narrower than its step there: the long square log just past its vertex event 0.0105464
    (and its dual), where the stable diagonal class lies between arcs about the faces' directions and was
    walked as one ring round the end face, whose index 0 hid both.  The ring becomes the arcs between those
    points, and where both ends of an arc stop at a minimum or a maximum, its index follows from them
    (:func:`_index_between`): next to such an event the gradient round the arc's ends is rounding."""
    G = np.asarray(group, dtype=float)
    for c in [c for c in found if c.ring and c.shape == "closed"]:
        barriers, kinds = [], []

        def bar(u, soft, across):
            images = list(G @ np.asarray(u))
            barriers.extend(images)
            kind = -1 if soft > 0 and across > 0 else 1 if soft < 0 and across < 0 else None
            kinds.extend([kind] * len(images))
        for o in found:
            if o.ring:
                continue
            across = max(o.eigen, key=abs)
            for image in G @ np.asarray(o.u):
                soft = on_family(image, c, group, 1e-6) and _decided(poly, local(poly, image, s), s, scale,
                                                                     event_dps=event_dps, group=group)
                if soft:
                    bar(o.u, soft, across)
                    break
        undecided = []          # mirror points whose second variation is not decided: their copies are not either
        for q in _mirror_points(c, group):
            if any(same_class(q, o.u, group, 1e-6) for o in found if not o.ring) \
                    or any(np.linalg.norm(q - b) <= 1e-6 for b in barriers):
                continue
            loc, ok = symmetric_newton(poly, q, s, scale, group)
            if not (ok and abs(loc.U - c.U) <= FLAT * scale) or any(same_class(loc.u, w, group, 1e-6) for w in undecided):
                continue
            soft = _decided(poly, loc, s, scale, event_dps=event_dps, group=group)
            if not soft:
                undecided.append(loc.u)
            else:
                pairs = _tangent_eigen(loc)
                g = float(np.linalg.norm(loc.gradient))
                found.append(Critical(representative(loc.u, group), loc.U, (float(pairs[0][0]), float(pairs[1][0])),
                                      g, 0.0, len(orbit(loc.u, group)), False))
                bar(loc.u, soft, max((p[0] for p in pairs), key=abs))
        if barriers:
            barriers = np.array(barriers)
            path = np.asarray(c.path, dtype=float)       # walked again from its point farthest from them
            start = path[int(np.argmax(np.min(np.linalg.norm(path[:, None] - barriers[None], axis=2), axis=1)))]
            c.shape, c.length, c.length_error, key, c.path = trace_family(poly, start, s, scale, group,
                                                                          barriers=barriers)
            c.u = representative(start, group)
            c.orbit = family_copies(c.shape, key, group, 1e-3)
            c.axis = key[0] if c.shape == "closed" else None
            if c.shape == "arc":
                c.index = _index_between(c, barriers, kinds)


def _index_between(c, barriers, kinds, reach: float = 2e-4):
    """The index of the arc *c* whose walk stopped at isolated classes: each end within *reach* (the walk's
    last step is at most ``0.005 / 256``, the chord kept a quarter of it from the class) of a minimum (the
    potential falls past that end: -1) or a maximum (+1); the index is the sign of the second variation across
    the arc times that, where both ends agree, 0 where they differ (a transversally stable arc falling past
    both ends is a saddle of the ring, docs/numerics.md section 4), None (the winding decides) where an end
    meets no such class."""
    ends = []
    for end in (np.asarray(c.path[0]), np.asarray(c.path[-1])):
        d = np.linalg.norm(barriers - end, axis=1)
        k = int(np.argmin(d))
        if d[k] > reach or kinds[k] is None:
            return None
        ends.append(kinds[k])
    across = 1 if max(c.eigen, key=abs) > 0 else -1
    return across * ends[0] if ends[0] == ends[1] else 0


def family_copies(shape: str, points, group, tol: float) -> int:
    """How many distinct families the symmetries make of one: a closed ring by its axis (pointing
    towards the ring: the rings around ``a`` and ``-a`` are two), an arc by its pair of ends."""
    images = []
    for g in group:
        key = [g @ p for p in points]
        if shape == "closed":
            same = lambda other: np.linalg.norm(key[0] - other[0]) <= tol
        else:
            same = lambda other: min(np.linalg.norm(key[0] - other[0]) + np.linalg.norm(key[1] - other[1]),
                                     np.linalg.norm(key[0] - other[1]) + np.linalg.norm(key[1] - other[0])) <= tol
        if not any(same(other) for other in images):
            images.append(key)
    return len(images)


def critical_points(poly: Polyhedron, s, seeds, group, scale: float, refine_dps: int = 30,
                    event_dps: int = 0) -> list[Critical]:
    """Every symmetry class of critical points reached by Newton from *seeds*, sorted by potential; *event_dps*:
    the digits that decide a class beside a ring just past a vertex event (:func:`_decided`)."""
    found: list[Critical] = []
    for loc, ok in newton_all(poly, seeds, s, scale):
        if not ok:
            continue
        pairs = _tangent_eigen(loc)
        eigen = (float(pairs[0][0]), float(pairs[1][0]))
        lam_min = min(abs(e) for e in eigen)
        # a point of a family already walked, or one just past its end that Newton's method does not resolve (the
        # gradient not below 1e-13 of the size: the potential falls there by less than the rounding); a resolved
        # point off the family is kept (the stable class between two arcs, their potential to 1e-13)
        unresolved = float(np.linalg.norm(loc.gradient)) > 1e-13 * scale
        if lam_min < 1e-6 * scale and any(c.ring and abs(c.U - loc.U) <= 1e-10 * scale
                                          and on_family(loc.u, c, group, 1e-2 if unresolved else 5e-5) for c in found):
            continue
        ring = lam_min < 1e-6 * scale and _is_ring(poly, loc, pairs, s, scale, group, event_dps)
        g = float(np.linalg.norm(loc.gradient))
        err = 0.0 if ring else min(g / max(lam_min, 1e-300), (g / scale) ** (1 / 3))
        match = [c for c in found if not c.ring and same_class(c.u, loc.u, group, 1e-7 + 2 * (err + c.error_rad))]
        if match and not ring and match[0].gradient <= g:
            continue
        found = [c for c in found if not any(c is m for m in match)]
        c = Critical(representative(loc.u, group), loc.U, eigen, g, err, len(orbit(loc.u, group)), ring)
        if ring:
            c.shape, c.length, c.length_error, key, c.path = trace_family(poly, c.u, s, scale, group)
            # a "ring" the walk cannot follow (or only for a few steps) is an isolated degenerate point
            c.ring = c.length >= (MIN_RING if c.shape == "closed" else MIN_FAMILY)
            if c.ring:
                c.orbit = family_copies(c.shape, key, group, 1e-3)
                c.axis = key[0] if c.shape == "closed" else None
            else:
                c.shape, c.length, c.length_error, c.path = "", 0.0, 0.0, ()
        found.append(c)
    _broken_rings(poly, found, s, scale, group, event_dps)
    for c in found:
        # a ring's error is across it (its tilt): the bound with its transverse eigenvalue
        c.error_rad, c.error_method, c.lipschitz = _error_estimate(poly, c, s, scale, refine_dps, group, found,
                                                                    event_dps)
        if c.ring:      # a family's length scales with its radius, known to the error across it
            radius = c.length / (2 * math.pi) if c.shape == "closed" else math.sin(_nearest_axis(c.u, group))
            c.length_error += c.length * c.error_rad / max(radius, c.error_rad)
    # two float64 points of one equilibrium, brought together by the polishing, are one class; the copies
    # of a class are counted with a tolerance tied to its error (a point closer to a mirror than its
    # error lies on it to what is known)
    merged = []
    for c in sorted(found, key=lambda c: (not c.ring, c.error_rad)):
        if not c.ring and any(not m.ring and same_class(m.u, c.u, group, 2 * (m.error_rad + c.error_rad) + 1e-12)
                              for m in merged):
            continue
        if not c.ring:
            c.orbit = len(orbit(c.u, group, max(1e-12, 4 * c.error_rad)))
        merged.append(c)
    found = merged
    # a point of a ring found before the ring was recognised: same potential, not an equilibrium
    # that symmetry fixes (its residual is not exactly zero), no decided second variation
    rings = [c for c in found if c.ring]
    found = [c for c in found if c.ring or c.error_method != "near-bifurcation estimate"
             or not any(abs(c.U - r.U) <= 1e-10 * scale for r in rings)]
    found.sort(key=lambda c: (round(c.U / scale, 12), -c.u[2], -c.u[0], -c.u[1]))
    return found


def distinct_seeds(seeds, group) -> list[np.ndarray]:
    """One seed per symmetry class (seeds in one class lead to one class of critical points); the same
    seeds and group give the same choice, kept for the last ones asked (every scene of a body asks again)."""
    seeds, group = np.asarray(seeds, dtype=float), np.asarray(group, dtype=float)
    kept = _distinct(seeds.tobytes(), group.tobytes(), len(group))
    return [seeds[k].copy() for k in kept]


@functools.lru_cache(maxsize=16)
def _distinct(seeds: bytes, group: bytes, order: int) -> tuple:
    """The indices of :func:`distinct_seeds` (seeds and group as float64 bytes)."""
    seeds = np.frombuffer(seeds).reshape(-1, 3)
    group = list(np.frombuffer(group).reshape(order, 3, 3))
    return tuple({tuple(np.round(representative(u, group), 9)): k for k, u in enumerate(seeds)}.values())


def sphere_seeds(theta_steps: int, phi_max: float, phi_steps: int) -> list[np.ndarray]:
    """Seeds on the spherical patch ``0 <= theta <= pi/2`` (from +z), ``0 <= phi <= phi_max``,
    including its edges and corners."""
    seeds = []
    for i in range(theta_steps + 1):
        theta = math.pi / 2 * i / theta_steps
        count = 1 if i == 0 else phi_steps
        for j in range(count + 1 if i else 1):
            phi = phi_max * j / max(count, 1)
            seeds.append(np.array([math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi),
                                   math.cos(theta)]))
    return seeds
