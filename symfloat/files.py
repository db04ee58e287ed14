"""Atomic file writing that leaves unchanged content untouched.

A report is rewritten only when its content changed beyond timings, so that
regenerating unchanged derivations changes no file.  A file is written to a
temporary file beside it and renamed over it: a run stopped at any moment leaves
either the old or the new file, never half of one; a write that fails (the
directory not writable, the disk full) removes the temporary file, keeps the
previous output and raises :class:`OutputError` with one line.  A new file gets
the ordinary permissions the umask gives (``0644`` under the usual ``022``); a
rewritten one keeps its own.
"""
from __future__ import annotations

import os
import re
import stat
import tempfile
from pathlib import Path

from .errors import EnvironmentProblem

__all__ = ["write_if_changed", "write_atomic", "without_timings", "OutputError", "writable_target"]

_TIMING = re.compile(r'("seconds": )[0-9.eE+-]+|\b[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)? (ms|s)\b')


class OutputError(EnvironmentProblem):
    """An output that cannot be written (exit status 2); the previous file is intact."""


def without_timings(text: str) -> str:
    """*text* with every timing (``"seconds": x`` in JSON, ``12.3 ms`` or
    ``1.2 s`` in prose and tables) replaced by a placeholder.

    >>> without_timings('{"seconds": 0.25, "x": 1} took 12.5 ms')
    '{"seconds": T, "x": 1} took T'
    """
    return _TIMING.sub(lambda m: (m.group(1) + "T") if m.group(1) else "T", text)


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _reason(exc: OSError) -> str:
    return exc.strerror or str(exc)


def writable_target(path: str | os.PathLike) -> Path:
    """*path* when a file can be written there (checked before any work), else :class:`OutputError`."""
    path = Path(path)
    if "\0" in str(path):
        raise OutputError(f"cannot write {str(path)!r}: a file name holds no NUL character")
    if path.is_dir():
        raise OutputError(f"cannot write {path}: it is a directory")
    parent = path.parent
    while not parent.exists() and parent != parent.parent:
        parent = parent.parent
    if not parent.is_dir():
        raise OutputError(f"cannot write {path}: {parent} is not a directory")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise OutputError(f"cannot write {path}: {parent} is not writable")
    return path


def write_atomic(path: str | os.PathLike, data: bytes) -> None:
    """Write *data* to *path* through a temporary file and a rename (see the module docstring)."""
    path = Path(path)
    try:
        mode = stat.S_IMODE(path.stat().st_mode)
    except OSError:
        mode = 0o666 & ~_umask()
    tmp = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.")
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(tmp, mode)
        os.replace(tmp, path)
        tmp = None
    except OSError as exc:
        raise OutputError(f"cannot write {path}: {_reason(exc)}; the previous file is unchanged") from None
    finally:
        if tmp is not None:
            Path(tmp).unlink(missing_ok=True)


def write_if_changed(path: str | os.PathLike, text: str) -> bool:
    """Write *text* to *path* atomically unless the file already holds the same
    text up to timings; return whether the file was written."""
    path = Path(path)
    try:
        if without_timings(path.read_text(encoding="utf-8")) == without_timings(text):
            return False
    except (OSError, UnicodeDecodeError):
        pass
    write_atomic(path, text.encode("utf-8"))
    return True
