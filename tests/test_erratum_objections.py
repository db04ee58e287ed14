"""Every erratum against its strongest objection (issue 31, item 1): in the sources whose errata have been
defended, each erratum states the best case that the print is right and the answer to it."""
from __future__ import annotations

import re

import pytest

from symfloat import registry

# every source of the library: all 182 errata have been held against their objections (the third pass)
DEFENDED = sorted({registry.manifest(did).source for did in registry.ids()})


@pytest.mark.parametrize("source", DEFENDED)
def test_every_erratum_of_a_defended_source_states_its_objection_and_answer(source):
    errata = {f"{did}/{p.name}": p.erratum for did in registry.ids() if registry.manifest(did).source == source
              for p in registry.statements(did).printed if p.erratum is not None}
    assert errata and [f for f, e in errata.items() if not (e.objection and e.answer)] == []


# a word of the prose inside a formula is typeset as italic letters run together ("tan φ₁ upto 2√3bs")
_MATH = re.compile(r"\$([^$]+)\$")
_WORD = re.compile(r"(?<![A-Za-z\\])(?:up to|and|for|with|the|is|of|where|than)(?![A-Za-z])")


def test_an_erratum_keeps_its_words_outside_its_formulas():
    inside = [(f"{did}/{p.name}", field, m.group(0))
              for did in registry.ids() for p in registry.statements(did).printed if p.erratum is not None
              for field in ("evidence", "objection", "answer")
              for m in _MATH.finditer(getattr(p.erratum, field))
              if _WORD.search(re.sub(r"\\(?:text|mathrm|operatorname)\{[^}]*\}", "", m.group(1)))]
    assert inside == []
