"""The Hasáb solution read at a scene's numbers: the long square prism lying on a face and standing upright.

Compiled readings (:mod:`symfloat.model.compiled`): a scene evaluates them without the statements."""
import math
from fractions import Fraction

from symfloat.model.compiled import Readings, reading
from symfloat.model.prediction import Prediction

# ---- predictions: the long square prism lying on a face, and standing upright (the remark) ---------------------
READINGS = Readings(__file__, __package__, {
    "CONDITION": reading("condition", ("rho",), 1),                # sign(rho^2 - rho + 1/6), the printed condition
    "REMARK": reading("remark", ("l",), 1, corrected=True),       # (3l + sqrt(9l^2 - 6))/(6l), the radical restored
})
CONDITION, REMARK = READINGS["CONDITION"], READINGS["REMARK"]


def _lying(rv, up):
    """Heel about the long axis: stable iff rho^2 - rho + 1/6 > 0 (the condition and its thresholds)."""
    return Prediction(("condition", "thresholds", "Delta-E"), up, "stable" if CONDITION(rv) > 0 else "unstable",
                      note="lying on a face (edges l horizontal), heel about the long axis")


def _is_square(poly):
    """True when the polygon is a square: four equal sides and equal diagonals (exact arithmetic)."""
    if len(poly) != 4:
        return False
    d2 = lambda p_, q_: (p_[0] - q_[0]) ** 2 + (p_[1] - q_[1]) ** 2  # noqa: E731
    sides = {d2(poly[k], poly[(k + 1) % 4]) for k in range(4)}
    return len(sides) == 1 and d2(poly[0], poly[2]) == d2(poly[1], poly[3])


def predict(scene):
    """section: a square cross-section, lying on a face; box: a long square prism (two equal edges a, the third
    L with L^2 > 3 a^2/2, so that the pitch about the short axis is stable at every density, as the text assumes),
    lying on a face and standing upright (the remark, read with the radical the scan lost)."""
    rv = Fraction(scene.density)
    if scene.body == "section":
        if not _is_square(scene.polygon):
            return []
        (x0, y0), (x1, y1) = scene.polygon[0], scene.polygon[1]
        n_ = (float(y1 - y0), float(x0 - x1))            # outward normal of the first side (counter-clockwise)
        norm = math.hypot(*n_)
        return [_lying(rv, (n_[0] / norm, n_[1] / norm, 0.0))]
    if scene.body not in ("box", "cube"):                # a cube is a box
        return []
    dims = [Fraction(x_) for x_ in scene.dims]
    for k in range(3):
        i, j = [m_ for m_ in range(3) if m_ != k]
        if dims[i] == dims[j] and dims[k] ** 2 > Fraction(3, 2) * dims[i] ** 2:
            upper = REMARK(float(dims[k] / dims[i]))
            up_lying, up_upright = [0.0] * 3, [0.0] * 3
            up_lying[i], up_upright[k] = 1.0, 1.0
            return [_lying(rv, tuple(up_lying)),
                    Prediction(("remark",), tuple(up_upright), "stable" if float(rv) > upper else "unstable",
                               note="standing upright: the printed stable range (3l + sqrt(9l^2 - 6))/(6l) < rho < 1 "
                                    "(the lower range is not printed)")]
    return []


BODIES = ("section", "box")
