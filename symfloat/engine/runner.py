"""Verifying a selection of derivations, with cache and progress.

Worker processes end with their parent: each asks the kernel for ``SIGKILL`` when its
parent dies (Linux ``PR_SET_PDEATHSIG``; elsewhere a watcher thread notices the new parent
within half a second), and ignores ``SIGINT``, which the parent handles: on Ctrl-C it kills
its workers at once, keeps every report already finished (each is cached as it arrives)
and lets the ``KeyboardInterrupt`` go on to the command line.
"""
from __future__ import annotations

import ctypes
import ctypes.util
import multiprocessing
import os
import signal
import sys
import threading
import time
import traceback
from concurrent.futures import ProcessPoolExecutor, as_completed
from contextlib import contextmanager
from pathlib import Path

from ..errors import DerivationError, SymfloatError
from ..registry import load, module_path, requires, select
from ..report.files import write_if_changed
from .cache import ReportCache, derivation_key
from .check import DerivationReport, check_derivation
from .proofs import ProofBook

__all__ = ["verify", "derivation_keys", "Progress", "default_workers", "worker_pool"]


class Progress:
    """One line per derivation on stderr; silent when ``quiet``."""

    def __init__(self, quiet: bool = False, stream=None):
        self.quiet = quiet
        self.stream = stream or sys.stderr

    def start(self, i, n, derivation_id):
        if not self.quiet:
            print(f"[{i}/{n}] {derivation_id} ...", end="", file=self.stream, flush=True)

    def checking(self, pending: int, cached: int, workers: int):
        """The line that opens a check: what is checked, what is read from the cache, on how many workers."""
        if not self.quiet:
            on = f" on {workers} workers, a line as each is done" if workers > 1 and pending > 1 else ""
            print(f"checking {pending} derivation{'s' * (pending != 1)}{on}; {cached} read from the cache",
                  file=self.stream, flush=True)

    def tick(self):
        if not self.quiet:
            print(".", end="", file=self.stream, flush=True)

    def done(self, report: DerivationReport):
        if not self.quiet:
            how = "cached" if report.cached else f"{report.seconds:.1f} s"
            bad = f", {len(report.failures)} FAILURES" if report.failures else ""
            print(f" {how}{bad}", file=self.stream, flush=True)


def default_workers() -> int:
    """Processes for checking: ``$SYMFLOAT_WORKERS``, else the usable cores (at most 4)."""
    env = os.environ.get("SYMFLOAT_WORKERS", "")
    if env.isdigit() and int(env) >= 1:
        return int(env)
    return max(1, min(4, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1))


def _end_with_parent(parent: int) -> None:
    """Worker initializer: ignore Ctrl-C (the parent handles it) and die with the parent."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    libc = ctypes.util.find_library("c") if sys.platform.startswith("linux") else None
    if libc:
        pr_set_pdeathsig = 1
        ctypes.CDLL(libc, use_errno=True).prctl(pr_set_pdeathsig, signal.SIGKILL, 0, 0, 0)
        if os.getppid() == parent:
            return                          # else the parent died before the request took effect

    def watch():
        while os.getppid() == parent:
            time.sleep(0.5)
        os._exit(1)
    threading.Thread(target=watch, daemon=True).start()


def _kill(pool: ProcessPoolExecutor) -> None:
    """End the pool's workers now (they may be deep in a symbolic check): ``kill_workers`` where
    the standard library has it (Python 3.14), else each of the pool's processes."""
    if hasattr(pool, "kill_workers"):
        pool.kill_workers()
    else:
        for process in list((getattr(pool, "_processes", None) or {}).values()):
            process.kill()
    pool.shutdown(wait=False, cancel_futures=True)


@contextmanager
def worker_pool(workers: int):
    """A pool of *workers* forked processes that end with this one; on any exception, Ctrl-C
    included, they are killed at once (finished results stay with the caller)."""
    pool = ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("fork"),
                               initializer=_end_with_parent, initargs=(os.getpid(),))
    try:
        yield pool
    except BaseException:
        _kill(pool)
        raise
    pool.shutdown()


def _cached_report(cache: ReportCache, did: str, key: str) -> DerivationReport | None:
    """The cached report of *did* when its entry passes the cache's checks (envelope, key, content
    hash) and reads back as a report of that derivation, else ``None`` (it is then checked again
    and the entry replaced)."""
    data = cache.get(did, key)
    if data is None:
        return None
    try:
        report = DerivationReport.from_json(data)
    except (TypeError, KeyError, ValueError, AttributeError):
        return None
    if report.id != did or report.failures:
        return None
    report.cached = True
    return report


def _check(did: str, key: str, search: bool, tick=None) -> DerivationReport:
    """Check one derivation, replaying its proof certificates (or searching anew).  An exception
    from the module or its check becomes one :class:`DerivationError` naming where it arose."""
    try:
        d, _ = load(did)
        t0 = time.perf_counter()
        report = check_derivation(d, key, book=ProofBook.load(did, search=search), progress=tick)
    except SymfloatError:
        raise
    except Exception as exc:
        raise DerivationError(f"derivation {did} could not be checked: {type(exc).__name__}: {exc}"
                              f"{_where(exc, module_path(did))}") from exc
    report.seconds = time.perf_counter() - t0
    return report


def _where(exc: BaseException, module: Path) -> str:
    """`` (module.py, line N)``: the last line of the derivation module in *exc*'s traceback."""
    line = next((f.lineno for f in reversed(traceback.extract_tb(exc.__traceback__))
                 if Path(f.filename).resolve() == module.resolve()), None)
    return f" ({module.name}, line {line})" if line else ""


def _check_json(did: str, key: str, search: bool) -> dict:
    """:func:`_check` in a worker process: the report as JSON."""
    return _check(did, key, search).to_json()


def derivation_keys(ids) -> dict[str, str]:
    """The cache key of each derivation of *ids*, from the sources alone:
    finding a cached report imports no derivation module."""
    keys: dict[str, str] = {}

    def key(did):
        if did not in keys:
            keys[did] = derivation_key(module_path(did), [key(r) for r in requires(did)], ProofBook.path(did))
        return keys[did]

    return {did: key(did) for did in ids}


def verify(selector: str | None = None, *, use_cache: bool = True, cache: ReportCache | None = None,
           progress: Progress | None = None, workers: int | None = None, search_proofs: bool = False,
           record_proofs: bool = False, share: bool = False) -> list[DerivationReport]:
    """Reports for the derivations *selector* picks, ancestors included, in dependency order.

    Derivations missing from the cache are checked in *workers* processes (checks are independent
    of one another; only the cache keys chain through the ancestors).  *search_proofs* searches every
    claim's proof anew instead of replaying its certificate (and so bypasses the cache);
    *record_proofs* writes the certificates of every derivation checked without failure to
    ``proofs/<id>.json`` (see :mod:`symfloat.engine.proofs`).  *share*: other processes verify into
    the same cache at the same time (test workers); each derivation is checked by whichever process
    takes its lock first, the others read its report from the cache (:func:`_shared`)."""
    cache = cache or ReportCache(enabled=use_cache and not search_proofs)
    progress = progress or Progress(quiet=True)
    workers = default_workers() if workers is None else workers
    ids = select(selector)
    keys: dict[str, str] = {}
    reports: dict[str, DerivationReport] = {}
    pending = []
    keys.update(derivation_keys(ids))
    for did in ids:
        report = _cached_report(cache, did, keys[did])
        if report is not None:
            reports[did] = report
        else:
            pending.append(did)
    done = 0

    def finish(did, report):
        nonlocal done
        done += 1
        if not report.failures:
            cache.put(did, keys[did], report.to_json())
            if record_proofs:
                write_if_changed(ProofBook.path(did), ProofBook.text(report.certificates()))
        reports[did] = report

    progress.checking(len(pending), len(ids) - len(pending), workers)
    for did in ids:
        if did in reports:
            done += 1
            progress.start(done, len(ids), did)
            progress.done(reports[did])
    if workers > 1 and len(pending) > 1:
        with worker_pool(min(workers, len(pending))) as pool:
            # the largest modules first (a proxy for their cost), so that no worker is left with a long
            # check at the end while the other idles
            largest_first = sorted(pending, key=lambda did: -module_path(did).stat().st_size)
            futures = {pool.submit(_check_json, did, keys[did], search_proofs): did for did in largest_first}
            for future in as_completed(futures):
                did = futures[future]
                finish(did, DerivationReport.from_json(future.result()))
                progress.start(done, len(ids), did)
                progress.done(reports[did])
    else:
        shared = _shared(cache, sorted(pending, key=lambda did: -module_path(did).stat().st_size)) if share else None
        for did, lock in shared or ((did, None) for did in pending):
            report = _cached_report(cache, did, keys[did]) if lock is not None else None
            if report is None:
                progress.start(done + 1, len(ids), did)
                finish(did, _check(did, keys[did], search_proofs, progress.tick))
            else:
                done += 1
                reports[did] = report
            progress.done(reports[did])
            if lock is not None:
                lock.close()
    return [reports[did] for did in ids]


def _shared(cache: ReportCache, pending: list[str]):
    """*pending* in the order this process can take their locks (``<cache>/<id>.lock``, ``flock``):
    first those no other process holds, then, waiting for each, the rest; yields ``(id, open lock)``.
    A derivation another process finished is then read from the cache, not checked again."""
    import fcntl
    cache.root.mkdir(parents=True, exist_ok=True)
    waiting = []
    for did in pending:
        lock = open(cache.root / f"{did}.lock", "w")
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            lock.close()
            waiting.append(did)
            continue
        yield did, lock
    for did in waiting:
        lock = open(cache.root / f"{did}.lock", "w")
        fcntl.flock(lock, fcntl.LOCK_EX)
        yield did, lock
