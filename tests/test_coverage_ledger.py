"""The coverage ledger: spans found as the transcriptions mark them, each quoted, waived or
unaccounted; the committed baseline of unaccounted spans only shrinks; docs/coverage.md is current."""
import json
from pathlib import Path

import pytest

from symfloat.cli import main
from symfloat.model.source import SOURCES
from symfloat.model.span import math_intervals, math_spans, quantitative_sentences
from symfloat.report.ledger import (Entry, LedgerError, account, baseline_keys, entry_key, ledger, ledger_markdown,
                                    quotes, totals, waivers)
from symfloat.report.ledger_command import baseline_text

ROOT = Path(__file__).resolve().parents[1]
BASELINE = json.loads((ROOT / "docs" / "coverage-baseline.json").read_text(encoding="utf-8"))


def _entry(source, line, text):
    found = [e for e in ledger(source) if e.span.line == line and e.span.text == text]
    assert len(found) == 1, (source, line, text, found)
    return found[0]


# ---- spans ---------------------------------------------------------------------------------------
def test_a_stray_dollar_is_an_error():
    with pytest.raises(ValueError, match="unpaired"):
        math_intervals("a $x$ and $y\n")


def test_a_texts_math_spans_are_found_once_and_cannot_be_changed():
    text = "a $x$ b\n$$y = 1$$\n"
    assert math_intervals(text) is math_intervals(text) == ((2, 5, "inline"), (8, 17, "display"))


def test_span_counts_follow_the_dollars():
    # hasab: 16 lines are $$...$$ displays (grep -c '^\$\$' on the transcription); metazentrum has no $$
    # and writes its displays as $...$ alone on a line.
    hasab = math_spans("hasab")
    assert sum(s.kind == "display" for s in hasab) == 16
    assert all(s.text.startswith("$$") for s in hasab if s.kind == "display")
    meta = [s for s in math_spans("metazentrum") if s.kind == "display"]
    assert meta and not any(s.text.startswith("$$") for s in meta)
    for key in SOURCES:
        text = SOURCES[key].text()
        for s in math_spans(key):
            assert text[s.start:s.end] == s.text and s.text[0] == s.text[-1] == "$"
            assert text.splitlines()[s.line - 1][s.column - 1:].startswith(s.text.splitlines()[0])


def test_sentences_in_words_are_found():
    # scheeffer, VII-VIII: the roots of F(z) lie ... ; hasab: the remark on the second position
    texts = [s.text for s in quantitative_sentences("scheeffer")]
    assert any("Doppelwurzeln" in t for t in texts)
    assert not any(t.startswith("#") for t in texts)
    assert all("$$" not in t for t in texts)


# ---- statuses -------------------------------------------------------------------------------------
def test_every_span_has_one_status_and_quoted_spans_overlap_their_quote():
    for key in SOURCES:
        spans_of_quotes = {fid: (a, b) for a, b, fid in quotes()[key]}
        for e in ledger(key):
            assert e.status in ("quoted", "waived", "unaccounted")
            assert (e.status == "waived") == bool(e.reason)
            for fid in e.quoted_by:
                assert e.span.overlaps(*spans_of_quotes[fid])


def test_known_entries():
    # hasab line 11 is quoted as hasab/s (DISPLAYS[0] of derivations/hasab/statements.py)
    assert _entry("hasab", 11, "$$s = \\varrho.$$").quoted_by == ("hasab/s",)
    # scheeffer line 48: "über dem Schwerpunkt $S_1$" -- a bare symbol
    assert _entry("scheeffer", 48, "$S_1$").reason == "bare-symbol"
    # metazentrum repeats z_G = c - d (line 174, quoted) on line 282
    assert _entry("metazentrum", 174, "$ z_G = c - d $").status == "quoted"
    assert _entry("metazentrum", 282, "$ z_G = c - d $").reason == "repeat"
    # metazentrum: the units of its table of variables are judged notation
    assert _entry("metazentrum", 564, "$kg/m^3$").reason == "notation"


def test_dropping_a_quote_leaves_its_span_unaccounted():
    # mutation: without the quote of hasab/x+y the display (x+y)/2 = rho is accounted for by nothing
    quoted = [q for q in quotes()["hasab"] if q[2] != "hasab/x+y"]
    entries = {(e.span.line, e.span.text): e for e in account("hasab", quoted, waivers("hasab"))}
    assert entries[(27, "$$\\frac{x + y}{2} = \\varrho.$$")].status == "unaccounted"
    full = {(e.span.line, e.span.text): e for e in ledger("hasab")}
    assert full[(27, "$$\\frac{x + y}{2} = \\varrho.$$")].status == "quoted"


def test_a_stale_or_malformed_waiver_is_an_error():
    quoted = quotes()["hasab"]
    with pytest.raises(LedgerError, match="stale"):
        account("hasab", quoted, [{"line": 11, "text": "$$s = \\varrho.$$", "reason": "notation", "note": "x"}])
    with pytest.raises(LedgerError, match="no span"):
        account("hasab", quoted, [{"line": 12, "text": "$$s = \\varrho.$$", "reason": "notation", "note": "x"}])
    text = "A teljes energia két részre bontható, a hasáb és a kiszorított víz helyzeti energiájára."
    ok = account("hasab", quoted, [{"line": 7, "text": text, "reason": "notation", "note": "a splitting"}])
    assert [e.reason for e in ok if e.span.text == text] == ["notation"]


def test_waiver_files_use_judged_reasons_with_notes():
    for key in SOURCES:
        for w in waivers(key):
            assert w["reason"] in ("figure-reference", "lost-text", "notation") and w["note"].strip()


# ---- baseline and report --------------------------------------------------------------------------
def test_no_unaccounted_span_outside_the_baseline():
    listed = baseline_keys(BASELINE)
    new = [entry_key(e) for k in SOURCES for e in ledger(k) if e.status == "unaccounted" and entry_key(e) not in listed]
    assert new == [], f"unaccounted spans not in docs/coverage-baseline.json (quote or waive them): {new[:10]}"


def test_the_baseline_only_shrinks():
    now = {entry_key(e) for k in SOURCES for e in ledger(k) if e.status == "unaccounted"}
    accounted = sorted(baseline_keys(BASELINE) - now)
    assert accounted == [], ("entries of docs/coverage-baseline.json are accounted for now: run "
                             f"`symfloat coverage --update-baseline` and commit: {accounted[:10]}")
    assert len(BASELINE["unaccounted"]) == len(baseline_keys(BASELINE))


def test_baseline_file_is_what_the_command_writes():
    assert (ROOT / "docs" / "coverage-baseline.json").read_text(encoding="utf-8") == baseline_text()


def test_coverage_report_is_current():
    assert (ROOT / "docs" / "coverage.md").read_text(encoding="utf-8") == ledger_markdown(), \
        "docs/coverage.md is stale: run `symfloat coverage --write` and commit"


def test_totals_add_up():
    for key in SOURCES:
        t = totals(ledger(key))
        assert t["spans"] == t["display"] + t["inline"] + t["sentences"]
        assert t["spans"] == t["quoted"] + sum(t["waived"].values()) + t["unaccounted"]


# ---- command line ---------------------------------------------------------------------------------
def _one_unaccounted(monkeypatch, source):
    """Patch the ledger (where the command and the table read it) so that the first span of *source* is
    unaccounted; return that entry."""
    import symfloat.report.ledger as ledger_module
    import symfloat.report.ledger_command as command
    real = ledger_module.ledger
    first = Entry(real(source)[0].span, "unaccounted")

    def fake(s):
        return (first,) + real(s)[1:] if s == source else real(s)
    monkeypatch.setattr(ledger_module, "ledger", fake)
    monkeypatch.setattr(command, "ledger", fake)
    return first


def test_cli_json_and_exit_status(capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    assert main(["coverage", "hasab", "--format", "json"]) == 0      # hasab is accounted span by span
    out = json.loads(capsys.readouterr().out)
    entries = out["sources"]["hasab"]["entries"]
    assert out["sources"]["hasab"]["totals"]["spans"] == len(entries) == len(ledger("hasab"))
    assert {e["status"] for e in entries} <= {"quoted", "waived", "unaccounted"}
    _one_unaccounted(monkeypatch, "hasab")                              # mutation: one span left unaccounted
    assert main(["coverage", "hasab", "--format", "json"]) == 1
    out = json.loads(capsys.readouterr().out)
    assert out["sources"]["hasab"]["totals"]["unaccounted"] == 1


def test_cli_table_marks_pending_spans(capsys, monkeypatch, tmp_path):
    import symfloat.report.ledger_command as command
    monkeypatch.chdir(tmp_path)      # the baseline is the checkout's, wherever the command runs
    main(["coverage", "euler"])
    out = capsys.readouterr().out
    assert out.startswith("euler: 386 spans") and "0 unaccounted" in out and "NEW" not in out
    e = _one_unaccounted(monkeypatch, "hasab")
    main(["coverage", "hasab"])
    out = capsys.readouterr().out
    assert out.startswith("hasab: 32 spans") and "NEW     hasab:" in out and "pending" not in out
    monkeypatch.setattr(command, "load_baseline", lambda path: {"unaccounted": [e.as_dict()]})
    main(["coverage", "hasab"])
    out = capsys.readouterr().out
    assert "pending hasab:" in out and "NEW" not in out


def test_cli_unknown_source(capsys):
    assert main(["coverage", "nosuch"]) == 2
    assert "unknown source" in capsys.readouterr().err


def test_a_sentence_repeated_word_for_word_is_a_computed_repeat():
    # metazentrum prints its stability paragraph twice (transcription 003, lines 274 and 833): the first
    # is quoted (metazentrum/criterion-words), the second is waived as a repeat without a judged waiver
    from symfloat.report.ledger import ledger
    entries = [e for e in ledger("metazentrum") if e.span.kind == "sentence" and e.span.line in (274, 833)]
    assert [(e.span.line, e.status, e.reason) for e in entries] == [(274, "quoted", ""), (833, "waived", "repeat")]


@pytest.mark.parametrize("baseline, says", [
    ("garbage{", "cannot read the coverage baseline"),
    ("[]", "is no coverage baseline"),
    ('{"unaccounted": [1, 2]}', "is no coverage baseline"),
])
def test_a_bad_baseline_or_output_folder_is_one_line(tmp_path, capsys, baseline, says):
    # each of these once ended in a traceback (JSONDecodeError, TypeError, NotADirectoryError)
    (tmp_path / "coverage-baseline.json").write_text(baseline, encoding="utf-8")
    assert main(["coverage", "hasab", "--output", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert says in err and err.count("\n") == 1
    assert main(["coverage", "hasab", "--output", str(tmp_path / "coverage-baseline.json")]) == 2
    assert "not a folder" in capsys.readouterr().err
    assert main(["coverage", "hasab", "--write", "--output", str(tmp_path / "a" / "b")]) == 2
    assert "creates one folder, not a tree" in capsys.readouterr().err and not (tmp_path / "a").exists()
