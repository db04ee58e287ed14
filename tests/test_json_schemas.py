"""Every ``--format json`` output validates against its written schema (symfloat/schemas/, shipped
with the package), and the committed records too; the schemas themselves are valid and not vacuous."""
import copy
import json
import math
from collections import Counter
from importlib.resources import files
from pathlib import Path

import pytest
from jsonschema import Draft202012Validator

from symfloat.cli import main
from symfloat.engine.witness import record_decision

ROOT = Path(__file__).resolve().parents[1]


def schema(name):
    return json.loads(files("symfloat").joinpath("schemas", f"{name}.schema.json").read_text(encoding="utf-8"))


def errors(name, instance):
    return [f"{list(e.absolute_path)}: {e.message}" for e in Draft202012Validator(schema(name)).iter_errors(instance)]


@pytest.fixture
def run(capsys, monkeypatch, cache_dir, tmp_path):
    monkeypatch.setenv("SYMFLOAT_CACHE", str(cache_dir))
    monkeypatch.chdir(tmp_path)

    def call(*argv):
        assert main([*argv, "--format", "json", "--quiet"]) == 0
        return json.loads(capsys.readouterr().out)
    return call


@pytest.mark.parametrize("name", ["verify", "errata", "scene", "phase", "report", "check"])
def test_schemas_are_valid_json_schemas(name):
    Draft202012Validator.check_schema(schema(name))


def test_committed_records_follow_their_schemas():
    assert errors("verify", json.loads((ROOT / "docs" / "verification.json").read_text(encoding="utf-8"))) == []
    assert errors("errata", json.loads((ROOT / "docs" / "errata.json").read_text(encoding="utf-8"))) == []


def counted_from_entries(record):
    """The summary's counts made again from the record's formula entries alone."""
    formulas = record["formulas"]
    checked = [f for f in formulas if f["verdict"] in ("verified", "erratum") and f.get("numeric_content", True)]
    witnesses = [r for f in formulas for r in f["numeric"] + (f.get("erratum") or {}).get("numeric", [])]
    return {"formulas": len(formulas),
            **{v: sum(f["verdict"] == v for f in formulas) for v in ("verified", "erratum", "unverifiable", "trivial")},
            "evidence": dict(Counter(f["evidence"] or "none" for f in formulas)),
            "cross_checked": {"formulas": sum(bool(f["numeric"] or (f.get("erratum") or {}).get("numeric"))
                                              for f in checked), "with_numeric_content": len(checked)},
            "certified": dict(Counter(record_decision(r) for r in witnesses if r.get("certified")))}


def test_committed_summary_counts_what_the_entries_hold():
    # the summary once counted the corrected readings' witness records, which the entries did not carry
    # (1,074 formulas cross-checked said, 1,057 to be found; 935 certified agreements said, 788 found)
    record = json.loads((ROOT / "docs" / "verification.json").read_text(encoding="utf-8"))
    summary = {k: record["summary"][k] for k in counted_from_entries(record)}
    assert counted_from_entries(record) == summary
    erratum = next(f for f in record["formulas"] if (f.get("erratum") or {}).get("numeric"))
    del erratum["erratum"]["numeric"]
    assert counted_from_entries(record) != summary


def test_verify_and_errata_outputs(run, graefe_reports):
    record = run("verify", "graefe")
    assert errors("verify", record) == []
    assert errors("errata", run("errata", "graefe")) == []
    # not vacuous: an unverifiable formula without its reason, a verified one without evidence, an
    # erratum of an unknown kind are each caught
    bad = copy.deepcopy(record)
    unverifiable = next(f for f in bad["formulas"] if f["verdict"] == "unverifiable")
    del unverifiable["reason"]
    next(f for f in bad["formulas"] if f["verdict"] == "verified")["evidence"] = None
    next(f for f in bad["formulas"] if f["verdict"] == "erratum")["erratum"]["kind"] = "typo"
    assert len(errors("verify", bad)) == 3


@pytest.mark.parametrize("argv", [
    ("cube", "--density", "0.22"),
    ("prism", "--sides", "5", "--dims", "1,2", "--density", "0.6"),
    ("cylinder", "--dims", "1,2", "--density", "0.3"),
    ("section", "--polygon", "0,0 3,0 0,1", "--density", "0.3"),
], ids=lambda a: a[0])
def test_scene_outputs(run, argv):
    record = run("scene", *argv)
    assert errors("scene", record) == []
    for e in record["equilibria"]:
        assert math.isclose(math.hypot(*e["up"]), 1, rel_tol=1e-12)
        for p in e["predictions"]:
            assert math.isclose(math.hypot(*p["predicted_up"]), 1, rel_tol=1e-12)
    for p in record["unmatched_predictions"]:
        assert math.isclose(math.hypot(*p["predicted_up"]), 1, rel_tol=1e-12)
    bad = copy.deepcopy(record)
    bad["equilibria"][0]["waterplane"] = "0-gon"            # the label of a degenerate answer
    bad["seconds"] = 1.5                                     # seconds is an object
    assert len(errors("scene", bad)) == 2


@pytest.mark.slow
def test_phase_output(run):
    # the default run validates the phase record of tests/test_phase.py's sweep instead
    record = run("phase", "cube", "--steps", "4")
    assert errors("phase", record) == []
    assert record["dims"] == [1.0, 1.0, 1.0] and record["dims_exact"] == ["1", "1", "1"]
    bad = copy.deepcopy(record)
    bad["dims"] = bad["dims_exact"]                          # dims are numbers, as in the scene record
    assert errors("phase", bad)
