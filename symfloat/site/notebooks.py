"""The executed notebooks as the site shows them: the committed cells and outputs, unexecuted.

Two things are added to the staged copy, none changed: a MyST target before each printed formula's
heading (an anchor the edition and the errata link to), and the quotations (``> excerpt``) shown
as the transcription shows them.  A quotation is an excerpt verbatim, and an excerpt may begin or
end inside a formula (its dollars then do not pair up); found in the transcription, it is widened to
whole math spans and rendered like the edition, MathML included.
"""
from __future__ import annotations

import json
import re
from pathlib import Path

from .edition import cell_label, quotes
from .records import Records
from .text import excerpt_html

__all__ = ["staged_notebook"]

_QUOTE = re.compile(r"(?m)^(?:>.*(?:\n|$))+")


def _dequote(block: str) -> str:
    return "\n".join(line[2:] if line.startswith("> ") else line[1:] for line in block.rstrip("\n").split("\n"))


def _quotation(match: re.Match, text: str) -> str:
    excerpt = _dequote(match.group(0))
    if not excerpt.strip() or excerpt not in text:
        return match.group(0)
    [(a, b, _)] = quotes(text, [{"id": "quotation", "printed": excerpt}])
    html = excerpt_html(text[a:b]).strip()
    return "````{raw} html\n<blockquote class=\"printed\">\n" + html + "\n</blockquote>\n````\n"


def staged_notebook(path: Path, records: Records, derivation: str, text: str) -> str:
    """The notebook at *path* with its formula targets and rendered quotations; *text* is the
    transcription its derivation quotes."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    anchors = {c.cell for fid, c in records.cells.items() if fid.startswith(derivation + "/")}
    for cell in nb["cells"]:
        if cell["cell_type"] != "markdown":
            continue
        source = "".join(cell["source"])
        source = _QUOTE.sub(lambda m: _quotation(m, text), source)
        if cell.get("id") in anchors:
            source = f"({cell_label(derivation, cell['id'])})=\n" + source
        cell["source"] = source
    return json.dumps(nb, ensure_ascii=False, indent=1) + "\n"
