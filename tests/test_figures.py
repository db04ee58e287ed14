"""The main job's pictures (docs/figures/phase-*.png, scheeffer-ix-grid.png): current, deterministic, and
drawing what their data say.

Expected values: the committed data (docs/figures/phase-*.json, docs/scheeffer-ix-grid.json), the solver
run again on a few cells, the printed tables' own predictor (``tables_prediction``) and Scheeffer's (79)
roots of 6 s(1 - s) = 1 computed here with SymPy.
"""
from __future__ import annotations

import copy
import json
import math
import shutil
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

pytest.importorskip("matplotlib")

from matplotlib.collections import QuadMesh  # noqa: E402

from symfloat.derivations.scheeffer_ix import figure as ix_figure  # noqa: E402
from symfloat.errors import CheckFailed  # noqa: E402
from symfloat.registry import load  # noqa: E402
from symfloat.report import figures  # noqa: E402
from symfloat.report.figures import Figure  # noqa: E402
from symfloat.report.phase_figure import phase_figure, phase_intervals  # noqa: E402
from symfloat.report.phase_data import PHASES, phase_figures, phase_stamp  # noqa: E402

DOCS = Path(__file__).resolve().parents[1] / "docs"
IX = load("scheeffer-ix")[1].predictors


def _figure(name):
    return next(f for f in figures.main_job_figures() if f.filename == name)


def _json(name):
    return json.loads((DOCS / name).read_text(encoding="utf-8"))


def test_every_picture_is_committed_with_the_fingerprint_of_its_present_data_and_code():
    names = sorted(f.filename for f in figures.main_job_figures())
    assert names == ["phase-cube.png", "phase-square-log.png", "scheeffer-ix-grid.png"]
    for f in figures.main_job_figures():
        assert figures.recorded_fingerprint(DOCS / "figures" / f.filename) == figures.fingerprint(f, DOCS), \
            f"docs/figures/{f.filename} is stale: run `make run` and commit"


def test_the_phase_data_are_stamped_with_the_present_solver_and_sources():
    # `symfloat run` computes a diagram again only when its stamp changes: a stale stamp is a stale diagram
    for name in PHASES:
        assert _json(f"figures/phase-{name}.json")["stamp"] == phase_stamp(name), f"phase-{name}.json is stale"


def test_drawing_a_picture_again_from_unchanged_data_gives_the_same_bytes(tmp_path):
    fig = _figure("phase-cube.png")
    committed = (DOCS / "figures" / fig.filename).read_bytes()
    again = figures.png_bytes(figures.draw(fig, DOCS), figures.fingerprint(fig, DOCS))
    assert again == committed
    # and the main job, given the same data, redraws nothing; changed data are drawn again
    docs = tmp_path / "docs"
    (docs / "figures").mkdir(parents=True)
    for name in ("phase-cube.json", "phase-cube.png"):
        shutil.copy(DOCS / "figures" / name, docs / "figures" / name)
    assert figures.write_figures(docs, figures=[fig]) == []
    data = json.loads((docs / "figures" / "phase-cube.json").read_text())
    data["source_thresholds_not_found"].append({"value": 0.5, "derivation": "x", "locators": [], "label": "x",
                                                "change": "stable above"})
    (docs / "figures" / "phase-cube.json").write_text(json.dumps(data))
    assert figures.write_figures(docs, figures=[fig]) == [fig.filename]
    assert (docs / "figures" / fig.filename).read_bytes() != committed


# ---------------------------------------------------------------- the phase diagrams

def _vertical_lines(fig):
    ax = fig.axes[0]
    return sorted(line.get_xdata()[0] for line in ax.lines if line.get_xdata()[0] == line.get_xdata()[1])


def test_the_phase_picture_draws_the_thresholds_of_its_record():
    record = _json("figures/phase-cube.json")
    fig = phase_figure(record)
    expected = sorted({t["density"] for t in record["thresholds"] if t["source"]}
                      | {t["density"] for t in record["thresholds"] if not t["source"]}
                      | {k["value"] for k in record["source_thresholds_not_found"]})
    assert _vertical_lines(fig) == expected
    # the upright cube stops being stable at Scheeffer's root of 6 s (1 - s) = 1 (79): (3 - sqrt 3)/6
    root = float(sp.Rational(1, 2) - sp.sqrt(3) / 6)
    face = [t for t in record["thresholds"] if t["position"] == "face z up" and t["change"] == "stable below"]
    assert face and abs(face[0]["density"] - root) <= face[0]["error"] + 1e-15


def test_the_phase_bars_are_the_thresholds_and_agree_with_the_sweep():
    record = _json("figures/phase-cube.json")
    spans = phase_intervals(record)          # fails when a sweep density is not what the bars say
    fig = phase_figure(record)
    drawn = [[(float(p.vertices[:, 0].min()), float(p.vertices[:, 0].max())) for p in c.get_paths()]
             for c in fig.axes[0].collections]
    labels = [label for label in spans if spans[label]]
    assert [t.get_text() for t in fig.axes[0].get_yticklabels()] == labels
    assert drawn == [[(pytest.approx(a), pytest.approx(b)) for a, b in spans[label]] for label in labels]
    # the upright cube: stable up to Scheeffer's root of 6 s (1 - s) = 1 (79), and again from its dual
    root = float(sp.Rational(1, 2) - sp.sqrt(3) / 6)
    (a, b), (c, d) = spans["face z up"]
    assert abs(b - root) < 1e-12 and abs(c - (1 - root)) < 1e-12
    assert (a, d) == (record["sweep"][0]["density"], record["sweep"][-1]["density"])
    broken = copy.deepcopy(record)          # a threshold lost: the bars no longer give the sweep
    broken["thresholds"] = [t for t in broken["thresholds"] if abs(t["density"] - root) > 1e-9]
    with pytest.raises(CheckFailed, match="the thresholds"):
        phase_intervals(broken)


# ---------------------------------------------------------------- Scheeffer IX's case tables

def _mesh(fig) -> np.ndarray:
    return next(c for c in fig.axes[0].collections if isinstance(c, QuadMesh)).get_array()


def test_the_ix_picture_colours_each_cell_by_the_solvers_count():
    grid = _json("scheeffer-ix-grid.json")
    cells = [c for c in grid["cells"] if not c["boundary"]]
    assert len(cells) == 390
    counts = np.asarray(_mesh(ix_figure.grid_figure(grid))).reshape(39, 10)
    densities = sorted({Fraction(c["s"]) for c in cells})
    ratios = sorted({Fraction(c["ratio"]) for c in cells})
    for c in cells:
        assert counts[densities.index(Fraction(c["s"])), ratios.index(Fraction(c["ratio"]))] == c["solver_stable"]
    # the solver again, on cells with two stable classes and with one (the grid's data could be stale)
    from symfloat.solver import make_scene, solve
    for s, ratio in (("1/40", "2"), ("1/10", "2"), ("9/10", "1.1"), ("29/40", "1.1")):
        sol = solve(make_scene("section", s, polygon=f"0,0 {ratio},0 {ratio},1 0,1"))
        i, j = densities.index(Fraction(s)), ratios.index(Fraction(ratio))
        assert counts[i, j] == sum(e.stability == "stable" for e in sol.equilibria)
    assert {int(v) for v in counts.flat} == {1, 2}
    changed = copy.deepcopy(grid)
    cell = next(c for c in changed["cells"] if not c["boundary"])
    cell["solver_stable"] += 1
    assert not np.array_equal(np.asarray(_mesh(ix_figure.grid_figure(changed))).reshape(39, 10), counts)


@pytest.mark.parametrize("label", [b[0] for b in ix_figure.BOUNDARIES] + [ix_figure.N1[0]])
def test_each_drawn_boundary_is_where_the_printed_tables_change(label):
    # the boundary is evaluated from the derivation's reading of the print; the predictor that reads the
    # tables (tables_prediction, its own expressions) must change its answer there and only there
    densities = [0.05 + 0.9 * k / 60 for k in range(61)]
    values = ix_figure.boundaries(densities)[label]
    checked = 0
    for s, n in zip(densities, values):
        if not (n > 1.0001 and math.isfinite(n)) or abs(s - 0.5) < 1e-9:
            continue
        below, above = (IX.tables_prediction(s, math.sqrt(n * f)) for f in (1 - 1e-7, 1 + 1e-7))
        assert [(p["region"], p["stability"]) for p in below] != [(p["region"], p["stability"]) for p in above], \
            (label, s, n)
        checked += 1
    assert checked >= 5, label


def test_a_figure_whose_data_are_missing_is_not_drawn(tmp_path):
    fig = Figure("x.png", ("nothing.json",), lambda data: None)
    assert figures.write_figures(tmp_path, figures=[fig]) == [] and not (tmp_path / "figures").exists()
    assert [f.filename for f in phase_figures()] == ["phase-cube.png", "phase-square-log.png"]


_IMPORTS = """
import sys
from fractions import Fraction
from symfloat.comparison.thresholds import _closed_forms, phase_with_sources
from symfloat.registry import predicting, predictor
from symfloat.report.phase import phase_record
from symfloat.report.phase_data import PHASES
from symfloat.solver import make_scene, solve
for body, dims in PHASES.values():
    edges = tuple(Fraction(x) for x in dims.split(",")) if dims else ()
    scene = make_scene(body, Fraction(3, 10), dims)
    for did in predicting(body, edges):
        predictor(did).predictor.predict(scene)
_closed_forms()
from symfloat.report.stamp import source_file      # a compiled module by its C source
print("\\n".join(sorted({str(source_file(m.__file__)) for name, m in list(sys.modules.items())
                        if name.startswith("symfloat") and getattr(m, "__file__", None)})))
"""


def test_the_phase_stamp_changes_with_every_module_a_phase_record_is_made_from(monkeypatch):
    # the sweep, the sources' thresholds and predictions compared with it, and the manifests that choose the
    # derivations: the stamp once left out symfloat/comparison/ (the thresholds and disagreements the record
    # lists), manifest.py and registry.py (which derivations a body reads) and engine/roots.py (Scheeffer IX's,
    # VII's and X's predictors), so a change there kept a stale diagram stamped current. Each module the record's
    # computation loads (run in a fresh process) is changed by a comment, as read, and some stamp must change
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-c", _IMPORTS], capture_output=True, text=True, check=True)
    root = DOCS.parent
    loaded = sorted(f for f in (Path(x).resolve() for x in done.stdout.split()) if f.is_relative_to(root))
    # what makes no record: the report package's docstring, the stamp's own digest, the derivations' docstring
    exempt = {"symfloat/report/__init__.py", "symfloat/report/stamp.py", "derivations/__init__.py"}
    before = {name: phase_stamp(name) for name in PHASES}
    text, raw = Path.read_text, Path.read_bytes
    missed = []
    for f in loaded:
        if str(f.relative_to(root)) in exempt:
            continue
        monkeypatch.setattr(Path, "read_text",
                            lambda self, *a, f=f, **k: text(self, *a, **k) + "#" * (self.resolve() == f))
        monkeypatch.setattr(Path, "read_bytes", lambda self, f=f: raw(self) + b"#" * (self.resolve() == f))
        if all(phase_stamp(name) == before[name] for name in PHASES):
            missed.append(str(f.relative_to(root)))
        monkeypatch.undo()
    assert len(loaded) > 40 and missed == [], missed
