"""The manifest of a derivation package (symfloat/manifest.py): read field by field, refused with one line
naming the file and the fault; and held to what the package's modules declare when it is loaded."""
from __future__ import annotations

import pytest

from symfloat import registry
from symfloat.manifest import ManifestError, read_manifest

GOOD = 'id = "some-text"\nsource = "graefe"\nrequires = ["graefe-s1-prismatoid-volume"]\npredicts = ["box"]\n' \
       '[provides]\nreport = "outputs"\n'


def _package(tmp_path, manifest=GOOD, parts=("statements", "predictors", "outputs")):
    folder = tmp_path / "some_text"
    folder.mkdir()
    (folder / "manifest.toml").write_text(manifest, encoding="utf-8")
    for part in parts:
        (folder / f"{part}.py").write_text("", encoding="utf-8")
    return folder


def test_a_manifest_is_read_field_by_field(tmp_path):
    m = read_manifest(_package(tmp_path))
    assert (m.id, m.source, m.requires, m.predicts, m.provides, m.package) == (
        "some-text", "graefe", ("graefe-s1-prismatoid-volume",), ("box",), {"report": "outputs"}, "some_text")


@pytest.mark.parametrize("change, parts, why", [
    (('id = "some-text"', 'id = "other-text"'), None, "must be named 'other_text'"),
    (('source = "graefe"', 'source = 3'), None, "source must name a source key"),
    (('predicts = ["box"]', 'predicts = ["boat"]'), None, "predicts must be a list of bodies"),
    (('report = "outputs"', 'poster = "outputs"'), None, "unknown kind 'poster'"),
    (('report = "outputs"', 'report = "witnesses"'), None, "provides.report must name a module"),
    (('id = "some-text"', 'id = "some-text"\ntitle = "x"'), None, "unknown fields ['title']"),
    (("", ""), ("statements", "outputs"), "predicts bodies but the package has no predictors.py"),
    (("", ""), ("predictors", "outputs"), "the package has no statements.py"),
])
def test_a_faulty_manifest_is_one_line_naming_the_fault(tmp_path, change, parts, why):
    folder = _package(tmp_path, GOOD.replace(*change) if change[0] else GOOD,
                      parts or ("statements", "predictors", "outputs"))
    with pytest.raises(ManifestError, match=why.replace("(", r"\(").replace("[", r"\[")):
        read_manifest(folder)


def test_every_package_declares_what_its_manifest_says():
    # load() compares the bodies predicted and the kinds provided with the manifest; requires and the
    # source are compared by statements()
    for did in registry.ids():
        d, _ = registry.load(did)
        m = registry.manifest(did)
        assert (d.source, tuple(d.requires)) == (m.source, m.requires)
        assert set(d.predictor.bodies if d.predictor else ()) == set(m.predicts)
        assert set(d.provided) == set(m.provides)
