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

import mpmath
import numpy as np

from .bodies import centred_polygon

__all__ = ["box_group", "prism_group", "planar_group", "orbit", "same_class", "representative", "mirror_normals",
           "symmetry_group"]


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


def planar_group(polygon, dps: int = 50) -> list[np.ndarray]:
    """The symmetries of a convex polygon centred at its centroid (as 3x3 matrices acting on the
    x-y plane): every rotation and reflection that maps the vertex set onto itself.  The vertices
    are exact (rationals), so the test is made at *dps* digits with tolerance ``10^(10 - dps)``
    times the size: a true symmetry maps vertices onto vertices to that precision, a polygon
    symmetric only to 1e-13 (or to any error above the tolerance) is not symmetric."""
    group = []
    with mpmath.workdps(dps):
        pts = [(mpmath.mpf(x.numerator) / x.denominator if hasattr(x, "numerator") else mpmath.mpf(x),
                mpmath.mpf(y.numerator) / y.denominator if hasattr(y, "numerator") else mpmath.mpf(y))
               for x, y in polygon]
        scale = max(max(abs(x), abs(y)) for x, y in pts)
        tol = mpmath.mpf(10) ** (10 - dps) * scale
        a0 = mpmath.atan2(pts[0][1], pts[0][0])
        for i in range(len(pts)):
            ai = mpmath.atan2(pts[i][1], pts[i][0])
            for reflect in (False, True):
                # the map sending vertex 0 to vertex i (reflected: orientation reversed)
                c, s = (mpmath.cos(a0 + ai), mpmath.sin(a0 + ai)) if reflect else \
                    (mpmath.cos(ai - a0), mpmath.sin(ai - a0))
                m2 = [[c, s], [s, -c]] if reflect else [[c, -s], [s, c]]
                image = [(m2[0][0] * x + m2[0][1] * y, m2[1][0] * x + m2[1][1] * y) for x, y in pts]
                if all(min(mpmath.hypot(p[0] - q[0], p[1] - q[1]) for q in pts) <= tol for p in image):
                    m = np.eye(3)
                    m[:2, :2] = [[float(v) for v in row] for row in m2]
                    if not any(np.allclose(m, g) for g in group):
                        group.append(m)
    return group


def orbit(u, group, tol: float = 1e-9) -> list[np.ndarray]:
    """The distinct images ``g u`` (unit vectors) of *u* under *group*: each image in the group's order, kept
    where it lies farther than *tol* from every image kept before it (the distances all at once, :func:`_lengths`)."""
    if len(group) == 0:
        return []
    images = np.asarray(group, dtype=float) @ np.asarray(u, dtype=float)
    far = _lengths(images[:, None, :] - images[None, :, :]) > tol
    kept: list[int] = []
    for i in range(len(images)):
        if far[i, kept].all():
            kept.append(i)
    return [images[i].copy() for i in kept]


def same_class(u, v, group, tol: float = 1e-7) -> bool:
    """Whether *v* is (within *tol*) the image of *u* under some element of *group*: the distances
    ``|g u - v|`` of all its elements at once (:func:`_lengths`)."""
    if len(group) == 0:
        return False
    d = np.asarray(group, dtype=float) @ np.asarray(u, dtype=float) - np.asarray(v, dtype=float)
    return bool((_lengths(d) <= tol).any())


def _lengths(d: np.ndarray) -> np.ndarray:
    """The lengths of the vectors along the last axis of *d*, each its dot product with itself as
    ``numpy.linalg.norm`` takes it for one vector, bit for bit (a sum of the squares differs in the last bit)."""
    return np.sqrt(np.matmul(d[..., None, :], d[..., :, None])[..., 0, 0])


def representative(u, group) -> np.ndarray:
    """One member of the orbit of *u*, chosen the same way for every member: the image with the
    largest ``(z, x, y)`` after rounding to 9 decimals (ties broken by the unrounded values)."""
    images = (np.asarray(group) @ np.asarray(u, dtype=float)).tolist()        # Python floats: round() is cheap
    return np.array(max(images, key=lambda v: (round(v[2], 9), round(v[0], 9), round(v[1], 9), v[2], v[0], v[1])))


def mirror_normals(group) -> list[np.ndarray]:
    """Unit normals of the mirror planes of *group*: its reflections (determinant -1, trace 1), each the
    eigenvector of its eigenvalue -1."""
    out = []
    for g in group:
        g = np.asarray(g, dtype=float)
        if np.linalg.det(g) < 0 and abs(np.trace(g) - 1) < 1e-12:
            w, vectors = np.linalg.eigh((g + g.T) / 2)
            out.append(vectors[:, int(np.argmin(w))])
    return out


def symmetry_group(scene):
    """The symmetry group of a scene's body (orthogonal matrices in the body frame)."""
    if scene.body in ("cube", "box"):
        return box_group(scene.dims)
    if scene.body == "prism":
        return prism_group(scene.sides)
    if scene.body == "section":
        return planar_group(centred_polygon(scene))
    return [np.diag(d) for d in ((1, 1, 1), (1, -1, 1), (-1, 1, 1), (-1, -1, 1),
                                 (1, 1, -1), (1, -1, -1), (-1, 1, -1), (-1, -1, -1))]
