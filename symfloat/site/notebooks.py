"""The executed notebooks as the site shows them: the committed cells and outputs, unexecuted.

What is added to the staged copy (nothing is changed): after the title, links to the pictures that draw
the derivation's printed formulas (:mod:`.figures`); a MyST target before each printed formula's
heading (an anchor the edition and the errata link to), the quotations (``> excerpt``) shown as the
transcription shows them, and the fractions a note writes in TeX without dollars (``\\frac{a}{b}``
in a line ``Note: ...``) put between dollars, so that they are rendered.  A quotation is an excerpt verbatim, and an excerpt may begin or
end inside a formula (its dollars then do not pair up); found in the transcription, it is widened to
whole math spans and rendered like the edition, typeset included.  A correction in words that the notebook
displayed as one formula (``$$ $a$ if ... $$``) is shown as the words it is.  The symbols are shown as the
notebook wrote them: under their typeset names (:mod:`symfloat.model.symbol_names`).
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
_WORDS_DISPLAYED = re.compile(r"(?m)^\$\$ ([^\n]*\$[^\n]*) \$\$$")      # a correction in words with its own dollars


def _dequote(block: str) -> str:
    return "\n".join(line[2:] if line.startswith("> ") else line[1:] for line in block.rstrip("\n").split("\n"))


def _quotation(match: re.Match, text: str) -> str:
    excerpt = _dequote(match.group(0))
    if not excerpt.strip() or excerpt not in text:
        return match.group(0)
    [(a, b, _)] = quotes(text, [{"id": "quotation", "printed": excerpt}])
    html = excerpt_html(text[a:b]).strip()
    return "````{raw} html\n<blockquote class=\"printed\">\n" + html + "\n</blockquote>\n````\n"


def _dollar_fractions(line: str) -> str:
    """A note's ``\\frac{..}{..}`` outside dollars, between dollars.

    >>> _dollar_fractions(r"Note: rebuilt: N = \\frac{4n}{(2+4n)}, and $\\frac{a}{b}$.")
    'Note: rebuilt: N = $\\\\frac{4n}{(2+4n)}$, and $\\\\frac{a}{b}$.'
    """
    out, pos = [], 0
    for m in re.finditer(r"\\frac\{", line):
        if m.start() < pos or line[:m.start()].count("$") % 2:
            continue
        end, groups, depth = m.end() - 1, 0, 0
        while end < len(line) and groups < 2:
            depth += {"{": 1, "}": -1}.get(line[end], 0)
            if depth == 0 and line[end] == "}":
                groups += 1
                if groups < 2 and line[end + 1:end + 2] != "{":
                    break
            end += 1
        if groups == 2:
            out += [line[pos:m.start()], "$", line[m.start():end], "$"]
            pos = end
    return "".join(out) + line[pos:]


def staged_notebook(path: Path, records: Records, derivation: str, text: str, pictures=()) -> str:
    """The notebook at *path* with its formula targets and rendered quotations; *text* is the
    transcription its derivation quotes, *pictures* the pictures (:class:`.figures.Picture`) to link."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    if pictures:
        links = ", ".join(f"{{ref}}`{p.title} <{p.name}>`" for p in pictures)
        nb["cells"].insert(1, {"cell_type": "markdown", "id": "symfloat-site-pictures", "metadata": {},
                               "source": f"In pictures: {links}."})
    anchors = {c.cell for fid, c in records.cells.items() if fid.startswith(derivation + "/")}
    for cell in nb["cells"]:
        for output in cell.get("outputs", ()):
            if "text/markdown" in output.get("data", {}):
                output["data"]["text/markdown"] = _WORDS_DISPLAYED.sub(r"\1", "".join(output["data"]["text/markdown"]))
        if cell["cell_type"] != "markdown":
            continue
        source = _QUOTE.sub(lambda m: _quotation(m, text), "".join(cell["source"]))
        source = re.sub(r"(?m)^Note: .*$", lambda m: _dollar_fractions(m.group(0)), source)
        if cell.get("id") in anchors:
            source = f"({cell_label(derivation, cell['id'])})=\n" + source
        cell["source"] = source
    return json.dumps(nb, ensure_ascii=False, indent=1) + "\n"
