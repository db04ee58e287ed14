"""docs/numerics.md and its figures from the benchmark, the orders and the stiff cases.

Times are printed as ``12.3 ms`` / ``1.2 s`` so that :func:`~symfloat.files.write_if_changed`
ignores them; a figure is rewritten only when its fingerprint (everything it shows except timings,
stored in the PNG's text chunk) changed.
"""
from __future__ import annotations

import hashlib
import inspect
import io
import math
import re
import statistics
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from PIL import Image  # noqa: E402

from ..numbers import scientific, written  # noqa: E402

__all__ = ["pareto", "method_rows", "cheapest", "family_figure", "write_png_if_changed", "fmt_time",
           "fmt_err", "fmt_proven", "FLOOR"]

FLOOR = 1e-110   # exact results are plotted here
THRESHOLDS = (1e-12, 1e-30)


def fmt_time(seconds: float) -> str:
    """``0.25 ms`` or ``1.20 s`` (the timing forms write_if_changed ignores)."""
    return f"{seconds * 1e3:.2f} ms" if seconds < 1 else f"{seconds:.2f} s"


def fmt_err(e) -> str:
    """An error as ``1.2 × 10⁻¹⁵``; ``failed`` where the method raised, ``no bound`` for a ball that is not
    finite."""
    if e is None:
        return "failed"
    if e == math.inf:
        return "no bound"
    return scientific(e)


def fmt_proven(n, total) -> str:
    """Whether the errors of a row are proven bounds: ``yes``, ``no`` or ``n of total`` witnesses."""
    return "yes" if n == total else "no" if n == 0 else f"{n} of {total}"


def pareto(points):
    """Indices of the non-dominated ``(time, error)`` points (no other point is
    at least as fast and at least as accurate, and better in one), by time."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], math.inf
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def _worst(m):
    errs = list(m.errors.values())
    return None if any(e is None for e in errs) else max(errs)


def method_rows(measurements):
    """Per method, in first-seen order: (method, witnesses, worst error, median error, median time, witnesses
    whose error is proven)."""
    by = defaultdict(list)
    for m in measurements:
        by[m.method].append(m)
    rows = []
    for method, ms in by.items():
        errs = [e for m in ms for e in m.errors.values()]
        ok = [e for e in errs if e is not None]
        worst = None if len(ok) < len(errs) else max(ok)
        rows.append((method, len(ms), worst, statistics.median(ok) if ok else None,
                     statistics.median(m.seconds for m in ms), sum(m.proven for m in ms)))
    return rows


TIE = 2.0   # methods within this factor of the fastest count as equally fast


def nominal(method: str) -> tuple:
    """A timing-free cost order of a method name: precision (float64 = 15 digits), float64 or exact before
    mpmath, then nodes or panels.

    >>> nominal("mpmath, 30 digits") < nominal("mpmath, 50 digits") < nominal("tanh-sinh, 100 digits")
    True
    >>> nominal("Gauss-Legendre n=2, float64") < nominal("Gauss-Legendre n=8, float64")
    True
    """
    digits = re.search(r"(\d+) digits", method)
    nodes = re.search(r"n=(\d+)|(\d+) panels", method)
    return (int(digits.group(1)) if digits else 15, 0 if "float64" in method or "exact" in method else 1,
            int(next(g for g in nodes.groups() if g)) if nodes else 0, method)


def cheapest(bench, threshold):
    """Formula -> (method, witness, seconds, error) of the cheapest measurement within *threshold*, or None.

    Methods are compared by their median time over the witness family (steadier than one witness's time);
    among those within a factor ``TIE`` of the fastest, the first in the timing-free order :func:`nominal`
    wins, so that timing noise between near-equal methods does not change the choice."""
    times = defaultdict(list)
    for m in bench.measurements:
        times[m.family, m.method].append(m.seconds)
    cost = {k: statistics.median(v) for k, v in times.items()}
    candidates = {}
    for m in bench.measurements:
        for name, e in m.errors.items():
            key = f"{m.derivation}/{name}"
            candidates.setdefault(key, [])
            if e is not None and e <= threshold:
                candidates[key].append((cost[m.family, m.method], (m.method, m.witness, m.seconds, e)))
    best = {}
    for key, cs in candidates.items():
        fastest = min((c for c, _ in cs), default=None)
        best[key] = None if fastest is None else min(
            (r for c, r in cs if c <= TIE * fastest), key=lambda r: (nominal(r[0]), r[1]))
    return best


def kind(method: str) -> str:
    """The family of a method name, for colours and legends."""
    for key in ("tanh-sinh", "Gauss-Legendre (mpmath)", "Gauss-Legendre n=", "Simpson", "trapezoid",
                "exact hull", "slices", "Arb ball arithmetic"):
        if method.startswith(key):
            return key.rstrip("=").replace(" n", " float64")
    if method.startswith("definitions, "):          # the definition route: the derivation's definitions by mpmath
        return f"the derivation's definitions, {method.removeprefix('definitions, ')}"
    return f"own computation, {method}"


def fingerprint(draw, *parts) -> str:
    """Hash of what a figure shows apart from timings: the data *parts* and the source of its drawing
    function *draw* (a change of style redraws it)."""
    return hashlib.sha256((inspect.getsource(draw) + repr(parts)).encode()).hexdigest()[:16]


def write_png_if_changed(path, fig, fp: str) -> bool:
    """Save *fig* to *path* unless the PNG there carries the same fingerprint."""
    path = Path(path)
    try:
        if Image.open(path).text.get("Fingerprint") == fp:
            plt.close(fig)
            return False
    except (OSError, AttributeError):
        pass
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, metadata={"Software": None, "Fingerprint": fp})
    plt.close(fig)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(buf.getvalue())
    return True


def family_figure(family, measurements, unit="witness"):
    """Error against time for one witness family: faint points per witness (per *unit*) and
    method (worst error over its formulas), large markers per method (median
    time, median error, a line up to the worst error), the Pareto front of the
    large markers."""
    fig, ax = plt.subplots(figsize=(8, 5.5))
    kinds = sorted({kind(m.method) for m in measurements})
    colours = dict(zip(kinds, plt.cm.tab10.colors))
    faint = [(max(m.seconds, 1e-6), max(e, FLOOR), colours[kind(m.method)])
             for m in measurements if (e := _worst(m)) is not None and math.isfinite(e)]
    if faint:       # one collection, drawn point by point in this order (one scatter a point took seconds to save)
        xs, ys, cs = zip(*faint)
        ax.scatter(xs, ys, s=6, alpha=0.25, color=cs)
    rows = [r for r in method_rows(measurements) if r[3] is not None and math.isfinite(r[3])]
    pts = [(r[4], max(r[3], FLOOR)) for r in rows]
    for r, (t, e) in zip(rows, pts):
        ax.scatter(t, e, s=40, color=colours[kind(r[0])], edgecolor="black", linewidth=0.5, zorder=3)
        if r[2] is not None and math.isfinite(r[2]):
            ax.plot([t, t], [e, max(r[2], FLOOR)], color=colours[kind(r[0])], lw=0.8, zorder=2)
    front = pareto(pts)
    ax.plot([pts[i][0] for i in front], [pts[i][1] for i in front], "k--", lw=1, zorder=2, label="Pareto front")
    for i in front:
        ax.annotate(rows[i][0], pts[i], fontsize=6, xytext=(4, 3), textcoords="offset points")
    for k in kinds:
        ax.scatter([], [], color=colours[k], label=k)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(FLOOR / 10, 10)
    ax.axhline(1e-12, color="grey", lw=0.5)
    ax.axhline(1e-30, color="grey", lw=0.5)
    ax.set_xlabel(f"wall time per {unit} (s; large markers: median over the family)")
    ax.set_ylabel(f"relative error (large markers: median, line up to the worst; exact at {written(FLOOR)})")
    ax.set_title(f"{family}: error against run time")
    ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fp = fingerprint(family_figure, family, [(m.witness, m.method, fmt_err(_worst(m))) for m in measurements])
    return fig, fp
