"""One fault, one erratum: same_as links are checked, unlinked repeats are listed (docs/repeats.json)."""
import json
from pathlib import Path

import pytest

from symfloat.model.derivation import Printed
from symfloat.model.erratum import Erratum
from symfloat.report.repeats import candidates, candidates_text, errata_index, link_problems

ROOT = Path(__file__).resolve().parents[1]


def _p(name, kind="transcription", confidence="high", same_as="", evidence="probe"):
    return Printed(name, "(1)", "x", reading=(1, 1),
                   erratum=Erratum(kind, confidence, "y", evidence, same_as=same_as))


def test_links_must_name_a_booked_fault_of_the_same_kind_and_confidence():
    index = {"d/a": ("s", _p("a")),
             "d/b": ("s", _p("b", same_as="d/a")),                              # a good link
             "d/c": ("s", _p("c", confidence="low", same_as="d/a")),            # confidence differs
             "d/e": ("s", _p("e", same_as="d/b")),                              # a repeat of a repeat
             "d/f": ("s", _p("f", same_as="d/nothing"))}                        # no such erratum
    problems = link_problems(index)
    assert len(problems) == 3
    assert any(m.startswith("d/c:") and "transcription/high" in m for m in problems)
    assert any(m.startswith("d/e:") and "book the fault once" in m for m in problems)
    assert any(m.startswith("d/f:") and "names no formula" in m for m in problems)


def test_same_as_must_be_a_formula_id():
    with pytest.raises(ValueError, match="formula id"):
        Erratum("transcription", "high", "y", "probe", same_as="81a")


def test_candidates_come_from_the_evidence_and_vanish_when_linked():
    index = {"d/81a": ("s", _p("81a")), "d/82": ("s", _p("82", evidence="the same '6' read as 'b' as in (81a)"))}
    assert [(c["erratum"], c["same_as"], c["consistent"]) for c in candidates(index)] == [("d/82", "d/81a", True)]
    linked = {**index, "d/82": ("s", _p("82", same_as="d/81a", evidence="the same '6' read as 'b' as in (81a)"))}
    assert candidates(linked) == []


def test_the_project_links_hold_and_the_candidates_are_recorded():
    index = errata_index()
    assert link_problems(index) == []
    pairs = {(c["erratum"], c["same_as"]) for c in candidates(index)}
    assert ("scheeffer-vi-cf/82", "scheeffer-vi-cf/81a") in pairs       # '6' read as 'b', (81a) and (82)
    assert (ROOT / "docs" / "repeats.json").read_text(encoding="utf-8") == candidates_text(index), \
        "docs/repeats.json is stale: run `symfloat coverage --write` and commit"
    assert json.loads(candidates_text(index))["candidates"]
