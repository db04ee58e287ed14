"""Cross-references of every source to its equations, paragraphs and figures, resolved and checked (issue 12, item 3).

Targets: the displays a transcription tags (``\\quad (78c)``, ``(78c)`` or ``(38^*)`` closing a display) are
equations; a line opening with ``§. N`` is Euler's paragraph N; ``Fig. N`` points to a figure, of which no
transcription carries more than a caption standing alone on its line (``Fig. 3a``, ``Fig. 1.``: no reference).
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
* ``figure lost``: a figure, whose caption survives or not; what the text still checks is checked
  (:func:`_figure_status`): a surviving caption names no point the text does not name with the figure, and a
  reference back to the figure of an earlier section names only points that section names;
* ``target lost``: the transcription lost the display that carried the number (judged, below);
* ``suspect``: no target (a number no display carries), a target that comes later, a cited formula the citing
  quote's steps do not use, directly or through their chain, or a figure whose labels fail the check.

A ``suspect``, ``figure lost`` or ``plausible`` reference may be decided by a judgement kept as data,
``symfloat/sources/<key>.references.json`` (:func:`judged`): resolved to a target line, wrong (naming the
erratum that books it) or target lost, with the passage quoted verbatim and a one-line reason that quotes what the
target gives and what the citing sentence takes from it.  A ``plausible`` reference has a target the rules found,
so it is judged resolved or wrong only.  An entry that no longer matches (no such reference, a reference the rules
decide by themselves, a passage not on its line or without the number's tag, an erratum that does not exist, a
found target judged lost) fails :func:`check`, as does a reference with no status.

The steps behind a quote are the step of the same name and the steps that establish a quantity of its reading;
a step reaches the steps it ``uses`` and those that establish the quantities its claim mentions.  A citing quote
whose steps rest on nothing is not judged.
"""
from __future__ import annotations

import json
import re
from functools import cache
from importlib import resources

from ..model.source import SOURCES, get_source
from ..model.span import line_of, math_intervals

__all__ = ["STATUSES", "JUDGEABLE", "VERDICTS", "tags", "paragraphs", "references", "judged", "stale", "check",
           "anchors", "uses_target", "status_counts", "references_markdown"]

STATUSES = ("resolved", "plausible", "figure lost", "target lost", "wrong", "suspect")
JUDGEABLE = ("suspect", "figure lost", "plausible")   # the statuses a judged entry may decide
VERDICTS = ("resolved", "wrong", "target lost", "figure lost")  # what a judged entry may say

_TAG = re.compile(r"(?:\\quad\s*|\\qquad\s*|\\tag\{)\(?(\d{1,3}\s?[a-e]?)\)?\}?\s*\$\$$|\((\d{1,3}\s?[a-e]?)(?:\^\*)?\)\s*\$\$$")
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
    for m in re.finditer(r"^[ \t]*Fig\.\s*(\d{1,2})[a-z]?\.?[ \t]*$", text, re.M):
        out.setdefault(m.group(1), (line_of(text, m.start())[0], m.start(), m.end()))
    return out


_SENTENCE_END = re.compile(r"(?<!Fig)(?<!\bs)(?<!vgl)(?<!\bd)(?<!\bh)(?<!\bu)(?<!Gl)(?<!\d)\.\s+(?=[A-ZÄÖÜ$„(])")


def _sentence_at(text: str, offset: int) -> tuple[int, int]:
    """(start, end) of the sentence around *offset*, inside its line (a paragraph of the transcription)."""
    bol, eol = text.rfind("\n", 0, offset) + 1, text.find("\n", offset)
    eol = len(text) if eol < 0 else eol
    a = max((m.end() for m in _SENTENCE_END.finditer(text, bol, offset)), default=bol)
    m = _SENTENCE_END.search(text, offset, eol)
    return a, m.start() + 1 if m else eol


@cache
def _figure_mentions(source: str) -> dict[str, tuple[tuple[int, int], ...]]:
    """Figure number -> the sentences ``(start, end)`` that refer to it, in text order."""
    text = get_source(source).text()
    out: dict[str, list] = {}
    for kind, a, b, matched, number in _found(source):
        if kind == "figure" and _sentence_at(text, a) not in out.setdefault(number, []):
            out[number].append(_sentence_at(text, a))
    return {k: tuple(v) for k, v in out.items()}


def _points_in(source: str, a: int, b: int) -> set[str]:
    from .labels import _read, points
    return {p for at, token in _read(source)[1] if a <= at < b for p in points(token)}


def _section_span(source: str, at: int) -> tuple[int, int, str]:
    """(start, end, name) of the section (:func:`symfloat.report.labels.sections`) around *at*."""
    from .labels import sections
    starts = sections(source) + [(len(get_source(source).text()), "")]
    i = max(i for i, (start, _) in enumerate(starts[:-1]) if start <= at)
    return starts[i][0], starts[i + 1][0], starts[i][1]


def _figure_status(source: str, number: str, at: int, caption) -> tuple[str, str]:
    """``figure lost``, with what the text still checks: a caption that survives names no point the text does
    not name with the figure, and a reference back to a figure of an earlier section uses only labels that
    section names; ``suspect`` where either fails."""
    text = get_source(source).text()
    where = (f"only its caption survives (line {caption[0]})" if caption else
             "neither the figure nor its caption is in the transcription")
    sentence = _sentence_at(text, at)
    mentions = _figure_mentions(source)[number]
    named = set().union(*(_points_in(source, *m) for m in mentions))
    on_caption = _points_in(source, caption[1], caption[2]) if caption else set()
    if on_caption - named:
        return "suspect", (f"figure lost, {where}: the caption names {', '.join(sorted(on_caption - named))}, "
                           f"which the text never names with Fig. {number}")
    own = _points_in(source, *sentence)
    home, here = _section_span(source, mentions[0][0]), _section_span(source, at)
    if home == here:
        first = mentions[0] == sentence
        return "figure lost", (f"{where}; " + ("first mentioned here" if first else
                                               f"first mentioned on line {line_of(text, mentions[0][0])[0]}")
                               + (f", with {', '.join(sorted(own))}" if own else ""))
    foreign = sorted(own - _points_in(source, home[0], home[1]))
    if foreign:
        return "suspect", (f"figure lost, {where}: a reference back to the figure of section {home[2]}, which "
                           f"never names {', '.join(foreign)}")
    return "figure lost", (f"{where}; a reference back to the figure of section {home[2]}"
                           + (f", which names {', '.join(sorted(own))} as well" if own else ""))


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
        if re.fullmatch(r"[a-z]?\.?", (prose[bol:m.start()] + prose[m.end():eol]).strip()):
            continue                              # a caption standing alone (Fig. 3a, Fig. 23.): where the figure was
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


@cache
def _quotes_by_line(source: str) -> dict[int, list]:
    """The quotes of *source* (:func:`_quotes`) by the line they begin on."""
    text = get_source(source).text()
    out: dict[int, list] = {}
    for q in _quotes(source):
        out.setdefault(line_of(text, q[0])[0], []).append(q)
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


def _automatic(source: str, kind: str, a: int, b: int, matched: str, number: str, line: int, quotes,
               target) -> tuple[str, str]:
    """The status the rules of the module docstring give a reference, and why."""
    covering = [q for q in quotes if q[0] < b and a < q[1]]
    verdict, by, why = _judged(number, matched.split()[0], covering)
    if verdict == "wrong":
        return "wrong", f"erratum {by} ({why})"
    if verdict == "unbooked":
        return "wrong", f"UNBOOKED: {by} says {why!r}"
    if kind == "figure":
        return _figure_status(source, number, a, target)
    if target is None:
        return "suspect", "no display carries the number: lost in the transcription, or a wrong reference"
    if target[0] > line and not (kind == "paragraph" and target[1] < a):
        return "suspect", "the target comes later"
    targets = [q for q in quotes if q[0] < target[2] and target[1] < q[1]]
    uses = covering or _quotes_by_line(source).get(line, [])
    at_target, at_use = [q[2] for q in targets], [q[2] for q in uses]
    reached = [uses_target(_anchors(u), set().union(*(_anchors(t) for t in targets))) for u in uses] \
        if targets else []
    if at_target and at_use and False in reached and True not in reached:
        u = uses[reached.index(False)]
        return "suspect", (f"target quoted by {at_target[0]}, but the steps behind {u[2]} "
                           f"({', '.join(sorted(n for _, n in _anchors(u)))}) do not rest on the steps behind "
                           f"it ({', '.join(sorted(n for _, n in set().union(*(_anchors(t) for t in targets)))) or '–'})")
    if at_target and at_use:
        return "resolved", f"target quoted by {at_target[0]}, use by {at_use[0]}"
    return "plausible", "the target is not quoted" if not at_target else "the passage that uses it is not quoted"


def _found_refs(source: str):
    """(kind, start, end, matched text, number, line, target) of every reference of *source*."""
    text = get_source(source).text()
    equations, sections = tags(source), paragraphs(source)
    for kind, a, b, matched, number in _found(source):
        if kind == "equation":
            target = equations.get(number) or min(
                (v for k, v in equations.items() if re.fullmatch(rf"{number}[a-e]", k)), default=None)
        elif kind == "paragraph":
            target = sections.get(number)
        else:
            target = _captions(source).get(number)
        yield kind, a, b, matched, number, line_of(text, a)[0], target


def references(source: str) -> list[dict]:
    """Every reference of *source* with its target and status (see the module docstring); a judged entry
    (:func:`judged`) decides a reference the rules leave ``suspect``, ``figure lost`` or ``plausible``."""
    quotes = _quotes(source)
    judgements = {(j["line"], j["number"], j["reference"]): j for j in judged(source)}
    out = []
    for kind, a, b, matched, number, line, target in _found_refs(source):
        status, reason = _automatic(source, kind, a, b, matched, number, line, quotes, target)
        reference = " ".join(matched.split())
        j = judgements.get((line, number, reference))
        target_line = target[0] if target else None
        if j is not None and status in JUDGEABLE:
            status, target_line = j["verdict"], j["target"]
            reason = f"judged: {j['reason']}" + (f" (erratum {j['erratum']})" if j.get("erratum") else "")
        out.append({"source": source, "line": line, "kind": kind, "reference": reference, "number": number,
                    "target_line": target_line, "status": status, "reason": reason})
    return out


def _anchors(q) -> set:
    return anchors(q[2].rsplit("/", 1)[0], q[3])


def judged_file(source: str):
    """``symfloat/sources/<key>.references.json``, the judged references of *source*."""
    return resources.files("symfloat").joinpath("sources", f"{source}.references.json")


@cache
def judged(source: str) -> tuple[dict, ...]:
    """The judged references of *source*, ``symfloat/sources/<key>.references.json``, checked for form: each has
    ``line``, ``reference`` and ``number`` (as :func:`references` lists them), ``target`` (the line of the target,
    or null when it is lost), ``passage`` (verbatim on the target's line, or on the reference's when the target is
    lost), a ``verdict`` of :data:`VERDICTS`, a one-line ``reason``, and for ``wrong`` the ``erratum`` (a formula
    id) that books it.  A figure's target is its caption's line, or null when no caption survives."""
    path = judged_file(source)
    if not path.is_file():
        return ()
    entries = json.loads(path.read_text(encoding="utf-8"))
    keys = {"line", "reference", "number", "target", "passage", "verdict", "reason"}
    for j in entries:
        extra = {"erratum"} if j.get("verdict") == "wrong" else set()
        if (set(j) != keys | extra or j["verdict"] not in VERDICTS or not j["reason"].strip()
                or ((j["target"] is None) != (j["verdict"] == "target lost") and j["verdict"] != "figure lost")):
            raise ValueError(f"{source}.references.json: malformed entry {j!r}: needs {sorted(keys | extra)}, a "
                             f"verdict of {VERDICTS} and a target line unless the target is lost")
    return tuple(entries)


def stale(source: str) -> list[str]:
    """The judged entries of *source* that no longer match: no such reference on the line, a reference the
    rules decide by themselves, ``figure lost`` for an equation or resolved/target lost for a figure, a
    ``plausible`` reference (its target found) judged neither resolved nor wrong, a passage not on its line or
    (resolved) without the number's tag, or an erratum that does not exist."""
    text = get_source(source).text()
    lines = text.split("\n")
    found = {}
    quotes = _quotes(source)
    for kind, a, b, matched, number, line, target in _found_refs(source):
        found[(line, number, " ".join(matched.split()))] = \
            kind, _automatic(source, kind, a, b, matched, number, line, quotes, target)[0]
    errata = {q[2] for q in quotes if q[3].erratum is not None}
    out = []
    for j in judged(source):
        where = f"{source}.references.json line {j['line']} {j['reference']!r}"
        at = j["target"] if j["target"] is not None else j["line"]
        kind, status = found.get((j["line"], j["number"], j["reference"]), (None, None))
        if kind is None:
            out.append(f"{where}: no such reference of number {j['number']} on that line")
        elif status not in JUDGEABLE:
            out.append(f"{where}: the rules decide it ({status}); drop the entry")
        elif j["verdict"] != "wrong" and (kind == "figure") != (j["verdict"] == "figure lost"):
            out.append(f"{where}: a reference of kind {kind} judged {j['verdict']!r}")
        elif status == "plausible" and j["verdict"] not in ("resolved", "wrong"):
            out.append(f"{where}: the rules found its target; a plausible reference is judged resolved or wrong, "
                       f"not {j['verdict']!r}")
        if not 1 <= at <= len(lines) or j["passage"] not in lines[at - 1]:
            out.append(f"{where}: the passage {j['passage']!r} is not on line {at}")
        carried = {_key(n) for n in re.findall(r"(?:\(|\\tag\{)(\d{1,3}\s?[a-e]?)", j["passage"])}   # (57) or \tag{57}
        if j["verdict"] == "resolved" and not carried & {j["number"], *(j["number"] + c for c in "abcde")}:
            out.append(f"{where}: the passage {j['passage']!r} carries no tag ({j['number']})")
        if j["verdict"] == "wrong" and j["erratum"] not in errata:
            out.append(f"{where}: {j['erratum']!r} is no erratum of a quote of {source}")
    return out


def check(refs) -> list[str]:
    """The failed self-checks: references the derivations call wrong with no erratum booked, a reference with no
    status, and the stale judged entries of the sources of *refs*."""
    out = [f"{r['source']} line {r['line']}: {r['reference']!r}: {r['reason']}" for r in refs
           if r["reason"].startswith("UNBOOKED")]
    out += [f"{r['source']} line {r['line']}: {r['reference']!r}: no status" for r in refs
            if r.get("status") not in STATUSES]
    return out + [msg for s in dict.fromkeys(r["source"] for r in refs) if s in SOURCES for msg in stale(s)]


def status_counts(refs) -> dict[str, int]:
    """``{"references": n, status: count, ...}`` for the references *refs* of one source."""
    return {"references": len(refs), **{st: sum(r["status"] == st for r in refs) for st in STATUSES}}


def references_markdown(sources=tuple(SOURCES)) -> str:
    """``docs/references.md``: every reference of every source with its status, suspect and wrong ones first."""
    from .labels import labels_markdown
    out = ["# Cross-references of the sources", "",
           "Generated by `symfloat coverage --write` (`symfloat/report/references.py`). A reference is an equation",
           "number after *Gleichung*, *Gl.*, *nach*, *aus*, *s.*, *vgl.*, *Bedingung* or in *in N ein*, a figure",
           "(*Fig. N*) or Euler's paragraph (*§. N* inside a paragraph). Status: **resolved** (target before the use,",
           "both quoted by the derivations, the citing quote's steps not missing the target's; or judged), **plausible**",
           "(target before the use, a side unquoted, not judged), **figure lost** (no transcription carries the figures:",
           "the caption survives or not; a surviving caption names no point the text does not give the figure, and a",
           "reference back to the figure of an earlier section names only points that section names), **target lost**",
           "(the transcription lost the display that carried the number; judged),",
           "**wrong** (an erratum corrects the number), **suspect** (undecided: no target, a later one, a target the",
           "citing quote's steps do not rest on through their `uses` or the quantities they mention, or a figure",
           "whose labels do not agree). Where the rules cannot decide, a judgement is kept as data in",
           "`symfloat/sources/<key>.references.json` (line, reference, target, verdict, a reason quoting the passage);",
           "an entry that no longer matches a reference of the transcription fails the check.", "",
           "| source | references | " + " | ".join(STATUSES) + " |", "|---|---:|" + "---:|" * len(STATUSES)]
    everything = {s: references(s) for s in sources}
    for s, refs in everything.items():
        counts = status_counts(refs)
        out.append(f"| {s} | {counts['references']} | " + " | ".join(str(counts[st]) for st in STATUSES) + " |")
    order = {st: i for i, st in enumerate(("wrong", "suspect", "target lost", "figure lost", "plausible", "resolved"))}
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
