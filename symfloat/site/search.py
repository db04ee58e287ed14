"""The site's search index holds the words of the pages, not their typeset formulas.

Sphinx indexes raw HTML by its text with the tags stripped, so the raw HTML that carries formulas typeset by
KaTeX (the editions' transcriptions, the errata's pages, a notebook's quotations) filled the index with runs
of glyphs and MathML letters, such as ``nghnghngh`` or ``y3y_3y3``; and it indexes a MyST formula by its TeX
(``frac``, ``varphi``).  This Sphinx extension leaves formulas out of the index and keeps the words: a raw
HTML block with KaTeX in it is indexed by its text with every formula cut out (:func:`words_of`), and a
formula node is not indexed.  What a page shows does not change.
"""
from __future__ import annotations

import html
import re

from docutils import nodes

__all__ = ["closing_span", "words_of", "setup"]

_FORMULA = re.compile(r'<span class="katex">|<code class="tex-unrendered"[^>]*>.*?</code>', re.S)
_SPAN = re.compile(r"<span\b|</span>")
_HIDDEN = re.compile(r"<(style|script)\b.*?</\1>", re.S | re.I)
_TAG = re.compile(r"<[^>]*>")


def closing_span(markup: str, start: int) -> re.Match:
    """The ``</span>`` that closes the span whose opening tag ends at *start* in *markup* (KaTeX nests spans
    deep); ValueError if none does."""
    depth = 1
    for tag in _SPAN.finditer(markup, start):
        depth += 1 if tag.group() == "<span" else -1
        if not depth:
            return tag
    raise ValueError(f"a span opened before {start} is not closed")


def words_of(markup: str) -> str:
    """The words of the HTML *markup*, every formula (KaTeX's ``katex`` span, a TeX shown as code) cut out and
    every tag a space: an element set apart by its style ends a word ("Corrected" above "with the same
    length" was indexed as "correctedwith").

    >>> words_of('<p>Der Schwerpunkt <span class="katex"><span class="katex-mathml">'
    ...          '<math><mi>S</mi></math></span><span>S</span></span> liegt &uuml;ber <b>B</b>.</p>'
    ...          '<span class="label">Corrected</span>with')
    'Der Schwerpunkt liegt über B . Corrected with'
    """
    out, pos = [], 0
    while match := _FORMULA.search(markup, pos):
        out.append(markup[pos:match.start()])
        pos = match.end()
        if match.group().startswith("<span"):         # to the end of the formula's outermost span
            pos = closing_span(markup, pos).end()
    out.append(markup[pos:])
    return " ".join(html.unescape(_TAG.sub(" ", _HIDDEN.sub("", "".join(out)))).split())


class unindexed(nodes.Element):
    """Its children, shown as they are and left out of the search index (Sphinx skips ``no-search``)."""


class indexed_words(nodes.TextElement):
    """Words for the search index alone: not shown."""


def _shown_as_children(self, node):
    pass


def _not_shown(self, node):
    raise nodes.SkipNode


def _formulas_left_out(app, doctree, docname):
    for node in [*doctree.findall(nodes.math), *doctree.findall(nodes.math_block)]:
        node["classes"].append("no-search")
    for raw in list(doctree.findall(nodes.raw)):
        if "html" in raw.get("format", "").split() and '<span class="katex">' in raw.astext():
            kept = unindexed(classes=["no-search"])
            raw.replace_self([kept, indexed_words("", words_of(raw.astext()))])
            kept += raw


def setup(app):
    """Register the two nodes and leave the formulas of every page out of the index before it is fed."""
    app.add_node(unindexed, html=(_shown_as_children, _shown_as_children))
    app.add_node(indexed_words, html=(_not_shown, None))
    app.connect("doctree-resolved", _formulas_left_out)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
