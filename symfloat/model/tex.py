"""Plain comparisons of TeX as the transcriptions write it: no parsing, only layout removed.

``normalise`` drops what changes the look but not the formula (dollars, ``\\displaystyle``,
``\\left``/``\\right``, thin spaces, an equation tag ``\\quad (78c)``, white space, closing
punctuation); ``chains`` cuts a formula into rows and each row into members and relations, so that
a formula can be recognised as a repeat of a quoted one, or of a contiguous part of its chain.
"""
from __future__ import annotations

import re

__all__ = ["normalise", "chains", "is_bare_symbol", "braced_end", "RELATIONS"]

RELATIONS = ("=", "<", ">", r"\leq", r"\geq", r"\le", r"\ge", r"\neq", r"\approx", r"\cong", r"\equiv",
             r"\lessgtr", r"\gtrless", r"\sim")

_LAYOUT = re.compile(r"\\(?:displaystyle|left|right|bigl|bigr|Bigl|Bigr|big|Big|,|;|!|:|qquad|quad)(?![A-Za-z])")
_TAG = re.compile(r"\\quad\s*\(\d+[a-z]?\)|\(\d+[a-z]?\)\s*$")
_ENV = re.compile(r"\\(?:begin|end)\{(?:aligned|align\*?|array|cases|gathered|matrix)\}(?:\{[lcr]*\})?")
_RELATION = re.compile("|".join(re.escape(r) + (r"(?![A-Za-z])" if r[0] == "\\" else "")
                                for r in sorted(RELATIONS, key=len, reverse=True)))
_EDGE_TEXT = re.compile(r"^(?:\\text\{[^{}]*\})+|(?:\\text\{[^{}]*\})+$")

_LETTERLIKE = {
    "alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta", "vartheta", "iota",
    "kappa", "lambda", "mu", "nu", "xi", "pi", "varpi", "rho", "varrho", "sigma", "varsigma", "tau",
    "upsilon", "phi", "varphi", "chi", "psi", "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi",
    "Sigma", "Upsilon", "Phi", "Psi", "Omega", "prime", "overline", "bar", "hat", "tilde", "mathrm",
    "mathit", "mathbf", "text", "ell",
}
_LABEL = re.compile(r"\(\d+[a-z]?\)|\\S\.?\s*\d+\.?|[+-]|\\pm|\\mp|\\int(?:[_^](?:\{[^{}]*\}|\w))?")
_BARE_TOKEN = re.compile(r"\s+|,|[A-Za-zÀ-ž]|'|[{}]|[_^](?:\{[^{}]*\}|[A-Za-z0-9*])|\\([A-Za-z]+)")


def normalise(tex: str) -> str:
    """*tex* without layout: the formula as a compact string.

    >>> normalise(r"$$ z_M = -\\displaystyle\\frac{ d }{2} \\quad (12a)$$")
    'z_M=-\\\\frac{d}{2}'
    """
    s = tex.strip().strip("$")
    s = _TAG.sub("", s)
    s = _LAYOUT.sub("", s)
    s = re.sub(r"\s+", "", s)
    return s.rstrip(".,;:")


def chains(tex: str) -> list[list[str]]:
    """The rows of a formula, each as ``[member, relation, member, ...]`` (relations at brace depth 0).

    >>> chains(r"a &= b + c \\\\ d < e")
    [['a', '=', 'b+c'], ['d', '<', 'e']]
    """
    s = normalise(_ENV.sub(r"\\\\", tex)).replace("&", "")
    rows = []
    for row in re.split(r"\\\\", s):
        row = _EDGE_TEXT.sub("", row).strip(".,;:")
        if not row:
            continue
        parts, depth, last, i = [], 0, 0, 0
        while i < len(row):
            ch = row[i]
            depth += (ch == "{") - (ch == "}")
            m = _RELATION.match(row, i) if depth == 0 else None
            if m:
                parts += [row[last:i], m.group(0)]
                last = i = m.end()
                continue
            i += 1
        rows.append(parts + [row[last:]])
    return rows


def is_bare_symbol(tex: str) -> bool:
    """True for a single symbol or label, or a list of them (``S_1``, ``\\varphi``, ``A, B``, ``V_3 e``):
    letters, indices and letter-like commands only, no operator, relation or number; or a label
    alone: an equation number ``(135b)``, a paragraph ``\\S. 234.``, a sign or an integral sign
    named in the text (``signum $+$``, ``$\\int_1$``).

    >>> [is_bare_symbol(t) for t in ("$S_1$", r"$\\overline{OF}$", "$x^2$", "$2a$", "$a = b$", "$$(135b)$$")]
    [True, True, False, False, False, True]
    """
    s = _LAYOUT.sub("", tex.strip().strip("$")).strip().rstrip(",;:")
    if _LABEL.fullmatch(s):
        return True
    s = s.rstrip(".")
    if not s:
        return False
    pos = 0
    while pos < len(s):
        m = _BARE_TOKEN.match(s, pos)
        if not m or (m.group(1) and m.group(1) not in _LETTERLIKE):
            return False
        if m.group(0)[0] == "^" and not re.fullmatch(r"\^\{?(?:\\prime|'+|\*|[0-9]+|[A-Za-z]+)\}?", m.group(0)):
            return False
        if m.group(0)[0] == "^" and re.fullmatch(r"\^\{?[0-9]+\}?", m.group(0)) and m.group(0) not in ("^1", "^{1}"):
            return False
        pos = m.end()
    return True


def braced_end(tex: str, at: int) -> int:
    """The index after the brace group opening at *at* (``-1`` when it does not close).

    >>> braced_end(r"\\frac{a}{b}", 5), braced_end("{a{b}", 0)
    (8, -1)
    """
    depth = 0
    for j in range(at, len(tex)):
        depth += {"{": 1, "}": -1}.get(tex[j], 0)
        if depth == 0:
            return j + 1
    return -1
