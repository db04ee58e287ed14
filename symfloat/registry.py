"""The derivation modules and their dependency graph.

Each module of the ``derivations`` package defines one ``DERIVATION``; its
module name is the derivation id with ``-`` written as ``_``.  A selector (a
source key or an id prefix) picks derivations by module name, so only the
selected modules and their ancestors are imported.
"""
from __future__ import annotations

import importlib
import pkgutil
from functools import cache

import derivations

from .errors import InputError
from .model.derivation import Derivation

__all__ = ["module_names", "load", "select", "SelectorError"]


class SelectorError(InputError):
    """A selector that matches no derivation (exit status 2)."""


def module_names() -> list[str]:
    """All derivation module names, sorted."""
    return sorted(m.name for m in pkgutil.iter_modules(derivations.__path__) if not m.name.startswith("_"))


@cache
def load(derivation_id: str) -> tuple[Derivation, object]:
    """The derivation with *derivation_id* and the module that defines it."""
    name = derivation_id.replace("-", "_")
    if name not in module_names():
        raise SelectorError(f"no derivation {derivation_id!r}")
    module = importlib.import_module(f"derivations.{name}")
    d = module.DERIVATION
    if d.id != derivation_id:
        raise RuntimeError(f"module {name} defines {d.id!r}, expected {derivation_id!r}")
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
        for r in load(i)[0].requires:
            visit(r, trail + (i,))
        ordered.append(i)

    for i in picked:
        visit(i)
    return ordered
