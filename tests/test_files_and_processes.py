"""Files and processes: atomic writes with ordinary permissions, one line for an unwritable or full
directory with the previous output intact, selections that never replace the record of everything,
a cache verified by content hash, workers that end with their parent, Ctrl-C as exit status 130."""
import errno
import gc
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

import symfloat.cli as cli
import symfloat.project as project
from symfloat.engine.cache import ReportCache
from symfloat.engine.runner import verify
from symfloat.errors import CheckFailed
from symfloat.files import OutputError, write_atomic, write_if_changed

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture
def umask_022():
    old = os.umask(0o022)
    yield
    os.umask(old)


def test_new_files_get_ordinary_permissions_and_rewritten_ones_keep_theirs(tmp_path, umask_022):
    new = tmp_path / "new.md"
    assert write_if_changed(new, "a\n")
    assert new.stat().st_mode & 0o777 == 0o644               # 0666 & ~022, not mkstemp's 0600
    kept = tmp_path / "kept.md"
    kept.write_text("old\n")
    kept.chmod(0o640)
    assert write_if_changed(kept, "new\n") and kept.read_text() == "new\n"
    assert kept.stat().st_mode & 0o777 == 0o640


def _no_temporaries(folder):
    return [p.name for p in folder.iterdir() if p.name.startswith(".")] == []


def test_a_full_disk_keeps_the_previous_output(tmp_path, monkeypatch):
    out = tmp_path / "errata.md"
    out.write_text("previous\n")

    def full(fd):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    monkeypatch.setattr(os, "fsync", full)
    with pytest.raises(OutputError, match="No space left on device; the previous file is unchanged"):
        write_atomic(out, b"new\n")
    assert out.read_text() == "previous\n" and _no_temporaries(tmp_path)


def test_an_unwritable_directory_is_one_line(tmp_path, monkeypatch):
    out = tmp_path / "errata.md"
    out.write_text("previous\n")

    def denied(**kw):
        raise PermissionError(errno.EACCES, os.strerror(errno.EACCES))
    monkeypatch.setattr(tempfile, "mkstemp", denied)
    with pytest.raises(OutputError, match="Permission denied"):
        write_atomic(out, b"new\n")
    assert out.read_text() == "previous\n"


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into read-only directories")
def test_a_read_only_directory_is_refused_before_any_work(tmp_path, capsys):
    folder = tmp_path / "ro"
    folder.mkdir()
    folder.chmod(0o555)
    try:
        assert cli.main(["scene", "cube", "--density", "0.3", "--plot", str(folder / "x.png"), "--quiet"]) == 2
    finally:
        folder.chmod(0o755)
    assert capsys.readouterr().err.count("\n") == 1


@pytest.mark.parametrize("argv, message", [
    (["scene", "cube", "--density", "0.3", "--plot", "x.txt"], "--output writes a PNG image"),
    (["scene", "cube", "--density", "0.3", "--plot", "/dev/null/x.png"], "/dev/null is not a directory"),
    (["errata", "graefe-s1", "--output", "."], "it is a directory"),
    (["errata", "graefe", "--output", str(ROOT / "docs" / "errata.md")], "is the record of every source"),
    (["verify", ""], "a selector is a source key"),
    (["verify", "graefe\n"], "a selector is a source key"),
    # symfloat issue 32: a folder that is not there is not created, /proc takes no file even as root,
    # a name longer than the file system allows (255 bytes) is one line, not OSError 36
    (["scene", "cube", "--density", "0.3", "--plot", "/nonexistent-symfloat/dir/x.png"],
     "the folder /nonexistent-symfloat/dir does not exist"),
    (["scene", "cube", "--density", "0.3", "--plot", "/proc/x.png"], "cannot write /proc/x.png"),
    (["scene", "cube", "--density", "0.3", "--plot", "a" * 300 + ".png"], "File name too long"),
    (["errata", "graefe-s1", "--output", "a" * 300 + ".md"], "File name too long"),
    (["notebooks", "graefe-s1", "--output", "a" * 300], "File name too long"),
    (["notebooks", "graefe-s1", "--output", "no/such/tree"], "symfloat creates one folder, not a tree"),
])
def test_bad_paths_and_selectors_are_one_line_before_any_work(argv, message, capsys, monkeypatch, tmp_path):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(cli, "verify", lambda *a, **k: pytest.fail("work started"))
    monkeypatch.setattr("symfloat.solver.solve", lambda *a, **k: pytest.fail("work started"))
    golden = (ROOT / "docs" / "errata.md").stat()
    assert cli.main([*argv, "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("symfloat: ") and message in err and err.count("\n") == 1
    assert (ROOT / "docs" / "errata.md").stat().st_mtime_ns == golden.st_mtime_ns


def test_an_unusable_cache_is_one_line(capsys, monkeypatch):
    monkeypatch.setenv("SYMFLOAT_CACHE", os.devnull)
    assert cli.main(["verify", "graefe-s1", "--quiet"]) == 2
    assert "cannot use the cache directory /dev/null (SYMFLOAT_CACHE): not a directory" in capsys.readouterr().err


@pytest.mark.parametrize("variable, value, message", [
    # symfloat issue 32: each of these was a ValueError or OSError traceback
    ("SYMFLOAT_WORKERS", "²", "SYMFLOAT_WORKERS must be a whole number from 1 to 64, not '²'"),
    ("SYMFLOAT_WORKERS", "9" * 5000, "SYMFLOAT_WORKERS must be a whole number from 1 to 64"),
    ("SYMFLOAT_WORKERS", "0", "SYMFLOAT_WORKERS must be a whole number from 1 to 64, not '0'"),
    ("SYMFLOAT_SLOWDOWN", "fast", "SYMFLOAT_SLOWDOWN must be a number >= 1, not 'fast'"),
    ("SYMFLOAT_SLOWDOWN", "0.5", "SYMFLOAT_SLOWDOWN must be a number >= 1, not '0.5'"),
    ("SYMFLOAT_SLOWDOWN", "nan", "SYMFLOAT_SLOWDOWN must be a number >= 1, not 'nan'"),
    ("SYMFLOAT_CACHE", "/tmp/" + "a" * 300, "SYMFLOAT_CACHE): File name too long"),
    ("SYMFLOAT_LIBRARY", "/tmp/" + "a" * 300, "is not a usable folder (File name too long)"),
])
def test_an_unusable_environment_variable_is_one_line_and_exit_2(variable, value, message, capsys, monkeypatch):
    monkeypatch.setenv(variable, value)
    monkeypatch.setattr("symfloat.engine.runner.select", lambda *a, **k: pytest.fail("work started"))
    assert cli.main(["verify", "graefe-s1", "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("symfloat: ") and message in err and err.count("\n") == 1, err


def test_default_outputs_belong_to_the_checkout(monkeypatch, tmp_path, capsys, graefe_reports):
    monkeypatch.chdir(tmp_path)
    assert project.project_root() == ROOT                     # wherever the command runs
    monkeypatch.setattr(cli, "verify", lambda *a, **k: graefe_reports)
    (tmp_path / "checkout").mkdir()                           # a checkout (its docs/ is made if missing)
    monkeypatch.delenv("SYMFLOAT_LIBRARY", raising=False)                 # no library: the checkout's
    monkeypatch.setattr(project, "project_root", lambda: tmp_path / "checkout")
    assert cli.main(["errata", "--quiet"]) == 0
    assert (tmp_path / "checkout" / "docs" / "errata.md").read_text(encoding="utf-8").startswith("# Errata")
    assert not (tmp_path / "docs").exists()
    monkeypatch.setattr(project, "project_root", lambda: None)
    assert cli.main(["errata", "--quiet"]) == 2
    assert "not inside a symfloat checkout" in capsys.readouterr().err
    assert cli.main(["errata", "--quiet", "--output", "mine.md"]) == 0 and (tmp_path / "mine.md").exists()


# ------------------------------------------------------------------ exit status policy

def test_a_failed_self_check_is_exit_1_and_ctrl_c_is_130(monkeypatch, capsys, tmp_path, cache_dir):
    monkeypatch.setenv("SYMFLOAT_CACHE", str(cache_dir))

    def index_fails(*a, **k):
        raise CheckFailed("Poincaré–Hopf index sum 0, expected 2")
    monkeypatch.setattr(cli, "verify", index_fails)
    assert cli.main(["verify", "graefe-s1", "--quiet"]) == 1
    assert capsys.readouterr().err == "symfloat: Poincaré–Hopf index sum 0, expected 2\n"

    def interrupted(*a, **k):
        raise KeyboardInterrupt
    monkeypatch.setattr(cli, "verify", interrupted)
    assert cli.main(["verify", "graefe-s1", "--quiet"]) == 130
    assert capsys.readouterr().err == "symfloat: interrupted (finished checks are kept in the cache)\n"

    def kernel_dies_of_ctrl_c(*a, **k):    # a notebook kernel turns Ctrl-C into its own error
        collecting = gc.isenabled()
        gc.disable()        # no collection between the signal and its handler: a collector's callback (Hypothesis
        try:                # times collections) would receive the KeyboardInterrupt and Python would ignore it
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(1)
        except KeyboardInterrupt:
            raise RuntimeError("Kernel died") from None
        finally:
            if collecting:
                gc.enable()
    monkeypatch.setattr(cli, "verify", kernel_dies_of_ctrl_c)
    assert cli.main(["verify", "graefe-s1", "--quiet"]) == 130


def test_quiet_policy(monkeypatch, capsys, cache_dir, graefe_reports):
    monkeypatch.setenv("SYMFLOAT_CACHE", str(cache_dir))
    for value, silent in (("1", True), ("yes", True), ("0", False), ("", False)):
        monkeypatch.setenv("SYMFLOAT_QUIET", value)
        assert cli.main(["verify", "graefe-s1"]) == 0
        assert (capsys.readouterr().err == "") == silent, value


# ------------------------------------------------------------------ the cache

@pytest.fixture(scope="module")
def checked_once(tmp_path_factory):
    """graefe-s1 checked once into a private cache: the cache and the fresh report."""
    folder = tmp_path_factory.mktemp("cache")
    return folder, verify("graefe-s1", cache=ReportCache(folder))[0]


def _entry(folder):
    (path,) = folder.glob("graefe-s1-prismatoid-volume.*.json")
    return path


@pytest.mark.parametrize("damage", ["edit a verdict", "truncate", "{}", "[]", "other format", "other key"])
def test_a_damaged_cache_entry_is_not_trusted(checked_once, tmp_path, damage):
    shutil.copytree(checked_once[0], tmp_path, dirs_exist_ok=True)
    path = _entry(tmp_path)
    did, key = path.name.split(".")[:2]
    cache = ReportCache(tmp_path)
    assert cache.get(did, key) is not None
    text = path.read_text(encoding="utf-8")
    entry = json.loads(text)
    path.write_text({"edit a verdict": text.replace('"erratum"', '"verified"', 1),
                     "truncate": text[:len(text) // 2], "{}": "{}", "[]": "[]",
                     "other format": json.dumps({**entry, "format": 1}),
                     "other key": json.dumps({**entry, "key": "0" * 32})}[damage], encoding="utf-8")
    assert path.read_text(encoding="utf-8") != text
    assert cache.get(did, key) is None


def test_a_hand_edited_verdict_is_recomputed(checked_once, tmp_path):
    # symfloat issue 17: setting verdicts to 'verified' in a cache file changed the summary
    shutil.copytree(checked_once[0], tmp_path, dirs_exist_ok=True)
    path = _entry(tmp_path)
    text = path.read_text(encoding="utf-8")
    assert '"erratum"' in text
    path.write_text(text.replace('"erratum"', '"verified"'), encoding="utf-8")
    again = verify("graefe-s1", cache=ReportCache(tmp_path))[0]
    assert not again.cached                                    # checked again, not read
    assert [f.verdict for f in again.formulas] == [f.verdict for f in checked_once[1].formulas]
    assert verify("graefe-s1", cache=ReportCache(tmp_path))[0].cached     # the entry replaced by a sound one


def _concurrent_puts(folder, n):
    cache = ReportCache(folder)
    for i in range(n):
        cache.put("d", f"{i % 3:032x}", {"id": "d", "i": i, "payload": "x" * 5000})
        got = [cache.get("d", f"{k:032x}") for k in range(3)]
        assert all(g is None or (g["id"] == "d" and len(g["payload"]) == 5000) for g in got)


def test_concurrent_writers_never_leave_a_damaged_entry(tmp_path):
    code = f"import sys; sys.path.insert(0, {str(Path(__file__).parent)!r}); " \
           f"from test_files_and_processes import _concurrent_puts; _concurrent_puts({str(tmp_path)!r}, 300)"
    procs = [subprocess.Popen([sys.executable, "-c", code]) for _ in range(3)]
    assert [p.wait(timeout=120) for p in procs] == [0, 0, 0]
    entries = list(tmp_path.glob("d.*.json"))
    assert len(entries) <= 3 and _no_temporaries(tmp_path)
    for path in entries:
        assert ReportCache(tmp_path).get("d", path.name.split(".")[1]) is not None


# ------------------------------------------------------------------ signals and workers

def _children(pid):
    try:
        text = Path(f"/proc/{pid}/task/{pid}/children").read_text()
    except OSError:
        return []
    return [int(c) for c in text.split()]


def _alive(pid):
    try:
        return Path(f"/proc/{pid}/stat").read_text().split()[2] != "Z"
    except OSError:
        return False


def _start(tmp_path, *argv):
    env = {**os.environ, "SYMFLOAT_CACHE": str(tmp_path / "cache"), "SYMFLOAT_WORKERS": "2"}
    env.pop("SYMFLOAT_QUIET", None)
    return subprocess.Popen([sys.executable, "-m", "symfloat", *argv, "--quiet"], env=env, cwd=tmp_path,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _wait_for(predicate, seconds=120):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.05)
    return False


needs_proc = pytest.mark.skipif(not Path("/proc/self/task").exists(), reason="reads /proc")


@needs_proc
def test_workers_end_with_their_parent_on_sigkill(tmp_path):
    proc = _start(tmp_path, "verify", "graefe")
    assert _wait_for(lambda: len(_children(proc.pid)) >= 2)
    workers = _children(proc.pid)
    proc.kill()
    proc.wait()
    assert _wait_for(lambda: not any(_alive(w) for w in workers), seconds=5), "workers outlived their parent"


@needs_proc
def test_ctrl_c_stops_at_once_keeps_finished_checks_and_exits_130(tmp_path):
    proc = _start(tmp_path, "verify", "graefe")
    cache = tmp_path / "cache"
    assert _wait_for(lambda: any(cache.glob("*.json")) and len(_children(proc.pid)) >= 2)
    workers = _children(proc.pid)
    kept = {p.name for p in cache.glob("*.json")}
    sent = time.monotonic()
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=30)
    stopped = time.monotonic() - sent
    assert proc.returncode == 130, err
    assert err == "symfloat: interrupted (finished checks are kept in the cache)\n"
    assert stopped < 5, f"took {stopped:.1f} s to stop"        # not the 16-24 s of waiting for the checks
    assert _wait_for(lambda: not any(_alive(w) for w in workers), seconds=5)
    assert kept <= {p.name for p in cache.glob("*.json")} and _no_temporaries(cache)
    rerun = _start(tmp_path, "verify", "graefe-s1")            # the next run recovers and reads what was kept
    out, err = rerun.communicate(timeout=300)
    assert rerun.returncode == 0 and "printed formulas" in out


def _concurrent_writes(path, tag, n):
    for i in range(n):
        write_if_changed(path, f"{tag} {i}\n" * 2000)


def test_concurrent_writers_leave_one_whole_output(tmp_path):
    out = tmp_path / "errata.md"
    code = "import sys; sys.path.insert(0, {here!r}); from test_files_and_processes import _concurrent_writes; " \
           "_concurrent_writes({out!r}, {tag!r}, 200)"
    procs = [subprocess.Popen([sys.executable, "-c", code.format(here=str(Path(__file__).parent), out=str(out),
                                                                  tag=tag)]) for tag in ("a", "b")]
    assert [p.wait(timeout=120) for p in procs] == [0, 0]
    lines = out.read_text().splitlines()
    assert len(lines) == 2000 and len(set(lines)) == 1 and _no_temporaries(tmp_path)
