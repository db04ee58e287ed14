"""The derivations in pictures: the page of the pictures the main job draws, and the notebooks they concern.

The pictures and their data are committed by ``symfloat run`` (:mod:`symfloat.report.figures`): the phase
diagrams ``docs/figures/phase-*.png`` from ``docs/figures/phase-*.json`` and Scheeffer IX's case tables
against the solver ``docs/figures/scheeffer-ix-grid.png`` from ``docs/scheeffer-ix-grid.json``.  The
captions say what is drawn, read from the same data; nothing is computed or drawn here.
"""
from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

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


def _ix(docs: Path) -> Picture | None:
    data, png = docs / "scheeffer-ix-grid.json", docs / "figures" / "scheeffer-ix-grid.png"
    if not (data.is_file() and png.is_file()):
        return None
    cells = json.loads(data.read_text(encoding="utf-8"))["cells"]
    grid = [c for c in cells if not c["boundary"]]
    bad = sum(not c["agree"] for c in cells)
    caption = (
        f"The long rectangular log (Scheeffer IX): its section a × b, density s against a/b. Each of the "
        f"{len(grid)} grid cells is coloured by the number of stable positions the solver finds in the section "
        f"(one per symmetry class; the dots are the {len(cells) - len(grid)} cells a relative 1e-3 in (a/b)² "
        f"either side of a printed boundary). The black lines are the boundaries of the printed case tables, "
        f"evaluated from the derivation's readings of (132a), (132b), the condition of IX.C, (165) and n₁ of "
        f"(156) with t of (147); for s < 1/2 the text's rule (1 − s for s) where it prints one side only. "
        f"{bad} of {len(cells)} cells disagree with the tables (outlined in red). Data: "
        f"`docs/scheeffer-ix-grid.json`, written by `symfloat run` with the [table of the grid](scheeffer-ix-grid.md).")
    return Picture("picture-scheeffer-ix-grid", "scheeffer-ix-grid.png", "Scheeffer IX: the case tables against "
                   "the solver", caption, ("scheeffer-ix",))


def pictures(docs: Path) -> list[Picture]:
    """The committed pictures with their captions, in the page's order."""
    found = [_phase(docs, key, title) for key, title in _PHASES] + [_ix(docs)]
    return [p for p in found if p is not None]


def figures_page(found: list[Picture], notebooks) -> str:
    """The MyST page of the pictures; *notebooks* are the derivations with a notebook page."""
    lines = ["# The derivations in pictures", "",
             "Drawn by `symfloat run` from the data it commits (the picture is redrawn only when its data or its "
             "drawing code change); this page shows them as committed.", ""]
    for p in found:
        links = ", ".join(f"[{d}](notebooks/{d}.ipynb)" for d in p.derivations if d in notebooks)
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
