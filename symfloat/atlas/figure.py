"""The atlas as pictures: per slice c/a, the number of stable positions over (b/a, s).

Each column is one b/a of the grid, split along s at the atlas's thresholds (exact to their error
bounds, not to the sweep's spacing) and coloured by the number of stable classes (positions up to
the box's symmetry).  On top: the thresholds of Scheeffer IX's printed tables for the box turned
about its c edge (cross-section 1 x b/a; the lines where the tables' number of stable positions
changes, evaluated on a fine grid), and the cube's thresholds (``symfloat phase cube``) as dotted
lines.  A cell or interval whose solver self-check failed is left white.  PNG through Agg, without
software or date metadata: the same atlas gives the same bytes.
"""
from __future__ import annotations

import functools
import io
import math
from fractions import Fraction
from pathlib import Path

import numpy as np

from ..files import write_atomic

__all__ = ["write_slices", "slice_png"]


def _edges(values: list[float]) -> list[float]:
    """Column edges on a log scale: geometric midpoints, the outer ones mirrored."""
    if len(values) == 1:
        return [values[0] / 1.2, values[0] * 1.2]
    mids = [math.sqrt(a * b) for a, b in zip(values, values[1:])]
    return [values[0] ** 2 / mids[0]] + mids + [values[-1] ** 2 / mids[-1]]


@functools.lru_cache(maxsize=4)
def _ix_counts(ratios: tuple, densities: tuple) -> np.ndarray:
    """The number of stable positions Scheeffer IX's tables give at each density (rows, exact) and b/a (columns);
    read-only and remembered: the slices of one atlas share their b/a columns and densities as a rule, and the
    160 x 161 points cost seconds.  The tables read a density s below 1/2 as 1 - s (the text's rule), so a row
    is counted once for s and 1 - s: half the rows of a grid symmetric about 1/2."""
    from .checks import _ix_tables
    tables = _ix_tables()
    rows: dict = {}

    def row(s: Fraction) -> list[int]:
        key = max(s, 1 - s)
        if key not in rows:
            rows[key] = [sum(p["stability"] == "stable" for p in tables(key, r)) for r in ratios]
        return rows[key]
    counts = np.array([row(s) for s in densities])
    counts.flags.writeable = False
    return counts


def slice_png(rows, meta, ca: Fraction, reference=None) -> bytes:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.patches import Rectangle

    mine = [r for r in rows if Fraction(r["c_a_exact"]) == ca and not r["failure"]]
    ba = sorted({Fraction(r["b_a_exact"]) for r in rows if Fraction(r["c_a_exact"]) == ca})
    edges = _edges([float(x) for x in ba])
    exact_lo, exact_hi = Fraction(meta["densities"][0]), Fraction(meta["densities"][-1])
    lo, hi = float(exact_lo), float(exact_hi)
    top = max([r["stable_classes"] for r in mine] + [3])
    cmap = ListedColormap(plt.get_cmap("viridis", top + 1)(range(top + 1)))
    norm = BoundaryNorm([k - 0.5 for k in range(top + 2)], top + 1)
    fig, ax = plt.subplots(figsize=(6.4, 5.4))
    for r in mine:
        k = ba.index(Fraction(r["b_a_exact"]))
        ax.add_patch(Rectangle((edges[k], r["s_from"]), edges[k + 1] - edges[k], r["s_to"] - r["s_from"],
                               facecolor=cmap(norm(r["stable_classes"])), edgecolor="none"))
    ratios = np.geomspace(edges[0], edges[-1], 160)
    densities = tuple(exact_lo + (exact_hi - exact_lo) * Fraction(k, 160) for k in range(161))
    counts = _ix_counts(tuple(float(x) for x in ratios), densities)
    if counts.max() > counts.min():
        levels = [k + 0.5 for k in range(int(counts.min()), int(counts.max()))]
        ax.contour(ratios, [float(s) for s in densities], counts, levels=levels, colors="white", linewidths=1.0)
    ax.plot([], [], color="white", label="Scheeffer IX tables (turned about c: section 1 × b/a)")
    for t in (reference or {}).get("thresholds", []):
        if lo < t["density"] < hi:
            ax.axhline(t["density"], color="0.85", linestyle=":", linewidth=0.8)
    ax.plot([], [], color="0.85", linestyle=":", label="cube thresholds (symfloat phase cube)")
    for x in edges:
        ax.axvline(x, color="black", linewidth=0.3)
    ax.set_xscale("log")
    ax.set_xlim(edges[0], edges[-1])
    ax.set_ylim(lo, hi)
    ax.set_xticks([float(x) for x in ba], [str(x) for x in ba])
    ax.minorticks_off()
    ax.set_xlabel("b/a")
    ax.set_ylabel("density s (water = 1)")
    ax.set_title(f"box 1 × b/a × {ca}: number of stable positions (classes up to symmetry)", fontsize=9)
    ax.add_patch(Rectangle((0, 0), 0, 0, facecolor="white", edgecolor="0.5",
                           label="no data (a solver self-check failed)"))
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2, fontsize=7, facecolor="0.45",
              labelcolor="white", framealpha=1.0)
    bar = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, ticks=range(top + 1))
    bar.set_label("stable classes")
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=100, metadata={"Software": None}, bbox_inches="tight")
    plt.close(fig)
    return buffer.getvalue()


def write_slices(rows, meta, folder: Path, reference=None) -> list[Path]:
    """One PNG per c/a of the atlas: ``folder/atlas-c<c/a>.png`` (``/`` written ``_``)."""
    out = []
    for ca in sorted({Fraction(x) for x in meta["c_a"]}):
        path = Path(folder) / f"atlas-c{str(ca).replace('/', '_')}.png"
        write_atomic(path, slice_png(rows, meta, ca, reference))
        out.append(path)
    return out
