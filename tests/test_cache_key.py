"""The cache key cannot go stale (issue 28, item 5): it covers a derivation's whole package, the
transcription it quotes and every library module its check executes, found from the imports.

Each test changes the bytes of one file as the key reads it (``symfloat.engine.key._content``) and asserts
exactly which derivations' keys change, the expected set computed independently of the key's own import
search: from the manifests (which source each quotes, which it requires) or from the packages' text."""
from __future__ import annotations

from pathlib import Path

import pytest

from symfloat import registry
from symfloat.engine import key as key_module
from symfloat.engine.runner import derivation_keys
from symfloat.model.source import get_source

LIBRARY = Path(key_module.__file__).resolve().parents[1]


def _keys_with(monkeypatch, changed: Path) -> dict[str, str]:
    """Every derivation's key with the bytes of *changed* altered by one line."""
    real = key_module._content
    monkeypatch.setattr(key_module, "_content",
                        lambda p: real(p) + b"\n# edited\n" if Path(p).resolve() == changed.resolve() else real(p))
    return derivation_keys(registry.ids())


def _with_descendants(ids: set[str]) -> set[str]:
    out = set(ids)
    while True:
        more = {i for i in registry.ids() if set(registry.requires(i)) & out} - out
        if not more:
            return out
        out |= more


def _changed(before, after) -> set[str]:
    return {i for i in before if before[i] != after[i]}


@pytest.mark.parametrize("source", ["hasab", "scheeffer"])
def test_editing_a_transcription_rechecks_exactly_the_derivations_that_quote_it(monkeypatch, source):
    before = derivation_keys(registry.ids())
    transcription = next(p for p in key_module.source_files(source) if p.name == get_source(source).filename)
    after = _keys_with(monkeypatch, transcription)
    expected = _with_descendants({i for i in registry.ids() if registry.manifest(i).source == source})
    assert _changed(before, after) == expected and expected


def test_editing_the_cylinder_slices_rechecks_the_derivations_whose_witnesses_run_them(monkeypatch):
    before = derivation_keys(registry.ids())
    after = _keys_with(monkeypatch, LIBRARY / "geometry" / "cylinder.py")
    # the floating-body witnesses run the cylinder's slices (symfloat.engine.floating_witness imports them)
    running = {i for i in registry.ids()
               if any("floating_witness" in f.read_text(encoding="utf-8") for f in registry.files(i) if f.suffix == ".py")}
    assert "scheeffer-vi-ab" in running
    assert _changed(before, after) == _with_descendants(running)


def test_editing_a_package_file_rechecks_it_and_what_builds_on_it(monkeypatch):
    before = derivation_keys(registry.ids())
    manifest = registry.manifest("metazentrum")
    assert _changed(before, _keys_with(monkeypatch, manifest.folder / "predictors.py")) == \
        _with_descendants({"metazentrum"})


def test_a_module_no_check_executes_is_not_in_any_key(monkeypatch):
    # the site's builder is no part of any check: editing it re-checks nothing
    before = derivation_keys(registry.ids())
    assert _changed(before, _keys_with(monkeypatch, LIBRARY / "site" / "build.py")) == set()
