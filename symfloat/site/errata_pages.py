"""The errata as pages: one per erratum, and one list per facet (source, kind, confidence).

An erratum's page shows the printed excerpt and the correction rendered, kind, confidence, the
evidence, and links to the passage in the annotated edition and to the derivation's notebook
section.  A correction is mathematics unless it is written in words (then it is prose, its
dollars rendered as in the transcriptions).
"""
from __future__ import annotations

import html
import re

from ..model.source import SOURCES
from .edition import formula_anchor, notebook_anchor, quotes, witness_line
from .typeset import typeset
from .records import Records, slug
from .text import excerpt_html

__all__ = ["erratum_page", "facet_pages", "errata_index", "corrected_html", "FACETS"]

FACETS = ("source", "kind", "confidence")
_WORDS = re.compile(r"[A-Za-zäöüß]{3,}[ ,]+[A-Za-zäöüß]{3,}")


def corrected_html(corrected: str) -> str:
    """A correction: words (with their dollars) as prose, a formula typeset as a display.

    >>> corrected_html("x = 2,44")[:31]
    '<div class="math-display"><math'
    """
    if "$" in corrected or (_WORDS.search(re.sub(r"\\[A-Za-z]+(\{[^}]*\})?", " ", corrected))
                            and "\\" not in corrected):
        return excerpt_html(corrected)
    return f'<div class="math-display">{typeset(corrected, display=True)}</div>'


def erratum_page(e: dict, records: Records) -> str:
    """The MyST page of erratum *e*."""
    f = records.formula(e["formula"])
    text = SOURCES[e["source"]].text()
    [(a, b, _)] = quotes(text, [f])                # the excerpt widened to whole math spans
    cell = records.cells.get(e["formula"])
    source = SOURCES[e["source"]]
    links = [f'<a href="../edition/{e["source"]}.html#{formula_anchor(e["formula"])}">the passage in the '
             f'annotated edition</a>']
    if cell and e["derivation"] in records.notebooks:
        links.append(f'<a href="../notebooks/{e["derivation"]}.html#{notebook_anchor(e["derivation"], cell.cell)}">the '
                     f'derivation\'s notebook section</a>')
    body = [
        f'<p class="facts"><span class="badge k-{e["kind"]}">{e["kind"]}</span> '
        f'<span class="badge c-{e["confidence"]}">{e["confidence"]} confidence</span> '
        f'{html.escape(source.author)}, {html.escape(e["locator"])} · derivation <code>{e["derivation"]}</code> · '
        f'formula <code>{html.escape(e["formula"])}</code></p>',
        '<h2>Printed</h2>', f'<div class="printed">{excerpt_html(text[a:b])}</div>',
        '<h2>Corrected</h2>', f'<div class="corrected">{corrected_html(e["corrected"])}</div>',
        '<h2>Evidence</h2>', f'<p class="evidence">{html.escape(e["evidence"])}</p>',
        f'<p>Verdict of the printed formula: {f["verdict"]} (evidence: {f["evidence"]}). Witnesses: '
        f'{html.escape(witness_line(f["numeric"]))}.</p>',
        f'<p>See {" and ".join(links)}.</p>',
    ]
    return "\n".join([f"# Erratum {e['id']}", "", "````{raw} html", *body, "````", ""])


def _facet_values(records: Records, facet: str) -> list[str]:
    order = {"source": list(SOURCES), "kind": ["transcription", "misprint", "calculation", "consequential", "claim"],
             "confidence": ["high", "medium", "low"]}[facet]
    present = {e[facet] for e in records.errata}
    return [v for v in order if v in present] + sorted(present - set(order))


def _line(e: dict) -> str:
    first = e["evidence"].split(". ")[0].rstrip(".")
    first = first if len(first) <= 160 else first[:159] + "…"
    return (f"- [{e['source']} {e['locator']}]({slug(e['id'])}.md) — {e['kind']}, {e['confidence']} confidence: "
            f"{_plain(first)}")


def _plain(text: str) -> str:
    """Prose for a MyST list line: Markdown's special characters escaped."""
    return re.sub(r"([\\`*_{}\[\]<>#|$])", r"\\\1", text)


def facet_pages(records: Records) -> dict[str, str]:
    """File name -> MyST page, one per value of each facet."""
    pages = {}
    for facet in FACETS:
        for value in _facet_values(records, facet):
            chosen = [e for e in records.errata if e[facet] == value]
            pages[f"{facet}-{slug(value)}.md"] = "\n".join(
                [f"# Errata: {facet} {value}", "", f"{len(chosen)} of {len(records.errata)} errata.", "",
                 *(_line(e) for e in chosen), ""])
    return pages


def errata_index(records: Records) -> str:
    """The errata's front page: the facets with their counts, then every erratum."""
    out = ["# Errata", "", f"{len(records.errata)} errata, each with the printed excerpt, the correction, its kind, "
           "confidence and evidence. By facet:", ""]
    for facet in FACETS:
        values = _facet_values(records, facet)
        counts = {v: sum(e[facet] == v for e in records.errata) for v in values}
        out.append(f"- {facet}: " + ", ".join(f"[{v}]({facet}-{slug(v)}.md) ({counts[v]})" for v in values))
    out += ["", "## Every erratum", "", *(_line(e) for e in records.errata), "",
            "```{toctree}", ":hidden:", "", *(f"{facet}-{slug(v)}" for facet in FACETS
                                               for v in _facet_values(records, facet)),
            *(slug(e["id"]) for e in records.errata), "```", ""]
    return "\n".join(out)
