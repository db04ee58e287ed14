"""The potential of a floating polyhedron near one orientation: value, gradient and Hessian.

With ``u`` the up vector (body frame), ``G`` the centroid and ``B(u)`` the
centre of buoyancy at the draught that displaces ``s`` times the volume, the
potential is ``U(u) = u . (G - B(u))``, the height of G above B.  Turning
the body changes the submerged part only by two thin wedges of equal volume at
the waterplane, whose heights above the waterplane cancel; hence
``u . dB = 0`` and the gradient of ``U`` on the unit sphere is the horizontal
part of ``G - B``:

    grad U = (e1 . (G - B), e2 . (G - B)),

``(e1, e2)`` an orthonormal basis of the waterplane.  At an equilibrium the
covariant Hessian is the metacentric matrix (Scheeffer (8), Duhamel)

    H = T / V - U Id,

``T`` the second-moment tensor of the waterplane about its centroid and ``V``
the submerged volume; it is continuous in ``u``, so Newton's method with it
converges quadratically to every equilibrium.  Everything is measured on the
clipped polyhedron (:mod:`symfloat.geometry.floating`), never by a formula of
a source.
"""
from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass

import mpmath
import numpy as np

from ..geometry.floating import floating_state, submerged

__all__ = ["Local", "local", "tangent_step", "waterplane_polygon"]


@dataclass(frozen=True)
class Local:
    """``u`` (unit), potential ``U``, the waterplane ``basis`` (3x2, columns e1, e2),
    ``gradient`` and ``hessian`` in that basis (2 and 2x2), the floating ``state`` (None from the
    batched search, :func:`symfloat.solver.critical.newton_all`)."""
    u: np.ndarray
    U: float
    basis: np.ndarray
    gradient: np.ndarray
    hessian: np.ndarray
    state: object

    def eigen(self):
        """Hessian eigenvalues (ascending) and their eigenvectors as 3-D tangent vectors."""
        w, vecs = np.linalg.eigh(self.hessian)
        return w, (self.basis @ vecs).T


MEMO = 4096      # evaluations remembered: Newton's method restarted from a point it reached, and a family walked
                 # again from a point walked before (the second search), ask for the same ones
_remembered: OrderedDict = OrderedDict()    # (id of the body, bits of u, type and value of s) -> (body, Local)


def local(poly, u, s) -> Local:
    """Potential, gradient and metacentric Hessian of *poly* at up vector *u* and density *s*.  At a float64
    *u* on a float64 body the result is remembered (:data:`MEMO`), keyed by the body itself (held, so its id
    is not reused), the bits of *u* and the exact density with its type; its arrays are read-only."""
    v = np.asarray(u)
    if poly.dps is not None or v.dtype != np.float64 or v.shape != (3,):
        return _evaluated(poly, u, s)
    key = (id(poly), v.tobytes(), type(s), s)
    if key in _remembered:
        _remembered.move_to_end(key)
        return _remembered[key][1]
    loc = _evaluated(poly, u, s)
    for a in (loc.u, loc.basis, loc.gradient, loc.hessian):
        a.flags.writeable = False
    _remembered[key] = (poly, loc)
    if len(_remembered) > MEMO:
        _remembered.popitem(last=False)
    return loc


def _evaluated(poly, u, s) -> Local:
    st = floating_state(poly, tuple(u), s)
    e1, e2 = (np.array([float(x) for x in e]) for e in st.basis)
    d = np.array([float(g - b) for g, b in zip(st.G, st.B)])
    V, U = float(st.volume), float(st.potential)
    T = [[float(x) for x in row] for row in st.tensor]
    E = np.stack([e1, e2], axis=1)                                # 3x2
    return Local(np.array([float(x) for x in st.u]), U, E, E.T @ d, np.array(T) / V - U * np.eye(2), st)


def gradient_at(poly, u, s) -> np.ndarray:
    """The gradient (3-vector) evaluated in *poly*'s own arithmetic (float64 or mpmath)."""
    st = floating_state(poly, tuple(u), s)
    with mpmath.workdps(poly.dps or 15):
        d = [g - b for g, b in zip(st.G, st.B)]
        comps = [sum(e[k] * d[k] for k in range(3)) for e in st.basis]
        vec = [comps[0] * st.basis[0][k] + comps[1] * st.basis[1][k] for k in range(3)]
    return np.array([float(x) for x in vec])


def tangent_step(u: np.ndarray, step: np.ndarray) -> np.ndarray:
    """Move the unit vector *u* along the tangent vector *step* (radians) on the sphere."""
    angle = float(np.linalg.norm(step))
    if angle == 0:
        return u
    return u * np.cos(angle) + step / angle * np.sin(angle)


def waterplane_polygon(poly, state) -> list[np.ndarray]:
    """The waterplane polygon of a floating *state* (3-D vertices, counter-clockwise from above)."""
    wp = submerged(poly, state.u, state.t).waterplane
    return [np.array([float(x) for x in p]) for p in wp.polygon]
