"""Which printed formulas predict each equilibrium of a scene, and whether they agree.

The derivations that speak about a body are found without importing any: each
lists the bodies it predicts in its manifest (:func:`symfloat.registry.predicting`).
Only those derivations' statements and predictors are read: their predictors evaluate the printed formulas at
the scene's numbers.  Nothing is re-proved and no witness runs; each printed
formula carries the verdict its derivation *declares* (an erratum where one is
declared, ``unverifiable`` where the text is lost, else ``verified``), which
the proof checks (``symfloat verify``, CI) hold the derivation to.  A
prediction *agrees* when the solver found an equilibrium in its symmetry class
(within ``MATCH_RAD``) with the predicted stability; a prediction without a
matching equilibrium is a disagreement of its own.
"""
from __future__ import annotations

import math

import numpy as np

from ..registry import predicting, reader
from ..solver.bodies import polyhedron
from ..solver.local import local
from ..solver.solve import Solution, body_scale
from ..solver.symmetry import symmetry_group

__all__ = ["predicting", "cover", "declared_verdict"]

MATCH_RAD = 1e-6


def _distance(scene, group, predicted, eq) -> float:
    """Angle (radians) between a predicted up vector and an equilibrium's class."""
    u = np.asarray(predicted, dtype=float)
    u = u / np.linalg.norm(u)
    if scene.body == "cylinder":
        tilt = math.acos(min(1.0, abs(u[2])))
        return abs(tilt - math.radians(eq.tilt_deg))
    v = np.asarray(eq.up)
    return min(math.acos(max(-1.0, min(1.0, float(np.dot(g @ u, v))))) for g in group)


def _on_ring(scene, predicted, eq) -> bool:
    """Whether the predicted up vector is an equilibrium with the ring's potential."""
    poly = polyhedron(scene)
    loc = local(poly, np.asarray(predicted, dtype=float) / np.linalg.norm(predicted), scene.density)
    scale = body_scale(scene)
    return np.linalg.norm(loc.gradient) <= 1e-7 * scale and abs(loc.U - eq.potential) <= 1e-7 * scale


def declared_verdict(erratum: bool, lost) -> str:
    """The verdict a derivation declares for a printed formula with an erratum or not, lost or not (what its
    proof checks confirm)."""
    if erratum:
        return "erratum"
    return "unverifiable" if lost else "verified"


def cover(solution: Solution) -> tuple[list[str], list[dict]]:
    """Attach the predicting formulas to *solution*'s equilibria; returns the derivations
    read and the predictions that match no equilibrium."""
    scene = solution.scene
    ids = predicting(scene.body, scene.dims)
    group = symmetry_group(scene)
    unmatched = []
    for did in ids:
        d = reader(did)
        for pred in d.predict(scene):
            printed = [p for p in d.printed if p["name"] in pred.printed]
            entry = {"derivation": did, "printed": [f"{did}/{p['name']}" for p in printed],
                     "locators": sorted({p["locator"] for p in printed}),
                     "verdicts": sorted({declared_verdict(p["erratum"], p["lost"]) for p in printed}),
                     "corrections": [{"locator": p["locator"], "corrected": p["corrected"]}
                                     for p in printed if p["erratum"]],
                     "predicted_up": [float(x) for x in pred.up], "predicted_stability": pred.stability,
                     "predicted_family": pred.family, "note": pred.note}
            best = min(solution.equilibria, key=lambda e: _distance(scene, group, pred.up, e), default=None)
            match = None
            if best is not None:
                if _distance(scene, group, pred.up, best) <= MATCH_RAD:
                    match = best
                else:
                    rings = [e for e in solution.equilibria if e.family == "ring" and _on_ring(scene, pred.up, e)]
                    match = rings[0] if rings else None
            if match is None:
                entry["agrees"] = False
                entry["disagreement"] = "the solver finds no equilibrium there"
                unmatched.append(entry)
                continue
            entry["agrees"] = pred.stability is None or pred.stability == match.stability
            if not entry["agrees"]:
                entry["disagreement"] = f"predicted {pred.stability}, the solver finds {match.stability}"
            match.predictions.append(entry)
            for loc in entry["locators"]:
                if loc not in match.formulas:
                    match.formulas.append(loc)
    return ids, unmatched
