"""Nothing left behind, nothing thrown away (symfloat issue 32): temporary files of a killed run are
swept by the next, kernels' connection files and site build folders of dead processes removed, cache
entries get the umask's mode, finished notebooks and checks are kept when a worker or the disk fails,
and a worker killed at a random moment is one line naming what was lost."""
import errno
import json
import os
import pickle
import random
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from types import SimpleNamespace

import pytest

import symfloat.cli as cli
import symfloat.engine.runner as runner
import symfloat.report.notebooks as notebooks
from symfloat.engine.cache import CacheError, ReportCache
from symfloat.engine.runner import WorkerLost, _cached_report, completed, verify, worker_pool
from symfloat.leftovers import STALE_SECONDS, sweep_orphans, sweep_stale
from symfloat.files import write_atomic

OLD = time.time() - 2 * STALE_SECONDS


def _aged(path: Path, when=OLD) -> Path:
    path.write_text("half a write\n")
    os.utime(path, (when, when))
    return path


def _dead_pid() -> int:
    """The id of a process that has ended (and been reaped)."""
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


# ------------------------------------------------------------------ temporary files of a killed run

def test_a_killed_runs_cache_temporaries_are_swept_and_a_running_ones_kept(tmp_path):
    old = _aged(tmp_path / ".graefe-s1-prismatoid-volume.x1y2.tmp")
    fresh = _aged(tmp_path / ".graefe-s2-volumes-simpson.a1b2.tmp", time.time())   # a concurrent run's write
    entry = _aged(tmp_path / "graefe-s1-prismatoid-volume.0123.json")               # an entry, however old
    ReportCache(tmp_path).prepare()
    assert not old.exists() and fresh.exists() and entry.exists()


def test_a_killed_writes_temporary_is_swept_by_the_next_write_of_that_file(tmp_path):
    old = _aged(tmp_path / ".errata.md.k2j3h4")
    other = _aged(tmp_path / ".errata.json.k2j3h4")            # another file's: left to its own write
    write_atomic(tmp_path / "errata.md", b"new\n")
    assert not old.exists() and other.exists() and (tmp_path / "errata.md").read_text() == "new\n"
    assert sweep_stale(tmp_path, ".errata.json.*") == 1


def test_kernel_connection_files_and_site_build_folders_of_dead_processes_are_removed(tmp_path):
    dead = _dead_pid()
    folder = notebooks.kernel_files()
    orphan = _aged(folder / f"kernel-{dead}-0a1b2c.json")
    own = _aged(folder / f"kernel-{os.getpid()}-0a1b2c.json")
    try:
        assert notebooks.kernel_files() == folder and not orphan.exists() and own.exists()
    finally:
        own.unlink()
    (tmp_path / f"symfloat-site-{dead}-abc" / "html").mkdir(parents=True)
    (tmp_path / f"symfloat-site-{os.getpid()}-abc").mkdir()
    assert sweep_orphans(tmp_path, "symfloat-site-") == 1
    assert [p.name for p in tmp_path.iterdir()] == [f"symfloat-site-{os.getpid()}-abc"]


def test_a_notebook_kernels_connection_file_lies_in_the_swept_folder(monkeypatch):
    seen = {}

    class Client:
        def __init__(self, nb, **kw):
            seen["file"] = kw["config"]["KernelManager"]["connection_file"]

        def execute(self, **kw):
            pass
    monkeypatch.setattr(notebooks, "NotebookClient", Client)
    notebooks.execute_notebook(notebooks.nbformat.v4.new_notebook(), ".")
    assert Path(seen["file"]).parent == notebooks.kernel_files()
    assert Path(seen["file"]).name.startswith(f"kernel-{os.getpid()}-")


@pytest.mark.parametrize("mask, mode", [(0o022, 0o644), (0o077, 0o600), (0o002, 0o664)])
def test_cache_entries_get_the_umasks_mode(tmp_path, mask, mode):
    old = os.umask(mask)
    try:
        ReportCache(tmp_path).put("d", "0" * 32, {"id": "d"})
    finally:
        os.umask(old)
    (entry,) = tmp_path.glob("d.*.json")
    assert entry.stat().st_mode & 0o777 == mode                   # 0666 & ~umask, as the README says


# ------------------------------------------------------------------ finished work is kept

def test_a_notebook_phase_stopped_late_keeps_the_notebooks_it_finished(tmp_path, monkeypatch):
    monkeypatch.setenv("SYMFLOAT_WORKERS", "1")
    ids = ["graefe-s1-prismatoid-volume", "graefe-s2-volumes-simpson"]

    def executed(did, stamp, folder):
        if did == ids[1]:
            raise KeyboardInterrupt                          # Ctrl-C (or a kill) during the second notebook
        return json.dumps({"cells": [], "metadata": {"symfloat": {"stamp": stamp}}, "nbformat": 4,
                           "nbformat_minor": 5}) + "\n"
    monkeypatch.setattr(notebooks, "_executed_text", executed)
    with pytest.raises(KeyboardInterrupt):
        notebooks.write_notebooks(ids, tmp_path)
    assert [p.name for p in tmp_path.iterdir()] == [f"{ids[0]}.ipynb"]


def test_a_full_cache_disk_keeps_the_checks_and_says_so_once(tmp_path, monkeypatch, capsys):
    def full(self, *a):
        raise CacheError(f"cannot write to the cache directory {self.root} (SYMFLOAT_CACHE): No space left on device")
    monkeypatch.setattr(ReportCache, "put", full)
    reports = verify("graefe-s2", cache=ReportCache(tmp_path), workers=1)
    assert [r.id for r in reports] == ["graefe-s1-prismatoid-volume", "graefe-s2-volumes-simpson"]
    assert not any(r.failures for r in reports)
    (line,) = capsys.readouterr().err.splitlines()
    assert "No space left on device; the results of this run are used but not kept" in line


def _full(*args, **kwargs):
    raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))


def _a_quick_check(did, key, search):
    return {"id": did}                           # the check is not what fails: writing its result is


def test_a_full_temporary_directory_is_one_line_not_a_workers_traceback(tmp_path, monkeypatch, capsys):
    # workers hand their results back through files of the temporary directory (WorkerPool); where it is full,
    # the worker's OSError reached the command as a traceback from the pool
    monkeypatch.setattr(runner, "pickle", SimpleNamespace(dump=_full, load=pickle.load, HIGHEST_PROTOCOL=5))
    monkeypatch.setattr(runner, "_check_json", _a_quick_check)
    monkeypatch.setenv("SYMFLOAT_WORKERS", "2")
    monkeypatch.setenv("SYMFLOAT_CACHE", str(tmp_path))
    assert cli.main(["verify", "graefe-s2", "--quiet"]) == 2
    (line,) = capsys.readouterr().err.splitlines()
    assert "cannot keep the workers' results in the temporary directory" in line
    assert "No space left on device" in line and "TMPDIR" in line
    assert not list(Path(tempfile.gettempdir()).glob(f"symfloat-results-{os.getpid()}-*"))   # nothing left


# ------------------------------------------------------------------ a worker killed at a random moment

KILLER = """
import os, random, signal, sys, threading
import symfloat.engine.runner as runner
from symfloat.cli import main

real = runner._check_json
victim, delay = sys.argv[1], float(sys.argv[2])

def check_json(did, key, search):
    if did == victim:            # the out-of-memory killer picks this worker at a random moment
        threading.Timer(delay, os.kill, (os.getpid(), signal.SIGKILL)).start()
    return real(did, key, search)

runner._check_json = check_json
sys.exit(main(["verify", "graefe-s2", "--quiet"]))
"""


def test_a_worker_killed_at_a_random_moment_is_one_line_and_keeps_the_finished_checks(tmp_path):
    seed = random.randrange(10**6)
    rng = random.Random(seed)
    victim = rng.choice(["graefe-s1-prismatoid-volume", "graefe-s2-volumes-simpson"])
    delay = rng.uniform(0, 4)            # both checks take 1 to 4 s (docs/performance.md): before or after
    env = {**os.environ, "SYMFLOAT_CACHE": str(tmp_path / "cache"), "SYMFLOAT_WORKERS": "2",
           "SYMFLOAT_SLOWDOWN": "1e9"}
    proc = subprocess.run([sys.executable, "-c", KILLER, victim, str(delay)], env=env, capture_output=True,
                          text=True, timeout=300)
    why = f"seed {seed}: {victim} killed after {delay:.2f} s; stderr {proc.stderr!r}"
    assert "Traceback" not in proc.stderr, why
    cache = ReportCache(tmp_path / "cache")
    keys = {p.name.split(".")[0]: p.name.split(".")[1] for p in cache.root.glob("*.json")}
    kept = {did for did, key in keys.items() if _cached_report(cache, did, key) is not None}
    if proc.returncode == 0:                                   # the kill came after the work
        assert kept == {"graefe-s1-prismatoid-volume", "graefe-s2-volumes-simpson"}, why
        return
    assert proc.returncode == 2, why
    (line,) = proc.stderr.splitlines()
    assert line.startswith("symfloat: a worker process died (killed by a signal"), why
    lost = line.split("the checks of ")[1].split(" did not finish")[0].split(", ")
    assert lost and not set(lost) & kept, why                 # what is named lost is not in the cache ...
    assert set(lost) | kept == {"graefe-s1-prismatoid-volume", "graefe-s2-volumes-simpson"}, why   # ... the rest is
    assert f"the {len(kept)} finished are kept" in line, why


# ------------------------------------------------------------------ output targets and limits

def test_an_atlas_too_large_or_with_too_many_workers_is_refused_before_any_work(tmp_path, capsys, monkeypatch):
    pytest.importorskip("dask.distributed")
    monkeypatch.setattr("symfloat.atlas.command.run_atlas", lambda *a, **k: pytest.fail("work started"))
    grid = ["atlas", "box", "--density", "1/4:3/4:3", "--out", str(tmp_path / "a"), "--quiet"]
    started = time.monotonic()
    assert cli.main([*grid, "--ba", "1:2:2000", "--ca", "1:2:2000"]) == 2
    assert time.monotonic() - started < 60                    # not two minutes of validating 4 million shapes
    assert "2000 x 2000 = 4000000 shapes; an atlas takes at most 10000" in capsys.readouterr().err
    assert cli.main([*grid, "--ba", "2", "--ca", "3", "--workers", "1024"]) == 2
    assert "--workers must lie between 0 and 64, got 1024" in capsys.readouterr().err
    assert cli.main([*grid[:5], "/proc/at", "--quiet", "--ba", "2", "--ca", "3"]) == 2
    assert "cannot write into /proc/at" in capsys.readouterr().err
    assert cli.main([*grid[:5], str(tmp_path / ("a" * 300)), "--quiet", "--ba", "2", "--ca", "3"]) == 2
    assert "File name too long" in capsys.readouterr().err                  # not OSError 36
    assert not (tmp_path / "a").exists()


def _die():
    os.kill(os.getpid(), signal.SIGKILL)        # as the out-of-memory killer does


def _long_result():
    return "x" * 3_000_000                       # a report or an executed notebook: hundreds of kilobytes and more


def test_a_long_result_comes_back_through_a_file_whose_name_the_pipe_takes_whole():
    # make test under load once hung for 300 s in the random test above: a worker killed while it wrote a long
    # result into the pool's pipe left half a message, and CPython 3.11's pool manager waits for the rest for
    # ever.  What a worker sends now is a file's name, far below the pipe's atomic write (PIPE_BUF, 4096 bytes)
    with worker_pool(2) as pool:
        future = pool.submit(_long_result)
        sent = future.result()
        assert Path(sent).parent == Path(pool.folder) and len(sent.encode()) < 4096
        assert list(completed({future: "long"}, "checks")) == [("long", _long_result())]
        assert not Path(sent).exists()           # read once, then gone
        folder = pool.folder
    assert not Path(folder).exists()
    # a run killed outright leaves its folder, named by its process, which the next pool removes
    orphan = Path(folder).with_name(f"symfloat-results-{2 ** 22 + 1}-x")
    orphan.mkdir()
    with worker_pool(2):
        assert not orphan.exists()


def test_a_broken_pool_is_ended_before_the_command_returns():
    # The random test above once printed CPython 3.11's "Bad file descriptor" traceback: the pool's
    # manager thread, left running, closed its wake-up pipe while the interpreter's exit wrote to it.
    # Waiting for that thread in _kill closes the race; with shutdown(wait=False) it is still alive here.
    with pytest.raises(WorkerLost):
        with worker_pool(2) as pool:
            futures = {pool.submit(_die): "the victim"}
            manager = pool.executor._executor_manager_thread
            for _ in completed(futures, "checks"):
                pass
    assert not manager.is_alive()
