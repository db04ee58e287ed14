"""The main job's pictures, ``docs/figures/*.png``, drawn from committed data.

A picture (:class:`Figure`) is drawn from JSON files under ``docs/`` that another step of the main
job wrote and stamped (the phase diagrams of :mod:`symfloat.report.phase_data`, Scheeffer IX's grid,
a report of that derivation: :mod:`symfloat.derivations._ix_figure`), never from a new computation.  Its PNG carries a text chunk
``Fingerprint``: the digest of the data, the code that draws it and Matplotlib's version.  The main
job redraws a picture only when that differs; Matplotlib writes the PNG without ``Software`` and
without a date, so the same data drawn again give the same bytes.
"""
from __future__ import annotations

import io
import json
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from .files import write_atomic
from .stamp import digest

__all__ = ["Figure", "main_job_figures", "fingerprint", "png_bytes", "recorded_fingerprint", "draw", "write_figures"]


@dataclass(frozen=True)
class Figure:
    """A picture, ``docs/figures/<filename>`` (PNG): ``draw(*data)`` gets the JSON files ``data`` (paths
    under ``docs/``) parsed and returns a Matplotlib figure; ``code`` are the source files that decide
    its look (with the data, its fingerprint)."""

    filename: str
    data: tuple[str, ...]
    draw: Callable[..., object]
    code: tuple = ()


def _ix_grid(grid):
    from ..derivations._ix_figure import grid_figure
    return grid_figure(grid)


def main_job_figures() -> list[Figure]:
    """The pictures of the main job: the phase diagrams and Scheeffer IX's grid."""
    from .phase_data import phase_figures
    root = Path(__file__).resolve().parents[1]
    return [*phase_figures(), Figure("scheeffer-ix-grid.png", ("scheeffer-ix-grid.json",), _ix_grid,
                                     code=(root / "derivations" / "_ix_figure.py",))]


def _data(figure, docs: Path) -> list[dict]:
    return [json.loads((docs / name).read_text(encoding="utf-8")) for name in figure.data]


def fingerprint(figure, docs: Path) -> str:
    """Digest of the picture's data files, its drawing code and the Matplotlib that draws it."""
    import matplotlib
    return digest(*(docs / name for name in figure.data), Path(__file__), *figure.code, matplotlib.__version__)


def draw(figure, docs: Path):
    """The Matplotlib figure of *figure*, from its committed data."""
    import matplotlib
    matplotlib.use("Agg")
    return figure.draw(*_data(figure, docs))


def png_bytes(fig, fp: str) -> bytes:
    """The PNG of *fig* with the fingerprint *fp* and no software name or date; the figure is closed."""
    import matplotlib.pyplot as plt
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, metadata={"Software": None, "Fingerprint": fp})
    plt.close(fig)
    return buf.getvalue()


def recorded_fingerprint(path: Path) -> str | None:
    """The fingerprint a PNG written here carries, or None."""
    from PIL import Image
    try:
        with Image.open(path) as image:
            return image.text.get("Fingerprint")
    except OSError:
        return None


def write_figures(docs: Path, progress=None, figures=None) -> list[str]:
    """Draw every picture whose fingerprint changed into ``docs/figures/``; the names drawn."""
    written = []
    for figure in main_job_figures() if figures is None else figures:
        if not all((docs / name).is_file() for name in figure.data):
            continue                                    # its data are not written (a partial checkout)
        path, fp = docs / "figures" / figure.filename, fingerprint(figure, docs)
        if recorded_fingerprint(path) == fp:
            continue
        progress and progress(f"drawing docs/figures/{figure.filename}")
        path.parent.mkdir(parents=True, exist_ok=True)
        write_atomic(path, png_bytes(draw(figure, docs), fp))
        written.append(figure.filename)
    return written
