"""The derivation modules and their dependency graph.

Each module of the ``derivations`` package defines one ``DERIVATION``; its
module name is the derivation id with ``-`` written as ``_``.  A selector (a
source key or an id prefix) picks derivations by module name.  The dependency
graph is read from the modules' source (the literal ``requires=(...)`` of
their ``Derivation``), so selecting, ordering and finding a cached report
import no derivation module at all; :func:`load` imports one when it is
checked, and confirms that what it declares is what was read.
"""
from __future__ import annotations

import ast
import importlib
import pkgutil
import re
from functools import cache
from pathlib import Path

from . import derivations
from .errors import InputError
from .model.derivation import Derivation

__all__ = ["module_names", "module_path", "requires", "providing", "load", "select", "cross_use_problems",
           "SelectorError"]


class SelectorError(InputError):
    """A selector that matches no derivation (exit status 2)."""


@cache
def module_names() -> list[str]:
    """All derivation module names, sorted."""
    return sorted(m.name for m in pkgutil.iter_modules(derivations.__path__) if not m.name.startswith("_"))


def module_path(derivation_id: str) -> Path:
    """The source file of the derivation module *derivation_id*."""
    name = derivation_id.replace("-", "_")
    if name not in module_names():
        raise SelectorError(f"no derivation {derivation_id!r}")
    return next(Path(folder) / f"{name}.py" for folder in derivations.__path__ if (Path(folder) / f"{name}.py").is_file())


@cache
def requires(derivation_id: str) -> tuple[str, ...]:
    """The ids a derivation builds on, read from the literal ``requires=`` of its ``Derivation(...)``."""
    path = module_path(derivation_id)
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "Derivation":
            for kw in node.keywords:
                if kw.arg == "requires":
                    try:
                        return tuple(ast.literal_eval(kw.value))
                    except ValueError:
                        raise RuntimeError(f"{path.name}: requires=... must be a literal tuple of ids") from None
            return ()
    raise RuntimeError(f"{path.name}: no Derivation(...) found")


_PROVIDES = re.compile(r"""\.provides\(\s*["'](\w+)["']""")


@cache
def providing(kind: str) -> tuple[str, ...]:
    """Ids of the derivations that provide *kind* (``d.provides("kind", ...)``, read from their source)."""
    return tuple(m.replace("_", "-") for m in module_names()
                 if kind in _PROVIDES.findall(module_path(m).read_text(encoding="utf-8")))


def provided(kind: str) -> list[tuple[str, object]]:
    """``(derivation id, value)`` for every value the derivations provide as *kind*, in id order."""
    return [(did, value) for did in providing(kind) for value in load(did)[0].provided.get(kind, ())]


@cache
def load(derivation_id: str) -> tuple[Derivation, object]:
    """The derivation with *derivation_id* and the module that defines it."""
    name = derivation_id.replace("-", "_")
    if name not in module_names():
        raise SelectorError(f"no derivation {derivation_id!r}")
    module = importlib.import_module(f"{derivations.__name__}.{name}")
    d = module.DERIVATION
    if d.id != derivation_id:
        raise RuntimeError(f"module {name} defines {d.id!r}, expected {derivation_id!r}")
    if tuple(d.requires) != requires(derivation_id):
        raise RuntimeError(f"module {name}: requires {d.requires} differs from what its source declares")
    return d, module


def select(selector: str | None = None) -> list[str]:
    """Ids of the derivations a selector picks, ancestors first.

    ``None`` selects everything; a source key selects its derivations; any
    other string selects the ids that start with it.
    """
    ids = [m.replace("_", "-") for m in module_names()]
    if selector:
        picked = [i for i in ids if i.startswith(selector)]
        if not picked:
            raise SelectorError(f"selector {selector!r} matches no derivation; known: {', '.join(ids)}")
    else:
        picked = ids
    ordered: list[str] = []

    def visit(i, trail=()):
        if i in trail:
            raise RuntimeError(f"dependency cycle: {' -> '.join(trail + (i,))}")
        if i in ordered:
            return
        for r in requires(i):
            visit(r, trail + (i,))
        ordered.append(i)

    for i in picked:
        visit(i)
    return ordered


def cross_use_problems(d: Derivation) -> list[str]:
    """Every ``derivation-id:step`` in the ``uses`` of *d*'s steps that does not name a step of one of *d*'s
    ancestors (its ``requires``, transitively): a dangling or unchecked dependency, reported as a failure."""
    ancestors, todo = set(), list(d.requires)
    while todo:
        a = todo.pop()
        if a not in ancestors:
            ancestors.add(a)
            todo.extend(requires(a))
    problems = []
    for s in d.steps:
        for use in s.uses:
            if ":" not in use:
                continue
            other, step = use.split(":", 1)
            if other not in ancestors:
                problems.append(f"step {s.name!r} uses {use!r}, but {other!r} is not among the derivations "
                                f"{d.id} requires")
            elif step not in {t.name for t in load(other)[0].steps}:
                problems.append(f"step {s.name!r} uses {use!r}, which names no step of {other}")
    return problems
