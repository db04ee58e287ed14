"""Building and executing the derivation notebooks.

One notebook per derivation module, built with nbformat and executed with
nbclient.  The mathematics (names, steps, quotations, readings) is written
into Markdown cells from the derivation module when the notebook is built; the
code cells import the module and show what the engine found.  Cell ids derive
from what a cell shows (step or formula name), so an unchanged derivation
regenerates an identical notebook and a new step changes only its own cells;
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

from ..errors import CheckFailed, EnvironmentProblem
from ..leftovers import sweep_orphans
from ..model.source import get_source
from ..project import library_folders
from ..registry import load
from ..files import write_if_changed
from .notebook_view import definitions_markdown, reading_markdown, step_markdown
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


def _library_of(module) -> Path | None:
    """The library of texts (``SYMFLOAT_LIBRARY``) whose ``derivations/`` holds *module*, else ``None``."""
    where = Path(module.__file__).resolve().parents[1]          # the package's __init__.py, in derivations/<name>/
    return next((folder for folder in library_folders() if (folder / "derivations").resolve() == where), None)


def build_notebook(derivation_id: str, folder: str | os.PathLike | None = None) -> nbformat.NotebookNode:
    """The unexecuted notebook of one derivation; one of a library of texts finds its library from
    *folder*, where it is written (so it re-runs there without ``SYMFLOAT_LIBRARY``)."""
    d, module = load(derivation_id)
    library = _library_of(module)
    setup = ""
    if library is not None:
        path = Path(os.path.relpath(library, Path(folder or ".").resolve())).as_posix()
        setup = ("import os  # the derivation belongs to a library of texts, found from this notebook's folder\n"
                 f"os.environ['SYMFLOAT_LIBRARY'] = os.path.abspath({path!r})\n")
    src = get_source(d.source)
    about = inspect.cleandoc(module.__doc__ or "")
    md, code = nbformat.v4.new_markdown_cell, nbformat.v4.new_code_cell
    cells = [
        (cell_id("title"), md(
            f"# {d.title}\n\n{src.author}, *{src.title}*{', ' + str(src.year) if src.year else ''} — "
            f"{d.locator} (source key `{d.source}`).\n\n{d.summary}\n\n"
            f"Derivation `{d.id}`" + (f", building on {', '.join(f'`{r}`' for r in d.requires)}" if d.requires
                                      else "") + ".\n\n**Assumptions**\n\n"
            + "\n".join(f"- {a}" for a in d.assumptions))),
        *([(cell_id("about"), md("## About this section\n\n" + about))] if about else []),
        (cell_id("setup"), code(
            setup + f"from symfloat.derivations import {module.__name__.split('.')[-1]} as derivation\n"
            "from symfloat.report.notebook_view import NotebookView\n\n"
            "view = NotebookView(derivation)   # what the engine found on this derivation\n"
            "assert not view.failures, view.failures\n"
            "view.summary()")),
    ]
    names = definitions_markdown(d)
    if names:
        cells.append((cell_id("names"), md(names)))
    cells.append((cell_id("derivation"), md(
        "## Derivation\n\nEach step: what it says, its expressions before and after, and how the engine "
        "justified it (a step is checked as an identity inside the stated assumptions, unless it is a "
        "definition).")))
    for i, s in enumerate(d.steps, 1):
        cells.append((cell_id("step", s.name), md(step_markdown(d, i, s))))
        cells.append((cell_id("step-check", s.name), code(f"view.step({s.name!r})")))
    cells.append((cell_id("printed"), md(
        "## Printed formulas\n\nThe transcription quoted verbatim and read as printed (the print's "
        "arithmetic kept), then the verdict, the erratum if there is one, and the independent witnesses.")))
    for p in d.printed:
        cells.append((cell_id("formula", p.name), md(reading_markdown(d, p))))
        cells.append((cell_id("formula-check", p.name), code(f"view.formula({p.name!r})")))
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
    """The notebook of *derivation_id* (to be written in *folder*), executed and stamped, as the text
    written to disk; a cell that fails is a failed check named in one line
    (:class:`~symfloat.errors.CheckFailed`), not a traceback.  A library's notebook runs in *folder*, as
    it will when re-run there."""
    nb = build_notebook(derivation_id, folder)
    where = Path.cwd()
    if _library_of(load(derivation_id)[1]) is not None:
        where = Path(folder)
        where.mkdir(parents=True, exist_ok=True)
    try:
        nb = execute_notebook(nb, where)
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
