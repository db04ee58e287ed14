r"""What a correction changes: the corrected TeX with the parts that differ from the printed TeX marked,
and the correction rendered (:func:`corrected_html`).

The two formulas are cut into TeX tokens (a command, a number, a letter, any other character), and
their words (a ``\text{...}`` group, a printed excerpt's prose around its ``$...$``, a printed sentence)
into whole words, so that a changed letter marks its word, never a piece of it.  The runs of the
correction that the print does not have, or has otherwise (:class:`difflib.SequenceMatcher`
on the tokens, spaces ignored), are wrapped in ``\htmlClass{changed}{...}``, which KaTeX sets as a
``<span class="changed">`` (the stylesheet frames and shades it).  A run is marked only where it
is a whole TeX group: balanced braces, no ``&``, ``\\``, ``\left``, ``\right``, ``\begin`` or
``\end`` inside, not starting with a sub- or superscript sign, not ending in a command that waits for
its argument; a run from the words of one ``\text{}`` through a formula into the next is marked piece by
piece.  Changed letters of a name (``\\operatorname{cotg}``) mark the whole name.

>>> highlighted(r"\frac{b}{2} = b s (1 - s)", r"\frac{b}{2} = 6 s (1 - s)")
'\\frac{b}{2} = \\htmlClass{changed}{6} s (1 - s)'
>>> highlighted(r"Nach $4$ ist das Gleichgewichtlage", r"\text{Nach 54 ist die Gleichgewichtslage}")
'\\text{Nach \\htmlClass{changed}{54} ist \\htmlClass{changed}{die Gleichgewichtslage}}'

A marked sub- or superscript is braced, the argument its sign takes (Scheeffer VIII's ``x_3^1`` for ``x_s^1``):

>>> highlighted(r"$x_3^1$ die Entfernung", r"x_s^1 \text{ die Entfernung}")
'x_{\\htmlClass{changed}{s}}^1 \\text{ die Entfernung}'
"""
from __future__ import annotations

import html
import re
from difflib import SequenceMatcher

from ..model.tex import braced_end
from .text import excerpt_html
from .typeset import UNRENDERED, typeset

__all__ = ["highlighted", "corrected_html", "reads_as_words"]

_WORDS = re.compile(r"[A-Za-zäöüß]{3,}[ ,]+[A-Za-zäöüß]{3,}")
_TOKEN = re.compile(r"\\[A-Za-z]+\*?|\\.|\d+(?:[.,]\d+)?|\S")
_WORD_TOKEN = re.compile(r"\\[A-Za-z]+\*?|\\.|\d+(?:[.,]\d+)?|[^\W\d_]+|\S")     # a word of letters is one token
_TEXT_GROUP = re.compile(r"\\(?:text|textrm|textit|mbox)\{")
_UNSAFE = re.compile(r"&|\\\\|\\(?:left|right|middle|begin|end)\b")
_ARGUMENT = re.compile(r"\\[A-Za-z]+$")
_NAMED = re.compile(r"\\(?:operatorname|mathrm)\{[^{}]*$")


def _prose(tex: str) -> list[tuple[int, int]]:
    """The spans of *tex* that are words: the contents of its text groups and, where it holds ``$...$``, what
    lies outside them."""
    spans = []
    if "$" in tex:          # words, formula, words, ...: between the dollars (``$`` or ``$$``)
        ends = [0] + [i for m in re.finditer(r"\$\$?", tex) for i in m.span()] + [len(tex)]
        spans += list(zip(ends[::4], ends[1::4]))
    for m in _TEXT_GROUP.finditer(tex):
        end = braced_end(tex, m.end() - 1)
        spans.append((m.end(), (end if end >= 0 else len(tex)) - 1))
    return spans


def _tokens(tex: str, prose: list[tuple[int, int]] | None = None) -> list[tuple[int, int, str]]:
    """The TeX tokens of *tex*, a word of its *prose* (default :func:`_prose`) one token."""
    tokens, pos = [], 0
    for a, b in sorted(_prose(tex) if prose is None else prose) + [(len(tex), len(tex))]:
        if a < pos:
            continue
        tokens += [(m.start(), m.end(), m.group(0)) for m in _TOKEN.finditer(tex, pos, a)]
        tokens += [(m.start(), m.end(), m.group(0)) for m in _WORD_TOKEN.finditer(tex, a, b)]
        pos = b
    return [t for t in tokens if t[2] != "$"]


def _whole(run: str) -> bool:
    depth = 0
    for c in run:
        depth += {"{": 1, "}": -1}.get(c, 0)
        if depth < 0:
            return False
    return depth == 0 and not _UNSAFE.search(run) and run[0] not in "^_'" and not _ARGUMENT.search(run)


def highlighted(printed: str, corrected: str) -> str:
    """*corrected* with the runs that differ from *printed* in ``\\htmlClass{changed}{...}``."""
    new = _tokens(corrected)
    # a print without dollars or commands may be a formula or a sentence: read as the correction resembles more
    readings = [_tokens(printed)] + ([_tokens(printed, [(0, len(printed))])] if not re.search(r"[$\\]", printed)
                                     else [])
    matcher = max((SequenceMatcher(None, [t for _, _, t in old], [t for _, _, t in new], autojunk=False)
                   for old in readings), key=SequenceMatcher.ratio)
    out, pos = [], 0
    for j1, j2 in _runs(matcher, new, corrected):
        a, b = new[j1][0], new[j2 - 1][1]
        inside = _NAMED.search(corrected, 0, a)          # letters of a name: the whole name is marked
        if inside and "}" in corrected[b:]:
            a, b = inside.start(), corrected.index("}", b) + 1
        if a < pos:
            continue
        run = corrected[a:b]
        if _whole(run):
            script = corrected[:a].rstrip().endswith(("_", "^"))     # x_\htmlClass{..}{s} is no TeX: braced
            out += [corrected[pos:a], "{" * script, r"\htmlClass{changed}{", run, "}", "}" * script]
            pos = b
    return "".join(out) + corrected[pos:]


def _runs(matcher, new, corrected):
    """``(j1, j2)``: the token runs of the correction the print does not have.  A run that reaches from the words
    of one ``\\text{}`` through a formula into the next is cut at the groups' braces; one that reaches over
    another group's brace is kept within it."""
    closing = {b for a, b in _prose(corrected) if b < len(corrected) and corrected[b] == "}"}

    def opens(j):
        return j >= 0 and _TEXT_GROUP.match(new[j][2] + "{")

    def cut(j):
        return opens(j) or (new[j][2] == "{" and opens(j - 1)) or new[j][0] in closing

    for op, _, _, j1, j2 in matcher.get_opcodes():
        if op not in ("replace", "insert") or j1 == j2:
            continue
        if _whole(corrected[new[j1][0]:new[j2 - 1][1]]):
            yield j1, j2
            continue
        pieces, start = [], j1
        for j in range(j1, j2 + 1):
            if j == j2 or cut(j):
                pieces += [(start, j)] if start < j else []
                start = j + 1
        for j1, j2 in pieces:
            while j1 < j2 and new[j1][2] in "{}":
                j1 += 1
            while j1 < j2 and new[j2 - 1][2] in "{}":
                j2 -= 1
            if j1 < j2:
                yield j1, j2


def reads_as_words(corrected: str) -> bool:
    """Whether a correction is words (its mathematics between dollars, or sentences with none), not one formula.

    >>> reads_as_words("e > 0 in the stable case"), reads_as_words(r"x = \\frac{a}{b}"), reads_as_words("$s$ only")
    (True, False, True)
    """
    return "$" in corrected or bool(_WORDS.search(re.sub(r"\\[A-Za-z]+(\{[^}]*\})?", " ", corrected))
                                    and "\\" not in corrected)


_CHANGED = r"\htmlClass{changed}{"


def _sentence_html(tex: str) -> str | None:
    """A correction that is a sentence -- its top level ``\\text{}`` groups of words (its change marked inside
    them) and formulas between them, more words than formula -- as HTML prose with the formulas typeset inline, so
    that it wraps on a narrow screen; ``None`` for anything else (a formula with words in it, an environment, TeX
    inside the words)."""
    pieces, formula, at = [], "", 0
    while at < len(tex):
        changed = tex.startswith(_CHANGED, at)
        opening = _TEXT_GROUP.match(tex, at + len(_CHANGED) if changed else at)
        if opening is None:
            formula += tex[at]
            at += 1
            continue
        end = braced_end(tex, opening.end() - 1)
        close = braced_end(tex, at + len(_CHANGED) - 1) if changed else end
        if end < 0 or close != (end + 1 if changed else end):
            return None                      # a mark around more than the one group: a formula
        pieces += [("math", formula)] if formula.strip() else []
        pieces.append(("changed" if changed else "text", tex[opening.end():end - 1]))
        formula, at = "", close
    pieces += [("math", formula)] if formula.strip() else []
    words = "".join(t for kind, t in pieces if kind != "math")
    maths = "".join(t for kind, t in pieces if kind == "math")
    if len(re.findall(r"[^\W\d_]{2,}", words)) < 3 or len(words) < len(maths) or _UNSAFE.search(tex):
        return None
    out = []
    for kind, text in pieces:
        if kind == "math":
            out.append(typeset(text))
            continue
        parts = re.split("(" + re.escape(_CHANGED) + r"[^{}\\]*\})", text)
        if any("\\" in part or "{" in part for part in parts[::2]):
            return None                      # TeX inside the words
        shown = "".join(f'<span class="changed">{html.escape(part[len(_CHANGED):-1])}</span>' if k % 2
                        else html.escape(part) for k, part in enumerate(parts))
        out.append(f'<span class="changed">{shown}</span>' if kind == "changed" else shown)
    return "".join(out)


def corrected_html(corrected: str, printed: str = "") -> str:
    """A correction: words (with their dollars) as prose, a formula as a typeset display, its change
    from the *printed* TeX marked.

    >>> corrected_html("x = 2,44")[:26]
    '<div class="math-display">'
    """
    if reads_as_words(corrected):
        return excerpt_html(corrected)
    marked = highlighted(printed, corrected) if printed else corrected
    words = _sentence_html(marked)
    if words is not None:                   # a sentence in \text{} with formulas in it: set as prose, it wraps
        return f'<p class="math-words">{words}</p>'
    shown = typeset(marked, display=True)
    if marked != corrected and shown.startswith("<code"):        # the marks made it untypesettable
        UNRENDERED.discard(marked)
        shown = typeset(corrected, display=True)
    return f'<div class="math-display">{shown}</div>'
