"""What the derivation notebooks display: steps, printed formulas, witnesses.

The notebooks call these helpers on the derivation's report (from the cache
when the derivation is unchanged), so their outputs are the engine's results,
rendered as Markdown with LaTeX.
"""
from __future__ import annotations

from ..engine.runner import verify

__all__ = ["checked", "steps_markdown", "formula_markdown", "show"]

STATUS = {"proved": "proved", "sampled": "sampled (no symbolic proof)", "refuted": "**REFUTED**",
          "undecided": "undecided", "definition": "definition", "applied": "lemma applied"}


def checked(derivation_id: str):
    """The report of *derivation_id* (its ancestors are verified too)."""
    return next(r for r in verify(derivation_id) if r.id == derivation_id)


def _time(seconds: float) -> str:
    return f"{seconds * 1e3:.1f} ms" if seconds < 1 else f"{seconds:.2f} s"


def steps_markdown(report) -> str:
    lines = []
    for i, s in enumerate(report.steps, 1):
        uses = f"; uses {', '.join(s.uses)}" if s.uses else ""
        how = ""
        if s.identity:
            # which strategy ran out of time depends on the machine: name the outcome only
            how = f" — {s.identity['strategy'] or 'no symbolic proof within the time budget'}"
            if s.identity.get("counterexample"):
                how += f"; counterexample {s.identity['counterexample']}"
        lines.append(f"**{i}. {s.name}** ({s.why}{uses}): {STATUS[s.status]}{how}\n\n$$ {s.latex} $$")
        if s.note:
            lines.append(f"> {s.note}")
    return "\n\n".join(lines)


def _records(title, records) -> list[str]:
    """A title and one Markdown table (one block, rows joined by single newlines)."""
    if not records:
        return []
    rows = ["| method | cases | abs. error | rel. error | time |", "|---|---|---|---|---|"]
    for r in records:
        rows.append(f"| {r['method']} | {r.get('cases', 1)} | {r['abs_error']:.2e} | {r['rel_error']:.2e} "
                    f"| {_time(r['seconds'])} |")
    return [title, "\n".join(rows)]


def formula_markdown(report, name: str) -> str:
    f = next(f for f in report.formulas if f.id.endswith("/" + name))
    out = [f"**Verdict: {f.verdict}**" + (f" (evidence: {f.evidence})" if f.evidence else "")]
    if f.latex:
        out.append(f"SymPy reading of the print (SymPy may normalise its arithmetic): $$ {f.latex} $$")
    if f.reason:
        out.append(f"Reason: {f.reason}")
    if f.erratum:
        e = f.erratum
        out.append(f"Erratum ({e['kind']}, confidence {e['confidence']}): corrected "
                   f"$$ {e['corrected']} $$\n\n{e['evidence']}")
    out += _records("Witnesses against the printed formula:", f.numeric)
    out += _records("Witnesses against the correction:", f.corrected_numeric)
    out += [f"> {n}" for n in f.witness_notes]
    return "\n\n".join(out)


def show(markdown: str):
    """Display Markdown in a notebook (plain text elsewhere)."""
    try:
        from IPython.display import Markdown, display
    except ImportError:  # pragma: no cover - outside IPython
        print(markdown)
        return
    display(Markdown(markdown))
