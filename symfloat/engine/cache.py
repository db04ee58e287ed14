"""A cache of derivation reports keyed by content, verified when read.

The key hashes the derivation module's source, its proof certificates, the
source of the library itself (model, engine, geometry) and the keys of the
derivations it requires, so any change to what a result depends on re-checks it.

An entry is ``{"format", "derivation", "key", "sha256", "report"}`` in the file
``<derivation>.<key>.json``; ``sha256`` is the hash of the report's canonical JSON
(sorted keys, no spaces).  Reading checks the envelope, the id and key it was
stored under and the hash; an entry that fails any check (truncated, corrupted,
edited by hand, written by another format) is a miss: the derivation is checked
again and the entry replaced.  Entries are written to a temporary file and
renamed, so concurrent runs read either a whole old entry or a whole new one.
"""
from __future__ import annotations

import hashlib
import json
import os
import tempfile
from functools import cache
from pathlib import Path

from ..errors import EnvironmentProblem

__all__ = ["library_fingerprint", "derivation_key", "report_hash", "ReportCache", "CacheError", "FORMAT"]

_LIBRARY_PARTS = ("model", "engine", "geometry", "__init__.py")
FORMAT = 2


class CacheError(EnvironmentProblem):
    """The cache directory cannot be used (exit status 2)."""


@cache
def library_fingerprint() -> str:
    root = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    for part in _LIBRARY_PARTS:
        for f in sorted((root / part).rglob("*.py")) if (root / part).is_dir() else [root / part]:
            h.update(f.relative_to(root).as_posix().encode())
            h.update(f.read_bytes())
    return h.hexdigest()


def derivation_key(source: Path, required_keys, proofs: Path | None = None) -> str:
    """The cache key of the derivation whose module is *source*."""
    h = hashlib.sha256(library_fingerprint().encode())
    h.update(Path(source).read_bytes())
    if proofs is not None and proofs.exists():
        h.update(proofs.read_bytes())
    for k in required_keys:
        h.update(k.encode())
    return h.hexdigest()[:32]


def report_hash(report) -> str:
    """SHA-256 of the report's canonical JSON (sorted keys, compact separators).

    >>> report_hash({"b": 1, "a": [1.5, None]}) == report_hash({"a": [1.5, None], "b": 1})
    True
    """
    text = json.dumps(report, sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def _default_root() -> Path:
    from ..project import outputs_root
    env = os.environ.get("SYMFLOAT_CACHE")
    if env:
        return Path(env)
    return (outputs_root() or Path.cwd()) / ".symfloat-cache"


class ReportCache:
    """Reports stored as verified JSON entries under *root* (``$SYMFLOAT_CACHE``, else
    ``.symfloat-cache`` in the library of ``SYMFLOAT_LIBRARY`` or the project checkout, else in the
    working directory)."""

    def __init__(self, root: str | os.PathLike | None = None, enabled: bool = True):
        self.root = Path(root) if root else _default_root()
        self.enabled = enabled

    def _path(self, derivation_id, key):
        return self.root / f"{derivation_id}.{key}.json"

    def prepare(self) -> None:
        """Create the cache directory and make sure it can be written, before any work."""
        if not self.enabled:
            return
        if self.root.exists() and not self.root.is_dir():
            raise CacheError(f"cannot use the cache directory {self.root} (SYMFLOAT_CACHE): not a directory")
        try:
            self.root.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise CacheError(f"cannot use the cache directory {self.root} (SYMFLOAT_CACHE): "
                             f"{exc.strerror or exc}") from None
        if not self.root.is_dir() or not os.access(self.root, os.W_OK | os.X_OK):
            raise CacheError(f"cannot use the cache directory {self.root} (SYMFLOAT_CACHE): not a writable "
                             f"directory")

    def get(self, derivation_id, key):
        """The stored report, or ``None`` when there is none or it fails a check."""
        if not self.enabled:
            return None
        try:
            entry = json.loads(self._path(derivation_id, key).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None
        if not (isinstance(entry, dict) and entry.get("format") == FORMAT
                and entry.get("derivation") == derivation_id and entry.get("key") == key
                and isinstance(entry.get("report"), dict) and entry.get("sha256") == report_hash(entry["report"])):
            return None
        return entry["report"]

    def put(self, derivation_id, key, data):
        if not self.enabled:
            return
        entry = {"format": FORMAT, "derivation": derivation_id, "key": key, "sha256": report_hash(data),
                 "report": data}          # the report in insertion order, as a fresh check writes it
        tmp = None
        try:
            self.root.mkdir(parents=True, exist_ok=True)
            for old in self.root.glob(f"{derivation_id}.*.json"):
                old.unlink(missing_ok=True)
            fd, tmp = tempfile.mkstemp(dir=self.root, prefix=f".{derivation_id}.", suffix=".tmp")
            with os.fdopen(fd, "w", encoding="utf-8") as f:
                f.write(json.dumps(entry, ensure_ascii=False))
            os.replace(tmp, self._path(derivation_id, key))
            tmp = None
        except OSError as exc:
            raise CacheError(f"cannot write to the cache directory {self.root} (SYMFLOAT_CACHE): "
                             f"{exc.strerror or exc}") from None
        finally:
            if tmp is not None:
                Path(tmp).unlink(missing_ok=True)
