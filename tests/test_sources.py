"""The shipped transcriptions are the project's sources, byte for byte."""
from pathlib import Path

import pytest

from symfloat.model.source import SOURCES, _source
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


def test_sources_are_found_from_their_metadata_files():
    # the five sources of shared/sources/INDEX.md, in its order, each found from <key>.source.json
    assert list(SOURCES) == ["scheeffer", "graefe", "euler", "metazentrum", "hasab"]
    assert SOURCES["euler"].locators == "the paragraph, e.g. §216"      # INDEX.md, numbering conventions
    # the sections' headings come from the metadata files too (Scheeffer's "# IX." lines)
    assert SOURCES["scheeffer"].sections and not SOURCES["hasab"].sections


@pytest.mark.parametrize("change, message", [
    (lambda m: m.pop("locators"), "the fields must be"),
    (lambda m: m.update(extra="x"), "the fields must be"),
    (lambda m: m.update(sections="^(#"), "sections is not a regular expression"),
    (lambda m: m.update(sections="^#+ [IVX]+"), "in one group"),
    (lambda m: m.update(year="1902"), "year has the wrong type"),
    (lambda m: m.update(key="other"), "must be named after its key"),
    (lambda m: m.update(file="missing.txt"), "no transcription missing.txt"),
])
def test_a_malformed_metadata_file_is_refused(change, message):
    meta = {"key": "hasab", "author": "(solved problem)", "title": "t", "year": None, "language": "Hungarian",
            "file": SOURCES["hasab"].filename, "locators": "the heading"}
    assert _source("hasab.source.json", meta).key == "hasab"
    change(meta)
    with pytest.raises(ValueError, match=message):
        _source("hasab.source.json", meta)


def test_every_numbered_section_of_scheeffer_is_found():
    # the scan sets "VIII." as a line of its own, without the heading marks of the other nine; the edition's
    # navigation lacked section VIII (its errata are cited "Scheeffer, VIII") until the pattern took both
    from symfloat.report.labels import sections
    assert [name for _, name in sections("scheeffer")[1:]] == ["I", "II", "III", "IV", "V", "VI", "VII", "VIII", "IX", "X"]
