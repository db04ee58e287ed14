"""The metacentre lesson read at a scene's numbers: the box upright on each edge, stable iff e > 0 (compiled
readings, :mod:`symfloat.model.compiled`)."""
from fractions import Fraction

from symfloat.model.compiled import Readings, reading
from symfloat.model.prediction import Prediction, box_uprights

# ---- predictions: the box floating upright ------------------------------------------------------------------------
READINGS = Readings(__file__, __package__, {
    "E_PRINTED": reading("e", ("b", "c", "d"), 1),      # e = b^2/(6c^2) - d/(2c) (1 - d/(2c)) as printed
})
E_PRINTED = READINGS["E_PRINTED"]


def predict(scene):
    """Each edge direction of the box vertical in turn (height 2c, breadth 2b the shorter, length 2a the longer of
    the other two edges, draught d = 2c s): stable iff e = b^2/(6c^2) - d/(2c)(1 - d/(2c)) > 0 (the criterion
    z_M >= z_G, decided in exact arithmetic); where 0 < e <= 1 the closing sentence ('größer als eins' when
    stable) says otherwise."""
    if scene.body not in ("box", "cube"):                # a cube is a box
        return []
    sv = Fraction(scene.density)
    dims = [Fraction(x_) for x_ in scene.dims]
    out = []
    for k, i, j in box_uprights(dims):
        bv, cv = min(dims[i], dims[j]) / 2, dims[k] / 2
        ev = E_PRINTED(bv, cv, 2 * cv * sv)
        up = [0.0] * 3
        up[k] = 1.0
        out.append(Prediction(("e", "criterion", "z_M"), tuple(up),
                              "stable" if ev > 0 else "unstable" if ev < 0 else None,
                              note=f"upright, edge {k} vertical: e = {float(ev):.4g}"))
        if 0 < ev <= 1:
            out.append(Prediction(("e-sign",), tuple(up), "unstable",
                                  note=f"e = {float(ev):.4g} is not 'größer als eins': the closing sentence's "
                                       "stable case excludes it"))
    return out


BODIES = ("box",)
