"""Scheeffer I-III's witnesses: floating prisms clipped exactly (:mod:`symfloat.engine.floating_witness`)."""
import sympy as sp

from symfloat.engine.declare import declarer
from symfloat.engine.floating_witness import LIMIT_METHODS, Body, FloatingWitness
from symfloat.engine.measured import measured
from symfloat.engine.witness import Case, Precision

from .statements import Hh, P1, P2, V1, c0, d, e1, h0, phi

# ---- witnesses: the clipped body, named (symfloat.engine.floating_witness) --------------------------------

EXACT = (Precision(15, 1e-10), Precision(50, 1e-40))
TRAPEZOID = Body.prism(((0, -P1 / 2), (Hh, -P2 / 2), (Hh, P2 / 2), (0, P1 / 2)), 4)


def _trap_case(p1, p2, hh, q):
    """The vertical prism (axis z, length 4) over the trapezoid with the parallel sides P1 (x = 0) and P2
    (x = H), half immersed (V1 = 2 * area, e1 = 1), tilted with tg phi = q, the side x = H dipping."""
    params = {P1: p1, P2: p2, Hh: hh, phi: sp.atan(sp.Rational(q)), V1: 2 * sp.Rational(hh) * (p1 + p2) / 2,
              e1: 1, c0: 0, h0: 0}
    return Case(params, label=f"vertical prism over the trapezoid P1={p1}, P2={p2}, H={hh}; tg phi = {q}")


TRAP = (_trap_case(3, 3, 2, sp.Rational(1, 5)), _trap_case(2, 1, 2, sp.Rational(1, 2)),
        _trap_case(2, sp.Rational(1, 2), sp.Rational(3, 2), sp.Rational(3, 4)))


# the trapezoid prism tilted from upright (both water planes clipped from the body, the axis where they meet found,
# not assumed at the centroid)
tilted = declarer(d, FloatingWitness, body=TRAPEZOID, up=(-sp.tan(phi), 0, 1), reference=(0, 0, 1),
                  density=sp.Rational(1, 2), methods=EXACT)
tilted("wedges-e-k", "V3 e = V3 x3 + V4 x4 and V3 k = V3 y3 + V4 y4 of the clipped wedges",
       ("moments-10", "moments-sum", "moments-11"), TRAP,
       (measured("immersed wedge moment, horizontal") + measured("emerged wedge moment, horizontal"),
        measured("immersed wedge moment, vertical") + measured("emerged wedge moment, vertical")))
tilted("wedge-3", "static moments of the clipped immersed wedge", ("moments-10a",), TRAP,
       (measured("immersed wedge moment, vertical"), measured("immersed wedge moment, horizontal")))
tilted("wedge-4", "static moments of the clipped emerged wedge", ("moments-10b",), TRAP,
       (measured("emerged wedge moment, vertical"), measured("emerged wedge moment, horizontal")))
tilted("wedge-volume-3", "volume of the clipped immersed wedge", ("volume-V3",), TRAP,
       measured("immersed wedge volume"))
tilted("wedge-volume-4", "volume of the clipped emerged wedge", ("volume-V4",), TRAP, measured("emerged wedge volume"))
tilted("wedge-volume-over-tg", "clipped wedge volumes over tg phi (both wedges)", ("moments-equal",), TRAP,
       measured("emerged wedge volume") / sp.tan(phi))
tilted("axis-position", "where the tilted water plane meets the old one (clipping, draught)", ("axis-centroid",), TRAP,
       measured("axis position"))
tilted("buoyancy-body-frame", "centre of buoyancy of the clipped tilted body in the body frame, times V1",
       ("moments-raw", "moments-6"), TRAP,
       (measured("immersed volume") * measured("B - G, x"), -measured("immersed volume") * measured("B - G, z")))
tilted("buoyancy-world-frame", "centre of buoyancy of the clipped tilted body in the world frame", ("rotation-5",),
       TRAP, (measured("righting arm"), measured("G above B")))
tilted("righting-moment", "V1 m, V1 n of the clipped tilted body", ("moments-7",), TRAP,
       (measured("immersed volume") * measured("righting arm"), measured("immersed volume") * measured("G above B")))
tilted("righting-moment-m", "V1 m of the clipped tilted body", ("moment-12",), TRAP,
       measured("immersed volume") * measured("righting arm"))
tilted("righting-moment-n", "V1 n (weight times height of S above S2) of the clipped tilted body", ("moment-13",), TRAP,
       measured("immersed volume") * measured("G above B"))


# -- small-angle limits: horizontal prisms heeled by psi about their axis z (the side -x dips) --------------
psi, s_body = sp.symbols("psi s_body", positive=True)


def _box(W, H):
    return Body.prism(((-W / 2, -H / 2), (W / 2, -H / 2), (W / 2, H / 2), (-W / 2, H / 2)), 3)


# the triangle (0,0), (1,2), (-1,2), apex down, floating at draught dd: s = (dd/2)^2, waterline width dd
APEX_DOWN = Body.prism(((0, 0), (1, 2), (-1, 2)), 2)
SMALL = (
    Case({P1: 3, P2: 3, Hh: 2, V1: 6, e1: sp.Rational(1, 2), s_body: sp.Rational(1, 2)}, {"body": _box(2, 2)},
         "box 2 x 2 x 3, half immersed (prismatic at the waterline)"),
    Case({P1: 2, P2: 2, Hh: 1, V1: 1, e1: sp.Rational(2, 3), s_body: sp.Rational(1, 4)}, {"body": APEX_DOWN},
         "triangular prism apex down, draught 1 (not prismatic at the waterline; unstable)"),
    Case({P1: 2, P2: 2, Hh: sp.Rational(9, 5), V1: sp.Rational(81, 25), e1: sp.Rational(2, 15),
          s_body: sp.Rational(81, 100)}, {"body": APEX_DOWN},
         "triangular prism apex down, draught 9/5 (not prismatic at the waterline; stable)"),
)


heeled = declarer(d, FloatingWitness, body=None, up=(sp.sin(psi), sp.cos(psi), 0), reference=(0, 1, 0),
                  density=s_body, limit=(psi, 1), methods=LIMIT_METHODS)      # a body of each case's own
heeled("righting-arm-limit", "lim m(psi)/psi from the clipped heeled body (extrapolated)",
       ("duhamel-16", "general-body"), SMALL, measured("righting arm"))
heeled("wedge-limits", "leading terms of the clipped immersed wedge's moments (extrapolated)", ("series-3",), SMALL,
       (measured("immersed wedge moment, horizontal"), measured("immersed wedge moment, vertical") / psi))
heeled("wedge-limits-4", "leading terms of the clipped emerged wedge's moments (extrapolated)", ("series-4",), SMALL,
       (measured("emerged wedge moment, horizontal"), measured("emerged wedge moment, vertical") / psi))
