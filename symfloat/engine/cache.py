"""A cache of derivation reports keyed by content, verified when read.

The key (:mod:`symfloat.engine.key`) hashes everything a derivation's report depends on: its package,
the transcription it quotes, the library modules its check executes and the keys of the derivations it
requires, so any change to what a result depends on re-checks it.

An entry is ``{"format", "derivation", "key", "sha256", "report"}`` in the file
``<derivation>.<key>.json``; ``sha256`` is the hash of the report's canonical JSON
(sorted keys, no spaces).  Reading checks the envelope, the id and key it was
stored under and the hash; an entry that fails any check (truncated, corrupted,
edited by hand, written by another format) is a miss: the derivation is checked
again and the entry replaced.  Entries are written to a temporary file and
renamed, so concurrent runs read either a whole old entry or a whole new one; an entry gets the
mode the umask gives (``0644`` under ``022``), and the temporary file of a write that a killed run
left is removed by the next run that prepares the cache.  What the cache returns is checked
once more by the runner: the report must stand up to the checker's own rules
(:func:`symfloat.engine.check.rejudged`).
"""
from __future__ import annotations

import hashlib
import json
import os
import tempfile
from pathlib import Path

from ..errors import EnvironmentProblem
from ..leftovers import sweep_stale

__all__ = ["report_hash", "ReportCache", "CacheError", "FORMAT"]

FORMAT = 4          # 4: reports carry what their verdicts are judged again from (see check.rejudged), keys
                    # cover whole derivation packages (engine/key.py)


class CacheError(EnvironmentProblem):
    """The cache directory cannot be used (exit status 2)."""


def report_hash(report) -> str:
    """SHA-256 of the report's canonical JSON (sorted keys, compact separators).

    >>> report_hash({"b": 1, "a": [1.5, None]}) == report_hash({"a": [1.5, None], "b": 1})
    True
    """
    text = json.dumps(report, sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


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

    def path(self, derivation_id, key) -> Path:
        """The file of the entry of *derivation_id* under *key*."""
        return self.root / f"{derivation_id}.{key}.json"

    def prepare(self) -> None:
        """Create the cache directory and make sure it can be written, before any work; remove the
        temporary files of writes a killed run left (:func:`~symfloat.leftovers.sweep_stale`)."""
        if not self.enabled:
            return
        shown = str(self.root) if len(str(self.root)) <= 120 else f"{str(self.root)[:60]}...{str(self.root)[-50:]}"
        try:
            if self.root.exists() and not self.root.is_dir():
                raise CacheError(f"cannot use the cache directory {shown} (SYMFLOAT_CACHE): not a directory")
            self.root.mkdir(parents=True, exist_ok=True)
            fd, probe = tempfile.mkstemp(dir=self.root, prefix=".probe.", suffix=".tmp")
            os.close(fd)
            os.unlink(probe)
        except OSError as exc:
            if isinstance(exc, CacheError):
                raise
            raise CacheError(f"cannot use the cache directory {shown} (SYMFLOAT_CACHE): "
                             f"{exc.strerror or exc}") from None
        sweep_stale(self.root, ".*.tmp")

    def get(self, derivation_id, key):
        """The stored report, or ``None`` when there is none or it fails a check."""
        return self.read(derivation_id, key)[0]

    def read(self, derivation_id, key) -> tuple[dict | None, str]:
        """``(report, "")``, or ``(None, why)``: ``why`` is empty when there is no entry, else the check
        the entry fails (its envelope, the derivation and key it was stored under, its content hash)."""
        if not self.enabled:
            return None, ""
        try:
            entry = json.loads(self.path(derivation_id, key).read_text(encoding="utf-8"))
        except FileNotFoundError:
            return None, ""
        except (OSError, ValueError) as exc:
            return None, f"not readable JSON ({getattr(exc, 'strerror', None) or type(exc).__name__})"
        if not (isinstance(entry, dict) and entry.get("format") == FORMAT):
            return None, f"not an entry of format {FORMAT}"
        if entry.get("derivation") != derivation_id or entry.get("key") != key:
            return None, "stored under another derivation or key than its name says"
        if not isinstance(entry.get("report"), dict) or entry.get("sha256") != report_hash(entry["report"]):
            return None, "its content hash does not match the report"
        return entry["report"], ""

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
            os.chmod(tmp, 0o666 & ~_umask())          # the umask's mode, not mkstemp's 0600
            os.replace(tmp, self.path(derivation_id, key))
            tmp = None
        except OSError as exc:
            raise CacheError(f"cannot write to the cache directory {self.root} (SYMFLOAT_CACHE): "
                             f"{exc.strerror or exc}") from None
        finally:
            if tmp is not None:
                Path(tmp).unlink(missing_ok=True)
