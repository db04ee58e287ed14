"""Phase diagrams: the stable positions of a cube or box against the density.

The sweep solves the scene at densities ``s_k = k / (steps + 1)``; between
neighbours whose sets of stable positions differ, each threshold is located
by bisection on the density with the position *tracked* (Newton's method from
the last stable point): the predicate "the tracked equilibrium exists and is
stable" flips exactly at the threshold, so the bracket shrinks to ``1e-13``.
A branch that ends at a more symmetric position (a pitchfork: the child dies
into its parent) ends where the parent's soft eigenvalue crosses zero, located
on the parent.  Every branch born at a threshold, isolated or a ring, is
followed past the next sweep density, so a window narrower than the sweep, or
ending at a sweep density, is found.
Thresholds known from elsewhere (the closed forms the sources print, handed in by
:mod:`symfloat.comparison.thresholds`) are looked for where the sweep missed them and matched.
Boxes are centrally symmetric, so the stable set at ``1 - s`` is the stable
set at ``s`` turned upside down; the sweep still solves both halves (the
duality is checked, not assumed).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np

from ..geometry.floating import box
from .bodies import make_scene
from .critical import _is_ring, _tangent_eigen, newton, symmetric_newton
from .solve import body_scale, solve
from .symmetry import box_group, mirror_normals, same_class

__all__ = ["Threshold", "PhaseDiagram", "phase_diagram", "position_label"]

BRACKET = 1e-13
RING_ERROR = 1e-6       # stated error of a threshold where a ring or arc of equilibria ends


def position_label(up, family: str) -> str:
    """A name for a position class that does not change along a branch: which components of the
    (representative) up vector vanish or are equal; a ring (closed or an arc) by its axis."""
    u = [abs(x) for x in up]
    nonzero = [i for i in range(3) if u[i] > 1e-9]
    axes = "".join("xyz"[i] for i in nonzero)
    if family == "ring":
        return f"ring around {'xyz'[int(np.argmax(u))]}"
    if len(nonzero) == 1:
        return f"face {axes} up"
    values = [u[i] for i in nonzero]
    equal = max(values) - min(values) <= 1e-9
    if len(nonzero) == 2:
        return f"edge up ({axes})" if equal else f"tilted in the {axes[0]}-{axes[1]} plane"
    if equal:
        return "corner up"
    pairs = [(i, j) for i in range(3) for j in range(i + 1, 3) if abs(u[i] - u[j]) <= 1e-9]
    return f"tilted, |u_{'xyz'[pairs[0][0]]}| = |u_{'xyz'[pairs[0][1]]}|" if pairs else "tilted (general)"


@dataclass
class Threshold:
    density: float
    bracket: float
    label: str
    change: str                 # "stable below" or "stable above"
    source: list = field(default_factory=list)
    note: str = ""
    tilt: float = math.inf      # a ring's last tracked point: its tilt from the nearest axis
    up: tuple = ()              # the tracked position on the stable side


@dataclass
class PhaseDiagram:
    body: str
    dims: tuple
    densities: list
    stable: list                # per density: sorted labels of the stable positions
    thresholds: list
    unmatched_sources: list     # source thresholds the solver does not find
    duality_ok: bool
    seconds: float
    unpaired: list = field(default_factory=list)    # thresholds whose dual at 1 - s is missing


def _stable(scene):
    return _stable_of(solve(scene))


def _stable_of(sol):
    return {position_label(e.up, e.family): e for e in sol.equilibria if e.stability == "stable"}


def _tracked_stable(poly, group, u, s, label, family, scale) -> tuple[bool, np.ndarray]:
    """Whether the equilibrium tracked from *u* exists at density *s*, keeps its label and is
    stable.  The sign of the second variation decides, beyond rounding (``1e-14 * scale``: a point
    of a ring, where an eigenvalue is zero, is not a stable isolated position), so the predicate
    flips at the threshold itself.  An isolated position is tracked within its symmetry
    (:func:`symmetric_newton`: a soft direction across a mirror does not move it off the mirror).  A
    ring must stay a ring: off every axis, one null direction, positive across."""
    loc, ok = newton(poly, u, s, scale) if family == "ring" else symmetric_newton(poly, u, s, scale, group)
    if not ok:
        return False, u
    w = sorted(loc.eigen()[0], key=abs)
    if family == "ring":
        tilted = position_label(loc.u, "isolated").startswith("tilted")
        off_axis = min(np.linalg.norm(np.abs(loc.u) - e) for e in np.eye(3)) > 1e-6
        return tilted and off_axis and w[1] > 0 and abs(w[0]) < 1e-6 * scale, loc.u
    if position_label(loc.u, family) != label or not min(w) > 1e-14 * scale:
        return False, loc.u
    parent = _parent(poly, group, loc.u, s, scale, NEAR_PARENT)
    if parent is not None and min(parent.eigen()[0]) > 1e-14 * scale:
        return False, loc.u         # the point is its stable parent, not a distinct position (past a pitchfork)
    return True, loc.u


NEAR_PARENT = 1e-6      # radians: a tracked point this close to a stable more symmetric equilibrium is that one
PITCHFORK = 1e-2        # radians: a branch that ends this close to a more symmetric one ends at its pitchfork


def _parent(poly, group, u, s, scale, near):
    """The more symmetric equilibrium within *near* of *u* (the point of highest symmetry there,
    :func:`~symfloat.solver.degenerate.symmetric_point`, polished within its symmetry), or None.
    Next to a pitchfork the child lies at ``c sqrt|s - s*|`` from this parent and exists only on the
    side where the parent is unstable across the mirror (the normal form ``x (eps - x^2)``); past
    it, Newton's method within the child's symmetry lands on the parent only to the rounding of the
    gradient divided by the parent's soft eigenvalue (7e-10 rad where that is 1.3e-7, the box
    1 x 1 x 4 at 9/32 + 1e-7), which a label's tolerance of 1e-9 does not tell from a child.  A stable
    child within 1e-6 of a stable parent would need a third equilibrium between them."""
    from .degenerate import symmetric_point
    v = symmetric_point(u, group, 2 * near)
    if _fixing(group, v) <= _fixing(group, u):
        return None
    loc, ok = symmetric_newton(poly, v, s, scale, group)
    return loc if ok and np.linalg.norm(loc.u - v) <= 2 * near else None


def _locate(poly, group, scale, label, eq, s_in, s_out) -> tuple[float, float, float, str]:
    value, err, tilt, note, _ = _locate_tracked(poly, group, scale, label, eq, s_in, s_out)
    return value, err, tilt, note


def _locate_tracked(poly, group, scale, label, eq, s_in, s_out):
    """Bisection between *s_in* (label stable) and *s_out* (not) with tracking; returns the
    threshold, the half-width of the bracket, for a ring the tilt of its last point from the
    nearest axis (a ring born from an axis has a tilt near zero there), and a note.  Where an
    isolated position's smallest eigenvalue vanishes to a high order (it joins a ring of
    equilibria: ``lambda ~ (s - s*)^3`` for the cube's oblique positions), the sign is lost in
    rounding up to 1e-5 from ``s*``; then the threshold is where the waterplane passes a vertex of
    the body on the tracked branch (the ring of the first rotation region ends exactly there), found
    by bisection on which vertices are above water."""
    u = np.array(eq.up)
    lo, step = s_in, (s_out - s_in) / 8
    widest, before = abs(step), False
    while abs(step) > BRACKET / 2:          # continuation in s: a step is halved where the predicate fails
        mid = lo + step
        ok = abs(mid - s_in) < abs(s_out - s_in)
        if ok:
            ok, u_mid = _tracked_stable(poly, group, u, mid, label, eq.family, scale)
            ok = ok and (eq.family == "ring" or np.linalg.norm(u_mid - u) <= 0.05)
        if ok:
            lo, u = mid, u_mid
            if before and 2 * abs(step) <= widest:
                # two steps in a row held: the step grows again (never beyond the first), so a branch that
                # moved fast next to its birth (a pitchfork's square root) is not then walked in tiny steps
                step *= 2
        else:
            step /= 2
        before = ok
    hi = lo + 2 * step
    err = abs(hi - lo) / 2
    tilt = min(math.acos(min(1.0, abs(float(x)))) for x in u)     # from the nearest axis
    note = ""
    if eq.family != "ring":
        event = _vertex_event(poly, group, u, lo, s_out, label, scale)
        if event is not None:
            return event[0], event[1], tilt, "where the waterplane passes a vertex: the position joins a ring", u
        fork = _pitchfork(poly, group, u, lo, scale)
        if fork is not None:
            return fork[0], fork[1], tilt, f"born from the position '{fork[2]}' (pitchfork)", u
        root = _eigenvalue_root(poly, group, u, lo, scale)
        if root is not None and abs(root[0] - (lo + hi) / 2) <= 2 * err + 1e-12:
            return root[0], root[1], tilt, note, u
        fold = _fold_point(poly, group, u, lo, scale)
        if fold is not None and abs(fold[0] - lo) <= 1e-6:
            return fold[0], fold[1], tilt, "a fold: the position meets another branch and both end; error estimated", u
    else:
        # the family's point on the mirror of its representative (the walk along it may have drifted off)
        up = np.array(eq.up)
        k = int(np.argmax(np.abs(u)))
        i, j = sorted((x for x in range(3) if x != k), key=lambda x: -abs(up[x]))
        v = np.zeros(3)
        v[k], v[i] = u[k], math.copysign(math.hypot(u[i], u[j]), up[i] if up[i] else 1.0)
        loc, ok = symmetric_newton(poly, v, lo, scale, group)
        event = _vertex_event(poly, group, loc.u, lo, s_out, position_label(loc.u, "isolated"), scale,
                              ring=True) if ok else None
        if event is not None:
            return event[0], event[1], tilt, "where the waterplane passes a vertex: the family ends", u
    return (lo + hi) / 2, err, tilt, note, u


def _pitchfork(poly, group, u, s, scale):
    """A branch whose tracking ended at *s* next to a more symmetric equilibrium (its parent, within
    :data:`PITCHFORK` of the last point *u*) ends at the parent's pitchfork: where the parent's soft
    eigenvalue (across the mirror the child leaves) crosses zero, a simple crossing located by
    :func:`_eigenvalue_root` on the parent, which exists on both sides, instead of on the child,
    which does not (its own eigenvalue ``~ -2 lambda_parent`` is lost with it past the fork, and
    its distance to the parent ``~ sqrt|s - s*|`` falls below what float64 resolves).  Returns
    ``(density, error, parent's label)`` or None (no parent there, or its crossing not within 1e-4 of
    *s*).  Witness: Scheeffer IX, the long square log at 9/32 and 23/32 (tests/test_phase_log.py)."""
    parent = _parent(poly, group, u, s, scale, PITCHFORK)
    if parent is None:
        return None
    root = _eigenvalue_root(poly, group, parent.u, s, scale, gate=None, softest=True)
    if root is None or abs(root[0] - s) > 1e-4:
        return None
    return root[0], root[1], position_label(parent.u, "isolated")


def _fixing(group, u) -> int:
    """How many symmetries of the body fix *u* (to 1e-9, the tolerance of :func:`symmetric_newton`)."""
    return sum(np.linalg.norm(g @ u - u) <= 1e-9 for g in group)


def _eigenvalue_root(poly, group, u, s, scale, h: float = 1e-7, gate: float | None = 1e-8, softest=False):
    """Where the smallest eigenvalue (*softest*: the one of least magnitude) of the branch through *u*
    (followed within its symmetry) crosses zero next to *s*: Newton's method on ``lambda(s) = 0`` with
    a central difference for its slope.
    The bisection's predicate flips where ``lambda`` exceeds its rounding (``1e-14 * scale``), a few
    1e-14 past the root; the root itself is found to ``2 |last correction| + 1e-14 * scale / |slope|``
    (the rounding of ``lambda`` divided by its slope).  Returns ``(density, error)`` or None where the
    crossing is not simple (the slope below 1e-6: a root of higher order, or a ring) or ``lambda``
    at *s* exceeds ``gate * scale`` (None: no gate)."""
    def smallest(density, v):
        loc, ok = symmetric_newton(poly, v, density, scale, group)
        if not ok:
            return None, v
        w = loc.eigen()[0]
        return (float(w[np.argmin(np.abs(w))]) if softest else float(min(w))), loc.u

    for _ in range(8 if gate is None else 4):
        lam, u = smallest(s, u)
        above, _ = smallest(s + h, u)
        below, _ = smallest(s - h, u)
        if lam is None or above is None or below is None:
            return None
        slope = (above - below) / (2 * h)
        if abs(slope) < 1e-6 * scale or (gate is not None and abs(lam) > gate * scale):
            return None
        step = lam / slope
        s -= step
        if abs(step) < 1e-16:
            break
    return float(s), float(2 * abs(step) + 1e-14 * scale / abs(slope))


def _vertex_event(poly, group, u, s, s_out, label, scale, ring: bool = False):
    """The density within 1e-3 of *s* (or 1e-5, 1e-7: a window narrower than that, the long square
    log's ring around z, 4e-5 wide) where the waterplane of the branch tracked from *u* passes
    a vertex, when the eigenvalue on the side of *s_out* (*ring*: on the side of *s*, the family's)
    is zero to rounding there (a ring point), as ``(density, half-width)``; None when there is no
    such event.  The branch is followed by
    Newton's method within its symmetry (:func:`symmetric_newton`): across the mirror the potential
    is flat to rounding there, along it the position is well conditioned, so the vertices above water
    are decided at every density and the bisection closes to ``BRACKET``."""
    from .local import local
    if not ring and min(abs(local(poly, u, s).eigen()[0])) > 1e-6 * scale:
        return None                                 # a simple eigenvalue crossing: the bisection is exact
    for reach in (1e-3, 1e-5, 1e-7):
        event = _vertex_event_within(poly, group, u, s, s_out, label, scale, reach, ring)
        if event is not None:
            return event
    return None


def _vertex_event_within(poly, group, u, s, s_out, label, scale, reach, ring):
    towards = math.copysign(1.0, s_out - s)
    ends = []
    for target in (s - towards * reach, s + towards * reach):
        loc, ok = symmetric_newton(poly, u, target, scale, group)
        if not ok or position_label(loc.u, "isolated") != label:
            return None
        ends.append((target, loc))
    (lo, a), (hi, b) = ends
    inside = _vertices_above(poly, a)
    if _vertices_above(poly, b) == inside or min(abs((a if ring else b).eigen()[0])) > 1e-12 * scale:
        return None
    v = a.u
    while abs(hi - lo) > BRACKET / 8:
        mid = (lo + hi) / 2
        loc, ok = symmetric_newton(poly, v, mid, scale, group)
        if ok and _vertices_above(poly, loc) == inside:
            lo, v = mid, loc.u
        else:
            hi = mid
    return (lo + hi) / 2, abs(hi - lo) / 2 + 1e-14     # + the float64 test of which vertices are above water


def _vertices_above(poly, loc) -> tuple:
    """Which vertices of the body lie above the waterplane of *loc* (the combinatorial type of the
    floating position: the potential is analytic in the density while it does not change)."""
    t = float(loc.state.t)
    return tuple(float(np.dot(loc.u, [float(c) for c in v])) > t for v in poly.vertices)


def _continue(poly, u, label, sa, sb, scale):
    """Follow the isolated equilibrium *u* (labelled *label*) from density *sa* towards *sb* by
    Newton's method in steps of the density (halved where Newton fails, lands on another label or
    moves by more than 0.1 rad).  Returns ``(s, u, died)``: the last density reached, the point
    there and whether the branch ends before *sb* (a fold: the step fell below 1e-13)."""
    s, step = sa, sb - sa
    while s != sb:
        target = sb if abs(sb - s) <= abs(step) else s + step
        loc, ok = newton(poly, u, target, scale)
        if ok and position_label(loc.u, "isolated") == label and np.linalg.norm(loc.u - u) <= 0.1:
            s, u, step = target, loc.u, step * 2
        else:
            step /= 2
            if abs(step) < BRACKET:
                return s, u, True
    return s, u, False


def _partners(poly, group, u, s, scale) -> list:
    """Equilibria next to *u* at density *s* (a fold's other branch): Newton from steps of 1e-3 ...
    3e-2 rad along the softer eigenvector, those of another symmetry class."""
    from .critical import newton as _newton
    from .local import local, tangent_step
    values, vectors = local(poly, u, s).eigen()
    soft = vectors[int(np.argmin(np.abs(values)))]
    out = []
    for delta in (1e-3, 3e-3, 1e-2, 3e-2):
        for sign in (1, -1):
            loc, ok = _newton(poly, tangent_step(u, sign * delta * soft), s, scale)
            if ok and not same_class(loc.u, u, group, 1e-6) and not any(same_class(loc.u, v.u, group, 1e-6)
                                                                       for v in out):
                out.append(loc)
    return out


def _fold_windows(poly, group, scale, solution, sa, sb) -> list:
    """Stable positions that live only between two sweep densities: every isolated equilibrium of
    *solution* (at *sa*) is continued towards *sb*; where one ends (a fold), the branch it meets there
    is found and, when that one is stable, returned as ``(label, eq, s_fold, s_side)``: stable at
    ``s_side`` next to the fold."""
    out = []
    for e in solution.equilibria:
        if e.family == "ring":
            continue
        label = position_label(e.up, e.family)
        s, u, died = _continue(poly, np.array(e.up), label, sa, sb, scale)
        if not died:
            continue
        # a little back from the fold, where the two branches that meet there are apart
        side = s - math.copysign(min(1e-4, abs(s - sa) / 2), sb - sa)
        here, ok = newton(poly, u, side, scale)
        # Newton's method from the fold lands on either branch that meets there (to the last bits of u): where
        # the continued one is not stable, the other one it may land on is a candidate too
        other = ok and e.stability != "stable" and not same_class(here.u, u, group, 1e-6)
        candidates = ([here] if other else []) + _partners(poly, group, here.u if ok else u, side, scale)
        for k, loc in enumerate(candidates):
            if any(same_class(loc.u, o.u, group, 1e-6) for o in candidates[:k]):
                continue
            # stable by the predicate the bisection uses (a point of a ring, flat along it to rounding, is not;
            # nor one whose null eigenvalue rounding leaves just above zero: the box 1 x 3/2 x 1 at 0.91795)
            kind = position_label(loc.u, "isolated")
            if _is_ring(poly, loc, _tangent_eigen(loc), side, scale, group):
                continue
            if _tracked_stable(poly, group, loc.u, side, kind, "isolated", scale)[0]:
                out.append((kind, _Tracked(tuple(loc.u), "isolated"), s, side))
    return out


def _fold(poly, group, eq, value, err, side, scale) -> tuple[float, float]:
    """A fold's density from the tracked bisection's *value* (which ends where Newton's method stops
    converging, short of the fold or past it by an amount set by its tolerance): the fold itself is
    the solution of the extended system of :func:`_fold_point`, started from the branch at *value*.
    Where that does not converge next to *value*, the bisection's value is kept, its error the distance
    past the fold at which Newton's method still accepts a point.
    Witness: the cube's fold of Scheeffer X (171), 1 - 0.76230923886637546 at 30 digits
    (tests/test_scheeffer_x.py), and its dual."""
    loc, ok = symmetric_newton(poly, np.array(eq.up), value + math.copysign(BRACKET, side - value), scale, group)
    found = _fold_point(poly, group, loc.u, value, scale) if ok else None
    if found is not None and abs(found[0] - value) <= 1e-6:
        return found
    # no convergence: past a fold Newton's method accepts the point of least gradient while that gradient is
    # below 1e-11 * scale, and the least gradient grows at the rate |dg/ds|, so the bisection may end up to
    # c = 1e-11 * scale / |dg/ds| past the fold: that is its error
    from .local import local
    loc, ok = newton(poly, np.array(eq.up), value + math.copysign(BRACKET, side - value), scale)
    if not ok:
        return value, err
    h = 1e-6
    rate = np.linalg.norm(local(poly, loc.u, value + h).gradient - local(poly, loc.u, value - h).gradient) / (2 * h)
    return value, max(err, 1e-11 * scale / max(float(rate), 1e-300))


def _fold_point(poly, group, u, s, scale, iterations: int = 30):
    """The fold next to the equilibrium *u* at density *s*: Newton's method on the extended system
    ``F(u, s) = 0, lambda(u, s) = 0`` (Moore–Spence), ``F`` the gradient in the tangent directions
    that the symmetries of *u* fix and ``lambda`` the smallest eigenvalue of the Hessian restricted to
    them.  At a fold its Jacobian is regular (the branch turns back in *s*), so Newton converges to
    the fold from either side; ``dF/du`` is the Hessian, the other derivatives central differences.
    Returns ``(density, error)``, the error twice the last correction plus 1e-14 (the evaluation of
    ``F`` and ``lambda`` in float64), or None when the iteration does not settle."""
    from .local import local, tangent_step
    u = np.asarray(u, dtype=float)
    P = np.mean([g for g in group if np.linalg.norm(g @ u - u) <= 1e-9], axis=0)

    def restricted(v, density, B=None):
        loc = local(poly, v, density)
        if B is None:
            Pt = P - np.outer(loc.u, loc.u)
            w, vecs = np.linalg.eigh((Pt + Pt.T) / 2)
            B = vecs[:, w > 0.5]
        J = B.T @ (loc.basis @ loc.hessian @ loc.basis.T) @ B
        values = np.linalg.eigvalsh(J)
        lam = float(values[np.argmin(np.abs(values))]) if len(values) else 0.0
        return loc, B, B.T @ (loc.basis @ loc.gradient), J, lam

    last = math.inf
    for _ in range(iterations):
        loc, B, F, J, lam = restricted(u, s)
        k = B.shape[1]
        if k == 0:
            return None
        hs, hy = 1e-7 * max(1e-3, min(s, 1 - s)), 1e-6
        F_s = (restricted(u, s + hs, B)[2] - restricted(u, s - hs, B)[2]) / (2 * hs)
        lam_s = (restricted(u, s + hs)[4] - restricted(u, s - hs)[4]) / (2 * hs)
        lam_y = [(restricted(tangent_step(loc.u, hy * B[:, i]), s)[4]
                  - restricted(tangent_step(loc.u, -hy * B[:, i]), s)[4]) / (2 * hy) for i in range(k)]
        M = np.zeros((k + 1, k + 1))
        M[:k, :k], M[:k, k], M[k, :k], M[k, k] = J, F_s, lam_y, lam_s
        try:
            step = np.linalg.solve(M, -np.append(F, lam))
        except np.linalg.LinAlgError:
            return None
        dy, ds = step[:k], float(step[k])
        if not np.all(np.isfinite(step)) or np.linalg.norm(dy) > 0.05 or abs(ds) > 1e-3:
            return None
        u, s = tangent_step(loc.u, B @ dy), s + ds
        if abs(ds) < 1e-16 or (abs(ds) >= last and abs(ds) < 1e-13):
            return s, 2 * abs(ds) + 1e-14
        last = abs(ds)
    return None


@dataclass
class _Tracked:
    up: tuple
    family: str


def _thresholds_between(poly, group, scale, a, b, sa, sb) -> list[Threshold]:
    """Thresholds between two densities whose stable sets *a* and *b* differ.  A position the scene calls
    stable that the tracking predicate does not hold at its own density (:func:`_tracked_stable`: a short arc
    of equilibria next to a ring's end, flat along it, that the scene reports as one class stable across it,
    the box 1 x 3/2 x 1 at 1/12 - 1e-6) cannot be followed: the bisection never left that density and the
    threshold was reported at it, 1/12 - 1e-6 and its dual 11/12 + 1e-6 in `phase box --dims 1,3/2,1` (the
    source's look at 1/12 -+ 1e-6).  Such a position gives no threshold here."""
    out = []
    for label, side, (s_in, s_out) in [(x, "stable below", (sa, sb)) for x in sorted(set(a) - set(b))] + \
                                      [(x, "stable above", (sb, sa)) for x in sorted(set(b) - set(a))]:
        eq = (a if side == "stable below" else b)[label]
        if eq.family != "ring" and not _tracked_stable(poly, group, np.array(eq.up), s_in, label, eq.family, scale)[0]:
            continue
        value, err, tilt, note, u = _locate_tracked(poly, group, scale, label, eq, s_in, s_out)
        t = Threshold(value, err, label, side, note=note)
        t.tilt, t.up = tilt, tuple(u)
        out.append(t)
    return out


def _windows_between(poly, group, scale, sol_a, sol_b, sa, sb) -> list[Threshold]:
    """Both ends of every stable window that lies wholly between the sweep densities *sa* and *sb*,
    found at the folds of the branches continued from either side (*sol_a*, *sol_b*; None: no side)."""
    out = []
    for sol, s_from, s_to in ((sol_a, sa, sb), (sol_b, sb, sa)):
        if sol is None:
            continue
        for label, eq, s_fold, side in _fold_windows(poly, group, scale, sol, s_from, s_to):
            upward = s_to > s_from
            end, end_err, _, _ = _locate(poly, group, scale, label, eq, side, s_to)
            value, err, tilt, note = _locate(poly, group, scale, label, eq, side, s_from)
            if abs(end - s_to) <= 2 * end_err or abs(value - s_from) <= 2 * err:
                # stable at a sweep density: not a window (what ended was not a fold, but a branch met its child
                # at a pitchfork); the sweep's own change of stable sets locates it
                continue
            end, end_err = _fold(poly, group, eq, end, end_err, side, scale)
            out.append(Threshold(end, end_err, label, "stable below" if upward else "stable above",
                                 note="a fold: the position meets another branch and both end; "
                                      "error estimated"))
            birth = Threshold(value, err, label, "stable above" if upward else "stable below", note=note)
            birth.tilt = tilt
            out.append(birth)
    return out


def _follow(poly, group, scale, thresholds, densities, stable_at=None) -> list[Threshold]:
    """Every position that becomes stable at a threshold, isolated or a ring, is followed by
    continuation across its stable range, up to the sweep density beyond the next one: where it stops
    being stable before that (a fold, or the end of a ring, in a window narrower than the sweep or
    ending at a sweep density, where the ring has shrunk to nothing), the end is a threshold too.  A
    ring born from an axis opens like ``sqrt(s - s*)`` (the long square log's ring around z: 0.8 degrees
    1e-6 past its birth), so Newton's method from the birth falls back onto the axis; it is started
    from the ring the solver finds at the first density past the birth (*stable_at*: density -> the
    stable positions by label).  Positions born where a followed ring breaks (:func:`_ring_breaks`) are
    followed in turn."""
    out, born, followed = [], [], set()
    for t in thresholds:
        if not t.up:
            continue
        family = "ring" if t.label.startswith("ring") else "isolated"
        toward = 1 if t.change == "stable above" else -1
        beyond = sorted((s for s in densities if (s - t.density) * toward > 0), key=lambda s: abs(s - t.density))
        if not beyond:
            continue
        s_end = beyond[min(1, len(beyond) - 1)]
        u0 = None
        # off a pitchfork's quartic flatness; farther where the second variation is still zero to rounding
        # there (born where the waterplane passes a vertex: lambda ~ (s - s*)^3, the cube's diagonal at (3 - sqrt 2)/7)
        # (or nearer, where the window is narrower than 1e-6: the long square log's diagonal positions)
        for offset in (max(4 * t.bracket, 1e-6), 1e-7, 1e-4, 1e-3):
            start = t.density + toward * offset
            if (s_end - start) * toward <= 0:
                break
            ok, u = _tracked_stable(poly, group, np.array(t.up), start, t.label, family, scale)
            if not ok and family == "isolated":     # next to a pitchfork Newton falls back onto the parent: look beside it
                near = [loc.u for loc in _partners(poly, group, np.array(t.up), start, scale)
                        if position_label(loc.u, "isolated") == t.label and min(loc.eigen()[0]) > 0]
                ok, u = bool(near), (near[0] if near else u)
            elif not ok and stable_at is not None:
                ring = stable_at(start).get(t.label)
                if ring is not None:
                    ok, u = _tracked_stable(poly, group, np.array(ring.up), start, t.label, family, scale)
            if ok:
                u0 = u
                break
        if u0 is None:
            continue
        # what follows depends on these alone: a threshold found twice (by the sweep and by the source's look,
        # each with its own tracked point) that starts from one point is followed once
        start_point = (t.density, t.label, t.change, start, np.asarray(u0, dtype=float).tobytes())
        if start_point in followed:
            continue
        followed.add(start_point)
        value, err, tilt, note, u = _locate_tracked(poly, group, scale, t.label, _Tracked(tuple(u0), family),
                                                    start, s_end)
        if family == "ring" and stable_at is not None:
            born += _ring_breaks(poly, group, scale, t.label, u0, start, value, stable_at)
        if abs(value - s_end) <= 2 * err + 1e-9:
            continue                                  # stable all the way
        end = Threshold(value, err, t.label, "stable below" if toward > 0 else "stable above", note=note)
        end.tilt, end.up = tilt, tuple(u)
        if family == "isolated" and not note:
            end.density, end.bracket = _fold(poly, group, _Tracked(tuple(u), "isolated"), value, err, start, scale)
            end.note = "a fold: the position meets another branch and both end; error estimated"
        out.append(end)
    return out + born + (_follow(poly, group, scale, born, densities) if born else [])


def _ring_mirrors(group, axis: int) -> list[np.ndarray]:
    """Unit directions, perpendicular to the coordinate axis *axis*, of the mirror planes of the body
    (reflections of *group*) that contain that axis."""
    e = np.eye(3)[axis]
    out = []
    for n in mirror_normals(group):
        if abs(float(n @ e)) < 1e-12:           # the plane contains the axis
            d = np.cross(e, n)
            out.append(d / np.linalg.norm(d))
    return out


def _mirror_ring_end(poly, group, scale, u, s0, s1, tol: float = 1e-11) -> float:
    """The density between *s0* and *s1* where the point *u* of a ring, on a mirror plane and followed
    within it (:func:`symmetric_newton`), stops being a point of the family (its null eigenvalue
    leaves rounding, ``1e-9 * scale``), to *tol*: continuation whose step is halved where that fails
    and doubles again (never beyond the first) where it holds, so that a ring that opens like
    ``sqrt(s - s*)`` next to its birth is walked in steps that grow with it."""
    lo, first = s0, (s1 - s0) / 8
    step = first
    while abs(step) > tol:
        mid = lo + step
        if (s1 - mid) * (s1 - s0) <= 0:
            step /= 2
            continue
        loc, ok = symmetric_newton(poly, u, mid, scale, group)
        w = loc.eigen()[0] if ok else (0.0, 0.0)
        if ok and abs(min(w, key=abs)) <= 1e-9 * scale and max(w) > 0:
            lo, u = mid, loc.u
            step = min(2 * abs(step), abs(first)) * (1 if first > 0 else -1)
        else:
            step /= 2
    return lo


def _ring_breaks(poly, group, scale, label, u0, start, end, stable_at) -> list[Threshold]:
    """Positions born where a ring breaks before its end: the ring's points on the body's other mirror
    planes through its axis (the representative *u0*'s own is the one followed to *end*) are followed
    from *start*; where one stops being a point of the family inside ``(start, end)``, the waterplane
    passes a vertex there and the ring breaks into arcs, and a position may become stable beside it
    with its eigenvalue rising like a power of ``s - s*`` (the long square log's diagonal positions,
    born at 0.0105464799 inside its ring window 0.0105275 ... 0.0105655, stable for about 1e-6 and
    seen by the solver only from about 5e-8 past the break).  The stable set is solved on the ring
    before the break (half-way from *start*) and at 1e-7 ... 1e-5 past it (within the window), and a
    new stable position is located by bisection with tracking."""
    axis = int(np.argmax(np.abs(u0)))
    r = math.hypot(*(u0[i] for i in range(3) if i != axis))
    toward = 1.0 if end > start else -1.0
    out, seen = [], []
    for d in _ring_mirrors(group, axis):
        v = u0[axis] * np.eye(3)[axis] + r * d
        v = v / np.linalg.norm(v)
        if same_class(v, u0, group, 1e-6) or any(same_class(v, w, group, 1e-6) for w in seen):
            continue
        seen.append(v)
        loc, ok = symmetric_newton(poly, v, start, scale, group)
        if not ok:
            continue
        e = _mirror_ring_end(poly, group, scale, loc.u, start, end)
        if not (abs(e - start) > 1e-9 and abs(end - e) > 1e-9):
            continue
        before = (start + e) / 2
        a = stable_at(before)
        for delta in (1e-7, 1e-6, 1e-5):
            after = e + toward * delta
            if (end - after) * toward <= 0:
                break
            b = stable_at(after)
            if set(b) - set(a) - {label}:
                (sa, sa_set), (sb, sb_set) = sorted(((before, a), (after, b)), key=lambda x: x[0])
                out += [x for x in _thresholds_between(poly, group, scale, sa_set, sb_set, sa, sb)
                        if x.label != label]
                break
    return out


def _annotate_families(thresholds) -> None:
    for t in thresholds:
        if t.label.startswith("tilted") and not t.note and t.tilt < 1e-2:
            parents = [p for p in thresholds if p.label.startswith(("face", "edge")) and p.change != t.change
                       and abs(p.density - t.density) <= 1e-6]
            if parents:
                # a tilted pair collapsing onto a symmetric position is born where that position changes
                # stability (a pitchfork); Newton cannot follow it into the quartic potential
                t.density, t.bracket = parents[0].density, parents[0].bracket
                t.note = f"born from the position '{parents[0].label}' (pitchfork)"
            continue
        if not t.label.startswith("ring") or t.note:
            continue
        parents = [p for p in thresholds if p.label.startswith("face") and abs(p.density - t.density) <= 1e-6]
        if t.tilt < 1e-2 and parents:
            # a ring collapsing onto an axis is born where that position changes stability (a
            # pitchfork); Newton cannot follow it into the quartic potential, so take the axis's value
            t.density, t.bracket = parents[0].density, parents[0].bracket
            t.note = f"born from the position '{parents[0].label}' (pitchfork)"
        else:
            # where a family shrinks to a point, its null direction and the Newton tolerance blur the
            # predicate: the bisection bracket is not the error
            t.bracket = max(t.bracket, RING_ERROR)
            t.note = "end of a family of equilibria: error estimated, not bounded"


def phase_diagram(body: str, dims=None, steps: int = 48, progress=None, densities=None, known=()) -> PhaseDiagram:
    """The stable positions on a sweep of *steps* densities (or the given increasing *densities*,
    symmetric about 1/2 for the duality check) and every threshold located.  *known*: thresholds found
    elsewhere (``{"value", "label", "locators", "claim", "errata", ...}``, the sources' printed ones:
    :func:`symfloat.comparison.thresholds.phase_with_sources`); each one the sweep missed (outside it,
    or a window narrower than its spacing) is looked for at its density +- 1e-6 before it is called a
    disagreement, and every threshold found lists those it matches."""
    start = time.perf_counter()
    base = make_scene(body, "1/2", dims)
    poly = box(*base.dims)
    group = box_group(base.dims)
    scale = body_scale(base)
    densities = ([Fraction(k, steps + 1) for k in range(1, steps + 1)] if densities is None
                 else [Fraction(s) for s in densities])
    solved = {}                             # exact density -> the scene's solution: each density is solved once

    def solution_at(s):
        s = Fraction(s)
        if s not in solved:
            solved[s] = solve(make_scene(body, s, base.dims))
        return solved[s]

    def stable_at(s):
        return _stable_of(solution_at(s))

    stable, solutions = [], []
    for i, s in enumerate(densities, 1):
        if progress:
            progress(f"[{i}/{len(densities)}] density {float(s):.4f}")
        solutions.append(solution_at(s))
        stable.append(_stable_of(solutions[-1]))
    thresholds = []
    for k in range(len(densities) - 1):
        sa, sb = float(densities[k]), float(densities[k + 1])
        if set(stable[k]) != set(stable[k + 1]):
            thresholds += _thresholds_between(poly, group, scale, stable[k], stable[k + 1], sa, sb)
        thresholds += _windows_between(poly, group, scale, solutions[k], solutions[k + 1], sa, sb)
    # and before the first and after the last density of the sweep (continued to 1/64 of the gap)
    first, last = float(densities[0]), float(densities[-1])
    thresholds += _windows_between(poly, group, scale, None, solutions[0], first / 64, first)
    thresholds += _windows_between(poly, group, scale, solutions[-1], None, last, 1 - (1 - last) / 64)
    known = list(known)

    def matches(k, t):
        return abs(k["value"] - t.density) <= max(1e-9, 2 * t.bracket) and k["label"] == t.label

    seen = {}                               # id of a source threshold -> the solver's view beside it
    for k in known:
        if any(matches(k, t) for t in thresholds):
            continue
        if progress:
            progress(f"looking at the source's threshold {k['value']:.6f} ({', '.join(k['locators'])})")
        for width in (1e-6, 1e-3):           # close by first; a little farther where the close look is blurred
            sa, sb = Fraction(k["value"] - width), Fraction(k["value"] + width)
            if not 0 < sa < sb < 1:
                continue
            a, b = stable_at(sa), stable_at(sb)
            seen.setdefault(id(k), (width, k["label"] in a, k["label"] in b))
            new = _thresholds_between(poly, group, scale, a, b, float(sa), float(sb))
            thresholds += [t for t in new if not any(abs(t.density - u.density) <= 1e-9 and t.label == u.label
                                                     for u in thresholds)]
            if any(t.label == k["label"] for t in new):
                break
    _annotate_families(thresholds)          # pitchforks snapped first: a branch is followed from its birth
    thresholds += _follow(poly, group, scale, thresholds, [float(s) for s in densities], stable_at)
    _annotate_families(thresholds)
    unique = []
    for t in thresholds:                     # one entry per position and density (after the families' snapping)
        if not any(abs(t.density - u.density) <= max(1e-12, t.bracket) and t.label == u.label for u in unique):
            unique.append(t)
    thresholds = unique
    for t in thresholds:
        t.source = [k for k in known if matches(k, t)]
    matched = {id(k) for t in thresholds for k in t.source}
    unmatched = [{**k, **_why_not_found(k, seen.get(id(k)), thresholds)} for k in known if id(k) not in matched]
    labels = [sorted(x) for x in stable]
    unpaired = _unpaired(thresholds)
    duality_ok = all(labels[k] == labels[len(labels) - 1 - k] for k in range(len(labels))) and not unpaired
    thresholds.sort(key=lambda t: (t.density, t.label))
    return PhaseDiagram(body, tuple(str(d) for d in base.dims), [float(s) for s in densities], labels, thresholds,
                        unmatched, duality_ok, time.perf_counter() - start, unpaired)


def _why_not_found(k, seen, thresholds) -> dict:
    """Why the printed threshold *k* is not among the thresholds found: ``{"seen", "why"}``, from what
    the solver sees at ``k -+ width`` (``seen = (width, stable below, stable above)``; None: not looked
    at, the threshold lying within the width of 0 or 1) and the nearest change of the same position.
    ``seen`` is ``stable on neither side`` or ``stable on both sides`` (no change of the stable set
    there: the print and the solver disagree), ``change not located`` (the solver's stable set does
    change there, but its bisection found no threshold: a failure of the machinery) or ``not looked at``."""
    near = min((t for t in thresholds if t.label == k["label"]),          # of two as near (to 12 digits), the lower
               key=lambda t: (round(abs(t.density - k["value"]), 12), t.density), default=None)
    nearest = (f"; the nearest change of this position found is at {near.density:.13g} ({near.change})"
               if near is not None else "; the solver finds no change of this position")
    if seen is None:
        return {"seen": "not looked at", "why": "within the look's width of 0 or 1" + nearest}
    width, below, above = seen
    if below == above:
        kind = "stable on both sides" if below else "stable on neither side"
        why = f"at s -+ {width:.0e} the solver finds this position {kind}" + nearest
        if below and k["claim"] == "silent beyond":
            return {"seen": "stable on both sides, the print silent beyond",
                    "why": why + "; the printed formulas do not predict it unstable beyond this density (their region"
                                 " ends, or the position ceases to exist by them)"}
        if k["errata"]:
            return {"seen": f"{kind}, erratum declared",
                    "why": why + f"; an erratum is declared on {', '.join(k['errata'])}"}
        return {"seen": kind, "why": why}
    return {"seen": "change not located",
            "why": f"at s -+ {width:.0e} the solver finds it stable {'below' if below else 'above'} only, "
                   f"but no threshold of it was located there" + nearest}


def _unpaired(thresholds) -> list:
    """Thresholds without a dual: the same position at ``1 - s`` (within both errors and the float
    rounding of ``1 - s``) with the opposite change (a box turned upside down is the same box)."""
    opposite = {"stable below": "stable above", "stable above": "stable below"}
    return [t for t in thresholds
            if not any(u.label == t.label and u.change == opposite[t.change]
                       and abs(u.density - (1 - t.density)) <= t.bracket + u.bracket + 1e-15 for u in thresholds)]
