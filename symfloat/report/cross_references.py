"""A derivation's words name its steps and printed formulas as a reader finds them, not by their program names.

A note, an erratum's evidence or a reason may point to another step or printed formula of the derivation by the
name the derivation module gives it (``see 'slab-a-c'``, ``(step moment-y)``, ``booked at duhamel-18``), or to
one of another derivation (``scheeffer-i-iii:righting-moment-12``, ``graefe-s2-volumes-simpson/simpson-rule``,
``(scheeffer-iv-v (33))``).  A reader sees the notebook's numbering instead: *step 7* (the notebook's
``### Step 7``), *formula (104)*, *formula 3 of §216* (the heading of a printed formula whose place several
share), and another derivation by its source and place, *Scheeffer I-III*.

The labels come from the engine's report on the derivation (:class:`~symfloat.engine.check.DerivationReport`: its
steps in order, its printed formulas with their places), which the record and the errata hold already, or from the
derivation itself, which a notebook holds: no module is imported for them; another derivation's report is asked of
the runner (from the cache) only when the words name it and it is not at hand.

Only names with a hyphen are program names (``duhamel-18``); a one-word name (``lemma``, ``remark``) is also a
word, and so is a hyphenated name after an article (*the five mid-sections*, *the heeled V-prism*), unless it is
quoted or follows the word *step*.  A name in a code span (````symfloat verify euler-192-219````, a command to
run) stays.

>>> from symfloat.registry import statements
>>> readable(statements("graefe-s2-volumes-simpson"), "see 'slab-a-c', not ``slab-a-c``")
"see formula 1 of §2 Simpson's rule, not ``slab-a-c``"
"""
from __future__ import annotations

import re
from collections import Counter
from functools import cache

from ..model.source import SOURCES
from ..registry import ids

__all__ = ["readable", "derivation_label"]

# an article, and at most one word, before a name: the name is a word of the sentence (a hyphenated noun)
_ARTICLE = re.compile(r"\b(?:[Tt]he|an?)\s+(?:[\w²³]+\s+)?$")


def labels(of) -> dict:
    """name -> (its label as a step, its label as a printed formula), either ``None``, for the program names
    (with a hyphen) of a derivation, given by the engine's report on it or by the derivation itself: a step by
    its number, a printed formula by its place (numbered when several share it)."""
    if hasattr(of, "formulas"):                                 # a DerivationReport
        printed = [(f.id.split("/", 1)[1], f.locator) for f in of.formulas]
    else:
        printed = [(p.name, p.locator) for p in of.printed]
    steps = {s.name: f"step {i}" for i, s in enumerate(of.steps, 1)}
    sharing, seen, formulas = Counter(place for _, place in printed), Counter(), {}
    for name, place in printed:
        seen[place] += 1
        formulas[name] = f"formula {place}" if sharing[place] == 1 else f"formula {seen[place]} of {place}"
    return {name: (steps.get(name), formulas.get(name)) for name in {*steps, *formulas} if "-" in name}


def derivation_label(of) -> str:
    """A derivation (its report, or itself) as a reader finds it: its source and place, *Scheeffer IX*."""
    return f"{SOURCES[of.source].short} {of.locator}"


def _alternatives(names) -> str:
    return "|".join(re.escape(n) for n in sorted(names, key=len, reverse=True))


@cache
def _pattern(own: frozenset) -> re.Pattern:
    """A cited name: of another derivation (its id, then ``:`` or ``/`` and a name), or of this one."""
    return re.compile(rf"(?<![\w-])(?P<step>(?:the )?steps? )?(?P<q>'?)(?:(?P<other>{_alternatives(ids())})"
                      rf"(?:[:/](?P<name>[A-Za-z0-9]+(?:-[A-Za-z0-9]+)*))?|(?P<own>{_alternatives(own) or '(?!)'}))"
                      r"(?P=q)(?![\w-])")


def _label(both: tuple, step: str | None) -> str:
    """A name's label: as a step after the word *step* (which the label then replaces), else as a formula."""
    as_step, as_formula = both
    if step and as_step:
        return step.replace("steps ", "").replace("step ", "") + as_step
    return (step or "") + (as_formula or as_step)


def _report(derivation_id: str, reports: dict):
    if derivation_id not in reports:
        from ..engine.runner import verify
        reports.update({r.id: r for r in verify(derivation_id)})
    return reports[derivation_id]


def readable(of, text: str, reports: dict | None = None) -> str:
    """*text*, words of a derivation (given by the engine's report on it, or by itself), with the program names
    it cites replaced by what a reader finds in the notebooks (see the module); *reports*: other derivations'
    reports by id, where at hand."""
    if not text or "-" not in text:
        return text
    own = labels(of)
    reports = dict(reports or {})
    pattern = _pattern(frozenset(own))

    def one(m: re.Match) -> str:
        if not (m.group("q") or m.group("step")) and _ARTICLE.search(m.string, 0, m.start()):
            return m.group(0)               # "the five mid-sections", "the heeled V-prism": words, not names
        if m.group("own"):
            return _label(own[m.group("own")], m.group("step"))
        other = _report(m.group("other"), reports)
        name = m.group("name")
        theirs = labels(other).get(name) if name else None
        if name and theirs is None:
            return m.group(0)
        return (m.group("step") or "") + derivation_label(other) + (f", {_label(theirs, None)}" if theirs else "")

    pieces = re.split(r"(``[^`]+``|`[^`]+`)", text)
    return "".join(piece if k % 2 else pattern.sub(one, piece) for k, piece in enumerate(pieces))
