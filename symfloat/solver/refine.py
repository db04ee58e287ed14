"""High-precision references for equilibria: Newton's method in mpmath on the exactly clipped body.

Used to measure the solver's true error (the float64 result against a
50-digit equilibrium) near bifurcation densities, where the Hessian is nearly
singular and the error estimate must still bound the error.
"""
from __future__ import annotations

import mpmath

from ..geometry.floating import floating_state
from .bodies import polyhedron

__all__ = ["refine_sphere", "polish", "refine_planar", "polish_planar", "planar_slope", "planar_potential",
           "planar_residual", "angle_between"]


def _local_mp(poly, u, s):
    """Gradient (2) and Hessian (2x2) of the potential in the waterplane basis, in mpmath."""
    st = floating_state(poly, u, s)
    d = [g - b for g, b in zip(st.G, st.B)]
    grad = mpmath.matrix([sum(e[k] * d[k] for k in range(3)) for e in st.basis])
    T = mpmath.matrix([[st.tensor[0][0], st.tensor[0][1]], [st.tensor[1][0], st.tensor[1][1]]])
    H = T / st.volume - st.potential * mpmath.eye(2)
    return st, grad, H


def refine_sphere(scene, u, dps: int = 50, steps: int = 12):
    """The equilibrium next to the unit vector *u*, by Newton's method at *dps* digits; returns the
    refined up vector (mpf triple) and the norm of the gradient there."""
    poly = polyhedron(scene, dps=dps)
    with mpmath.workdps(dps):
        u = [mpmath.mpf(float(x)) for x in u]
        norm = mpmath.sqrt(sum(x * x for x in u))
        u = [x / norm for x in u]
        for _ in range(steps):
            st, g, H = _local_mp(poly, u, scene.density)
            if mpmath.norm(g) < mpmath.mpf(10) ** (5 - dps):
                break
            step = mpmath.lu_solve(H, -g)
            e1, e2 = st.basis
            v = [u[k] + step[0] * e1[k] + step[1] * e2[k] for k in range(3)]
            norm = mpmath.sqrt(sum(x * x for x in v))
            u = [x / norm for x in v]
        st, g, _ = _local_mp(poly, u, scene.density)
        return tuple(u), mpmath.norm(g)


def polish(poly, u, s, scale: float, steps: int = 40, cap: float = 1e-2):
    """Newton's method at *poly*'s precision (an mpmath body) from the unit vector *u* (floats or mpf): returns
    ``(u, |grad U|, eigenvalues)`` at the best point reached (mpf; the eigenvalues of the metacentric
    Hessian there, ascending).  Steps are capped at *cap* radians and halved (up to four times) where
    the gradient would grow: next to a bifurcation the Hessian is nearly singular and a float64 point
    lies far from the equilibrium in its soft direction.  The iteration stops at a gradient of
    ``10^(2 - dps) * scale`` (the arithmetic's rounding) or when it no longer falls."""
    with mpmath.workdps(poly.dps):
        u = [mpmath.mpf(x) if isinstance(x, mpmath.mpf) else mpmath.mpf(float(x)) for x in u]
        norm = mpmath.sqrt(sum(x * x for x in u))
        u = [x / norm for x in u]
        floor = mpmath.mpf(10) ** (2 - poly.dps) * scale
        st, g, H = _local_mp(poly, u, s)
        best = (tuple(u), mpmath.norm(g), H)
        for _ in range(steps):
            if best[1] <= floor:
                break
            try:
                step = mpmath.lu_solve(H, -g)
            except ZeroDivisionError:
                break
            length = mpmath.norm(step)
            if length > cap:
                step = step * (cap / length)
            e1, e2 = st.basis
            for _ in range(5):
                v = [u[k] + step[0] * e1[k] + step[1] * e2[k] for k in range(3)]
                norm = mpmath.sqrt(sum(x * x for x in v))
                v = [x / norm for x in v]
                st_v, g_v, H_v = _local_mp(poly, v, s)
                if mpmath.norm(g_v) < best[1]:
                    break
                step = step / 2
            else:
                break
            u, st, g, H = v, st_v, g_v, H_v
            best = (tuple(u), mpmath.norm(g), H)
        u, size, H = best
        mean, half = (H[0, 0] + H[1, 1]) / 2, mpmath.sqrt(((H[0, 0] - H[1, 1]) / 2) ** 2 + H[0, 1] ** 2)
        return u, size, (mean - half, mean + half)


def refine_planar(scene, theta, dps: int = 50, steps: int = 12):
    """The heel angle of a section's equilibrium next to *theta*, at *dps* digits."""
    poly = polyhedron(scene, dps=dps)
    with mpmath.workdps(dps):
        theta = mpmath.mpf(float(theta))
        for _ in range(steps):
            u = (mpmath.cos(theta), mpmath.sin(theta), mpmath.mpf(0))
            e = (-mpmath.sin(theta), mpmath.cos(theta), mpmath.mpf(0))
            st, g, H = _local_mp(poly, u, scene.density)
            b = [[sum(basis[k] * e[k] for k in range(3))] for basis in st.basis]
            f = g[0] * b[0][0] + g[1] * b[1][0]
            fp = sum(b[i][0] * H[i, j] * b[j][0] for i in range(2) for j in range(2))
            if abs(f) < mpmath.mpf(10) ** (5 - dps):
                break
            theta -= f / fp
        return theta


def _planar(poly, theta, s):
    """``U'(theta)`` and ``U''(theta)`` of a section at *poly*'s precision (mpmath)."""
    u = (mpmath.cos(theta), mpmath.sin(theta), mpmath.mpf(0))
    e = (-mpmath.sin(theta), mpmath.cos(theta), mpmath.mpf(0))
    st, g, H = _local_mp(poly, u, s)
    b = [sum(basis[k] * e[k] for k in range(3)) for basis in st.basis]
    return g[0] * b[0] + g[1] * b[1], sum(b[i] * H[i, j] * b[j] for i in range(2) for j in range(2))


def planar_slope(poly, theta, s):
    """``U'(theta)`` and ``U''(theta)`` of a section at *poly*'s precision (mpmath), under its digits."""
    with mpmath.workdps(poly.dps):
        return _planar(poly, mpmath.mpf(theta), s)


def polish_planar(scene, theta, scale: float, dps: int = 30, steps: int = 40, cap: float = 1e-2):
    """Newton's method on ``U'(theta) = 0`` of a section at *dps* digits from the float *theta*, steps
    capped at *cap* and halved where ``|U'|`` would grow (as :func:`polish`): returns ``(theta, |U'|,
    U'')`` (mpf) at the best point reached."""
    poly = polyhedron(scene, dps=dps)
    with mpmath.workdps(dps):
        theta = mpmath.mpf(float(theta))
        floor = mpmath.mpf(10) ** (2 - dps) * scale
        f, fp = _planar(poly, theta, scene.density)
        for _ in range(steps):
            if abs(f) <= floor or fp == 0:
                break
            step = -f / fp
            step = max(-cap, min(cap, step))
            for _ in range(5):
                f_new, fp_new = _planar(poly, theta + step, scene.density)
                if abs(f_new) < abs(f):
                    break
                step /= 2
            else:
                break
            theta, f, fp = theta + step, f_new, fp_new
        return theta, abs(f), fp


def planar_potential(scene, dps: int = 30):
    """The potential of a section as a function of the heel angle, at *dps* digits (mpf)."""
    poly = polyhedron(scene, dps=dps)

    def potential(theta):
        with mpmath.workdps(dps):
            theta = mpmath.mpf(theta)
            return floating_state(poly, (mpmath.cos(theta), mpmath.sin(theta), mpmath.mpf(0)), scene.density).potential
    return potential


def planar_residual(scene, theta, dps: int = 30) -> float:
    """``|U'(theta)|`` of a section at *dps* digits (the float64 root's true residual)."""
    poly = polyhedron(scene, dps=dps)
    with mpmath.workdps(dps):
        theta = mpmath.mpf(float(theta))
        u = (mpmath.cos(theta), mpmath.sin(theta), mpmath.mpf(0))
        e = (-mpmath.sin(theta), mpmath.cos(theta), mpmath.mpf(0))
        st = floating_state(poly, u, scene.density)
        return float(abs(sum(e[k] * (st.G[k] - st.B[k]) for k in range(3))))


def angle_between(u, v) -> float:
    """The angle (radians) between two vectors given in any arithmetic, at 30 digits."""
    with mpmath.workdps(30):
        u = [mpmath.mpf(x) for x in u]
        v = [mpmath.mpf(x) for x in v]
        cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        return float(mpmath.atan2(mpmath.sqrt(sum(c * c for c in cross)), sum(a * b for a, b in zip(u, v))))
