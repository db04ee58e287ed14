"""The floating circular cylinder in its meridian plane, by quadrature of exact slices.

Radius ``r``, length ``L`` along z, centroid at the origin, up vector
``u = (sin theta, 0, cos theta)``.  The slice of the cylinder at height ``z``
is a disk; the part below the water plane ``u . p = t`` is the segment
``x <= c(z) = (t - z cos theta) / sin theta``.  Writing ``c = r cos psi``,

    A(psi) = r^2 (pi - psi + sin psi cos psi),   int x dA = -(2/3) r^3 sin^3 psi,
    z(psi) = (t - r cos psi sin theta) / cos theta,  dz = r tan theta sin psi dpsi,

so the submerged volume and its moments are integrals of ``(pi - psi + sin psi
cos psi) sin psi``, the same times ``cos psi``, and ``sin^4 psi``, plus the
fully submerged disks.  The waterplane ``(w, y)``, ``p = t u + w e_theta + y
e_y``, has half-width ``sqrt(r^2 - x^2)`` with ``x = t sin theta + w cos
theta``; with ``x = -r cos phi`` its area and second moment are integrals of
``sin^2 phi`` times ``1``, ``cos phi`` and ``cos^2 phi``, and of ``sin^4 phi``
(about e_y, the slices contribute ``w^2`` times their width; about the w axis,
``2 (r sin phi)^3 / 3``).  Each of these has an elementary primitive
(:func:`_primitives`), which takes the slice integrals in mpmath; float64 takes
them by Gauss–Legendre at 40 nodes, exact to rounding.  Upright (``theta = 0``) and lying (``theta = pi/2``)
positions have their own closed forms.  Nothing here uses a formula of a
source.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath
import numpy as np

__all__ = ["CylinderSlice", "cylinder_slice", "CylinderState", "cylinder_state"]

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(40)


@dataclass(frozen=True)
class CylinderSlice:
    """``U`` (height of G above B), ``f = dU/dtheta``, ``fprime = d2U/dtheta2`` (the metacentric
    height for tilting in the meridian plane), the draught ``t`` and the waterplane ``shape``."""
    theta: object
    U: object
    f: object
    fprime: object
    t: object
    shape: str


class _Math:
    """float64 or mpmath arithmetic with the same names."""

    def __init__(self, dps):
        self.dps = dps
        m = math if dps is None else mpmath
        self.sin, self.cos, self.acos, self.sqrt, self.pi = m.sin, m.cos, m.acos, m.sqrt, m.pi

    def trig(self, theta):
        """``(sin theta, cos theta)`` with values below the arithmetic's resolution set to 0, so
        that the upright and lying positions take their exact branches."""
        eps = 1e-13 if self.dps is None else mpmath.mpf(10) ** (3 - self.dps)
        st, ct = self.sin(theta), self.cos(theta)
        return (self.num(0) if abs(st) < eps else st), (self.num(0) if abs(ct) < eps else ct)

    def num(self, x):
        return float(x) if self.dps is None else mpmath.mpf(x)


_INTEGRANDS = ("A sin", "A sin cos", "sin^4", "sin^2", "sin^2 cos", "sin^2 cos^2")


def _primitives(M, p):
    """The primitives at *p* of the slice integrands, with A(p) = pi - p + sin p cos p:

    int A sin p = -(pi - p) cos p - sin p + sin^3 p / 3,
    int A sin p cos p = -(pi - p) cos 2p / 4 - sin 2p / 8 + p / 8 - sin 4p / 32,
    int sin^4 p = 3p/8 - sin 2p / 4 + sin 4p / 32,
    int sin^2 p = p/2 - sin 2p / 4,   int sin^2 p cos p = sin^3 p / 3,   int sin^2 p cos^2 p = p/8 - sin 4p / 32

    (each checked by differentiation in ``tests/test_cylinder_slices.py``)."""
    sn, cs = M.sin(p), M.cos(p)
    s2, c2 = 2 * sn * cs, cs * cs - sn * sn
    s4 = 2 * s2 * c2
    rest = M.pi - p
    return {"A sin": -rest * cs - sn + sn ** 3 / 3,
            "A sin cos": -rest * c2 / 4 - s2 / 8 + p / 8 - s4 / 32,
            "sin^4": 3 * p / 8 - s2 / 4 + s4 / 32,
            "sin^2": p / 2 - s2 / 4,
            "sin^2 cos": sn ** 3 / 3,
            "sin^2 cos^2": p / 8 - s4 / 32}


def _integrals(M, a, b, about=0):
    """The slice integrals over ``[a, b]`` (all 0 unless b > a), and ``"central"``, int (cos p - about)^2 sin^2 p:
    in float64 by Gauss–Legendre at 40 nodes (exact to rounding for these integrands on ``[0, pi]``, and as
    accurate on a narrow interval); in mpmath by the primitives of :func:`_primitives`, their differences taken
    with 4 guard bits per bit of ``1/(b - a)`` (on a narrow interval a primitive's terms cancel to about the
    fourth power of its width)."""
    if not b > a:
        return dict.fromkeys((*_INTEGRANDS, "central"), M.num(0))
    if M.dps is None:
        half, mid = (b - a) / 2, (a + b) / 2
        p = mid + half * _NODES
        sn, cs = np.sin(p), np.cos(p)
        rest = np.pi - p + sn * cs
        values = {"A sin": rest * sn, "A sin cos": rest * sn * cs, "sin^4": sn ** 4, "sin^2": sn * sn,
                  "sin^2 cos": sn * sn * cs, "sin^2 cos^2": (sn * cs) ** 2, "central": ((cs - about) * sn) ** 2}
        return {k: float(half * np.dot(_WEIGHTS, v)) for k, v in values.items()}
    with mpmath.extraprec(4 * max(0, -mpmath.mag(b - a)) + 10):
        lo, hi = _primitives(M, a), _primitives(M, b)
        out = {k: hi[k] - lo[k] for k in _INTEGRANDS}
        out["central"] = out["sin^2 cos^2"] - 2 * about * out["sin^2 cos"] + about * about * out["sin^2"]
        return out


def _volume_moments(M, r, L, theta, t):
    """Submerged volume and its moments ``(V, int x dV, int z dV)``."""
    st, ct = M.trig(theta)
    if st == 0:
        h = min(max(t + L / 2, 0), L)
        return M.pi * r * r * h, M.num(0), M.pi * r * r * ((-L / 2 + h) ** 2 - L * L / 4) / 2
    if ct == 0:
        c = min(max(t, -r), r)
        psi = M.acos(c / r)
        area = r * r * (M.pi - psi + M.sin(psi) * M.cos(psi))
        return L * area, L * (-2 * r ** 3 * M.sin(psi) ** 3 / 3), M.num(0)
    z_full, z_empty = (t - r * st) / ct, (t + r * st) / ct
    lo, hi = -L / 2, L / 2
    full_hi = min(hi, z_full)
    V = Mx = Mz = M.num(0)
    if full_hi > lo:
        V += M.pi * r * r * (full_hi - lo)
        Mz += M.pi * r * r * (full_hi ** 2 - lo ** 2) / 2
    a, b = max(lo, z_full), min(hi, z_empty)
    if b > a:
        # the slice at z(psi) = (t - r cos psi sin theta)/cos theta: area r^2 A(psi), int x dA = -(2/3) r^3 sin^3 psi,
        # dz = jac sin psi dpsi
        psi_of = lambda z: M.acos(min(max((t - z * ct) / st / r, -1), 1))
        jac = r * st / ct
        i = _integrals(M, psi_of(a), psi_of(b))
        V += r * r * jac * i["A sin"]
        Mz += r * r * jac / ct * (t * i["A sin"] - r * st * i["A sin cos"])
        Mx += -2 * r ** 3 / 3 * jac * i["sin^4"]
    return V, Mx, Mz


def _waterplane(M, r, L, theta, t, area_only=False):
    """Area, centroid ``w``, central second moments about e_y (``I_w``) and about the w axis (``I_y``: the
    waterplane is symmetric about y = 0) of the waterplane, and its shape (``area_only``: the area alone)."""
    st, ct = M.trig(theta)
    if st == 0:
        return M.pi * r * r if area_only else (M.pi * r * r, M.num(0), M.pi * r ** 4 / 4, M.pi * r ** 4 / 4, "circle")
    if ct == 0:
        half = M.sqrt(max(r * r - t * t, 0))
        if area_only:
            return 2 * half * L
        return 2 * half * L, M.num(0), 2 * half * L ** 3 / 12, L * (2 * half) ** 3 / 12, "rectangle"
    w_lo, w_hi = (-r - t * st) / ct, (r - t * st) / ct
    z_lo, z_hi = (t * ct - L / 2) / st, (t * ct + L / 2) / st
    a, b = max(w_lo, z_lo), min(w_hi, z_hi)
    shape = "ellipse" if (a == w_lo and b == w_hi) else "truncated ellipse"
    # the slice at w(phi) = (-r cos phi - t sin theta)/cos theta, dw = r sin phi / cos theta dphi, of width
    # 2 r sin phi: area int 2 r^2 sin^2 phi / cos theta, int w dA, int (w - centre)^2 dA, and
    # int y^2 dA = int 2 (r sin phi)^3/3 dw
    phi_of = lambda w: M.acos(min(max(-(t * st + w * ct) / r, -1), 1))
    p0, p1 = phi_of(a), phi_of(b)
    if p0 > p1:
        p0, p1 = p1, p0
    i = _integrals(M, p0, p1)
    weight = 2 * r * r / ct
    area = weight * i["sin^2"]
    if area_only:
        return area
    if not area > 0:
        return area, M.num(0), M.num(0), M.num(0), shape
    centre = weight / ct * (-r * i["sin^2 cos"] - t * st * i["sin^2"]) / area
    # about the centroid: w - centre = -(r / cos theta)(cos phi - k), k = -(t sin theta + centre cos theta)/r
    about = -(t * st + centre * ct) / r
    I_w = weight * (r / ct) ** 2 * _integrals(M, p0, p1, about)["central"]
    I_y = 2 * r ** 4 / (3 * ct) * i["sin^4"]
    return area, centre, I_w, I_y, shape


def _draught(M, r, L, theta, s):
    st, ct = M.trig(theta)
    total = M.pi * r * r * L
    lo, hi = -(L / 2 * ct + r * st), L / 2 * ct + r * st
    target = s * total
    t = lo + s * (hi - lo)
    tol = (hi - lo) * (M.num("1e-15") if M.dps is None else mpmath.mpf(10) ** (2 - M.dps))
    for _ in range(200):
        f = _volume_moments(M, r, L, theta, t)[0] - target
        if f < 0:
            lo = t
        else:
            hi = t
        area = _waterplane(M, r, L, theta, t, area_only=True)
        new = t - f / area if area > 0 else (lo + hi) / 2
        if not lo < new < hi:
            new = (lo + hi) / 2
        if abs(new - t) <= tol or hi - lo <= tol:
            return new
        t = new
    return t


def cylinder_slice(r, L, theta, s, dps=None) -> CylinderSlice:
    """The potential and its first two derivatives in the meridian plane at tilt *theta*."""
    M = _Math(dps)
    with (mpmath.workdps(dps) if dps else _nothing()):
        r, L, theta, s = M.num(r), M.num(L), M.num(theta), M.num(s)
        t = _draught(M, r, L, theta, s)
        V, Mx, Mz = _volume_moments(M, r, L, theta, t)
        B = (Mx / V, Mz / V)
        st, ct = M.trig(theta)
        U = -(st * B[0] + ct * B[1])
        f = -(ct * B[0] - st * B[1])
        area, centre, I, _, shape = _waterplane(M, r, L, theta, t)
        return CylinderSlice(theta, U, f, I / V - U, t, shape)


@dataclass(frozen=True)
class CylinderState:
    """The cylinder floating at tilt ``theta`` in its meridian plane: ``sin``, ``cos`` of the tilt (0 below the
    arithmetic's resolution: the upright and lying branches), the draught ``t`` (the water plane ``u . p = t``),
    the submerged volume ``V`` and its moments ``Mx = int x dV``, ``Mz = int z dV``, and the waterplane
    ``p = t u + w e_theta + y e_y``: its ``area``, centroid ``centre`` (along w), central second moments
    ``I_w`` (about the line along e_y) and ``I_y`` (about the w axis), and its ``shape``."""
    sin: object
    cos: object
    t: object
    V: object
    Mx: object
    Mz: object
    area: object
    centre: object
    I_w: object
    I_y: object
    shape: str


def cylinder_state(r, L, theta, s, dps=None) -> CylinderState:
    """The floating state of the cylinder of radius *r*, length *L* at tilt *theta* and density ratio *s*, in
    float64 (``dps`` None) or at *dps* digits."""
    M = _Math(dps)
    with (mpmath.workdps(dps) if dps else _nothing()):
        r, L, theta, s = M.num(r), M.num(L), M.num(theta), M.num(s)
        t = _draught(M, r, L, theta, s)
        return CylinderState(*M.trig(theta), t, *_volume_moments(M, r, L, theta, t), *_waterplane(M, r, L, theta, t))


class _nothing:
    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False
