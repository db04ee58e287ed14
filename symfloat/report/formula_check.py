"""``symfloat check``'s report: the verdict on one printed formula, as text or JSON."""
from __future__ import annotations

import json

from ..engine.formula_check import FormulaCheck
from ..engine.proof_words import PROOF_WORDS
from ..model.evidence_tex import tex_number

__all__ = ["check_json", "check_text"]


def check_json(result: FormulaCheck) -> str:
    return json.dumps(result.to_json(), indent=1, ensure_ascii=False) + "\n"


def _point(point: dict) -> str:
    return ", ".join(f"{k} = {v}" for k, v in point.items())


def check_text(result: FormulaCheck) -> str:
    """The verdict, its evidence, the counterexample with labelled sides, the witness, the corrections."""
    lines = [f"printed:  {result.printed}"] + [f"against:  {a}" for a in result.against]
    if result.verdict == "holds":
        words = PROOF_WORDS.get(result.strategy, "").replace("$", "")
        digits = result.evidence.partition(" (")[2].removesuffix(")")      # exact, or 60 digits
        samples = "exact samples" if digits == "exact" else f"samples at {digits}"
        how = (f"proved ({words})" if words else "proved") if result.evidence == "symbolic" else \
            f"equal to within half a unit in the last printed digit, {result.rounding} (compared at {digits})" \
            if result.rounding else f"every one of {result.samples} {samples} agrees, no symbolic proof"
        lines.append(f"verdict:  holds: {how}")
    elif result.verdict == "refuted":
        tex = result.counterexample["tex"]
        at = f" at {_point(tex['point'])}" if tex["point"] else ""
        left, right = result.counterexample["sides"]
        sides = (f"printed {tex['printed']}, derived {tex['derived']}" if left != right else
                 f"the {left} sides are {tex['left']} and {tex['right']}")    # a link within the print, say
        beyond = f"; they differ by more than half a unit in the last printed digit, {result.rounding}" \
            if result.rounding else ""
        lines.append(f"verdict:  refuted{at}: {sides}{beyond}")
    else:
        lines.append(f"verdict:  undecided: {result.reason}")
    w = result.witness
    if w:
        agrees = {"printed": "agrees with the print", "derived": "agrees with the derivation, not the print",
                  "neither": "agrees with neither"}[w["agrees_with"]]
        lines.append(f"witness:  {w['method']} at {_point(w['tex']['point'])}: "
                     f"{tex_number(w['measured'])} ({agrees})")
    if result.corrections:
        lines.append("corrections that make the print hold, likeliest first:")
        for i, c in enumerate(result.corrections, 1):
            lines.append(f"  {i}. {c.text}    [{c.change}; {c.what}, {c.kind}; {c.status}]")
    elif result.verdict == "refuted":
        lines.append("corrections: no single small edit of the print makes it hold")
    return "\n".join(lines) + "\n"
