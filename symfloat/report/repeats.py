"""One fault, one erratum: repeats of a fault booked once and referenced, with the same kind and confidence.

An erratum that repeats a fault booked elsewhere names the booking erratum in ``same_as``
(:class:`symfloat.model.erratum.Erratum`).  :func:`link_problems` checks every such link: the target
exists, carries an erratum, is itself no repeat, and has the same kind and confidence.

:func:`candidates` finds repeats that are not linked yet: an erratum whose evidence says the fault is
the same as elsewhere ("as in (86a)", "the same ... as in ex6-ratio", "again in §226") is paired with
the errata it names (by printed name or equation number of its locator, else by paragraph, within
the same source).  Each candidate says whether kind and confidence agree; the list is the work of the
second pass (issue 12, item 5).
"""
from __future__ import annotations

import json
import re

from ..registry import load, select

__all__ = ["errata_index", "link_problems", "candidates", "candidates_text"]

_REPEAT = re.compile(r"(?:\bas in\b|\bas at\b|\bsame\b[^.;]{0,80}?\bas\b|\bagain\b(?: in)?|\brepeat\w*\b|"
                     r"\brecurs\b(?: in)?)([^.;]{0,80})", re.I)
_EQUATION = re.compile(r"\((\d+[a-e]?)\)")
_PARAGRAPH = re.compile(r"§\s?(\d+)")


def errata_index() -> dict[str, tuple[str, object]]:
    """Formula id -> (source, printed) for every printed formula that declares an erratum."""
    out = {}
    for did in select():
        d, _ = load(did)
        for p in d.printed:
            if p.erratum is not None:
                out[d.formula_id(p)] = (d.source, p)
    return out


def link_problems(index=None) -> list[str]:
    """Every ``same_as`` link that does not hold, as a message naming both formulas."""
    index = errata_index() if index is None else index
    problems = []
    for fid, (_, p) in index.items():
        target = p.erratum.same_as
        if not target:
            continue
        if target not in index:
            problems.append(f"{fid}: same_as {target!r} names no formula with an erratum")
            continue
        t = index[target][1].erratum
        if t.same_as:
            problems.append(f"{fid}: same_as {target!r}, which is itself a repeat of {t.same_as!r}: "
                            "book the fault once")
        if (t.kind, t.confidence) != (p.erratum.kind, p.erratum.confidence):
            problems.append(f"{fid}: {p.erratum.kind}/{p.erratum.confidence}, but the fault it repeats ({target}) is "
                            f"{t.kind}/{t.confidence}")
    return problems


def _named(ref: str, source: str, own: str, index) -> list[str]:
    """Formula ids with an erratum in *source* that the words *ref* name."""
    equations = set(_EQUATION.findall(ref))
    paragraphs = set(_PARAGRAPH.findall(ref))
    others = [(fid, p) for fid, (src, p) in index.items() if src == source and fid != own]
    exact = [fid for fid, p in others
             if (len(name := fid.split("/", 1)[1]) > 1 and re.search(rf"(?<![\w-]){re.escape(name)}(?![\w-])", ref))
             or equations & set(_EQUATION.findall(p.locator))]
    if exact:
        return exact
    return [fid for fid, p in others if paragraphs & set(_PARAGRAPH.findall(p.locator))]


def candidates(index=None) -> list[dict]:
    """Pairs (erratum, the erratum its evidence calls the same fault) that no ``same_as`` links."""
    index = errata_index() if index is None else index
    out = []
    for fid, (source, p) in index.items():
        for m in _REPEAT.finditer(p.erratum.evidence):
            for other in _named(m.group(1), source, fid, index):
                o = index[other][1].erratum
                if p.erratum.same_as == other or o.same_as == fid:
                    continue
                pair = {"erratum": fid, "same_as": other, "phrase": m.group(0).strip(),
                        "consistent": (o.kind, o.confidence) == (p.erratum.kind, p.erratum.confidence),
                        "kinds": [f"{p.erratum.kind}/{p.erratum.confidence}", f"{o.kind}/{o.confidence}"]}
                if pair not in out:
                    out.append(pair)
    return out


def candidates_text(index=None) -> str:
    """The unlinked repeats as JSON (``docs/repeats.json``)."""
    return json.dumps({"note": "Errata whose evidence calls their fault the same as another erratum's, not yet "
                               "linked by same_as (issue 12, item 5). 'consistent' says whether kind and "
                               "confidence agree.", "candidates": candidates(index)},
                      ensure_ascii=False, indent=1) + "\n"
