"""The command line and its JSON contracts (design brief, 'Output contracts')."""
import json

import pytest

from symfloat.cli import main

FORMULA_KEYS = {"id", "source", "locator", "verdict", "evidence", "numeric"}
RECORD_KEYS = {"method", "abs_error", "rel_error", "seconds"}
ERRATUM_KEYS = {"id", "source", "locator", "printed", "corrected", "kind", "confidence", "evidence", "derivation"}


@pytest.fixture
def in_tmp(tmp_path, monkeypatch, cache_dir, graefe_reports):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("SYMFLOAT_CACHE", str(cache_dir))
    return tmp_path


def test_verify_json_contract(in_tmp, capsys):
    assert main(["verify", "graefe", "--format", "json", "--quiet"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["formulas"] and set(out["summary"]) >= {"verified", "erratum", "unverifiable", "seconds"}
    for f in out["formulas"]:
        assert FORMULA_KEYS <= set(f) and f["source"] == "graefe"
        assert f["verdict"] in ("verified", "erratum", "unverifiable")
        assert f["evidence"] in ("symbolic", "sampled", "numeric", None)
        for rec in f["numeric"]:
            assert RECORD_KEYS <= set(rec) and rec["seconds"] >= 0
    s = out["summary"]
    assert s["verified"] + s["erratum"] + s["unverifiable"] + s["trivial"] == len(out["formulas"]) == s["formulas"]


def test_selector_computes_only_what_it_selects_and_its_ancestors(in_tmp, capsys):
    assert main(["verify", "graefe-s3", "--format", "json", "--quiet"]) == 0
    derivations = json.loads(capsys.readouterr().out)["summary"]["derivations"]
    assert derivations == ["graefe-s1-prismatoid-volume", "graefe-s3-prismatoid-centroid"]


def test_a_selections_errata_are_its_own(in_tmp, capsys):
    # graefe-s3 is checked with its ancestor graefe-s1, whose errata `errata graefe-s3` listed too (as
    # `errata hasab` listed Scheeffer's)
    assert main(["errata", "graefe-s3", "--format", "json", "--quiet"]) == 0
    derivations = {e["derivation"] for e in json.loads(capsys.readouterr().out)}
    assert derivations == {"graefe-s3-prismatoid-centroid"}


def test_errata_json_contract(in_tmp, capsys):
    assert main(["errata", "graefe", "--format", "json", "--quiet"]) == 0
    entries = json.loads(capsys.readouterr().out)
    assert entries
    for e in entries:
        assert ERRATUM_KEYS <= set(e)
        assert e["kind"] in ("transcription", "misprint", "calculation", "consequential", "claim")
        assert e["confidence"] in ("high", "medium", "low") and e["evidence"]
    assert len({e["id"] for e in entries}) == len(entries)


def test_a_selection_prints_its_errata_or_writes_them_where_asked(in_tmp, capsys):
    assert main(["errata", "graefe", "--quiet"]) == 0
    printed = capsys.readouterr().out
    assert printed.startswith("# Errata") and "## graefe" in printed and "## scheeffer" not in printed
    assert not (in_tmp / "docs").exists()
    (in_tmp / "sel").mkdir()
    assert main(["errata", "graefe", "--quiet", "--output", "sel/graefe.md"]) == 0
    assert (in_tmp / "sel" / "graefe.md").read_text(encoding="utf-8") == printed


def test_unknown_selector_is_one_clear_message(in_tmp, capsys):
    assert main(["verify", "nosuchsource", "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("symfloat: selector 'nosuchsource' matches no derivation") and "Traceback" not in err


def test_table_is_readable(in_tmp, capsys):
    assert main(["verify", "graefe-s1", "--quiet"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0].split()[:3] == ["formula", "locator", "verdict"]
    assert "printed formulas:" in out
    # an erratum whose only witness measures its correction shows that witness (it showed "—", while the
    # summary counted it as cross-checked): Graefe §1's list of tetrahedra
    row = next(line for line in out.splitlines() if line.startswith("graefe-s1-prismatoid-volume/tetrahedra-list "))
    assert row.endswith(", of the correction") and "proven" in row


def test_unexpected_failure_gives_exit_status_1(in_tmp, monkeypatch, capsys, graefe_reports):
    import copy

    import symfloat.cli as cli
    broken = copy.deepcopy(graefe_reports[:1])
    broken[0].failures = ["graefe §1 (x): the print is refuted and no erratum is declared"]
    monkeypatch.setattr(cli, "verify", lambda *a, **k: broken)
    assert cli.main(["verify", "graefe-s1", "--quiet"]) == 1
    assert "FAILURE: graefe §1 (x)" in capsys.readouterr().out


def test_no_cache_is_offered_where_a_cache_is_read(capsys):
    # --no-cache ("re-check every derivation") was offered by scene, phase, check, atlas, site and bench,
    # which read no cache; it is still accepted there, so scripts that pass it keep working
    from symfloat.cli import _parser
    for name in ("verify", "errata", "notebooks", "run", "scene", "phase", "check"):
        sub = _parser(name)._subparsers._group_actions[0].choices[name]
        assert ("--no-cache" in sub.format_help()) == (name in ("verify", "errata", "notebooks", "run")), name
    assert main(["scene", "cube", "--density", "0.3", "--no-cache", "--quiet"]) == 0
