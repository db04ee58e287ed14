"""The second variation at the positions a symmetry of the body fixes, in exact arithmetic.

A position ``u`` that a subgroup of the body's symmetries fixes, with no tangent direction fixed
(face, edge or corner up; a prism's axis up), is an equilibrium by
symmetry.  Its stability is decided here from the scene's rationals, never from float eigenvalues:
next to a pitchfork the smallest eigenvalue is 1e-9 and float64 (or a polished point that wandered
onto the ring being born) gets its sign wrong.

With ``n`` an integer direction (``u = n / sqrt N``, ``N = n . n``) the water plane is ``n . p = tau``.
Between two consecutive heights ``n . v`` of the vertices the submerged volume ``V(tau)`` is a cubic
and the moments of the submerged part and of the waterplane are polynomials of degree at most 4 in
``tau`` with rational coefficients (the clipped vertices are affine in ``tau``); they are measured by
clipping the body exactly (FLINT's rationals, ``fmpq``) at five interior offsets and interpolated.
The draught ``tau0`` is the root of ``V(tau) - s V_body`` in its slab: rational or algebraic (the cube's
corner up: a cube root).  On the waterplane, projected onto the coordinate plane across the largest
component ``n_k`` of ``n`` (area scale ``sqrt N / |n_k|``) with central second moments ``J`` and the
lift ``L`` (``p - c = L (q - c_q)``), the metacentric matrix ``T/V - U`` (Scheeffer (8)) has

    lambda1 + lambda2 = (N tr M / (|n_k| V) - 2 d) / sqrt N,
    lambda1 lambda2  = N e2(M) / (n_k^2 V^2) - d tr M / (|n_k| V) + d^2 / N,

``M = L J L^T`` (rational), ``e2`` the sum of its principal 2 x 2 minors, ``d = n . (G - B)``.  Each sign
is the sign of a polynomial in ``tau0`` with rational coefficients (positive denominators cleared): zero exactly when
the minimal polynomial of ``tau0`` divides it, else decided on an isolating interval of ``tau0`` narrowed
until the polynomial's Taylor bound there excludes zero (it terminates: the value is not zero).  The
polynomials, their factors over QQ and the bisections are FLINT's exact rationals (``fmpq_poly``, ``fmpq``).

A regular prism's vertices are not rational; its axis up is decided from the n-gon's polar moment
``J = n R^4 sin(2 pi/n) (2 + cos(2 pi/n)) / 12`` (the fan of triangles from the centre, each
``area (|P_k|^2 + |P_k+1|^2 + P_k . P_k+1) / 6``): ``lambda = R^2 (2 + cos(2 pi/n)) / (12 s b) - b (1 - s) / 2``,
zero exactly only where ``cos(2 pi/n)`` is rational (n = 3, 4, 6: exact rationals), else never at a
rational density, so enough digits decide its sign.  Its lateral faces and edges up are decided from
the body clipped at 30 digits or more (:func:`lateral_second_variation`), not exactly.
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import numpy as np
from flint import fmpq, fmpq_poly

from ..geometry.convex import hull_2d
from ..geometry.floating import _clip, floating_state, polygon_moments
from .bodies import polyhedron
from .symmetry import same_class

__all__ = ["ExactSecondVariation", "exact_second_variation", "prism_axis_second_variation", "lateral_second_variation",
           "symmetric_positions",
           "rational_faces", "integer_direction"]

@dataclass(frozen=True)
class ExactSecondVariation:
    """The metacentric eigenvalues at a symmetric position: the signs of their sum and product
    (``sum_sign``, ``product_sign``: -1, 0, +1), the eigenvalues (floats, ascending), whether they are equal
    exactly (``isotropic``) and how the signs were decided (``draught``: "rational" or "algebraic of degree k",
    exactly; "N digits" for a prism lying, from the body clipped at N digits)."""
    eigenvalues: tuple
    sum_sign: int
    product_sign: int
    isotropic: bool
    draught: str

    @property
    def stability(self) -> str:
        """``stable`` (both positive), ``unstable`` (one negative) or ``degenerate`` (one zero)."""
        if self.product_sign < 0:
            return "unstable"
        if self.product_sign == 0:
            return "degenerate"
        return "stable" if self.sum_sign > 0 else "unstable"


def rational_faces(scene):
    """The faces of a cube or box scene with exact rational vertices (FLINT's ``fmpq``; the body frame of
    :func:`~symfloat.solver.bodies.polyhedron`)."""
    a, b, c = (_q(x) for x in scene.dims)
    polygon = [(-a / 2, -b / 2), (a / 2, -b / 2), (a / 2, b / 2), (-a / 2, b / 2)]
    h = c / 2
    n = len(polygon)
    top = tuple((x, y, h) for x, y in polygon)
    bottom = tuple((x, y, -h) for x, y in reversed(polygon))
    sides = tuple(((polygon[i][0], polygon[i][1], -h), (polygon[(i + 1) % n][0], polygon[(i + 1) % n][1], -h),
                   (polygon[(i + 1) % n][0], polygon[(i + 1) % n][1], h), (polygon[i][0], polygon[i][1], h))
                  for i in range(n))
    return (bottom, top) + sides


def integer_direction(u, limit: int = 10 ** 6) -> tuple | None:
    """The integer vector ``n`` (coprime components) with ``n / |n|`` equal to the unit vector *u* to
    1e-12, or None: the exact direction of a symmetric position from its float64 up vector."""
    u = np.asarray(u, dtype=float)
    big = float(np.max(np.abs(u)))
    ratios = [Fraction(float(x) / big).limit_denominator(1000) for x in u]
    common = math.lcm(*(r.denominator for r in ratios))
    n = [int(r * common) for r in ratios]
    g = math.gcd(*n)
    n = tuple(x // g for x in n)
    if max(abs(x) for x in n) > limit:
        return None
    back = np.array(n, dtype=float) / math.sqrt(sum(x * x for x in n))
    return n if np.linalg.norm(back - u) <= 1e-12 else None


def _volume_moment(faces):
    """Volume and first moment ``int p dV`` of a closed polyhedron (faces counter-clockwise from outside),
    by fan tetrahedra from the origin: exact in the arithmetic of the coordinates."""
    volume, moment = fmpq(0), [fmpq(0)] * 3
    for ring in faces:
        a = ring[0]
        for b, d in zip(ring[1:], ring[2:]):
            v = (a[0] * (b[1] * d[2] - b[2] * d[1]) + a[1] * (b[2] * d[0] - b[0] * d[2])
                 + a[2] * (b[0] * d[1] - b[1] * d[0])) / 6
            volume += v
            for k in range(3):
                moment[k] += v * (a[k] + b[k] + d[k]) / 4
    return volume, moment


def _below(faces, n, tau, k):
    """The part of the body below ``n . p = tau`` (exact): volume, ``n . int p dV``, and the waterplane
    projected across axis *k*: area, first and raw second moments ``(A, (Sx, Sy), (Sxx, Sxy, Syy))``."""
    kept, on_plane = _clip(faces, n, tau)
    i, j = [x for x in range(3) if x != k]
    coords = {(p[i], p[j]): p for p in on_plane}
    ring2 = hull_2d(list(coords))
    cap = [coords[q] for q in ring2]
    if len(cap) >= 3:
        normal = sum((cap[m][(k + 1) % 3] - cap[0][(k + 1) % 3]) * (cap[m + 1][(k + 2) % 3] - cap[0][(k + 2) % 3])
                     - (cap[m][(k + 2) % 3] - cap[0][(k + 2) % 3]) * (cap[m + 1][(k + 1) % 3] - cap[0][(k + 1) % 3])
                     for m in range(1, len(cap) - 1))
        kept = list(kept) + [tuple(cap) if normal * n[k] > 0 else tuple(cap[::-1])]
    volume, moment = _volume_moment(kept)
    area, centroid, J = polygon_moments(ring2) if len(ring2) >= 3 else (fmpq(0), None, None)
    if centroid is None:
        return volume, sum(n[m] * moment[m] for m in range(3)), (fmpq(0), (fmpq(0),) * 2, (fmpq(0),) * 3)
    cx, cy = centroid
    raw = (J[0][0] + area * cx * cx, J[0][1] + area * cx * cy, J[1][1] + area * cy * cy)
    return volume, sum(n[m] * moment[m] for m in range(3)), (area, (area * cx, area * cy), raw)


def _q(x) -> fmpq:
    """A :class:`~fractions.Fraction` or an int as a FLINT rational (a FLINT rational as it is)."""
    if isinstance(x, fmpq):
        return x
    x = Fraction(x)
    return fmpq(x.numerator, x.denominator)


def _interpolate(points, values) -> fmpq_poly:
    """The polynomial in ``tau`` (over QQ) through ``(points[i], values[i])`` (Lagrange, exact)."""
    xs, ys = [_q(p) for p in points], [_q(v) for v in values]
    out = fmpq_poly([])
    for i, (xi, yi) in enumerate(zip(xs, ys)):
        term = fmpq_poly([yi])
        for j, xj in enumerate(xs):
            if j != i:
                term *= fmpq_poly([-xj, 1]) / (xi - xj)
        out += term
    return out


def _sign_of(x) -> int:
    return (x > 0) - (x < 0)


def _narrowed(f, a, b):
    """The half of the isolating interval ``[a, b]`` of the simple root of *f* that holds it (exact signs;
    a midpoint that is the root is not possible: *f* is irreducible of degree at least 2)."""
    m = (a + b) / 2
    return (a, m) if _sign_of(f(a)) * _sign_of(f(m)) < 0 else (m, b)


def _sign_at_root(p, root) -> int:
    """The sign of the polynomial *p* at the algebraic number *root* = ``(f, a, b)``: *f* irreducible
    over QQ with exactly one root in the rational interval ``[a, b]`` (a point where *f* is linear).
    Zero exactly when *f* divides *p*; else the remainder ``r = p mod f`` (not zero at the root) is
    expanded at the midpoint ``m`` of the interval (half-width ``h``) and its sign is that of ``r(m)``
    once ``|r(m)|`` exceeds the Taylor bound ``sum |r_e| h^e`` (e >= 1), the interval halved (16 times a
    round) until it does."""
    f, a, b = root
    r = p % f
    if r.is_zero():
        return 0
    if f.degree() == 1:
        return _sign_of(r(a))
    while True:
        m, h = (a + b) / 2, (b - a) / 2
        coeffs = r(fmpq_poly([m, 1])).coeffs()      # r(m + x): its Taylor coefficients at m
        bound = sum((abs(c) * h ** e for e, c in enumerate(coeffs) if e >= 1), fmpq(0))
        if abs(coeffs[0]) > bound:
            return _sign_of(coeffs[0])
        for _ in range(16):
            a, b = _narrowed(f, a, b)


def _root_in(f_all, lo, hi):
    """The root of *f_all* in ``[lo, hi]`` (exactly one, simple, *f_all* increasing there): ``(f, a, b)``
    with *f* its irreducible factor over QQ and ``[a, b]`` an isolating interval (``a = b`` for a rational
    root).  The factor is the linear one whose root lies in ``[lo, hi]`` or the one that changes sign
    between *lo* and *hi* (a factor of degree 2 or more has no rational root, the others none inside)."""
    for f, _ in f_all.factor()[1]:
        if f.degree() == 1:
            r = -f.coeffs()[0] / f.coeffs()[1]
            if lo <= r <= hi:
                return f, r, r
        elif _sign_of(f(lo)) * _sign_of(f(hi)) < 0:
            return f, lo, hi
    raise ArithmeticError("the draught is not in its slab")


def exact_second_variation(scene, n) -> ExactSecondVariation:
    """The second variation at the up direction ``n / |n|`` (*n* integer) of a cube or box scene, decided
    exactly (module docstring)."""
    faces = rational_faces(scene)
    s = _q(scene.density)
    N = sum(x * x for x in n)
    k = max(range(3), key=lambda m: abs(n[m]))
    nk = abs(n[k])
    total, moment = _volume_moment(faces)
    nG = sum(n[m] * moment[m] for m in range(3)) / total
    target = s * total
    heights = sorted({sum(n[m] * v[m] for m in range(3)) for ring in faces for v in ring})
    lo = hi = None
    for a, b in zip(heights, heights[1:]):
        if _below(faces, n, a, k)[0] <= target <= _below(faces, n, b, k)[0]:
            lo, hi = a, b
            break
    samples = [lo + (hi - lo) * fmpq(m, 6) for m in range(1, 6)]
    measured = [_below(faces, n, t, k) for t in samples]
    V = _interpolate(samples, [x[0] for x in measured])
    nM = _interpolate(samples, [x[1] for x in measured])
    A = _interpolate(samples, [x[2][0] for x in measured])
    S1 = [_interpolate(samples, [x[2][1][m] for x in measured]) for m in range(2)]
    S2 = [_interpolate(samples, [x[2][2][m] for x in measured]) for m in range(3)]
    Vs = _q(target)
    root = _root_in(V - Vs, _q(lo), _q(hi))
    # A J = A S2 - S1 S1^T (the central moments times the area: polynomials)
    AJ = [[A * S2[0] - S1[0] * S1[0], A * S2[1] - S1[0] * S1[1]], [A * S2[1] - S1[0] * S1[1], A * S2[2] - S1[1] * S1[1]]]
    i, j = [x for x in range(3) if x != k]
    L = [[0, 0] for _ in range(3)]
    L[i][0], L[j][1] = 1, 1
    L[k] = [fmpq(-n[i], n[k]), fmpq(-n[j], n[k])]
    AM = [[sum(L[r][p] * AJ[p][q] * L[c][q] for p in range(2) for q in range(2)) for c in range(3)] for r in range(3)]
    trAM = AM[0][0] + AM[1][1] + AM[2][2]
    e2A2 = sum(AM[r][r] * AM[c][c] - AM[r][c] * AM[c][r] for r in range(3) for c in range(r + 1, 3))
    dV = fmpq_poly([_q(nG) * Vs]) - nM                        # d Vs = n . (G - B) V
    # sign(lambda1 + lambda2) = sign(N tr(AM) - 2 |n_k| A (d Vs)); product times N n_k^2 Vs^2 A^2 (module docstring)
    total_poly = N * trAM - 2 * nk * A * dV
    product_poly = N * N * e2A2 - N * nk * dV * trAM * A + nk * nk * dV * dV * A * A
    discriminant = trAM * trAM - 4 * e2A2          # (mu1 - mu2)^2 A^2
    sum_sign, product_sign = _sign_at_root(total_poly, root), _sign_at_root(product_poly, root)
    isotropic = _sign_at_root(discriminant, root) == 0
    f, a, b = root
    while b - a > fmpq(1, 10 ** 45):
        a, b = _narrowed(f, a, b)
    with mpmath.workdps(40):
        t0 = (_mp(a) + _mp(b)) / 2

        def at(p):
            return mpmath.polyval([_mp(c) for c in reversed(p.coeffs())], t0)
        Vf, Af, trf, e2f, df = _mp(Vs), at(A), at(trAM), at(e2A2), at(dV)
        scale_T = mpmath.sqrt(N) / nk                   # the waterplane's area scale
        tr_T, e2_T = scale_T * trf / Af, scale_T ** 2 * e2f / Af ** 2
        U = df / Vf / mpmath.sqrt(N)
        half = 0 if isotropic else mpmath.sqrt(max(tr_T ** 2 / 4 - e2_T, 0))
        eigen = tuple(float(m / Vf - U) for m in (tr_T / 2 - half, tr_T / 2 + half))
    if product_sign == 0:
        eigen = (0.0, eigen[1]) if abs(eigen[0]) <= abs(eigen[1]) else (eigen[0], 0.0)
        eigen = tuple(sorted(eigen))
    if isotropic and sum_sign == 0:
        eigen = (0.0, 0.0)
    kind = "rational" if f.degree() == 1 else f"algebraic of degree {f.degree()}"
    return ExactSecondVariation(eigen, sum_sign, product_sign, isotropic, kind)


def _mp(x: fmpq):
    """A FLINT rational in mpmath at the working precision."""
    return mpmath.mpf(int(x.p)) / int(x.q)


def prism_axis_second_variation(scene) -> ExactSecondVariation:
    """The second variation of a regular prism (side ``a``, length ``b``) axis up: both eigenvalues
    ``R^2 (2 + cos(2 pi/n)) / (12 s b) - b (1 - s) / 2`` (module docstring).  For n = 3, 4, 6 it is a
    rational; otherwise ``cos(2 pi/n)`` is irrational (Niven) and the value is not zero at a rational
    density: it is evaluated at 30, 60, ... digits until it exceeds ``10^(5 - dps)`` of the size (the
    rounding of a dozen operations), which decides its sign."""
    n, a, b, s = scene.sides, Fraction(scene.dims[0]), Fraction(scene.dims[1]), Fraction(scene.density)
    rational_sin2 = {3: Fraction(3, 4), 4: Fraction(1, 2), 6: Fraction(1, 4)}
    if n in rational_sin2:
        sin2 = rational_sin2[n]
        value = a * a / (4 * sin2) * (3 - 2 * sin2) / (12 * s * b) - b * (1 - s) / 2
        return ExactSecondVariation((float(value),) * 2, _sign(value), 1 if value else 0, True, "rational")
    dps = 30
    while True:
        with mpmath.workdps(dps):
            sin2 = mpmath.sinpi(mpmath.mpf(1) / n) ** 2
            q = lambda x: mpmath.mpf(x.numerator) / x.denominator
            value = q(a) ** 2 / (4 * sin2) * (3 - 2 * sin2) / (12 * q(s) * q(b)) - q(b) * (1 - q(s)) / 2
            if abs(value) > mpmath.mpf(10) ** (5 - dps) * max(q(a), q(b)):
                sign = 1 if value > 0 else -1
                return ExactSecondVariation((float(value),) * 2, sign, 1, True, "rational")
        dps *= 2


def _sign(x) -> int:
    return (x > 0) - (x < 0)


def lateral_second_variation(scene, k: int) -> ExactSecondVariation:
    """The second variation of a regular prism lying with ``u = (cos(k pi/n), sin(k pi/n), 0)`` up (a lateral
    face or edge up), from the body clipped in mpmath at 30, 60, 120 and 240 digits (its vertices ``cos`` and
    ``sin`` of multiples of ``2 pi/n``, irrational but for n = 3, 4, 6): the first precision at which the
    smaller eigenvalue exceeds ``10^(5 - dps)`` of the size in magnitude (the clipping's stated error,
    :mod:`symfloat.geometry.floating`) decides the signs; where none does, the position is taken as
    degenerate and its higher orders decide (:mod:`~symfloat.solver.degenerate`)."""
    n, scale = scene.sides, float(max(scene.dims[0] / (2 * math.sin(math.pi / scene.sides)), scene.dims[1]))
    for dps in (30, 60, 120, 240):
        body = polyhedron(scene, dps=dps)
        with mpmath.workdps(dps):
            u = (mpmath.cospi(mpmath.mpf(k) / n), mpmath.sinpi(mpmath.mpf(k) / n), mpmath.mpf(0))
            st = floating_state(body, u, scene.density)
            T = st.tensor
            a, b, c = T[0][0] / st.volume - st.potential, T[0][1] / st.volume, T[1][1] / st.volume - st.potential
            mean, half = (a + c) / 2, mpmath.sqrt(((a - c) / 2) ** 2 + b ** 2)
            eigen = (mean - half, mean + half)
            rounding = mpmath.mpf(10) ** (5 - dps) * scale
            if min(abs(e) for e in eigen) > rounding:
                return ExactSecondVariation(tuple(float(e) for e in eigen), _sign(eigen[0] + eigen[1]),
                                            _sign(eigen[0] * eigen[1]), False, f"{dps} digits")
    small = min(range(2), key=lambda i: abs(eigen[i]))
    values = tuple(sorted(0.0 if i == small else float(eigen[i]) for i in range(2)))
    return ExactSecondVariation(values, _sign(eigen[1 - small]), 0, False, f"{dps} digits")


def symmetric_positions(scene, group) -> list:
    """One up vector per symmetry class of the positions a symmetry of the body fixes with no tangent
    direction fixed, with the exact direction and its second variation: ``(u, n, exact)``.  Cube and box:
    the faces, and the edges and corners where the symmetries fix them; a regular prism: its axis (exact)
    and its lateral faces and edges up (*n* None: decided at 30 digits or more,
    :func:`lateral_second_variation`)."""
    if scene.body == "prism":
        out = [(np.array([0.0, 0.0, 1.0]), (0, 0, 1), prism_axis_second_variation(scene))]
        for k in range(2 * scene.sides):
            u = np.array([math.cos(math.pi * k / scene.sides), math.sin(math.pi * k / scene.sides), 0.0])
            if not any(same_class(u, w, group, 1e-9) for w, _, _ in out):
                out.append((u, None, lateral_second_variation(scene, k)))
        return out
    if scene.body not in ("cube", "box"):
        return []
    out = []
    candidates = [v for v in itertools.product((-1, 0, 1), repeat=3) if any(v)]
    for n in candidates:
        u = np.array(n, dtype=float) / math.sqrt(sum(x * x for x in n))
        if not _fixed_only(u, group) or any(same_class(u, w, group, 1e-9) for w, _, _ in out):
            continue
        out.append((u, n, exact_second_variation(scene, n)))
    return out


def _fixed_only(u, group) -> bool:
    """Whether the symmetries that fix *u* fix no tangent direction (then *u* is an equilibrium by symmetry)."""
    fixing = [g for g in group if np.allclose(g @ u, u, atol=1e-12)]
    P = np.mean(fixing, axis=0) - np.outer(u, u)
    return not np.any(np.linalg.eigvalsh((P + P.T) / 2) > 0.5)
