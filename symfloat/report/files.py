"""Atomic file writing that leaves unchanged content untouched.

A report is rewritten only when its content changed beyond timings, so that
regenerating unchanged derivations changes no file.
"""
from __future__ import annotations

import os
import re
import tempfile
from pathlib import Path

__all__ = ["write_if_changed", "without_timings"]

_TIMING = re.compile(r'("seconds": )[0-9.eE+-]+|\b[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)? (ms|s)\b')


def without_timings(text: str) -> str:
    """*text* with every timing (``"seconds": x`` in JSON, ``12.3 ms`` or
    ``1.2 s`` in prose and tables) replaced by a placeholder.

    >>> without_timings('{"seconds": 0.25, "x": 1} took 12.5 ms')
    '{"seconds": T, "x": 1} took T'
    """
    return _TIMING.sub(lambda m: (m.group(1) + "T") if m.group(1) else "T", text)


def write_if_changed(path: str | os.PathLike, text: str) -> bool:
    """Write *text* to *path* atomically unless the file already holds the same
    text up to timings; return whether the file was written."""
    path = Path(path)
    try:
        if without_timings(path.read_text(encoding="utf-8")) == without_timings(text):
            return False
    except OSError:
        pass
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.")
    with os.fdopen(fd, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)
    return True
