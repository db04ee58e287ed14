"""A phase diagram as a picture, drawn from its record (:func:`symfloat.report.phase.phase_record`).

A bar per position class over the densities where it is stable, read from the thresholds alone and
checked against the sweep (:func:`phase_intervals`); a line at each threshold, dark where a source
prints it, red dotted where a source prints one the solver does not find.  Used by ``symfloat phase
--plot`` and by the main job's pictures (:mod:`symfloat.report.phase_data`).
"""
from __future__ import annotations

from ..errors import CheckFailed

__all__ = ["phase_intervals", "phase_figure"]


def phase_intervals(record) -> dict[str, list[tuple[float, float]]]:
    """Position label -> the density intervals of the sweep's range where it is stable, read from the
    thresholds alone (each one flips its position: ``stable above`` begins an interval, ``stable below``
    ends one), starting from the stable set at the first sweep density; thresholds outside the sweep's
    range (the long square log's upright position and ring around z, 0.0105 and 0.9895) are not read.
    The sweep is the other route: a sweep density whose stable set the intervals do not give fails the
    check (:class:`CheckFailed`)."""
    sweep = record["sweep"]
    lo, hi = sweep[0]["density"], sweep[-1]["density"]
    labels = sorted({label for row in sweep for label in row["stable"]} | {t["position"] for t in record["thresholds"]})
    out = {}
    for label in labels:
        events = sorted((t["density"], t["change"]) for t in record["thresholds"]
                        if t["position"] == label and lo <= t["density"] <= hi)
        start, spans = (lo if label in sweep[0]["stable"] else None), []
        for density, change in events:
            if change == "stable above" and start is None:
                start = density
            elif change == "stable below" and start is not None:
                spans.append((start, density))
                start = None
        if start is not None:
            spans.append((start, hi))
        out[label] = spans
    for row in sweep:
        drawn = sorted(label for label, spans in out.items() if any(a <= row["density"] <= b for a, b in spans))
        if drawn != sorted(row["stable"]):
            raise CheckFailed(f"phase diagram of the {record['body']}: at s = {row['density']:.6f} the thresholds "
                              f"give {drawn}, the sweep {row['stable']}")
    return out


def phase_figure(record):
    """The phase diagram *record* (:func:`phase_record`) as a Matplotlib figure: a bar per position over
    the densities where it is stable (:func:`phase_intervals`), a line at each threshold (dark where a
    source prints it), and a red dotted line where a source prints a threshold the solver does not find."""
    import matplotlib.pyplot as plt

    spans = phase_intervals(record)
    labels = [label for label in spans if spans[label]]
    fig, ax = plt.subplots(figsize=(8, 0.42 * max(len(labels), 5) + 1.9))   # room for the legend below
    colours = plt.cm.tab10.colors
    for y, label in enumerate(labels):
        ax.broken_barh([(a, b - a) for a, b in spans[label]], (y - 0.3, 0.6), color=colours[y % 10])
    printed = [t["density"] for t in record["thresholds"] if t["source"]]
    alone = [t["density"] for t in record["thresholds"] if not t["source"]]
    for xs, colour, style, name in ((alone, "0.65", "--", "threshold the solver finds, no source prints it"),
                                    (printed, "0.2", "-", "threshold the solver finds and a source prints"),
                                    ([k["value"] for k in record["source_thresholds_not_found"]], "red", ":",
                                     "threshold a source prints, the solver does not find")):
        for k, x in enumerate(sorted(set(xs))):
            ax.axvline(x, color=colour, linewidth=0.7, linestyle=style, label=None if k else name)
    ax.set_yticks(range(len(labels)), labels, fontsize=8)
    ax.set_ylim(-0.7, len(labels) - 0.3)
    ax.set_xlim(0, 1)
    ax.set_xlabel("density s (water = 1)")
    dims = ",".join(str(d) for d in record["dims_exact"])
    ax.set_title(f"{record['body']} ({dims}): stable positions against the density "
                 f"({len(record['thresholds'])} thresholds)", fontsize=9)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.18), ncol=1, frameon=False)
    fig.tight_layout()
    return fig
