"""Certificates of equilibria in ball arithmetic (issue 33, item 2): Krawczyk's test proves exactly one
equilibrium in a box round each reported position, and enclosures of the second variation's eigenvalues
decide its stability, or the certificate says why not."""
import math
from dataclasses import replace
from fractions import Fraction

import numpy as np
import pytest
from flint import arb

from symfloat.geometry.floating import box, draught, floating_state
from symfloat.solver import make_scene, solve
from symfloat.solver.certificate import (Certificate, CertificateError, _jacobian, _parts, _system, arb_body, certify,
                                         certify_equilibrium)


@pytest.fixture(scope="module")
def cube_030():
    sol = solve(make_scene("cube", "3/10"))
    certify(sol)
    return sol


def _at(sol, up):
    return next(e for e in sol.equilibria if np.linalg.norm(np.array(e.up) - np.array(up)) < 1e-9)


def test_every_position_of_the_cube_at_030_is_certified(cube_030):
    for e in cube_030.equilibria:
        assert e.certificate.certified and e.certificate.radius > 0
        assert e.certificate.stability == e.stability
    # face up: the metacentric height I/V - (G - B) = (1/12)/(3/10) - (1 - 3/10)/2 = -13/180 twice (a cube of
    # side 1 at draught 3/10, Scheeffer VI (79)); its enclosures hold it
    face = _at(cube_030, (0, 0, 1)).certificate
    assert all(lo <= -13 / 180 <= hi for lo, hi in face.eigenvalues)
    assert all(hi - lo < 1e-6 for lo, hi in face.eigenvalues)


def test_the_enclosures_hold_the_clipped_floating_state(cube_030):
    # the edge-up position's eigenvalues from the clipping module's metacentric matrix T/V - (G - B) at 30 digits
    # (symfloat.geometry.floating, an independent implementation)
    edge = _at(cube_030, (math.sqrt(0.5), 0, math.sqrt(0.5)))
    st = floating_state(box(1, 1, 1, dps=30), (1, 0, 1), Fraction(3, 10))
    values = sorted(float(x) / float(st.volume) - float(st.potential) for x in (st.I_min, st.I_max))
    assert all(lo <= v <= hi for (lo, hi), v in zip(edge.certificate.eigenvalues, values))


def test_a_position_off_the_equilibrium_is_refuted():
    # mutation: the face-up position turned by 1e-4 rad is no equilibrium; no box round it is certified
    body, poly = arb_body(make_scene("cube", "3/10")), box(1, 1, 1)
    up = (math.sin(1e-4), 0.0, math.cos(1e-4))
    cert = certify_equilibrium(body, Fraction(3, 10), up, draught(poly, up, Fraction(3, 10))[0])
    assert not cert.certified and "Krawczyk" in cert.reason


def test_a_certificate_contradicting_the_solver_fails_the_scene():
    # mutation: the corner-up position (stable at 3/10) reported unstable must be an error (exit status 1)
    sol = solve(make_scene("cube", "3/10"))
    corner = _at(sol, (1 / math.sqrt(3),) * 3)
    sol.equilibria[sol.equilibria.index(corner)] = replace(corner, stability="unstable")
    with pytest.raises(CertificateError, match="stable by its certificate"):
        certify(sol)


def test_families_degenerate_positions_and_other_bodies_say_why_not():
    # the cube 1e-6 below the end of its ring round z (phase cube: 1/4) has an arc: no isolated zero
    sol = solve(make_scene("cube", Fraction(1, 4) - Fraction(1, 10 ** 6)))
    certify(sol)
    arc = [e for e in sol.equilibria if e.family == "ring"]
    assert arc and arc[0].certificate == Certificate(False, reason="a family of equilibria: no isolated zero to certify")
    assert all(e.certificate.certified for e in sol.equilibria if e.family != "ring")
    # the cube edge up at 1/2: two edges lie in the water plane and the second variation is singular
    half = solve(make_scene("cube", "1/2"))
    certify(half)
    edge = _at(half, (math.sqrt(0.5), 0, math.sqrt(0.5)))
    assert not edge.certificate.certified and edge.certificate.reason
    cyl = solve(make_scene("cylinder", "3/10", "1,2"))
    certify(cyl)
    assert all(not e.certificate.certified and "cubes, boxes and prisms" in e.certificate.reason for e in cyl.equilibria)


@pytest.mark.parametrize("sides", [3, 6])
def test_prisms_are_certified(sides):
    sol = solve(make_scene("prism", "3/10", "1,2", sides))
    certify(sol)
    assert all(e.certificate.certified and e.certificate.stability == e.stability
               for e in sol.equilibria if e.family != "ring")


def test_the_jacobian_is_the_derivative_of_the_system():
    # the waterplane's integrals against central differences of the system's values (clipped volumes and moments,
    # step 1e-6: the difference's error ~ h^2 times the third derivative, far below the tolerance), at a point
    # where no vertex is on the plane
    body = arb_body(make_scene("box", "3/10", "1,3/2,1"))
    s = arb(3) / 10
    centre = tuple(arb(v) for v in (0.3, 0.2, 0.932737905308882))
    e1, e2 = tuple(arb(v) for v in (1.0, 0, 0)), tuple(arb(v) for v in (0, 1.0, 0))
    point = (0.01, -0.02, -0.12)
    below = [float(sum(c.mid() * p.mid() for c, p in zip(centre, v))) + point[0] * float(v[0].mid())
             + point[1] * float(v[1].mid()) < point[2] for v in body.vertices]
    J = _jacobian(body, centre, e1, e2, *(arb(v) for v in point), _parts(body, centre, e1, e2, *(arb(v) for v in point), below))
    h = 1e-6
    for j in range(3):
        up = list(point), list(point)
        up[0][j] += h
        up[1][j] -= h
        plus = _system(body, s, centre, e1, e2, *(arb(v) for v in up[0]), below)
        minus = _system(body, s, centre, e1, e2, *(arb(v) for v in up[1]), below)
        for i in range(3):
            difference = (float(plus[i].mid()) - float(minus[i].mid())) / (2 * h)
            assert abs(difference - float(J[i][j].mid())) <= 1e-6, (i, j)
            assert float(J[i][j].rad()) < 1e-12


def test_a_certificate_stands_beside_an_indifferent_position():
    # where the solver left a position indifferent, the certificate's decision is shown, no contradiction
    sol = solve(make_scene("cube", "3/10"))
    corner = _at(sol, (1 / math.sqrt(3),) * 3)
    sol.equilibria[sol.equilibria.index(corner)] = replace(corner, stability="indifferent")
    certify(sol)
    assert _at(sol, (1 / math.sqrt(3),) * 3).certificate.stability == "stable"
