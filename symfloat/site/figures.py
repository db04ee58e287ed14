"""The derivations in pictures: the page of the pictures the main job draws, and the notebooks they concern.

The pictures and their data are committed by ``symfloat run`` (:mod:`symfloat.report.figures`): the phase
diagrams ``docs/figures/phase-*.png`` from ``docs/figures/phase-*.json``, and the pictures the derivations
provide (``provides("figure", ...)``, e.g. Scheeffer IX's case tables against the solver), each with the
caption its derivation writes from the same data.  Nothing is computed or drawn here.
"""
from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from ..registry import statements
from ..report.cross_references import derivation_label

__all__ = ["Picture", "pictures", "figures_page", "notebook_links", "PAGE"]

PAGE = "figures"
_PHASES = (("cube", "The cube"), ("square-log", "The long square log"))


@dataclass(frozen=True)
class Picture:
    name: str               # the figure's target on the page
    file: str               # under figures/
    title: str
    caption: str
    derivations: tuple      # the derivations whose printed formulas it shows


def _phase(docs: Path, key: str, title: str) -> Picture | None:
    data, png = docs / "figures" / f"phase-{key}.json", docs / "figures" / f"phase-{key}.png"
    if not (data.is_file() and png.is_file()):
        return None
    r = json.loads(data.read_text(encoding="utf-8"))
    printed = sum(bool(t["source"]) for t in r["thresholds"])
    derivations = tuple(sorted({k["derivation"] for t in r["thresholds"] for k in t["source"]}
                               | {k["derivation"] for k in r["source_thresholds_not_found"]}))
    dims = ",".join(r["dims_exact"])
    caption = (
        f"The {r['body']} ({dims}): for each position class (up to the body's symmetry) a bar over the densities s "
        f"where it floats stably, from the {len(r['thresholds'])} thresholds the solver locates "
        f"({printed} of them printed by a source; dark lines) and checked against the stable sets of its sweep of "
        f"{r['steps']} densities k/{r['steps'] + 1}; a red dotted line is a threshold a source prints and the "
        f"solver does not find ({len(r['source_thresholds_not_found'])}). "
        f"Duality s ↔ 1 − s {'holds' if r['duality_holds'] else 'FAILS'}. "
        f"Data: `docs/figures/phase-{key}.json`, written by `symfloat run` as "
        f"`symfloat phase {r['body']}{' --dims ' + dims if r['body'] == 'box' else ''} --steps {r['steps']} "
        f"--format json` gives it (without the time); no source formula enters the solver.")
    return Picture(f"picture-phase-{key}", f"phase-{key}.png", f"{title}: phase diagram", caption, derivations)


def _provided(docs: Path, did: str, figure) -> Picture | None:
    data, png = [docs / name for name in figure.data], docs / "figures" / figure.filename
    if not (all(p.is_file() for p in data) and png.is_file()):
        return None
    caption = figure.caption(*(json.loads(p.read_text(encoding="utf-8")) for p in data))
    return Picture(f"picture-{Path(figure.filename).stem}", figure.filename, figure.title, caption, (did,))


def pictures(docs: Path) -> list[Picture]:
    """The committed pictures with their captions, in the page's order."""
    from ..registry import provided
    found = [_phase(docs, key, title) for key, title in _PHASES]
    found += [_provided(docs, did, figure) for did, figure in provided("figure")]
    return [p for p in found if p is not None]


def figures_page(found: list[Picture], notebooks) -> str:
    """The MyST page of the pictures; *notebooks* are the derivations with a notebook page."""
    lines = ["# The derivations in pictures", "",
             "Drawn by `symfloat run` from the data it commits (the picture is redrawn only when its data or its "
             "drawing code change); this page shows them as committed.", ""]
    for p in found:
        links = ", ".join(f"[{derivation_label(statements(d))}](notebooks/{d}.ipynb)" for d in p.derivations
                          if d in notebooks)
        lines += [f"({p.name})=", f"## {p.title}", "", f"```{{figure}} figures/{p.file}", f":alt: {p.title}", "",
                  p.caption, "```", ""]
        if links:
            lines += [f"The printed formulas drawn here: {links}.", ""]
    return "\n".join(lines)


def notebook_links(found: list[Picture]) -> dict[str, list[Picture]]:
    """Derivation -> the pictures that show its printed formulas."""
    out = {}
    for p in found:
        for d in p.derivations:
            out.setdefault(d, []).append(p)
    return out
