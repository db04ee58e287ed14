"""Building and executing the derivation notebooks.

One notebook per derivation module, built with nbformat and executed with
nbclient.  Cell ids derive from the derivation id and the cell's position, so
an unchanged derivation regenerates an identical notebook (timings aside,
which :func:`~symfloat.report.files.write_if_changed` ignores).
"""
from __future__ import annotations

import inspect
import os
from pathlib import Path

import subprocess

import nbformat
from nbclient import NotebookClient

from ..model.source import get_source
from ..registry import load
from .files import write_if_changed
from .stamp import digest

__all__ = ["build_notebook", "execute_notebook", "write_notebooks", "notebook_stamp", "recorded_stamp"]

KERNEL = {"name": "python3", "display_name": "Python 3", "language": "python"}


def _quote(text: str) -> str:
    return "\n".join("> " + line if line.strip() else ">" for line in text.splitlines())


def build_notebook(derivation_id: str) -> nbformat.NotebookNode:
    """The unexecuted notebook of one derivation."""
    d, module = load(derivation_id)
    src = get_source(d.source)
    about = inspect.cleandoc(module.__doc__ or "")
    cells = [
        nbformat.v4.new_markdown_cell(
            f"# {d.title}\n\n{src.author}, *{src.title}*{', ' + str(src.year) if src.year else ''} — "
            f"{d.locator} (source key `{d.source}`).\n\n{d.summary}\n\n"
            f"Derivation `{d.id}`" + (f", building on {', '.join(f'`{r}`' for r in d.requires)}" if d.requires
                                      else "") + ".\n\n**Assumptions**\n\n"
            + "\n".join(f"- {a}" for a in d.assumptions)),
        *([nbformat.v4.new_markdown_cell("## About this section\n\n" + about)] if about else []),
        nbformat.v4.new_code_cell(
            "from symfloat.report.notebook_view import checked, formula_markdown, show, steps_markdown\n"
            f"report = checked({d.id!r})\n"
            "assert not report.failures, report.failures\n"
            "print(f'{len(report.steps)} steps, {len(report.formulas)} printed formulas: ' +\n"
            "      ', '.join(f'{v} {sum(f.verdict == v for f in report.formulas)}'\n"
            "                for v in ('verified', 'erratum', 'unverifiable')))"),
        nbformat.v4.new_markdown_cell("## Derivation\n\nEach step with its justification and the engine's verdict."),
        nbformat.v4.new_code_cell("show(steps_markdown(report))"),
        nbformat.v4.new_markdown_cell("## Printed formulas\n\nThe transcription quoted verbatim, then its "
                                      "reading, verdict and witnesses."),
    ]
    for p in d.printed:
        cells.append(nbformat.v4.new_markdown_cell(f"### {p.locator}: `{p.name}`\n\n{_quote(p.excerpt)}"))
        cells.append(nbformat.v4.new_code_cell(f"show(formula_markdown(report, {p.name!r}))"))
    nb = nbformat.v4.new_notebook(cells=cells, metadata={"kernelspec": KERNEL})
    nb.nbformat_minor = 5
    slug = d.id.replace("graefe-", "g-")[:40]
    for i, cell in enumerate(nb.cells):
        cell.id = f"{slug}-{i:03d}"
    return nb


def execute_notebook(nb, cwd: str | os.PathLike) -> nbformat.NotebookNode:
    client = NotebookClient(nb, timeout=900, kernel_name="python3", record_timing=False,
                            resources={"metadata": {"path": str(cwd)}})
    # The kernel's own log (a transport warning at start) is noise here; a
    # failing cell raises CellExecutionError with its traceback regardless.
    client.execute(stderr=subprocess.DEVNULL)
    return nb


def notebook_stamp(derivation_id: str, keys: dict) -> str:
    """The content stamp of a derivation's notebook: its cache key (module, proofs, library,
    ancestors), the code that builds and shows the notebook, and the SymPy that renders it."""
    import sympy

    here = Path(__file__).resolve().parent
    return digest(keys[derivation_id], here / "notebooks.py", here / "notebook_view.py", sympy.__version__)


def write_notebooks(ids, folder: str | os.PathLike = "notebooks", progress=None, *, force: bool = False) -> list[Path]:
    """Build, execute and write the notebooks of *ids*; return the files written.

    A notebook whose recorded content stamp (its metadata ``symfloat.stamp``) equals the present
    one is current and is neither executed nor written, unless *force*."""
    from ..engine.runner import derivation_keys

    folder = Path(folder)
    os.environ.setdefault("SYMFLOAT_CACHE", str(Path(".symfloat-cache").resolve()))
    keys = derivation_keys(ids)
    written = []
    for did in ids:
        path = folder / f"{did}.ipynb"
        stamp = notebook_stamp(did, keys)
        if not force and recorded_stamp(path) == stamp:
            continue
        if progress:
            progress(did)
        nb = execute_notebook(build_notebook(did), Path.cwd())
        nb.metadata["symfloat"] = {"stamp": stamp}
        if write_if_changed(path, nbformat.writes(nb) + "\n"):
            written.append(path)
    return written


def recorded_stamp(path: Path) -> str | None:
    """The content stamp a written notebook records, or ``None``."""
    try:
        return nbformat.read(path, as_version=4).metadata.get("symfloat", {}).get("stamp")
    except (OSError, ValueError):
        return None
