"""A cached report is judged again when read (symfloat issue 32): an entry whose content hash was
recomputed after an edit is still refused when the report does not stand up to the checker's own
rules (the report schema, the key it was stored under, every verdict re-derived from its recorded
checks, witness records and erratum), re-checked, and named on stderr; it is never believed."""
import json
import shutil

import pytest

from symfloat.engine.cache import ReportCache, report_hash
from symfloat.engine.check import judge, rejudged
from symfloat.engine.runner import _cached_report, verify

DID = "graefe-s1-prismatoid-volume"


@pytest.fixture(scope="module")
def checked_once(tmp_path_factory):
    """graefe-s1 checked once into a private cache (20 printed formulas, 9 of them errata)."""
    folder = tmp_path_factory.mktemp("cache")
    return folder, verify("graefe-s1", cache=ReportCache(folder))[0]


@pytest.fixture
def forge(checked_once, tmp_path):
    """``forge(edit)``: a copy of the cache whose entry's report *edit* changed, its hash recomputed
    (so the envelope's checks all pass); returns the cache and the entry's key."""
    shutil.copytree(checked_once[0], tmp_path, dirs_exist_ok=True)
    (path,) = tmp_path.glob(f"{DID}.*.json")
    key = path.name.split(".")[1]

    def forged(edit):
        entry = json.loads(path.read_text(encoding="utf-8"))
        edit(entry["report"])
        entry["sha256"] = report_hash(entry["report"])
        path.write_text(json.dumps(entry), encoding="utf-8")
        cache = ReportCache(tmp_path)
        assert cache.get(DID, key) is not None          # the envelope vouches for it: only the rules can refuse
        return cache, key
    return forged


def _errata_to_verified(report):
    for f in report["formulas"]:
        if f["verdict"] == "erratum":
            f["verdict"], f["erratum"] = "verified", None


def _every_step_refuted(report):
    for s in report["steps"]:
        s["status"] = "refuted"
        if s["identity"] is not None:
            s["identity"]["status"] = "refuted"


def _witness_off_by_2e_2(report):
    # a method's record (a certified one is decided by its bounds, not by rel_error)
    f = next(f for f in report["formulas"] if f["verdict"] == "verified"
             and any(not r.get("certified") for r in f["numeric"]))
    next(r for r in f["numeric"] if not r.get("certified"))["rel_error"] = 2e-2


def _ball_moved_off(report):
    # a certified record (the definition route's, in balls) whose difference is made proven beyond its rounding
    f = next(f for f in report["formulas"] if f["verdict"] == "verified" and any(r.get("certified") for r in f["numeric"]))
    next(r for r in f["numeric"] if r.get("certified")).update(abs_error=1e-3, abs_error_lower=1e-3)


FORGERIES = {
    "a certified difference moved off 0": (_ball_moved_off, "a witness disagrees"),
    "nine errata turned verified": (_errata_to_verified, "recorded 'verified'"),
    "verdict banana": (lambda r: r["formulas"][0].update(verdict="banana"), "the report.formulas[0].verdict must be one of"),
    "every step refuted": (_every_step_refuted, "is refuted"),
    "no formula": (lambda r: r.update(formulas=[]), "the report.formulas must contain at least 1 items"),
    "a witness 2e-2 off left verified": (_witness_off_by_2e_2, "a witness disagrees"),
    "seconds of the wrong type": (lambda r: r.update(seconds="3 s"), "the report.seconds must be number"),
    "uses of the wrong type": (lambda r: r["steps"][0].update(uses=5), "the report.steps[0].uses must be array"),
    "another derivation's key": (lambda r: r.update(key="0" * 32), "under key 00000"),
}


def test_the_honest_entry_is_read(checked_once):
    folder, fresh = checked_once
    (path,) = folder.glob(f"{DID}.*.json")
    report = _cached_report(ReportCache(folder), DID, path.name.split(".")[1])
    assert report is not None and report.cached
    assert [f.verdict for f in report.formulas] == [f.verdict for f in fresh.formulas]


@pytest.mark.parametrize("name", FORGERIES)
def test_a_forged_entry_is_refused_with_one_line(forge, capsys, name):
    edit, reason = FORGERIES[name]
    cache, key = forge(edit)
    assert _cached_report(cache, DID, key) is None
    (line,) = capsys.readouterr().err.splitlines()
    assert line.startswith(f"symfloat: cache entry {cache.path(DID, key)} refused (") and reason in line, line


def test_a_forged_verdict_is_checked_again_and_replaced(forge, checked_once, capsys):
    # the attack of the issue: Graefe's errata of graefe-s1 (10 of 21 formulas) turned "verified", hash recomputed
    cache, key = forge(_errata_to_verified)
    again = verify("graefe-s1", cache=cache)[0]
    assert not again.cached and "refused" in capsys.readouterr().err
    assert [f.verdict for f in again.formulas] == [f.verdict for f in checked_once[1].formulas]
    assert sum(f.verdict == "erratum" for f in again.formulas) == 10      # graefe-s1's errata, docs/errata.md
    assert verify("graefe-s1", cache=cache)[0].cached                       # the entry replaced by a sound one


def test_judge_refuses_what_the_checker_refuses(checked_once):
    """The rule a cached report is judged by is the checker's: a refuted reading without an erratum, a
    declared erratum on a print that holds, a witness beyond its bound are failures."""
    fresh = checked_once[1]
    erratum = next(f for f in fresh.formulas if f.verdict == "erratum")
    verified = next(f for f in fresh.formulas
                    if f.verdict == "verified" and any(not r.get("certified") for r in f.numeric))
    assert judge(erratum, True)[:2] == ("erratum", erratum.evidence) and judge(erratum, True)[2] == []
    assert "no erratum is declared" in judge(erratum, False)[2][0]
    assert judge(verified, True)[2] == ["an erratum is declared but the print holds"]
    k = next(k for k, r in enumerate(verified.numeric) if not r.get("certified"))
    verified.numeric[k] = {**verified.numeric[k], "rel_error": 2e-2}
    assert judge(verified, False)[2] == ["derived and printed agree but a witness disagrees"]


def test_the_test_run_reads_only_the_cache_it_writes(cache_dir, tmp_path_factory):
    # conftest: SYMFLOAT_CACHE is this run's cache, a folder of the run's own temporary directory,
    # so no command a test runs reads the checkout's .symfloat-cache
    assert ReportCache().root == cache_dir
    assert cache_dir.is_relative_to(tmp_path_factory.getbasetemp().parent)


def test_search_proofs_searches_whatever_the_cache_holds(checked_once, tmp_path):
    # symfloat issue 32: with a warm cache, --search-proofs printed "cached" and searched nothing
    shutil.copytree(checked_once[0], tmp_path, dirs_exist_ok=True)
    assert verify("graefe-s1", cache=ReportCache(tmp_path))[0].cached
    searched = verify("graefe-s1", cache=ReportCache(tmp_path), search_proofs=True)[0]
    assert not searched.cached and searched.searched()          # every claim's proof searched anew
    assert set(searched.searched()) == set(checked_once[1].proofs)
    assert [f.verdict for f in searched.formulas] == [f.verdict for f in checked_once[1].formulas]


def test_every_report_the_checker_writes_stands_up_to_its_own_judgement(all_reports):
    # the judgement refuses no sound report: each of the library's 17 reports, as checked in this run, is
    # read back (its proofs include certificates whose search found no strategy: strategy null)
    for report in all_reports:
        assert not report.failures, report.id
        again = rejudged(report.to_json(), report.id, report.key)
        assert [(f.verdict, f.evidence) for f in again.formulas] == [(f.verdict, f.evidence) for f in report.formulas]
