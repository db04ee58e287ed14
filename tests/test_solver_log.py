"""The long square log (the box 1 x 1 x 4) next to the ring born from its end face (issue 14): the scenes inside
that window, which `solve` answered wrongly (no stable ring at 0.01054, exit 0) or not at all (index sum 10 at
0.01056).

Expected values, computed without the solver:

- the ring around z (tests/test_phase_log.py): while the waterplane cuts the four long faces only, a tilt of slope m
  about any horizontal axis is an equilibrium where m^2 = 12 d (4 - d) - 2, d = 4 s the draught; it is born at
  s* = 1/2 - sqrt(1/4 - 1/96) = 0.0105275 (m = 0) and is whole until the waterplane reaches a bottom vertex across
  the diagonal, d = m sqrt(2)/2: 14 d^2 - 48 d + 2 = 0, s = (96 - sqrt 8768)/224 = 0.0105464; past that it keeps its
  arcs about the faces' directions until d = m/2, s = (96 - sqrt 8704)/256 = 0.0105655;
- between those, like the cube's past (3 - sqrt 2)/7, positions on the diagonal mirror (|u_x| = |u_y|): found here
  as the minimum of the potential along the mirror (the clipped body's floating state, golden-section search), a
  window that closes at a fold before s = 0.010548.
"""
import math
from fractions import Fraction

from symfloat.geometry.floating import box, floating_state
from symfloat.solver import make_scene, solve

RING_WHOLE_END = (96 - math.sqrt(8768)) / 224
RING_END = (96 - math.sqrt(8704)) / 256


def _ring_tilt(s) -> float:
    d = 4 * float(s)
    return math.atan(math.sqrt(12 * d * (4 - d) - 2))


def _tilt(e) -> float:
    return math.acos(abs(e.up[2]) / math.sqrt(sum(x * x for x in e.up)))


def _diagonal_minimum(s, lo: float, hi: float) -> float:
    """The tilt of the potential's minimum along the diagonal mirror u = (sin t/sqrt 2, sin t/sqrt 2, cos t)."""
    body = box(1, 1, 4)
    potential = lambda t: float(floating_state(body, (math.sin(t) / math.sqrt(2), math.sin(t) / math.sqrt(2),  # noqa: E731
                                                      math.cos(t)), s).potential)
    golden = (math.sqrt(5) - 1) / 2
    for _ in range(60):
        a, b = hi - golden * (hi - lo), lo + golden * (hi - lo)
        if potential(a) < potential(b):
            hi = b
        else:
            lo = a
    return (lo + hi) / 2


def test_the_whole_ring_inside_its_window_is_found_stable():
    # 0.01054 lies between s* and RING_WHOLE_END: before, `scene box --dims 1,1,4 --density 0.01054` listed no ring
    # (its index sum closed without it) and exited 0
    s = Fraction("0.01054")
    assert 0.0105275 < s < RING_WHOLE_END
    rings = [e for e in solve(make_scene("box", s, "1,1,4")).equilibria if e.family == "ring"]
    assert len(rings) == 1 and rings[0].stability == "stable" and rings[0].ring_shape == "closed"
    assert abs(_tilt(rings[0]) - _ring_tilt(s)) <= 1e-9


def test_past_the_vertex_the_arcs_and_the_diagonal_window_are_found():
    # 0.010547: the ring's arcs (same tilt) and a stable class on the diagonal mirror beside an unstable one
    s = Fraction("0.010547")
    assert RING_WHOLE_END < s < RING_END
    sol = solve(make_scene("box", s, "1,1,4"))
    arcs = [e for e in sol.equilibria if e.family == "ring"]
    assert len(arcs) == 1 and arcs[0].ring_shape == "arc" and arcs[0].stability == "stable"
    assert abs(_tilt(arcs[0]) - _ring_tilt(s)) <= 1e-9
    diagonal = [e for e in sol.equilibria if e.family == "isolated" and 0 < abs(e.up[2]) < 1
                and abs(abs(e.up[0]) - abs(e.up[1])) <= 1e-9 and _tilt(e) < 0.1]
    stable = [e for e in diagonal if e.stability == "stable"]
    assert len(stable) == 1 and len(diagonal) == 2
    assert abs(_tilt(stable[0]) - _diagonal_minimum(s, 0.055, 0.0620)) <= 1e-6


def test_past_the_fold_the_arcs_close_the_check():
    # 0.01056: before, IndexCheckError (index sum 10: the arcs were not found)
    s = Fraction("0.01056")
    sol = solve(make_scene("box", s, "1,1,4"))
    arcs = [e for e in sol.equilibria if e.family == "ring"]
    assert len(arcs) == 1 and arcs[0].ring_shape == "arc" and arcs[0].stability == "stable"
    assert abs(_tilt(arcs[0]) - _ring_tilt(s)) <= 1e-9
    assert not any(e.stability == "stable" and e.family == "isolated" and abs(e.up[2]) > 0.9 for e in sol.equilibria)
