"""The committed reports and notebooks are what the code generates now.

This is the proof check of CI: a verdict that changes, an erratum that
appears or disappears, or a notebook that no longer matches fails here until
the outputs are regenerated (``make run``) and committed.
"""
import json
import math
import re
from pathlib import Path

import nbformat
import pytest

from symfloat.report.errata import errata_json, errata_markdown
from symfloat.files import without_timings
from symfloat.engine.runner import derivation_keys
from symfloat.report.notebooks import build_notebook, notebook_stamp, recorded_stamp, write_notebooks
from symfloat.report.record import (HARDWARE_DOUBLES, record_differences, record_json, verification_record,
                                    write_record)

ROOT = Path(__file__).resolve().parents[1]


def test_no_check_fails(all_reports):
    failures = [m for r in all_reports for m in r.failures]
    assert failures == []


def test_errata_report_is_current(all_reports):
    assert (ROOT / "docs" / "errata.md").read_text(encoding="utf-8") == errata_markdown(all_reports), \
        "docs/errata.md is stale: run `make run` and commit"
    assert (ROOT / "docs" / "errata.json").read_text(encoding="utf-8") == errata_json(all_reports)


def test_verification_record_is_current(all_reports):
    committed = json.loads((ROOT / "docs" / "verification.json").read_text(encoding="utf-8"))
    fresh = json.loads(json.dumps(verification_record(all_reports)))
    assert record_differences(committed, fresh) == [], "docs/verification.json is stale: run `make run` and commit"


def test_the_record_is_kept_when_only_float64_last_bits_and_timings_differ(tmp_path, all_reports):
    # another machine or numpy release sums in another order: the committed file must stay as it is
    path = tmp_path / "verification.json"
    record = json.loads(record_json(all_reports))
    f = next(f for f in record["formulas"] if any(n["method"] == "float64" and n["abs_error"] for n in f["numeric"]))
    n = next(n for n in f["numeric"] if n["method"] == "float64" and n["abs_error"])
    n["abs_error"], n["seconds"] = math.nextafter(n["abs_error"], math.inf), n["seconds"] + 1
    text = json.dumps(record, indent=1, ensure_ascii=False) + "\n"
    path.write_text(text, encoding="utf-8")
    assert not write_record(path, all_reports) and path.read_text(encoding="utf-8") == text
    f["evidence"] = "sampling"                                # a real change is written
    path.write_text(json.dumps(record, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    assert write_record(path, all_reports) and path.read_text(encoding="utf-8") == record_json(all_reports)


def test_a_changed_verdict_or_witness_is_a_difference():
    # the comparison must see what matters: a verdict, an evidence level, a digit of an mpmath witness
    committed = json.loads((ROOT / "docs" / "verification.json").read_text(encoding="utf-8"))
    for change in ({"verdict": "erratum"}, {"evidence": "sampled"}):
        fresh = json.loads(json.dumps(committed))
        fresh["formulas"][0].update(change)
        assert record_differences(committed, fresh) == [f"{fresh['formulas'][0]['id']}: {next(iter(change))} differs"]
    fresh = json.loads(json.dumps(committed))
    f = next(f for f in fresh["formulas"] if any("mpmath" in n["method"] for n in f["numeric"]))
    n = next(n for n in f["numeric"] if "mpmath" in n["method"])
    n["abs_error"] = n["abs_error"] * (1 + 1e-12) + 1e-300
    assert record_differences(committed, fresh) == [f"{f['id']}: witness {n['method']} differs"]


# A witness's row whose figures are the machine's (symfloat.report.record: what another machine reproduces): in
# hardware doubles, "| float64 | 2 | ≤ 7.9e-15 | ≤ 2.0e-13 |" (7.2e-15 and 1.8e-13 on a processor with AVX-512),
# and an agreeing enclosure, whose ball may start at a float64 root
_MACHINE_ROWS = (re.compile(rf"(\| (?:{'|'.join(map(re.escape, HARDWARE_DOUBLES))}) \| \d+ \|) ≤ [^|\n]* \| ≤ [^|\n]* \|"),
                 re.compile(r"(\| Arb ball arithmetic \| \d+ \|) ≤ \S+ (\(agrees, \d+ bits\)) \| ≤ [^|\n]* \|"))


def _machine_figures_masked(text: str) -> str:
    """*text* with the figures of the rows above as ``F``.

    >>> _machine_figures_masked("| float64 | 2 | ≤ 7.9e-15 | ≤ 2.0e-13 |\\n| mpmath, 50 digits | 1 | ≤ 1e-50 | ≤ 1e-50 |")
    '| float64 | 2 | ≤ F | ≤ F |\\n| mpmath, 50 digits | 1 | ≤ 1e-50 | ≤ 1e-50 |'
    """
    text = _MACHINE_ROWS[0].sub(r"\1 ≤ F | ≤ F |", text)
    return _MACHINE_ROWS[1].sub(r"\1 ≤ F \2 | ≤ F |", text)


def _cells(path):
    nb = nbformat.read(path, as_version=4)
    return [(c.id, c.cell_type, c.source,
             _machine_figures_masked(without_timings(json.dumps(c.get("outputs", []), sort_keys=True, ensure_ascii=False))))
            for c in nb.cells]


def test_the_machines_figures_are_masked_and_nothing_else():
    rows = ("| float64 | 2 | ≤ 7.9e-15 | ≤ 2.0e-13 |", "| definitions, 15 digits | 3 | ≤ 1.1e-16 | ≤ 4.2e-16 |",
            "| Arb ball arithmetic | 3 | ≤ 1.4e-47 (agrees, 128 bits) | ≤ 2.2e-47 |",
            "| Arb ball arithmetic | 1 | ≤ 0.52 (refuted, 128 bits) | ≤ 0.11 |", "| mpmath, 50 digits | 1 | ≤ 2e-50 | ≤ 3e-50 |")
    assert [_machine_figures_masked(r) for r in rows] == [
        "| float64 | 2 | ≤ F | ≤ F |", "| definitions, 15 digits | 3 | ≤ F | ≤ F |",
        "| Arb ball arithmetic | 3 | ≤ F (agrees, 128 bits) | ≤ F |", *rows[3:]]


def _assert_cells_rebuilt(did, report):
    committed = nbformat.read(ROOT / "notebooks" / f"{did}.ipynb", as_version=4)
    built = build_notebook(did, report)
    assert [(c.id, c.cell_type, c.source) for c in committed.cells] == \
        [(c.id, c.cell_type, c.source) for c in built.cells], f"notebooks/{did}.ipynb is stale"


def test_notebooks_are_stamped_with_their_present_inputs(all_reports):
    # a notebook is re-executed only when its stamp changes (derivation, library, notebook code, SymPy):
    # a committed notebook with the present stamp is what `make run` would write, if the stamp covers every
    # input of the cells (rebuilt below for two derivations, and for all in the slow run)
    ids = [r.id for r in all_reports]
    keys = derivation_keys(ids)
    for did in ids:
        committed = ROOT / "notebooks" / f"{did}.ipynb"
        assert committed.exists(), f"notebooks/{did}.ipynb is missing: run `make run`"
        assert recorded_stamp(committed) == notebook_stamp(did, keys), f"notebooks/{did}.ipynb is stale"
    assert sorted(p.stem for p in (ROOT / "notebooks").glob("*.ipynb")) == sorted(ids)


def test_the_notebook_stamp_changes_with_every_report_module_a_notebook_is_built_from(monkeypatch):
    # the stamp once left out the witness tables' words (report/witness_words.py): their numbers changed form and
    # `make run`, seeing every stamp current, left every notebook with the old tables.  Each module of
    # symfloat/report that the notebook builder imports, directly or through another (read from the sources'
    # relative imports), is changed by a byte as read, and the stamp must change
    import ast
    # (and the library's own top-level modules it imports, such as the words of prose and numbers; the packages
    # below, engine and model, are in the derivation's cache key)
    library = ROOT / "symfloat"
    seen, todo = set(), ["report/notebooks"]
    while todo:
        name = todo.pop()
        if name in seen or not (library / f"{name}.py").is_file():
            continue
        seen.add(name)
        for node in ast.walk(ast.parse((library / f"{name}.py").read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.module and node.level in (1, 2):
                todo.append(("report/" if node.level == 1 and name.startswith("report/") else "")
                            + node.module.split(".")[0])
    assert {"report/notebook_view", "report/witness_words", "numbers", "prose"} <= seen
    # what the derivation's cache key holds already (the library its check executes) changes the stamp through it
    from symfloat.engine.key import library_files
    from symfloat.registry import files
    keyed = {f.resolve() for f in library_files(files("graefe-s2-volumes-simpson"), "graefe_s2_volumes_simpson")}
    keys = {"graefe-s2-volumes-simpson": "k"}
    before = notebook_stamp("graefe-s2-volumes-simpson", keys)
    raw = Path.read_bytes
    missed = []
    # the digest itself makes no notebook; errors, files and leftovers say how, not what, it is written
    for name in sorted(seen - {"report/stamp", "errors", "files", "leftovers"}):
        f = library / f"{name}.py"
        if f.resolve() in keyed:
            continue
        monkeypatch.setattr(Path, "read_bytes", lambda self, f=f: raw(self) + b"#" * (self.resolve() == f))
        if notebook_stamp("graefe-s2-volumes-simpson", keys) == before:
            missed.append(name)
        monkeypatch.undo()
    assert missed == []


# two cheap notebooks to build (2.4 s and 3.0 s at load 16, against 9 to 17 s for Scheeffer VI.C-F's) that still
# take most kinds of cell: printed formulas refuted at a point and corrected, readings kept as printed
# (evaluate(False)), proof strategies cancel, expand and simplify, integrals carried out at a point (hasab)
SMALL = ("graefe-s1-prismatoid-volume", "hasab")


@pytest.mark.parametrize("did", SMALL)
def test_a_notebooks_cells_are_what_the_code_builds_now(did, reports_by_id):
    _assert_cells_rebuilt(did, reports_by_id[did])


@pytest.mark.slow
def test_every_notebooks_cells_are_what_the_code_builds_now(all_reports):
    for report in all_reports:
        _assert_cells_rebuilt(report.id, report)


@pytest.mark.slow
def test_notebooks_execute_to_their_committed_outputs(all_reports, tmp_path, monkeypatch, cache_dir):
    monkeypatch.setenv("SYMFLOAT_CACHE", str(cache_dir))
    monkeypatch.chdir(ROOT)
    ids = [r.id for r in all_reports]
    write_notebooks(ids, tmp_path, force=True)
    for did in ids:
        assert _cells(ROOT / "notebooks" / f"{did}.ipynb") == _cells(tmp_path / f"{did}.ipynb"), \
            f"notebooks/{did}.ipynb is stale"


def test_notebooks_executed_side_by_side_are_the_committed_ones(graefe_reports, tmp_path, monkeypatch, cache_dir):
    # `make run` executes stale notebooks in parallel, one kernel per notebook: the outputs must not depend
    # on it (two small notebooks of Graefe, executed at once, against their committed cells and outputs)
    monkeypatch.setenv("SYMFLOAT_CACHE", str(cache_dir))
    monkeypatch.setenv("SYMFLOAT_WORKERS", "2")
    monkeypatch.chdir(ROOT)
    ids = ["graefe-s1-prismatoid-volume", "graefe-s4-ship-centroid"]
    written = write_notebooks(ids, tmp_path, force=True)
    assert sorted(p.name for p in written) == sorted(f"{did}.ipynb" for did in ids)
    for did in ids:
        assert _cells(ROOT / "notebooks" / f"{did}.ipynb") == _cells(tmp_path / f"{did}.ipynb")
