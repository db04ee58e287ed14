"""Building and executing the derivation notebooks.

One notebook per derivation, built with nbformat and executed with nbclient.  A notebook is
plain SymPy a reader can change and run again: its first code cell declares the derivation's
symbols, and each step and printed formula is a Markdown cell (title in words, the source's
quotation, the explanation, the chain typeset, what the engine found) above a code cell that
states it in SymPy and checks it (:mod:`symfloat.report.notebook_cells`); a check that no longer
holds stops the notebook.  The derivation is read through :func:`symfloat.registry.load` and the
engine's report through :func:`symfloat.engine.runner.verify` when the notebook is built; the
kernel imports SymPy only.  Cell ids derive from what a cell shows (step or formula name), so an
unchanged derivation regenerates an identical notebook and a new step changes only its own cells;
no output carries a timing.
"""
from __future__ import annotations

import hashlib
import inspect
import os
import re
import subprocess
import tempfile
import uuid
from pathlib import Path

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError, DeadKernelError
from traitlets.config import Config

from ..engine.runner import verify
from ..errors import CheckFailed, EnvironmentProblem
from ..files import write_if_changed
from ..leftovers import sweep_orphans
from ..model.source import get_source
from ..registry import load
from .notebook_cells import CellWriter
from .notebook_view import NotebookView, definitions_markdown, reading_markdown, step_markdown, step_titles, words
from ..prose import displayed, without_program_names
from .stamp import digest

__all__ = ["build_notebook", "execute_notebook", "kernel_files", "write_notebooks", "notebook_stamp", "recorded_stamp"]

KERNEL = {"name": "python3", "display_name": "Python 3", "language": "python"}


def cell_id(kind: str, name: str = "") -> str:
    """A stable, valid cell id (``[A-Za-z0-9_-]``, at most 64 characters) for one cell.

    >>> cell_id("step", "mid-section-g"), cell_id("formula", "1+3t")
    ('step-mid-section-g-2336', 'formula-1_3t-02f4')
    """
    safe = re.sub(r"[^A-Za-z0-9_-]", "_", name)[:40]
    digest = hashlib.sha256(name.encode()).hexdigest()[:4]
    return f"{kind}-{safe}-{digest}" if name else kind


READING = """## How to read this notebook

Every step of the derivation below is a Markdown cell — what the step says, in the source's words
and ours, and its expressions before and after — above a code cell in plain SymPy that states the
step and checks it:

- `chain` holds the members of the step, which it asserts equal;
- `insert` puts in the values the earlier steps established (kept in `derived`) and carries out
  the integrals, limits and derivatives;
- the difference of each pair of members is reduced to 0 by the SymPy call of the step's proof
  certificate (`cancel`, `expand`, `radsimp`, `simplify`, or comparing squares), and asserted;
- `at` evaluates the members at a small point inside the assumptions: the same number twice
  (`same` compares two such values, exactly or to 25 digits, where a step has no symbolic proof).

Change a member and run the cells again: a step that no longer holds stops with an
`AssertionError`.  A printed formula is read as printed the same way; where the print is wrong,
its cell shows a point where its members differ and checks the correction instead."""


def _work(derivation_id: str) -> str:
    """A derivation this one builds on, as a reader finds it: its title, the work and the place in it
    (Euler's §§192-219 build on results derived for Scheeffer's VI.C-F)."""
    d = load(derivation_id)[0]
    src = get_source(d.source)
    return f"*{d.title}* ({src.author}{', ' + str(src.year) if src.year else ''}, {d.locator})"


def build_notebook(derivation_id: str, report=None) -> nbformat.NotebookNode:
    """The unexecuted notebook of one derivation; *report* is the engine's report on it (by default
    :func:`~symfloat.engine.runner.verify` gives it, from the cache when the derivation is unchanged).
    A report with failures is a failed check (:class:`~symfloat.errors.CheckFailed`)."""
    d, module = load(derivation_id)
    if report is None:
        report = next(r for r in verify(derivation_id) if r.id == derivation_id)
    if report.failures:
        raise CheckFailed(f"notebook {derivation_id}: the check fails: {report.failures[0]}")
    view = NotebookView(d, report)
    writer = CellWriter(d, report)
    src = get_source(d.source)
    about = inspect.cleandoc(module.__doc__ or "")
    md, code = nbformat.v4.new_markdown_cell, nbformat.v4.new_code_cell
    body = []
    names = definitions_markdown(d)
    if names:
        body.append((cell_id("names"), md(names)))
    body.append((cell_id("derivation"), md(
        "## Derivation\n\nEach step: what it says, its expressions before and after, how the engine justified "
        "it, and the step in SymPy (a step is checked as an identity inside the stated assumptions, unless it "
        "is a definition).")))
    titles = step_titles(d)
    for i, s in enumerate(d.steps, 1):
        body.append((cell_id("step", s.name), md(step_markdown(d, i, s, view.step_markdown(s.name), titles[s.name]),
                                                 metadata={"symfloat": {"step": s.name}})))
        body.append((cell_id("step-check", s.name), code(writer.step(s))))
    body.append((cell_id("printed"), md(
        "## Printed formulas\n\nThe transcription quoted verbatim and read as printed (the print's "
        "arithmetic kept), then the verdict, the erratum if there is one, and the independent witnesses; "
        "below each, the reading in SymPy and its check.")))
    for p in d.printed:
        body.append((cell_id("formula", p.name), md(reading_markdown(d, p, view.formula_markdown(p.name)),
                                                    metadata={"symfloat": {"formula": p.name}})))
        check = writer.formula(p)
        if check is not None:
            body.append((cell_id("formula-check", p.name), code(check)))
    cells = [
        (cell_id("title"), md(
            f"# {d.title}\n\n{src.author}, *{src.title}*{', ' + str(src.year) if src.year else ''} — "
            f"{d.locator}.\n\n{words(d, d.summary)}\n\n"
            + (f"Building on {', '.join(_work(r) for r in d.requires)}.\n\n" if d.requires else "")
            + f"Checked by `symfloat verify {d.id}`.\n\n**Assumptions**\n\n"
            + "\n".join(f"- {words(d, a)}" for a in d.assumptions))),
        *([(cell_id("about"), md("## About this section\n\n" + displayed(words(d, without_program_names(about)))))]
          if about else []),
        (cell_id("engine"), md("## What the engine found\n\n" + view.summary_markdown())),
        (cell_id("reading"), md(READING)),
        (cell_id("setup"), code(writer.setup())),
        *body,
    ]
    nb = nbformat.v4.new_notebook(cells=[c for _, c in cells], metadata={"kernelspec": KERNEL})
    nb.nbformat_minor = 5
    for cid, cell in cells:
        cell.id = cid
    if len({c.id for c in nb.cells}) != len(nb.cells):
        raise RuntimeError(f"{d.id}: duplicate notebook cell ids")
    return nb


def kernel_files() -> Path:
    """The folder of the kernels' connection files (``symfloat-kernels-<uid>`` in the temporary
    directory, private to the user): each is named after the process that started its kernel, and
    one whose process is gone (killed before it could remove the file) is removed here."""
    folder = Path(tempfile.gettempdir()) / f"symfloat-kernels-{os.getuid()}"
    folder.mkdir(mode=0o700, exist_ok=True)
    sweep_orphans(folder, "kernel-")
    return folder


def execute_notebook(nb, cwd: str | os.PathLike) -> nbformat.NotebookNode:
    """Execute *nb* in a fresh kernel whose connection file lies in :func:`kernel_files` (nbclient
    removes it when the kernel ends; a killed run's is removed by the next)."""
    connection = kernel_files() / f"kernel-{os.getpid()}-{uuid.uuid4().hex[:12]}.json"
    client = NotebookClient(nb, timeout=900, kernel_name="python3", record_timing=False,
                            resources={"metadata": {"path": str(cwd)}},
                            config=Config({"KernelManager": {"connection_file": str(connection)}}))
    # The kernel's own log (a transport warning at start) is noise here; a
    # failing cell raises CellExecutionError with its traceback regardless.
    client.execute(stderr=subprocess.DEVNULL)
    nb.metadata.pop("language_info", None)   # the kernel's Python version: machine, not mathematics
    for cell in nb.cells:
        if cell.cell_type == "code":
            cell.outputs = _coalesced(cell.outputs)
    return nb


def _coalesced(outputs) -> list:
    """*outputs* with consecutive pieces of one stream joined: the kernel sends a cell's printing in as
    many pieces as it happened to flush (a slow step's line comes in two), which is the clock's, not the
    notebook's."""
    out = []
    for o in outputs:
        if out and o.output_type == "stream" and out[-1].output_type == "stream" and out[-1].name == o.name:
            out[-1].text += o.text
        else:
            out.append(o)
    return out


def notebook_stamp(derivation_id: str, keys: dict) -> str:
    """The content stamp of a derivation's notebook: its cache key (module, proofs, library,
    ancestors), the code that builds and shows the notebook (the report modules it imports, its witness tables'
    words and numbers among them), and the SymPy that renders it."""
    import sympy

    here = Path(__file__).resolve().parent
    code = [here / f for f in ("notebooks.py", "notebook_view.py", "notebook_cells.py", "notebook_code.py",
                               "cross_references.py", "witness_words.py")]
    return digest(keys[derivation_id], *code, here.parent / "prose.py", here.parent / "numbers.py", sympy.__version__)


def write_notebooks(ids, folder: str | os.PathLike = "notebooks", progress=None, *, force: bool = False) -> list[Path]:
    """Build, execute and write the notebooks of *ids*; return the files written.

    A notebook whose recorded content stamp (its metadata ``symfloat.stamp``) equals the present
    one is current and is neither executed nor written, unless *force*."""
    from ..engine.runner import completed, default_workers, derivation_keys, worker_pool

    folder = Path(folder)
    os.environ.setdefault("SYMFLOAT_CACHE", str(Path(".symfloat-cache").resolve()))
    keys = derivation_keys(ids)
    stale = [(did, notebook_stamp(did, keys)) for did in ids]
    stale = [(did, stamp) for did, stamp in stale if force or recorded_stamp(folder / f"{did}.ipynb") != stamp]
    written = []

    def finished(did, text):          # written as soon as executed: a killed run keeps what it finished
        if write_if_changed(folder / f"{did}.ipynb", text):
            written.append(folder / f"{did}.ipynb")
        if progress:
            progress(did)

    if default_workers() > 1 and len(stale) > 1:          # one kernel per notebook, as many at once as cores
        with worker_pool(min(default_workers(), len(stale))) as pool:
            futures = {pool.submit(_executed_text, did, stamp, folder): did for did, stamp in stale}
            for did, text in completed(futures, "notebooks"):
                finished(did, text)
    else:
        for did, stamp in stale:
            finished(did, _executed_text(did, stamp, folder))
    order = {did: i for i, (did, _) in enumerate(stale)}
    return sorted(written, key=lambda path: order[path.stem])


def _executed_text(derivation_id: str, stamp: str, folder: Path) -> str:
    """The notebook of *derivation_id* (to be written in *folder*), executed in *folder* as a reader
    re-runs it there (its kernel needs SymPy alone, so a library's notebook runs without
    ``SYMFLOAT_LIBRARY``) and stamped, as the text written to disk; a cell that fails is a failed check
    named in one line (:class:`~symfloat.errors.CheckFailed`), not a traceback."""
    nb = build_notebook(derivation_id)
    Path(folder).mkdir(parents=True, exist_ok=True)
    try:
        nb = execute_notebook(nb, folder)
    except CellExecutionError as exc:
        raise CheckFailed(f"notebook {derivation_id}: a cell failed with {exc.ename}: {exc.evalue}") from None
    except DeadKernelError:
        raise EnvironmentProblem(f"notebook {derivation_id}: its kernel died (killed by a signal, perhaps for "
                                 f"want of memory); the notebooks finished before are kept") from None
    nb.metadata["symfloat"] = {"stamp": stamp}
    return nbformat.writes(nb) + "\n"


def recorded_stamp(path: Path) -> str | None:
    """The content stamp a written notebook records, or ``None``."""
    try:
        return nbformat.read(path, as_version=4).metadata.get("symfloat", {}).get("stamp")
    except (OSError, ValueError):
        return None
