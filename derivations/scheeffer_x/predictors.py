"""Scheeffer X read at a scene's density: the triangle, the hexagon and the pentagons of (171) for the cube."""
import numpy as np
import sympy as sp

from symfloat.engine.roots import illinois
from symfloat.model.prediction import Prediction

from .statements import d, half, s, xl

# ==== prediction ==========================================================================================
# (171) as read, left minus right side with the printed 2T and z, for numeric x, s: floats or numpy arrays alike
f_num = d.evaluator("171", (xl, s), 1, row=2)
S172 = float(d.evaluator("172-number", (), 0)())      # (172): (4 + sqrt 2)/7, as read


def _roots_171_float(q):
    f = lambda t_: f_num(t_, q)  # noqa: E731
    grid = np.arange(1, 201) / 200
    positive = f_num(grid, q) > 0
    return [illinois(f, float(grid[i]), float(grid[i + 1]), 1e-12)
            for i in range(len(grid) - 1) if positive[i] != positive[i + 1]]


def predict(scene):
    """The equilibria section X predicts for the cube at density s (as printed)."""
    if scene.body == "box" and len(set(scene.dims)) != 1:
        return []
    sv = scene.density
    out = []
    if sv > sp.Rational(5, 6) or sv < sp.Rational(1, 6):
        out.append(Prediction(("five-sixths", "tri-symmetric", "tri-unstable"), (1.0, 1.0, 1.0), "unstable",
                              note="triangular waterplane across a diagonal, always unstable"))
    elif sv == sp.Rational(1, 2):
        out.append(Prediction(("hex-symmetric", "hex-half"), (1.0, 1.0, 1.0), "stable",
                              note="regular hexagon, stable (Schülen)"))
    else:
        out.append(Prediction(("hex-symmetric", "173-only-45"), (1.0, 1.0, 1.0), None,
                              note="a hexagonal equilibrium lies across a diagonal; the text leaves its stability "
                                   "open"))
    if sv != sp.Rational(1, 2):
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


d.predicts(("cube",), predict)
