"""Scheeffer X read at a scene's density: the triangle, the hexagon and the pentagons of (171) for the cube
(compiled readings, :mod:`symfloat.model.compiled`)."""
from fractions import Fraction

import numpy as np

from symfloat.engine.roots import illinois
from symfloat.model.compiled import Readings, reading
from symfloat.model.prediction import Prediction

# ==== prediction ==========================================================================================
READINGS = Readings(__file__, __package__, {
    "f_num": reading("171", ("xl", "s"), 1, row=2),   # (171) as read, left minus right side with the printed 2T, z
    "S172": reading("172-number", (), 0),             # (172): (4 + sqrt 2)/7, as read
})
f_num = READINGS["f_num"]                             # for numeric x, s: floats or numpy arrays alike
S172 = float(READINGS["S172"]())
half = Fraction(1, 2)


GRID = np.arange(1, 201) / 200
ROUNDING = 1e-12    # float64 rounds (171) on the grid by far less (terms below 10, a few dozen operations: < 1e-14)


def _roots_171_float(q):
    """The roots of (171) in x on a grid of 1/200 at the float density *q*, refined by Illinois: the sign of each
    grid value decided in float64 beyond :data:`ROUNDING`, exactly (the float arguments by their binary values)
    within it, so that a root on a grid point (x = 1 at s = 5/6) is decided by the print and not by rounding."""
    f = lambda t_: f_num(t_, q)  # noqa: E731
    values = f_num(GRID, q)
    positive = [bool(v > 0) if abs(v) > ROUNDING else f_num(Fraction(float(g)), Fraction(q)) > 0
                for g, v in zip(GRID, values)]
    return [illinois(f, float(GRID[i]), float(GRID[i + 1]), 1e-12)
            for i in range(len(GRID) - 1) if positive[i] != positive[i + 1]]


def predict(scene):
    """The equilibria section X predicts for the cube at density s (as printed)."""
    if scene.body == "box" and len(set(scene.dims)) != 1:
        return []
    sv = scene.density
    out = []
    if sv > Fraction(5, 6) or sv < Fraction(1, 6):
        out.append(Prediction(("five-sixths", "tri-symmetric", "tri-unstable"), (1.0, 1.0, 1.0), "unstable",
                              note="triangular waterplane across a diagonal, always unstable"))
    elif sv == half:
        out.append(Prediction(("hex-symmetric", "hex-half"), (1.0, 1.0, 1.0), "stable",
                              note="regular hexagon, stable (Schülen)"))
    else:
        out.append(Prediction(("hex-symmetric", "173-only-45"), (1.0, 1.0, 1.0), None,
                              note="a hexagonal equilibrium lies across a diagonal; the text leaves its stability "
                                   "open"))
    if sv != half:
        q = float(sv) if sv > half else 1 - float(sv)
        names = ("171", "172", "pentagon-exists", "pentagon-stable") if sv > half else \
            ("171", "dual-threshold", "dual-exists", "pentagon-stable")
        for xr in _roots_171_float(q):
            z = 1 - xr + xr ** 3 / 6
            pv = (1 - q) / z
            # below 1/2 the cube at 1 - s turned over (up -> -up: wet and dry exchanged), then mirrored in its
            # middle plane z = 0 (a symmetry of the cube, the same class): the face +z up, as above 1/2
            up = (-pv, -pv, 1.0) if sv > half else (pv, pv, 1.0)
            # (171) is a pentagon while the face opposite the dipping corner stays dry, beta = (2 - x)(1 - s)/z < 1
            # (s the heavy cube's density); the print states no such bound and claims the pentagon for every s
            # below 0.7735 (above 0.2265 turned over): beyond it the claim is booked as an erratum at X
            beta = (2 - xr) * (1 - q) / z
            beyond = "" if beta < 1 else \
                (f"; beyond the pentagon (the opposite face cut: beta = (2 - x)(1 - s)/z = {beta:.3f} > 1), where the "
                 f"print still claims it: booked as an erratum at X")
            out.append(Prediction(names, up, "stable" if q < S172 else None,
                                  note=f"pentagonal waterplane, leg x = {xr:.6f} (root of (171))" + beyond))
    return out


BODIES = ("cube",)
