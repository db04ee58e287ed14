"""The coverage ledger: every math span and quantitative sentence of a source, quoted or waived.

A span (:mod:`symfloat.model.span`) is *quoted* when it overlaps the verbatim excerpt of a printed
formula of some derivation (the excerpt's first occurrence in the transcription).  Otherwise it is
*waived* with one reason of :data:`REASONS`: two are computed here (``bare-symbol``, ``repeat``),
the others are judgments kept as data beside the transcription, ``symfloat/sources/<key>.waivers.json``
(a list of ``{"line", "text", "reason", "note"}``, ``line`` where the span starts; a waiver covers
every span of that text on that line; ``text`` is the span verbatim, dollars included).
What is neither is *unaccounted*: a formula or a claim that no derivation checks yet.

Self-checks: a judged waiver that matches no span, or a span that is already quoted or waived
automatically, is stale and an error; so is an unknown reason.
"""
from __future__ import annotations

import json
from collections import Counter
from dataclasses import dataclass
from functools import cache
from importlib import resources

from ..model.source import SOURCES, get_source
from ..model.span import Span, spans
from ..model.tex import chains, is_bare_symbol
from ..registry import load, select

__all__ = ["REASONS", "JUDGED", "Entry", "LedgerError", "account", "ledger", "quotes", "waivers", "totals",
           "ledger_json", "ledger_table", "ledger_markdown", "baseline_keys", "entry_key", "one_line"]

REASONS = {
    "bare-symbol": "a single symbol or label, or a list of them: it states nothing (computed)",
    "repeat": "repeats a quoted formula, or a contiguous part of its chain, or a quoted sentence word for word, "
              "of the same source (computed by normalised comparison)",
    "figure-reference": "points to a figure or names a figure's points or lines; states nothing to check",
    "lost-text": "the transcription lost or garbled the passage: nothing can be read from it",
    "notation": "a naming or a construction (let x denote, draw AB perpendicular to CD): it asserts "
                "nothing that a derivation could refute",
}
JUDGED = ("figure-reference", "lost-text", "notation")


class LedgerError(ValueError):
    """A ledger that contradicts itself: a stale or malformed waiver."""


@dataclass(frozen=True)
class Entry:
    """One span and how it is accounted for: ``status`` quoted, waived or unaccounted."""

    span: Span
    status: str
    reason: str = ""
    note: str = ""
    quoted_by: tuple[str, ...] = ()

    def as_dict(self) -> dict:
        d = {"source": self.span.source, "kind": self.span.kind, "line": self.span.line, "column": self.span.column,
             "text": self.span.text, "status": self.status}
        if self.reason:
            d["reason"] = self.reason
        if self.note:
            d["note"] = self.note
        if self.quoted_by:
            d["quoted_by"] = list(self.quoted_by)
        return d


def entry_key(e: Entry | dict) -> tuple:
    """What identifies a span across runs: source, kind, line, column and text."""
    d = e.as_dict() if isinstance(e, Entry) else e
    return (d["source"], d["kind"], d["line"], d["column"], d["text"])


@cache
def quotes() -> dict[str, list[tuple[int, int, str]]]:
    """Per source, ``(start, end, formula id)`` of the first occurrence of every printed excerpt."""
    found: dict[str, list] = {k: [] for k in SOURCES}
    for did in select():
        d, _ = load(did)
        text = get_source(d.source).text()
        for p in d.printed:
            at = text.find(p.excerpt)
            found[d.source].append((at, at + len(p.excerpt), d.formula_id(p)))
    return found


def waivers(source: str) -> list[dict]:
    """The judged waivers of *source*, checked for form."""
    path = resources.files("symfloat").joinpath("sources", f"{source}.waivers.json")
    if not path.is_file():
        return []
    data = json.loads(path.read_text(encoding="utf-8"))
    for w in data:
        if set(w) != {"line", "text", "reason", "note"} or w["reason"] not in JUDGED or not w["note"].strip():
            raise LedgerError(f"{source}.waivers.json: malformed waiver {w!r}: needs line, text, a reason of "
                              f"{JUDGED} and a note")
    return data


def _sequences(tex: str) -> list[tuple[str, ...]]:
    return [tuple(row) for row in chains(tex)]


def _contains(row: tuple[str, ...], part: tuple[str, ...]) -> bool:
    """Whether *part* (members and relations, an empty end member standing for any) lies in *row* at
    member boundaries; a lone member of one or two characters (``0``, ``2b``) is too short to be a repeat."""
    if not any(part[::2]) or (len(part) == 1 and len(part[0]) < 3):
        return False
    n = len(part)
    for i in range(0, len(row) - n + 1, 2):
        window = row[i:i + n]
        if all(p == w or (p == "" and k in (0, n - 1)) for k, (p, w) in enumerate(zip(part, window))):
            return True
    return False


def account(source: str, quoted, waivers) -> tuple[Entry, ...]:
    """Every span of *source* with its status, in text order, given the quoted intervals
    ``(start, end, formula id)`` and the judged waivers."""
    all_spans = spans(source)
    by_span: dict[Span, tuple[str, ...]] = {
        s: tuple(fid for a, b, fid in quoted if s.overlaps(a, b)) for s in all_spans}
    quoted_rows = [row for s, ids in by_span.items() if ids and s.kind != "sentence" for row in _sequences(s.text)]
    quoted_sentences = {s.text for s, ids in by_span.items() if ids and s.kind == "sentence"}
    entries: dict[Span, Entry] = {}
    for s in all_spans:
        if by_span[s]:
            entries[s] = Entry(s, "quoted", quoted_by=by_span[s])
        elif s.kind != "sentence" and is_bare_symbol(s.text):
            entries[s] = Entry(s, "waived", "bare-symbol")
        elif s.kind != "sentence" and (rows := _sequences(s.text)) and all(
                any(_contains(q, r) for q in quoted_rows) for r in rows):
            entries[s] = Entry(s, "waived", "repeat")
        elif s.kind == "sentence" and s.text in quoted_sentences:
            entries[s] = Entry(s, "waived", "repeat")
    index: dict[tuple, list[Span]] = {}
    for s in all_spans:
        index.setdefault((s.line, s.text), []).append(s)
    for w in waivers:
        found = index.get((w["line"], w["text"]))
        if not found:
            raise LedgerError(f"{source}.waivers.json: no span {w['text']!r} on line {w['line']}")
        for s in found:
            if s in entries:
                raise LedgerError(f"{source}.waivers.json: the span {w['text']!r} on line {w['line']} is already "
                                  f"{entries[s].status} ({entries[s].reason or ', '.join(entries[s].quoted_by)}): "
                                  f"the waiver is stale")
            entries[s] = Entry(s, "waived", w["reason"], w["note"])
    return tuple(entries.get(s) or Entry(s, "unaccounted") for s in all_spans)


@cache
def ledger(source: str) -> tuple[Entry, ...]:
    """The ledger of *source*: its spans against the quotes of every derivation and its waivers file."""
    get_source(source)
    return account(source, quotes()[source], waivers(source))


def totals(entries) -> dict:
    """Counts: spans by kind, quoted, waived by reason, unaccounted."""
    c = Counter(e.status for e in entries)
    return {"spans": len(entries), "display": sum(e.span.kind == "display" for e in entries),
            "inline": sum(e.span.kind == "inline" for e in entries),
            "sentences": sum(e.span.kind == "sentence" for e in entries),
            "quoted": c["quoted"], "waived": dict(sorted(Counter(e.reason for e in entries
                                                                  if e.status == "waived").items())),
            "unaccounted": c["unaccounted"]}


def baseline_keys(baseline: dict) -> set[tuple]:
    """The keys of the spans a baseline file lists as pending."""
    return {entry_key(d) for d in baseline["unaccounted"]}


def ledger_json(sources) -> str:
    """``{"sources": {key: {"totals", "entries"}}}`` as indented JSON."""
    out = {k: {"totals": totals(ledger(k)), "entries": [e.as_dict() for e in ledger(k)]} for k in sources}
    return json.dumps({"sources": out}, ensure_ascii=False, indent=1) + "\n"


def one_line(text: str, width: int = 110) -> str:
    """*text* on one line, cut to *width* characters with an ellipsis."""
    one = " ".join(text.split())
    return one if len(one) <= width else one[:width - 1] + "…"


def ledger_table(sources, pending: set[tuple] = frozenset()) -> str:
    """Per source one line of totals, then every unaccounted span (``pending`` ones marked)."""
    lines = []
    for k in sources:
        t = totals(ledger(k))
        waived = ", ".join(f"{r} {n}" for r, n in t["waived"].items()) or "none"
        lines.append(f"{k}: {t['spans']} spans ({t['display']} display, {t['inline']} inline, {t['sentences']} "
                     f"sentences) — {t['quoted']} quoted, {sum(t['waived'].values())} waived ({waived}), "
                     f"{t['unaccounted']} unaccounted")
    for k in sources:
        for e in ledger(k):
            if e.status == "unaccounted":
                mark = "pending" if entry_key(e) in pending else "NEW"
                lines.append(f"  {mark:7} {k}:{e.span.line} {e.span.kind:8} {one_line(e.span.text)}")
    return "\n".join(lines) + "\n"


def _pct(n: int, d: int) -> str:
    return f"{100 * n / d:.1f} %" if d else "–"


def ledger_markdown(sources=tuple(SOURCES)) -> str:
    """``docs/coverage.md``: totals per source and kind, and the share waived per reason."""
    out = ["# Coverage ledger", "",
           "Generated by `symfloat coverage --write`. Every math span of a transcription (display and inline, as",
           "its dollars mark them) and every sentence whose words make a quantitative claim is *quoted* (it",
           "overlaps the excerpt of a printed formula of some derivation), *waived* with a reason, or",
           "*unaccounted*. The unaccounted spans are listed in `docs/coverage-baseline.json`; the tests fail",
           "on any other unaccounted span, and on a listed one that has since been accounted for.", "",
           "| source | kind | spans | quoted | waived | unaccounted | quoted share |",
           "|---|---|---:|---:|---:|---:|---:|"]
    everything = []
    for k in sources:
        es = ledger(k)
        everything += es
        for kind in ("display", "inline", "sentence"):
            sub = [e for e in es if e.span.kind == kind]
            if sub:
                c = Counter(e.status for e in sub)
                out.append(f"| {k} | {kind} | {len(sub)} | {c['quoted']} | {c['waived']} | {c['unaccounted']} | "
                           f"{_pct(c['quoted'], len(sub))} |")
    c = Counter(e.status for e in everything)
    n = len(everything)
    out += [f"| **all** | | {n} | {c['quoted']} | {c['waived']} | {c['unaccounted']} | {_pct(c['quoted'], n)} |",
            "", f"Accounted: {c['quoted'] + c['waived']} of {n} ({_pct(c['quoted'] + c['waived'], n)}).", "",
            "## Waivers by reason", "", "| reason | spans | share of all spans | meaning |", "|---|---:|---:|---|"]
    reasons = Counter(e.reason for e in everything if e.status == "waived")
    for r, meaning in REASONS.items():
        out.append(f"| `{r}` | {reasons[r]} | {_pct(reasons[r], n)} | {meaning} |")
    out += ["", "Judged waivers (`figure-reference`, `lost-text`, `notation`) live in",
            "`symfloat/sources/<key>.waivers.json`, each with the span, its line and a note.", ""]
    return "\n".join(out)
