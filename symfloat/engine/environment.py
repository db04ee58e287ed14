"""The environment variables of checking, read without loading the checker: ``SYMFLOAT_WORKERS`` (processes)
and ``SYMFLOAT_SLOWDOWN`` (a factor on every search time limit).  The command line asks them before any work,
a scene included, so this module imports nothing of the engine (and no SymPy)."""
from __future__ import annotations

import os

from ..errors import EnvironmentProblem

__all__ = ["MAX_WORKERS", "default_workers", "slowdown", "check_environment"]

MAX_WORKERS = 64


def default_workers() -> int:
    """Processes for checking: ``$SYMFLOAT_WORKERS`` (1 to :data:`MAX_WORKERS`), else the usable cores
    (at most 4).  Any other value of the variable is an environment problem (exit status 2)."""
    env = os.environ.get("SYMFLOAT_WORKERS", "")
    if env:
        if not (env.isascii() and env.isdigit() and len(env) <= 2 and 1 <= int(env) <= MAX_WORKERS):
            raise EnvironmentProblem(f"SYMFLOAT_WORKERS must be a whole number from 1 to {MAX_WORKERS}, "
                                     f"not {env[:40]!r}")
        return int(env)
    return max(1, min(4, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1))


def slowdown() -> float:
    """``$SYMFLOAT_SLOWDOWN``: a factor by which every search time limit is divided,
    to try the engine as if on a machine that much slower (default 1).  Replayed
    certificates use no time limit, so no verdict can depend on it."""
    raw = os.environ.get("SYMFLOAT_SLOWDOWN", "")
    try:
        factor = float(raw) if raw and len(raw) <= 40 and raw.isascii() else 1.0 if not raw else None
    except ValueError:
        factor = None
    if factor is None or not factor >= 1:
        raise EnvironmentProblem(f"SYMFLOAT_SLOWDOWN must be a number >= 1, not {raw[:40]!r}")
    return factor


def check_environment() -> None:
    """The environment variables of checking (``SYMFLOAT_WORKERS``, ``SYMFLOAT_SLOWDOWN``) are usable, else
    :class:`~symfloat.errors.EnvironmentProblem` (exit status 2): the command line asks before any work."""
    default_workers()
    slowdown()
