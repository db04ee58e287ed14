"""The symmetry group of a body and the symmetry class of an orientation.

Equilibria are reported once per symmetry class: two up vectors ``u`` and
``g u`` (``g`` a rotation or reflection mapping the body onto itself, centroid
fixed) describe the same floating position.  Groups are finite lists of
orthogonal 3x3 matrices; the cylinder's continuous symmetry is reduced by the
solver itself (its meridian problem) and needs only the reflections here.
"""
from __future__ import annotations

import itertools
import math

import numpy as np

__all__ = ["box_group", "prism_group", "planar_group", "orbit", "same_class", "representative"]


def box_group(dims) -> list[np.ndarray]:
    """Signed permutation matrices that map the box ``dims`` (edges along x, y, z) to itself:
    8 for three different edges, 16 for two equal, 48 for the cube."""
    group = []
    for perm in itertools.permutations(range(3)):
        if any(dims[perm[i]] != dims[i] for i in range(3)):
            continue
        for signs in itertools.product((1, -1), repeat=3):
            m = np.zeros((3, 3))
            for i in range(3):
                m[i, perm[i]] = signs[i]
            group.append(m)
    return group


def _rotation_z(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def prism_group(n: int) -> list[np.ndarray]:
    """The ``4n`` symmetries of the right prism over the regular n-gon with a vertex on +x:
    rotations by ``2 pi k / n`` about z, the reflection ``y -> -y``, and ``z -> -z``."""
    flip_y, flip_z = np.diag([1.0, -1.0, 1.0]), np.diag([1.0, 1.0, -1.0])
    group = []
    for k in range(n):
        r = _rotation_z(2 * math.pi * k / n)
        for m in (r, r @ flip_y):
            group += [m, m @ flip_z]
    return group


def planar_group(polygon, tol: float = 1e-12) -> list[np.ndarray]:
    """The symmetries of a convex polygon centred at its centroid (as 3x3 matrices acting on the
    x-y plane): every rotation and reflection that maps the vertex set onto itself."""
    pts = np.array(polygon, dtype=float)
    scale = float(np.max(np.abs(pts)))
    n = len(pts)
    group = []
    for i in range(n):
        for reflect in (False, True):
            # candidate: the map sending vertex 0 to vertex i (and, reflected, orientation reversed)
            a0 = math.atan2(pts[0, 1], pts[0, 0])
            ai = math.atan2(pts[i, 1], pts[i, 0])
            if reflect:
                m2 = np.array([[math.cos(a0 + ai), math.sin(a0 + ai)], [math.sin(a0 + ai), -math.cos(a0 + ai)]])
            else:
                m2 = np.array([[math.cos(ai - a0), -math.sin(ai - a0)], [math.sin(ai - a0), math.cos(ai - a0)]])
            image = pts @ m2.T
            if all(np.min(np.linalg.norm(pts - p, axis=1)) <= tol * scale for p in image):
                m = np.eye(3)
                m[:2, :2] = m2
                if not any(np.allclose(m, g) for g in group):
                    group.append(m)
    return group


def orbit(u, group, tol: float = 1e-9) -> list[np.ndarray]:
    """The distinct images ``g u`` (unit vectors) of *u* under *group*."""
    images = []
    for g in group:
        v = g @ np.asarray(u, dtype=float)
        if not any(np.linalg.norm(v - w) <= tol for w in images):
            images.append(v)
    return images


def same_class(u, v, group, tol: float = 1e-7) -> bool:
    """Whether *v* is (within *tol*) the image of *u* under some element of *group*."""
    v = np.asarray(v, dtype=float)
    return any(np.linalg.norm(g @ np.asarray(u, dtype=float) - v) <= tol for g in group)


def representative(u, group) -> np.ndarray:
    """One member of the orbit of *u*, chosen the same way for every member: the image with the
    largest ``(z, x, y)`` after rounding to 9 decimals (ties broken by the unrounded values)."""
    images = [g @ np.asarray(u, dtype=float) for g in group]
    return max(images, key=lambda v: (round(v[2], 9), round(v[0], 9), round(v[1], 9), v[2], v[0], v[1]))
