"""The draught's step (the volume below a plane and the waterplane's area) in C and in MPFR gives the numbers
of the body's own arithmetic bit for bit: Python's floats for a float64 body, mpmath's for an mpmath body
(symfloat/geometry/floating.py, ``_volume_and_area``); so does the submerged part (its volume and centroid,
the waterplane polygon and its moments, ``submerged``) in C and in MPFR.  Each is compared with the Python function it
replaces, run in the body's arithmetic, on generated bodies and planes: tilted, through a vertex, along a face,
outside the body."""
import dataclasses
import random
import shutil
import sysconfig

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from symfloat.geometry import floating
from symfloat.geometry.floating import box, regular_prism, right_prism
from symfloat.geometry.prismatoid import random_convex_polygon


def _body(kind, seed, dps):
    if kind == "box":
        return box(1 + seed % 3, 2, 0.5 + seed % 5, dps=dps)
    if kind == "regular":
        return regular_prism(3 + seed % 30, 0.3, 2, dps=dps)
    return right_prism(random_convex_polygon(random.Random(seed), 3 + seed % 9), 1.5, dps=dps)


def _plane(body, u, where):
    """The unit vector and an offset: below, through, or above the body, or through one of its vertices."""
    u = floating._unit(u, body.dps)
    heights = sorted(floating._dot(u, p) for p in body.vertices)
    if where < 0:
        return u, heights[int(-where * len(heights)) % len(heights)]
    return u, heights[0] + (heights[-1] - heights[0]) * floating._num(where, body.dps)


BODIES = st.sampled_from(["box", "regular", "polygon"])
SEEDS = st.integers(0, 10 ** 6)
DIRECTIONS = st.one_of(st.tuples(*[st.floats(-1, 1)] * 3).filter(lambda u: sum(x * x for x in u) > 1e-6),
                       st.sampled_from([(0, 0, 1), (0, 0, -1), (1, 0, 0), (0, 1, 1), (1, 1, 1)]))
WHERE = st.one_of(st.floats(-0.1, 1.1), st.sampled_from([-0.0001, -0.3, -0.5, -0.99]))


def _bits(x):
    return x._mpf_ if isinstance(x, mpmath.mpf) else x.hex()


def _all_bits(x):
    """Every number of *x* (a dataclass, a tuple, a number or None) as its bits, in order."""
    if dataclasses.is_dataclass(x):
        return [_all_bits(getattr(x, f.name)) for f in dataclasses.fields(x)]
    if isinstance(x, tuple):
        return [_all_bits(v) for v in x]
    return None if x is None else _bits(x)


def _step_in_python(body, u, t):
    """The draught's step as the Python function gives it in the body's own numbers."""
    return floating._clipped_volume_and_area(body.faces, u, t, floating._num(0, body.dps))


def _submerged_in_python(body, u, t):
    """``submerged`` as the Python function gives it in the body's own numbers."""
    u, t = floating._unit(u, body.dps), floating._num(t, body.dps)
    basis = floating.waterplane_basis(u, body.dps)
    volume, centroid, ring, area, c2, J = floating._submerged_part(body.faces, u, t, basis, floating._num(0, body.dps))
    return floating.Submerged(volume, centroid, floating._waterplane(ring, area, c2, J, u, t, basis, body.dps))


# each step as the solver calls it (in C or MPFR where it can), and as the Python function computes it
STEPS = {"draught's step": (floating._volume_and_area, _step_in_python),
         "submerged part": (floating.submerged, _submerged_in_python)}


@pytest.mark.skipif(floating._compiled_submerged is None, reason="the C steps are not built (no compiler)")
@pytest.mark.parametrize("step", sorted(STEPS))
@settings(max_examples=400, deadline=None)
@given(BODIES, SEEDS, DIRECTIONS, WHERE)
def test_the_c_steps_give_pythons_floats(step, kind, seed, u, where):
    fast, python = STEPS[step]
    body = _body(kind, seed, None)
    u, t = _plane(body, u, where)
    assert _all_bits(fast(body, u, t)) == _all_bits(python(body, u, t))


@pytest.mark.parametrize("step", sorted(STEPS))
@settings(max_examples=120, deadline=None)
@given(BODIES, SEEDS, DIRECTIONS, WHERE, st.sampled_from([20, 40, 61]))
def test_the_mpfr_steps_give_mpmaths_numbers(step, kind, seed, u, where, dps):
    fast, python = STEPS[step]
    body = _body(kind, seed, dps)
    with mpmath.workdps(dps):
        u, t = _plane(body, u, where)
        assert _all_bits(fast(body, u, t)) == _all_bits(python(body, u, t))


@pytest.mark.skipif(floating._compiled_submerged is None, reason="the C steps are not built (no compiler)")
def test_the_submerged_comparison_sees_a_changed_bit_and_a_turned_polygon():
    body = box(1, 2, 3)
    u, t = _plane(body, (0.3, 0.2, 0.9), 0.37)
    sub = floating.submerged(body, u, t)
    wp = sub.waterplane
    nudged = dataclasses.replace(sub, volume=sub.volume * (1 + 2 ** -52))
    turned = dataclasses.replace(sub, waterplane=dataclasses.replace(wp, polygon=wp.polygon[1:] + wp.polygon[:1]))
    assert _all_bits(nudged) != _all_bits(sub) and _all_bits(turned) != _all_bits(sub)
    # a top face lying in the plane is replaced by the cap, counter-clockwise from the lowest corner
    top = floating.submerged(body, (0, 0, 1), 1.5).waterplane.polygon
    assert top == ((-0.5, -1.0, 1.5), (0.5, -1.0, 1.5), (0.5, 1.0, 1.5), (-0.5, 1.0, 1.5))


def test_an_offset_wider_than_the_working_precision_gives_mpmaths_numbers():
    # MPFR would round an offset of 60 digits to the body's 40 on the way in; mpmath computes with all its bits
    # (at t = 7/97 - 1/5 the rounding changes the volume's last bit)
    body = box(1, 2, 3, dps=40)
    with mpmath.workdps(60):
        t = mpmath.mpf(7) / 97 - mpmath.mpf(1) / 5
    with mpmath.workdps(40):
        u = floating._unit((0.3, 0.2, 0.9), 40)
        python = floating._clipped_volume_and_area(body.faces, u, t, mpmath.mpf(0))
        assert list(map(_bits, floating._volume_and_area(body, u, t))) == list(map(_bits, python))
        assert _bits(floating._volume_and_area(body, u, +t)[0]) != _bits(python[0])    # the offset rounded differs


def test_a_changed_rounding_would_be_seen():
    # the comparison is bit for bit: the box 1 x 2 x 3 tilted, at 40 digits, rounded once more to 39 digits
    body = box(1, 2, 3, dps=40)
    with mpmath.workdps(40):
        u, t = _plane(body, (0.3, 0.2, 0.9), 0.37)
        volume, _ = floating._volume_and_area(body, u, t)
    with mpmath.workdps(39):
        assert _bits(+volume) != _bits(volume)


@pytest.mark.skipif(shutil.which((sysconfig.get_config_var("CC") or "cc").split()[0]) is None, reason="no C compiler here")
def test_where_a_compiler_is_at_hand_the_c_step_is_built():
    # setup.py builds the module optionally: a failed build would leave the Python step serving in silence
    assert floating._compiled_volume_and_area is not None and floating._compiled_submerged is not None
