"""Shared fixtures: Graefe checked once per session, from scratch.

The library is checked as on a machine a billion times slower than this one
(``SYMFLOAT_SLOWDOWN``): every proof search would stop at once, so the
committed verdicts must rest on replayed certificates alone, which no clock
can change."""
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


@pytest.fixture(scope="session")
def cache_dir(tmp_path_factory):
    """A private, initially empty cache: every derivation is re-checked once."""
    return tmp_path_factory.mktemp("symfloat-cache")


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
def graefe_reports(cache_dir):
    with _infinitely_slow():
        return verify("graefe", cache=ReportCache(cache_dir))


@pytest.fixture(scope="session")
def all_reports(cache_dir, graefe_reports):
    with _infinitely_slow():
        return verify(None, cache=ReportCache(cache_dir))


@pytest.fixture(scope="session")
def reports_by_id(all_reports):
    """The report of every derivation, checked once per session, by id."""
    return {r.id: r for r in all_reports}
