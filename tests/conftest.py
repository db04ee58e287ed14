"""Shared fixtures: Graefe checked once per session, from scratch."""
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


@pytest.fixture(scope="session")
def graefe_reports(cache_dir):
    return verify("graefe", cache=ReportCache(cache_dir))


@pytest.fixture(scope="session")
def all_reports(cache_dir, graefe_reports):
    return verify(None, cache=ReportCache(cache_dir))


@pytest.fixture(scope="session")
def reports_by_id(all_reports):
    """The report of every derivation, checked once per session, by id."""
    return {r.id: r for r in all_reports}
