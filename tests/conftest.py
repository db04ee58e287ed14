"""Shared fixtures: Graefe checked once per session, from scratch.

The library is checked as on a machine a billion times slower than this one
(``SYMFLOAT_SLOWDOWN``): every proof search would stop at once, so the
committed verdicts must rest on replayed certificates alone, which no clock
can change.

A test run reads no cache it did not write: its cache (:func:`cache_dir`) is a folder of this run's
temporary directory, which pytest makes anew for every run (and empties first when ``--basetemp``
names it), and ``SYMFLOAT_CACHE`` points there for the whole run, so that a command a test runs
without naming a cache, in this process or a subprocess, cannot read the checkout's
``.symfloat-cache`` or one the environment named."""
import os
from contextlib import contextmanager

import mpmath
import pytest

from symfloat.engine.cache import ReportCache
from symfloat.engine.runner import verify


@pytest.fixture(autouse=True)
def _restore_mpmath_precision():
    dps = mpmath.mp.dps
    yield
    mpmath.mp.dps = dps


# Under pytest-xdist (``-n 2``, the README's test command) the test workers check the derivations together:
# each takes the ones no other worker has taken, into one cache they share (``verify(share=True)``).
XDIST = "PYTEST_XDIST_WORKER" in os.environ


@pytest.fixture(scope="session")
def cache_dir(tmp_path_factory):
    """An initially empty cache, private to this test run: every derivation is re-checked once."""
    if XDIST:
        shared = tmp_path_factory.getbasetemp().parent / "symfloat-cache"
        shared.mkdir(exist_ok=True)
        return shared
    return tmp_path_factory.mktemp("symfloat-cache")


@pytest.fixture(scope="session", autouse=True)
def _the_runs_own_cache(cache_dir):
    """``SYMFLOAT_CACHE`` is the run's cache while the tests run (see the module docstring)."""
    old = os.environ.get("SYMFLOAT_CACHE")
    os.environ["SYMFLOAT_CACHE"] = str(cache_dir)
    yield
    if old is None:
        os.environ.pop("SYMFLOAT_CACHE", None)
    else:
        os.environ["SYMFLOAT_CACHE"] = old


def _verify(selector, cache_dir):
    if XDIST:
        return verify(selector, cache=ReportCache(cache_dir), workers=1, share=True)
    return verify(selector, cache=ReportCache(cache_dir))


@contextmanager
def _infinitely_slow():
    old = os.environ.get("SYMFLOAT_SLOWDOWN")
    os.environ["SYMFLOAT_SLOWDOWN"] = "1e9"
    try:
        yield
    finally:
        if old is None:
            os.environ.pop("SYMFLOAT_SLOWDOWN")
        else:
            os.environ["SYMFLOAT_SLOWDOWN"] = old


@pytest.fixture(scope="session")
def check(cache_dir):
    """``check(selector)``: the reports of the derivations *selector* picks, checked as ``all_reports`` checks
    them (into the session's cache, certificates replayed, no proof search)."""
    def checked(selector):
        with _infinitely_slow():
            return _verify(selector, cache_dir)
    return checked


@pytest.fixture(scope="session", autouse=True)
def _derivations_checked_by_both_workers(request, cache_dir):
    """In a run of the whole suite on test workers, every worker first checks the derivations together with
    the others (each takes the ones no other has taken), so that no worker waits on a long serial chain of
    checks that another started for one test file; their tests then read the shared cache."""
    if XDIST and len({item.path for item in request.session.items}) >= 10:
        with _infinitely_slow():
            _verify(None, cache_dir)


@pytest.fixture(scope="session")
def graefe_reports(cache_dir):
    with _infinitely_slow():
        return _verify("graefe", cache_dir)


@pytest.fixture(scope="session")
def all_reports(cache_dir, graefe_reports):
    with _infinitely_slow():
        return _verify(None, cache_dir)


@pytest.fixture(scope="session")
def reports_by_id(all_reports):
    """The report of every derivation, checked once per session, by id."""
    return {r.id: r for r in all_reports}

