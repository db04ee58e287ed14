"""A cache of derivation reports keyed by content.

The key hashes the derivation module's source, its proof certificates, the
source of the library itself (model, engine, geometry) and the keys of the
derivations it requires, so any change to what a result depends on re-checks it.
"""
from __future__ import annotations

import hashlib
import json
import os
from functools import cache
from pathlib import Path

__all__ = ["library_fingerprint", "derivation_key", "ReportCache"]

_LIBRARY_PARTS = ("model", "engine", "geometry", "__init__.py")


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


class ReportCache:
    """Reports stored as JSON files under *root* (``.symfloat-cache`` by
    default, or ``$SYMFLOAT_CACHE``); written atomically."""

    def __init__(self, root: str | os.PathLike | None = None, enabled: bool = True):
        self.root = Path(root or os.environ.get("SYMFLOAT_CACHE", ".symfloat-cache"))
        self.enabled = enabled

    def _path(self, derivation_id, key):
        return self.root / f"{derivation_id}-{key}.json"

    def get(self, derivation_id, key):
        if not self.enabled:
            return None
        path = self._path(derivation_id, key)
        try:
            return json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None

    def put(self, derivation_id, key, data):
        if not self.enabled:
            return
        self.root.mkdir(parents=True, exist_ok=True)
        for old in self.root.glob(f"{derivation_id}-*.json"):
            old.unlink(missing_ok=True)
        path = self._path(derivation_id, key)
        tmp = path.with_suffix(".tmp")
        tmp.write_text(json.dumps(data), encoding="utf-8")  # insertion order, as a fresh check writes it
        tmp.replace(path)
