"""The library knows no derivation (issue 13, item 4): no module of ``symfloat`` outside
``derivations/`` names a derivation in its code or imports a derivation module; what the library
needs from a derivation it asks the registry for (``provides(kind, ...)``, ``predicts``)."""
from __future__ import annotations

import ast
from pathlib import Path

from symfloat.registry import ids as derivation_ids, provided

PACKAGE = Path(__file__).resolve().parents[1] / "symfloat"


def _docstrings(tree):
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                yield first.value


def naming(path: Path, ids) -> list[str]:
    """The derivation ids or module names *path* names in a string of its code (docstrings aside) or in
    an import."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    docs = {id(c) for c in _docstrings(tree)}
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docs:
            found += [i for i in ids if i in node.value]
        elif isinstance(node, ast.ImportFrom):
            names = [node.module or ""] + [a.name for a in node.names]
            found += [i for i in ids if any(i in n for n in names)]
    return found


def test_no_library_module_names_a_derivation():
    ids = set(derivation_ids()) | {i.replace("-", "_") for i in derivation_ids()}
    offenders = {str(p.relative_to(PACKAGE)): naming(p, ids) for p in PACKAGE.rglob("*.py")
                 if "derivations" not in p.relative_to(PACKAGE).parts}
    assert {k: v for k, v in offenders.items() if v} == {}


def test_the_check_sees_a_name_in_code_and_an_import(tmp_path):
    # the check itself can fail: a library module that loads a derivation by name is caught
    bad = tmp_path / "bad.py"
    bad.write_text('"""Docstrings may name scheeffer-ix."""\nfrom ..derivations._ix_figure import x\n'
                   'def f():\n    return load("scheeffer-ix")\n')
    assert sorted(naming(bad, {"scheeffer-ix", "_ix_figure"})) == ["_ix_figure", "scheeffer-ix"]


def test_the_figures_and_tables_come_from_the_derivations_that_provide_them():
    # Scheeffer IX provides its grid's picture and its case tables (derivations/scheeffer_ix/outputs.py, predictors.py)
    figures = {did: f.filename for did, f in provided("figure")}
    assert figures == {"scheeffer-ix": "scheeffer-ix-grid.png"}
    (did, tables), = provided("tables")
    # the first region of (132a) at s = 1/2, a/b = 2: n = 4 > 6 s (1 - s) = 3/2, the upright position is stable
    assert did == "scheeffer-ix" and tables(0.5, 2.0)[0]["stability"] == "stable"
