"""What a derivation's check depends on, hashed into its cache key.

The key of a derivation covers every file its report can depend on, found rather than listed:

* its whole package (modules, manifest, proof certificates);
* the source it quotes: the transcription and its metadata file;
* every module of the library its check executes: the ``symfloat`` modules its package imports and
  the checker (:mod:`symfloat.engine.check`) imports, followed import by import to the end (an
  import inside a function counts as well), with the packages they sit in;
* the keys of the derivations it requires (their results are its premises).

So editing a line of a transcription re-checks the derivations that quote it (and those built on
them), and editing a module a witness runs (say the cylinder's slices in the solver) re-checks the
derivations whose witnesses run it, and no other.
"""
from __future__ import annotations

import ast
import hashlib
from functools import cache
from pathlib import Path

__all__ = ["derivation_key", "library_files", "source_files"]

_LIBRARY = Path(__file__).resolve().parents[1]      # the symfloat package
_CHECKER = ("symfloat.engine.check",)


def _module_file(name: str) -> Path | None:
    """The file of library module *name* (``symfloat.a.b``), or ``None`` when it is not one."""
    parts = name.split(".")
    if parts[0] != "symfloat" or parts[1:2] == ["derivations"]:
        return None
    base = _LIBRARY.joinpath(*parts[1:])
    for f in (base.with_suffix(".py"), base / "__init__.py", base.with_suffix(".c")):     # .c: a compiled module's source
        if f.is_file():
            return f
    return None


@cache
def _imports(path: Path, module: str) -> frozenset[str]:
    """The names *path* (the module *module*) imports, and each ``from`` name as a possible submodule (none for the C
    source of a compiled module)."""
    if path.suffix != ".py":
        return frozenset()
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_bytes())):
        if isinstance(node, ast.Import):
            found |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[:len(package.split(".")) - node.level + 1]
                stem = ".".join(base + ([node.module] if node.module else []))
            else:
                stem = node.module or ""
            found.add(stem)
            found |= {f"{stem}.{a.name}" for a in node.names}
    return frozenset(found)


def _with_parents(name: str) -> list[str]:
    parts = name.split(".")
    return [".".join(parts[:i]) for i in range(1, len(parts) + 1)]


def library_files(package_files, package_name: str = "") -> list[Path]:
    """The library modules a check of the derivation whose modules are *package_files* executes."""
    todo = list(_CHECKER)
    for f in package_files:
        if f.suffix == ".py":
            todo += _imports(f, f"{package_name}.{f.stem}" if package_name else f.stem)
    seen: dict[str, Path] = {}
    while todo:
        name = todo.pop()
        for n in _with_parents(name):
            if n in seen:
                continue
            f = _module_file(n)
            if f is not None:
                seen[n] = f
                todo += _imports(f, n)
    return sorted(set(seen.values()))


def source_files(source_key: str) -> list[Path]:
    """The transcription of *source_key* and its metadata file, wherever the source was found."""
    from ..model.source import _folders, get_source
    src = get_source(source_key)
    names = (src.filename, f"{source_key}.source.json")
    return [Path(str(folder.joinpath(n))) for n in names for folder in _folders() if folder.joinpath(n).is_file()][:2]


def _content(path: Path) -> bytes:
    return path.read_bytes()


def derivation_key(package_files, source_key: str, required_keys, package_name: str = "") -> str:
    """The cache key of a derivation: its package, its source, the library its check runs, its premises."""
    h = hashlib.sha256(b"symfloat-key")
    groups = (("package", sorted(package_files)), ("source", source_files(source_key)),
              ("library", library_files(package_files, package_name)))
    for label, paths in groups:
        for f in paths:
            h.update(f"{label}:{f.name if label != 'library' else f.relative_to(_LIBRARY).as_posix()}".encode())
            h.update(_content(f))
    for k in required_keys:
        h.update(k.encode())
    return h.hexdigest()[:32]
