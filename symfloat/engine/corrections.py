r"""Proposed corrections of a refuted print: the small edits of its LaTeX that make it hold.

The edits are those a compositor, an author or an OCR engine makes: a glyph read for a look-alike
(6/b, 1/l, \kappa/x, \nu/v, 3/8, a dash read as "="; the table is data, ``confusions.json``), one
digit, a sign, a relation turned round, an exponent, a subscript, a letter, a fraction bar (numerator
and denominator exchanged), two neighbours swapped.  Each edit has a cost from the table (lower is
likelier) and a kind: ``scan-like`` for a confusion of shape, ``print-like`` for the others.  The
edits are tried in order of cost, and those for which the caller's test says the print holds are
reported, likeliest first.  Only text is edited; reading and deciding are the caller's (the
allow-list reader and the identity check), so nothing here evaluates the text.

>>> from fractions import Fraction
>>> def holds(tex):             # a test for the doctest: "x = 3/4" and nothing else holds
...     return "proved" if tex.replace(" ", "") == r"x=\frac{3}{4}" else None
>>> [(c.change, c.kind) for c in corrections(r"x = \frac{3}{8}", holds, limit=3)]
[('8 → 4', 'print-like')]
>>> [(c.change, c.kind) for c in corrections(r"x - \frac{3}{4}", holds)]
[('- → =', 'scan-like')]
"""
from __future__ import annotations

import itertools
import json
import re
from dataclasses import asdict, dataclass
from pathlib import Path

from ..model.latex import token_spans
from ..model.tex import braced_end

__all__ = ["Correction", "candidates", "corrections", "CONFUSIONS"]

CONFUSIONS = json.loads((Path(__file__).with_name("confusions.json")).read_text(encoding="utf-8"))
_COST = CONFUSIONS["edits"]
_PAIRED = 40           # the likeliest single confusions that are also tried two at a time
_RELATIONS = {"<": ">", ">": "<", r"\leq": r"\geq", r"\geq": r"\leq", r"\le": r"\ge", r"\ge": r"\le"}


@dataclass(frozen=True)
class Correction:
    """One edit of the print: the corrected text, the change (``3 → 4``), what was edited (``digit``,
    ``glyph`` ...), the kind of fault it suggests (``scan-like`` or ``print-like``), its cost, and
    once tested, how the corrected print holds (``proved`` or ``sampled``)."""

    text: str
    change: str
    what: str
    kind: str
    cost: float
    status: str = ""

    def to_json(self) -> dict:
        return asdict(self)


def _replace(tex: str, start: int, end: int, new: str) -> str:
    """*tex* with ``tex[start:end]`` replaced by *new*; a command followed by a letter keeps a space."""
    after = tex[end:end + 1]
    if re.fullmatch(r".*\\[A-Za-z]+", new) and after.isalpha():
        new += " "
    return tex[:start] + new + tex[end:]


def _glyph_edits(tex, starts, ends):
    """The confusions of the table: at each occurrence, at every occurrence at once, and two at two places
    (a scan that confuses ν/μ and v/V reads "\\mu V" as "\\nu v")."""
    singles = []
    for a, b, cost in CONFUSIONS["glyphs"]:
        for old, new in ((a, b), (b, a)):
            spots = [m.start() for m in re.finditer(re.escape(old), tex)
                     if m.start() in starts and m.start() + len(old) in ends]
            singles += [(at, old, new, cost) for at in spots]
            if len(spots) > 1:
                text = tex
                for at in reversed(spots):
                    text = _replace(text, at, at + len(old), new)
                yield (text, f"{old} → {new} at all {len(spots)} places", "glyph", "scan-like",
                       cost + CONFUSIONS["every-occurrence"])
    for at, old, new, cost in singles:
        yield _replace(tex, at, at + len(old), new), f"{old} → {new}", "glyph", "scan-like", cost
    singles = sorted(singles, key=lambda e: e[3])[:_PAIRED]
    for (a1, o1, n1, c1), (a2, o2, n2, c2) in itertools.combinations(sorted(singles), 2):
        if a1 + len(o1) <= a2:
            text = _replace(_replace(tex, a2, a2 + len(o2), n2), a1, a1 + len(o1), n1)
            yield text, f"{o1} → {n1} and {o2} → {n2}", "glyph", "scan-like", c1 + c2


def _token_edits(tex, spans):
    """Digits, signs, relations, exponents, subscripts, letters, fraction bars, swapped neighbours."""
    solid = [t for t in spans if t[0] != "space"]
    letters = sorted({t[1] for t in solid if t[0] == "letter" and t[1].isascii()})
    for i, (kind, text, start, end) in enumerate(solid):
        before = solid[i - 1][1] if i else ""
        if kind == "number" and before not in ("^", "_"):
            for k, digit in enumerate(text):
                if not digit.isdigit():
                    continue
                for other in "0123456789":
                    if other != digit and not (k == 0 and other == "0" and len(text) > 1):
                        yield (_replace(tex, start + k, start + k + 1, other), f"{digit} → {other}", "digit",
                               "print-like", _COST["digit"])
                if len(text) > 1:
                    yield (_replace(tex, start + k, start + k + 1, ""), f"{text} → {text[:k] + text[k + 1:]}",
                           "digit", "print-like", _COST["digit"] + 0.5)
            for k in range(len(text) - 1):
                if text[k] != text[k + 1] and text[k].isdigit() and text[k + 1].isdigit():
                    swapped = text[:k] + text[k + 1] + text[k] + text[k + 2:]
                    yield _replace(tex, start, end, swapped), f"{text} → {swapped}", "swap", "print-like", _COST["swap"]
        if text in ("+", "-"):
            other = "-" if text == "+" else "+"
            yield _replace(tex, start, end, other), f"{text} → {other}", "sign", "print-like", _COST["sign"]
        if text in _RELATIONS:
            yield (_replace(tex, start, end, _RELATIONS[text]), f"{text} → {_RELATIONS[text]}", "relation",
                   "print-like", _COST["relation"])
        if text in ("^", "_") and i + 1 < len(solid):
            what = "exponent" if text == "^" else "subscript"
            nxt = solid[i + 1]
            digit = nxt[1][0] if nxt[0] == "number" else ""
            if digit:
                for other in "1234" if text == "^" else "01234":
                    if other != digit:
                        yield (_replace(tex, nxt[2], nxt[2] + 1, other), f"{text}{digit} → {text}{other}", what,
                               "print-like", _COST[what])
                if text == "^":
                    yield (_replace(tex, start, nxt[2] + 1, ""), f"^{digit} dropped", what, "print-like",
                           _COST[what] + 0.5)
        if kind == "letter" and before not in ("_", "^", "\\text"):
            for other in letters:
                if other != text:
                    yield _replace(tex, start, end, other), f"{text} → {other}", "letter", "print-like", _COST["letter"]
        if text in (r"\frac", r"\dfrac", r"\tfrac") and tex[end:end + 1] == "{":
            middle = braced_end(tex, end)
            if middle > 0 and tex[middle:middle + 1] == "{":
                close = braced_end(tex, middle)
                if close > 0:
                    flipped = tex[:end] + tex[middle:close] + tex[end:middle] + tex[close:]
                    yield (flipped, f"{tex[end:middle]} and {tex[middle:close]} exchanged across the fraction bar",
                           "fraction", "print-like", _COST["fraction"])
        if i + 1 < len(solid):
            nxt = solid[i + 1]
            if kind in ("letter", "number") and nxt[0] in ("letter", "number") and text != nxt[1] \
                    and before not in ("_", "^"):
                swapped = tex[:start] + nxt[1] + tex[end:nxt[2]] + text + tex[nxt[3]:]
                yield swapped, f"{text}{nxt[1]} → {nxt[1]}{text}", "swap", "print-like", _COST["swap"]


def candidates(tex: str) -> list[Correction]:
    r"""Every single edit of *tex*, likeliest first (then by where it falls); one entry per distinct text.

    >>> [c.change for c in candidates("x = 6 b")][:4]
    ['6 → b', 'b → 6', 'x → \\kappa', '= → -']
    """
    spans = token_spans(tex)
    starts, ends = {t[2] for t in spans}, {t[3] for t in spans}
    best: dict[str, tuple] = {}
    for order, (text, change, what, kind, cost) in enumerate(
            [*_glyph_edits(tex, starts, ends), *_token_edits(tex, spans)]):
        if text != tex and (text not in best or cost < best[text][0]):
            best[text] = (cost, order, change, what, kind)
    ranked = sorted(best.items(), key=lambda kv: (kv[1][0], kv[1][1]))
    return [Correction(text, change, what, kind, cost) for text, (cost, _, change, what, kind) in ranked]


def corrections(tex: str, holds, *, limit: int = 3, budget: int = 2000) -> list[Correction]:
    """The likeliest edits of *tex* that make it hold: at most *limit*, from the first *budget* candidates.

    *holds(text)* is the caller's test of a corrected print: ``"proved"`` or ``"sampled"`` when it holds,
    a false value otherwise (an unreadable text does not hold)."""
    found = []
    for c in candidates(tex)[:budget]:
        status = holds(c.text)
        if status:
            found.append(Correction(c.text, c.change, c.what, c.kind, c.cost, status))
            if len(found) >= limit:
                break
    return found
