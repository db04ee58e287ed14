"""What a killed run leaves behind, swept by the next one.

A run stopped by ``SIGKILL`` (the kernel's out-of-memory killer, a closed terminal) cannot remove
its temporary files: a cache entry or a report half-written under its temporary name, the
connection file of a notebook kernel.  Each kind is named so that its owner can be recognised, and
the next run that writes the same kind of file removes those whose owner is gone: a temporary file
older than :data:`STALE_SECONDS` (no write takes that long, so a concurrent run's file is never
touched), a kernel connection file or a site's build folder whose process no longer exists (their
names carry the process id: ``<prefix><pid>-...``).
"""
from __future__ import annotations

import os
import shutil
import time
from pathlib import Path

__all__ = ["STALE_SECONDS", "sweep_stale", "sweep_orphans", "alive"]

STALE_SECONDS = 600


def sweep_stale(folder: str | os.PathLike, pattern: str, older_than: float = STALE_SECONDS) -> int:
    """Remove the files of *folder* matching *pattern* last modified more than *older_than* seconds
    ago; return how many.  A file that vanishes meanwhile, or cannot be removed, is left to the next
    sweep."""
    removed = 0
    limit = time.time() - older_than
    try:
        candidates = list(Path(folder).glob(pattern))
    except OSError:
        return 0
    for path in candidates:
        try:
            if path.is_file() and path.stat().st_mtime < limit:
                path.unlink()
                removed += 1
        except OSError:
            continue
    return removed


def sweep_orphans(folder: str | os.PathLike, prefix: str) -> int:
    """Remove the files and folders of *folder* named ``<prefix><pid>-...`` whose process *pid* is gone;
    return how many."""
    removed = 0
    try:
        candidates = list(Path(folder).glob(f"{prefix}*-*"))
    except OSError:
        return 0
    for path in candidates:
        owner = path.name[len(prefix):].split("-")[0]
        if not owner.isdigit() or alive(int(owner)):
            continue
        try:
            if path.is_dir() and not path.is_symlink():
                shutil.rmtree(path)
            else:
                path.unlink()
            removed += 1
        except OSError:
            continue
    return removed


def alive(pid: int) -> bool:
    """Whether a process *pid* exists (signal 0 asks the kernel without sending anything).

    >>> alive(os.getpid())
    True
    """
    try:
        os.kill(pid, 0)
    except (ProcessLookupError, OverflowError):
        return False
    except PermissionError:          # it exists, under another user
        return True
    return True
