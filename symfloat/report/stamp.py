"""Content stamps: a generated file records the digest of what it was made from.

Executing the notebooks and solving the Scheeffer IX grid are the slow parts of
the main job, and both depend only on code and data that rarely change.  Each
such output carries a *stamp* — the digest of its inputs (source files, the
unexecuted notebook, the derivation's cache key) — and is regenerated only when
the stamp of its present inputs differs, like the derivation cache but kept in
the committed file itself, so that a fresh clone starts warm.
"""
from __future__ import annotations

import hashlib
import re
from importlib.machinery import EXTENSION_SUFFIXES
from pathlib import Path

__all__ = ["digest", "package_digest", "stamp_line", "stamp_of", "source_file"]

_STAMP = re.compile(r'<!-- content stamp: ([0-9a-f]{16,64}) -->|^ "stamp": "([0-9a-f]{16,64})"', re.M)


def digest(*parts) -> str:
    """SHA-256 (first 32 hex digits) of *parts*: strings, bytes, or files (their name and bytes:
    never where the checkout lies, so that every clone computes the same stamp)."""
    h = hashlib.sha256()
    for part in parts:
        if isinstance(part, Path):
            h.update(part.name.encode() + b"\0" + part.read_bytes())
        elif isinstance(part, bytes):
            h.update(part)
        else:
            h.update(str(part).encode())
        h.update(b"\0\0")
    return h.hexdigest()[:32]


def source_file(module_file: str) -> Path:
    """The file a module's code is read from, for a stamp: the module's own, or a compiled module's C source beside
    it (``_clipped.cpython-311-x86_64-linux-gnu.so`` is made from ``_clipped.c``).

    >>> source_file("/p/symfloat/geometry/_clipped.cpython-311-x86_64-linux-gnu.so").name
    '_clipped.c'
    """
    path = Path(module_file)
    compiled = path.name.endswith(tuple(EXTENSION_SUFFIXES))       # a module's name holds no dot: it ends at the first
    return path.with_name(path.name.partition(".")[0] + ".c") if compiled else path


def package_digest(*folders: str) -> str:
    """Digest of every ``.py`` file under the named folders of the ``symfloat`` package."""
    root = Path(__file__).resolve().parents[1]
    files = [f for name in folders for f in sorted((root / name).rglob("*.py"))]
    return digest(*(str(f.relative_to(root)) + "\n" + f.read_text(encoding="utf-8") for f in files))


def stamp_line(key: str) -> str:
    """The line a Markdown output ends with."""
    return f"<!-- content stamp: {key} -->"


def stamp_of(path: Path) -> str | None:
    """The stamp recorded in *path* (a Markdown file's stamp line, a JSON file's top-level ``"stamp"`` as
    ``json.dumps(..., indent=1)`` writes it), or ``None`` (no file, or no stamp)."""
    try:
        match = _STAMP.search(path.read_text(encoding="utf-8"))
    except OSError:
        return None
    return (match.group(1) or match.group(2)) if match else None
