"""A derivation's words cite its steps and printed formulas as a reader finds them (symfloat/report/cross_references.py):
by the notebook's numbering, never by the program name the module gives them."""
import json
import re
from pathlib import Path

import pytest

from symfloat import registry
from symfloat.registry import load
from symfloat.report.cross_references import _ARTICLE, _pattern, labels, readable

ROOT = Path(__file__).resolve().parents[1]


def _step(derivation: str, name: str) -> int:
    return [s.name for s in load(derivation)[0].steps].index(name) + 1


def readable_in(derivation: str, text: str) -> str:
    return readable(load(derivation)[0], text)


def test_a_cited_step_or_formula_is_named_by_the_notebooks_numbering(check):
    # Scheeffer VII-VIII's note "(step moment-y)": the notebook's "### Step N"; Graefe §2's "see 'slab-a-c'": the
    # heading of the printed formula, numbered among those at §2 Simpson's rule
    n = _step("scheeffer-vii-viii", "moment-y")
    assert readable_in("scheeffer-vii-viii", "read as the moment itself (step moment-y)") == \
        f"read as the moment itself (step {n})"
    assert readable_in("scheeffer-vii-viii", "as the step moment-y says") == f"as the step {n} says"
    assert readable_in("graefe-s2-volumes-simpson", "(factor 2m, see 'slab-a-c'); the algebra") == \
        "(factor 2m, see formula 1 of §2 Simpson's rule); the algebra"
    # another derivation by its source and place, and its formula (Scheeffer (13))
    reports = {r.id: r for r in check("scheeffer-iv-v")}
    assert readable(reports["scheeffer-iv-v"], "agrees with scheeffer-i-iii:moment-13.", reports) == \
        "agrees with Scheeffer I-III, formula (13)."
    assert readable(reports["scheeffer-iv-v"], "(scheeffer-i-iii:no-such-step)", reports) == \
        "(scheeffer-i-iii:no-such-step)"                             # a name the other does not have stays


@pytest.mark.parametrize("text", [
    "The triangles are the mid-sections of the pyramids EOFB",       # Graefe §1: a step's name and an English noun
    "M·GZ/φ of the heeled V-prism by exact clipping",                 # Euler §§229-243
    "Checked by ``symfloat verify scheeffer-x``, step ``moment-y``",  # a command to run, a code span
    "the slab a-c of bodies with cubic section areas",               # no name of the derivation
])
def test_words_that_only_look_like_names_stay(text):
    derivation = "scheeffer-x" if "scheeffer-x" in text else "graefe-s1-prismatoid-volume"
    assert readable_in(derivation, text) == text


def _texts(d):
    yield from (d.summary, *d.assumptions, *(s.note for s in d.steps), *(p.note for p in d.printed))
    for p in d.printed:
        if p.erratum is not None:
            yield from (p.erratum.evidence, p.erratum.objection, p.erratum.answer)
    yield from (w.description for w in d.witnesses)


@pytest.mark.parametrize("derivation", registry.ids())
def test_no_program_name_is_left_in_a_derivations_words(derivation):
    d, _ = load(derivation)
    pattern = _pattern(frozenset(labels(d)))
    left = []
    for text in filter(None, _texts(d)):
        shown = readable_in(derivation, text)
        for piece in re.split(r"(``[^`]+``|`[^`]+`)", shown)[::2]:
            left += [m.group(0) for m in pattern.finditer(piece)         # a hyphenated noun after an article stays
                     if m.group("q") or m.group("step") or not _ARTICLE.search(piece, 0, m.start())]
    assert not left, left[:5]


def test_the_engines_report_and_the_derivation_give_the_same_labels(check):
    # the record and the errata label from the report, the notebooks from the derivation: the same numbering
    for derivation in ("graefe-s2-volumes-simpson", "scheeffer-vii-viii", "euler-229-243"):
        report = next(r for r in check(derivation) if r.id == derivation)
        assert labels(report) == labels(load(derivation)[0]) != {}


def test_the_records_and_notebooks_show_no_cited_name():
    # what the site's errata pages show (docs/errata.json) and the notebooks say: Graefe §2's 'slab-a-c' is gone,
    # its formula's heading is there
    errata = json.loads((ROOT / "docs" / "errata.json").read_text(encoding="utf-8"))
    words = " ".join(e["evidence"] + e.get("objection", "") + e.get("answer", "") for e in errata)
    assert "slab-a-c" not in words and "see formula 1 of §2 Simpson's rule" in words
    notebook = (ROOT / "notebooks" / "graefe-s2-volumes-simpson.ipynb").read_text(encoding="utf-8")
    cells = [c for c in json.loads(notebook)["cells"] if c["cell_type"] == "markdown"]
    assert not any("'slab-a-c'" in "".join(c["source"]) for c in cells)
