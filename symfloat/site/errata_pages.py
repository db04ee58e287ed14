"""The errata as pages: one per erratum, and one list per facet (apparatus, source, kind, confidence).

The errata are kept in two apparatus (:data:`symfloat.model.erratum.APPARATUS`): the faults of the
original and the corrections of the transcription, marked, counted and listed apart.  An erratum's
page shows the printed (for the transcription's: the transcribed) excerpt and the correction with
its change marked (:mod:`.difference`), the reason in one sentence, kind and confidence, then the
evidence and links to the passage in the annotated edition and to the derivation's notebook section.
"""
from __future__ import annotations

import html

from ..model.erratum import APPARATUS, apparatus
from ..model.source import SOURCES
from ..model.myst import inline
from .edition import (badge, correction_html, evidence_words, formula_anchor, notebook_anchor, quotes, reason_of,
                      witness_line)
from .records import Records, slug
from .text import excerpt_html, prose_html

__all__ = ["erratum_page", "erratum_title", "facet_pages", "errata_index", "FACETS"]

FACETS = ("apparatus", "source", "kind", "confidence")
_APPARATUS_WORDS = {a: title for a, (title, _) in APPARATUS.items()}


def _apparatus(e: dict) -> str:
    return e.get("apparatus") or apparatus(e["kind"])


def erratum_page(e: dict, records: Records) -> str:
    """The MyST page of erratum *e*: the printed (or transcribed) and the corrected form, its change marked,
    the reason in one sentence, kind and confidence, then the evidence."""
    f = records.formula(e["formula"])
    text = SOURCES[e["source"]].text()
    [(a, b, _)] = quotes(text, [f])                # the excerpt widened to whole math spans
    cell = records.cells.get(e["formula"])
    source = SOURCES[e["source"]]
    links = [f'<a href="../edition/{e["source"]}.html#{formula_anchor(e["formula"])}">the passage in the '
             f'annotated edition</a>']
    if cell and e["derivation"] in records.notebooks:
        links.append(f'<a href="../notebooks/{e["derivation"]}.html#{notebook_anchor(e["derivation"], cell.cell)}">the '
                     f'derivation step by step</a>')
    mark = "transcription" if _apparatus(e) == "transcription" else "fault"
    body = [
        f'<p class="facts">{badge(mark)} {html.escape(source.author)}, <em>{html.escape(source.title)}</em>, '
        f'{html.escape(e["locator"])} · <a href="../errata-kinds.html">how the kind is decided</a></p>',
        correction_html(e, excerpt_html(text[a:b])),
        '<h2>Evidence</h2>', f'<p class="evidence">{prose_html(e["evidence"])}</p>',
        *([f'<h2>The strongest objection</h2><p class="objection">{prose_html(e["objection"])}</p>',
           f'<p class="answer"><strong>Answer.</strong> {prose_html(e["answer"])}</p>'] if e.get("objection") else []),
        f'<p>The verdict: {evidence_words(f, mark)}. Witnesses: '
        f'{html.escape(witness_line(f["numeric"]))}.</p>',
        f'<p>See {" and ".join(links)}.</p>',
    ]
    return "\n".join([f"# {erratum_title(e, records)}", "", "````{raw} html", *body, "````", ""])


def erratum_title(e: dict, records: Records) -> str:
    """The title of erratum *e*'s page: its apparatus, source and place, and where several errata of one
    apparatus sit at one place (Euler §223: three corrections of the transcription), which of them it is,
    so that a search's hits and a browser's tabs tell them apart."""
    apparatus = _apparatus(e)
    what = "Correction of the transcription" if apparatus == "transcription" else "Fault of the original"
    title = f"{what}: {SOURCES[e['source']].short}, {e['locator']}"
    same = [x["id"] for x in records.errata
            if (x["source"], x["locator"], _apparatus(x)) == (e["source"], e["locator"], apparatus)]
    return title if len(same) == 1 else f"{title} ({same.index(e['id']) + 1} of {len(same)})"


def _facet_values(records: Records, facet: str) -> list[str]:
    order = {"apparatus": list(APPARATUS), "source": list(SOURCES),
             "kind": ["misprint", "calculation", "consequential", "claim", "transcription"],
             "confidence": ["high", "medium", "low"]}[facet]
    present = {_value(e, facet) for e in records.errata}
    return [v for v in order if v in present] + sorted(present - set(order))


def _value(e: dict, facet: str) -> str:
    return _apparatus(e) if facet == "apparatus" else e[facet]


def _label(facet: str, value: str) -> str:
    """A facet's value in words: an apparatus by its name, a source by its short name and year (Scheeffer 1902),
    a kind or a confidence as it is."""
    if facet == "apparatus":
        return _APPARATUS_WORDS[value]
    if facet == "source" and value in SOURCES:
        return SOURCES[value].dated
    return value


def _line(e: dict) -> str:
    return (f"- [{SOURCES[e['source']].short}, {e['locator']}]({slug(e['id'])}.md) — {e['kind']}, {e['confidence']} "
            f"confidence: {inline(reason_of(e).rstrip('.'))}")


def facet_pages(records: Records) -> dict[str, str]:
    """File name -> MyST page, one per value of each facet."""
    pages = {}
    for facet in FACETS:
        for value in _facet_values(records, facet):
            chosen = [e for e in records.errata if _value(e, facet) == value]
            pages[f"{facet}-{slug(value)}.md"] = "\n".join(
                [f"# Errata: {_label(facet, value)}" if facet in ("apparatus", "source") else
                 f"# Errata: {facet} {value}", "",
                 f"{len(chosen)} of {len(records.errata)} errata.", "", *(_line(e) for e in chosen), ""])
    return pages


def errata_index(records: Records) -> str:
    """The errata's front page: the two apparatus, the facets with their counts, then every erratum, the
    faults of the original first."""
    out = ["# Errata", "", f"{len(records.errata)} errata in two apparatus, as an edition keeps them: the faults of the "
           "original print, and the corrections of this project's transcription of the scan (with what the "
           "original very probably printed). Each has the printed excerpt, the correction, its kind, confidence and "
           "evidence; [how the kind is decided](../errata-kinds.md). By facet:", ""]
    for facet in FACETS:
        values = _facet_values(records, facet)
        counts = {v: sum(_value(e, facet) == v for e in records.errata) for v in values}
        out.append(f"- {facet}: " + ", ".join(f"[{_label(facet, v)}]({facet}-{slug(v)}.md) ({counts[v]})"
                                              for v in values))
    for key, (title, _) in APPARATUS.items():
        chosen = [e for e in records.errata if _apparatus(e) == key]
        if chosen:
            out += ["", f"## {title[0].upper() + title[1:]} ({len(chosen)})", "", *(_line(e) for e in chosen)]
    out += ["", "```{toctree}", ":hidden:", "", *(f"{facet}-{slug(v)}" for facet in FACETS
                                                  for v in _facet_values(records, facet)),
            *(slug(e["id"]) for e in records.errata), "```", ""]
    return "\n".join(out)
