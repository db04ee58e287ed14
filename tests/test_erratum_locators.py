"""Locators that point at the quote (issue 31, item 4): every erratum's locator names the section,
paragraph, subsection, worked example or heading whose text contains its printed excerpt
(:func:`symfloat.model.locator.region`).  A piece without numbered sections may name a formula by a
short name instead of a heading (``sources/INDEX.md``: "the heading or a short name of the formula"),
which names no place; every other locator must resolve."""
from __future__ import annotations

from symfloat import registry
from symfloat.model.locator import region
from symfloat.model.source import get_source

def _errata():
    return [(did, p) for did in registry.ids() for p in registry.statements(did).printed if p.erratum is not None]


def _names_a_place(source: str, locator: str) -> bool:
    return bool(get_source(source).sections) or any(line.strip() == locator
                                                     for line in get_source(source).text().splitlines())


def test_the_locator_of_every_erratum_contains_its_printed_excerpt():
    wrong = []
    for did, printed in _errata():
        source = registry.manifest(did).source
        place = region(source, printed.locator)
        if place is None:
            if _names_a_place(source, printed.locator):
                wrong.append(f"{did}/{printed.name}: {printed.locator!r} resolves to no place")
        elif printed.excerpt not in get_source(source).text()[slice(*place)]:
            wrong.append(f"{did}/{printed.name}: the excerpt is not in {printed.locator!r}")
    assert wrong == []


def test_the_regions_are_the_places_the_locators_name():
    # provenance: the transcriptions themselves (symfloat/sources/); each region opens with its heading, mark
    # or tag, and a locator in the wrong place is caught
    scheeffer, euler = get_source("scheeffer").text(), get_source("euler").text()
    start, end = region("scheeffer", "VI.D")
    assert scheeffer[start:].startswith("#### D. Der Würfel.") and "E. Das n-seitige" not in scheeffer[start:end]
    start, end = region("scheeffer", "(78c)")       # (78c) stands in section VI, which opens with '## VI.'
    assert scheeffer[start:].startswith("## VI.")
    start, end = region("euler", "§218")
    assert euler[start:].startswith("§. 218.") and "§. 219." not in euler[start:end]
    text = get_source("metazentrum").text()          # the closing sentence on e stands in the formula list only
    start, end = region("metazentrum", "Analyse der Stabilitätsbedingung für das Parallelepiped")
    assert text[start:].startswith("Analyse der Stabilit") and "Um sicherzustellen" in text[start:end]
    assert "was größer als eins im Falle einer stabilen Situation" not in text[start:end]
    assert region("hasab", "solution, upright") is None


def test_a_citation_lists_the_places_in_the_texts_order_each_once():
    # sources/INDEX.md's locators as a reader cites them: Scheeffer's (95a) stands before (103a) in section VII
    # although a predictor named it last, a section after its equations, a place named twice once, a heading in
    # quotation marks; a mark of the print stays bare
    from symfloat.model.locator import citation
    assert citation("scheeffer", ["(103a)", "(117)", "(95a)", "(134)", "IX.C", "(103a)"]) == \
        "Scheeffer 1902 (95a), (103a), (117), (134), IX.C"
    assert citation("scheeffer", ["V", "(51)", "IV"]) == "Scheeffer 1902 IV, (51), V"
    assert citation("euler", ["§216", "§200"]) == "Euler 1749 §200, §216"
    assert citation("metazentrum", ["formula list"]) == "Auftrieb Stabilität “formula list”"
