"""Scheeffer IX's case tables against the solver, as a picture: density s against a/b.

Each cell of the grid (``docs/scheeffer-ix-grid.json``, :mod:`.grid`) is
coloured by the number of stable positions the solver finds in the section a x b; a cell where the
printed tables and the solver disagree is outlined in red, and the cells beside the boundaries are
dots in the same colours.  On top, the boundaries of the printed tables, each evaluated from the
derivation's reading of the print (:func:`boundaries`), not typed again here.  a/b is drawn on a
logarithmic axis.
"""
from __future__ import annotations

import math

import numpy as np
import sympy as sp

from . import statements

__all__ = ["BOUNDARIES", "boundaries", "cell_counts", "grid_figure", "grid_caption"]

# (label, printed formula of scheeffer-ix, row of its printed condition, mirrored for s < 1/2): the
# condition, read as printed, is linear in n = (a/b)^2; the boundary is where it is zero.  "Mirrored":
# the text writes the case for s > 1/2 only and reads s < 1/2 with 1 - s (as the tables do).
BOUNDARIES = (
    ("(132a): n = 6s(1-s), upright stable above", "132a", None, False),
    ("(132b): n = 2(1-s)(4s-1), 2s(3-4s): the oblique position of (125) leaves the first region", "132b", 1, False),
    ("(IX.C): n = 1/(6s(1-s)), the other upright unstable above", "unstable-3", None, False),
    ("(165): n = 1/(2(1-s)(4s-1)), the oblique position of (166) leaves the third region", "165", None, True),
)
N1 = ("(156) with t of (147): n_1, the double root of F (s > 23/32)", "156", "t-of-s")


def _printed(d, name):
    return next(p for p in d.printed if p.name == name)


def _member(expr, row):
    return expr[row] if row is not None else expr


def _curve(expr, s):
    """A float function of the density from the SymPy expression *expr* in *s* (NaN where undefined)."""
    f = sp.lambdify(s, expr, "math")

    def value(x):
        try:
            v = f(x)
        except (ValueError, ZeroDivisionError, TypeError):
            return math.nan
        return float(v) if isinstance(v, (int, float)) else math.nan
    return value


def boundaries(densities) -> dict[str, np.ndarray]:
    """Label -> n = (a/b)^2 on the printed boundary at each of *densities* (NaN where it is not drawn)."""
    d = statements.DERIVATION
    a, b, s, t, n = statements.a, statements.b, statements.s, statements.t, sp.Symbol("n", positive=True)
    out = {}
    for label, name, row, mirrored in BOUNDARIES:
        condition = sp.sympify(_member(_printed(d, name).reading[0], row)).subs(a, sp.sqrt(n) * b).doit()
        f = _curve(-condition.subs(n, 0) / sp.diff(condition, n), s)
        out[label] = np.array([f(max(x, 1 - x) if mirrored else x) for x in densities])
    label, name, t_of = N1
    n1 = sp.sympify(_printed(d, name).reading[1][0]).subs(t, _printed(d, t_of).reading[1])
    f = _curve(n1, s)
    out[label] = np.array([f(max(x, 1 - x)) for x in densities])
    return out


def cell_counts(grid: dict):
    """The grid's densities, ratios and the solver's stable count per cell (rows: densities)."""
    cells = [c for c in grid["cells"] if not c["boundary"]]
    densities = sorted({c["s_float"] for c in cells})
    ratios = sorted({c["ratio_float"] for c in cells})
    counts = np.full((len(densities), len(ratios)), -1)
    for c in cells:
        counts[densities.index(c["s_float"]), ratios.index(c["ratio_float"])] = c["solver_stable"]
    return densities, ratios, counts


def _edges(values, log=False):
    v = np.log(values) if log else np.asarray(values, dtype=float)
    mid = (v[1:] + v[:-1]) / 2
    e = np.concatenate([[v[0] - (mid[0] - v[0])], mid, [v[-1] + (v[-1] - mid[-1])]])
    return np.exp(e) if log else e


def grid_figure(grid: dict):
    """The picture (a Matplotlib figure) of the grid *grid* (``docs/scheeffer-ix-grid.json``)."""
    import matplotlib.pyplot as plt
    from matplotlib.colors import BoundaryNorm, ListedColormap

    densities, ratios, counts = cell_counts(grid)
    low, top = (int(f(c["solver_stable"] for c in grid["cells"])) for f in (min, max))
    cmap = ListedColormap(plt.cm.viridis(np.linspace(0.35, 0.95, top - low + 1)))
    norm = BoundaryNorm(np.arange(low - 0.5, top + 1), cmap.N)
    fig, ax = plt.subplots(figsize=(8, 7))
    xe, ye = _edges(ratios, log=True), _edges(densities)
    mesh = ax.pcolormesh(xe, ye, counts, cmap=cmap, norm=norm, edgecolors="face", linewidth=0)
    for c in grid["cells"]:
        if c["boundary"]:
            ax.scatter(c["ratio_float"], c["s_float"], s=14, c=[cmap(norm(c["solver_stable"]))],
                       edgecolors="black", linewidths=0.4, zorder=3)
        elif not c["agree"]:
            i, j = densities.index(c["s_float"]), ratios.index(c["ratio_float"])
            ax.add_patch(plt.Rectangle((xe[j], ye[i]), xe[j + 1] - xe[j], ye[i + 1] - ye[i], fill=False,
                                       edgecolor="red", linewidth=1.2, zorder=4))
    fine = np.linspace(0.001, 0.999, 999)
    styles = ["-", "--", "-.", ":", (0, (5, 1, 1, 1))]
    for (label, values), style in zip(boundaries(fine).items(), styles):
        with np.errstate(invalid="ignore"):
            r = np.where(values >= 1, np.sqrt(np.abs(values)), np.nan)
        r[r > xe[-1]] = np.nan
        ax.plot(r, fine, color="black", linewidth=1.1, linestyle=style, label=label, zorder=5)
    ax.set_xscale("log")
    ax.set_xlim(1, xe[-1])
    ax.set_ylim(0, 1)
    ticks = [r for r in ratios if r >= 1.1]          # 1.02 sits next to 1.1
    ax.set_xticks(ticks, [f"{r:g}" for r in ticks])
    ax.minorticks_off()
    ax.set_xlabel("a/b (the section a × b, a ≥ b)")
    ax.set_ylabel("density s (water = 1)")
    bad = sum(not c["agree"] for c in grid["cells"])
    ax.set_title(f"Scheeffer IX: stable positions the solver finds in {len(grid['cells'])} cells "
                 f"({bad} disagree with the tables); lines: the printed boundaries", fontsize=9)
    bar = fig.colorbar(mesh, ax=ax, ticks=range(low, top + 1), fraction=0.04, pad=0.02)
    bar.set_label("stable positions (one per symmetry class)")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.09), frameon=False)
    fig.tight_layout()
    return fig


def grid_caption(grid: dict) -> str:
    """The site's caption of the picture of *grid*: what is drawn, counted from the same data."""
    cells = grid["cells"]
    inner = [c for c in cells if not c["boundary"]]
    bad = sum(not c["agree"] for c in cells)
    return (
        f"The long rectangular log (Scheeffer IX): its section a × b, density s against a/b. Each of the "
        f"{len(inner)} grid cells is coloured by the number of stable positions the solver finds in the section "
        f"(one per symmetry class; the dots are the {len(cells) - len(inner)} cells a relative 10⁻³ in (a/b)² "
        f"either side of a printed boundary). The black lines are the boundaries of the printed case tables, "
        f"evaluated from the derivation's readings of (132a), (132b), the condition of IX.C, (165) and n₁ of "
        f"(156) with t of (147); for s < 1/2 the text's rule (1 − s for s) where it prints one side only. "
        f"{bad} of {len(cells)} cells disagree with the tables (outlined in red). Data: "
        f"`docs/scheeffer-ix-grid.json`, written by `symfloat run` with the [table of the grid](scheeffer-ix-grid.md).")
