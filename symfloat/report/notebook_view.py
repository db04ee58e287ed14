"""What the derivation notebooks display: steps, printed formulas, witnesses.

Two kinds of content.  The mathematics of a derivation — its named helper
expressions, each step's statement and its chain of expressions, each printed
formula's reading — is rendered from the derivation module when the notebook is
built (:func:`definitions_markdown`, :func:`step_markdown`,
:func:`reading_markdown`).  The engine's findings — how each step was justified,
each verdict, the witness tables — are shown by a :class:`NotebookView` when the
notebook runs.  No timing is displayed: times go to the verification record and
the benchmark, so a regenerated notebook changes only when mathematics changes.
"""
from __future__ import annotations

import sympy as sp

from ..engine.runner import verify
from ..model.claim import expressions, members
from ..model.relation import is_relation, relation_latex
from ..model.symbol_names import latex
from ..registry import load
from .witness_words import error_cells

__all__ = ["NotebookView", "definitions_markdown", "step_markdown", "reading_markdown", "correction_markdown",
           "named", "chain_latex", "show"]

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


def chain_latex(d, claim) -> str:
    """The chain ``a = b = c`` of a claim, one member per line when long, in the derivation's names
    (a relation, :mod:`symfloat.model.relation`, on one line)."""
    if is_relation(claim):
        return "$$ " + relation_latex(claim, lambda e: _latex(d, e)) + " $$"
    ms = [_latex(d, m) for m in members(claim)]
    if sum(len(m) for m in ms) < 90:
        return "$$ " + " = ".join(ms) + " $$"
    return "$$ \\begin{aligned} " + ms[0] + " &= " + " \\\\ &= ".join(ms[1:]) + " \\end{aligned} $$"


def definitions_markdown(d) -> str:
    """The named helper expressions of the derivation, each shown once (in the names before it)."""
    if not d.names:
        return ""
    lines = ["## Names used below", "",
             "Helper expressions of the derivation, each shown once; the steps and readings below "
             "write them by these names.", ""]
    for i, (symbol, value, text) in enumerate(d.names):
        shown = latex(named(d.names[:i], value))
        lines.append(f"- {text}: ${latex(symbol)} = {shown}$" if text else f"- ${latex(symbol)} = {shown}$")
    return "\n".join(lines)


def _quoted(text: str) -> str:
    return "\n".join("> " + line if line.strip() else ">" for line in text.splitlines())


def step_markdown(d, index: int, step) -> str:
    """A step's heading, its statement in the source's words and its chain of expressions."""
    head = f"### Step {index}: {step.name}\n\n*{JUSTIFICATION[step.why]}*"
    if step.uses:
        head += " — uses " + ", ".join(f"`{u}`" for u in step.uses)
    out = [head]
    quotes = [p for p in d.printed if p.name == step.name]
    for p in quotes:
        fault = (f" (as transcribed; the printed formula `{p.name}` below has its erratum)"
                 if p.erratum is not None else "")
        out.append(f"The source ({p.locator}){fault}:\n\n{_quoted(p.excerpt)}")
    if step.note:
        out.append(f"In our words ({d.locator}): {step.note[0].upper() + step.note[1:]}"
                   + ("" if step.note.rstrip().endswith(".") else "."))
    out.append(("Definition:" if step.why == "definition" else "Before and after:") + "\n\n"
               + chain_latex(d, step.claim))
    if step.result is not None:
        out.append(f"This establishes ${latex(step.result)}$, used in later steps and readings.")
    return "\n\n".join(out)


def _derived_symbols(d, claims) -> str:
    """Which symbols of *claims* stand for values the steps derived, and where."""
    where = {s.result: (i, s.name) for i, s in enumerate(d.steps, 1) if s.result is not None}
    found = {}
    for claim in claims:
        for m in expressions(claim):
            for sym in sorted(getattr(m, "free_symbols", set()), key=str):
                if sym in where:
                    found[sym] = where[sym]
    if not found:
        return ""
    return ("Compared with the derivation: " + "; ".join(
        f"${latex(sym)}$ is the value of step {i} (`{name}`)" for sym, (i, name) in found.items()) + ".")


def reading_markdown(d, p) -> str:
    """A printed formula: locator, the verbatim quotation and its reading as printed."""
    out = [f"### {p.locator}: `{p.name}`", _quoted(p.excerpt)]
    if p.lost:
        out.append(f"Text lost in the transcription: {p.lost}")
    if p.unreadable:
        out.append(f"Not readable as printed: {p.unreadable}")
    if p.reading is not None:
        out.append("Read as printed:\n\n" + chain_latex(d, p.reading))
    corrected = p.erratum.corrected_reading if p.erratum is not None else None
    if corrected is not None:
        out.append("The correction, read:\n\n" + chain_latex(d, corrected))
    derived = _derived_symbols(d, [c for c in (p.reading, corrected) if c is not None])
    if derived:
        out.append(derived)
    if p.note:
        out.append(f"Note: {p.note}")
    return "\n\n".join(out)


def correction_markdown(kind: str, corrected: str) -> str:
    """A correction: words (a claim in words, or words with their own dollars) are prose, anything else (a
    claim's correction written in LaTeX too) a displayed formula."""
    prose = "$" in corrected or (kind == "claim" and "\\" not in corrected)
    return corrected if prose else f"$$ {corrected} $$"


# ---- the engine's findings, shown when the notebook runs ----------------------------------------------------------
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
        return f"proved symbolically (strategy `{identity.get('strategy')}`), after being {sampled}"
    if status == "sampled":
        return f"{sampled}; no symbolic proof"
    if status == "agrees":
        return "agrees with the computed value to the printed precision"
    if status == "refuted":
        cx = identity.get("counterexample") or {}
        point = ", ".join(f"{k} = {v}" for k, v in cx.get("point", {}).items())
        return (f"**refuted**: at {point or 'the printed numbers'} the left member gives {cx.get('lhs')}, "
                f"the right {cx.get('rhs')}")
    return f"undecided: {sampled}, no symbolic proof found"


def _records(title, records) -> list[str]:
    """A title and one Markdown table (one block, rows joined by single newlines); no timings."""
    if not records:
        return []
    rows = ["| method | cases | abs. error | rel. error |", "|---|---|---|---|"]
    for r in records:
        abs_cell, rel_cell = error_cells(r)
        rows.append(f"| {r['method']} | {r.get('cases', 1)} | {abs_cell} | {rel_cell} |")
    return [title, "\n".join(rows)]


def show(markdown: str):
    """Display Markdown in a notebook (plain text elsewhere)."""
    try:
        from IPython.display import Markdown, display
    except ImportError:  # pragma: no cover - outside IPython
        print(markdown)
        return
    display(Markdown(markdown))


class NotebookView:
    """The engine's findings on one derivation module, for its notebook.

    The report comes from :func:`symfloat.engine.runner.verify` (the derivation
    and its ancestors checked, or read from the cache when unchanged)."""

    def __init__(self, module, report=None):
        self.derivation = load(module.DERIVATION.id)[0]        # with its witnesses declared
        self.report = report or next(r for r in verify(self.derivation.id) if r.id == self.derivation.id)
        self.failures = self.report.failures

    def summary_markdown(self) -> str:
        steps = {}
        for s in self.report.steps:
            steps[s.status] = steps.get(s.status, 0) + 1
        verdicts = {}
        for f in self.report.formulas:
            verdicts[f.verdict] = verdicts.get(f.verdict, 0) + 1
        order = ("verified", "erratum", "unverifiable", "trivial")
        return (f"{len(self.report.steps)} steps: " + ", ".join(f"{n} {k}" for k, n in sorted(steps.items()))
                + f".\n\n{len(self.report.formulas)} printed formulas: "
                + ", ".join(f"{verdicts.get(v, 0)} {v}" for v in order) + ".")

    def _witnesses(self, target: str) -> str:
        """What the first-principles witnesses of *target* compute, in the derivation's words."""
        ws = [w for w in self.derivation.witnesses if target.split("#")[0] in w.targets]
        return "; ".join(w.description + (f" ({len(w.instances)} cases)" if hasattr(w, "instances") else "")
                         for w in ws)

    def step_markdown(self, name: str) -> str:
        s = next(s for s in self.report.steps if s.name == name)
        out = [f"Justification: {_how(s.identity, s.status)}."]
        for f in self.report.formulas:
            if f.id.endswith("/" + name):
                out += _records(f"Witnesses of the printed formula `{name}` — {self._witnesses(name)}:", f.numeric)
        return "\n\n".join(out)

    def formula_markdown(self, name: str) -> str:
        f = next(f for f in self.report.formulas if f.id.endswith("/" + name))
        out = [f"**Verdict: {f.verdict}**" + (f" (evidence: {f.evidence})" if f.evidence else "")]
        if f.identity and f.verdict in ("verified", "erratum", "trivial"):
            out.append(f"The reading against the derivation: {_how(f.identity, f.identity['status'])}.")
        if f.reason:
            out.append(f"Reason: {f.reason}")
        if f.erratum:
            e = f.erratum
            out.append(f"Erratum ({e['kind']}, confidence {e['confidence']}). Corrected:\n\n"
                       f"{correction_markdown(e['kind'], e['corrected'])}\n\n{e['evidence']}")
        out += _records(f"Witnesses against the printed formula — {self._witnesses(name)}:", f.numeric)
        out += _records(f"Witnesses against the correction — {self._witnesses(name)}:", f.corrected_numeric)
        out += [f"> {n}" for n in f.witness_notes]
        return "\n\n".join(out)

    def summary(self):
        show(self.summary_markdown())

    def step(self, name: str):
        show(self.step_markdown(name))

    def formula(self, name: str):
        show(self.formula_markdown(name))
