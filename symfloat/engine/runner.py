"""Verifying a selection of derivations, with cache and progress.

Worker processes end with their parent: each asks the kernel for ``SIGKILL`` when its
parent dies (Linux ``PR_SET_PDEATHSIG``; elsewhere a watcher thread notices the new parent
within half a second), and ignores ``SIGINT``, which the parent handles: on Ctrl-C it kills
its workers at once, keeps every report already finished (each is cached as it arrives)
and lets the ``KeyboardInterrupt`` go on to the command line.  A worker that dies (killed by a
signal) breaks the pool: the command ends with one line naming the checks left unfinished
(:class:`WorkerLost`, exit status 2), the finished ones cached.
"""
from __future__ import annotations

import ctypes
import ctypes.util
import multiprocessing
import os
import pickle
import shutil
import signal
import sys
import tempfile
import threading
import time
import traceback
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from contextlib import contextmanager
from pathlib import Path

from ..errors import DerivationError, EnvironmentProblem, SymfloatError
from ..files import write_if_changed
from ..leftovers import sweep_orphans
from ..registry import files, load, manifest, requires, select
from .cache import CacheError, ReportCache
from .check import DerivationReport, Unsound, check_derivation, rejudged
from .key import derivation_key
from .environment import MAX_WORKERS, check_environment, default_workers
from .proofs import ProofBook

__all__ = ["verify", "derivation_keys", "Progress", "default_workers", "check_environment", "worker_pool", "completed",
           "WorkerPool", "WorkerLost", "MAX_WORKERS"]


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
    the standard library has it (Python 3.14), else each of the pool's processes.  The pool's
    manager thread is then waited for: with dead workers it ends at once, and left running it
    could be closing its wake-up pipe just as the interpreter's exit writes to it (a traceback
    on stderr, "Bad file descriptor", CPython 3.11)."""
    if hasattr(pool, "kill_workers"):
        pool.kill_workers()
    else:
        for process in list((getattr(pool, "_processes", None) or {}).values()):
            process.kill()
    pool.shutdown(wait=True, cancel_futures=True)


class WorkerLost(EnvironmentProblem):
    """A worker process died (a signal, the out-of-memory killer): exit status 2, one line naming
    what was not finished; what was finished is kept."""


def completed(futures: dict, what: str):
    """``(name, result)`` of each of *futures* (future -> name) as it completes, its result read from the file the
    worker left it in (:class:`WorkerPool`).  When a worker process dies, the pool breaks: :class:`WorkerLost`
    names the *what* (``checks``, ``notebooks``) left unfinished, after the caller has kept every result yielded
    before."""
    done = 0
    names = set(futures.values())
    try:
        for future in as_completed(futures):
            path = Path(future.result())
            with path.open("rb") as f:
                result = pickle.load(f)         # written by this run's own worker into this run's own folder
            path.unlink()
            done += 1
            names.discard(futures[future])
            yield futures[future], result
    except BrokenProcessPool:
        raise WorkerLost(f"a worker process died (killed by a signal, perhaps for want of memory): the {what} of "
                         f"{', '.join(sorted(names))} did not finish; the {done} finished are kept, run the "
                         f"command again to do the rest") from None


class ResultsUnwritable(EnvironmentProblem):
    """The temporary directory cannot take a worker's result (full, not writable): exit status 2, one line."""


def _unwritable(directory, exc: OSError) -> ResultsUnwritable:
    return ResultsUnwritable(f"cannot keep the workers' results in the temporary directory {directory} "
                             f"({exc.strerror or exc}): free space there, or name another with TMPDIR")


def _left_in_file(folder: str, fn, *args) -> str:
    """``fn(*args)`` in a worker, its result pickled into a new file of *folder*; the file's name is what goes back.
    A file that cannot be written (the temporary directory full) is removed and said in one line."""
    result = fn(*args)
    path = None
    try:
        fd, path = tempfile.mkstemp(dir=folder, suffix=".pickle")
        with os.fdopen(fd, "wb") as f:
            pickle.dump(result, f, protocol=pickle.HIGHEST_PROTOCOL)
    except OSError as exc:
        if path is not None:
            Path(path).unlink(missing_ok=True)
        raise _unwritable(Path(folder).parent, exc) from None
    return path


class WorkerPool:
    """Forked worker processes whose results come back through files.  A result sent through the pool's pipe
    is written in pieces when it is long (a report, an executed notebook: hundreds of kilobytes); a worker
    killed between two pieces leaves half a message there, and CPython's pool then waits for the rest for
    ever (``concurrent.futures.process``, 3.11: its manager reads the message before it looks at the dead
    worker).  A file's name is one write the pipe takes whole; the file itself is read by :func:`completed`."""

    def __init__(self, executor: ProcessPoolExecutor, folder: str):
        self.executor, self.folder = executor, folder

    def submit(self, fn, *args):
        return self.executor.submit(_left_in_file, self.folder, fn, *args)


@contextmanager
def worker_pool(workers: int):
    """A :class:`WorkerPool` of *workers* forked processes that end with this one; on any exception, Ctrl-C
    included, they are killed at once (finished results stay with the caller)."""
    executor = ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("fork"),
                                   initializer=_end_with_parent, initargs=(os.getpid(),))
    sweep_orphans(tempfile.gettempdir(), "symfloat-results-")      # the results folders of killed runs
    try:
        folder = tempfile.mkdtemp(prefix=f"symfloat-results-{os.getpid()}-")
    except OSError as exc:
        executor.shutdown()
        raise _unwritable(tempfile.gettempdir(), exc) from None
    try:
        try:
            yield WorkerPool(executor, folder)
        except BaseException:
            _kill(executor)
            raise
        executor.shutdown()
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def _cached_report(cache: ReportCache, did: str, key: str) -> DerivationReport | None:
    """The cached report of *did* when its entry passes the cache's checks (envelope, key, content
    hash) and the report stands up to the checker's rules (:func:`~symfloat.engine.check.rejudged`),
    else ``None``: it is then checked again and the entry replaced.  A refused entry is named on
    stderr with the reason, one line."""
    data, why = cache.read(did, key)
    if data is not None:
        try:
            report = rejudged(data, did, key)
        except Unsound as exc:
            why = f"its report does not stand up to the checker's rules: {exc}"
        else:
            report.cached = True
            return report
    if why:
        print(f"symfloat: cache entry {cache.path(did, key)} refused ({why}); checking {did} again",
              file=sys.stderr, flush=True)
    return None


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
                              f"{_where(exc, files(did))}") from exc
    report.seconds = time.perf_counter() - t0
    return report


def _where(exc: BaseException, package: list[Path]) -> str:
    """`` (module.py, line N)``: the last line of one of the derivation's files in *exc*'s traceback."""
    mine = {f.resolve() for f in package}
    frame = next((f for f in reversed(traceback.extract_tb(exc.__traceback__)) if Path(f.filename).resolve() in mine),
                 None)
    return f" ({Path(frame.filename).name}, line {frame.lineno})" if frame else ""


def _size(did: str) -> int:
    """The bytes of a derivation's package: a proxy for the cost of checking it."""
    return sum(f.stat().st_size for f in files(did) if f.suffix == ".py")


def _check_json(did: str, key: str, search: bool) -> dict:
    """:func:`_check` in a worker process: the report as JSON."""
    return _check(did, key, search).to_json()


def derivation_keys(ids) -> dict[str, str]:
    """The cache key of each derivation of *ids*, from the sources alone:
    finding a cached report imports no derivation module."""
    keys: dict[str, str] = {}

    def key(did):
        if did not in keys:
            m = manifest(did)
            keys[did] = derivation_key(files(did), m.source, [key(r) for r in requires(did)],
                                       f"symfloat.derivations.{m.package}")
        return keys[did]

    return {did: key(did) for did in ids}


def verify(selector: str | None = None, *, use_cache: bool = True, cache: ReportCache | None = None,
           progress: Progress | None = None, workers: int | None = None, search_proofs: bool = False,
           record_proofs: bool = False, share: bool = False) -> list[DerivationReport]:
    """Reports for the derivations *selector* picks, ancestors included, in dependency order.

    Derivations missing from the cache are checked in *workers* processes (checks are independent
    of one another; only the cache keys chain through the ancestors).  *search_proofs* searches every
    claim's proof anew instead of replaying its certificate (so it reads no cached report, whatever the
    cache holds, and caches what it finds);
    *record_proofs* writes the certificates of every derivation checked without failure to
    ``proofs/<id>.json`` (see :mod:`symfloat.engine.proofs`).  *share*: other processes verify into
    the same cache at the same time (test workers); each derivation is checked by whichever process
    takes its lock first, the others read its report from the cache (:func:`_shared`)."""
    cache = cache or ReportCache(enabled=use_cache)
    progress = progress or Progress(quiet=True)
    check_environment()
    workers = default_workers() if workers is None else workers
    ids = select(selector)
    keys: dict[str, str] = {}
    reports: dict[str, DerivationReport] = {}
    pending = []
    keys.update(derivation_keys(ids))
    for did in ids:
        report = None if search_proofs else _cached_report(cache, did, keys[did])
        if report is not None:
            reports[did] = report
        else:
            pending.append(did)
    done = 0

    unkept = []

    def finish(did, report):
        nonlocal done
        done += 1
        if not report.failures:
            try:
                cache.put(did, keys[did], report.to_json())
            except CacheError as exc:       # a full disk: the check is used, not thrown away, and said once
                if not unkept:
                    print(f"symfloat: {exc}; the results of this run are used but not kept", file=sys.stderr,
                          flush=True)
                unkept.append(did)
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
            largest_first = sorted(pending, key=lambda did: -_size(did))
            futures = {pool.submit(_check_json, did, keys[did], search_proofs): did for did in largest_first}
            for did, data in completed(futures, "checks"):
                finish(did, DerivationReport.from_json(data))
                progress.start(done, len(ids), did)
                progress.done(reports[did])
    else:
        shared = _shared(cache, sorted(pending, key=lambda did: -_size(did))) if share else None
        for did, lock in shared or ((did, None) for did in pending):
            report = _cached_report(cache, did, keys[did]) if lock is not None and not search_proofs else None
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
