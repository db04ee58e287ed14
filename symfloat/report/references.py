"""Cross-references of every source to its equations, paragraphs and figures, resolved and checked (issue 12, item 3).

Targets: the displays a transcription tags (``\\quad (78c)``, ``(78c)`` closing a display) are equations; a line
opening with ``§. N`` is Euler's paragraph N; ``Fig. N`` points to a figure, which no transcription carries.
References: a number after ``Gleichung``, ``Gl.``, ``nach``/``Nach``, ``aus``, ``s.``, ``vgl.``,
``Bedingung(en)``, or in ``in N ein``, with its ``u.``/``und``/comma lists (Scheeffer); ``§. N`` inside a
paragraph, ``per §. N`` (Euler); ``Fig. N``/``Figur N`` (all).  Each is resolved (an equation to the first display
tagged with the number, ``52`` also to ``52a`` when no ``52`` is tagged) and checked against the derivations:

* ``wrong``: a quote that covers the reference books an erratum that corrects its number (a misprint of the
  original); a quote whose note says the number means another one *without* an erratum is a failed self-check;
* ``resolved``: the target precedes the reference, and both the referring passage and the target are quoted by
  the derivations (so the use is checked there), and the steps behind a quote that cites it do not miss the
  steps behind the target's quote (:func:`uses_target`);
* ``plausible``: the target precedes, but a side is not quoted: the derivations cannot confirm the use;
* ``suspect``: no target (a figure the transcription lacks, a number no display carries), a target that comes
  later, or a cited formula the citing quote's steps do not use, directly or through their chain: listed,
  never passed.

The steps behind a quote are the step of the same name and the steps that establish a quantity of its reading;
a step reaches the steps it ``uses`` and those that establish the quantities its claim mentions.  A citing quote
whose steps rest on nothing is not judged.
"""
from __future__ import annotations

import re
from functools import cache

from ..model.source import SOURCES, get_source
from ..model.span import line_of, math_intervals

__all__ = ["STATUSES", "tags", "paragraphs", "references", "check", "anchors", "uses_target", "references_markdown"]

STATUSES = ("resolved", "plausible", "suspect", "wrong")

_TAG = re.compile(r"(?:\\quad\s*|\\qquad\s*|\\tag\{)\(?(\d{1,3}\s?[a-e]?)\)?\}?\s*\$\$$|\((\d{1,3}\s?[a-e]?)\)\s*\$\$$")
_NUMBER = r"\(?\d{1,3}(?: ?[a-e](?![a-zäöü]))?\)?(?![\d,]\d)"
_LIST = rf"{_NUMBER}(?:\s*(?:,|u\.|und)\s*{_NUMBER})*"
_EQUATION = re.compile(rf"(?<!\w)(?P<lead>Gleichung(?:en)?|Gl\.|[Nn]ach|aus|s\.|vgl\.|Bedingung(?:en)?)[ \t]*\n?[ \t]*(?P<nums>{_LIST})"
                       rf"(?!\s*(?:°|cm|mm|Teile|Grad|Seiten|Mal|mal|Jahr))"
                       rf"|(?P<lead2>in)\s+(?P<nums2>{_LIST})\s+ein")
_FIGURE = re.compile(r"(?P<lead>Fig\.|Figur)\s*(?P<nums>\d{1,2}(?:\s*(?:,|u\.|und)\s*\d{1,2})*)")
_PARAGRAPH = re.compile(r"(?P<lead>(?:per\s+)?§\.?)\s*(?P<nums>\d{3})")
_MEANS = re.compile(r"'(?:[Nn]ach |in )?(\d{1,3}\s?[a-e]?)\)?'[^.;]*?\b(?:means|the equation is) \(?(\d{1,3}[a-e]?)\)?")


def _key(number: str) -> str:
    return number.replace(" ", "").strip("()")


@cache
def tags(source: str) -> dict[str, tuple[int, int, int]]:
    """Equation number -> (line, start, end) of the first display that carries it."""
    text = get_source(source).text()
    out: dict[str, tuple[int, int, int]] = {}
    for a, b, kind in math_intervals(text):
        m = _TAG.search(text[a:b])
        if m:
            out.setdefault(_key(m.group(1) or m.group(2)), (line_of(text, a)[0], a, b))
    return out


@cache
def paragraphs(source: str) -> dict[str, tuple[int, int, int]]:
    """Euler's paragraph number -> (line, start, end) of the paragraph (a line that opens with ``§. N``)."""
    text = get_source(source).text()
    heads = [(m.group(1), m.start()) for m in re.finditer(r"^(?:Tab\.\s*[IVX]+\.\s*)?§\.?\s*(\d{3})", text, re.M)]
    out: dict[str, tuple[int, int, int]] = {}
    for i, (n, a) in enumerate(heads):
        b = heads[i + 1][1] if i + 1 < len(heads) else len(text)
        out.setdefault(n, (line_of(text, a)[0], a, b))
    return out


@cache
def _captions(source: str) -> dict[str, tuple[int, int, int]]:
    """Figure number -> (line, start, end) of a line that carries only its caption (``Fig. 3a``)."""
    text = get_source(source).text()
    out: dict[str, tuple[int, int, int]] = {}
    for m in re.finditer(r"^[ \t]*Fig\.\s*(\d{1,2})[a-z]?[ \t]*$", text, re.M):
        out.setdefault(m.group(1), (line_of(text, m.start())[0], m.start(), m.end()))
    return out


def _next_head(text: str, offset: int) -> str | None:
    m = re.compile(r"^(?:Tab\.\s*[IVX]+\.\s*)?§\.?\s*(\d{3})", re.M).search(text, offset)
    return m.group(1) if m else None


def _prose(text: str) -> str:
    masked = list(text)
    for a, b, _ in math_intervals(text):
        masked[a:b] = " " * (b - a)
    return "".join(masked)


def _found(source: str):
    """(kind, start, end, matched text, number) of every reference of *source*, in text order."""
    text = get_source(source).text()
    prose = _prose(text)
    out = []
    for m in _EQUATION.finditer(prose):
        nums = m.group("nums") or m.group("nums2")
        for n in re.findall(r"\d{1,3}(?: ?[a-e](?![a-zäöü]))?", nums):
            out.append(("equation", m.start(), m.end(), m.group(0), _key(n)))
    for m in _FIGURE.finditer(prose):
        bol, eol = prose.rfind("\n", 0, m.start()) + 1, prose.find("\n", m.end())
        if not (prose[bol:m.start()] + prose[m.end():eol]).strip(" \ta"):
            continue                              # a caption standing alone: where the figure would be
        for n in re.findall(r"\d{1,2}", m.group("nums")):
            out.append(("figure", m.start(), m.end(), m.group(0), n))
    for m in _PARAGRAPH.finditer(text):
        bol, eol = text.rfind("\n", 0, m.start()) + 1, text.find("\n", m.end())
        heading = not re.sub(r"Tab\.\s*[IVX]+\.", "", text[bol:m.start()]).strip()
        # a heading set at the end of the previous paragraph's last line ("... $Oc = c$. §. 221.", then §. 221)
        moved = text[m.end():eol].strip() in ("", ".") and _next_head(text, eol) == m.group("nums")
        if not heading and not moved:
            out.append(("paragraph", m.start(), m.end(), m.group(0), m.group("nums")))
    return sorted(out, key=lambda r: (r[1], r[4]))


@cache
def _quotes(source: str) -> list[tuple[int, int, str, object]]:
    """(start, end, formula id, printed formula) of every quote of *source* (first occurrence of its excerpt)."""
    from ..registry import load, select
    text = get_source(source).text()
    out = []
    for did in select():
        d, _ = load(did)
        if d.source != source:
            continue
        for p in d.printed:
            at = text.find(p.excerpt)
            if at >= 0:
                out.append((at, at + len(p.excerpt), d.formula_id(p), p))
    return out


def _symbols(claim) -> set:
    if claim is None:
        return set()
    from ..model.claim import expressions
    import sympy as sp
    return set().union(*(sp.sympify(m).free_symbols for m in expressions(claim)))


@cache
def _derivation(did: str):
    from ..registry import load
    return load(did)[0]


def anchors(did: str, printed) -> set[tuple[str, str]]:
    """The steps ``(derivation id, step name)`` behind a quote: the step of its name and those establishing a
    quantity of its reading."""
    d = _derivation(did)
    used = _symbols(printed.reading)
    return {(did, st.name) for st in d.steps if st.name == printed.name or st.result is not None and st.result in used}


def _edges(did: str, name: str) -> set[tuple[str, str]]:
    """What the step *name* of *did* rests on: its ``uses``, and the earlier steps establishing its quantities."""
    d = _derivation(did)
    at = next(i for i, st in enumerate(d.steps) if st.name == name)
    st = d.steps[at]
    out = {tuple(u.split(":", 1)) if ":" in u else (did, u) for u in st.uses}
    mentioned = _symbols(st.claim) - ({st.result} if st.result is not None else set())
    return out | {(did, e.name) for e in d.steps[:at] if e.result is not None and e.result in mentioned}


def uses_target(use: set, target: set) -> bool | None:
    """Whether the steps *use* reach the steps *target* through their uses and quantities; None when the use
    has no step that rests on anything (nothing to check)."""
    if use & target:
        return True
    if not use or not target or not any(_edges(*u) for u in use):
        return None
    seen, todo = set(), list(use)
    while todo:
        node = todo.pop()
        if node in target:
            return True
        if node in seen:
            continue
        seen.add(node)
        try:
            todo += _edges(*node)
        except (StopIteration, KeyError, ValueError):      # a step of a derivation not loaded here
            continue
    return False


def _judged(number: str, lead: str, covering) -> tuple[str, str, str]:
    """What the quotes covering a reference say of its number: ("wrong", formula id, erratum) when an erratum
    corrects it, ("unbooked", id, note) when a note says it means another number without one, else ("", "", "")."""
    for a, b, fid, p in covering:
        err = p.erratum
        if err is not None and lead in err.corrected and number not in re.findall(r"\d{1,3}[a-e]?",
                                                                                   err.corrected.replace(" ", "")):
            return "wrong", fid, f"{err.kind}, {err.confidence}: {err.corrected}"
    for a, b, fid, p in covering:
        means = [m.group(2) for m in _MEANS.finditer(p.note or "") if _key(m.group(1)) == number]
        if means and any(m != number for m in means):
            return "unbooked", fid, p.note
    return "", "", ""


def references(source: str) -> list[dict]:
    """Every reference of *source* with its target and status (see the module docstring)."""
    text = get_source(source).text()
    quotes = _quotes(source)
    equations, sections = tags(source), paragraphs(source)
    out = []
    for kind, a, b, matched, number in _found(source):
        line = line_of(text, a)[0]
        if kind == "equation":
            target = equations.get(number) or min(
                (v for k, v in equations.items() if re.fullmatch(rf"{number}[a-e]", k)), default=None)
        elif kind == "paragraph":
            target = sections.get(number)
        else:
            target = _captions(source).get(number)
        covering = [q for q in quotes if q[0] < b and a < q[1]]
        verdict, by, why = _judged(number, matched.split()[0], covering)
        if verdict == "wrong":
            status, reason = "wrong", f"erratum {by} ({why})"
        elif verdict == "unbooked":
            status, reason = "wrong", f"UNBOOKED: {by} says {why!r}"
        elif target is None:
            status = "suspect"
            reason = ("the figure is not in the transcription" if kind == "figure" else
                      "no display carries the number: lost in the transcription, or a wrong reference")
        elif kind == "figure":
            status, reason = "suspect", f"only the caption survives (line {target[0]}): the figure is not transcribed"
        elif target[0] > line and not (kind == "paragraph" and target[1] < a):
            status, reason = "suspect", "the target comes later"
        else:
            targets = [q for q in quotes if q[0] < target[2] and target[1] < q[1]]
            uses = covering or [q for q in quotes if line_of(text, q[0])[0] == line]
            at_target, at_use = [q[2] for q in targets], [q[2] for q in uses]
            reached = [uses_target(_anchors(u), set().union(*(_anchors(t) for t in targets))) for u in uses] \
                if targets else []
            if at_target and at_use and False in reached and True not in reached:
                status, u = "suspect", uses[reached.index(False)]
                reason = (f"target quoted by {at_target[0]}, but the steps behind {u[2]} "
                          f"({', '.join(sorted(n for _, n in _anchors(u)))}) do not rest on the steps behind "
                          f"it ({', '.join(sorted(n for _, n in set().union(*(_anchors(t) for t in targets)))) or '–'})")
            elif at_target and at_use:
                status, reason = "resolved", f"target quoted by {at_target[0]}, use by {at_use[0]}"
            else:
                status = "plausible"
                reason = "the target is not quoted" if not at_target else "the passage that uses it is not quoted"
        out.append({"source": source, "line": line, "kind": kind, "reference": " ".join(matched.split()),
                    "number": number, "target_line": target[0] if target else None, "status": status,
                    "reason": reason})
    return out


def _anchors(q) -> set:
    return anchors(q[2].rsplit("/", 1)[0], q[3])


def check(refs) -> list[str]:
    """The failed self-checks: references the derivations call wrong with no erratum booked."""
    return [f"{r['source']} line {r['line']}: {r['reference']!r}: {r['reason']}" for r in refs
            if r["reason"].startswith("UNBOOKED")]


def references_markdown(sources=tuple(SOURCES)) -> str:
    """``docs/references.md``: every reference of every source with its status, suspect and wrong ones first."""
    from .labels import labels_markdown
    out = ["# Cross-references of the sources", "",
           "Generated by `symfloat coverage --write` (`symfloat/report/references.py`). A reference is an equation",
           "number after *Gleichung*, *Gl.*, *nach*, *aus*, *s.*, *vgl.*, *Bedingung* or in *in N ein*, a figure",
           "(*Fig. N*) or Euler's paragraph (*§. N* inside a paragraph). Status: **resolved** (target before the use,",
           "both quoted by the derivations, the citing quote's steps not missing the target's), **plausible** (target",
           "before the use, a side unquoted), **suspect** (no target in the transcription, a later one, or a target",
           "the citing quote's steps do not rest on, through their `uses` or the quantities they mention: undecided),",
           "**wrong** (an erratum corrects the number).", "",
           "| source | references | resolved | plausible | suspect | wrong |", "|---|---:|---:|---:|---:|---:|"]
    everything = {s: references(s) for s in sources}
    for s, refs in everything.items():
        counts = [sum(r["status"] == st for r in refs) for st in STATUSES]
        out.append(f"| {s} | {len(refs)} | " + " | ".join(map(str, counts)) + " |")
    order = {"wrong": 0, "suspect": 1, "plausible": 2, "resolved": 3}
    for s, refs in everything.items():
        if not refs:
            continue
        out += ["", f"## {s}", "", "| line | reference | number | target line | status | why |",
                "|---:|---|---|---:|---|---|"]
        for r in sorted(refs, key=lambda r: (order[r["status"]], r["line"], r["number"])):
            why = r["reason"].replace("|", "\\|").replace("\n", " ")
            out.append(f"| {r['line']} | {r['reference']} | {r['number']} | {r['target_line'] or '–'} | "
                       f"{r['status']} | {why} |")
    return "\n".join(out) + "\n\n" + labels_markdown(sources)
