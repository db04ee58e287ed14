"""The manifest of a derivation package: what the library may know of it without importing it.

Every derivation is a package (``derivations/<name>/``) with a ``manifest.toml`` of literals::

    id = "scheeffer-ix"                       # the derivation id; the package is named for it (- as _)
    source = "scheeffer"                      # the source key it quotes
    requires = ["scheeffer-iv-v"]             # the derivations whose results it builds on
    predicts = ["box", "cube"]                # the bodies whose scenes its predictors read (predictors.py)

    [provides]                                # a kind the library asks for = the module that provides it
    report = "outputs"
    tables = "predictors"

A body in ``predicts`` is a kind of scene (:data:`KINDS`): ``cube`` is a cube or a box with three equal
edges, ``square-box`` a box with two equal edges (the cube included), ``box`` any box.  A scene is of every
kind :func:`body_kinds` lists for it, so a derivation that speaks only about the cube is not read for a box
that is no cube.

Selecting, ordering, keying the cache and finding the derivations that speak about a body read the
manifests alone; :func:`symfloat.registry.load` imports a package and confirms that what its modules
declare is what the manifest says.
"""
from __future__ import annotations

import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["KINDS", "Manifest", "ManifestError", "PARTS", "PROVIDED_KINDS", "body_kinds", "read_manifest"]

PROVIDED_KINDS = ("thresholds", "forms", "report", "figure", "tables")   # see Derivation.provides
PARTS = ("statements", "witnesses", "predictors", "outputs")    # the modules of a package, by concern
KINDS = ("cube", "square-box", "box", "prism", "cylinder", "section")     # the bodies a predictor speaks about
_ID = re.compile(r"^[a-z0-9]+(-[a-z0-9]+)*$")
_KEYS = {"id", "source", "requires", "predicts", "provides"}


class ManifestError(ValueError):
    """A manifest that is not as this module describes (names the file and what is wrong)."""


@dataclass(frozen=True)
class Manifest:
    """The literals of ``manifest.toml`` and the package folder they describe."""

    id: str
    source: str
    folder: Path
    requires: tuple[str, ...] = ()
    predicts: tuple[str, ...] = ()
    provides: dict = field(default_factory=dict)

    @property
    def package(self) -> str:
        """The package's name (the id with ``-`` as ``_``)."""
        return self.id.replace("-", "_")

    def has(self, part: str) -> bool:
        """Whether the package has the module *part* (one of :data:`PARTS`)."""
        return (self.folder / f"{part}.py").is_file()


def body_kinds(body: str, dims=()) -> tuple[str, ...]:
    """The kinds of :data:`KINDS` a scene of *body* with edges *dims* is: a box is also a ``square-box``
    when two of its edges are equal and a ``cube`` when all three are, and a cube is all three kinds (a cube
    scene reads what the box 1,1,1 reads); any other body is its own kind (a prism's dimensions are no box's
    edges, so a square prism reads the predictors of prisms alone)."""
    if body == "cube":
        return ("box", "square-box", "cube")
    if body != "box":
        return (body,)
    equal = len(dims) - len(set(dims))
    return ("box",) + (("square-box",) if equal >= 1 else ()) + (("cube",) if equal == 2 else ())


def read_manifest(folder: Path) -> Manifest:
    """The manifest of the derivation package in *folder*, checked field by field."""
    path = folder / "manifest.toml"
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise ManifestError(f"{path}: unreadable manifest ({exc})") from None

    def fail(why):
        raise ManifestError(f"{path}: {why}")

    unknown = set(data) - _KEYS
    if unknown:
        fail(f"unknown fields {sorted(unknown)}; known: {sorted(_KEYS)}")
    did, source = data.get("id"), data.get("source")
    if not isinstance(did, str) or not _ID.match(did):
        fail("id must be lower-case words joined by '-'")
    if did.replace("-", "_") != folder.name:
        fail(f"the package of {did!r} must be named {did.replace('-', '_')!r}")
    if not isinstance(source, str) or not source:
        fail("source must name a source key")
    requires, predicts = data.get("requires", []), data.get("predicts", [])
    if not (isinstance(requires, list) and all(isinstance(r, str) and _ID.match(r) for r in requires)):
        fail("requires must be a list of derivation ids")
    if not (isinstance(predicts, list) and all(b in KINDS for b in predicts)):
        fail(f"predicts must be a list of bodies among {', '.join(KINDS)}")
    provides = data.get("provides", {})
    if not isinstance(provides, dict):
        fail("provides must be a table kind = module")
    for kind, part in provides.items():
        if kind not in PROVIDED_KINDS:
            fail(f"unknown kind {kind!r} in provides; known: {', '.join(PROVIDED_KINDS)}")
        if part not in PARTS or not (folder / f"{part}.py").is_file():
            fail(f"provides.{kind} must name a module of the package among {', '.join(PARTS)}")
    manifest = Manifest(did, source, folder, tuple(requires), tuple(predicts), dict(provides))
    if predicts and not manifest.has("predictors"):
        fail("predicts bodies but the package has no predictors.py")
    if not manifest.has("statements"):
        fail("the package has no statements.py")
    return manifest
