"""Spans of a transcription: its math, as the transcription marks it, and its quantitative sentences.

The transcriptions mark mathematics with TeX dollars: ``$$...$$`` for a displayed formula (it may
run over several lines), ``$...$`` for inline math within one line.  An inline formula that stands
alone on its line (the web lesson writes its displays so) counts as a display.  Every ``$`` must
pair up; a stray one is an error, since it would shift every later span.

A *quantitative sentence* is a sentence whose words (its math masked) assert a range, a count, an
inequality, a monotonicity, an identity, a stability or a decimal number: the claims in words.
The word lists are per language and deliberately broad; what they catch is accounted for in the
ledger (:mod:`symfloat.report.ledger`), quoted or waived, never dropped.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache

from .source import get_source

__all__ = ["Span", "KINDS", "math_intervals", "math_spans", "is_quantitative", "quantitative_sentences", "spans",
           "line_of"]

KINDS = ("display", "inline", "sentence")

_DISPLAY = re.compile(r"\$\$(.+?)\$\$", re.S)
_INLINE = re.compile(r"\$([^$\n]+?)\$")

# Words that make a sentence quantitative, by language (lower case, matched at a word start).
_CLAIM_WORDS = {
    "German": r"grö(?:ss|ß)er|kleiner|zwischen|mindestens|höchstens|positiv|negativ|null\b|unendlich|"
              r"maxim|minim|wächst|wachsen|zunimmt|zunehm|abnimmt|abnehm|desto|um so|identisch|"
              r"übereinstimm|stabil(?:e[nmrs]?)?\b|labil(?:e[nmrs]?)?\b|indifferent|wurzel|lösung|schnittpunkt|"
              r"gleichgewichtslagen|immer|stets|genau|einzig|keine|beide|"
              r"(?:zwei|drei|vier|fünf|sechs|sieben|acht|neun|zehn)(?:e[nr]?)?\b",
    "Latin": r"maior|minor|aequal|aequat|dupl|tripl|quadrupl|cresc|decresc|augeri|minu[ie]|stabil(?:is|e|em)\b|"
             r"labil(?:is|e|em)\b|"
             r"indifferen|euanesc|evanesc|positiv|negativ|infinit|maxim|minim|radic|semper|nunquam|"
             r"congru|(?:duae|duo|tres|tria|quatuor|quinque|sex)\b|proportion|inuers|invers",
    "Hungarian": r"nagyobb|kisebb|között|egyenl|azonos|stabil\b|labil\b|instabil\b|pozitív|negatív|minimál|"
                 r"maximál|legalább|legfeljebb|kettő|két\b|három|négy|gyök|megoldás",
}
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


def math_intervals(text: str) -> list[tuple[int, int, str]]:
    """(start, end, kind) of every math span; raises on a ``$`` that pairs with nothing.

    >>> math_intervals("a $x$ b\\n$$y = 1$$\\n$z$\\n")
    [(2, 5, 'inline'), (8, 17, 'display'), (18, 21, 'display')]
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
    return sorted(found)


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
    words = re.compile(rf"(?<![\w])(?:{_CLAIM_WORDS[language]})", re.I)
    return len(prose.split()) >= 4 and bool(words.search(prose) or _DECIMAL.search(prose))


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
