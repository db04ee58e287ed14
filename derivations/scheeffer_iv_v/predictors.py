"""Scheeffer IV-V read at a scene's numbers: the upright and the tilted positions of a right prism (compiled
readings, :mod:`symfloat.model.compiled`)."""
import math
from fractions import Fraction

from symfloat.geometry.floating import polygon_moments
from symfloat.model.compiled import Readings, exact_sqrt, reading
from symfloat.model.prediction import Prediction, box_uprights

READINGS = Readings(__file__, __package__, {
    "TAN2_54": reading("54", ("F1", "b", "T1", "s"), 1),        # (54) as read: tg^2 phi_1
    "BOUND_55": reading("55", ("b", "s", "utop", "ubot"), 1),   # (55) as read: the bound on tg phi_1
})


# ---- predictions: the upright and the tilted positions of the first rotation region (IV, V) -------------------------
def _axis_up(k, i, phi_):
    """Up vector tilted by phi_ from the prism axis e_k towards e_i."""
    up = [0.0, 0.0, 0.0]
    up[k], up[i] = math.cos(phi_), math.sin(phi_)
    return tuple(up)


def _upright(T_min, V_, e_, up):
    """(18): upright stable iff T_1/V_1 - e_1 > 0 for every axis, i.e. for the least moment T_1 of the base."""
    g = T_min / V_ - e_
    return Prediction(("stable-18",) if g > 0 else ("unstable-18",) if g < 0 else ("stable-18", "unstable-18"), up,
                      "stable" if g > 0 else "unstable" if g < 0 else None, note="upright, (18) with the least moment")


TAN2_54, BOUND_55 = READINGS["TAN2_54"], READINGS["BOUND_55"]


def _first_region_tilt(F_, T_, h_, sv, um2):
    """(54) tan^2 phi_1 = F_1 b^2 s(1-s)/T_1 - 2 and the bound (55) tan phi_1 <= b(1-s)/u_m (s > 1/2; b s/u_m
    for s < 1/2), um2 = u_m^2, both evaluated from their readings (exactly for a box, whose numbers are
    Fractions): the tilt phi_1, or None when there is none in the first rotation region."""
    t2 = TAN2_54(F_, h_, T_, sv)
    um = exact_sqrt(um2) if isinstance(um2, Fraction) else math.sqrt(um2)
    return math.atan(math.sqrt(float(t2))) if 0 < t2 and t2 <= BOUND_55(h_, sv, um, um) ** 2 else None


def _isotropic_ring(F_, T_, h_, sv, um2_min, um2_max, up_of):
    """(48)-(51), law (52a): a base with equal moments has the tilted position for every axis direction, stable;
    (55) with u_m^2 between um2_min and um2_max decides which directions stay in the first rotation region
    (the representative up_of(phi_1) has u_m smallest)."""
    phi1 = _first_region_tilt(F_, T_, h_, sv, um2_min)
    if phi1 is None:
        return []
    full = _first_region_tilt(F_, T_, h_, sv, um2_max) is not None
    return [Prediction(("54", "55", "51-claim", "law"), up_of(phi1), "stable", "ring",
                       note="tilted ring (isotropic base)" + ("" if full else ": an arc of axis directions by (55)"))]


def _box_predictions(dims, sv):
    """A box is a right prism over a rectangle in three ways: each edge direction e_k vertical in turn (one per
    class of equal shape), the base the rectangle of the other two edges."""
    out = []
    for k, i, j in box_uprights(dims):
        p_, q_, h_ = dims[i], dims[j], dims[k]
        F_, V_, e_ = p_ * q_, p_ * q_ * h_ * sv, h_ * (1 - sv) / 2
        Ti, Tj = p_ * q_ ** 3 / 12, q_ * p_ ** 3 / 12     # about the axes along e_i and e_j
        out.append(_upright(min(Ti, Tj), V_, e_, _axis_up(k, i, 0.0)))
        if p_ == q_:                                      # square base: u_m from p/2 (side) to p/sqrt2 (diagonal)
            out += _isotropic_ring(F_, Ti, h_, sv, p_ ** 2 / 4, p_ ** 2 / 2, lambda ph, k=k, i=i: _axis_up(k, i, ph))
            continue
        # (47): omega = 0 or 90 deg; tilting about e_i lifts towards e_j (u_m = q/2), about e_j towards e_i
        for T_, T_perp, toward, um in ((Ti, Tj, j, q_ / 2), (Tj, Ti, i, p_ / 2)):
            phi1 = _first_region_tilt(F_, T_, h_, sv, um ** 2)
            if phi1 is not None:
                out.append(Prediction(("54", "55", "43a-conclusion", "claim-43a"), _axis_up(k, toward, phi1),
                                      "stable" if T_perp > T_ else "unstable",
                                      note="tilted about a symmetry axis of the base; (43a): stable iff T_1^1 > T_1"))
    return out


def _ngon_predictions(n_, av, h_, sv):
    """The regular n-gon base (vertex on +x): F_1 and T_1 from its vertices (polygon moments), u_m from
    r cos(pi/n) (an axis parallel to a side) to r (an axis across a vertex)."""
    R_ = av / (2 * math.sin(math.pi / n_))
    F_, _, ((_, _), (_, Iyy)) = polygon_moments(
        [(R_ * math.cos(2 * math.pi * k / n_), R_ * math.sin(2 * math.pi * k / n_)) for k in range(n_)])
    out = [_upright(Iyy, F_ * h_ * sv, h_ * (1 - sv) / 2, (0.0, 0.0, 1.0))]
    ang = math.pi / n_ + (math.pi if sv > 0.5 else 0.0)  # a side meets the water last: the axis parallel to it
    return out + _isotropic_ring(F_, Iyy, h_, sv, (R_ * math.cos(math.pi / n_)) ** 2, R_ ** 2, lambda ph: (
        math.sin(ph) * math.cos(ang), math.sin(ph) * math.sin(ang), math.cos(ph)))


def predict(scene):
    """A right prism floating with its axis vertical (boxes: each edge direction in turn, decided in exact
    arithmetic; regular n-gon prisms): the upright position (18) and the tilted ones of the first rotation region
    (27)/(54), (43a), (51), (55)."""
    if scene.body in ("box", "cube"):                    # a cube is a box
        return _box_predictions([Fraction(x_) for x_ in scene.dims], Fraction(scene.density))
    if scene.body == "prism":
        return _ngon_predictions(scene.sides, float(scene.dims[0]), float(scene.dims[1]), float(scene.density))
    return []


BODIES = ("box", "prism")
