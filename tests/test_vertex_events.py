"""Vertex events (issue 33, items 1 and 4): where a ring round a prism's axis breaks, known from the body.

Provenance of the thresholds (symfloat/solver/vertex.py: the ring's tilt ``tan^2 theta* = A L^2 s (1 - s) / I - 2``
meets a base vertex where ``R^2 tan^2 theta* = L^2 s^2``):

- the cube (``A = 1``, ``I = 1/12``, ``R^2 = 1/2``, ``L = 1``): ``7 s^2 - 6 s + 1 = 0``, ``s = (3 - sqrt 2) / 7 =
  0.2265409196610`` (Scheeffer VI.D (80), and X: the diagonal class is stable above it, "wenn s > (3 - sqrt 2)/7");
  its dual ``(4 + sqrt 2) / 7`` ((172)); the phase diagram's threshold ``docs/figures/phase-cube.json``;
- the box 1 x 3/2 x 1 about its square axis y (``L = 3/2``): ``21 s^2 - 18 s + 4/3 = 0``, ``s = (9 - sqrt 53) / 21 =
  0.0818990``, between the ring's birth ``27 s (1 - s) = 2`` (0.0800) and its end 1/12.

At the cube's event the vertex reaches the plane with ``tan theta* = s / R = sqrt 2 s``, so the depth grows at
``d/ds (R tan theta* - s) = R * 6 (1 - 2 s) / tan theta* - 1 = 3 (1 - 2 s) / s - 1 = 6.2398``.
"""
import math
from fractions import Fraction

import mpmath
import numpy as np
import pytest

from symfloat.solver import make_scene
from symfloat.solver.critical import Critical
from symfloat.solver.phase import _stable
from symfloat.solver.selfcheck import IndexCheckError
from symfloat.solver.solve import _unbroken, solve
from symfloat.solver.symmetry import box_group
from symfloat.solver.vertex import EVENT_DIGITS, event_digits, lateral_arc, vertex_depths

def CUBE_EVENT():
    return (3 - mpmath.sqrt(2)) / 7             # Scheeffer VI.D (80)


def BOX_EVENT():
    return (9 - mpmath.sqrt(53)) / 21           # module docstring


def _near(event, delta) -> Fraction:
    """The exact density *delta* away from the irrational threshold *event()* (taken at 60 digits)."""
    with mpmath.workdps(60):
        return Fraction(mpmath.nstr(event(), 60, min_fixed=-80, max_fixed=80)) + Fraction(delta)


def _depth(body, dims, s, axis):
    return {a: d for a, d, _ in vertex_depths(make_scene(body, s, dims))}[axis]


@pytest.mark.parametrize("body, dims, event, axis", [("cube", None, CUBE_EVENT, (0, 0, 1)),
                                                     ("box", "1,3/2,1", BOX_EVENT, (0, 1, 0))])
def test_the_vertex_reaches_the_waterplane_at_the_event(body, dims, event, axis):
    # before the event the vertex lies above the plane (depth < 0, the ring closed), past it beyond; a threshold
    # off by 1e-30 would put both sides on one side
    with mpmath.workdps(60):
        assert _depth(body, dims, _near(event, Fraction(-1, 10 ** 30)), axis) < 0
        assert _depth(body, dims, _near(event, Fraction(1, 10 ** 30)), axis) > 0
        # the dual: the end face above, s -> 1 - s
        assert _depth(body, dims, 1 - _near(event, Fraction(-1, 10 ** 30)), axis) < 0
        assert _depth(body, dims, 1 - _near(event, Fraction(1, 10 ** 30)), axis) > 0


def test_the_depth_grows_as_derived_past_the_cubes_event():
    with mpmath.workdps(50):
        slope = 3 * (1 - 2 * CUBE_EVENT()) / CUBE_EVENT() - 1      # module docstring: 6.2398
        depth = _depth("cube", None, _near(CUBE_EVENT, Fraction(1, 10 ** 12)), (0, 0, 1))
        assert abs(depth / mpmath.mpf(10) ** -12 - slope) < 1e-9 * slope


def _convergents(x, count):
    """The first *count* convergents p/q of the continued fraction of the mpf *x* (at the working precision)."""
    out, (p0, q0), (p1, q1) = [], (0, 1), (1, 0)
    for _ in range(count):
        a = int(mpmath.floor(x))
        (p0, q0), (p1, q1) = (p1, q1), (a * p1 + p0, a * q1 + q0)
        out.append(Fraction(p1, q1))
        x = 1 / (x - a)
    return out


def test_the_depth_keeps_its_sign_at_a_density_next_to_the_event():
    # a convergent p/q of the continued fraction of (3 - sqrt 2)/7 lies within about 1/q^2 of the event: the first
    # past it with a denominator of 55 digits or more (58), where the depth is 2.3e-116, cancelled from lengths of
    # order 1; at 50 digits plus the density's it came out -4.5e-109 (the ring taken for closed, the class between
    # the arcs never looked for). Expected: the depth from the cube's closed form sqrt((12 t (1 - t) - 2)/2) - t
    # (R = sqrt(2)/2, L = 1; module docstring) at 600 digits
    with mpmath.workdps(600):
        s = next(c for c in _convergents(CUBE_EVENT(), 200)
                 if len(str(c.denominator)) >= 55 and mpmath.mpf(c.numerator) / c.denominator > CUBE_EVENT())
        t = mpmath.mpf(s.numerator) / s.denominator
        exact = mpmath.sqrt((12 * t * (1 - t) - 2) / 2) - t
    assert 0 < exact < 1e-100
    scene = make_scene("cube", s)
    depth = _depth("cube", None, s, (0, 0, 1))
    assert depth > 0 and abs(depth - exact) < 1e-6 * exact
    assert event_digits(scene, 1.0) > EVENT_DIGITS          # closer than the solver resolves: the scene refuses


@pytest.mark.parametrize("dims", ["3,3,4", "9,9,12", "3/7,3/7,4/7"])
def test_a_rational_event_is_depth_zero_whatever_the_scale(dims):
    # the box a x a x c about c has its event where 7 c^2 t^2 - 6 c^2 t + a^2 = 0 (R^2 = a^2/2, I/A = a^2/12): for
    # a/c = 3/4 at t = 3/28 exactly (112 t^2 - 96 t + 9 = 0; tan^2 theta* = 2/49, R^2 tan^2 theta* = 9/49 = (L t)^2).
    # The vertex is on the plane, the ring closed: the same for the body scaled by 3 or 1/7 (the rounding of a zero
    # difference gave +2.7e-51 for 9 x 9 x 12 and 330 digits)
    for s in (Fraction(3, 28), Fraction(25, 28)):
        scene = make_scene("box", s, dims)
        assert [float(d) for _, d, _ in vertex_depths(scene)] == [0.0] and event_digits(scene, 1.0) == 0
    assert _depth("box", dims, Fraction(3, 28) + Fraction(1, 10 ** 6), (0, 0, 1)) > 0     # past it, beyond


def test_the_digits_follow_from_the_depth():
    # 1e-12 past the cube's event: depth 6.24e-12, soft eigenvalue 8.1e-33 (measured at 120 digits), decided where
    # the residual 10^(2 - d) is below its square: 20 - 6 log10(6.24e-12) = 87.2; 1e-9 past: 69.2; before: none
    assert event_digits(make_scene("cube", _near(CUBE_EVENT, Fraction(1, 10 ** 12))), 1.0) == 88
    assert event_digits(make_scene("cube", _near(CUBE_EVENT, Fraction(1, 10 ** 9))), 1.0) == 70
    assert event_digits(make_scene("cube", _near(CUBE_EVENT, Fraction(-1, 10 ** 12))), 1.0) == 0
    # at 1/2 the vertex lies sqrt(2)/2 - 1/2 = 0.207 beyond the plane (tan theta* = 1): 20 - 6 log10(0.207) = 24.1,
    # fewer than the 60 digits the solver spends anyway
    assert event_digits(make_scene("cube", Fraction(1, 2)), 1.0) == 25


def _closed_ring(axis, length=1.917):
    """A closed ring as the walk reports it 1e-12 from the cube's event: length 2 pi sin theta* = 1.917."""
    return Critical(np.array([0.305, 0.0, 0.952]), 0.0, (0.0, 0.04), 0.0, 0.0, 6, True, "closed", length,
                    axis=np.asarray(axis, dtype=float))


def test_a_closed_ring_past_an_event_is_refused():
    # the guard that keeps a ring walked closed past the event (the answer before this fix, exit 0) from
    # being reported: 1e-12 past the cube's event it refuses, 1e-12 before it lets the closed ring stand
    group = box_group((1, 1, 1))
    with pytest.raises(IndexCheckError, match="vertex lies 6.24e-12 beyond its waterplane"):
        _unbroken(make_scene("cube", _near(CUBE_EVENT, Fraction(1, 10 ** 12))), [_closed_ring((0, 0, 1))], group)
    with pytest.raises(IndexCheckError):
        _unbroken(make_scene("cube", _near(CUBE_EVENT, Fraction(1, 10 ** 12))), [_closed_ring((-1, 0, 0))], group)
    _unbroken(make_scene("cube", _near(CUBE_EVENT, Fraction(-1, 10 ** 12))), [_closed_ring((0, 0, 1))], group)
    # a closed ring round the axis at another tilt is not the one the event breaks
    _unbroken(make_scene("cube", _near(CUBE_EVENT, Fraction(1, 10 ** 12))), [_closed_ring((0, 0, 1), 1.0)], group)


@pytest.mark.slow
@pytest.mark.parametrize("density", [_near(CUBE_EVENT, Fraction(1, 10 ** 12)),
                                     1 - _near(CUBE_EVENT, Fraction(1, 10 ** 12))])
def test_past_the_cubes_event_the_diagonal_class_is_stable_between_arcs(density):
    # the scenes that were wrong with exit 0 (a closed ring, no diagonal class): 1e-12 past 0.2265409196610 and
    # 1e-12 before its dual 0.7734590803390
    solution = solve(make_scene("cube", density))
    assert "tilted, |u_x| = |u_y|" in _stable(make_scene("cube", density))
    rings = [e for e in solution.equilibria if e.family == "ring"]
    assert rings and all(e.ring_shape == "arc" for e in rings)
    # the class on the diagonal mirror at the ring's tilt (z = cos theta* = 0.9523), not the saddle at z = 0.80
    diagonal = [e for e in solution.equilibria if e.family == "isolated" and abs(e.up[0] - e.up[1]) < 1e-9
                and abs(e.up[2] - 0.9523198) < 1e-6 and e.copies == 24]
    assert len(diagonal) == 1 and diagonal[0].stability == "stable"
    # its soft eigenvalue 8.1e-33 1e-12 past (2.4e-33 at the dual, the factor (1 - s) / s), decided at 88 digits
    assert 1e-33 < diagonal[0].eigenvalues[0] < 1e-32
    assert solution.checks["poincare_hopf_index_sum"] == 2


def _arc_closed_form(s, R, L, tan2):
    """The length of the arc of the ring round a square prism's axis centred on a face's direction: the ring at
    ``tan theta* = sqrt(tan2)`` keeps its end face off the plane while ``R tan theta* cos(pi/4 - phi) <= L s``
    (the nearer vertex at azimuth pi/4), so ``|phi| <= pi/4 - acos(L s / (R tan theta*))`` and the arc is ``2 sin
    theta*`` times that (the cube at 1/4 - delta: about 16 delta sin theta*, the issue's measurement)."""
    t = mpmath.sqrt(tan2)
    return 2 * mpmath.sin(mpmath.atan(t)) * (mpmath.pi / 4 - mpmath.acos(L * s / (R * t)))


def _cube_arc(s):
    return _arc_closed_form(s, mpmath.sqrt(2) / 2, 1, 12 * s * (1 - s) - 2)


ARCS = [
    # the cube near the ring's end 1/4 (the edge's midpoint reaches the water: (1/2) tan theta* = s), 1e-3 and 1e-9
    # before it: tan^2 theta* = 12 s (1 - s) - 2, R = sqrt(2)/2, L = 1
    ("cube", None, Fraction(1, 4) - Fraction(1, 10 ** 3), _cube_arc),
    ("cube", None, Fraction(1, 4) - Fraction(1, 10 ** 9), _cube_arc),
    # the box 1 x 3/2 x 1 about y near its ring's end 1/12 ((1/2) tan theta* = (3/2) s): tan^2 theta* = 27 s (1 - s) - 2
    ("box", "1,3/2,1", Fraction(1, 12) - Fraction(1, 10 ** 6),
     lambda s: _arc_closed_form(s, mpmath.sqrt(2) / 2, mpmath.mpf(3) / 2, 27 * s * (1 - s) - 2)),
]


@pytest.mark.parametrize("body, dims, density, closed_form", ARCS)
def test_an_arcs_length_is_located_to_its_ends_brackets(body, dims, density, closed_form):
    scene = make_scene(body, density, dims)
    with mpmath.workdps(40):
        s = mpmath.mpf(density.numerator) / density.denominator
        exact = closed_form(s)      # a point of the arc: its middle, on the face's direction (phi = 0)
        t = float(mpmath.sqrt(12 * s * (1 - s) - 2 if body == "cube" else 27 * s * (1 - s) - 2))
    theta = math.atan(t)
    u = (math.sin(theta), 0.0, math.cos(theta)) if body == "cube" else (math.sin(theta), math.cos(theta), 0.0)
    length, error = lateral_arc(scene, u, 1e-9)
    assert abs(length - float(exact)) <= error           # the bound holds
    assert error < 1e-25 * max(length, 1e-9) + 2 * math.ulp(length)     # and is tight: the brackets are 1e-30 rad
    # mutation: a point off the ring's tilt is on no such arc
    assert lateral_arc(scene, (math.sin(theta + 1e-6), 0.0, math.cos(theta + 1e-6)) if body == "cube"
                       else (math.sin(theta + 1e-6), math.cos(theta + 1e-6), 0.0), 1e-9) is None


def test_a_scene_reports_the_located_length():
    # the scene's arc 1e-3 before the cube's ring end 1/4: walked from a point 1e-4 rad past its end (the potential
    # falls there by the cut corner's cube, below float64), its length before this located to 3.2e-4 only
    density = Fraction(1, 4) - Fraction(1, 10 ** 3)
    arcs = [e for e in solve(make_scene("cube", density)).equilibria if e.family == "ring"]
    with mpmath.workdps(40):
        exact = float(_cube_arc(mpmath.mpf(density.numerator) / density.denominator))     # 0.0072898902046463
    assert len(arcs) == 1 and arcs[0].ring_shape == "arc"
    # the error: the float64 rounding of the length
    assert abs(arcs[0].ring_length - exact) <= arcs[0].ring_length_error < 1e-17


def test_a_scene_closer_to_an_event_than_float64_bounds_hold_is_refused():
    # 1e-55 past the cube's event the vertex lies 6.2e-55 beyond the plane: 346 digits, and the class's soft eigenvalue
    # (about depth^3 / 30 = 8e-165) has a square below float64's smallest number, so the Kantorovich test divided by
    # 0.0 (ZeroDivisionError, a traceback from `symfloat scene cube --density 0.2265409196609864...`); it refuses now,
    # as it does a scene closer than EVENT_DIGITS digits resolve. 1e-40 past (255 digits) is within the bounds
    near = make_scene("cube", _near(CUBE_EVENT, Fraction(1, 10 ** 55)))
    assert event_digits(near, 1.0) == 346
    with pytest.raises(IndexCheckError, match="by less than 300 digits resolve"):
        solve(near)
    assert event_digits(make_scene("cube", _near(CUBE_EVENT, Fraction(1, 10 ** 40))), 1.0) <= EVENT_DIGITS == 300
