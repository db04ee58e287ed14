"""The shipped transcriptions are the project's sources, byte for byte."""
from pathlib import Path

import pytest

from symfloat.model.source import SOURCES
from symfloat.registry import load, select

SHARED = Path(__file__).resolve().parents[2] / "shared" / "sources"


@pytest.mark.skipif(not SHARED.is_dir(), reason="no shared/sources beside the checkout")
@pytest.mark.parametrize("key", sorted(SOURCES))
def test_shipped_copy_is_identical(key):
    src = SOURCES[key]
    assert src.text() == (SHARED / src.filename).read_text(encoding="utf-8")


@pytest.mark.skipif(not SHARED.is_dir(), reason="no shared/sources beside the checkout")
def test_index_lists_exactly_the_known_sources():
    index = (SHARED / "INDEX.md").read_text(encoding="utf-8")
    rows = [line.split("|") for line in index.splitlines() if line.startswith("| `")]
    assert {r[1].strip(" `"): r[2].strip(" `") for r in rows} == {k: s.filename for k, s in SOURCES.items()}


def test_every_excerpt_is_verbatim_and_named_once():
    for did in select():
        d, _ = load(did)
        names = [p.name for p in d.printed]
        assert len(names) == len(set(names))
        for p in d.printed:
            assert SOURCES[d.source].contains(p.excerpt), (did, p.name)
