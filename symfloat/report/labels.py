"""Point labels of every source tied to where each section introduces them (issue 12, item 2).

A point label is a capital letter with an optional subscript (``S_1``, ``S₁``, ``H_2``); a token of several
(``AEBF``, ``O C``) names the points it joins.  Labels are read from the prose (a single capital standing as a
word, or a run of them) and from math spans (runs of two or more capitals: a single capital in a formula is a
quantity, ``F``, ``T``, ``V``).  A section (Scheeffer's I–X, Graefe's §§, Euler's paragraphs, the whole text of
the others) introduces a point in the first sentence that names it next to a cue (*Fig.*, *Punkt*, *sei*,
*Achse*, *Gerade*, *Ebene*, *Schwerpunkt*; *sit*, *ponatur*, *punctum*, *axis*, *recta*, *centrum*; ...), or in
an earlier section.  A point used in a quote with no introduction before it is *flagged*.

Two contradictions are found mechanically as well (:func:`contradictions`): a point that one section
introduces twice as different kinds of point (the nearest kind word within a few words of the label:
centre of gravity, centre of buoyancy, midpoint, metacentre), and a letter that one quoted formula uses both
as a point (in a run such as ``CD``) and alone as a quantity (``D``).
"""
from __future__ import annotations

import re
from functools import cache

import sympy as sp

from ..model.source import SOURCES, get_source
from ..model.span import line_of, math_intervals

__all__ = ["sections", "points", "labels_in", "introductions", "flagged", "flags", "contradicting", "contradictions",
           "labels_markdown"]

_SUB = "₀₁₂₃₄₅₆₇₈₉"
_POINT = re.compile(rf"[A-Z](?:_\{{?[0-9a-z]\}}?|_[0-9a-z]|[{_SUB}]|')?")
_PROSE_LABEL = re.compile(rf"(?<![\w\\])(?:[A-Z](?:[{_SUB}]|')?)(?:\s?[A-Z](?:[{_SUB}]|')?){{0,4}}(?![\w.]?[a-zäöüß])")
_MATH_LABEL = re.compile(r"(?<![\\\w])[A-Z](?:_\{?[0-9]\}?)?(?:\s?[A-Z](?:_\{?[0-9]\}?)?){1,4}(?![a-z])")
_ROMAN = re.compile(r"[IVXL]+")
_CUES = re.compile(r"Fig|Figur|Punkt|Punkte|sei|seien|heiss|Achse|Gerade|Linie|Ebene|Schwerpunkt|Mittelpunkt|Ecke|"
                   r"Seite|Kante|Basis|Grundfläche|Strecke|Dreieck|Viereck|Durchschnitt|\bsit\b|\bsint\b|ponatur|"
                   r"punct|axis|axe|recta|linea|centr|figura|sectio|curua|curva|ducatur|vocetur|pont|tengely|"
                   r"Schnitt|Lot|Abstand|parallel", re.I)
_KINDS = {"centre of gravity": re.compile(r"schwerpunkt|centr\w*\s+gr[au]vitatis|súlypont", re.I),
          "centre of buoyancy": re.compile(r"centr\w*\s+magnitudinis|auftriebs?punkt|verdrängungsschwerpunkt|"
                                           r"metacentr|metazentr", re.I),
          "midpoint": re.compile(r"mittelpunkt|halbierungspunkt|punct\w*\s+\w*\s*medi|\bmedi(?:us|um|o)\b", re.I)}
_NEAR = 40                 # characters between a label and the kind word that describes it
_LONE = re.compile(r"(?<![\\\w{])(?<![a-z] )[A-Z](?![\w}'])(?! [a-z]\b)")   # not beside a point o, c: "G c"
_NOT_LABELS = {"I", "II", "III", "IV", "V", "VI", "VII", "VIII", "IX", "X", "D", "A.", "B.", "C."}


@cache
def sections(source: str) -> list[tuple[int, str]]:
    """(start offset, name) of every section of *source*, in order."""
    text = get_source(source).text()
    pattern = get_source(source).sections          # its metadata file (sources/<key>.source.json)
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


def _kind(text: str, at: int, token: str) -> str | None:
    """The kind of point the words nearest to the label at *at* describe, or None."""
    a, b = max(0, at - _NEAR), min(len(text), at + len(token) + _NEAR)
    best = None
    for kind, pattern in _KINDS.items():
        for m in pattern.finditer(text, a, b):
            gap = m.start() - (at + len(token)) if m.start() >= at else at - m.end()
            if best is None or gap < best[0]:
                best = (gap, kind)
    return best[1] if best else None


def contradicting(text: str, starts, quoted, source: str = "", found=None, products=None) -> list[dict]:
    """The contradictions of *text* (sections opening at *starts*; quotes ``(start, end, formula id)``): a point
    a section introduces as two kinds of point, and a letter one quote uses as a point and as a quantity.
    ``products`` (formula id -> the symbol names of its hand reading) tells a product from a segment: a run
    whose letters are all symbols of the reading (``ND``) is a product."""
    products = products or {}
    found = labels_in(text) if found is None else found
    kinds: dict[tuple[str, str], dict[str, int]] = {}
    for at, token in found:
        pts = points(token)
        if len(pts) != 1 or not _CUES.search(_sentence(text, at)):
            continue
        kind = _kind(text, at, token)
        if kind:
            kinds.setdefault((_section_of(starts, at), pts[0]), {}).setdefault(kind, at)
    out = []
    for (sec, p), by_kind in kinds.items():
        if len(by_kind) > 1:
            (k1, a1), (k2, a2) = sorted(by_kind.items(), key=lambda kv: kv[1])[:2]
            out.append({"source": source, "line": line_of(text, a2)[0], "section": sec, "label": p, "quote": "",
                        "why": f"introduced as the {k1} (line {line_of(text, a1)[0]}) and as the {k2}"})
    intervals = math_intervals(text)
    for a, b, fid in quoted:
        for ma, mb, _ in (iv for iv in intervals if iv[0] < b and a < iv[1]):
            tex = text[max(a, ma):min(b, mb)]
            runs = list(_MATH_LABEL.finditer(tex))
            in_runs = {q for m in runs for q in points(m.group(0)) if not _ROMAN.fullmatch(m.group(0))
                       and not set(points(m.group(0))) <= products.get(fid, set())}
            covered = [(m.start(), m.end()) for m in runs]
            lone = {m.group(0) for m in _LONE.finditer(tex) if not any(x <= m.start() < y for x, y in covered)}
            for p in sorted(in_runs & lone):
                out.append({"source": source, "line": line_of(text, ma)[0], "section": _section_of(starts, ma),
                            "label": p, "quote": fid,
                            "why": "one formula uses the letter as a point (in a segment) and alone as a quantity"})
    unique = {(f["line"], f["label"], f["why"]): f for f in out}
    return sorted(unique.values(), key=lambda f: (f["line"], f["label"]))


def contradictions(source: str) -> list[dict]:
    """:func:`contradicting` for the quotes of every derivation of *source*."""
    from .references import _quotes
    from ..model.claim import expressions
    text, found, _ = _read(source)
    products = {}
    for a, b, fid, p in _quotes(source):
        if p.reading is not None:
            products[fid] = {q.name for m in expressions(p.reading) for q in sp.sympify(m).free_symbols}
    return contradicting(text, sections(source), [(a, b, fid) for a, b, fid, _ in _quotes(source)], source, found,
                         products)


def labels_markdown(sources=tuple(SOURCES)) -> str:
    """The labels section of ``docs/references.md``: counts per source, every flagged label and every
    contradiction."""
    out = ["# Point labels of the quotes", "",
           "A point label used in a quote is tied to the first sentence of its section that names it beside a cue",
           "(*Fig.*, *Punkt*, *sei*, *Achse*, ...; `symfloat/report/labels.py`). Flagged: a label the section",
           "introduces only after the quote, or never (nor an earlier section). Contradictions: a point a section",
           "introduces as two kinds of point (centre of gravity, centre of buoyancy, midpoint), or a letter one quote",
           "uses both as a point (in a segment such as CD) and alone as a quantity (D); listed, for the reader to judge.",
           "", "| source | points introduced | labels flagged | contradictions |", "|---|---:|---:|---:|"]
    found = {s: flags(s) for s in sources}
    clashes = {s: contradictions(s) for s in sources}
    for s in sources:
        out.append(f"| {s} | {sum(1 for (sec, p) in introductions(s))} | {len(found[s])} | {len(clashes[s])} |")
    for s, fl in found.items():
        if fl:
            out += ["", f"## {s}", "", "| line | section | label | in | quote | why |", "|---:|---|---|---|---|---|"]
            out += [f"| {f['line']} | {f['section']} | {f['label']} | `{f['token']}` | {f['quote']} | {f['why']} |"
                    for f in fl]
    for s, cl in clashes.items():
        if cl:
            out += ["", f"## {s}: contradictions", "", "| line | section | label | quote | why |", "|---:|---|---|---|---|"]
            out += [f"| {f['line']} | {f['section']} | {f['label']} | {f['quote'] or '–'} | {f['why']} |" for f in cl]
    return "\n".join(out) + "\n"
