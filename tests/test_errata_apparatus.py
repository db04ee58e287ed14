"""The errata report's two apparatus (symfloat/report/errata.py, symfloat/model/erratum.py): faults of the
original and corrections of the transcription, counted and listed apart.  The entries are stand-ins in the
shape of a derivation report; their kinds are chosen so that each apparatus has one."""
from __future__ import annotations

import json
from types import SimpleNamespace

from symfloat.model.erratum import APPARATUS, KINDS, apparatus
from symfloat.cli import _summary_by_source
from symfloat.report.errata import apparatus_counts, errata_json, errata_latex, errata_markdown


def _formula(name, kind):
    return SimpleNamespace(id=f"scheeffer-x/{name}", verdict="erratum", source="scheeffer", locator=f"({name})",
                           excerpt=f"printed {name}", erratum={"kind": kind, "confidence": "high",
                                                               "corrected": f"corrected {name}",
                                                               "evidence": f"why {name}"})


REPORTS = [SimpleNamespace(id="scheeffer-x", formulas=[_formula("1", "transcription"), _formula("2", "misprint"),
                                                        _formula("3", "claim")])]


def test_every_kind_has_one_apparatus():
    assert sorted(k for _, kinds in APPARATUS.values() for k in kinds) == sorted(KINDS)
    assert [apparatus(k) for k in ("misprint", "calculation", "consequential", "claim", "transcription")] == \
        ["original"] * 4 + ["transcription"]


def test_the_json_stays_one_array_and_names_the_apparatus():
    entries = json.loads(errata_json(REPORTS))
    assert isinstance(entries, list) and [e["apparatus"] for e in entries] == ["transcription", "original", "original"]


def test_the_markdown_lists_the_two_apparatus_apart():
    md = errata_markdown(REPORTS)
    one, two = md.index("# Part I: Faults of the original (2)"), md.index("# Part II: Corrections of the transcription (1)")
    assert one < md.index("### (2)") < md.index("### (3)") < two < md.index("### (1)")    # the misprint in I, the scan's in II
    assert "The original very probably printed:" in md[two:] and "The original very probably printed:" not in md[:two]
    assert "3 errata: 2 faults of the original, 1 correction of the transcription" in md      # one: singular
    counts = apparatus_counts(json.loads(errata_json(REPORTS)))
    assert counts == "2 faults of the original, 1 correction of the transcription"


def test_the_latex_list_keeps_the_two_apparatus_apart_too():
    # it was one list per source, the scan's corrections first (source order), each labelled "Read:"
    tex = errata_latex(REPORTS)
    one = tex.index("\\section*{Part I: Faults of the original (2)}")
    two = tex.index("\\section*{Part II: Corrections of the transcription (1)}")
    assert one < tex.index("\\textbf{(2)}") < tex.index("\\textbf{(3)}") < two < tex.index("\\textbf{(1)}")
    assert tex[one:two].count("Corrected:") == 2 and "The original very probably printed:" in tex[two:]
    assert "\\\\" not in tex               # lines end with \par: \\ after a display \] is a LaTeX error


def test_the_run_summary_counts_the_apparatus_apart():
    reports = [SimpleNamespace(source="scheeffer", seconds=1.0, formulas=REPORTS[0].formulas)]
    line = _summary_by_source(reports)
    assert "3 printed formulas — 0 verified, 2 faults of the original, 1 transcription corrected" in line
    assert "errata" not in line
