"""Where a locator points in a transcription: the stretch of text it names.

A locator cites a place as ``sources/INDEX.md`` says: Scheeffer by equation number ``(78c)`` (also
``after (15)``), by section and subsection ``VI.D`` or ``I, Fig. 3``, or by worked example
``Example 4``; Euler by paragraph ``§216``; Graefe by section ``§4`` plus a name; the two modern pieces
by a heading.  :func:`region` turns a locator into the ``(start, end)`` offsets of the section,
paragraph, subsection, example or heading's text it names, or ``None`` when the locator names no place
(a short name of a formula, "formula list").  An erratum's printed excerpt must lie in the region of its
locator (``tests/test_erratum_locators.py``).
"""
from __future__ import annotations

import math
import re

from .source import get_source

__all__ = ["citation", "region", "sections"]

_ROMAN = re.compile(r"^([IVX]+)\b(?:\.([A-F])\b)?")
_EQUATION = re.compile(r"\((\d+)([a-z]?)\)")
_EXAMPLE = re.compile(r"^Example (\d+)$")
_SCHEEFFER_SECTION = r"^(?:#+\s*)?([IVX]+)\.\s*$"        # VIII. stands on a line of its own, unmarked
_SUBSECTION = r"^(?:#+\s*)?{}\. [A-ZÄÖÜ][a-zäöüß]"          # "#### D. Der Würfel", "C. Das dritte ...", not "D. h."
_EULER_PARAGRAPH = re.compile(r"(?:§|\\S)\.?\s*(\d{3})\.")      # §. 218.  or, inside a display, \S. 233.


def sections(source_key: str, pattern: str | None = None) -> dict[str, tuple[int, int]]:
    """Section name -> ``(start, end)`` of its text, by the source's heading pattern (``sections``)."""
    src = get_source(source_key)
    pattern = pattern or src.sections
    if not pattern:
        return {}
    text = src.text()
    heads = [(m.group(1), m.start()) for m in re.finditer(pattern, text, re.MULTILINE)]
    out: dict[str, tuple[int, int]] = {}
    for k, (name, start) in enumerate(heads):
        end = heads[k + 1][1] if k + 1 < len(heads) else len(text)
        out.setdefault(name, (start, end))
    return out


def _paragraphs(text: str) -> dict[str, tuple[int, int]]:
    """Euler's paragraphs: each mark ``§. N.`` whose number follows the last one, to the next such mark."""
    marks, last = [], 0
    for m in _EULER_PARAGRAPH.finditer(text):
        if int(m.group(1)) > last:
            marks.append((m.group(1), m.start()))
            last = int(m.group(1))
    return {n: (a, marks[k + 1][1] if k + 1 < len(marks) else len(text)) for k, (n, a) in enumerate(marks)}


def _within(pattern: str, text: str, start: int, end: int, stop: str) -> tuple[int, int] | None:
    """From the first line matching *pattern* in ``text[start:end]`` to the next line matching *stop*."""
    head = re.compile(pattern, re.MULTILINE).search(text, start, end)
    if head is None:
        return None
    nxt = re.compile(stop, re.MULTILINE).search(text, head.end(), end)
    return head.start(), nxt.start() if nxt else end


def _tagged(text: str, n: str, letter: str) -> int | None:
    """The offset of the equation number ``(n letter)`` as the print sets it: ``\\quad (78c)``,
    ``\\tag{161a}``, ``(81 a)``, or ``162 a`` closing a line."""
    tags = (rf"\\q?quad\s*\(\s*{n}\s*{letter}\s*\)", rf"\\tag\{{\s*{n}\s*{letter}\s*\}}",
            rf"\(\s*{n}\s*{letter}\s*\)", rf"\b{n}\s+{letter}\s*$" if letter else r"(?!)")
    return next((m.start() for t in tags for m in [re.compile(t, re.MULTILINE).search(text)] if m), None)


def _scheeffer(locator: str, text: str, parts: dict) -> tuple[int, int] | None:
    eq = _EQUATION.search(locator)
    if eq:
        n, letter = eq.groups()
        at = _tagged(text, n, letter)
        if at is None and not letter:               # a display whose number the scan lost: between its
            before, after = _tagged(text, str(int(n) - 1), ""), _tagged(text, str(int(n) + 1), "")   # neighbours
            return (before, after) if before is not None and after is not None else None
        return next(((a, b) for a, b in parts.values() if a <= at < b), None) if at is not None else None
    example = _EXAMPLE.match(locator)
    if example:
        n = int(example.group(1))
        start = text.index("Zahlenbeispiel")
        return _within(rf"^{n}\. ", text, start, parts["VII"][0], rf"^({n + 1}\. |#)")
    roman = _ROMAN.match(locator)
    if roman is None or roman.group(1) not in parts:
        return None
    start, end = parts[roman.group(1)]
    if roman.group(2):
        return _within(_SUBSECTION.format(roman.group(2)), text, start, end, _SUBSECTION.format("[A-F]"))
    return start, end


def region(source_key: str, locator: str) -> tuple[int, int] | None:
    """The ``(start, end)`` offsets of the text *locator* names in the transcription of *source_key*, or
    ``None`` when it names no place the text marks."""
    text = get_source(source_key).text()
    if source_key == "scheeffer":
        return _scheeffer(locator, text, sections(source_key, _SCHEEFFER_SECTION))
    number = re.match(r"^§\s*(\d+)", locator)
    if source_key == "euler":
        return _paragraphs(text).get(number.group(1)) if number else None
    if get_source(source_key).sections:             # Graefe's sections: §k plus a name
        return sections(source_key).get(number.group(1)) if number else None
    return _under_heading(text, locator)


def _under_heading(text: str, locator: str) -> tuple[int, int] | None:
    """A piece without numbered sections: the text under the last line that is the heading *locator*
    (a table of contents may list it first) or the paragraph it begins, to the end of its block (a web
    page's block closes with its ``ID:(n, m)`` line), else to the end of the text."""
    heads = list(re.finditer(rf"^{re.escape(locator)}(\.|$)", text, re.MULTILINE))
    if not heads:
        return None
    start = heads[-1].start()
    end = re.compile(r"^ID:\(\d+, \d+\)$", re.MULTILINE).search(text, heads[-1].end())
    return start, end.start() if end else len(text)


_MARK = re.compile(r"^(?:\(\d+[a-z]?\)|[IVX]+\b|§|Example \d|after \()")     # a place the print marks, not a name


def citation(source_key: str, locators) -> str:
    """The places *locators* name in a source as a reader cites them: the source's short name and year, then the
    places in the text's order, each once (``Scheeffer 1902 IV, (79), VI.D, (123)``); a place named by a heading
    or by the name of a formula, not by a mark of the print, in quotation marks (``Auftrieb Stabilität “formula
    list”``)."""
    src = get_source(source_key)
    places = list(dict.fromkeys(locators))
    starts = {p: (region(source_key, p) or (len(src.text()), 0))[0] for p in places}
    numbers = {p: int(m.group(1)) if (m := _EQUATION.fullmatch(p)) else math.inf for p in places}
    ordered = sorted(places, key=lambda p: (starts[p], numbers[p], places.index(p)))
    cited = ", ".join(p if _MARK.match(p) else f"“{p}”" for p in ordered)
    return f"{src.dated} {cited}" if cited else src.dated
