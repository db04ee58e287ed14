"""The annotated edition: a source's transcription with every quoted span marked by its verdict.

A printed formula's excerpt is found where the coverage ledger finds it (its first occurrence in
the transcription; a mark that would begin or end inside a math span takes the whole span).  The
ledger (:func:`symfloat.report.ledger.account`, given these quotes) says how every other math span
and quantitative sentence is accounted for: waived with its reason (lost text and figures among
them) or not yet accounted for.  Each quoted stretch links to its note below the paragraph: the
formula's verdict, the reading, the evidence, the erratum and the witnesses' errors and times; its
``title`` says the same in one line for a pointer that rests on it.
"""
from __future__ import annotations

import html
from collections import Counter

from ..model.source import Source
from ..model.span import math_intervals
from ..report.ledger import REASONS, account, waivers
from .names import typeset_names
from .records import Records, slug
from .text import render
from .typeset import typeset

__all__ = ["VERDICTS", "quotes", "edition_page", "note", "formula_anchor", "cell_label", "notebook_anchor",
           "witness_line"]

VERDICTS = ("erratum", "unverifiable", "verified", "trivial")      # a stretch quoted twice shows the first


def formula_anchor(fid: str) -> str:
    """The id of a formula's note in the edition."""
    return "f-" + slug(fid)


def cell_label(derivation: str, cell: str) -> str:
    """The MyST target placed before a notebook cell's heading (labels are global: the notebook's
    name makes them unique)."""
    return f"{derivation}--{cell}"


def notebook_anchor(derivation: str, cell: str) -> str:
    """The HTML id Sphinx gives the target :func:`cell_label` of a notebook cell."""
    from docutils.nodes import make_id
    return make_id(cell_label(derivation, cell))


def quotes(text: str, formulas) -> list[tuple[int, int, str]]:
    """``(start, end, formula id)`` of each formula's excerpt in *text*, widened to whole math spans."""
    maths = math_intervals(text)
    out = []
    for f in formulas:
        at = text.find(f["printed"])
        if at < 0:
            raise ValueError(f"{f['id']}: the printed excerpt is not in the transcription")
        a, b = at, at + len(f["printed"])
        for s, e, _ in maths:
            if s < a < e:
                a = s
            if s < b < e:
                b = e
        out.append((a, b, f["id"]))
    return out


def witness_line(numeric) -> str:
    """The witnesses in one line: method, cases, absolute and relative error, seconds."""
    return "; ".join(f"{n['method']} ({n.get('cases', '?')} cases): abs {n['abs_error']:.1e}, "
                     f"rel {n['rel_error']:.1e}, {n['seconds']:.3g} s" for n in numeric) or "no numeric witness"


def _title(f: dict, erratum: dict | None) -> str:
    head = f"{f['locator']} · {f['verdict']}"
    if erratum:
        head += f" ({erratum['kind']}, {erratum['confidence']} confidence)"
    parts = [head, f"evidence: {f['evidence']}", f"witnesses: {witness_line(f['numeric'])}"]
    if f.get("reason"):
        parts.append(f["reason"])
    return " — ".join(parts)


def _witness_table(numeric) -> str:
    if not numeric:
        return "<p>No numeric witness.</p>"
    rows = "".join(f"<tr><td>{html.escape(n['method'])}</td><td>{n.get('cases', '')}</td>"
                   f"<td>{n['abs_error']:.1e}</td><td>{n['rel_error']:.1e}</td><td>{n['seconds']:.3g} s</td></tr>"
                   for n in numeric)
    return ('<table class="witnesses"><tr><th>witness method</th><th>cases</th><th>abs. error</th>'
            f"<th>rel. error</th><th>time</th></tr>{rows}</table>")


def note(f: dict, records: Records, root: str) -> str:
    """A formula's note (``<details>``): verdict, reading, evidence, erratum, witnesses, links.
    *root* is the relative path from the page to the site's root."""
    erratum = records.erratum_of.get(f["id"])
    cell = records.cells.get(f["id"])
    lines = [f'<details class="note v-{f["verdict"]}" id="{formula_anchor(f["id"])}">',
             f'<summary><span class="badge v-{f["verdict"]}">{f["verdict"]}</span> {html.escape(f["locator"])} '
             f'<code>{html.escape(f["id"])}</code></summary>',
             f'<p>Evidence: <strong>{f["evidence"]}</strong>'
             + (f' — {html.escape(f["reason"])}' if f.get("reason") else "") + "</p>"]
    if cell and cell.reading:
        lines.append(f'<p>Read as printed:</p><div class="reading">'
                     f'{typeset(typeset_names(f["derivation"], cell.reading), display=True)}</div>')
    if erratum:
        lines.append(f'<p>Erratum <a href="{root}errata/{slug(erratum["id"])}.html">{html.escape(erratum["id"])}</a>: '
                     f'{erratum["kind"]}, {erratum["confidence"]} confidence.</p>')
    lines.append(_witness_table(f["numeric"]))
    if cell and f["derivation"] in records.notebooks:
        lines.append(f'<p><a href="{root}notebooks/{f["derivation"]}.html#{notebook_anchor(f["derivation"], cell.cell)}">'
                     f'The derivation step by step</a> (notebook <code>{f["derivation"]}</code>).</p>')
    lines.append("</details>")
    return "\n".join(lines)


def _legend(counts: Counter, waived: Counter, unaccounted: int) -> str:
    items = [f'<span class="q v-{v}">{v}</span> {counts[v]}' for v in VERDICTS if counts[v]]
    items += [f'<span class="w w-{r}" title="{html.escape(REASONS[r])}">waived: {r}</span> {n}'
              for r, n in sorted(waived.items())]
    if unaccounted:
        items.append(f'<span class="w w-unaccounted">not yet accounted for</span> {unaccounted}')
    items.append('<span class="figure-missing">Fig.</span> a figure the transcription does not have')
    return '<p class="legend">' + " · ".join(items) + "</p>"


def edition_page(source: Source, records: Records) -> str:
    """The MyST page of *source*: heading, legend and the marked transcription (raw HTML)."""
    text = source.text()
    formulas = [f for f in records.formulas if f["source"] == source.key]
    quoted = quotes(text, formulas)
    entries = account(source.key, quoted, waivers(source.key))
    ledger_marks = [e for e in entries if e.status != "quoted"
                    and (e.span.kind != "sentence" or e.reason in ("lost-text", "figure-reference"))]
    cuts = {x for a, b, _ in quoted for x in (a, b)} | {x for e in ledger_marks for x in (e.span.start, e.span.end)}
    rank = {v: i for i, v in enumerate(VERDICTS)}
    ends = {fid: e for _, e, fid in quoted}

    def wrap(a, b, body):
        fids = sorted((fid for s, e, fid in quoted if s < b and a < e),
                      key=lambda fid: rank[records.formula(fid)["verdict"]])
        if fids:
            first = records.formula(fids[0])
            title = "\n".join(_title(records.formula(fid), records.erratum_of.get(fid)) for fid in fids)
            more = "".join(f'<a class="more v-{records.formula(fid)["verdict"]}" href="#{formula_anchor(fid)}" '
                           f'title="{html.escape(_title(records.formula(fid), records.erratum_of.get(fid)))}">'
                           f'{i}</a>' for i, fid in enumerate(fids[1:], 2) if ends[fid] == b)
            return (f'<a class="q v-{first["verdict"]}" href="#{formula_anchor(first["id"])}" '
                    f'title="{html.escape(title)}">{body}</a>' + (f'<sup class="more">{more}</sup>' if more else ""))
        inner = [e for e in ledger_marks if e.span.start < b and a < e.span.end]
        if not inner:
            return body
        e = min(inner, key=lambda e: e.span.end - e.span.start)          # the math span inside a sentence
        reason = e.reason or "unaccounted"
        title = f"waived: {e.reason} — {e.note or REASONS[e.reason]}" if e.reason else \
            "not yet accounted for by any derivation (docs/coverage-baseline.json)"
        return f'<span class="w w-{reason}" title="{html.escape(title)}">{body}</span>'

    starts = sorted((a, fid) for a, _, fid in quoted)
    placed: set[str] = set()

    def after(a, b):                    # the notes of the quotes that start before this block ends
        due = [fid for s, fid in starts if s < b and fid not in placed]
        placed.update(due)
        return "\n".join(note(records.formula(fid), records, "../") for fid in due)

    body = render(text, cuts, wrap, after) + after(len(text), len(text) + 1)
    counts = Counter(f["verdict"] for f in formulas)
    waived = Counter(e.reason for e in entries if e.status == "waived")
    unaccounted = sum(e.status == "unaccounted" for e in entries)
    year = f", {source.year}" if source.year else ""
    head = [f"# {source.author}: {source.title}{year}", "",
            f"The transcription of `{source.key}` ({source.language}) as text, every printed formula that a "
            f"derivation quotes marked by its verdict. Rest the pointer on a mark for the verdict in one line, "
            f"or follow it to the note below its paragraph: the reading as printed, the evidence, the erratum "
            f"and the independent witnesses' errors and times. Math spans and claims in words that no "
            f"formula quotes are marked as the coverage ledger accounts for them (lost text and figure "
            f"references among them). Locators: {source.locators or 'as printed'}.", "",
            "````{raw} html", _legend(counts, waived, unaccounted), '<div class="edition">', body.rstrip("\n"),
            "</div>", "````", ""]
    return "\n".join(head)
