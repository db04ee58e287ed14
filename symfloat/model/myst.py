"""Words with their ``$...$`` mathematics as one line of MyST Markdown: a list item or a table cell.

The words' Markdown special characters are escaped and the mathematics is kept for MyST's dollar math,
which the site typesets with KaTeX; in a table cell a formula's ``|`` is written ``\\vert`` (``\\|``
``\\Vert``), since the table's own syntax would split the cell there.
"""
from __future__ import annotations

import re

from .evidence_tex import spans

__all__ = ["inline", "unescaped"]

_MARKDOWN = re.compile(r"([\\`*_{}\[\]<>#|$])")
_ESCAPED = re.compile(r"\\([\\`*_{}\[\]()#+\-.!|>])")       # Markdown's backslash escapes
_BARS = re.compile(r"\\\||\|")


def unescaped(text: str) -> str:
    r"""*text* (Markdown, as the transcriptions are written) without its backslash escapes: ``\*`` is ``*``.

    >>> unescaped(r"Schülen\*) and 3\.")
    'Schülen*) and 3.'
    """
    return _ESCAPED.sub(r"\1", text)


def inline(text: str, limit: int | None = 160, cell: bool = False) -> str:
    """*text* (prose with ``$...$`` or ``$$...$$`` mathematics) as one line of MyST, cut after *limit*
    characters (``None``: never) at the end of a word, never inside a formula, and a formula it begins with shown
    whole; *cell*: for a table cell.

    >>> inline("where $|x| < 1$ and a*b", cell=True)
    'where $\\\\vert x\\\\vert  < 1$ and a\\\\*b'
    >>> inline("the turn about the main axis, which leads back", limit=38)
    'the turn about the main axis, which…'
    """
    out, length = [], 0
    for kind, piece in spans(re.sub(r"\$\$", "$", " ".join(text.split()))):
        room = None if limit is None else limit - length
        if kind == "text":
            if room is not None and len(piece) > room:
                cut = piece[:room] if piece[room].isspace() or " " not in piece[:room] else \
                    piece[:piece.rindex(" ", 0, room)]          # a word is not cut
                return ("".join(out) + _MARKDOWN.sub(r"\\\1", cut)).rstrip() + "…"
            out.append(_MARKDOWN.sub(r"\\\1", piece))
        else:
            if room is not None and len(piece) > room and out:      # never cut; the first shown whole
                return "".join(out).rstrip() + "…"
            if cell:
                piece = _BARS.sub(lambda m: r"\Vert " if m.group(0) == r"\|" else r"\vert ", piece)
            out.append(f"${piece.strip()}$")
        length += len(piece)
    return "".join(out)
