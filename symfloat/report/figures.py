"""The main job's pictures, ``docs/figures/*.png``, drawn from committed data.

A picture (:class:`Figure`) is drawn from JSON files under ``docs/`` that another step of the main
job wrote and stamped (the phase diagrams of :mod:`symfloat.report.phase_data`, and the pictures the
derivations provide with ``provides("figure", Figure(...))`` from their own reports), never from a new
computation.  Its PNG carries a text chunk ``Fingerprint``: the digest of the data, the code that draws it and Matplotlib's version.  The main
job redraws a picture only when that differs; Matplotlib writes the PNG without ``Software`` and
without a date, so the same data drawn again give the same bytes.
"""
from __future__ import annotations

import io
import json
from pathlib import Path

from ..model.derivation import Figure
from ..files import write_atomic
from .stamp import digest

__all__ = ["Figure", "main_job_figures", "fingerprint", "png_bytes", "recorded_fingerprint", "draw", "write_figures"]


def main_job_figures() -> list[Figure]:
    """The pictures of the main job: the phase diagrams and the pictures the derivations provide."""
    from ..registry import provided
    from .phase_data import phase_figures
    return [*phase_figures(), *(figure for _, figure in provided("figure"))]


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
