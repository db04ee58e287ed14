"""The phase diagrams the main job keeps: the cube, and the long square log.

``docs/figures/phase-<name>.json`` is the record of ``symfloat phase`` (:func:`symfloat.report.phase.
phase_record`, without its time) plus the ``stamp`` of what it depends on: the code it is made from
(:func:`code_files`: the solver, geometry and model packages, the comparison with the sources, the
manifests and the registry that choose the derivations it reads, the engine's polynomial roots the
predictors use, this module and :mod:`symfloat.report.phase`), the derivations whose predictors and
closed forms it compares with, and the body and sweep.  The main job computes a diagram again only when
that stamp differs (about 25 s for the cube and 40 s for the long square log, processor time); the
pictures are drawn from these files (:func:`symfloat.report.phase_figure.phase_figure`, through
:mod:`symfloat.report.figures`).

The long square log is the box 1 × 1 × 4: its sections across the long axis are the unit square of
Scheeffer IX with a = b and of the hasáb problem (which asks for a length l with l² > 3/2).
"""
from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

from .stamp import digest

__all__ = ["PHASES", "STEPS", "code_files", "phase_stamp", "phase_data", "write_phase_data", "phase_figures"]

PHASES = {"cube": ("cube", None), "square-log": ("box", "1,1,4")}
STEPS = 24
# the code of the symfloat package a record is made from: the sweep and the sources' thresholds, and the modules
# that find and read the derivations (engine/roots.py: the polynomial roots of IX's, VII-VIII's and X's predictors)
_PACKAGES = ("solver", "geometry", "model", "comparison")
_MODULES = ("__init__.py", "errors.py", "project.py", "manifest.py", "registry.py", "engine/__init__.py",
            "engine/roots.py", "report/phase.py", "report/phase_data.py")


def code_files() -> list[Path]:
    """The files of the ``symfloat`` package a phase record is made from (its derivations aside): the packages'
    modules and the C source of a compiled one."""
    root = Path(__file__).resolve().parents[1]
    return [f for name in _PACKAGES for f in sorted((root / name).rglob("*")) if f.suffix in (".py", ".c")] \
        + [root / f for f in _MODULES]


def _derivation_files(body: str, dims: str | None) -> list[Path]:
    from ..registry import files, predicting, providing
    edges = tuple(Fraction(x) for x in dims.split(",")) if dims else ()
    ids = sorted(set(predicting(body, edges)) | set(providing("thresholds")))
    return [f for did in ids for f in files(did) if f.suffix == ".py"]


def phase_stamp(name: str) -> str:
    body, dims = PHASES[name]
    root = Path(__file__).resolve().parents[1]
    return digest(*(f"{f.relative_to(root)}\n{f.read_text(encoding='utf-8')}" for f in code_files()),
                  *_derivation_files(body, dims), repr((body, dims, STEPS)))


def phase_data(name: str, progress=None) -> str:
    """The JSON of the phase diagram *name*, computed now (``seconds`` left out)."""
    from ..comparison.thresholds import phase_with_sources
    from .phase import phase_record
    body, dims = PHASES[name]
    record = phase_record(phase_with_sources(body, dims, STEPS, progress=progress))
    del record["seconds"]
    return json.dumps({"stamp": phase_stamp(name), "steps": STEPS, **record}, indent=1) + "\n"


def _stamp_in(path: Path) -> str | None:
    try:
        return json.loads(path.read_text(encoding="utf-8")).get("stamp")
    except (OSError, ValueError):
        return None


def write_phase_data(docs: Path, progress=None) -> list[str]:
    """Compute the diagrams whose stamp changed into ``docs/figures/``; the files written."""
    from ..files import write_if_changed
    written = []
    for name in PHASES:
        path = docs / "figures" / f"phase-{name}.json"
        if _stamp_in(path) != phase_stamp(name):
            progress and progress(f"computing the phase diagram {path.name}")
            write_if_changed(path, phase_data(name))
            written.append(path.name)
    return written


def phase_figures():
    """The pictures of the diagrams (:class:`symfloat.report.figures.Figure`)."""
    from .figures import Figure
    from .phase_figure import phase_figure
    return [Figure(f"phase-{name}.png", (f"figures/phase-{name}.json",), phase_figure,
                   code=(Path(__file__).with_name("phase_figure.py"),)) for name in PHASES]
