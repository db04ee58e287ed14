"""Atomic file writing that leaves unchanged content untouched.

A report is rewritten only when its content changed beyond timings, so that
regenerating unchanged derivations changes no file.  A file is written to a
temporary file beside it and renamed over it: a run stopped at any moment leaves
either the old or the new file, never half of one (the temporary file a killed
write left is removed by the next write of that file); a write that fails (the
directory not writable, the disk full) removes the temporary file, keeps the
previous output and raises :class:`OutputError` with one line.  A new file gets
the ordinary permissions the umask gives (``0644`` under the usual ``022``); a
rewritten one keeps its own.
"""
from __future__ import annotations

import errno
import os
import re
import stat
import tempfile
from glob import escape as glob_escape
from pathlib import Path

from .errors import EnvironmentProblem
from .leftovers import sweep_stale

__all__ = ["write_if_changed", "write_atomic", "without_timings", "OutputError", "writable_target", "writable_folder"]

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


def _shown(path) -> str:
    """*path* for a one-line message: at most 120 characters, the middle elided."""
    text = str(path)
    return text if len(text) <= 120 else f"{text[:60]}...{text[-50:]}"


def _probe(folder: Path) -> None:
    """Create and remove a file in *folder*: the only test of writability that holds for root too
    (``os.access`` says yes to ``/proc`` and to a read-only mount)."""
    sweep_stale(folder, ".symfloat-probe-*")
    fd, name = tempfile.mkstemp(dir=folder, prefix=".symfloat-probe-")
    os.close(fd)
    os.unlink(name)


def writable_target(path: str | os.PathLike) -> Path:
    """*path* when a file can be written there (checked before any work), else :class:`OutputError`:
    its folder must exist (none is created), be a folder, and take a new file."""
    path = Path(path)
    if "\0" in str(path):
        raise OutputError(f"cannot write {str(path)[:60]!r}: a file name holds no NUL character")
    try:
        if path.is_dir():
            raise OutputError(f"cannot write {_shown(path)}: it is a directory")
        parent = path.parent
        if not parent.exists():
            raise OutputError(f"cannot write {_shown(path)}: the folder {_shown(parent)} does not exist "
                              f"(symfloat creates no folders for a file)")
        if not parent.is_dir():
            raise OutputError(f"cannot write {_shown(path)}: {_shown(parent)} is not a directory")
        _probe(parent)
    except OutputError:
        raise
    except OSError as exc:
        raise OutputError(f"cannot write {_shown(path)}: {_reason(exc)}") from None
    return path


def writable_folder(folder: str | os.PathLike) -> Path:
    """*folder* when files can be written into it, or it can be made there: an existing folder that
    takes a new file, or a new one in an existing folder that does (one level; no tree is created
    silently).  Else :class:`OutputError`, before any work."""
    folder = Path(folder)
    if "\0" in str(folder):
        raise OutputError(f"cannot write into {str(folder)[:60]!r}: a file name holds no NUL character")
    try:
        if folder.is_dir():
            _probe(folder)
        elif folder.exists():
            raise OutputError(f"cannot write into {_shown(folder)}: it is not a folder")
        elif not folder.parent.is_dir():
            raise OutputError(f"cannot write into {_shown(folder)}: the folder {_shown(folder.parent)} does not "
                              f"exist (symfloat creates one folder, not a tree)")
        else:
            if len(folder.name.encode()) > os.pathconf(folder.parent, "PC_NAME_MAX"):
                raise OSError(errno.ENAMETOOLONG, os.strerror(errno.ENAMETOOLONG))
            _probe(folder.parent)
    except OutputError:
        raise
    except OSError as exc:
        raise OutputError(f"cannot write into {_shown(folder)}: {_reason(exc)}") from None
    return folder


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
        sweep_stale(path.parent, f".{glob_escape(path.name)}.*")      # what a killed write of this file left
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
