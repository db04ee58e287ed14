"""The thresholds the sources print, and phase diagrams compared with them.

A derivation that predicts a body's equilibria (its manifest's ``predicts``) is read at densities on a
grid, as a scene reads it (:func:`symfloat.registry.reader`: its compiled readings, no statements module); where its predicted set of stable positions changes, the density is bisected to ``1e-15``
(:func:`source_thresholds`).  :func:`phase_with_sources` hands these to the solver's phase diagram,
which looks for each one the sweep missed and matches every threshold it finds with them.
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np
import sympy as sp

from ..registry import predicting, provided, reader, statements
from ..solver.bodies import least_layer, make_scene
from ..solver.phase import PhaseDiagram, phase_diagram, position_label
from ..solver.symmetry import box_group, representative

__all__ = ["source_thresholds", "phase_with_sources"]


def phase_with_sources(body: str, dims=None, steps: int = 48, progress=None, densities=None) -> PhaseDiagram:
    """:func:`~symfloat.solver.phase.phase_diagram` with the sources' printed thresholds looked for and
    matched (those it does not find are its ``unmatched_sources``)."""
    base = make_scene(body, "1/2", dims)
    return phase_diagram(body, dims, steps, progress, densities, known=source_thresholds(body, base.dims))


def _predicted(d, scene, group, stability=("stable",)) -> dict:
    """Label -> names of the printed formulas by which the derivation *d* (a :class:`~symfloat.registry.Reader`)
    predicts a position at this scene with a stability in *stability* (``"stable"``, ``"unstable"``, ``None``
    for no claim)."""
    out = {}
    for p in d.predict(scene):
        if p.stability not in stability:
            continue
        label = position_label(representative(np.asarray(p.up, dtype=float) / np.linalg.norm(p.up), group), p.family)
        out.setdefault(label, set()).update(p.printed)
    return out


def source_thresholds(body: str, dims, grid: int = 400) -> list[dict]:
    """Densities where the printed formulas change their predicted set of stable positions: each
    ``{"value", "label", "change", "claim", "locators", "errata", "derivation", "expression"}``.  Found on the
    predictors (:mod:`symfloat.model.prediction`) by a sweep and bisection to ``1e-15``; the
    printed closed form is named where a derivation's result gives it (``expression``).  ``claim``
    is ``"unstable beyond"`` where the formulas predict the position unstable on the other side (the
    print claims a change of stability) and ``"silent beyond"`` where they predict it there with no
    stability or not at all (the position ceases to exist, or leaves the region the formulas cover);
    ``errata`` the locators among them whose printed formula carries an erratum."""
    group = box_group(dims)
    closed = _closed_forms()
    layer = least_layer(make_scene(body, "1/2", dims))       # a thin body's densities near 0 and 1 are outside
    densities = [Fraction(k, grid) for k in range(1, grid) if min(k, grid - k) / grid >= layer]
    out = []
    for did in predicting(body, dims):
        d = reader(did)
        at = lambda s: _predicted(d, make_scene(body, s, dims), group)
        states = [at(s) for s in densities]
        for k in range(len(densities) - 1):
            for label in sorted(set(states[k]) ^ set(states[k + 1])):
                inside = label in states[k]
                lo, hi = densities[k], densities[k + 1]
                while float(hi - lo) > 1e-15:
                    mid = (lo + hi) / 2
                    mid = Fraction(mid).limit_denominator(10 ** 18)
                    if (label in at(mid)) == inside:
                        lo = mid
                    else:
                        hi = mid
                value = float((lo + hi) / 2)
                names = states[k].get(label, set()) | states[k + 1].get(label, set())
                printed = [x for x in d.printed if x["name"] in names]
                locators = sorted({x["locator"] for x in printed})
                errata = sorted({x["locator"] for x in printed if x["erratum"]})
                expression = next((e for v, e in closed if abs(v - value) <= 1e-12), "")
                same = [o for o in out if o["derivation"] == did and o["label"] == label
                        and abs(o["value"] - value) <= 1e-13]
                if same:
                    same[0]["locators"] = sorted(set(same[0]["locators"]) | set(locators))
                    same[0]["errata"] = sorted(set(same[0]["errata"]) | set(errata))
                    continue
                beyond = _predicted(d, make_scene(body, hi if inside else lo, dims), group, ("unstable",))
                out.append({"value": value, "label": label, "change": "stable below" if inside else "stable above",
                            "claim": "unstable beyond" if label in beyond else "silent beyond",
                            "locators": locators, "errata": errata, "derivation": did, "expression": expression})
    return out


def _closed_forms() -> list[tuple[float, str]]:
    """Closed-form thresholds the derivations establish as results (value, expression): the results each
    derivation names with ``provides("thresholds", names)``.  These are results of the statements' steps, not
    readings of printed formulas, so they are no compiled reading: the statements that provide them are
    imported (with SymPy) here."""
    out = []
    for did, group in provided("thresholds"):
        d = statements(did)
        names = {str(symbol) for symbol in group}
        out += [(float(sp.N(value, 30)), str(sp.nsimplify(value)))
                for symbol, value in d.results().items() if str(symbol) in names]
    return out
