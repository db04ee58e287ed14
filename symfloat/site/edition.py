"""The annotated edition: a source's transcription with every quoted span marked by its verdict.

A printed formula's excerpt is found where the coverage ledger finds it (its first occurrence in
the transcription; a mark that would begin or end inside a math span takes the whole span).  A fault
printed in several places (an erratum with ``places``) is marked at every occurrence of its words, each
mark linking to the one note of its erratum (:func:`places`).  The
ledger (:func:`symfloat.report.ledger.account`, given these quotes) says how every other math span
and quantitative sentence is accounted for: waived with its reason (lost text and figures among
them) or not yet accounted for.  A mark (:data:`MARKS`) carries a sign, words and a shade; an
erratum's mark says its apparatus (a fault of the original, or a correction of the transcription).
Each quoted stretch links to its note below the paragraph: for an erratum the printed and the
corrected form with the change marked, the reason in one sentence, kind and confidence; then the
evidence, the reading, the witnesses and the links on demand.  The page opens with the work's
bibliographic record and the transcription's provenance (:func:`citation_html`), and a contents
list of the places a reader cites, each with an anchor (:func:`anchors`).
"""
from __future__ import annotations

import html
import re
from collections import Counter

from ..registry import statements
from ..model.erratum import apparatus
from ..model.source import Source
from ..model.span import math_intervals, widened
from ..numbers import counted, duration, method_words
from ..report.labels import sections
from ..report.ledger import REASONS, account, waivers
from ..report.witness_words import error_cells
from .difference import corrected_html
from .records import Records, slug
from .text import excerpt_html, prose_html, render
from .typeset import typeset

__all__ = ["MARKS", "EVIDENCE_WORDS", "evidence_words", "mark_of", "badge", "quotes", "edition_page", "note",
           "formula_anchor",
           "cell_label", "notebook_anchor", "witness_line", "reason_of", "correction_html", "anchors", "citation_html",
           "fault_words", "places", "permalink"]

# The marks of the edition, gravest first (a stretch quoted twice shows the first): mark -> (sign, words).
# An erratum is a fault of the original or a correction of the transcription (docs/errata-kinds.md).
MARKS = {"fault": ("✗", "fault of the original"), "transcription": ("✎", "transcription corrected"),
         "unverifiable": ("?", "not decided"), "verified": ("✓", "verified"),
         "trivial": ("=", "nothing to check: the print states its own definition")}
EVIDENCE_WORDS = {"symbolic": "proved symbolically", "sampled": "checked exactly at sampled rational points",
             "numeric": "checked numerically", None: "no evidence could be obtained"}
# A reading longer than this in TeX (a statement the derivation reads in coordinates or case by case, thousands of
# characters) is not set in the note, which would grow by hundreds of kilobytes (KaTeX's markup is about 60 times
# its TeX) for a display pages wide: the notebook, linked from the note, shows it in full.
_LONGEST_READING = 2000
_WAIVED = {"bare-symbol": "a lone symbol or label", "repeat": "repeats a checked formula",
           "figure-reference": "refers to a figure", "lost-text": "text lost in the transcription",
           "notation": "a naming or a construction"}


def mark_of(f: dict, records: Records) -> str:
    """The mark of formula *f*: its verdict, an erratum told by its apparatus."""
    if f["verdict"] != "erratum":
        return f["verdict"]
    e = records.erratum_of.get(f["id"])
    return "transcription" if e and apparatus(e["kind"]) == "transcription" else "fault"


def badge(mark: str) -> str:
    sign, words = MARKS[mark]
    return f'<span class="badge v-{mark}"><span class="sign" aria-hidden="true">{sign}</span> {words}</span>'


def permalink(anchor: str, label: str) -> str:
    """A link to *anchor* on its own page, to copy and cite (as the DLMF gives each equation a permalink)."""
    return (f'<a class="permalink" href="#{anchor}" title="a permanent link to {html.escape(label)} on this page: '
            f'copy it to cite the place">¶</a>')


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
        out.append((*widened(at, at + len(f["printed"]), maths), f["id"]))
    return out


def fault_words(f: dict, records: Records) -> str:
    """The words of formula *f*'s fault where its erratum lists other places (``places``): the erratum's
    ``fault``, else the whole excerpt, as the derivation declares it; "" for a fault printed once."""
    erratum = records.erratum_of.get(f["id"])
    if not erratum or not erratum.get("places"):
        return ""
    derivation, name = f["id"].split("/", 1)
    declared = next(p for p in statements(derivation).printed if p.name == name).erratum
    return declared.fault or f["printed"]


def places(text: str, fault: str, quote: tuple[int, int]) -> list[tuple[int, int]]:
    """``(start, end)`` of every other place of a repeated fault: each occurrence of its words *fault* in
    *text* outside its quote's stretch *quote*, widened to whole math spans; none for a fault printed once
    (its words "")."""
    if not fault:
        return []
    maths = math_intervals(text)
    return [widened(m.start(), m.end(), maths) for m in re.finditer(re.escape(fault), text)
            if not quote[0] <= m.start() < quote[1]]


def evidence_words(f: dict, mark: str) -> str:
    """What the verdict on formula *f* rests on, in words; for an erratum (*mark* ``fault`` or ``transcription``)
    that the print (or the transcription) is refuted and how its correction holds: its record's evidence is that
    of the correction."""
    how = EVIDENCE_WORDS.get(f["evidence"], f["evidence"])
    if mark in ("fault", "transcription") and f["evidence"] is not None:
        return f"the {'print' if mark == 'fault' else 'transcription'} refuted, its correction {how}"
    return how


def witness_line(numeric) -> str:
    """The witnesses in one line: method, cases, absolute and relative error, seconds."""
    return "; ".join(f"{method_words(n['method'])} ({counted(n.get('cases', '?'), 'case')}): abs {error_cells(n)[0]}, "
                     f"rel {error_cells(n)[1]}, {duration(n['seconds'])}" for n in numeric) or "no numeric witness"


def _title(f: dict, records: Records) -> str:
    erratum = records.erratum_of.get(f["id"])
    mark = mark_of(f, records)
    head = f"{f['locator']} · {MARKS[mark][0]} {MARKS[mark][1]}"
    if erratum:
        head += f" ({erratum['kind']}, {erratum['confidence']} confidence)"
    parts = [head, evidence_words(f, mark)]
    if erratum and "$" not in reason_of(erratum):       # a tooltip cannot typeset maths: left to the note
        parts.append(reason_of(erratum))
    if f.get("reason"):
        parts.append(f["reason"])
    return " — ".join(parts)


_SENTENCE_END = re.compile(r"(?<=[a-z0-9)\]}'$])(?<!i\.e)(?<!e\.g)\. (?=[A-Z(])")


_QUOTATION = re.compile(r"(?<!\w)'[^']+'(?!\w)|‘[^’]+’|“[^”]+”|„[^“”]+[“”]")


def reason_of(erratum: dict) -> str:
    """The erratum's reason in one sentence: the first of its evidence, a full stop inside a quotation not ending
    it (Scheeffer's 'wenn sein spec. Gewicht s > 0,7887 …')."""
    text = erratum["evidence"]
    words = re.sub(r"\$[^$]*\$", lambda m: " " * len(m[0]), text)      # a minute mark 22' in math quotes nothing
    quotations = [m.span() for m in _QUOTATION.finditer(words)]
    end = next((m.start() for m in _SENTENCE_END.finditer(text)
                if not any(a < m.start() < b for a, b in quotations)), len(text))
    return text[:end].rstrip(".") + "."


def correction_html(erratum: dict, printed_html: str) -> str:
    """The printed (or transcribed) form beside the corrected one, its change marked; kind, confidence and
    the reason in one sentence."""
    scan = apparatus(erratum["kind"]) == "transcription"
    shown, right = ("The transcription reads", "The original very probably printed") if scan else \
        ("Printed", "Corrected")
    return (f'<div class="correction"><p class="reason"><strong>{erratum["kind"]}, {erratum["confidence"]} '
            f'confidence.</strong> {prose_html(reason_of(erratum))}</p>'
            f'<div class="printed"><span class="label">{shown}</span>{printed_html}</div>'
            f'<div class="corrected"><span class="label">{right}</span>'
            f'{corrected_html(erratum["corrected"], replaced(erratum))}</div></div>')


def replaced(erratum: dict) -> str:
    """What the correction of *erratum* replaces, for marking its change: its declared fault where the correction
    keeps every word of it in order (a part of a sentence rewritten: Scheeffer (51)'s 'folglich das Gleichgewicht
    stabil', whose correction reuses words from elsewhere in the sentence), else the whole printed excerpt."""
    printed = erratum["printed"].strip()
    declared = next((p.erratum for p in statements(erratum["derivation"]).printed
                     if f'{erratum["derivation"]}/{p.name}' == erratum["formula"]), None)
    fault = declared.fault if declared is not None else ""
    words = re.findall(r"\w+", fault)
    kept = iter(re.findall(r"\w+", erratum["corrected"]))
    return fault if fault in printed and words and all(w in kept for w in words) else printed


def _witness_table(numeric) -> str:
    if not numeric:
        return "<p>No numeric witness.</p>"
    rows = "".join(f"<tr><td>{html.escape(method_words(n['method']))}</td><td>{n.get('cases', '')}</td>"
                   f"<td>{html.escape(error_cells(n)[0])}</td><td>{html.escape(error_cells(n)[1])}</td>"
                   f"<td>{duration(n['seconds'])}</td></tr>"
                   for n in numeric)
    return ('<table class="witnesses"><tr><th>witness method</th><th>cases</th><th>abs. error</th>'
            f"<th>rel. error</th><th>time</th></tr>{rows}</table>")


def note(f: dict, records: Records, root: str, printed_html: str = "") -> str:
    """A formula's note (``<details>``): its mark and locator; for an erratum the printed and the corrected
    form, the reason, kind and confidence; then the evidence on demand: how it was checked, the reading,
    the witnesses and the links.  *root* is the relative path from the page to the site's root;
    *printed_html* the printed excerpt as rendered."""
    erratum = records.erratum_of.get(f["id"])
    cell = records.cells.get(f["id"])
    mark = mark_of(f, records)
    lines = [f'<details class="note v-{mark}" id="{formula_anchor(f["id"])}">',
             f'<summary>{badge(mark)} {html.escape(f["locator"])} {permalink(formula_anchor(f["id"]), f["locator"])}'
             '</summary>']
    if erratum:
        lines.append(correction_html(erratum, printed_html))
    if f.get("reason"):
        lines.append(f'<p>{prose_html(f["reason"])}</p>')
    how = evidence_words(f, mark)
    lines += ['<details class="evidence"><summary>Evidence</summary>',
              f"<p>{how[0].upper() + how[1:]}." + (f' {prose_html(erratum["evidence"])}' if erratum else "") + "</p>"]
    if cell and cell.reading and len(cell.reading) <= _LONGEST_READING:
        lines.append(f'<p>Read as printed:</p><div class="reading">'
                     f'{typeset(cell.reading, display=True)}</div>')
    elif cell and cell.reading:
        lines.append("<p>Read as printed: a formula too long to set in a note; the derivation's notebook shows "
                     "it.</p>")
    lines.append(_witness_table(f["numeric"]))
    links = []
    if erratum:
        links.append(f'<a href="{root}errata/{slug(erratum["id"])}.html">the erratum\'s page</a>')
    if cell and f["derivation"] in records.notebooks:
        links.append(f'<a href="{root}notebooks/{f["derivation"]}.html#{notebook_anchor(f["derivation"], cell.cell)}">'
                     f'the derivation step by step</a>')
    if links:
        lines.append(f'<p>See {" and ".join(links)}.</p>')
    lines += ["</details>", "</details>"]
    return "\n".join(lines)


def _legend(counts: Counter, waived: Counter, unaccounted: int, root: str) -> str:
    items = [f'<span class="q v-{m}">{MARKS[m][0]} {MARKS[m][1]}</span> {counts[m]}' for m in MARKS if counts[m]]
    items += [f'<span class="w w-{r}" title="{html.escape(REASONS[r])}">{_WAIVED.get(r, r)}</span> {n}'
              for r, n in sorted(waived.items())]
    if unaccounted:
        items.append(f'<span class="w w-unaccounted">not yet accounted for</span> {unaccounted}')
    items.append('<span class="figure-missing">Fig.</span> a figure the transcription does not have')
    return ('<p class="legend">' + " · ".join(items) + f' · <a href="{root}errata-kinds.html">how an erratum\'s '
            'kind is decided</a></p>')


_EQUATION = re.compile(r"\\q?quad\s*\((\d{1,3})\s?([a-z]?)\)")
_EXAMPLES = re.compile(r"Zahlenbeispiel")
_EXAMPLE = re.compile(r"(\d{1,2})\.\s")


def anchors(source: Source) -> dict[int, list[tuple[str, str]]]:
    """Offset -> ``(id, label)`` of the places of *source* a reader cites: sections (§ paragraphs),
    equation numbers, worked examples; each id once, at its first place."""
    text = source.text()
    found: dict[int, list[tuple[str, str]]] = {}
    seen = set()

    def put(at, anchor, label):
        if anchor not in seen:
            seen.add(anchor)
            found.setdefault(at, []).append((anchor, label))

    starts = sections(source.key)[1:]
    for at, name in starts:
        put(at, f"s-{slug(name)}", ("§" if name.isdigit() else "") + name)
    for m in _EQUATION.finditer(text):
        put(m.start(), f"eq-{m.group(1)}{m.group(2)}", f"({m.group(1)}{m.group(2)})")
    examples = False
    for m in re.finditer(r"(?m)^.*$", text):
        line = m.group(0)
        if _EXAMPLES.match(line):
            examples = True
        elif any(at == m.start() for at, _ in starts):
            examples = False
        elif examples and _EXAMPLE.match(line):
            put(m.start(), f"example-{_EXAMPLE.match(line).group(1)}", f"Example {_EXAMPLE.match(line).group(1)}")
    return found


def citation_html(source: Source) -> str:
    """The bibliographic record of *source* and the transcription's provenance."""
    fields = dict(source.citation)
    parts = [html.escape(source.author), f"<em>{html.escape(source.title)}</em>"]
    if fields.get("series"):
        parts.append(html.escape(fields["series"]))
    imprint = ", ".join(html.escape(x) for x in (fields.get("place"), fields.get("publisher")) if x)
    parts.append(" ".join(x for x in (imprint, str(source.year) if source.year else "n.d.") if x))
    # the parts each end with a full stop: one of their own (n.d.) or one added
    record = "".join(part + ("" if part.endswith(".") else ".") + " " for part in parts).rstrip()
    extra = [html.escape(fields[k]) for k in ("number", "edition") if fields.get(k)]
    if extra:
        record += " " + "; ".join(extra) + "."
    if fields.get("note"):
        record += " " + html.escape(fields["note"][0].upper() + fields["note"][1:]) + "."
    return (f'<div class="bibliography"><p><strong>The work.</strong> {record} In {html.escape(source.language)}.</p>'
            f'<p><strong>The transcription.</strong> {html.escape(source.provenance[:1].upper() + source.provenance[1:])}'
            f'{"." if source.provenance else ""} Places are cited as {html.escape(source.locators or "printed")}; '
            "each has an anchor on this page (the page's address with #s-224 for a section or paragraph, "
            "#eq-78c for an equation number, #example-3 for a worked example).</p></div>")


def _contents(found: dict[int, list[tuple[str, str]]]) -> str:
    flat = [x for at in sorted(found) for x in found[at]]
    groups = [("Sections", [x for x in flat if x[0].startswith("s-")]),
              ("Equations", [x for x in flat if x[0].startswith("eq-")]),
              ("Worked examples", [x for x in flat if x[0].startswith("example-")])]
    out = []
    for title, items in groups:
        if items:
            links = " ".join(f'<a href="#{i}">{html.escape(label)}</a>' for i, label in items)
            out.append(f"<details{' open' if title == 'Sections' else ''}><summary>{title} ({len(items)})</summary>"
                       f"<p>{links}</p></details>")
    # a text without numbered places has no contents: no empty box above the legend
    return "\n".join(['<nav class="contents" aria-label="contents">', *out, "</nav>"]) if out else ""


def edition_page(source: Source, records: Records) -> str:
    """The MyST page of *source*: heading, legend and the marked transcription (raw HTML)."""
    text = source.text()
    formulas = [f for f in records.formulas if f["source"] == source.key]
    quoted = quotes(text, formulas)
    entries = account(source.key, quoted, waivers(source.key))
    ledger_marks = [e for e in entries if e.status != "quoted"
                    and (e.span.kind != "sentence" or e.reason in ("lost-text", "figure-reference"))]
    cuts = {x for a, b, _ in quoted for x in (a, b)} | {x for e in ledger_marks for x in (e.span.start, e.span.end)}
    rank = {v: i for i, v in enumerate(MARKS)}
    mark = {f["id"]: mark_of(f, records) for f in formulas}
    ends = {fid: e for _, e, fid in quoted}
    again = [(s, e, fid) for a, b, fid in quoted for s, e in places(text, fault_words(records.formula(fid), records),
                                                                     (a, b))]
    cuts |= {x for s, e, _ in again for x in (s, e)}

    def wrap(a, b, body):
        fids = sorted((fid for s, e, fid in quoted if s < b and a < e),
                      key=lambda fid: rank[mark[fid]])
        if fids:
            title = "\n".join(_title(records.formula(fid), records) for fid in fids)
            more = "".join(f'<a class="more v-{mark[fid]}" href="#{formula_anchor(fid)}" '
                           f'title="{html.escape(_title(records.formula(fid), records))}">'
                           f'{i}</a>' for i, fid in enumerate(fids[1:], 2) if ends[fid] == b)
            sign = (f'<span class="sign" aria-hidden="true">{MARKS[mark[fids[0]]][0]}</span>'
                    f'<span class="visually-hidden"> ({MARKS[mark[fids[0]]][1]})</span>' if ends[fids[0]] == b else "")
            return (f'<a class="q v-{mark[fids[0]]}" href="#{formula_anchor(fids[0])}" '
                    f'title="{html.escape(title)}">{body}{sign}</a>' + (f'<sup class="more">{more}</sup>' if more else ""))
        repeated = [(e, fid) for s, e, fid in again if s < b and a < e]
        if repeated:                    # another place of a repeated fault: the same mark, the one erratum
            end, fid = repeated[0]
            sign = (f'<span class="sign" aria-hidden="true">{MARKS[mark[fid]][0]}</span>'
                    f'<span class="visually-hidden"> ({MARKS[mark[fid]][1]}, printed here too)</span>'
                    if end == b else "")
            title = "The same fault printed here too. " + _title(records.formula(fid), records)
            return (f'<a class="q again v-{mark[fid]}" href="#{formula_anchor(fid)}" '
                    f'title="{html.escape(title)}">{body}{sign}</a>')
        inner = [e for e in ledger_marks if e.span.start < b and a < e.span.end]
        if not inner:
            return body
        e = min(inner, key=lambda e: e.span.end - e.span.start)          # the math span inside a sentence
        reason = e.reason or "unaccounted"
        title = f"{_WAIVED.get(e.reason, e.reason)} — {e.note or REASONS[e.reason]}" if e.reason else \
            "not yet accounted for by any derivation (docs/coverage-baseline.json)"
        return f'<span class="w w-{reason}" title="{html.escape(title)}">{body}</span>'

    starts = sorted((a, fid) for a, _, fid in quoted)
    placed: set[str] = set()

    def after(a, b):                    # the notes of the quotes that start before this block ends
        due = [fid for s, fid in starts if s < b and fid not in placed]
        placed.update(due)
        return "\n".join(note(records.formula(fid), records, "../", printed.get(fid, "")) for fid in due)

    printed = {fid: excerpt_html(text[a:b]) for a, b, fid in quoted if fid in records.erratum_of}
    found = anchors(source)
    pending = sorted(found)

    def ids(a, b):                      # the anchors up to this block's end (a skipped block's go to the next)
        due = [at for at in pending if at < b]
        del pending[:len(due)]
        return [i for at in due for i, _ in found[at]]

    body = render(text, cuts, wrap, after, ids) + after(len(text), len(text) + 1)
    counts = Counter(mark.values())
    waived = Counter(e.reason for e in entries if e.status == "waived")
    unaccounted = sum(e.status == "unaccounted" for e in entries)
    year = f", {source.year}" if source.year else ""
    head = [f"# {source.author}: {source.title}{year}", "",
            "````{raw} html", citation_html(source),
            "<p>The transcription as text, every printed formula that a derivation quotes marked by its verdict: "
            "a sign and a shade for each (the legend below). Rest the pointer on a mark for the verdict in one "
            "line, or follow it to the note below its paragraph: for an erratum the printed and the corrected "
            "form with the change marked, the reason, its kind and confidence, then the evidence on demand. "
            "Where two or more derivations read one printed formula, a small numbered mark after it, shaded by "
            "its verdict, leads to each further reading. Math spans and claims in words that no formula quotes "
            "are marked by how they are accounted for: waived with a reason, or not yet accounted for.</p>",
            _contents(found), _legend(counts, waived, unaccounted, "../"), '<div class="edition">',
            body.rstrip("\n"), "</div>", "````", ""]
    return "\n".join(head)
