"""Graefe 1866 in full: every displayed formula quoted and judged, every
verified one witnessed, and the errata found pinned with their provenance."""
import re

import pytest

from symfloat.model.source import SOURCES

DISPLAYS = re.findall(r"\$\$.+?\$\$", SOURCES["graefe"].text(), re.S)


@pytest.fixture(scope="module")
def formulas(graefe_reports):
    return [f for r in graefe_reports for f in r.formulas]


def test_the_source_has_the_displays_we_expect():
    assert len(DISPLAYS) > 80


def test_every_displayed_formula_is_quoted_and_judged(formulas):
    missing = [d for d in DISPLAYS if not any(d in f.excerpt or f.excerpt in d for f in formulas)]
    assert missing == []
    assert all(f.verdict in ("verified", "erratum", "unverifiable") for f in formulas)


def test_every_verified_display_carries_two_witness_records(formulas):
    thin = [f.id for f in formulas if f.verdict == "verified" and f.excerpt.startswith("$$")
            and len(f.numeric) < 2]
    assert thin == []
    for f in formulas:
        for rec in f.numeric:
            assert rec["seconds"] >= 0 and rec["abs_error"] >= 0 and rec["rel_error"] >= 0


def test_no_check_fails(graefe_reports):
    assert [m for r in graefe_reports for m in r.failures] == []


def test_lost_text_is_unverifiable_with_its_reason(formulas):
    lost = [f for f in formulas if f.verdict == "unverifiable"]
    assert lost and all(f.reason.startswith("text lost in the transcription") for f in lost)
