"""The floating cylinder's slice integrals (symfloat.geometry.cylinder): primitives and their conditioning."""
import types

import mpmath
import pytest
import sympy as sp

from symfloat.geometry.cylinder import _INTEGRANDS, _primitives, cylinder_state

p = sp.Symbol("p")
A = sp.pi - p + sp.sin(p) * sp.cos(p)                 # a segment's area over r^2 at the angle p
INTEGRANDS = {"A sin": A * sp.sin(p), "A sin cos": A * sp.sin(p) * sp.cos(p), "sin^4": sp.sin(p) ** 4,
              "sin^2": sp.sin(p) ** 2, "sin^2 cos": sp.sin(p) ** 2 * sp.cos(p),
              "sin^2 cos^2": sp.sin(p) ** 2 * sp.cos(p) ** 2}


@pytest.mark.parametrize("name", _INTEGRANDS)
def test_each_primitive_differentiates_to_its_integrand(name):
    # a primitive with a wrong coefficient (sin 4p/32 as /16, a dropped p/8) leaves a nonzero remainder
    symbolic = types.SimpleNamespace(sin=sp.sin, cos=sp.cos, pi=sp.pi)
    remainder = sp.diff(_primitives(symbolic, p)[name], p) - INTEGRANDS[name]
    assert sp.simplify(sp.expand_trig(remainder)) == 0


@pytest.mark.parametrize("theta", ["0.3", "1.5", "1.5707963"])
def test_thirty_digits_hold_next_to_lying(theta):
    # nearly lying (cos theta = 3e-8 at 1.5707963) the waterplane's phi interval is as narrow as cos theta and the
    # moments carry 1/cos^3 theta: the primitives' differences need their guard bits and I_w is taken about the
    # centroid.  Against the same closed forms at 60 digits, every quantity (relative to the body's size to its
    # power) to 1e-22 (1/cos theta times 1e-30; without the centroid the 30-digit I_w was off by 7e-17 here)
    r, L, s, tilt = mpmath.mpf("1.2"), mpmath.mpf("2.5"), mpmath.mpf("0.37"), mpmath.mpf(theta)   # the same numbers
    ref, got = cylinder_state(r, L, tilt, s, 60), cylinder_state(r, L, tilt, s, 30)
    for field, power in (("t", 1), ("V", 3), ("Mx", 4), ("Mz", 4), ("area", 2), ("centre", 1), ("I_w", 4),
                         ("I_y", 4)):
        assert abs(getattr(got, field) - getattr(ref, field)) <= mpmath.mpf("1e-22") * L ** power, field
