"""A scene's answer as JSON (the design brief's contract), as a table, and as a picture."""
from __future__ import annotations

import json
import math
import re
import unicodedata
from collections import Counter

import mpmath
import numpy as np

from ..numbers import signs
from ..prose import GREEK
from .citations import cited, source_of

__all__ = ["scene_record", "scene_json", "scene_table", "scene_plot"]


def _dims(scene):
    if scene.body == "section":
        return [[float(x), float(y)] for x, y in scene.polygon]
    return [float(d) for d in scene.dims]


def _unit(v) -> list:
    norm = math.sqrt(sum(float(x) ** 2 for x in v))
    return [float(x) / norm for x in v] if norm > 0 else [float(x) for x in v]


def _predictions(entries) -> list:
    """The predictions with ``predicted_up`` as a unit vector (a predictor's direction need not be one)."""
    return [{**p, "predicted_up": _unit(p["predicted_up"])} for p in entries]


def scene_record(solution, evaluated, unmatched, seconds) -> dict:
    sc = solution.scene
    return {
        "body": sc.body,
        "dims": _dims(sc),
        **({"sides": sc.sides} if sc.sides else {}),
        "density": float(sc.density),
        "density_exact": str(sc.density),
        "equilibria": [{
            "up": list(e.up),           # every digit of the float64 vector the error bound speaks of
            # where the solver polished the position at 30 digits (next to a bifurcation, where error_rad can
            # be far below the float64 rounding of up), those digits; else null (up is the result)
            "up_digits": [mpmath.nstr(x, 30) for x in e.digits] if e.digits else None,
            "tilt_deg": round(e.tilt_deg, 12),
            "stability": e.stability,
            "stability_evidence": e.stability_evidence,
            "family": e.family,
            **({"ring_shape": e.ring_shape, "ring_length_rad": e.ring_length,
                "ring_length_error_rad": e.ring_length_error} if e.family == "ring" else {}),
            "potential": e.potential,
            "waterplane": e.waterplane,
            "formulas": e.formulas,
            "predictions": _predictions(e.predictions),
            "metacentric_eigenvalues": list(e.eigenvalues),
            "error_rad": e.error_rad,          # for a ring: across it (its tilt)
            "error_method": e.error_method,
            **({"stability_decided": e.decided} if e.decided else {}),
            "copies": e.copies,
            **({"certificate": _certificate(e.certificate)} if e.certificate is not None else {}),
        } for e in solution.equilibria],
        "unmatched_predictions": _predictions(unmatched),
        "disagreements": sum(not p["agrees"] for e in solution.equilibria for p in e.predictions) + len(unmatched),
        "checks": solution.checks,
        "derivations_evaluated": evaluated,
        "seconds": {"solver": solution.seconds, "total": seconds},
    }


def _certificate(c) -> dict:
    """The JSON of a :class:`~symfloat.solver.certificate.Certificate`."""
    return {"certified": c.certified,
            **({"box_radius_rad": c.radius,
                "eigenvalue_enclosures": [list(pair) for pair in c.eigenvalues]} if c.certified else {}),
            **({"stability": c.stability} if c.stability else {}),
            **({"reason": c.reason} if c.reason else {})}


def _up(vector) -> str:
    """An up vector as the table shows it: ``(+0.573933, +0.573933, +0.584125)``."""
    return "(" + ", ".join(f"{x:+.6f}" for x in vector) + ")"


_GREEK_WORD = re.compile(r"\b(" + "|".join(GREEK) + r")\b")


def _words(text: str) -> str:
    """A predictor's sentence as a reader sees it: its signs (:func:`symfloat.numbers.signs`) and a Greek
    letter for a Greek name (``beta = (2 - x)(1 - s)/z`` as ``β = (2 − x)(1 − s)/z``); the record keeps its text.

    >>> _words("beta = (2 - x)(1 - s)/z = 1.085 > 1")
    'β = (2 − x)(1 − s)/z = 1.085 > 1'
    """
    return _GREEK_WORD.sub(lambda m: unicodedata.lookup(f"GREEK {'CAPITAL' if m[1][0].isupper() else 'SMALL'} "
                                                         f"LETTER {m[1].removeprefix('var').upper().replace('LAMBDA', 'LAMDA')}"),
                             signs(text))


def _formulas(predictions) -> str:
    """The formulas column: the places of the agreeing predictions cited together, each disagreeing one on its
    own with its reason."""
    agreeing = [p for p in predictions if p["agrees"]]
    parts = [f"{cited(agreeing)} (agree{'s' if len(agreeing) == 1 and len(agreeing[0]['locators']) == 1 else ''})"
             ] if agreeing else []
    parts += [f"{cited([p])} (DISAGREES: {p['disagreement']})" for p in predictions if not p["agrees"]]
    return "; ".join(parts) or "-"


def scene_json(record) -> str:
    return json.dumps(record, indent=2)


def scene_table(record) -> str:
    dims = (" ".join(",".join(f"{c:g}" for c in p) for p in record["dims"]) if record["body"] == "section"
            else ",".join(f"{d:g}" for d in record["dims"]))
    sides = f", {record['sides']} sides" if record.get("sides") else ""
    lines = [f"{record['body']} ({dims}{sides}) at density {record['density_exact']}: "
             f"{len(record['equilibria'])} equilibria (one per symmetry class)", "",
             f"{'up (body frame)':<34} {'tilt':>9} {'stability':<12} {'family':<9} {'G above B':>12} "
             f"{'waterplane':<18} {'error':>8}  formulas"]
    for e in record["equilibria"]:
        up = _up(e["up"])
        family = e["family"] if e["family"] != "ring" else ("ring" if e["ring_shape"] == "closed" else "arc")
        lines.append(f"{up:<34} {e['tilt_deg']:>8.4f}° {e['stability']:<12} {family:<9} "
                     f"{e['potential']:>12.9f} {e['waterplane']:<18} {e['error_rad']:>8.1e}  "
                     + _formulas(e["predictions"]))
    for e in record["equilibria"]:
        c = e.get("certificate")
        if c is None:
            continue
        up = _up(e["up"])
        if c["certified"]:
            eigen = ", ".join(f"[{lo:.6g}, {hi:.6g}]" for lo, hi in c["eigenvalue_enclosures"])
            lines.append(f"certified: up {up} is the only equilibrium within {c['box_radius_rad']:.0e} rad "
                         f"(Krawczyk, ball arithmetic); eigenvalues in {eigen}"
                         + (f": {c['stability']}" if c.get("stability") else f"; {c['reason']}"))
        else:
            lines.append(f"not certified: up {up}: {c['reason']}")
    for p in record["unmatched_predictions"]:
        lines.append(f"DISAGREEMENT: {cited([p])} predicts an equilibrium at up {_up(p['predicted_up'])} "
                     f"({p['predicted_stability'] or 'no stability claimed'}); {_words(p['disagreement'])}"
                     + (f" ({_words(p['note'])})" if p.get("note") else ""))
    completeness = record["checks"].get("completeness")
    if completeness:
        lines.append(f"completeness: {completeness['statement']} ({completeness['squares_examined']} squares of the "
                     f"sphere of up vectors examined: {completeness['squares_excluded']} without an equilibrium, "
                     f"{completeness['squares_accounted']} holding exactly one reported, the others split; "
                     f"{completeness['seconds']:.1f} s)")
    lines.append("")
    lines.append(f"self-check: {_self_check(record['checks'])}")
    lines.append(f"derivations evaluated: {_evaluated(record['derivations_evaluated'])}; "
                 f"{record['seconds']['total']:.2f} s")
    return "\n".join(lines)


def _evaluated(ids) -> str:
    """How many derivations a scene evaluated, by the source each reads, the most first (``7 (5 of Scheeffer 1902,
    1 of ...)``); the record keeps their ids."""
    ranked = Counter(source_of(d) for d in ids).most_common()         # ties in the record's order
    return f"{len(ids)} ({', '.join(f'{n} of {s}' for s, n in ranked)})" if ids else "none"


def _self_check(checks: dict) -> str:
    """The solver's index sum in words: a body's Poincaré–Hopf sum over the equilibria on the sphere of up
    vectors (it must be 2), a section's minima − maxima of the heel angle over its fundamental arc (0), and the
    searches that reached it (the solver stops with an error where the sum is not what it must be); a cylinder's
    minima − maxima of its tilt over a whole turn in its meridian plane (0), its tilts searched on one grid."""
    if "searches" not in checks:                    # a cylinder: its tilts on one grid
        return (f"minima − maxima of the tilt over a whole turn is {checks['minima_minus_maxima']}, as it must be "
                f"(the tilts from 0° to 90° on a grid of {checks['grid']} points; {checks['note']})")
    searches = checks["searches"]
    if "poincare_hopf_index_sum" in checks:
        families = [("undecided" if i is None else str(i)) for i in checks.get("family_indices", ())]
        named = "the family's index" if len(families) == 1 else "the families' indices"
        indices = f"; {named} {', '.join(families)}" if families else ""
        then = f", then: {'; '.join(searches[1:])}" if len(searches) > 1 else ""
        return (f"the Poincaré–Hopf index sum of the equilibria is {checks['poincare_hopf_index_sum']}, as it must "
                f"be (found from {checks['seeds']} seeds{then}){indices}")
    lo, hi = (f"{x:g}°".replace("-", "−") for x in checks["arc_deg"])
    coarser = f", after {len(searches) - 1} coarser" if len(searches) > 1 else ""
    return (f"minima − maxima of the heel angle is {checks['minima_minus_maxima']}, as it must be, over the arc "
            f"from {lo} to {hi} (a grid of {checks['grid']} points{coarser})")


def _rotation_to_up(u) -> np.ndarray:
    """A rotation taking the body-frame vector *u* to the vertical (0, 0, 1)."""
    u = np.asarray(u, dtype=float)
    z = np.array([0.0, 0.0, 1.0])
    v, c = np.cross(u, z), float(np.dot(u, z))
    if np.linalg.norm(v) < 1e-15:
        return np.eye(3) if c > 0 else np.diag([1.0, -1.0, -1.0])
    k = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + k + k @ k / (1 + c)


def scene_plot(solution, path) -> None:
    """One panel per stable equilibrium: the body turned so that ``up`` is vertical, the water
    plane shaded and the part below it drawn darker."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    from ..geometry.floating import clip_below, draught
    from ..solver.bodies import polyhedron
    from ..geometry.cylinder import cylinder_slice

    scene = solution.scene
    stable = [e for e in solution.equilibria if e.stability == "stable"] or solution.equilibria
    fig = plt.figure(figsize=(4 * len(stable), 4.2))
    for i, e in enumerate(stable, 1):
        ax = fig.add_subplot(1, len(stable), i, projection="3d")
        if scene.body == "cylinder":
            from ..geometry.floating import regular_prism
            r, L = (float(x) for x in scene.dims)
            poly = regular_prism(64, 2 * r * math.sin(math.pi / 64), L)
            t = float(cylinder_slice(r, L, math.radians(e.tilt_deg), float(scene.density)).t)
        else:
            poly = polyhedron(scene)
            t = draught(poly, e.up, scene.density)[0]
        R = _rotation_to_up(e.up)
        lift = np.array([0.0, 0.0, -float(t)])
        body = [[R @ np.array([float(c) for c in p]) + lift for p in ring] for ring in poly.faces]
        wet = [[R @ np.array([float(c) for c in p]) + lift for p in ring]
               for ring in clip_below(poly, e.up, t).faces]
        ax.add_collection3d(Poly3DCollection(body, facecolor=(0.8, 0.8, 0.8, 0.25), edgecolor="0.3", linewidth=0.5))
        ax.add_collection3d(Poly3DCollection(wet, facecolor=(0.2, 0.4, 0.8, 0.45), edgecolor="none"))
        pts = np.array([p for ring in body for p in ring])
        span = float(np.max(np.abs(pts))) * 1.1
        for setter in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
            setter(-span, span)
        xx, yy = np.meshgrid([-span, span], [-span, span])
        ax.plot_surface(xx, yy, np.zeros_like(xx), color=(0.3, 0.6, 1.0), alpha=0.15)
        ax.set_title(f"{e.family} tilt {e.tilt_deg:.2f}°\n{e.waterplane} waterplane", fontsize=9)
        ax.set_axis_off()
    fig.suptitle(f"{scene.body} at density {scene.density}: stable positions", fontsize=10)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
