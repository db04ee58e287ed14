"""A phase diagram as JSON, as a table and as a picture."""
from __future__ import annotations

import json
from fractions import Fraction

__all__ = ["phase_record", "phase_json", "phase_table", "phase_plot"]


def phase_record(diagram) -> dict:
    return {
        "body": diagram.body, "dims": [float(Fraction(d)) for d in diagram.dims], "dims_exact": list(diagram.dims),
        "sweep": [{"density": s, "stable": labels} for s, labels in zip(diagram.densities, diagram.stable)],
        "thresholds": [{"density": t.density, "error": t.bracket, "position": t.label, "change": t.change,
                        "note": t.note, "source": t.source} for t in diagram.thresholds],
        "source_thresholds_not_found": diagram.unmatched_sources,
        "duality_holds": diagram.duality_ok,
        "thresholds_without_dual": [{"density": t.density, "error": t.bracket, "position": t.label,
                                     "change": t.change} for t in diagram.unpaired],
        "seconds": diagram.seconds,
    }


def phase_json(diagram) -> str:
    return json.dumps(phase_record(diagram), indent=2)


def _sources(entries) -> str:
    """The places that print a threshold, cited together where they give the same value by the same closed form
    (``Scheeffer 1902 IV, (79), VI.D, (123), (132a): 1/2 − √3/6 = 0.2113248654052``)."""
    from ..numbers import signs             # the table's words only: a phase record is made without them
    from .citations import cited
    forms: dict[tuple, list] = {}
    for k in entries:
        forms.setdefault((k["expression"], f"{k['value']:.13f}"), []).append(k)
    return "; ".join(cited(same) + (f": {signs(expression)} = {value}" if expression else f": {value}")
                     for (expression, value), same in forms.items())


def phase_table(diagram) -> str:
    from ..numbers import signs
    from .citations import cited
    lines = [f"{diagram.body} ({','.join(diagram.dims)}): stable positions against density "
             f"({len(diagram.densities)} densities, {diagram.seconds:.1f} s)", ""]
    previous = None
    for s, labels in zip(diagram.densities, diagram.stable):
        if labels != previous:
            lines.append(f"  from s = {s:.4f}: {'; '.join(labels)}")
            previous = labels
    lines += ["", "thresholds (bisection with tracking; ± = error bound):"]
    for t in diagram.thresholds:
        src = _sources(t.source) or "no source prints this threshold"
        note = f" ({t.note})" if t.note else ""
        lines.append(f"  s = {t.density:.13f} ± {t.bracket:.0e}  {t.label}: {t.change}{note}  [{src}]")
    for k in diagram.unmatched_sources:
        lines.append(f"  DISAGREEMENT: {cited([k])} puts a threshold at s = "
                     f"{k['value']:.13f} ({k['label']}: {k['change']}); the solver finds none there: "
                     f"{signs(k['why'])}")
    lines.append("")
    for t in diagram.unpaired:
        lines.append(f"  NO DUAL: s = {t.density:.13f} ({t.label}: {t.change}) has no threshold at 1 − s")
    lines.append("duality s ↔ 1 − s: " + ("holds on the sweep and threshold by threshold" if diagram.duality_ok
                                            else "VIOLATED"))
    return "\n".join(lines)


def phase_plot(diagram, path) -> None:
    """``symfloat phase --plot``: :func:`phase_figure` of the diagram, as PNG."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from .phase_figure import phase_figure

    fig = phase_figure(phase_record(diagram))
    fig.savefig(path, dpi=110, metadata={"Software": None})
    plt.close(fig)
