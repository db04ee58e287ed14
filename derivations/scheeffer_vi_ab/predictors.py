"""Scheeffer VI.A-B read at a scene's numbers: the regular triangular prism and the circular cylinder (compiled
readings, :mod:`symfloat.model.compiled`)."""
import math
from fractions import Fraction

from symfloat.model.compiled import Readings, reading
from symfloat.model.prediction import Prediction


# =====================================================================================================
# Predictions: the positions of the first rotation region as (65) and (69)-(73) print them
# =====================================================================================================
def _tilted(phi_, toward_x):
    """Up vector tilted by phi_ from the axis towards +x (toward_x > 0) or -x."""
    return (math.copysign(math.sin(phi_), toward_x), 0.0, math.cos(phi_))


READINGS = Readings(__file__, __package__, {
    "MARGIN_65": reading("65-I", ("a", "b", "s"), 0),     # (65) I: (a/b)^2 - 12 s(1-s), equality counted stable
    "TAN2_65": reading("65-tan", ("a", "b", "s"), 1),     # (65): tg^2 phi_1 = 24 (b/a)^2 s(1-s) - 2
    "RING_65": reading("65-II", ("a", "b", "s"), 0),      # (65) II: rows 12s(1-s) - q, q - (62) upper, q - (62) lower
    "ARC_64": reading("64", ("a", "b", "s"), 0),          # (64): rows 6(1-s)(3s-1) - q, 6s(2-3s) - q
    "MARGIN_70": reading("70", ("r", "b", "s"), 0),       # (69)/(70): (2r/b)^2 - 8 s + 8 s^2
    "LIMIT_73": reading("73", ("r", "b", "s"), 0),        # (73): rows 8s(1-s) - K2, K2 - 2(1-s)(5s-1), K2 - 2s(4-5s)
    "TAN2_72A": reading("72a-tan", ("r", "b", "s"), 1),   # (72a): tg^2 phi_1 = 16 (b/2r)^2 s(1-s) - 2
})
MARGIN_65, TAN2_65, RING_65, ARC_64 = (READINGS[k] for k in ("MARGIN_65", "TAN2_65", "RING_65", "ARC_64"))
MARGIN_70, LIMIT_73, TAN2_72A = (READINGS[k] for k in ("MARGIN_70", "LIMIT_73", "TAN2_72A"))


def _triangle_predictions(av, bv, sv):
    """(65): I upright stable; II upright labile, an oblique stable position for every horizontal axis (a ring);
    III the same for a restricted axis direction (an arc of the ring, (61)); IV no oblique position.  The
    conditions are the readings of (65) and (64), evaluated exactly."""
    margin = MARGIN_65(av, bv, sv)
    out = [Prediction(("57", "65-I", "density-range") if margin >= 0 else ("57", "density-range"), (0.0, 0.0, 1.0),
                      "stable" if margin >= 0 else "unstable",
                      note="upright: (57) (a/b)^2 > 12 s(1-s); (65) I counts equality as stable")]
    if margin >= 0:
        return out
    phi1 = math.atan(math.sqrt(TAN2_65(float(av), float(bv), float(sv))))
    upper = sv >= Fraction(1, 2)
    ring = RING_65(av, bv, sv)[1 if upper else 2]       # q - (62), the whole ring
    arc = ARC_64(av, bv, sv)[0 if upper else 1]         # (64) - q, an arc
    # omega = 0 of the text: an edge on the side of the base that meets the water first (the upper base on the
    # dipping side for s > 1/2, the lower one on the rising side for s < 1/2), the vertex opposite
    up = _tilted(phi1, 1 if upper else -1)
    if ring >= 0:
        out.append(Prediction(("65-II", "65-tan", "60-tan"), up, "stable", "ring",
                              note="(65) II: oblique ring, any horizontal axis"))
    elif arc <= 0:
        out.append(Prediction(("65-III", "65-III-omega", "65-III-claim", "65-tan"), up, "stable", "ring",
                              note="(65) III: the arc of axis directions allowed by (61) around omega = 0"))
    return out


def _cylinder_predictions(rv, bv, sv):
    """(69)-(73): upright stable iff 2r/b > sqrt(8 s(1-s)); else the oblique ring (72a) when (73) holds; the
    readings of (70) and (73) evaluated exactly."""
    margin = MARGIN_70(rv, bv, sv)
    out = [Prediction(("69", "71") if margin > 0 else ("72", "71") if margin < 0 else ("69",), (0.0, 0.0, 1.0),
                      "stable" if margin > 0 else "unstable" if margin < 0 else None,
                      note="upright: (69) 2r/b > sqrt(8 s(1-s)), (72) the labile case")]
    if margin >= 0:
        return out
    if LIMIT_73(rv, bv, sv)[1 if sv > Fraction(1, 2) else 2] >= 0:
        phi1 = math.atan(math.sqrt(TAN2_72A(float(rv), float(bv), float(sv))))
        out.append(Prediction(("72a-tan", "72a", "73"), _tilted(phi1, 1), "stable", "ring",
                              note="(73): the oblique ring of the first region, tilt from (72a)"))
    return out


def predict(scene):
    """VI.A: the regular triangular prism (prism, 3 sides); VI.B: the circular cylinder.  The conditions are
    decided in exact arithmetic (Fractions), the tilts in floating point."""
    sv, dims = Fraction(scene.density), [Fraction(x_) for x_ in scene.dims]
    if scene.body == "prism" and scene.sides == 3:
        return _triangle_predictions(dims[0], dims[1], sv)
    if scene.body == "cylinder":
        return _cylinder_predictions(dims[0], dims[1], sv)
    return []


BODIES = ("prism", "cylinder")
