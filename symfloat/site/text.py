"""A transcription, or a piece of one, as HTML: its Markdown blocks and its dollars typeset.

The transcriptions are Markdown with TeX dollars.  They are shown as text, faults included: blocks
between blank lines become headings (``#``), rules (``---``), tables (``|`` rows) or paragraphs;
inside a block, ``**bold**`` and ``*italic*``, backslash escapes, hard line breaks, list lines and
the ``<sub>``/``<sup>`` the transcriptions use are honoured, and every math span is typeset.  A block
that is only a web page's element number (``ID:(1610, 0)``) or a figure's file name is left out, and so is
the element number a web page sets after a quantity's symbol (``($z_M$)8671``).  A
reference to a figure (``Fig. 12``) is marked: the transcriptions have no figures.

The words of the records (an erratum's evidence, reason, objection and answer) are prose with TeX
inline math between dollars (:mod:`symfloat.model.evidence_tex`): :func:`prose_html` escapes the words
and typesets the math.

A caller marks stretches of the text: :func:`render` takes the offsets where a mark changes and a
function that wraps a run of HTML in its mark, and calls ``after(block_start, block_end)`` to add
what belongs below a block (the notes of the formulas quoted there).
"""
from __future__ import annotations

import html
import re

from ..model.evidence_tex import spans
from ..model.myst import unescaped
from ..model.span import math_intervals
from ..prose import typeset as ascii_mathematics
from .typeset import typeset

__all__ = ["blocks", "inline_html", "render", "excerpt_html", "prose_html"]

_BLANK = re.compile(r"\n[ \t]*\n\s*")
_TAGS = re.compile(r"&lt;(/?)(sub|sup)&gt;")
# The web page's element numbers and a figure's file name, alone on their line: not the text's words
_BOILERPLATE = re.compile(r"ID:\(\d+, \d+\)|[\w-]+\.(?:eps|png|jpe?g|gif)")
# ... and the element number a web page sets after a quantity's symbol: "die Höhe des Metazentrums ($z_M$)8671"
_ELEMENT_NUMBER = re.compile(r"(?<=\$\))\d{4,5}(?!\d)")
_FIGURE = re.compile(r"\b(Fig(?:ur(?:en)?|\.)\s*\d+[a-z]?(?:\s*(?:und|u\.|et|,)\s*\d+[a-z]?)*)")


def blocks(text: str, maths) -> list[tuple[int, int]]:
    """(start, end) of the blocks of *text*: split at blank lines outside its displays."""
    displays = [(a, b) for a, b, kind in maths if kind == "display"]
    cuts = [m for m in _BLANK.finditer(text) if not any(a < m.start() < b for a, b in displays)]
    out, pos = [], 0
    for m in cuts:
        if text[pos:m.start()].strip():
            out.append((pos, m.start()))
        pos = m.end()
    if text[pos:].strip():
        out.append((pos, len(text)))
    return [(a + len(text[a:b]) - len(text[a:b].lstrip()), a + len(text[a:b].rstrip())) for a, b in out]


def _prose(text: str) -> str:
    """Plain transcription text as HTML (Markdown's inline marks within this stretch only)."""
    out = html.escape(text, quote=False)
    out = _TAGS.sub(r"<\1\2>", out)
    out = re.sub(r"\*\*(\S(?:.*?\S)?)\*\*", r"<strong>\1</strong>", out, flags=re.S)
    out = re.sub(r"(?<![*\\])\*(\S(?:[^*]*?\S)?)\*(?!\*)", r"<em>\1</em>", out, flags=re.S)
    out = unescaped(out)
    out = _FIGURE.sub(r'<span class="figure-missing" title="the figure is not in the transcription">\1</span>', out)
    out = re.sub(r" {2,}\n|\\\n", "<br>\n", out)
    return re.sub(r"\n(?=[-*] |&gt;)", "<br>\n", out)


def _words(text: str, a: int, b: int) -> str:
    """``text[a:b]`` (prose) as HTML, without a web page's element numbers (the pattern looks back before *a*)."""
    kept, pos = [], a
    for m in _ELEMENT_NUMBER.finditer(text, a, b):
        kept.append(text[pos:m.start()])
        pos = m.end()
    return _prose("".join(kept) + text[pos:b])


def inline_html(text: str, a: int, b: int, maths) -> str:
    """``text[a:b]`` as HTML: prose and MathML (the math spans *maths* lie inside or outside it)."""
    out, pos = [], a
    for s, e, kind in maths:
        if e <= a or s >= b:
            continue
        s, e = max(s, a), min(e, b)
        out.append(_words(text, pos, s))
        tex = text[s:e]
        display = kind == "display" and tex.startswith("$$")
        out.append(typeset(tex.strip("$"), display=kind == "display"))
        if display:
            out[-1] = f'<span class="math-display">{out[-1]}</span>'
        pos = e
    out.append(_words(text, pos, b))
    return "".join(out)


def _runs(a: int, b: int, cuts, maths) -> list[tuple[int, int]]:
    """*a*..*b* cut at the offsets *cuts*, never inside a math span."""
    inside = [(s, e) for s, e, _ in maths if s < b and e > a]
    points = sorted({a, b, *(c for c in cuts if a < c < b and not any(s < c < e for s, e in inside))})
    return list(zip(points, points[1:]))


def _cells(text: str, a: int, b: int, maths) -> list[list[tuple[int, int]]]:
    """The rows of a table block as lists of cell intervals (``|`` outside math separates)."""
    rows, pos = [], a
    for line in text[a:b].split("\n"):
        start, end = pos, pos + len(line)
        pos = end + 1
        bars = [i for i in range(start, end) if text[i] == "|" and not any(s < i < e for s, e, _ in maths)]
        cells = [(x + 1, y) for x, y in zip(bars, bars[1:])]
        if cells and not all(re.fullmatch(r"\s*:?-+:?\s*", text[x:y]) for x, y in cells):
            rows.append(cells)
    return rows


def render(text: str, cuts, wrap, after=lambda a, b: "", ids=lambda a, b: ()) -> str:
    """*text* as HTML blocks; the stretch between two consecutive offsets of *cuts* goes through
    ``wrap(start, end, html)``; ``after(block_start, block_end)`` is appended below each block, and
    ``ids(block_start, block_end)`` are the anchors placed at its start."""
    maths = math_intervals(text)

    def stretch(a, b):
        return "".join(wrap(x, y, inline_html(text, x, y, maths)) for x, y in _runs(a, b, cuts, maths))

    out = []
    for a, b in blocks(text, maths):
        body = text[a:b]
        if _BOILERPLATE.fullmatch(body):
            continue
        out.extend(f'<span class="anchor" id="{i}"></span>' for i in ids(a, b))
        heading = re.match(r"(#{1,5})\s+", body)
        if heading:
            level = min(len(heading.group(1)) + 1, 6)
            out.append(f'<h{level} class="t">{stretch(a + heading.end(), b)}</h{level}>')
        elif re.fullmatch(r"(?:-{3,}|\*{3,})", body):
            out.append("<hr>")
        elif all(re.match(r"\s*(?:- )?\|", line) for line in body.split("\n")):       # a table (in a list item)
            rows = "".join("<tr>" + "".join(f"<td>{stretch(x, y)}</td>" for x, y in row) + "</tr>"
                           for row in _cells(text, a, b, maths))
            out.append(f'<table class="t">{rows}</table>')
        else:
            out.append(f'<div class="p">{stretch(a, b)}</div>')
        out.append(after(a, b))
    return "\n".join(o for o in out if o) + "\n"


def excerpt_html(excerpt: str) -> str:
    """A piece of text in the transcription's notation (whole math spans) as HTML, unmarked; with
    dollars that do not pair up, as plain text."""
    try:
        return render(excerpt, (), lambda a, b, h: h)
    except ValueError:
        return f'<div class="p">{_prose(excerpt)}</div>'



def prose_html(text: str) -> str:
    """Words of the records as HTML: what ASCII mathematics they still hold set as formulas (as the notebooks set
    it, :func:`symfloat.prose.typeset`), then :func:`dollars_html`."""
    return dollars_html(ascii_mathematics(text))


def dollars_html(text: str) -> str:
    """Words with their mathematics in dollars as HTML: the prose escaped, each ``$...$`` typeset inline."""
    return "".join(html.escape(piece, quote=False) if kind == "text" else typeset(piece)
                   for kind, piece in spans(text))
