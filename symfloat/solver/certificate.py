"""Certificates of equilibria: existence, uniqueness and stability proved in ball arithmetic (Arb).

For a convex polyhedron floating at density ratio ``s`` the up vector is charted round a solver's answer
``u_c`` as ``u = u_c + x e1 + y e2`` (``e1, e2`` orthonormal, across ``u_c``; ``u`` is not normalised, the water
plane is ``u . p = t``).  With ``V(u, t)`` and ``M(u, t)`` the volume and first moment of the part below the
plane and ``D = V G - M`` (``V`` times ``G - B``), an equilibrium is a zero of

    ``F1 = (u . u)(e1 . D) - (u . e1)(u . D)``,  ``F2`` the same with ``e2``,  ``F3 = V - s V_body``:

``F1, F2`` are ``|u|^3 V`` times the chart's gradient of the potential ``U = u^ . (G - B)`` (``G - B`` parallel to
``u``), ``F3`` fixes the draught ``t``.  The Krawczyk operator ``K(Z) = m - Y F(m) + (I - Y J(Z)) (Z - m)`` of the
box ``Z`` (``|x|, |y| <= r``, ``t`` round the draught), ``Y`` the inverse of the Jacobian at the middle ``m``,
lying inside ``Z`` proves that exactly one zero lies in ``Z`` (Krawczyk 1969; Moore, Kearfott and Cloud,
*Introduction to Interval Analysis*, 2009, Theorem 8.2).

Everything is evaluated in Arb balls (python-flint) from the body's exact dimensions: the vertices are balls
that hold the exact ones (rational for boxes, ``R cos(2 pi k / n)`` for prisms), the part below the plane is
clipped face by face (Sutherland-Hodgman, each crossing point ``a + (t - u.a)/(u.b - u.a) (b - a)`` on the
edge from below to above) and its volume and moment are sums of tetrahedra from an apex on the water plane
(the mean of the crossing points; the cap's tetrahedra vanish).  Their derivatives are the waterplane's
integrals (``dV = A dt - C . du``, ``dM = C dt - Q du``: :func:`_waterplane`), enclosed over the box with far
less overestimation than the volume's own sums would give.  Which vertices lie below is fixed where the box
decides it; a vertex whose height the box does not separate from the plane is taken both ways (``V`` and ``M``
are continuously differentiable across, so the union of the Jacobians holds the true one), up to
:data:`AMBIGUOUS` of them; a crossing point on an edge whose height may vanish is anywhere on that edge.

Stability: on ``F3 = 0`` the Jacobian of ``F1, F2`` reduced by ``F3`` (its Schur complement,
``R = J_xx - J_xt J_tx / J_tt``) is ``|u|^3 V`` times the chart's Hessian of ``U`` at the equilibrium, which has
the signs of the second variation (Sylvester's law of inertia); ``R`` enclosed over ``Z`` gives enclosures of
both eigenvalues (of its symmetric value at the zero), divided by an enclosure of ``|u|^3 V``.  An enclosure
that excludes zero decides the stability; one that does not leaves it to the solver's higher-order decision,
which the certificate says.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
from flint import arb, arb_mat, ctx

from ..geometry.floating import draught
from .bodies import polyhedron
from .selfcheck import SelfCheckError

__all__ = ["Certificate", "CertificateError", "certify", "certify_equilibrium", "ArbBody", "arb_body", "evaluate",
           "krawczyk", "exact_ball", "PRECISION"]

AMBIGUOUS = 4           # vertices whose side of the water plane the box leaves open: each taken both ways
PRECISION = 128         # bits of Arb's working precision
RADII = (1e-9, 1e-7, 1e-5)      # chart half-widths tried in turn (radians, to first order)
SINGULAR = 1e12         # the condition number of the Jacobian at the middle beyond which no box is tried
UNIT = arb(0.5, 0.5)    # the interval [0, 1]


class CertificateError(SelfCheckError):
    """A certificate contradicts the solver: the stability it proves is not the one reported (exit status 1)."""


@dataclass(frozen=True)
class Certificate:
    """What the ball arithmetic proved about one equilibrium: ``certified`` (exactly one equilibrium in the box
    of chart half-width ``radius`` round the reported up vector), the ``eigenvalues`` of the chart's second
    variation enclosed as ``(low, high)`` pairs, the ``stability`` they decide (``""`` where an enclosure holds
    zero), and ``reason``: why not certified, or how the stability was decided where the enclosure did not."""
    certified: bool
    radius: float = 0.0
    eigenvalues: tuple = ()
    stability: str = ""
    reason: str = ""


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _det(a, b, c):
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2])
            + a[2] * (b[0] * c[1] - b[1] * c[0]))


@dataclass(frozen=True)
class ArbBody:
    """A convex polyhedron with Arb vertices: ``vertices`` (balls holding the exact ones), ``faces`` (rings of
    vertex indices, counter-clockwise seen from outside), its ``volume`` and centroid ``G``, and ``radius``, a
    bound on ``|p|`` over its vertices."""
    vertices: tuple
    faces: tuple
    volume: arb
    G: tuple
    radius: float


def _prism(polygon, length) -> ArbBody:
    """The right prism over the convex counter-clockwise Arb *polygon*, axis ``z`` from ``-length/2`` to
    ``length/2`` (the faces of :func:`symfloat.geometry.floating.right_prism`)."""
    n, h = len(polygon), length / 2
    vertices = tuple((x, y, -h) for x, y in polygon) + tuple((x, y, h) for x, y in polygon)
    faces = (tuple(reversed(range(n))), tuple(range(n, 2 * n))) + tuple(
        (i, (i + 1) % n, n + (i + 1) % n, n + i) for i in range(n))
    volume, moment = arb(0), (arb(0), arb(0), arb(0))
    o = vertices[0]
    for ring in faces:
        a = vertices[ring[0]]
        for b, c in zip(ring[1:], ring[2:]):
            b, c = vertices[b], vertices[c]
            v = _det(*[[w[k] - o[k] for k in range(3)] for w in (a, b, c)]) / 6
            volume += v
            moment = tuple(moment[k] + v * (o[k] + a[k] + b[k] + c[k]) / 4 for k in range(3))
    radius = max(float(abs(_dot(p, p)).upper()) for p in vertices) ** 0.5 * (1 + 1e-12)
    return ArbBody(vertices, faces, volume, tuple(m / volume for m in moment), radius)


def exact_ball(q) -> arb:
    """The rational *q* as an Arb ball (exact where its denominator is a power of two, else one ulp wide)."""
    q = Fraction(q)
    return arb(q.numerator) / q.denominator


def arb_body(scene) -> ArbBody:
    """The :class:`ArbBody` of a cube, box or prism scene, from its exact dimensions."""
    if scene.body in ("cube", "box"):
        a, b, c = (exact_ball(d) / 2 for d in scene.dims)
        return _prism([(-a, -b), (a, -b), (a, b), (-a, b)], 2 * c)
    if scene.body == "prism":
        n = scene.sides
        side, length = (exact_ball(d) for d in scene.dims)
        R = side / (2 * arb(1 / arb(n)).sin_pi())
        return _prism([(R * arb(arb(2 * k) / n).cos_pi(), R * arb(arb(2 * k) / n).sin_pi()) for k in range(n)],
                      length)
    raise ValueError(f"certificates are made for cubes, boxes and prisms, not {scene.body}")


def _fraction(rise, height):
    """Where the plane crosses an edge from below to above: ``rise / height`` in ``[0, 1]`` (the crossing lies on
    the edge), all of it where the edge's height may vanish over the box (an edge nearly in the plane)."""
    if height > 0:
        r = rise / height
        return r.intersection(UNIT) if r.overlaps(UNIT) else r
    return UNIT


def _submerged(body: ArbBody, u, t, below):
    """Volume and first moment of the part of *body* below ``u . p = t`` with the vertices marked in
    *below* below the plane (module docstring); None where nothing is cut or nothing crosses."""
    heights = [_dot(u, p) for p in body.vertices]
    crossings, clipped = [], []
    for ring in body.faces:
        out, n = [], len(ring)
        for i in range(n):
            p, q = ring[i], ring[(i + 1) % n]
            if below[p]:
                out.append(body.vertices[p])
            if below[p] != below[q]:
                a, b = (p, q) if below[p] else (q, p)
                r = _fraction(t - heights[a], heights[b] - heights[a])
                x = tuple(r * (body.vertices[b][k] - body.vertices[a][k]) + body.vertices[a][k] for k in range(3))
                out.append(x)
                crossings.append(x)
        if len(out) >= 3:
            clipped.append(out)
    if not crossings:
        return None
    o = tuple(sum((x[k] for x in crossings[1:]), crossings[0][k]) / len(crossings) for k in range(3))
    volume, moment = arb(0), [arb(0), arb(0), arb(0)]
    for ring in clipped:
        a = [ring[0][k] - o[k] for k in range(3)]
        for b, c in zip(ring[1:], ring[2:]):
            b, c = [b[k] - o[k] for k in range(3)], [c[k] - o[k] for k in range(3)]
            v = _det(a, b, c) / 6
            volume = volume + v
            for k in range(3):
                moment[k] = moment[k] + v * (a[k] + b[k] + c[k] + 4 * o[k]) / 4
    return volume, moment


def _system(body: ArbBody, s, centre, e1, e2, x, y, t, below):
    """``(F1, F2, F3)`` at the chart point ``(x, y, t)`` (arb balls) for one choice of *below*; None where the
    plane cuts no edge."""
    u = tuple(centre[k] + x * e1[k] + y * e2[k] for k in range(3))
    cut = _submerged(body, u, t, below)
    if cut is None:
        return None
    volume, moment = cut
    D = [volume * body.G[k] - moment[k] for k in range(3)]
    uu, uD = _dot(u, u), _dot(u, D)
    F1 = uu * _dot(e1, D) - _dot(u, e1) * uD
    F2 = uu * _dot(e2, D) - _dot(u, e2) * uD
    return F1, F2, volume - s * body.volume


def _waterplane(body: ArbBody, u, t, below):
    """``A = int dS / |u|``, ``C = int p dS / |u|`` and ``Q = int p p^T dS / |u|`` over the waterplane ``u . p = t``
    (Arb balls), the derivatives of the submerged part's volume and moment: ``dV = A dt - C . du``,
    ``dM = C dt - Q du``.  Each crossed face gives the water-line segment from where its ring enters the part
    below to where it leaves it; each segment and the mean ``o`` of the crossing points a triangle, with
    ``int dS = |T|``, ``int p dS = |T| (o + a + b) / 3``, ``int p p^T dS = |T| (sum v v^T + (sum v)(sum v)^T) / 12``;
    None where the signed total area is not enclosed away from zero."""
    heights = [_dot(u, p) for p in body.vertices]
    segments, crossings = [], []
    for ring in body.faces:
        entry = leave = None
        n = len(ring)
        for i in range(n):
            p, q = ring[i], ring[(i + 1) % n]
            if below[p] != below[q]:
                a, b = (p, q) if below[p] else (q, p)
                r = _fraction(t - heights[a], heights[b] - heights[a])
                x = tuple(r * (body.vertices[b][k] - body.vertices[a][k]) + body.vertices[a][k] for k in range(3))
                crossings.append(x)
                if below[p]:
                    leave = x
                else:
                    entry = x
        if entry is not None and leave is not None:
            segments.append((entry, leave))
    if not segments:
        return None
    o = tuple(sum((x[k] for x in crossings[1:]), crossings[0][k]) / len(crossings) for k in range(3))
    uu = _dot(u, u)
    A, C, Q = arb(0), [arb(0)] * 3, [[arb(0)] * 3 for _ in range(3)]
    for a, b in segments:
        da, db = [a[k] - o[k] for k in range(3)], [b[k] - o[k] for k in range(3)]
        K = (da[1] * db[2] - da[2] * db[1], da[2] * db[0] - da[0] * db[2], da[0] * db[1] - da[1] * db[0])
        w = _dot(K, u) / (2 * uu)           # the triangle's signed area over |u|
        S = [o[k] + a[k] + b[k] for k in range(3)]
        A += w
        C = [C[k] + w * S[k] / 3 for k in range(3)]
        Q = [[Q[i][j] + w * (o[i] * o[j] + a[i] * a[j] + b[i] * b[j] + S[i] * S[j]) / 12 for j in range(3)]
             for i in range(3)]
    if A < 0:
        A, C, Q = -A, [-c for c in C], [[-q for q in row] for row in Q]
    elif not A > 0:
        return None
    return A, C, Q


def _parts(body: ArbBody, centre, e1, e2, x, y, t, below):
    """For one choice of *below*: the waterplane's integrals ``A, C, Q`` over the box ``x, y, t`` (arb balls,
    :func:`_waterplane`) and the submerged volume and moment at its middle; None where either is not made."""
    u = tuple(centre[k] + x * e1[k] + y * e2[k] for k in range(3))
    wp = _waterplane(body, u, t, below)
    xm, ym, tm = arb(x.mid()), arb(y.mid()), arb(t.mid())
    middle = _submerged(body, tuple(centre[k] + xm * e1[k] + ym * e2[k] for k in range(3)), tm, below)
    if wp is None or middle is None:
        return None
    return wp[0], wp[1], wp[2], middle[0], middle[1]


def _jacobian(body: ArbBody, centre, e1, e2, x, y, t, parts):
    """The Jacobian of ``(F1, F2, F3)`` over the box ``x, y, t`` (arb balls) from *parts* (:func:`_parts`, or their
    union over the choices of the vertices the box leaves open: at every point of the box one of them is the
    true one): ``V`` and ``D = V G - M`` over the box by the mean-value form of the true, continuously
    differentiable ``V`` and ``M`` about the box's middle, then ``dF1 = 2 (u . du)(e1 . D) + (u . u)(e1 . dD)
    - (du . e1)(u . D) - (u . e1)(du . D + u . dD)`` with ``du = e1, e2, 0`` for ``x, y, t`` (``F2`` with ``e2``),
    ``dF3 = dV``."""
    A, C, Q, Vm, Mm = parts
    u = tuple(centre[k] + x * e1[k] + y * e2[k] for k in range(3))
    dirs = (e1, e2, (arb(0), arb(0), arb(0)))
    dV = [-_dot(C, dirs[0]), -_dot(C, dirs[1]), A]
    dM = [[-_dot(Q[i], dirs[0]), -_dot(Q[i], dirs[1]), C[i]] for i in range(3)]
    dD = [[body.G[i] * dV[j] - dM[i][j] for j in range(3)] for i in range(3)]
    widths = (x - arb(x.mid()), y - arb(y.mid()), t - arb(t.mid()))
    V = Vm + sum((dV[j] * widths[j] for j in range(3)), arb(0))
    M = [Mm[i] + sum((dM[i][j] * widths[j] for j in range(3)), arb(0)) for i in range(3)]
    D = [V * body.G[i] - M[i] for i in range(3)]
    uu, uD = _dot(u, u), _dot(u, D)
    rows = []
    for e in (e1, e2):
        row = []
        for j in range(3):
            du, dDj = dirs[j], [dD[i][j] for i in range(3)]
            row.append(2 * _dot(u, du) * _dot(e, D) + uu * _dot(e, dDj) - _dot(du, e) * uD
                       - _dot(u, e) * (_dot(du, D) + _dot(u, dDj)))
        rows.append(row)
    rows.append(dV)
    return rows


def _sides(body: ArbBody, centre, e1, e2, x, y, t):
    """Per vertex: True (below the plane everywhere in the box), False (above) or None (undecided)."""
    out = []
    for p in body.vertices:
        h = _dot(centre, p) + x * _dot(e1, p) + y * _dot(e2, p) - t
        out.append(True if h < 0 else False if h > 0 else None)
    return out


def _hull(values):
    out = values[0]
    for v in values[1:]:
        out = out.union(v)
    return out


def evaluate(body, s, centre, e1, e2, x, y, t):
    """The values and Jacobian of the system over the box ``x, y, t`` (arb balls), the union over the vertices
    it leaves undecided; None and the reason where it cannot be made."""
    sides = _sides(body, centre, e1, e2, x, y, t)
    open_ = [i for i, side in enumerate(sides) if side is None]
    if len(open_) > AMBIGUOUS:
        return None, f"the water plane passes within the box through {len(open_)} vertices (more than {AMBIGUOUS})"
    values, parts = [], []
    for choice in itertools.product((True, False), repeat=len(open_)):
        below = list(sides)
        for i, c in zip(open_, choice):
            below[i] = c
        F = _system(body, s, centre, e1, e2, x, y, t, below)
        if F is None:
            return None, "the water plane meets no edge of the body"
        P = _parts(body, centre, e1, e2, x, y, t, below)
        if P is None:
            return None, "the waterplane is not enclosed (an edge of the body may lie in the water plane within the box)"
        values.append(F)
        parts.append(P)
    union = (_hull([P[0] for P in parts]), [_hull([P[1][i] for P in parts]) for i in range(3)],
             [[_hull([P[2][i][j] for P in parts]) for j in range(3)] for i in range(3)],
             _hull([P[3] for P in parts]), [_hull([P[4][i] for P in parts]) for i in range(3)])
    values = [_hull([F[i] for F in values]) for i in range(3)]
    jacobian = _jacobian(body, centre, e1, e2, x, y, t, union)
    if not all(v.is_finite() for v in values + [d for row in jacobian for d in row]):
        return None, "an edge of the body may lie in the water plane within the box (its crossing point is undefined)"
    return (values, jacobian), ""


def krawczyk(body, s, centre, e1, e2, t0, r, rt):
    """Whether ``K(Z)`` lies inside ``Z`` (``|x|, |y| <= r``, ``|t - t0| <= rt``), the Jacobian over ``Z``, and the
    reason where not."""
    Z = [arb(0, r), arb(0, r), arb(t0, rt)]
    middle, why = evaluate(body, s, centre, e1, e2, arb(0), arb(0), arb(t0))
    if middle is None:
        return False, None, why
    over, why = evaluate(body, s, centre, e1, e2, *Z)
    if over is None:
        return False, None, why
    Fm, _ = middle
    _, J = over
    Jm = np.array([[float(c.mid()) for c in row] for row in middle[1]])
    if not np.linalg.cond(Jm) < SINGULAR:
        return False, J, ("the second variation is singular at the reported position (a degenerate equilibrium): "
                          "no box proves it alone; its stability is the solver's higher-order decision")
    Yf = np.linalg.inv(Jm)
    Y = arb_mat([[arb(float(v)) for v in row] for row in Yf])
    JZ = arb_mat(J)
    K = arb_mat([[arb(0)], [arb(0)], [arb(t0)]]) - Y * arb_mat([[v] for v in Fm]) + (
        arb_mat([[arb(int(i == j)) for j in range(3)] for i in range(3)]) - Y * JZ) * arb_mat(
        [[Z[0] - 0], [Z[1] - 0], [Z[2] - t0]])
    inside = all(_strictly_inside(K[i, 0], Z[i]) for i in range(3))
    return inside, J, "" if inside else "the Krawczyk operator does not map the box into itself"


def _strictly_inside(a: arb, b: arb) -> bool:
    """Whether the ball *a* lies in the interior of the ball *b* (endpoints compared exactly)."""
    return bool(a.lower() > b.lower()) and bool(a.upper() < b.upper())


def _eigenvalues(J, volume, centre, e1, e2, r):
    """Enclosures of the chart's second variation's eigenvalues at the zero in the box, from the Jacobian *J*
    over it: the Schur complement ``R`` of ``J_tt`` (``|u|^3 V`` times the chart's Hessian there, symmetric at
    the zero), ``(a + d -+ sqrt((a - d)^2 + 4 b c)) / 2``, divided by ``|u|^3 V`` (``V`` the submerged *volume*)."""
    if J[2][2].contains(0):
        return None
    R = [[J[i][j] - J[i][2] * J[2][j] / J[2][2] for j in range(2)] for i in range(2)]
    a, b, c, d = R[0][0], R[0][1], R[1][0], R[1][1]
    disc = (a - d) ** 2 + 4 * b * c            # >= 0 at the zero, where R is symmetric
    root = disc.sqrt() if disc > 0 else arb(0).union(disc.upper().sqrt() if disc.upper() > 0 else arb(0))
    x, y = arb(0, r), arb(0, r)
    uu = _dot(*[tuple(centre[k] + x * e1[k] + y * e2[k] for k in range(3))] * 2)
    scale = uu * uu.sqrt() * volume
    return [((a + d - root) / 2) / scale, ((a + d + root) / 2) / scale]


def certify_equilibrium(body: ArbBody, s, up, t0: float) -> Certificate:
    """The :class:`Certificate` of the isolated equilibrium the solver reports at *up* (unit, floats or mpf) with
    draught *t0*: Krawczyk's test on the boxes of half-width :data:`RADII` in turn, the first that passes."""
    saved = ctx.prec
    ctx.prec = PRECISION
    try:
        s = exact_ball(s)
        submerged = body.volume * s
        centre = tuple(arb(float(c)) for c in up)
        c = np.array([float(v) for v in up])
        k = int(np.argmin(np.abs(c)))
        f = -c[k] * c
        f[k] += 1.0
        f /= np.linalg.norm(f)
        g = np.cross(c, f)
        e1, e2 = tuple(arb(float(v)) for v in f), tuple(arb(float(v)) for v in g)
        why = ""
        for r in RADII:
            rt = body.radius * 2 * r + 1e-12 * body.radius
            ok, J, why = krawczyk(body, s, centre, e1, e2, float(t0), r, rt)
            if ok:
                values = _eigenvalues(J, submerged, centre, e1, e2, r)
                if values is None:
                    return Certificate(True, r, (), "", "the waterplane's area is not enclosed away from zero")
                pairs = tuple((float(v.lower()), float(v.upper())) for v in values)
                if all(v > 0 for v in values):
                    return Certificate(True, r, pairs, "stable")
                if any(v < 0 for v in values):
                    return Certificate(True, r, pairs, "unstable")
                return Certificate(True, r, pairs, "", "an eigenvalue's enclosure holds zero: the stability is "
                                                        "the solver's higher-order decision")
        return Certificate(False, reason=why)
    finally:
        ctx.prec = saved


def certify(solution) -> None:
    """Attach a :class:`Certificate` to every equilibrium of a cube, box or prism *solution* (``certificate``);
    families and the other bodies get one that says why there is none.  A stability the certificate proves that
    contradicts the solver's (stable or unstable) is an error (:class:`CertificateError`); where the solver left it
    indifferent the certificate's stands beside it."""
    scene = solution.scene
    if scene.body not in ("cube", "box", "prism"):
        for e in solution.equilibria:
            e.certificate = Certificate(False, reason="certificates are made for cubes, boxes and prisms")
        return
    body, poly = arb_body(scene), polyhedron(scene)
    for e in solution.equilibria:
        if e.family == "ring":
            e.certificate = Certificate(False, reason="a family of equilibria: no isolated zero to certify")
            continue
        up = e.digits if e.digits else e.up
        t0, _ = draught(poly, tuple(float(x) for x in up), scene.density)
        e.certificate = certify_equilibrium(body, scene.density, up, t0)
        proved, reported = e.certificate.stability, e.stability
        if proved and reported in ("stable", "unstable") and proved != reported:
            raise CertificateError(f"{scene.body} at density {scene.density}: the equilibrium at up "
                                   f"{tuple(round(float(x), 9) for x in e.up)} is {e.stability} by the solver but "
                                   f"{e.certificate.stability} by its certificate (eigenvalues enclosed in "
                                   f"{', '.join(f'[{lo:.6g}, {hi:.6g}]' for lo, hi in e.certificate.eigenvalues)})")
