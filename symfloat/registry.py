"""The derivation packages and their dependency graph.

Each derivation is a package of ``symfloat.derivations`` (the checkout's top-level ``derivations/``
folder, mapped into the installed package, and the ``derivations/`` folders of the libraries named by
``SYMFLOAT_LIBRARY``), split by concern (:data:`symfloat.manifest.PARTS`): ``statements`` (what the
source says and how it is derived: symbols, steps, quotes, errata; defines ``DERIVATION``),
``witnesses`` (declared first-principles witnesses), ``predictors`` (the printed formulas read at a
scene's numbers) and ``outputs`` (reports and figures).  Its ``manifest.toml`` holds the literals the
library needs before importing anything (:mod:`symfloat.manifest`): selecting, ordering, keying the
cache and finding who predicts a body or provides a kind import no derivation.  :func:`statements`
imports what a derivation says; :func:`load` the whole package, for checking it.
"""
from __future__ import annotations

import importlib
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from .errors import InputError
from .manifest import PARTS, Manifest, body_kinds, read_manifest

__all__ = ["ids", "ids_in", "manifest", "files", "requires", "providing", "predicting", "provided", "predictor",
           "reader", "statements", "load", "part", "select", "matching", "cross_use_problems", "compiled_readings", "SelectorError",
           "Reader"]


class SelectorError(InputError):
    """A selector that matches no derivation (exit status 2)."""


def _folders() -> list[Path]:
    from . import derivations
    return [Path(p) for p in derivations.__path__]


@cache
def _manifests() -> dict[str, Manifest]:
    found: dict[str, Manifest] = {}
    for folder in _folders():
        for sub in sorted(folder.iterdir()) if folder.is_dir() else ():
            if not (sub / "manifest.toml").is_file():
                continue
            m = read_manifest(sub)
            if m.id in found:
                raise RuntimeError(f"two derivations {m.id!r}: {found[m.id].folder} and {m.folder}")
            found[m.id] = m
    return dict(sorted(found.items()))


def ids() -> list[str]:
    """All derivation ids, sorted."""
    return list(_manifests())


def ids_in(folder: Path) -> list[str]:
    """The ids of the derivations whose package lies in *folder* (a library of ``SYMFLOAT_LIBRARY``), sorted."""
    return [did for did, m in _manifests().items() if folder.resolve() in m.folder.resolve().parents]


def manifest(derivation_id: str) -> Manifest:
    """The manifest of *derivation_id*."""
    try:
        return _manifests()[derivation_id]
    except KeyError:
        raise SelectorError(f"no derivation {derivation_id!r}") from None


def files(derivation_id: str) -> list[Path]:
    """The files of a derivation's package (its modules, manifest and proof certificates), sorted; not its
    compiled readings (``compiled.json``), which are generated from its statements and predictors and written
    after the checks (a check's key would otherwise change when they are written)."""
    folder = manifest(derivation_id).folder
    return sorted(p for p in folder.rglob("*") if p.is_file() and "__pycache__" not in p.parts
                  and p.name != "compiled.json")


def requires(derivation_id: str) -> tuple[str, ...]:
    """The ids a derivation builds on (its manifest's ``requires``)."""
    return manifest(derivation_id).requires


def providing(kind: str) -> tuple[str, ...]:
    """Ids of the derivations whose manifest says they provide *kind*."""
    return tuple(did for did, m in _manifests().items() if kind in m.provides)


def predicting(body: str, dims=()) -> list[str]:
    """Ids of the derivations whose manifest says they predict equilibria of *body* with edges *dims*
    (of one of its kinds, :func:`~symfloat.manifest.body_kinds`)."""
    kinds = set(body_kinds(body, dims))
    return [did for did, m in _manifests().items() if kinds & set(m.predicts)]


@cache
def part(derivation_id: str, name: str):
    """The module *name* (one of :data:`~symfloat.manifest.PARTS`) of a derivation's package, imported
    (its declarations join the derivation), or ``None`` when the package has none."""
    if name not in PARTS:
        raise ValueError(f"unknown part {name!r}; parts: {', '.join(PARTS)}")
    m = manifest(derivation_id)
    if not m.has(name):
        return None
    from . import derivations
    module = importlib.import_module(f"{derivations.__name__}.{m.package}.{name}")
    if name == "predictors" and hasattr(module, "READINGS"):
        _register(derivation_id, module)
    return module


def _register(derivation_id: str, module) -> None:
    """Join a predictors module of compiled readings (``BODIES``, ``predict``, ``PROVIDES``; it imports no
    statements) to its derivation, as a predictor that registers itself would."""
    d = statements(derivation_id)
    d.predicts(module.BODIES, module.predict)
    for kind, value in getattr(module, "PROVIDES", {}).items():
        d.provides(kind, value)


@dataclass(frozen=True)
class Reader:
    """What a scene reads of a derivation: the bodies it predicts, its ``predict(scene)`` and its printed
    formulas' metadata (``{name, locator, erratum, lost, corrected}`` in its order)."""
    id: str
    bodies: tuple
    predict: object
    printed: tuple


def _predictors(derivation_id: str):
    """The predictors module of a derivation, imported alone (nothing registered with its statements)."""
    from . import derivations
    return importlib.import_module(f"{derivations.__name__}.{manifest(derivation_id).package}.predictors")


@cache
def reader(derivation_id: str) -> Reader:
    """A derivation as a scene reads it: a predictors module of compiled readings alone (no statements module,
    no SymPy where its compiled readings are current, :mod:`symfloat.model.compiled`), else its predictor."""
    m = manifest(derivation_id)
    module = _predictors(derivation_id)
    if hasattr(module, "READINGS"):
        if set(module.BODIES) != set(m.predicts):
            raise RuntimeError(f"{m.folder}: the predictors predict {module.BODIES}, the manifest says {m.predicts}")
        return Reader(derivation_id, tuple(module.BODIES), module.predict, tuple(module.READINGS.printed))
    d = predictor(derivation_id)
    printed = tuple({"name": p.name, "locator": p.locator, "erratum": p.erratum is not None, "lost": bool(p.lost),
                     "corrected": p.erratum.corrected if p.erratum is not None else None} for p in d.printed)
    return Reader(derivation_id, tuple(d.predictor.bodies), d.predictor.predict, printed)


@cache
def statements(derivation_id: str):
    """The derivation *derivation_id*, importing its statements module and no other part: cheap, and all
    a reader of the quotes needs (held to the manifest's id, source and requires)."""
    d = part(derivation_id, "statements").DERIVATION
    m = manifest(derivation_id)
    if d.id != derivation_id or d.source != m.source:
        raise RuntimeError(f"{m.folder}: the statements define {d.id!r} of {d.source!r}, the manifest "
                           f"{derivation_id!r} of {m.source!r}")
    if tuple(d.requires) != m.requires:
        raise RuntimeError(f"{m.folder}: requires {d.requires} differs from the manifest's {m.requires}")
    return d


@cache
def load(derivation_id: str):
    """The derivation with every part of its package imported (witnesses declared, predictor and
    provided values registered), and the package: what a check, a bench or a test needs.  The
    declarations are held to the manifest (bodies predicted, kinds provided)."""
    d = statements(derivation_id)
    for name in PARTS[1:]:
        part(derivation_id, name)
    m = manifest(derivation_id)
    bodies = tuple(d.predictor.bodies) if d.predictor else ()
    if set(bodies) != set(m.predicts) or set(d.provided) != set(m.provides):
        raise RuntimeError(f"{m.folder}: the package predicts {bodies} and provides {sorted(d.provided)}, the "
                           f"manifest says {m.predicts} and {sorted(m.provides)}")
    from . import derivations
    return d, importlib.import_module(f"{derivations.__name__}.{m.package}")


def predictor(derivation_id: str):
    """The derivation with its predictor registered: its statements and predictors imported and nothing
    else (no witness is declared), as a scene reads it."""
    part(derivation_id, "predictors")
    d = statements(derivation_id)
    if d.predictor is None or set(d.predictor.bodies) != set(manifest(derivation_id).predicts):
        raise RuntimeError(f"{manifest(derivation_id).folder}: the predictors do not predict the bodies the "
                           f"manifest lists ({manifest(derivation_id).predicts})")
    return d


def compiled_readings(write: bool = False, among=None) -> list[str]:
    """Ids of the derivations (those of *among*, if given) whose predictors' shipped compiled readings
    (``compiled.json`` in the package, :mod:`symfloat.model.compiled`) are not current; with *write*, written
    afresh from the statements (then the ids of those written)."""
    from .model.compiled import judged_current, write_shipped
    out = []
    for did, m in _manifests().items():
        if not m.has("predictors") or (among is not None and did not in among):
            continue
        readings = getattr(_predictors(did), "READINGS", None)
        if readings is not None and not judged_current(readings):
            if write:
                write_shipped(readings)
            out.append(did)
    return out


def provided(kind: str) -> list[tuple[str, object]]:
    """``(derivation id, value)`` for every value the derivations provide as *kind*, in id order; imports
    only the module each manifest names for it (a predictors module of compiled readings alone, as a scene reads
    it: no statements module)."""
    out = []
    for did in providing(kind):
        name = manifest(did).provides[kind]
        module = _predictors(did) if name == "predictors" else None
        if hasattr(module, "READINGS"):
            out.append((did, module.PROVIDES[kind]))
            continue
        part(did, name)
        out += [(did, value) for value in statements(did).provided.get(kind, ())]
    return out


def matching(selector: str | None = None) -> list[str]:
    """Ids of the derivations a selector names itself (``None``: every one), without their ancestors."""
    known = ids()
    if not selector:
        return known
    picked = [i for i in known if i.startswith(selector)]
    if not picked:
        raise SelectorError(f"selector {selector!r} matches no derivation; known: {', '.join(known)}")
    return picked


def select(selector: str | None = None) -> list[str]:
    """Ids of the derivations a selector picks, ancestors first.

    ``None`` selects everything; a source key selects its derivations; any
    other string selects the ids that start with it.
    """
    picked = matching(selector)
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


def cross_use_problems(d) -> list[str]:
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
            elif step not in {t.name for t in statements(other).steps}:
                problems.append(f"step {s.name!r} uses {use!r}, which names no step of {other}")
    return problems
