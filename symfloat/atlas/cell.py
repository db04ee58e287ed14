"""One shape cell of the atlas: the stable set of the box ``1 x b/a x c/a`` along the density.

The phase machinery (:func:`symfloat.comparison.thresholds.phase_with_sources`: a sweep, each change of the
stable set located by bisection with the position tracked, narrow windows found at folds and at
the printed thresholds) splits the swept range ``[A, B]`` at its thresholds; thresholds at the
same density (within their errors: a pitchfork's parent and child) make one boundary.  Each
interval between boundaries is one row: its ends with their error bounds, the thresholds at its
lower end, and the stable classes solved at its midpoint (orientation, tilt, G above B, smallest
eigenvalue, error), the Poincaré–Hopf sum there, whether the sweep densities inside the interval
saw the same stable set, the duality s <-> 1 - s inside the swept range (the sweep's stable sets
mirror, every threshold has its dual), and every printed prediction read there (:func:`symfloat.comparison.coverage.cover`).
Nothing in a row depends on the clock; the time a cell took is returned beside its rows.
"""
from __future__ import annotations

import time
from fractions import Fraction

from ..errors import SymfloatError
from ..solver import make_scene, solve
from ..comparison.coverage import cover
from ..comparison.thresholds import phase_with_sources
from ..solver.phase import position_label
from .grid import cell_body

__all__ = ["compute_cell", "boundaries"]


def boundaries(thresholds, lo: float, hi: float) -> list[dict]:
    """The thresholds strictly inside ``(lo, hi)`` grouped by density: thresholds whose densities
    differ by no more than the smaller of their errors (plus 1e-12) are one boundary (a threshold
    with a large error estimate does not swallow its neighbours), at the middle of the group, its
    error the group's half-width plus the largest error in it."""
    inside = sorted((t for t in thresholds if lo < t.density < hi), key=lambda t: (t.density, t.label, t.change))
    groups = []
    for t in inside:
        last = groups[-1][-1] if groups else None
        if last is not None and t.density - last.density <= min(t.bracket, last.bracket) + 1e-12:
            groups[-1].append(t)
        else:
            groups.append([t])
    out = []
    for g in groups:
        a, b = g[0].density, g[-1].density
        out.append({"density": (a + b) / 2, "error": (b - a) / 2 + max(t.bracket for t in g),
                    "changes": [{"position": t.label, "change": t.change, "note": t.note,
                                 "sources": [f"{k['derivation']} {', '.join(k['locators'])} = {k['value']:.13g}"
                                             for k in t.source]} for t in g]})
    return out


def _stable_classes(solution) -> list[dict]:
    out = []
    for e in solution.equilibria:
        if e.stability != "stable":
            continue
        values = sorted(e.eigenvalues, key=abs)[1:] if e.family == "ring" else list(e.eigenvalues)
        out.append({"position": position_label(e.up, e.family), "up": [float(x) for x in e.up],
                    "tilt_deg": float(e.tilt_deg), "family": e.family, "g_above_b": float(e.potential),
                    "min_eigenvalue": float(min(values)), "error_rad": float(e.error_rad),
                    "copies": e.copies, "waterplane": e.waterplane, "evidence": e.stability_evidence})
    return sorted(out, key=lambda c: (c["position"], c["up"]))


def _predictions(solution) -> list[dict]:
    """Every printed prediction at the scene, matched with the solver's equilibria."""
    _, unmatched = cover(solution)
    entries = [p for e in solution.equilibria for p in e.predictions] + unmatched
    out = [{"derivation": p["derivation"], "locators": list(p["locators"]), "verdicts": list(p["verdicts"]),
            "predicted_up": [float(x) for x in p["predicted_up"]], "predicted_stability": p["predicted_stability"],
            "agrees": bool(p["agrees"]), "disagreement": p.get("disagreement", "")} for p in entries]
    return sorted(out, key=lambda p: (p["derivation"], p["locators"], p["predicted_up"]))


def _failure_row(ba, ca, body, message) -> dict:
    return {"b_a": float(ba), "c_a": float(ca), "b_a_exact": str(ba), "c_a_exact": str(ca), "body": body,
            "failure": message, "interval": None}


def compute_cell(ba: Fraction, ca: Fraction, densities) -> tuple[list[dict], dict]:
    """The rows of the cell ``b/a = ba, c/a = ca`` swept over *densities*, and its cost
    ``{"seconds", "thresholds", "intervals"}`` (measured, kept out of the rows).  A self-check of the
    solver that fails (an index sum that does not close) in the sweep makes one row with the failure
    (``interval`` null); at an interval's sample, that row carries it."""
    start = time.perf_counter()
    body, dims = cell_body(ba, ca)
    densities = [Fraction(s) for s in densities]
    try:
        rows = _rows(ba, ca, body, dims, densities)
    except SymfloatError as exc:
        rows = [_failure_row(ba, ca, body, f"{type(exc).__name__}: {exc}")]
    thresholds = sum(len(r.get("from_changes") or []) for r in rows)
    cost = {"seconds": time.perf_counter() - start, "thresholds": thresholds, "intervals": len(rows)}
    return rows, cost


def _rows(ba, ca, body, dims, densities) -> list[dict]:
    diagram = phase_with_sources(body, dims, densities=densities)
    lo, hi = float(densities[0]), float(densities[-1])
    bounds = boundaries(diagram.thresholds, lo, hi)
    ends = [{"density": lo, "error": 0.0, "changes": []}] + bounds + [{"density": hi, "error": 0.0, "changes": []}]
    unpaired = [f"{t.label}: {t.change} at {t.density:.13g} ± {t.bracket:.0e}" for t in diagram.unpaired
                if lo < t.density < hi]
    mirrored = all(a == b for a, b in zip(diagram.stable, reversed(diagram.stable)))
    missing = [f"{k['derivation']} {', '.join(k['locators'])}: {k['label']} {k['change']} at {k['value']:.13g}"
               f" [{k['seen']}: {k['why']}]" for k in diagram.unmatched_sources]
    rows = []
    for k in range(len(ends) - 1):
        a, b = ends[k], ends[k + 1]
        sample = (a["density"] + b["density"]) / 2
        try:
            solution = solve(make_scene(body, Fraction(sample), dims))
            failure, stable, predictions = None, _stable_classes(solution), _predictions(solution)
            index = solution.checks.get("poincare_hopf_index_sum")
        except SymfloatError as exc:                    # the solver's self-check failed at this sample
            failure, stable, predictions, index = f"{type(exc).__name__}: {exc}", [], [], None
        labels = sorted({c["position"] for c in stable})
        inside = [row for s, row in zip(diagram.densities, diagram.stable)
                  if a["density"] + a["error"] < s < b["density"] - b["error"]]
        rows.append({
            "b_a": float(ba), "c_a": float(ca), "b_a_exact": str(ba), "c_a_exact": str(ca), "body": body,
            "failure": failure, "interval": k,
            "s_from": a["density"], "s_from_error": a["error"], "s_to": b["density"], "s_to_error": b["error"],
            "from_changes": [{"position": c["position"], "change": c["change"], "note": c["note"],
                              "sources": c["sources"]} for c in a["changes"]],
            "sample_density": sample, "stable": stable, "stable_classes": len(stable),
            "stable_positions": (None if any(c["copies"] is None for c in stable)
                                 else sum(c["copies"] for c in stable)),
            "index_sum": index,
            "sweep_points": len(inside), "sweep_agrees": all(sorted(row) == labels for row in inside),
            "duality_holds": mirrored and not unpaired, "thresholds_without_dual": unpaired,
            "sources_not_found": missing,
            "predictions": predictions,
        })
    return rows
