"""Scheeffer VI.C-F read at a scene's numbers: the square prism, the cube and the regular n-gon prism (compiled
readings, :mod:`symfloat.model.compiled`)."""
import math
from fractions import Fraction

from symfloat.model.compiled import Readings, reading
from symfloat.model.prediction import Prediction

READINGS = Readings(__file__, __package__, {
    "MARGIN_75": reading("75", ("a", "b", "s"), 0),
    "TAN_78B": reading("78b", ("a", "b", "s"), 1),
    "BOUND_78D": reading("78d", ("a", "b", "s"), 1),
    "T1_87": reading("87-cos2", ("r", "n"), 1),            # (87): T_1 of the regular n-gon of circumradius r
    "TAN2_54": reading("54-again", ("F", "b", "s", "n"), 1),  # (54) again (VI.F): tg^2 phi_1 at the base area F
    "UM_88": reading("88", ("r", "n", "om"), 1),            # (88): u_m at the axis angle omega
})


# ==== predictions: where the printed formulas put the square prism, the cube and the n-gon prism ======
def _toward(phi_, k, i):
    """Up vector (body frame) tilted by phi_ from the axis e_k towards e_i (tilt axis along the third edge)."""
    up = [0.0, 0.0, 0.0]
    up[k], up[i] = math.cos(phi_), math.sin(phi_)
    return tuple(up)


def _square_predictions(av, bv, sv, up_of, cube):
    """Upright and oblique positions of the square prism (edge av, height bv) as (75)/(78), (78b), (77)/(78a),
    (78d)/(78e) print them; for the cube (av = bv) as VI.D prints them.  up_of(phi) is the up vector tilted by
    phi about an axis parallel to a base edge (omega = 0).  av, bv, sv are Fractions: the conditions, read from
    the quoted readings, are decided exactly."""
    margin = MARGIN_75(av, bv, sv)                       # (75): (a/b)^2 - 6 s (1 - s); the cube: 1 - 6 s (1 - s)
    upright = ("cube-78", "79") if cube else \
        ("75", "78") if margin > 0 else ("75-unstable",) if margin < 0 else ("75",)
    out = [Prediction(upright, up_of(0.0),
                      "stable" if margin > 0 else "unstable" if margin < 0 else None,
                      note="upright (axis vertical): Duhamel's condition as printed")]
    if margin >= 0:
        return out
    phi1 = math.atan(TAN_78B(float(av), float(bv), float(sv)))   # (78b); the cube: (81a) corrected, the same
    bound = BOUND_78D(av, bv, sv)                        # (78d)/(82): sin^2(45 deg + omega) <= bound
    up = up_of(phi1)
    if bound >= 1:                                       # (77)/(78a): every axis direction, the whole ring
        names = ("78a", "77", "78b") if not cube else \
            ("80", "81-oblique-upper" if sv > Fraction(1, 2) else "81-oblique-lower", "cube-78a", "81a")
        out.append(Prediction(names, up, "stable", "ring",
                              note="oblique ring of the first domain, any horizontal axis (tilt phi_1 of (78b))"))
    elif cube and sv == Fraction(1, 2):                  # (82) gives omega = 0 only: phi_1 = 45 deg, edge up
        out.append(Prediction(("half-stable", "half-tilt", "82-half-omega", "82-half"), up, "stable",
                              note="s = 1/2: the axis parallel to an edge only, phi_1 = 45 deg (the edge up)"))
    elif cube:                                           # the printed claim: 0.2265 < s < 0.7735, edge-parallel axis
        # VI.D claims the edge-parallel axis throughout 0.2265 < s < 0.7735 (no narrower range is printed for it);
        # (82) itself at omega = 0 (sin^2 45 deg = 1/2) holds only for s <= 1/4 or s >= 3/4: where it fails, the
        # position is the print's claim alone, booked as an erratum (claim) at VI.D
        beyond = "" if bound >= Fraction(1, 2) else \
            (f"; the print claims it for every s between 0.2265 and 0.7735, but its own (82) at omega = 0 needs a "
             f"bound of at least 1/2, here {float(bound):.4f}: the claim is booked as an erratum at VI.D")
        out.append(Prediction(("edge-axis-range", "82", "81a"), up, "stable", "ring",
                              note="the arc |omega| <= omega* of (82) around the edge-parallel axis (omega = 0); "
                                   "81a and 82 read with 6 for the scan's b" + beyond))
    elif bound >= Fraction(1, 2):                        # (78c)/(78d): the arc around the edge-parallel axis
        out.append(Prediction(("78d", "78c", "78b"), up, "stable", "ring",
                              note="the arc sin^2(45 deg + omega) <= (78d) around the edge-parallel axis "
                                   "(omega = 0); (78c) printed with its cases exchanged, its corrected range used"))
    return out                                           # (78e): no oblique position in the first domain


MARGIN_75, TAN_78B, BOUND_78D = READINGS["MARGIN_75"], READINGS["TAN_78B"], READINGS["BOUND_78D"]
T1_87, TAN2_54, UM_88 = READINGS["T1_87"], READINGS["TAN2_54"], READINGS["UM_88"]


def _ngon_predictions(n_, av, bv, sv):
    """Regular n-gon prism (n >= 5, edge av, length bv): upright by T_1 - V_1 e_1 with T_1 of (87); the oblique
    ring by (54) again (VI.F) within the first domain of (88) with the bound b min(s, 1-s) / u_m."""
    r_ = av / (2 * math.sin(math.pi / n_))
    F_ = n_ * r_ ** 2 / 2 * math.sin(2 * math.pi / n_)                    # the base area
    duhamel = T1_87(r_, n_) - F_ * bv * sv * bv * (1 - sv) / 2           # T_1 - V_1 e_1, e_1 = b (1 - s)/2
    out = [Prediction(("87-cos2", "duhamel-decreasing"), (0.0, 0.0, 1.0),
                      "stable" if duhamel > 0 else "unstable" if duhamel < 0 else None,
                      note="upright: T_1 - V_1 e_1 with T_1 of (87)")]
    tan2_ = TAN2_54(F_, bv, sv, n_)
    if duhamel >= 0 or tan2_ <= 0:
        return out
    t1_, m_ = math.sqrt(tan2_), bv * min(sv, 1 - sv)
    # (88): u_m runs from r cos(pi/n) (omega = 0, the axis parallel to a side) up to r (omega = pi/n)
    if t1_ > m_ / UM_88(r_, n_, 0.0):
        return out
    phi1 = math.atan(t1_)
    ang = math.pi / n_ + (math.pi if sv > 0.5 else 0.0)   # a side dips (s > 1/2) or rises (s < 1/2)
    full_ring = t1_ <= m_ / UM_88(r_, n_, math.pi / n_)
    out.append(Prediction(("54-again", "88"), (math.sin(phi1) * math.cos(ang), math.sin(phi1) * math.sin(ang),
                                               math.cos(phi1)), "stable", "ring",
                          note="oblique ring of the first domain" + ("" if full_ring else
                               ", an arc around the axis parallel to a side")))
    return out


def predict(scene):
    """The equilibria of VI.C-F: the square prism (prism with 4 sides, box with a square base), the cube and the
    regular n-gon prism (n >= 5) in the first rotation domain.  The conditions are decided in exact arithmetic."""
    sv, one = Fraction(scene.density), Fraction(1)
    dims = [Fraction(x_) for x_ in scene.dims]
    if scene.body == "cube" or (scene.body == "box" and dims[0] == dims[1] == dims[2]):
        return _square_predictions(one, one, sv, lambda ph: _toward(ph, 2, 0), cube=True)
    if scene.body == "box":
        for k in range(3):
            i, j = [m_ for m_ in range(3) if m_ != k]
            if dims[i] == dims[j]:
                return _square_predictions(dims[i], dims[k], sv, lambda ph, k=k, i=i: _toward(ph, k, i), cube=False)
        return []
    if scene.body == "prism" and scene.sides == 4:
        c45 = math.sqrt(0.5)
        return _square_predictions(dims[0], dims[1], sv,
                                   lambda ph: (math.sin(ph) * c45, math.sin(ph) * c45, math.cos(ph)), cube=False)
    if scene.body == "prism" and scene.sides >= 5:
        return _ngon_predictions(scene.sides, float(dims[0]), float(dims[1]), float(sv))
    return []


BODIES = ("cube", "square-box", "prism")
