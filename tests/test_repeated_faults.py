"""Every place of a repeated fault listed (issue 31, item 3): a fault printed in several places is one
erratum with all its places.  For every erratum, each occurrence of its fault in the transcription (its
``fault`` words, else its whole excerpt) must stand in the text its quote's locator names or in the text
of one of its ``places``; a locator that names no place (a formula's short name) accounts for one
occurrence each."""
from __future__ import annotations

import re

import pytest

from symfloat import registry
from symfloat.model.locator import region
from symfloat.model.source import get_source

def unlisted(source: str, fault: str, locators) -> list[int]:
    """Offsets of the occurrences of *fault* that no locator of *locators* accounts for."""
    text = get_source(source).text()
    regions = [region(source, loc) for loc in locators]
    spare = sum(r is None for r in regions)
    out = [m.start() for m in re.finditer(re.escape(fault), text)
           if not any(r is not None and r[0] <= m.start() < r[1] for r in regions)]
    return out[spare:]


def test_every_place_of_a_fault_is_listed():
    left = {}
    for did in registry.ids():
        source = registry.manifest(did).source
        text = get_source(source).text()
        for printed in (p for p in registry.statements(did).printed if p.erratum is not None):
            places = unlisted(source, printed.erratum.fault or printed.excerpt, (printed.locator, *printed.erratum.places))
            if places:
                left[f"{did}/{printed.name}"] = [text.count("\n", 0, o) + 1 for o in places]
    assert left == {}, "faults printed at these lines too, neither listed nor judged"


def test_an_unlisted_place_is_found():
    # the metacentre lesson calls a 'Mittlere Länge' at eight places (symfloat/sources/003_02a33f8f897eb570.txt,
    # lines 155, 168, 243, 540, 578, 616, 677, 683); the first place alone accounts for one of them
    assert len(unlisted("metazentrum", "der Mittlere Länge des Parallelepipeds", ("Modell eines Schiffsrumpfes",))) == 7


def test_an_objection_comes_with_its_answer():
    from symfloat import Erratum
    with pytest.raises(ValueError, match="objection needs its answer"):
        Erratum("misprint", "low", "x", "why", objection="the author's convention")
    e = Erratum("misprint", "low", "x", "why", objection="the author's convention", answer="he uses it nowhere else")
    assert (e.objection, e.answer) == ("the author's convention", "he uses it nowhere else")
