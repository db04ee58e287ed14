"""The stability atlas: grid input, boundaries, checks that fail when they should, Dask = serial."""
from __future__ import annotations

import math
from fractions import Fraction as F
from pathlib import Path
from types import SimpleNamespace

import pytest

pytest.importorskip("pyarrow")
pytest.importorskip("dask.distributed")

from symfloat.atlas.cell import boundaries  # noqa: E402
from symfloat.atlas.checks import run_checks  # noqa: E402
from symfloat.atlas.dataset import part_path, read_atlas  # noqa: E402
from symfloat.atlas.grid import density_grid, parse_grid  # noqa: E402
from symfloat.atlas.run import build  # noqa: E402
from symfloat.cli import main  # noqa: E402
from symfloat.registry import load  # noqa: E402


def test_grid_forms_are_exact():
    assert parse_grid("1:2:5", "--ba") == [F(1), F(5, 4), F(3, 2), F(7, 4), F(2)]
    assert parse_grid("0.5", "--ca") == [F(1, 2)]
    assert density_grid("1/20:19/20:10")[4] == F(9, 20)


@pytest.mark.parametrize("argv, words", [
    (["--ba", "1:2:x"], "count must be a whole number"),
    (["--ba", "2:1:3"], "start must be smaller"),
    (["--ba", "0:2:3"], "ratios must lie in"),
    (["--ba", "1,3,2"], "increasing order"),
    (["--ba", "1::3"], "end must be a number"),
    (["--density", "1/10:8/10:5"], "symmetric about 1/2"),
    (["--density", "0:1:5"], "strictly between 0 and 1"),
    (["--density", "1/2"], "at least 2 values"),
    (["--workers", "-1"], "--workers must be a whole number"),
    (["--ca", "1e4"], "ratios must lie in"),
    (["--ba", "1/1000", "--density", "1/100:99/100:3"], "outside the range the solver handles"),
])
def test_bad_grids_are_one_line_and_exit_2(argv, words, capsys, tmp_path):
    base = {"--ba": "1", "--ca": "2", "--density": "1/4:3/4:3", "--out": str(tmp_path / "a")}
    for k in range(0, len(argv), 2):
        base[argv[k]] = argv[k + 1]
    args = ["atlas", "box"] + [x for kv in base.items() for x in kv]
    assert main(args) == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1
    assert not (tmp_path / "a").exists()            # nothing computed, nothing written


def test_atlas_is_for_the_box(capsys, tmp_path):
    assert main(["atlas", "cylinder", "--ba", "1", "--ca", "2", "--density", "1/4:3/4:3",
                 "--out", str(tmp_path)]) == 2


def _t(density, bracket, label, change="stable above"):
    return SimpleNamespace(density=density, bracket=bracket, label=label, change=change, note="", source=[])


def test_thresholds_at_one_density_are_one_boundary():
    """A pitchfork's parent and child at the same density within their errors make one boundary;
    thresholds outside the swept range are left out."""
    ts = [_t(0.3, 1e-13, "face z up", "stable below"), _t(0.3 + 5e-14, 1e-13, "tilted in the x-z plane"),
          _t(0.31, 1e-13, "tilted in the x-z plane", "stable below"), _t(0.05, 1e-13, "face y up")]
    b = boundaries(ts, 0.1, 0.9)
    assert [len(x["changes"]) for x in b] == [2, 1]
    assert b[0]["error"] >= 1e-13 and abs(b[0]["density"] - 0.3) < 1e-13


def _row(ba, ca, k, s_from, s_to, positions, **extra):
    stable = [{"position": p, "up": up, "tilt_deg": 0.0, "family": "isolated", "g_above_b": 0.0,
               "min_eigenvalue": 1.0, "error_rad": 1e-15, "copies": 2, "waterplane": "", "evidence": ""}
              for p, up in positions]
    row = {"b_a": float(ba), "c_a": float(ca), "b_a_exact": str(ba), "c_a_exact": str(ca), "body": "box",
           "failure": None, "interval": k, "s_from": s_from, "s_from_error": 1e-13 if k else 0.0, "s_to": s_to,
           "s_to_error": 1e-13, "from_changes": [], "sample_density": (s_from + s_to) / 2, "stable": stable,
           "stable_classes": len(stable), "stable_positions": 2 * len(stable), "index_sum": 2, "sweep_points": 1,
           "sweep_agrees": True, "duality_holds": True, "thresholds_without_dual": [], "sources_not_found": [],
           "predictions": []}
    row.update(extra)
    return row


META = {"b_a": ["2"], "c_a": ["3"], "densities": ["1/10", "9/10"]}
FACE_X = ("face x up", [1.0, 0.0, 0.0])
FACE_Y = ("face y up", [0.0, 1.0, 0.0])


def _check(checks, name):
    return next(c for c in checks if c.name.startswith(name))


def test_duality_check_fails_on_an_asymmetric_cell():
    symmetric = [_row(2, 3, 0, 0.1, 0.3, [FACE_X, FACE_Y]), _row(2, 3, 1, 0.3, 0.7, [FACE_X]),
                 _row(2, 3, 2, 0.7, 0.9, [FACE_X, FACE_Y])]
    assert _check(run_checks(symmetric, META), "duality").ok
    lopsided = [_row(2, 3, 0, 0.1, 0.3, [FACE_X, FACE_Y]), _row(2, 3, 1, 0.3, 0.72, [FACE_X]),
                _row(2, 3, 2, 0.72, 0.9, [FACE_X, FACE_Y])]
    assert not _check(run_checks(lopsided, META), "duality").ok
    missing = symmetric[:2] + [_row(2, 3, 2, 0.7, 0.9, [FACE_X])]
    assert not _check(run_checks(missing, META), "duality").ok


def test_index_and_sweep_checks_fail():
    rows = [_row(2, 3, 0, 0.1, 0.9, [FACE_X], index_sum=0, sweep_agrees=False)]
    checks = run_checks(rows, META)
    assert not _check(checks, "Poincaré").ok and not _check(checks, "sweep").ok
    # a sample without a sum fails too: families count with their winding, so the sum always applies
    assert not _check(run_checks([_row(2, 3, 0, 0.1, 0.9, [FACE_X], index_sum=None)], META), "Poincaré").ok
    assert _check(run_checks([_row(2, 3, 0, 0.1, 0.9, [FACE_X])], META), "Poincaré").ok


def test_long_box_check_against_the_printed_tables():
    """Box 1 x 3/2 x 20 at s = 0.3: Scheeffer IX's tables (section 3/2 x 1, n = 9/4 > 6 s(1 - s)) give
    the position with the short edge b = a vertical (face x up) as the only stable one; the atlas
    agrees when it has exactly that, and the check fails when a stable face y up is added."""
    tables = load("scheeffer-ix")[1].predictors.tables_prediction
    assert [p["phi"] for p in tables(0.3, 1.5) if p["stability"] == "stable"] == [0.0]
    meta = {"b_a": ["3/2"], "c_a": ["20"], "densities": ["1/5", "4/5"]}
    good = [_row(F(3, 2), 20, 0, 0.2, 0.8, [FACE_X])]
    assert _check(run_checks(good, meta), "long box").ok
    bad = [_row(F(3, 2), 20, 0, 0.2, 0.8, [FACE_X, FACE_Y])]
    assert not _check(run_checks(bad, meta), "long box").ok
    short = [_row(F(3, 2), 2, 0, 0.2, 0.8, [FACE_X, FACE_Y])]          # not long: not applicable
    assert "not applicable" in _check(run_checks(short, {**meta, "c_a": ["2"]}), "long box").summary


def test_cube_check_compares_thresholds():
    meta = {"b_a": ["1"], "c_a": ["1"], "densities": ["1/10", "9/10"]}
    cube = [_row(1, 1, 0, 0.1, 1 / 6, [("face z up", [0.0, 0.0, 1.0])]),
            _row(1, 1, 1, 1 / 6, 5 / 6, [("corner up", [3 ** -0.5] * 3)],
                 from_changes=[{"position": "corner up", "change": "stable above", "note": "", "sources": []}])]
    reference = {"thresholds": [{"density": 1 / 6 + 1e-14, "error": 1e-13, "position": "corner up",
                                 "change": "stable above"},
                                {"density": 0.05, "error": 1e-13, "position": "x", "change": "stable below"}]}
    assert _check(run_checks(cube, meta, reference), "cube").ok          # 0.05 lies outside the range
    reference["thresholds"].append({"density": 0.5, "error": 1e-13, "position": "edge up (xz)",
                                    "change": "stable above"})
    assert not _check(run_checks(cube, meta, reference), "cube").ok


def test_printed_thresholds_not_found_are_explained_and_a_missed_change_fails():
    """An unfound printed threshold carries what the solver sees beside it: a position stable on
    neither side is a reported disagreement; a stable set that changes there without a located
    threshold is a failure of the machinery.  (Entries as `compute_cell` writes them; the values are
    Scheeffer IV (43a)'s 1/4 for the square section, which the box 1 x 1 x 2 leaves unfound.)"""
    unstable = ("scheeffer-iv-v (43a): tilted in the x-y plane stable below at 0.25 "
                "[stable on neither side: at s -+ 1e-06 the solver finds this position stable on neither side]")
    rows = [_row(2, 3, 0, 0.1, 0.9, [FACE_X], sources_not_found=[unstable])]
    checks = run_checks(rows, META)
    reported = next(c for c in checks if c.name == "printed thresholds")
    assert not reported.ok and not reported.fails_command and "1 where the solver finds the position stable on " \
        "neither side" in reported.summary
    assert next(c for c in checks if c.name == "printed thresholds located").ok
    missed = unstable.replace("[stable on neither side", "[change not located")
    checks = run_checks([_row(2, 3, 0, 0.1, 0.9, [FACE_X], sources_not_found=[missed])], META)
    located = next(c for c in checks if c.name == "printed thresholds located")
    assert not located.ok and located.fails_command


def test_why_a_printed_threshold_is_not_found():
    """`_why_not_found` reads the solver's view at s -+ width: no change (neither or both sides stable)
    or a change the bisection did not locate, and names the nearest change of the same position."""
    from symfloat.solver.phase import Threshold, _why_not_found
    k = {"value": 0.25, "label": "tilted in the x-y plane", "claim": "unstable beyond", "errata": []}
    near = [Threshold(0.2113248654052, 1e-13, "tilted in the x-y plane", "stable above")]
    neither = _why_not_found(k, (1e-6, False, False), near)
    assert neither["seen"] == "stable on neither side" and "0.2113248654052" in neither["why"]
    assert _why_not_found(k, (1e-6, True, True), [])["seen"] == "stable on both sides"
    # a printed threshold where the formulas only stop predicting the position (their region ends) is no
    # disagreement of the print with a position stable on both sides
    silent = _why_not_found({**k, "claim": "silent beyond"}, (1e-6, True, True), [])
    assert silent["seen"] == "stable on both sides, the print silent beyond" and "region" in silent["why"]
    assert _why_not_found({**k, "claim": "silent beyond"}, (1e-6, False, False), [])["seen"] == "stable on neither side"
    # a printed claim the project already refutes (an erratum on one of its formulas) says so
    booked = _why_not_found({**k, "errata": ["VI.D"]}, (1e-6, False, False), [])
    assert booked["seen"] == "stable on neither side, erratum declared" and "VI.D" in booked["why"]
    assert _why_not_found(k, (1e-6, True, False), near)["seen"] == "change not located"
    assert _why_not_found(k, None, near)["seen"] == "not looked at"
    # of two changes as near to 12 digits (the cube's ring ends 1/4 and 3/4 about a print's 1/2, each located
    # to its bracket), the lower is named, in whichever order the sweep found them: the message does not depend
    # on the sweep's steps
    ends = [Threshold(0.75, 1e-13, "ring", "stable above"), Threshold(0.2499999999999, 1e-13, "ring", "stable below")]
    half = {**k, "value": 0.5, "label": "ring"}
    for order in (ends, ends[::-1]):
        assert "found is at 0.2499999999999 (stable below)" in _why_not_found(half, (1e-6, False, False), order)["why"]


def _one_scene_cell(ba, ca, densities):
    """A cheap cell for the plumbing test: the stable classes at the middle density only."""
    from symfloat.atlas.cell import _stable_classes
    from symfloat.solver import make_scene, solve
    s = densities[len(densities) // 2]
    stable = _stable_classes(solve(make_scene("box", s, (1, ba, ca))))
    row = _row(ba, ca, 0, float(densities[0]), float(densities[-1]), [])
    row.update(stable=stable, stable_classes=len(stable), sample_density=float(s))
    return [row], {"seconds": 0.0, "thresholds": 0, "intervals": 1}


def test_dask_plumbing_equals_serial(tmp_path):
    """Four cells of one scene each on a local cluster of two workers: the same part files, byte for byte,
    as computed serially here, the combined file in grid order, and a second run computes nothing."""
    import cloudpickle
    import sys
    cloudpickle.register_pickle_by_value(sys.modules[__name__])       # the workers cannot import this file
    grid = ([F(3, 2), F(2)], [F(3), F(4)], density_grid("2/5:3/5:3"))
    on_dask = build(tmp_path / "dask", *grid, workers=2, cell=_one_scene_cell)
    serial = build(tmp_path / "serial", *grid, workers=0, cell=_one_scene_cell)
    assert on_dask.workers == 2 and len(on_dask.computed) == 4
    for ba, ca in serial.cells:
        assert part_path(tmp_path / "dask", ba, ca).read_bytes() == part_path(tmp_path / "serial", ba, ca).read_bytes()
    assert on_dask.path.read_bytes() == serial.path.read_bytes()
    rows, _ = read_atlas(on_dask.path)
    assert [(r["b_a_exact"], r["c_a_exact"]) for r in rows] == [("3/2", "3"), ("2", "3"), ("3/2", "4"), ("2", "4")]
    assert [c["position"] for c in rows[0]["stable"]] == ["face x up"]      # the thinnest edge vertical at s = 1/2
    part_path(tmp_path / "dask", F(2), F(4)).unlink()                      # a run killed before this cell
    again = build(tmp_path / "dask", *grid, workers=0, cell=_one_scene_cell)
    assert again.computed == [(F(2), F(4))] and again.path.read_bytes() == serial.path.read_bytes()


@pytest.mark.slow
def test_dask_equals_serial_cell_for_cell(tmp_path):
    """A 2 x 2 atlas on a local cluster of two workers: every part file is byte for byte the one
    computed serially in this process, and so is the combined dataset (the cell 1 x 1 x 3/2, whose look at
    the printed 1/12 - 1e-6 failed the solver's index check before the short arc there was one class, now
    computes: `symfloat atlas box --ba 1 --ca 3/2 --density 1/4:3/4:3` holds every check)."""
    grid = ([F(1), F(2)], [F(3, 2), F(3)], density_grid("1/4:3/4:3"))
    on_dask = build(tmp_path / "dask", *grid, workers=2)
    serial = build(tmp_path / "serial", *grid, workers=0)
    assert on_dask.workers == 2 and len(on_dask.computed) == 4
    for ba, ca in serial.cells:
        assert part_path(tmp_path / "dask", ba, ca).read_bytes() == part_path(tmp_path / "serial", ba, ca).read_bytes()
    assert on_dask.path.read_bytes() == serial.path.read_bytes()
    again = build(tmp_path / "dask", *grid, workers=2)                   # resumable: nothing left to do
    assert again.computed == [] and again.path.read_bytes() == serial.path.read_bytes()
    rows, meta = read_atlas(serial.path)
    assert list(dict.fromkeys((r["b_a_exact"], r["c_a_exact"]) for r in rows)) == \
        [("1", "3/2"), ("2", "3/2"), ("1", "3"), ("2", "3")]
    assert all(math.isclose(r["s_from"] + r["s_to"], 1.0) for r in rows if r["interval"] == 0 and
               len([x for x in rows if x["b_a_exact"] == r["b_a_exact"] and x["c_a_exact"] == r["c_a_exact"]]) == 1)


def test_slice_figure_is_deterministic():
    """The same rows draw the same PNG bytes (no date or software in its metadata)."""
    from symfloat.atlas.figure import slice_png
    meta = {"b_a": ["1", "2"], "c_a": ["20"], "densities": ["1/10", "9/10"]}
    rows = [_row(1, 20, 0, 0.1, 0.9, [FACE_X]), _row(2, 20, 0, 0.1, 0.4, [FACE_X, FACE_Y]),
            _row(2, 20, 1, 0.4, 0.9, [FACE_X])]
    reference = {"thresholds": [{"density": 1 / 6, "error": 1e-13, "position": "corner up", "change": "stable above"}]}
    first = slice_png(rows, meta, F(20), reference)
    assert first[:8] == b"\x89PNG\r\n\x1a\n" and first == slice_png(rows, meta, F(20), reference)
    assert b"Software" not in first and b"Creation" not in first


def test_the_tables_overlay_counts_a_density_and_its_dual_once(monkeypatch):
    """The printed tables read s below 1/2 as 1 - s: a grid symmetric about 1/2 asks them about half its rows,
    and every row is what the tables say at its own density."""
    from symfloat.atlas import checks, figure
    from symfloat.registry import provided
    (_, tables), = provided("tables")
    asked = []

    def counted(s, r):
        asked.append(s)
        return tables(s, r)
    monkeypatch.setattr(checks, "_ix_tables", lambda: counted)
    ratios = (1.25, 3.0)
    densities = tuple(F(1, 10) + F(8, 10) * F(k, 8) for k in range(9))       # 1/10 .. 9/10, symmetric
    counts = figure._ix_counts.__wrapped__(ratios, densities)
    assert len(asked) == 5 * len(ratios) and min(asked) >= F(1, 2)
    assert counts.tolist() == [[sum(p["stability"] == "stable" for p in tables(s, r)) for r in ratios]
                               for s in densities]


@pytest.mark.parametrize("lopsided, status", [(False, 0), (True, 1)])
def test_command_fails_when_a_check_fails(lopsided, status, tmp_path, capsys):
    """Cells already written are not computed again; the checks run on them, are written to checks.md
    and printed, and a failed one (here the duality of a lopsided cell) makes the exit status 1."""
    from symfloat.atlas.dataset import write_part
    densities = density_grid("1/10:9/10:3")
    end = 0.72 if lopsided else 0.7
    write_part(tmp_path, F(2), F(3), densities, [_row(2, 3, 0, 0.1, 0.3, [FACE_X, FACE_Y]),
                                                _row(2, 3, 1, 0.3, end, [FACE_X]),
                                                _row(2, 3, 2, end, 0.9, [FACE_X, FACE_Y])])
    assert main(["atlas", "box", "--ba", "2", "--ca", "3", "--density", "1/10:9/10:3", "--out", str(tmp_path),
                 "--workers", "0", "--quiet"]) == status
    out = capsys.readouterr().out
    assert ("| duality s ↔ 1 − s | yes | FAILS |" in out) == lopsided
    assert (tmp_path / "checks.md").read_text(encoding="utf-8") == out


def test_existing_scheduler_by_address(tmp_path):
    """--scheduler: the cells go to a running cluster (here one started for the test), whose workers
    report back; the parts are those of the serial build."""
    import cloudpickle
    import sys
    from dask.distributed import LocalCluster
    cloudpickle.register_pickle_by_value(sys.modules[__name__])
    grid = ([F(3, 2)], [F(3), F(4)], density_grid("2/5:3/5:3"))
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0") as cluster:
        remote = build(tmp_path / "remote", *grid, scheduler=cluster.scheduler_address, cell=_one_scene_cell)
    serial = build(tmp_path / "serial", *grid, workers=0, cell=_one_scene_cell)
    assert remote.workers == 2 and remote.path.read_bytes() == serial.path.read_bytes()


@pytest.mark.slow
def test_unreachable_scheduler_is_one_line(tmp_path, capsys):
    """(slow: the client waits for its connection timeout, 10 s)"""
    assert main(["atlas", "box", "--ba", "2", "--ca", "3", "--density", "1/4:3/4:3", "--out", str(tmp_path),
                 "--scheduler", "tcp://127.0.0.1:9", "--quiet"]) == 2
    err = capsys.readouterr().err
    assert "cannot reach the Dask scheduler" in err and err.count("\n") == 1


def test_renamed_box_check():
    """1 x 2 x 1 and 1 x 1 x 2 are one box: their boundaries must agree within the errors."""
    meta = {"b_a": ["1", "2"], "c_a": ["1", "2"], "densities": ["1/10", "9/10"]}
    one = [_row(2, 1, 0, 0.1, 0.3, [FACE_X]), _row(2, 1, 1, 0.3, 0.9, [FACE_X])]
    other = [_row(1, 2, 0, 0.1, 0.3, [FACE_X]), _row(1, 2, 1, 0.3, 0.9, [FACE_X])]
    assert _check(run_checks(one + other, meta), "same box").ok
    other[0]["s_to"] = other[1]["s_from"] = 0.3 + 1e-8
    assert not _check(run_checks(one + other, meta), "same box").ok


@pytest.mark.parametrize("changed", ["derivations/scheeffer_x/predictors.py", "symfloat/comparison/thresholds.py",
                                     "symfloat/solver/vertex.py", "symfloat/manifest.py"])
def test_the_code_stamp_changes_with_a_derivation_and_the_comparison(changed, monkeypatch):
    # a part is computed again only when its code stamp changes: the stamp digested symfloat/derivations/, which a
    # checkout does not have (the derivations are its top-level folder), and not symfloat/comparison/, so a changed
    # predictor or threshold comparison kept every part of the atlas "current"
    from pathlib import Path

    from symfloat.atlas import dataset
    target = (Path(__file__).resolve().parents[1] / changed).resolve()
    assert target.is_file()

    def stamp():
        dataset.solver_stamp.cache_clear()
        dataset.code_stamp.cache_clear()
        return dataset.code_stamp()
    before = stamp()
    text, raw = Path.read_text, Path.read_bytes
    monkeypatch.setattr(Path, "read_text",
                        lambda self, *a, **k: text(self, *a, **k) + "#" * (self.resolve() == target))
    monkeypatch.setattr(Path, "read_bytes", lambda self: raw(self) + b"#" * (self.resolve() == target))
    after = stamp()
    monkeypatch.undo()
    assert stamp() == before != after


def _same_atlas_rows(committed: list[dict], rebuilt: list[dict]) -> list[str]:
    """Where two atlases differ: cells, intervals, positions, counts, checks and predictions alike, an
    interval's ends within the sum of both error bounds, every other number to 1e-8 of itself or of 1 (float64
    searches whose last bits follow the processor; a tilt's error bound of 6e-16 or 0 is the same)."""
    def same(a, b) -> bool:
        if isinstance(a, float) and isinstance(b, float):
            return abs(a - b) <= 1e-8 * max(1.0, abs(a), abs(b))
        if isinstance(a, dict) and isinstance(b, dict):
            return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
        if isinstance(a, list) and isinstance(b, list):
            return len(a) == len(b) and all(map(same, a, b))
        return a == b

    differences = []
    if len(committed) != len(rebuilt):
        differences.append(f"{len(committed)} rows committed, {len(rebuilt)} rebuilt")
    for a, b in zip(committed, rebuilt):
        where = f"b/a = {a['b_a_exact']}, c/a = {a['c_a_exact']}, interval {a['interval']}"
        for end in ("s_from", "s_to"):
            if abs(a[end] - b[end]) > a[f"{end}_error"] + b[f"{end}_error"] + 1e-15:
                differences.append(f"{where}: {end} {a[end]!r} committed, {b[end]!r} rebuilt")
        rest = [k for k in a if k not in ("s_from", "s_to", "s_from_error", "s_to_error")]
        for key in rest:
            if not same(a[key], b[key]):
                differences.append(f"{where}: {key} differs")
    return differences


def test_rows_that_differ_are_named():
    row = _row(2, 20, 0, 0.1, 0.4, [FACE_X])
    moved = {**row, "s_to": row["s_to"] + 1e-6}
    assert _same_atlas_rows([row], [dict(row)]) == []
    assert _same_atlas_rows([row], [moved]) == ["b/a = 2, c/a = 20, interval 0: s_to 0.4 committed, 0.400001 rebuilt"]
    assert _same_atlas_rows([row], [row, row]) == ["1 rows committed, 2 rebuilt"]
    assert _same_atlas_rows([row], [{**row, "stable_classes": 3}]) == [
        "b/a = 2, c/a = 20, interval 0: stable_classes differs"]


@pytest.mark.slow      # every cell of the committed grid computed again: about five minutes in one process
def test_the_committed_atlas_is_what_the_present_code_computes(tmp_path):
    committed = Path(__file__).resolve().parents[1] / "docs" / "atlas" / "atlas.parquet"
    rows, meta = read_atlas(committed)
    build(tmp_path, [F(x) for x in meta["b_a"]], [F(x) for x in meta["c_a"]], [F(x) for x in meta["densities"]],
          workers=0)
    rebuilt, rebuilt_meta = read_atlas(tmp_path / "atlas.parquet")
    assert {k: v for k, v in rebuilt_meta.items() if k != "code"} == {k: v for k, v in meta.items() if k != "code"}
    assert _same_atlas_rows(rows, rebuilt) == []


@pytest.mark.slow      # the long box's tables read at 2,000 densities per cell: about 15 s
def test_the_committed_checks_are_what_the_present_code_writes_of_the_committed_atlas():
    # docs/atlas/checks.md is a function of the committed rows (symfloat atlas writes it after the cells): its words
    # follow the code that writes them without the cells computed again (their check is the slow test above)
    import json
    from symfloat.atlas.checks import checks_markdown
    from symfloat.atlas.run import CUBE_REFERENCE
    atlas = Path(__file__).resolve().parents[1] / "docs" / "atlas"
    rows, meta = read_atlas(atlas / "atlas.parquet")
    reference = json.loads((atlas / CUBE_REFERENCE).read_text(encoding="utf-8"))
    assert checks_markdown(run_checks(rows, meta, reference), meta) == (atlas / "checks.md").read_text(encoding="utf-8")
