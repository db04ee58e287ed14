"""A wall-clock limit for one symbolic strategy.

SymPy cannot be interrupted from outside, so the limit uses ``SIGALRM``: it
works in the main thread of a Unix process (the CLI, pytest, a notebook
kernel).  Elsewhere the strategy runs without a limit, and says so.
"""
from __future__ import annotations

import signal
import threading
from contextlib import contextmanager

__all__ = ["TimeLimitExceeded", "time_limit", "limits_available"]


class TimeLimitExceeded(Exception):
    """Raised inside a block that ran past its time limit."""


def limits_available() -> bool:
    return hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()


@contextmanager
def time_limit(seconds: float):
    """Raise :class:`TimeLimitExceeded` if the block runs longer than *seconds*."""
    if not limits_available() or seconds <= 0:
        yield
        return

    def _expire(signum, frame):
        raise TimeLimitExceeded(f"exceeded {seconds:g} s")

    previous = signal.signal(signal.SIGALRM, _expire)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
