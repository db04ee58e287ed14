"""Point labels of every source tied to where each section introduces them (issue 12, item 2).

A point label is a capital letter with an optional subscript (``S_1``, ``S₁``, ``H_2``); a token of several
(``AEBF``, ``O C``) names the points it joins.  Labels are read from the prose (a single capital standing as a
word, or a run of them) and from math spans (runs of two or more capitals: a single capital in a formula is a
quantity, ``F``, ``T``, ``V``).  A section (Scheeffer's I–X, Graefe's §§, Euler's paragraphs, the whole text of
the others) introduces a point in the first sentence that names it next to a cue (*Fig.*, *Punkt*, *sei*,
*Achse*, *Gerade*, *Ebene*, *Schwerpunkt*; *sit*, *ponatur*, *punctum*, *axis*, *recta*, *centrum*; ...), or in
an earlier section.  A point used in a quote with no introduction before it is *flagged*.
"""
from __future__ import annotations

import re
from functools import cache

from ..model.source import SOURCES, get_source
from ..model.span import line_of, math_intervals

__all__ = ["sections", "points", "labels_in", "introductions", "flagged", "flags", "labels_markdown"]

_SUB = "₀₁₂₃₄₅₆₇₈₉"
_POINT = re.compile(rf"[A-Z](?:_\{{?[0-9a-z]\}}?|_[0-9a-z]|[{_SUB}]|')?")
_PROSE_LABEL = re.compile(rf"(?<![\w\\])(?:[A-Z](?:[{_SUB}]|')?)(?:\s?[A-Z](?:[{_SUB}]|')?){{0,4}}(?![\w.]?[a-zäöüß])")
_MATH_LABEL = re.compile(r"(?<![\\\w])[A-Z](?:_\{?[0-9]\}?)?(?:\s?[A-Z](?:_\{?[0-9]\}?)?){1,4}(?![a-z])")
_ROMAN = re.compile(r"[IVXL]+")
_CUES = re.compile(r"Fig|Figur|Punkt|Punkte|sei|seien|heiss|Achse|Gerade|Linie|Ebene|Schwerpunkt|Mittelpunkt|Ecke|"
                   r"Seite|Kante|Basis|Grundfläche|Strecke|Dreieck|Viereck|Durchschnitt|\bsit\b|\bsint\b|ponatur|"
                   r"punct|axis|axe|recta|linea|centr|figura|sectio|curua|curva|ducatur|vocetur|pont|tengely|"
                   r"Schnitt|Lot|Abstand|parallel", re.I)
_NOT_LABELS = {"I", "II", "III", "IV", "V", "VI", "VII", "VIII", "IX", "X", "D", "A.", "B.", "C."}


@cache
def sections(source: str) -> list[tuple[int, str]]:
    """(start offset, name) of every section of *source*, in order."""
    text = get_source(source).text()
    pattern = {"scheeffer": r"^#+\s*([IVX]+)\.\s*$", "graefe": r"^#+\s*§\.\s*(\d)\.", "euler": r"^§\.?\s*(\d{3})"
               }.get(source)
    found = [(m.start(), m.group(1)) for m in re.finditer(pattern, text, re.M)] if pattern else []
    return [(0, "opening")] + found


def _section_of(starts, offset: int) -> str:
    name = "opening"
    for start, n in starts:
        if start > offset:
            break
        name = n
    return name


def points(token: str) -> tuple[str, ...]:
    """The points a label token names: ``"S_1 O"`` -> ``("S1", "O")``."""
    return tuple(re.sub(r"[_{}]", "", p).translate(str.maketrans(_SUB, "0123456789")) for p in _POINT.findall(token))


def labels_in(text: str, base: int = 0):
    """(offset, token) of every label in *text* (prose and math), offsets shifted by *base*."""
    out = []
    intervals = math_intervals(text)
    masked = list(text)
    for a, b, _ in intervals:
        masked[a:b] = " " * (b - a)
        for m in _MATH_LABEL.finditer(text[a:b]):
            if not _ROMAN.fullmatch(m.group(0)):
                out.append((base + a + m.start(), m.group(0)))
    for m in _PROSE_LABEL.finditer("".join(masked)):
        if m.group(0).strip() not in _NOT_LABELS:
            out.append((base + m.start(), m.group(0)))
    return sorted(out)


def _sentence(text: str, offset: int) -> str:
    a = text.rfind(". ", 0, offset) + 1
    b = min(x for x in (text.find(". ", offset), len(text)) if x >= 0)
    return text[a:b]


def _introductions(text: str, starts, found) -> dict[tuple[str, str], int]:
    out: dict[tuple[str, str], int] = {}
    for at, token in found:
        if _CUES.search(_sentence(text, at)):
            for p in points(token):
                out.setdefault((_section_of(starts, at), p), at)
    return out


@cache
def _read(source: str):
    text = get_source(source).text()
    found = tuple(labels_in(text))
    return text, found, _introductions(text, sections(source), found)


def introductions(source: str) -> dict[tuple[str, str], int]:
    """(section, point) -> offset of the first sentence of that section that introduces it (see the docstring)."""
    return _read(source)[2]


def flagged(text: str, starts, quoted, source: str = "", found=None, intro=None) -> list[dict]:
    """The labels of the quotes ``(start, end, formula id)`` of *text* (sections opening at *starts*,
    ``(offset, name)``) that their section does not introduce before the use, nor an earlier section."""
    found = labels_in(text) if found is None else found
    intro = _introductions(text, starts, found) if intro is None else intro
    names = [n for _, n in starts]
    out, seen = [], set()
    for a, b, fid in quoted:
        for at, token in (x for x in found if a <= x[0] < b):
            sec = _section_of(starts, at)
            earlier = names[:names.index(sec)]
            for p in points(token):
                here = intro.get((sec, p))
                if (here is not None and here <= at) or any((s, p) in intro for s in earlier):
                    continue
                key = (line_of(text, at)[0], p)
                if key not in seen:
                    seen.add(key)
                    out.append({"source": source, "line": key[0], "section": sec, "label": p, "token": token.strip(),
                                "quote": fid, "why": "introduced later" if here is not None else "never introduced"})
    return sorted(out, key=lambda f: (f["line"], f["label"]))


def flags(source: str) -> list[dict]:
    """:func:`flagged` for the quotes of every derivation of *source*."""
    from .references import _quotes
    text, found, intro = _read(source)
    return flagged(text, sections(source), [(a, b, fid) for a, b, fid, _ in _quotes(source)], source, found, intro)


def labels_markdown(sources=tuple(SOURCES)) -> str:
    """The labels section of ``docs/references.md``: counts per source and every flagged label."""
    out = ["# Point labels of the quotes", "",
           "A point label used in a quote is tied to the first sentence of its section that names it beside a cue",
           "(*Fig.*, *Punkt*, *sei*, *Achse*, ...; `symfloat/report/labels.py`). Flagged: a label the section",
           "introduces only after the quote, or never (nor an earlier section).", "",
           "| source | points introduced | labels flagged |", "|---|---:|---:|"]
    found = {s: flags(s) for s in sources}
    for s in sources:
        out.append(f"| {s} | {sum(1 for (sec, p) in introductions(s))} | {len(found[s])} |")
    for s, fl in found.items():
        if fl:
            out += ["", f"## {s}", "", "| line | section | label | in | quote | why |", "|---:|---|---|---|---|---|"]
            out += [f"| {f['line']} | {f['section']} | {f['label']} | `{f['token']}` | {f['quote']} | {f['why']} |"
                    for f in fl]
    return "\n".join(out) + "\n"
