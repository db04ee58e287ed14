"""Scheeffer IX's printed case tables against the solver (docs/scheeffer-ix-grid.md): cells on both
sides of every table boundary agree, and a table with one stability flipped is caught."""
from fractions import Fraction
from pathlib import Path

import pytest

from symfloat.registry import load
from symfloat.derivations.scheeffer_ix import grid as ix_grid

IX = load("scheeffer-ix")[1].predictors


def _cells(densities, ratios):
    return ix_grid.grid_rows([Fraction(s) for s in densities], [Fraction(r) for r in ratios])


def _disagreeing(rows):
    return [r for r in rows if r["missing"] or r["wrong_stability"] or r["unpredicted"]]


def test_cells_across_the_table_boundaries_agree():
    # upright a-face down: 6 s(1-s) = (a/b)^2 crosses between s = 0.2 and 0.25 for a/b = 1.02 and 1.1;
    # the second region's threshold s = 23/32 (140) lies between 0.7 and 0.75
    rows = _cells(["0.2", "0.25", "0.5", "0.7", "0.75", "0.9"], ["1.02", "1.1", "2"])
    assert _disagreeing(rows) == []
    assert {r["solver"] for r in rows} != {2}         # the grid reaches tilted positions, not only upright ones


def test_a_flipped_stability_in_the_tables_is_reported(monkeypatch):
    real = IX.tables_prediction

    def flipped(s, ratio):
        out = real(s, ratio)
        out[0] = dict(out[0], stability="unstable" if out[0]["stability"] == "stable" else "stable")
        return out

    monkeypatch.setattr(IX, "tables_prediction", flipped)
    rows = _cells(["0.5"], ["2"])
    assert rows[0]["wrong_stability"] and rows[0]["wrong_stability"][0]["region"] == 1


def test_the_committed_grid_report_is_complete():
    text = (Path(__file__).resolve().parents[1] / "docs" / "scheeffer-ix-grid.md").read_text(encoding="utf-8")
    cells = len(ix_grid.DENSITIES) * len(ix_grid.RATIOS)
    assert f"— {cells} cells;" in text


def test_the_committed_grid_is_stamped_with_the_present_solver_and_tables():
    # `symfloat run` skips the grid when the stamp matches; a stale stamp means a stale grid
    from symfloat.report.stamp import stamp_of
    path = Path(__file__).resolve().parents[1] / "docs" / "scheeffer-ix-grid.md"
    assert stamp_of(path) == ix_grid.grid_stamp(), "docs/scheeffer-ix-grid.md is stale: run `make run` and commit"


def test_a_stamp_does_not_depend_on_where_the_checkout_lies(tmp_path):
    # a fresh clone elsewhere must find the committed stamps current: files enter by name and content
    from symfloat.report.stamp import digest
    a, b = tmp_path / "one" / "f.py", tmp_path / "two" / "f.py"
    for f in (a, b):
        f.parent.mkdir()
        f.write_text("x = 1\n")
    assert digest(a) == digest(b)
    b.write_text("x = 2\n")
    assert digest(a) != digest(b)


_GRID_IMPORTS = """
import sys
from fractions import Fraction
from symfloat.derivations.scheeffer_ix import grid
grid.grid_rows([Fraction(1, 2), Fraction(4, 5)], [Fraction(2)], extra=grid.boundary_cells([Fraction(4, 5)]))
from symfloat.report.stamp import source_file      # a compiled module by its C source
print("\\n".join(sorted({str(source_file(m.__file__)) for name, m in list(sys.modules.items())
                        if name.startswith("symfloat") and getattr(m, "__file__", None)})))
"""


def test_the_grid_stamp_changes_with_every_module_the_grid_is_made_from(monkeypatch):
    # the stamp once listed the solver, geometry and model packages and left out what IX's predictors import
    # (engine/roots.py, which compiling runs): editing it kept a stale grid stamped current. Each module a grid
    # computation loads (run in a fresh process), and the two its predictors compile with, is changed by a
    # comment, as read, and the stamp must change. The files the stamp is made from are found once: a comment
    # changes no import, so it cannot change them; a module they miss is still missed, its stamp unchanged
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-c", _GRID_IMPORTS], capture_output=True, text=True, check=True)
    root = Path(__file__).resolve().parents[1]
    loaded = {f for f in (Path(x).resolve() for x in done.stdout.split()) if f.is_relative_to(root)}
    loaded |= {root / "symfloat" / "engine" / "roots.py", root / "symfloat" / "model" / "compiled.py"}
    exempt = {"derivations/__init__.py"}            # the derivations' docstring and folder mapping
    before = ix_grid.grid_stamp()
    files = ix_grid.code_files()
    monkeypatch.setattr(ix_grid, "code_files", lambda: files)
    text, raw = Path.read_text, Path.read_bytes
    missed = []
    for f in sorted(loaded):
        if str(f.relative_to(root)) in exempt:
            continue
        with pytest.MonkeyPatch.context() as edited:      # undone alone: the files found once stay patched in
            edited.setattr(Path, "read_text",
                           lambda self, *a, f=f, **k: text(self, *a, **k) + "#" * (self.resolve() == f))
            edited.setattr(Path, "read_bytes", lambda self, f=f: raw(self) + b"#" * (self.resolve() == f))
            if ix_grid.grid_stamp() == before:
                missed.append(str(f.relative_to(root)))
    assert len(loaded) > 30 and missed == [], missed
