"""The solver's conditioning next to bifurcation densities: true error against the reported bound.

At a bifurcation density ``s*`` an equilibrium's second variation vanishes,
so the float64 position error grows like ``eps / lambda`` as ``s -> s*``.
For densities ``s* + delta`` the solver's equilibria are compared with a
50-digit Newton refinement of the same equilibrium
(:mod:`symfloat.solver.refine`); each row says whether the reported bound
(:mod:`symfloat.solver.errors`) covers the true error.
"""
from __future__ import annotations

import time
from dataclasses import dataclass
from fractions import Fraction

import mpmath

from ..solver import make_scene, solve
from ..solver.refine import angle_between, refine_planar, refine_sphere

__all__ = ["Case", "CASES", "Row", "conditioning_rows"]


@dataclass(frozen=True)
class Case:
    """A bifurcation density ``s_star`` (a 50-digit mpmath value, with its closed form and locator)
    and the scene family around it; ``side`` = +1 to approach from above, -1 from below."""
    label: str
    closed_form: str
    locator: str
    s_star: object
    scene: object          # density (Fraction) -> Scene
    side: int = 1


def _digits(x) -> Fraction:
    return Fraction(mpmath.nstr(x, 40, strip_zeros=False))


with mpmath.workdps(50):
    _S79 = mpmath.mpf(1) / 2 - mpmath.sqrt(mpmath.mpf(1) / 12)
    _S80 = (3 - mpmath.sqrt(2)) / 7

CASES = [
    Case("long square log, tilted position born at s* (2-D)", "1/2 - sqrt(1/12)", "scheeffer (79)", _S79,
         lambda s: make_scene("section", s, polygon="0,0 1,0 1,1 0,1")),
    Case("cube, ring born from the upright position", "1/2 - sqrt(1/12)", "scheeffer (79)", _S79,
         lambda s: make_scene("cube", s)),
    Case("cube, oblique positions at the end of the whole ring", "(3 - sqrt 2)/7", "scheeffer (80)", _S80,
         lambda s: make_scene("cube", s)),
]


@dataclass(frozen=True)
class Row:
    case: str
    delta: float
    tilt_deg: float
    stability: str
    true_error: float
    reported: float
    method: str
    seconds: float

    @property
    def bounded(self) -> bool:
        return self.true_error <= self.reported


def conditioning_rows(cases=CASES, deltas=(1e-2, 1e-4, 1e-6, 1e-8)) -> list[Row]:
    """One row per isolated equilibrium (not fixed by symmetry) of each case at each distance."""
    rows = []
    for case in cases:
        for delta in deltas:
            with mpmath.workdps(50):
                s = _digits(case.s_star + case.side * mpmath.mpf(delta))
            scene = case.scene(s)
            t0 = time.perf_counter()
            solution = solve(scene)
            seconds = time.perf_counter() - t0
            for e in solution.equilibria:
                if e.family == "ring" or e.error_method == "exact":
                    continue
                if scene.body == "section":
                    theta = mpmath.atan2(e.up[1], e.up[0])
                    ref = refine_planar(scene, theta)
                    true = float(abs(ref - theta))
                else:
                    ref, _ = refine_sphere(scene, e.up)
                    true = angle_between(e.up, ref)
                rows.append(Row(case.label, delta, e.tilt_deg, e.stability, true, e.error_rad, e.error_method,
                                seconds))
    return rows
