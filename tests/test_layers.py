"""The layers hold (issue 28, items 2 and 3): which package of the library may import which, what each part
of a derivation package may import, and no module-level name of a derivation bound twice.

The library, bottom up: ``errors``, ``manifest``, ``project``, ``files``, ``leftovers``, ``prose``, ``numbers``
(leaves); ``model``; ``geometry``; the ``solver`` (found without any formula of a source); the ``registry`` of derivations; the checking
``engine``; ``comparison`` (the solver's answers against the sources); ``numerics``; the writers
(``report``, ``site``, ``atlas``); the ``cli`` on top.  A derivation's statements import the formula model
and SymPy only (and the statements of the derivations they build on, directly or not); its witnesses the engine; its
outputs anything.
"""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

from symfloat import registry

LIBRARY = Path(__file__).resolve().parents[1] / "symfloat"
LEAVES = {"errors", "manifest", "project", "files", "leftovers", "prose", "numbers"}
ALLOWED = {
    "errors": set(), "manifest": set(), "leftovers": set(), "prose": set(), "numbers": set(), "project": {"errors"},
    "files": {"errors", "leftovers"},
    "model": {"errors", "manifest", "project"},
    "geometry": {"errors", "model"},
    "solver": {"errors", "geometry", "model"},
    "registry": {"errors", "manifest", "model", "derivations"},
    "engine": LEAVES | {"geometry", "model", "registry"},
    "comparison": LEAVES | {"model", "registry", "solver"},
    "numerics": LEAVES | {"engine", "geometry", "model", "registry", "solver"},
    "report": LEAVES | {"comparison", "engine", "geometry", "model", "numerics", "registry", "solver"},
    "site": LEAVES | {"model", "registry", "report"},
    "atlas": LEAVES | {"comparison", "registry", "report", "solver"},
    "__init__": {"model"},
    "__main__": {"cli"},
    "cli": None,                                        # the top: anything
    "session": None,                                    # the README's session, run through the command line
}
# what of the library each part of a derivation package may import (beside its own package); statements import
# nothing else but SymPy and a few modules of the standard library, the other parts any other package
PART_ALLOWED = {
    "statements": ("symfloat", "symfloat.model"),
    "witnesses": ("symfloat", "symfloat.model", "symfloat.engine", "symfloat.geometry"),
    "predictors": ("symfloat", "symfloat.model", "symfloat.engine.roots", "symfloat.geometry"),
    "outputs": None,
}
STATEMENTS_MAY_IMPORT = {"sympy", "mpmath", "fractions", "math", "__future__"}    # mpmath: SymPy's own numbers


def _imported(path: Path, module: str) -> set[str]:
    """The absolute names of the modules *path* (the module *module*) imports, relative imports resolved."""
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            stem = ".".join(package.split(".")[:len(package.split(".")) - node.level + 1]) if node.level else ""
            if node.module:
                found.add(f"{stem}.{node.module}" if stem else node.module)
            else:                                       # from . import name: the module stem.name
                found |= {f"{stem}.{a.name}" for a in node.names}
    return found


def _layer(name: str) -> str | None:
    parts = name.split(".")
    return (parts[1] if len(parts) > 1 else "__init__") if parts[0] == "symfloat" else None


def library_violations(root: Path = LIBRARY) -> list[str]:
    out = []
    for f in sorted(root.rglob("*.py")):
        rel = f.relative_to(root)
        if rel.parts[0] == "derivations":
            continue
        layer = rel.parts[0] if len(rel.parts) > 1 else rel.stem
        allowed = ALLOWED.get(layer, set())
        if allowed is None:
            continue
        module = ".".join(("symfloat",) + rel.with_suffix("").parts)
        for name in _imported(f, module):
            target = _layer(name)
            if name == "symfloat":
                target = "__init__"
            if target is not None and target != layer and target not in allowed:
                out.append(f"{rel}: imports {name} ({layer} may import {', '.join(sorted(allowed)) or 'nothing'})")
    return out


def _part_may_import(name: str, part: str, own: str, others: set) -> bool:
    if name.startswith(own + "."):
        return part != "statements"                     # statements import no other part of their package
    if name in others or any(name == a or (a != "symfloat" and name.startswith(a + ".")) for a in PART_ALLOWED[part]):
        return True
    if name.startswith("symfloat"):
        return False
    return part != "statements" or name.split(".")[0] in STATEMENTS_MAY_IMPORT


def part_violations(package: Path, requires=()) -> list[str]:
    """What the parts of the derivation package in *package* import beyond :data:`PART_ALLOWED`; the
    statements of the derivations it builds on (*requires*, its ancestors) are allowed to every part."""
    own = f"symfloat.derivations.{package.name}"
    others = {f"symfloat.derivations.{r.replace('-', '_')}.statements" for r in requires}
    return sorted(f"{package.name}/{part}.py: imports {name}"
                  for part, allowed in PART_ALLOWED.items() if allowed is not None and (package / f"{part}.py").is_file()
                  for name in _imported(package / f"{part}.py", f"{own}.{part}")
                  if not _part_may_import(name, part, own, others))


def rebound_names(path: Path) -> list[str]:
    """Module-level names *path* binds in more than one statement (assignment, def, class, import, loop)."""
    seen: dict[str, int] = {}
    out = []

    def bind(name, line):
        if name in seen:
            out.append(f"{path.name}:{line}: {name} bound again (first at line {seen[name]})")
        else:
            seen[name] = line

    def targets(t):
        if isinstance(t, ast.Name):
            yield t.id
        elif isinstance(t, (ast.Tuple, ast.List)):
            for e in t.elts:
                yield from targets(e)
        elif isinstance(t, ast.Starred):
            yield from targets(t.value)

    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        names = []
        if isinstance(node, ast.Assign):
            names = [n for t in node.targets for n in targets(t)]
        elif isinstance(node, (ast.AnnAssign, ast.AugAssign)):
            names = list(targets(node.target))
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names = [node.name]
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            names = [(a.asname or a.name).split(".")[0] for a in node.names if a.name != "*"]
        elif isinstance(node, ast.For):
            names = list(targets(node.target))
        for n in dict.fromkeys(names):
            bind(n, node.lineno)
    return out


PACKAGES = [registry.manifest(i) for i in registry.ids()]


def test_the_library_keeps_its_layers():
    assert library_violations() == []


def _ancestors(did: str) -> set[str]:
    out, todo = set(), list(registry.requires(did))
    while todo:
        a = todo.pop()
        if a not in out:
            out.add(a)
            todo += registry.requires(a)
    return out


@pytest.mark.parametrize("m", PACKAGES, ids=lambda m: m.id)
def test_each_part_of_a_derivation_imports_only_its_layer(m):
    assert part_violations(m.folder, _ancestors(m.id)) == []


@pytest.mark.parametrize("m", PACKAGES, ids=lambda m: m.id)
def test_no_module_level_name_of_a_derivation_is_bound_twice(m):
    assert [r for f in sorted(m.folder.glob("*.py")) for r in rebound_names(f)] == []


def test_the_checks_can_fail(tmp_path):
    # a solver module that reads the registry, a statement that imports the engine, a name bound twice
    lib = tmp_path / "symfloat"
    (lib / "solver").mkdir(parents=True)
    (lib / "solver" / "bad.py").write_text("from ..registry import load\nfrom .local import x\n")
    assert library_violations(lib) == ["solver/bad.py: imports symfloat.registry (solver may import errors, "
                                       "geometry, model)"]
    pkg = tmp_path / "some_text"
    pkg.mkdir()
    (pkg / "statements.py").write_text("import sympy as sp\nfrom symfloat.engine.witness import Case\n"
                                       "from ..other.statements import y\nfrom ..third.statements import z\n"
                                       "M3 = sp.Symbol('m_3')\nfor k in range(3):\n    pass\nM3 = 2\n")
    assert part_violations(pkg, requires=("other",)) == [
        "some_text/statements.py: imports symfloat.derivations.third.statements",
        "some_text/statements.py: imports symfloat.engine.witness"]
    assert rebound_names(pkg / "statements.py") == ["statements.py:8: M3 bound again (first at line 5)"]
