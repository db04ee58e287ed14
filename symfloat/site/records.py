"""The committed records the site is built from, read once: verdicts, errata, notebook sections.

The site computes nothing: it shows ``docs/verification.json`` (every printed formula's verdict,
evidence and witnesses), ``docs/errata.json`` and the executed notebooks as the main job wrote
them.  From a notebook it takes, per printed formula, the id of the cell that presents it (an
anchor for links) and its reading as printed (the first display after "Read as printed:").
"""
from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["Records", "load_records", "slug", "FormulaCell"]

_CHECK = re.compile(r"""^view\.formula\((['"])(?P<name>.+?)\1\)\s*$""")
_READING = re.compile(r"Read as printed:\s*\$\$(?P<tex>.+?)\$\$", re.S)


def slug(text: str) -> str:
    """A file or anchor name: lower-case letters, digits and single hyphens.

    >>> slug("scheeffer-(78c)-1"), slug("graefe-s4-ship-centroid/§4 sphere, two bases")
    ('scheeffer-78c-1', 'graefe-s4-ship-centroid-4-sphere-two-bases')
    """
    return re.sub(r"-{2,}", "-", re.sub(r"[^a-z0-9]+", "-", text.lower())).strip("-")


@dataclass(frozen=True)
class FormulaCell:
    """Where a notebook presents a printed formula: the markdown cell's id and the reading shown there."""

    cell: str
    reading: str | None


@dataclass
class Records:
    """Everything the site shows, in the records' own order."""

    formulas: list[dict]                    # docs/verification.json "formulas"
    summary: dict                           # docs/verification.json "summary"
    errata: list[dict]                      # docs/errata.json
    notebooks: dict[str, Path]              # derivation id -> executed notebook
    cells: dict[str, FormulaCell] = field(default_factory=dict)     # formula id -> its notebook cell
    reports: tuple = ()                     # Markdown documents the derivations provide, present and shown

    def formula(self, fid: str) -> dict:
        return self._by_id[fid]

    def __post_init__(self):
        self._by_id = {f["id"]: f for f in self.formulas}
        self.erratum_of = {e["formula"]: e for e in self.errata}


def formula_cells(derivation: str, notebook: dict) -> dict[str, FormulaCell]:
    """Formula id -> the markdown cell that presents it in *notebook*: the cell whose metadata
    ``symfloat.formula`` names it, or (a notebook written before the cells were SymPy) the markdown cell
    before its ``view.formula(NAME)`` check."""
    found, previous = {}, None
    for cell in notebook["cells"]:
        source = "".join(cell["source"])
        m = _CHECK.match(source.strip()) if cell["cell_type"] == "code" else None
        name = cell.get("metadata", {}).get("symfloat", {}).get("formula") if cell["cell_type"] == "markdown" \
            else None
        shown = cell if name else previous if m else None
        if shown is not None:
            r = _READING.search("".join(shown["source"]))
            found[f"{derivation}/{name or m['name']}"] = FormulaCell(shown["id"], r["tex"].strip() if r else None)
        if cell["cell_type"] == "markdown":
            previous = cell
    return found


def load_records(docs: Path, notebooks: Path) -> Records:
    """The records under *docs* and the notebooks under *notebooks* (one per derivation)."""
    record = json.loads((docs / "verification.json").read_text(encoding="utf-8"))
    errata = json.loads((docs / "errata.json").read_text(encoding="utf-8"))
    books = {d: notebooks / f"{d}.ipynb" for d in dict.fromkeys(f["derivation"] for f in record["formulas"])
             if (notebooks / f"{d}.ipynb").is_file()}
    records = Records(record["formulas"], record["summary"], errata, dict(sorted(books.items())))
    for d, path in records.notebooks.items():
        records.cells.update(formula_cells(d, json.loads(path.read_text(encoding="utf-8"))))
    return records
