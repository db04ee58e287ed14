"""A derivation's words name its steps and printed formulas as a reader finds them, not by their program names.

A note, an erratum's evidence or a witness's description may point to another step or printed formula of the
derivation by the name the derivation module gives it (``see 'slab-a-c'``, ``(step moment-y)``, ``booked at
duhamel-18``), or to one of another derivation (``scheeffer-i-iii:righting-moment-12``,
``graefe-s2-volumes-simpson/simpson-rule``, ``(scheeffer-iv-v (33))``).  A reader sees the notebook's numbering
instead: *step 7* (the notebook's ``### Step 7``), *formula (104)*, *formula 3 of §216* (the heading of a printed
formula whose place several share), and another derivation by its source and place, *Scheeffer I-III*.

Only names with a hyphen are program names (``duhamel-18``); a one-word name (``lemma``, ``remark``) is also a
word, and so is a hyphenated name after an article (*the five mid-sections*, *the heeled V-prism*), unless it is
quoted or follows the word *step*.  A name in a code span (````symfloat verify euler-192-219````, a command to
run) stays.

>>> readable_in("graefe-s2-volumes-simpson", "see 'slab-a-c'; as in scheeffer-i-iii:moment-13")
"see formula 1 of §2 Simpson's rule; as in Scheeffer I-III, formula (13)"
>>> readable_in("scheeffer-x", "(step moment-y) of ``symfloat verify scheeffer-x``")
'(step moment-y) of ``symfloat verify scheeffer-x``'
"""
from __future__ import annotations

import re
from functools import cache

from ..model.source import SOURCES
from ..registry import ids, load

__all__ = ["readable_in"]


def _derivation_label(derivation_id: str) -> str:
    d = load(derivation_id)[0]
    return f"{SOURCES[d.source].author.split()[-1]} {d.locator}"


@cache
def _own(derivation_id: str) -> dict:
    """name -> (its label as a step, its label as a printed formula), either ``None``: a printed formula by its
    place (numbered when several share it), a step by its number; program names only (with a hyphen)."""
    d = load(derivation_id)[0]
    steps = {s.name: f"step {i}" for i, s in enumerate(d.steps, 1)}
    formulas = {}
    for p in d.printed:
        same = [q for q in d.printed if q.locator == p.locator]
        formulas[p.name] = f"formula {p.locator}" if len(same) == 1 else f"formula {same.index(p) + 1} of {p.locator}"
    return {name: (steps.get(name), formulas.get(name)) for name in {*steps, *formulas} if "-" in name}


# an article, and at most one word, before a name: the name is a word of the sentence (a hyphenated noun)
_ARTICLE = re.compile(r"\b(?:[Tt]he|an?)\s+(?:[\w²³]+\s+)?$")


def _alternatives(names) -> str:
    return "|".join(re.escape(n) for n in sorted(names, key=len, reverse=True))


@cache
def _pattern(derivation_id: str) -> re.Pattern:
    own = _own(derivation_id)
    theirs = {n for other in ids() for n in _own(other)}
    return re.compile(rf"(?<![\w-])(?P<step>(?:the )?steps? )?(?P<q>'?)(?:(?P<other>{_alternatives(ids())})"
                      rf"(?:[:/](?P<name>{_alternatives(theirs)}))?|(?P<own>{_alternatives(own) or '(?!)'}))"
                      r"(?P=q)(?![\w-])")


def _label(labels: tuple, step: str | None) -> str | None:
    """A name's label: as a step after the word *step* (which the label then replaces), else as a formula."""
    as_step, as_formula = labels
    if step and as_step:
        return step.replace("steps ", "").replace("step ", "") + as_step
    return (step or "") + (as_formula or as_step)


def readable_in(derivation_id: str, text: str) -> str:
    """*text*, words of the derivation *derivation_id*, with the program names it cites replaced by what a reader
    finds in the notebooks (see the module); code spans as they are."""
    if not text or "-" not in text:
        return text
    pattern, own = _pattern(derivation_id), _own(derivation_id)

    def one(m: re.Match) -> str:
        if not (m.group("q") or m.group("step")) and _ARTICLE.search(m.string, 0, m.start()):
            return m.group(0)               # "the five mid-sections", "the heeled V-prism": words, not names
        if m.group("own"):
            return _label(own[m.group("own")], m.group("step"))
        where = _derivation_label(m.group("other"))
        name = m.group("name")
        theirs = _own(m.group("other")).get(name) if name else None
        if name and theirs is None:
            return m.group(0)
        return (m.group("step") or "") + where + (f", {_label(theirs, None)}" if theirs else "")

    pieces = re.split(r"(``[^`]+``|`[^`]+`)", text)
    return "".join(piece if k % 2 else pattern.sub(one, piece) for k, piece in enumerate(pieces))
