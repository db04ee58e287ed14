"""Scheeffer IX's case tables against the solver, cell by cell on a grid of (s, a/b).

Scheeffer IX turns the rectangular parallelepiped about an edge: a 2-D
problem for the cross-section ``a x b`` (``a/b >= 1``).  For every cell of
the grid the equilibria the printed tables give (:func:`tables_prediction`
in ``derivations/scheeffer_ix/predictors.py``: region, tilt from the position with ``b``
vertical, stability) are compared with the equilibria the solver finds in
the same section, which knows nothing of the tables.  A cell agrees when both
lists match one to one (tilt within ``MATCH_RAD``, same stability).

The derivation hands the grid to the main job as a report (``provides("report", ...)``):
``docs/scheeffer-ix-grid.md`` and its data ``docs/scheeffer-ix-grid.json`` (every cell's counts, the
picture's data: :mod:`.figure`), rebuilt when their stamp changes.
"""
from __future__ import annotations

import ast
import json
import math
import time
from fractions import Fraction
from pathlib import Path

import sympy as sp

import symfloat
from symfloat.numbers import written
from symfloat.report.stamp import digest, stamp_line
from symfloat.solver import make_scene, solve

from . import predictors

__all__ = ["DENSITIES", "RATIOS", "grid_rows", "report_rows", "grid_markdown", "grid_data", "grid_stamp", "code_files"]

DENSITIES = [Fraction(k, 40) for k in range(1, 40)]
RATIOS = [Fraction(x) for x in ("1.02", "1.1", "1.25", "1.5", "1.75", "2", "2.5", "3", "4", "6")]
MATCH_RAD = 1e-6


def _solver_positions(s, ratio):
    polygon = f"0,0 {ratio},0 {ratio},1 0,1"
    sol = solve(make_scene("section", s, polygon=polygon))
    # tilt from the position with b (along y) vertical, folded by the rectangle's symmetry; one per class
    return [(math.atan2(abs(e.up[0]), abs(e.up[1])), e.stability) for e in sol.equilibria]


def _bound(margin, s):
    """The n = (a/b)^2 where the printed *margin* (a reading of :mod:`.predictors` in (a, b, s), linear in n)
    vanishes at the exact density *s*."""
    n = sp.Symbol("n", positive=True)
    (root,) = sp.solve(margin(sp.sqrt(n), 1, s), n)
    return Fraction(int(root.p), int(root.q))


def boundary_cells(densities=DENSITIES[::2], margin=Fraction(1, 1000)) -> list[tuple[Fraction, Fraction]]:
    """Cells just inside and just outside every boundary of the tables, at each density: the
    curves n = (a/b)^2 = 6 s(1-s) (132a), 1/(6 s(1-s)) (IX.C), 2(1-s)(4s-1) (132b), its inverse (165), and n_1(s)
    of (156) as printed, each where it lies above n = 1 (a/b = sqrt(n), rounded to 6 digits); the curves from the
    readings the tables decide with."""
    margins = (predictors.UPRIGHT_132A, predictors.UNSTABLE_3, lambda *x: predictors.OBLIQUE_132B(*x)[1],
               predictors.BOUND_165)
    cells = []
    for s in densities:
        sv = max(s, 1 - s)
        curves = [_bound(m, sv) for m in margins]
        if sv > Fraction(23, 32):
            curves.append(Fraction(float(predictors._n1_printed(float(sv)))).limit_denominator(10 ** 12))
        for n in curves:
            for side in (1 - margin, 1 + margin):
                if n * side > 1:
                    ratio = Fraction(round((float(n * side)) ** 0.5, 6)).limit_denominator(10 ** 6)
                    cells.append((s, ratio))
    return sorted(set(cells))


def grid_rows(densities=DENSITIES, ratios=RATIOS, progress=None, extra=()) -> list[dict]:
    """One row per cell of the grid (and per *extra* cell ``(s, a/b)``): the table's and the
    solver's equilibria and the differences."""
    cells = [(s, r) for r in ratios for s in densities] + list(extra)
    rows = []
    for i, (s, ratio) in enumerate(cells, 1):
        if progress and i % 50 == 0:
            progress(f"[{i}/{len(cells)}]")
        t0 = time.perf_counter()
        solver = _solver_positions(s, ratio)
        table = [(p["phi"], p["stability"], p["region"], p["printed"])
                 for p in predictors.tables_prediction(s, ratio)]
        missing, wrong, unpredicted = [], [], list(solver)
        for phi, stab, region, printed in table:
            near = [q for q in unpredicted if abs(q[0] - phi) <= MATCH_RAD]
            if not near:
                missing.append({"region": region, "tilt_deg": math.degrees(phi), "stability": stab,
                                "printed": list(printed)})
                continue
            unpredicted.remove(near[0])
            if near[0][1] != stab:
                wrong.append({"region": region, "tilt_deg": math.degrees(phi), "table": stab,
                              "solver": near[0][1], "printed": list(printed)})
        rows.append({"s": float(s), "s_exact": str(s), "ratio": float(ratio), "ratio_exact": str(ratio),
                     "boundary": (s, ratio) in extra, "table": len(table),
                     "solver": len(solver), "table_stable": sum(t[1] == "stable" for t in table),
                     "solver_stable": sum(q[1] == "stable" for q in solver), "missing": missing, "wrong_stability": wrong,
                     "unpredicted": [{"tilt_deg": math.degrees(q[0]), "stability": q[1]} for q in unpredicted],
                     "seconds": time.perf_counter() - t0})
    return rows


_REPORT_ROWS: dict = {}


def report_rows(progress=None) -> list[dict]:
    """The rows of the main job's grid (with :func:`boundary_cells`), solved once per process for both
    files of the report."""
    stamp = grid_stamp()
    if stamp not in _REPORT_ROWS:
        _REPORT_ROWS[stamp] = grid_rows(progress=progress, extra=boundary_cells())
    return _REPORT_ROWS[stamp]


_LIBRARY = Path(symfloat.__file__).resolve().parent


def _imported(path: Path, module: str) -> list[str]:
    """The modules *path* (the module *module*) imports, an import inside a function too, with each ``from`` name
    as a possible submodule; relative imports made absolute.  A library package that imports its names when first
    asked for (a module-level ``__getattr__``: the formula model) imports every module of its folder; the
    library's root does so too, for the model's names (reached by the statements' own imports) and the checker's
    ``check`` (which the grid never runs), so it is left at its own imports."""
    if path.suffix != ".py":            # the C source of a compiled module imports nothing of the library
        return []
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    tree = ast.parse(path.read_bytes())
    lazy = path.name == "__init__.py" and module.startswith("symfloat.") and any(
        isinstance(node, ast.FunctionDef) and node.name == "__getattr__" for node in tree.body)
    names = [f"{module}.{f.stem}" for f in sorted(path.parent.glob("*.py"))] if lazy else []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            stem = node.module or ""
            if node.level:
                base = package.split(".")[:len(package.split(".")) - node.level + 1]
                stem = ".".join(base + ([node.module] if node.module else []))
            names += [stem] + [f"{stem}.{a.name}" for a in node.names]
    return names


def _file(module: str) -> Path | None:
    """The file of *module* when it is one of a derivation package (``scheeffer_ix.x``, relative to the folder of
    the derivation packages) or of the library (``symfloat.x``)."""
    first, *rest = module.split(".")
    packages = Path(__file__).parent.parent
    if first != "symfloat" and (packages / first / "manifest.toml").is_file():
        base = packages.joinpath(first, *rest)
    elif first == "symfloat" and rest[:1] != ["derivations"]:
        base = _LIBRARY.joinpath(*rest)
    else:
        return None
    candidates = (base.with_suffix(".py"), base / "__init__.py", base.with_suffix(".c"))     # .c: a compiled module's
    return next((f for f in candidates if f.is_file()), None)


def code_files() -> list[Path]:
    """The files the grid is computed from, found from the imports rather than listed: this module, the modules of
    its package it imports (the statements and predictors whose tables it reads) and every library module any of
    them imports, followed to the end, with the packages they sit in (so that the polynomial roots and compiled
    readings IX's predictors use are in, as is whatever they come to use; :func:`_imported`)."""
    own = __package__.rpartition(".")[2]
    seen: dict[str, Path] = {}
    todo = [f"{own}.grid"]
    while todo:
        name = todo.pop()
        parts = name.split(".")
        for n in (".".join(parts[:i]) for i in range(1, len(parts) + 1)):
            f = _file(n)
            if n not in seen and f is not None:
                seen[n] = f
                todo += _imported(f, n)
    return sorted(set(seen.values()))


def grid_stamp() -> str:
    """The content stamp of the grid: the files it is computed from (:func:`code_files`; library modules by their
    path in the package, the package's own by name) and the grid (see :mod:`symfloat.report.stamp`)."""
    files = [f"{f.relative_to(_LIBRARY).as_posix()}\n{f.read_text(encoding='utf-8')}" if f.is_relative_to(_LIBRARY)
             else f for f in code_files()]
    return digest(*files, repr((DENSITIES, RATIOS, MATCH_RAD)))


def grid_data(rows, stamp: str) -> str:
    """``docs/scheeffer-ix-grid.json``: every cell (s, a/b exact and as floats, on the grid or beside a
    boundary), the table's and the solver's number of equilibria and of stable ones, and whether they
    agree; no times, so that the same grid gives the same bytes."""
    cells = [{"s": r["s_exact"], "ratio": r["ratio_exact"], "s_float": r["s"], "ratio_float": r["ratio"],
              "boundary": r["boundary"], "table": r["table"], "solver": r["solver"],
              "table_stable": r["table_stable"], "solver_stable": r["solver_stable"],
              "agree": not (r["missing"] or r["wrong_stability"] or r["unpredicted"])} for r in rows]
    return json.dumps({"stamp": stamp, "match_rad": MATCH_RAD, "cells": cells}, indent=1) + "\n"


def grid_markdown(rows, stamp: str | None = None) -> str:
    bad = [r for r in rows if r["missing"] or r["wrong_stability"] or r["unpredicted"]]
    boundary = [r for r in rows if r["boundary"]]
    rows_grid = [r for r in rows if not r["boundary"]]
    ratios = sorted({r["ratio"] for r in rows_grid})
    densities = sorted({r["s"] for r in rows_grid})
    lines = ["# Scheeffer IX: the printed case tables against the solver", "",
             "Generated by `symfloat run`. The box turned about an edge is the 2-D problem of its "
             "cross-section a × b (a/b ≥ 1). For each cell the equilibria of the printed tables (131)–(132b), "
             "(161), (162), (162a), (164a)–(166), as the derivation reads them, "
             "are matched with those the solver finds in the section (tilt from the position with b "
             f"vertical within {written(MATCH_RAD)} rad, same stability).", "",
             f"Grid: {len(densities)} densities s from {densities[0]:g} to {densities[-1]:g} in steps of "
             f"{densities[1] - densities[0]:g} × a/b ∈ "
             f"{{{', '.join(f'{x:g}' for x in ratios)}}} — {len(rows_grid)} cells; plus {len(boundary)} cells "
             "a relative 10⁻³ in n = (a/b)² inside and outside every boundary curve of the tables (n = 6s(1−s), "
             "1/(6s(1−s)), 2(1−s)(4s−1) and its inverse, n₁(s) of (156)) at every other density. "
             f"Of all {len(rows)} cells {len(rows) - len(bad)} agree, {len(bad)} disagree.", ""]
    lines.append("| a/b | " + " | ".join(f"{s:.3f}" for s in densities[::4]) + " |")
    lines.append("|---|" + "---|" * len(densities[::4]))
    for ratio in ratios:
        marks = []
        for s in densities[::4]:
            r = next(r for r in rows_grid if r["ratio"] == ratio and r["s"] == s)
            marks.append("✓" if not (r["missing"] or r["wrong_stability"] or r["unpredicted"]) else "✗")
        lines.append(f"| {ratio:g} | " + " | ".join(marks) + " |")
    lines += ["", "(every fourth density shown above; every cell is listed below when it disagrees)", "",
              "Every cell's counts are in `scheeffer-ix-grid.json`; drawn with the printed boundaries:", "",
              "![The case tables of IX against the solver](figures/scheeffer-ix-grid.png)", ""]
    if bad:
        lines += ["## Cells where table and solver disagree", "",
                  "| s | a/b | table | solver | what differs |", "|---|---|---|---|---|"]
        for r in bad:
            what = []
            what += [f"table's {m['stability']} region-{m['region']} position at {m['tilt_deg']:.4f}° "
                     f"({', '.join(m['printed'])}) is no equilibrium" for m in r["missing"]]
            what += [f"region {w['region']} at {w['tilt_deg']:.4f}°: table {w['table']}, solver {w['solver']} "
                     f"({', '.join(w['printed'])})" for w in r["wrong_stability"]]
            what += [f"solver's {u['stability']} position at {u['tilt_deg']:.4f}° is not in the tables"
                     for u in r["unpredicted"]]
            lines.append(f"| {r['s_exact']} | {r['ratio_exact']} | {r['table']} | {r['solver']} | {'; '.join(what)} |")
    if stamp:
        lines += ["", stamp_line(stamp)]
    return "\n".join(lines) + "\n"
