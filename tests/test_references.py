"""Scheeffer's cross-references to his numbered equations, resolved to the displays that carry the numbers."""
from pathlib import Path

from symfloat.report.references import references, references_markdown, tags

ROOT = Path(__file__).resolve().parents[1]


def test_tags_are_the_display_numbers():
    t = tags("scheeffer")
    # (2) closes the display "V_1 m > 0. \quad (2)" (line 60 of the transcription); (175) is the last number
    assert t["2"] == 60 and "175" in t and "10a" in t
    assert "8" not in t          # (8) is only referred to (tests/test_scheeffer_coverage.py, LACKING)


def test_references_resolve_backwards_or_are_flagged():
    refs = references("scheeffer")
    by = {(r["line"], r["number"]): r for r in refs}
    assert by[(88, "7")]["status"] == "resolved" and by[(88, "8")]["status"] == "untagged"   # "(s. 7 u. 8)"
    assert by[(723, "73")]["target_line"] == 721                                              # "aus 73 auch"
    assert all(r["status"] in ("resolved", "forward", "untagged") for r in refs)
    assert all((r["target_line"] is None) == (r["status"] == "untagged") for r in refs)


def test_references_report_is_current():
    assert (ROOT / "docs" / "references.md").read_text(encoding="utf-8") == references_markdown(), \
        "docs/references.md is stale: run `symfloat coverage --write` and commit"
