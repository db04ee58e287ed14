"""Spans of a transcription: its math, as the transcription marks it, and its quantitative sentences.

The transcriptions mark mathematics with TeX dollars: ``$$...$$`` for a displayed formula (it may
run over several lines), ``$...$`` for inline math within one line.  An inline formula that stands
alone on its line (the web lesson writes its displays so) counts as a display.  Every ``$`` must
pair up; a stray one is an error, since it would shift every later span.

A *quantitative sentence* is a sentence whose words (its math masked) assert a range, a count, an
inequality, a monotonicity, an identity, a stability or a decimal number: the claims in words.
The word lists are per language, kept as data (``claim_words.json``; a library of texts may add its
own languages) and deliberately broad; a language without a list is judged by its decimal numbers.
What they catch is accounted for in the ledger (:mod:`symfloat.report.ledger`), quoted or waived, never dropped.
"""
from __future__ import annotations

import json
import re
from dataclasses import dataclass
from functools import cache, lru_cache
from pathlib import Path

from .source import get_source

__all__ = ["Span", "KINDS", "math_intervals", "widened", "math_spans", "is_quantitative", "quantitative_sentences",
           "spans", "line_of", "claim_words"]

KINDS = ("display", "inline", "sentence")

_DISPLAY = re.compile(r"\$\$(.+?)\$\$", re.S)
_INLINE = re.compile(r"\$([^$\n]+?)\$")

_DECIMAL = re.compile(r"\d+[,.]\d+")
_MATH_MASK = "\u2063"      # invisible separator: stands for masked math in the prose
_SENTENCE_END = re.compile(r"(?<=[.;!?])\s+(?=[A-ZÄÖÜÁÉÍÓÚ„\"(])")
_ABBREVIATION = re.compile(r"(?:\b(?:d|h|s|u|a|O|vgl|Fig|fig|Abschn|Gl|Nr|Jahrg|Tab|bzw|z|B|Dr|v|ff|S|§|cf|pag)\.|"
                           r"\b[IVX]+\.|\d\.)$")


@dataclass(frozen=True)
class Span:
    """A stretch of a transcription: ``text[start:end]``, starting on 1-based ``line`` at 1-based ``column``."""

    source: str
    kind: str           # one of KINDS
    start: int
    end: int
    line: int
    column: int
    text: str

    @property
    def math(self) -> str:
        """The TeX between the dollars (for a sentence, its text)."""
        if self.kind == "sentence":
            return self.text
        return self.text.strip("$")

    def overlaps(self, start: int, end: int) -> bool:
        return self.start < end and start < self.end


def line_of(text: str, offset: int) -> tuple[int, int]:
    """1-based line and column of *offset* in *text*."""
    return text.count("\n", 0, offset) + 1, offset - text.rfind("\n", 0, offset)


@lru_cache(maxsize=16)
def math_intervals(text: str) -> tuple[tuple[int, int, str], ...]:
    """(start, end, kind) of every math span; raises on a ``$`` that pairs with nothing.  Found once per text
    (remembered: the readings and the site look up each quote's spans in its whole source, a thousand times).

    >>> math_intervals("a $x$ b\\n$$y = 1$$\\n$z$\\n")
    ((2, 5, 'inline'), (8, 17, 'display'), (18, 21, 'display'))
    """
    found = [(m.start(), m.end(), "display") for m in _DISPLAY.finditer(text)]
    masked = _DISPLAY.sub(lambda m: " " * len(m.group(0)), text)
    for m in _INLINE.finditer(masked):
        bol = masked.rfind("\n", 0, m.start()) + 1
        eol = masked.find("\n", m.end())
        eol = len(masked) if eol < 0 else eol
        alone = not masked[bol:m.start()].strip() and not masked[m.end():eol].strip()
        found.append((m.start(), m.end(), "display" if alone else "inline"))
    rest = _INLINE.sub(lambda m: " " * len(m.group(0)), masked)
    if "$" in rest:
        at = rest.index("$")
        raise ValueError(f"unpaired $ at line {line_of(text, at)[0]}: {text[at:at + 60]!r}")
    return tuple(sorted(found))


def widened(a: int, b: int, maths) -> tuple[int, int]:
    """*a*..*b* widened to the whole math spans of *maths* (:func:`math_intervals`) it begins or ends in.

    >>> widened(3, 7, math_intervals("a $x + y$ b"))
    (2, 9)
    """
    for s, e, _ in maths:
        if s < a < e:
            a = s
        if s < b < e:
            b = e
    return a, b


@cache
def math_spans(source: str) -> tuple[Span, ...]:
    """Every math span of *source*, in text order."""
    text = get_source(source).text()
    return tuple(Span(source, kind, a, b, *line_of(text, a), text[a:b]) for a, b, kind in math_intervals(text))


def _segments(text: str, intervals) -> list[tuple[int, int]]:
    """Paragraph pieces between blank lines and displays: where sentences are looked for."""
    cuts = [(a, b) for a, b, kind in intervals if kind == "display"]
    cuts += [(m.start(), m.end()) for m in re.finditer(r"\n[ \t]*\n", text)]
    pieces, pos = [], 0
    for a, b in sorted(cuts):
        if a > pos:
            pieces.append((pos, a))
        pos = max(pos, b)
    pieces.append((pos, len(text)))
    return pieces


def _sentences(text: str, a: int, b: int):
    """(start, end) of the sentences of ``text[a:b]``, split after . ; ! ? but not after abbreviations."""
    start = a
    for m in _SENTENCE_END.finditer(text, a, b):
        if _ABBREVIATION.search(text[start:m.start()]):
            continue
        yield start, m.start()
        start = m.end()
    yield start, b


def is_quantitative(prose: str, language: str) -> bool:
    """Whether the words of a sentence (math masked) make a quantitative claim: a claim word or a
    decimal number, in a sentence of at least four words (a heading claims nothing).

    >>> is_quantitative("so ist die Lage stabil.", "German"), is_quantitative("Stabile Lage", "German")
    (True, False)
    """
    listed = claim_words().get(language)
    words = re.compile(rf"(?<![\w])(?:{listed})", re.I) if listed else None
    return len(prose.split()) >= 4 and bool((words and words.search(prose)) or _DECIMAL.search(prose))


@cache
def claim_words() -> dict[str, str]:
    """Language -> the claim words' regular expression: the package's ``claim_words.json``, extended by
    each library's ``sources/claim-words.json`` (``{"languages": {...}}``); a library's list for a
    language the package has is added to it.

    >>> sorted(claim_words())[:4]
    ['English', 'German', 'Hungarian', 'Latin']
    """
    from ..project import library_folders
    words = dict(json.loads((Path(__file__).with_name("claim_words.json")).read_text(encoding="utf-8"))["languages"])
    for folder in library_folders():
        extra = folder / "sources" / "claim-words.json"
        if extra.is_file():
            for language, pattern in json.loads(extra.read_text(encoding="utf-8"))["languages"].items():
                words[language] = f"{words[language]}|{pattern}" if language in words else pattern
    return words


@cache
def quantitative_sentences(source: str) -> tuple[Span, ...]:
    """Every sentence of *source* whose words make a quantitative claim, in text order."""
    src = get_source(source)
    text = src.text()
    intervals = math_intervals(text)
    masked = list(text)
    for a, b, _ in intervals:
        masked[a:b] = _MATH_MASK * (b - a)
    masked = "".join(masked)
    found = []
    for a, b in _segments(text, intervals):
        for s, e in _sentences(masked, a, b):
            chunk = text[s:e]
            lead = len(chunk) - len(chunk.lstrip())
            s, e = s + lead, s + len(chunk.rstrip())
            prose = masked[s:e].replace(_MATH_MASK, " ")
            if e > s and not text.startswith("#", s) and is_quantitative(prose, src.language):
                found.append(Span(source, "sentence", s, e, *line_of(text, s), text[s:e]))
    return tuple(found)


def spans(source: str) -> tuple[Span, ...]:
    """Math spans and quantitative sentences of *source*, in text order."""
    return tuple(sorted(math_spans(source) + quantitative_sentences(source), key=lambda s: (s.start, s.kind)))
