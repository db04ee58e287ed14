"""What the derivation notebooks say in words and typeset mathematics.

The mathematics of a derivation — its named helper expressions, each step's title, statement and
chain of expressions, each printed formula's quotation and reading — is rendered from the
derivation module (:func:`definitions_markdown`, :func:`step_markdown`, :func:`reading_markdown`);
the engine's findings on it — how each step was justified, each verdict, the erratum, the witness
tables — from its report (:class:`NotebookView`), when the notebook is built.  The code cells
(:mod:`symfloat.report.notebook_cells`) state and check the same steps in SymPy.  No timing is
displayed: times go to the verification record and the benchmark, so a regenerated notebook
changes only when mathematics changes.
"""
from __future__ import annotations

import re

import sympy as sp

from ..model.claim import expressions, members
from ..model.erratum import apparatus, apparatus_in_words
from ..model.relation import is_relation, relation_latex
from ..model.symbol_names import latex
from ..numbers import counted, method_words, steps_in_words
from ..registry import load
from .notebook_code import STRATEGY_WORDS
from ..prose import typeset
from .cross_references import readable
from .witness_words import error_cells

__all__ = ["NotebookView", "definitions_markdown", "step_markdown", "step_title", "step_titles", "reading_markdown",
           "correction_markdown", "named", "chain_latex"]

JUSTIFICATION = {
    "definition": "definition (stated, not checked)",
    "algebra": "algebra",
    "substitution": "substitution of earlier results",
    "integration": "integration",
    "geometry": "geometry in coordinates",
    "lemma": "a lemma applied",
    "limit": "a limit",
    "series": "a series expansion",
}

# an inequality sign of the print (TeX or Unicode)
_INEQUALITY = re.compile(r"\\(?:geqq|leqq|geq|leq|ge|le|gtrless)(?![A-Za-z])|[<>≤≥]")


# ---- the mathematics, rendered when the notebook is built ---------------------------------------------------------
def named(names, expr):
    """*expr* with the named helper expressions ``(symbol, value, text)`` written by their names."""
    if not names:
        return expr
    table = {value: symbol for symbol, value, _ in names if not isinstance(value, sp.MatrixBase)}
    if isinstance(expr, sp.MatrixBase):
        for symbol, value, _ in names:
            if isinstance(value, sp.MatrixBase) and value.shape == expr.shape and value == expr:
                return symbol
        return expr.applyfunc(lambda e: e.xreplace(table))
    return sp.sympify(expr).xreplace(table)


def _as_printed(expr) -> bool:
    """Does *expr* keep arithmetic unevaluated (a reading as printed)?"""
    nodes = expr if isinstance(expr, sp.MatrixBase) else [expr]
    return any(isinstance(a, sp.UnevaluatedExpr) or (isinstance(a, (sp.Add, sp.Mul, sp.Pow)) and a != a.func(*a.args))
               for e in nodes for a in sp.preorder_traversal(e))


def _latex(d, expr) -> str:
    """LaTeX of *expr* in the derivation's names; an expression kept as printed keeps its order of terms."""
    expr = named(d.names, expr)
    return latex(expr, order="none") if _as_printed(expr) else latex(expr)


def chain_latex(d, claim, split: bool = True) -> str:
    """The chain ``a = b = c`` of a claim in the derivation's names, a member the same as the one before it
    shown once (no ``5/2 = 5/2``), one member per line when long and *split* (a relation,
    :mod:`symfloat.model.relation`, on one line)."""
    if is_relation(claim):
        return "$$ " + relation_latex(claim, lambda e: _latex(d, e)) + " $$"
    ms = []
    for m in members(claim):
        text = _latex(d, m)
        if not ms or text != ms[-1]:
            ms.append(text)
    if sum(len(m) for m in ms) < 90 or not split:
        return "$$ " + " = ".join(ms) + " $$"
    return "\n\n".join([f"$$ {ms[0]} $$"] + [f"$$ = {m} $$" for m in ms[1:]])


def definitions_markdown(d) -> str:
    """The named helper expressions of the derivation, each shown once (in the names before it)."""
    if not d.names:
        return ""
    lines = ["## Names used below", "",
             "Helper expressions of the derivation, each shown once; the steps and readings below "
             "write them by these names.", ""]
    for i, (symbol, value, text) in enumerate(d.names):
        shown = latex(named(d.names[:i], value))
        lines.append(f"- {typeset(text)}: ${latex(symbol)} = {shown}$" if text else f"- ${latex(symbol)} = {shown}$")
    return "\n".join(lines)


def _quoted(text: str) -> str:
    return "\n".join("> " + line if line.strip() else ">" for line in text.splitlines())


def _capital(text: str) -> str:
    """*text* with a capital first letter, unless it begins with a symbol (``k is the normal``) or a formula."""
    if re.match(r"[a-z]\b", text) or text.startswith("$"):
        return text
    return text[0].upper() + text[1:]


def words(d, text: str) -> str:
    """Words of derivation *d* for a reader: the steps and formulas they cite by their notebook's numbering
    (:func:`~symfloat.report.cross_references.readable`), the mathematics typeset."""
    return typeset(readable(d, text))


def _sentence(d, text: str) -> str:
    text = words(d, text.strip())
    return _capital(text) + ("" if text.endswith((".", "?", "!")) else ".")


def step_title(d, step) -> str:
    """A step's title in words: the first phrase of its note, else what it establishes, else the printed
    formula it derives, else what it does to its first member.

    The note, typeset, ends at the first ``;``, ``:``, comma or bracket outside its formulas and brackets
    (not a locator's bracket, "in (12)"; not a ratio's colon, spaced on both sides, "I : K = EF² : AB²") that
    leaves at least three words; a longer phrase is cut at a space outside its formulas before 70 characters and
    ends with "…", unless what is left is a label before its formula ("Area element: $df_2 = …$"), which is the
    title without its colon."""
    if step.note:
        note = words(d, step.note.strip())
        outside = _outside_formulas(note)
        cuts = [m.start() for m in re.finditer(r";\s|(?<!\s):\s|\s\((?![\d§])|,\s", note)
                if outside[m.start()] and len(note[:m.start()].split()) >= 3
                and note[:m.start()].count("(") == note[:m.start()].count(")")]
        phrase = note[:cuts[0]] if cuts else note
        if len(phrase) > 70:
            spaces = [i for i, ch in enumerate(phrase[:70]) if ch == " " and outside[i]]
            if spaces:
                head = phrase[:spaces[-1]]
                phrase = head[:-1] if head.endswith(":") else head + " …"
        return _capital(phrase)
    quoted = [p for p in d.printed if p.name == step.name]
    if quoted:
        return f"The printed formula {quoted[0].locator}"
    what = {"definition": "Definition", "algebra": "Algebra", "substitution": "Substitution",
            "integration": "Integration", "geometry": "Geometry", "lemma": "A lemma", "limit": "A limit",
            "series": "A series"}[step.why]
    if step.result is not None:
        return f"{what}: the value of ${latex(step.result)}$"
    first = _latex(d, members(step.claim)[0])
    return f"{what} for ${first}$" if len(first) < 60 else what


def _outside_formulas(text: str) -> list[bool]:
    """For each character of *text*: is it outside the ``$…$`` formulas?"""
    out, inside = [], False
    for ch in text:
        if ch == "$":
            inside = not inside
            out.append(False)
        else:
            out.append(not inside)
    return out


def step_titles(d) -> dict:
    """Step name -> its title (:func:`step_title`); a title two steps share names what each establishes after
    it, where it establishes a quantity (the heading's step number tells the others apart)."""
    titles = {s.name: step_title(d, s) for s in d.steps}
    count: dict = {}
    for t in titles.values():
        count[t] = count.get(t, 0) + 1
    for s in d.steps:
        if count[titles[s.name]] > 1 and s.result is not None:
            titles[s.name] += f": ${latex(s.result)}$"
    return titles


def _uses(d, step) -> str:
    """The steps a step uses, by number (an earlier derivation's by its title)."""
    index = {s.name: i for i, s in enumerate(d.steps, 1)}
    own = [index[u] for u in step.uses if ":" not in u]
    other = sorted({u.split(":", 1)[0] for u in step.uses if ":" in u})
    parts = []
    if own:
        parts.append(("step " if len(own) == 1 else "steps ") + ", ".join(str(i) for i in own))
    if other:
        parts.append(", ".join(f"*{load(o)[0].title}* ({load(o)[0].locator})" for o in other))
    return " and ".join(parts)


def step_markdown(d, index: int, step, findings: str = "", title: str = "") -> str:
    """A step's heading in words (*title*, by default :func:`step_title`), its statement in the source's
    words and its chain of expressions, then what the engine found (*findings*)."""
    head = f"### Step {index}: {title or step_title(d, step)}\n\n*{JUSTIFICATION[step.why]}*"
    if step.uses:
        head += " — uses " + _uses(d, step)
    out = [head]
    quotes = [p for p in d.printed if p.name == step.name]
    for p in quotes:
        fault = (f" (as transcribed; the printed formula {p.locator} below has its erratum)"
                 if p.erratum is not None else "")
        out.append(f"The source ({p.locator}){fault}:\n\n{_quoted(p.excerpt)}")
    if step.note:
        out.append(f"In our words ({d.locator}): {_sentence(d, step.note)}")
    out.append(("Definition:" if step.why == "definition" else "Before and after:") + "\n\n"
               + chain_latex(d, step.claim))
    if step.result is not None:
        out.append(f"This establishes ${latex(step.result)}$, used in later steps and readings.")
    if findings:
        out.append(findings)
    return "\n\n".join(out)


def _derived_symbols(d, claims) -> str:
    """Which symbols of *claims* stand for values the steps derived, and where."""
    where = {s.result: i for i, s in enumerate(d.steps, 1) if s.result is not None}
    found = {}
    for claim in claims:
        for m in expressions(claim):
            for sym in sorted(getattr(m, "free_symbols", set()), key=str):
                if sym in where:
                    found[sym] = where[sym]
    if not found:
        return ""
    return ("Compared with the derivation: " + "; ".join(
        f"${latex(sym)}$ is the value established in step {i}" for sym, i in found.items()) + ".")


def reading_markdown(d, p, findings: str = "") -> str:
    """A printed formula: its locator as heading (numbered when several share it), the verbatim quotation,
    its reading as printed (an inequality read as an equation says so) and the correction's, then what the
    engine found (*findings*)."""
    same = [q for q in d.printed if q.locator == p.locator]
    head = f"### {p.locator}" + (f", formula {same.index(p) + 1} of {len(same)}" if len(same) > 1 else "")
    derived_by = [s for s in d.steps if s.name == p.name and s.note]
    first = _latex(d, members(p.reading)[0]) if p.reading is not None and not is_relation(p.reading) else ""
    if derived_by:
        head += f": {step_title(d, derived_by[0])[0].lower()}{step_title(d, derived_by[0])[1:]}"
    elif first and len(first) < 40:
        head += f": ${first}$"                     # what the formula gives, when the quotation is long to read
    out = [head, _quoted(p.excerpt)]
    if p.lost:
        out.append(f"Text lost in the transcription: {words(d, p.lost)}")
    if p.unreadable:
        out.append(f"Not readable as printed: {words(d, p.unreadable)}")
    if p.reading is not None:
        if not is_relation(p.reading) and _INEQUALITY.search(p.excerpt):
            out.append("The print states an inequality; it is read as the equation below (its bound, its margin or "
                       "its sign, as the note says).")
        out.append("Read as printed:\n\n" + chain_latex(d, p.reading, split=False))
    corrected = p.erratum.corrected_reading if p.erratum is not None else None
    if corrected is not None:
        out.append("The correction, read:\n\n" + chain_latex(d, corrected, split=False))
    derived = _derived_symbols(d, [c for c in (p.reading, corrected) if c is not None])
    if derived:
        out.append(derived)
    if p.note:
        out.append(f"Note: {_sentence(d, p.note)}")
    if findings:
        out.append(findings)
    return "\n\n".join(out)


def correction_markdown(kind: str, corrected: str) -> str:
    """A correction: words (a claim in words, or words with their own dollars) are prose, anything else (a
    claim's correction written in LaTeX too) a displayed formula."""
    prose = "$" in corrected or (kind == "claim" and "\\" not in corrected)
    return corrected if prose else f"$$ {corrected} $$"


# ---- the engine's findings, from its report ----------------------------------------------------------------------
def _how(identity: dict | None, status: str) -> str:
    if status == "definition":
        return "stated as a definition: not checked"
    if status == "applied":
        return "the lemma's statement applied: checked where the lemma is derived"
    if status == "trivial":
        return "**trivial**: its members are identical as built, so the comparison proves nothing"
    identity = identity or {}
    points = identity.get("samples", 0)
    kind = "exact rational" if identity.get("exact", True) else "60-digit"
    sampled = f"equal at {points} random {kind} points of the assumptions"
    if status == "proved":
        strategy = identity.get("strategy")
        return (f"proved symbolically, the difference {STRATEGY_WORDS.get(strategy, strategy)} to 0 (strategy "
                f"*{strategy}* of its proof certificate, the call in the cell below), after being {sampled}")
    if status == "sampled":
        return f"{sampled}; no symbolic proof (the cell below asserts it at a small point)"
    if status == "agrees":
        return "agrees with the computed value to the printed precision"
    if status == "refuted":
        return "**refuted**: the cell below shows a point inside the assumptions where its members differ"
    return f"undecided: {sampled}, no symbolic proof found"


def _records(title, records) -> list[str]:
    """A title and one Markdown table (one block, rows joined by single newlines); no timings."""
    if not records:
        return []
    rows = ["| method | cases | abs. error | rel. error |", "|---|---|---|---|"]
    for r in records:
        abs_cell, rel_cell = error_cells(r)
        rows.append(f"| {method_words(r['method'])} | {r.get('cases', 1)} | {abs_cell} | {rel_cell} |")
    return [title, "\n".join(rows)]


class NotebookView:
    """The engine's *report* (:class:`~symfloat.engine.check.DerivationReport`) on the derivation *d*, in
    words, for its notebook."""

    def __init__(self, d, report):
        self.derivation = d
        self.report = report
        self.failures = report.failures

    def summary_markdown(self) -> str:
        steps = {}
        for s in self.report.steps:
            steps[s.status] = steps.get(s.status, 0) + 1
        verdicts = {}
        for f in self.report.formulas:
            verdicts[f.verdict] = verdicts.get(f.verdict, 0) + 1
        kinds = [f.erratum["kind"] for f in self.report.formulas if f.erratum]
        apart = apparatus_in_words(kinds)
        order = ("verified", "erratum", "unverifiable", "trivial")
        return (f"{counted(len(self.report.steps), 'step')}: " + steps_in_words(steps)
                + f".\n\n{counted(len(self.report.formulas), 'printed formula')}: "
                + ", ".join(counted(verdicts.get(v, 0), v, "errata" if v == "erratum" else v)
                            + (f" ({apart})" if v == "erratum" and kinds else "") for v in order) + ".")

    def _witnesses(self, target: str) -> str:
        """What the first-principles witnesses of *target* compute, in the derivation's words."""
        ws = [w for w in self.derivation.witnesses if target.split("#")[0] in w.targets]
        return "; ".join(words(self.derivation, w.description)
                         + (f" ({counted(len(w.instances), 'case')})" if hasattr(w, "instances") else "") for w in ws)

    def step_markdown(self, name: str) -> str:
        s = next(s for s in self.report.steps if s.name == name)
        out = [f"Justification: {_how(s.identity, s.status)}."]
        for f in self.report.formulas:
            if f.id.endswith("/" + name):
                p = self.derivation.get_printed(name)
                wrong = (" as printed, which has an erratum (the errors are the print's; its correction is checked "
                         "with the formula below)" if f.verdict == "erratum" else "")
                out += _records(f"Witnesses of the printed formula {p.locator}{wrong} — {self._witnesses(name)}:",
                                f.numeric)
        return "\n\n".join(out)

    def formula_markdown(self, name: str) -> str:
        f = next(f for f in self.report.formulas if f.id.endswith("/" + name))
        out = [f"**Verdict: {f.verdict}**" + (f" (evidence: {f.evidence})" if f.evidence else "")]
        if f.identity and f.verdict in ("verified", "erratum", "trivial"):
            out.append(f"The reading against the derivation: {_how(f.identity, f.identity['status'])}.")
        if f.reason:
            out.append(f"Reason: {words(self.derivation, f.reason)}")
        if f.erratum:
            e = f.erratum
            why = self.derivation.get_printed(name).erratum.evidence
            head = (f"Correction of the transcription (confidence {e['confidence']}); the original very probably "
                    f"printed:" if apparatus(e["kind"]) == "transcription"
                    else f"Fault of the original ({e['kind']}, confidence {e['confidence']}). Corrected:")
            out.append(f"{head}\n\n{correction_markdown(e['kind'], e['corrected'])}\n\n{words(self.derivation, why)}")
        what = self._witnesses(name) or ("the derivation's definitions evaluated at concrete values (no declared "
                                         "witness measures this formula)")
        out += _records(f"Witnesses against the printed formula — {what}:", f.numeric)
        out += _records(f"Witnesses against the correction — {what}:", f.corrected_numeric)
        out += [f"> {words(self.derivation, n)}" for n in f.witness_notes]
        return "\n\n".join(out)
