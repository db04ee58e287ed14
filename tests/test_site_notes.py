"""A formula's note as the site writes it, without Sphinx or a browser: every note carries a permalink
to itself (as the DLMF gives each equation one).

Expected values come from the committed records (docs/verification.json, docs/errata.json)."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from symfloat.site import typeset
from symfloat.site.edition import formula_anchor, note
from symfloat.site.records import load_records

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def records():
    try:
        typeset.katex_dist()
    except typeset.TypesetterMissing as exc:
        pytest.skip(str(exc))
    return load_records(ROOT / "docs", ROOT / "notebooks")


@pytest.mark.parametrize("fid", ["scheeffer-vi-cf/81a", "scheeffer-vi-cf/78c", "graefe-s1-prismatoid-volume/"])
def test_every_note_carries_a_permalink_to_itself(records, fid):
    # a verified formula, an erratum and the first formula of another source: each links to its own note
    f = records.formula(fid) if not fid.endswith("/") else next(f for f in records.formulas
                                                                  if f["id"].startswith(fid))
    shown = note(f, records, "../")
    own = re.match(r'<details class="note [^"]+" id="([^"]+)">', shown).group(1)
    assert own == formula_anchor(f["id"])
    summary = shown[shown.index("<summary>"):shown.index("</summary>")]
    assert re.findall(r'<a class="permalink" href="#([^"]+)"', summary) == [own]
