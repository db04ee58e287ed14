r"""The typeset name of every symbol: the TeX a reader sees for a SymPy symbol of a derivation.

A derivation names a symbol for the reader where it makes it::

    tl45 = symbol("tanvarphi_lim45", r"\tan\varphi_{\lim 45}")

Every other symbol's name is translated by rule (:func:`tex_name`), so that a name written for the
program reads as the mathematics it stands for:

- a function and its power before the base, ``tan^2varphi_1`` -> ``\tan^{2}\varphi_{1}``,
  ``tanvarphi_lim45`` -> ``\tan\varphi_{\lim 45}``;
- a letter with digits, ``Q60`` -> ``Q_{60}``; a word tag after a hyphen is a superscript in words,
  ``Q60-lower`` -> ``Q_{60}^{\text{lower}}``;
- Greek names anywhere, ``S_omegac`` -> ``S_{\omega c}``, ``T_1(omega)`` -> ``T_{1}(\omega)``; ``lim``,
  ``max``, ``min`` as operators; a word of three letters or more in an index upright,
  ``L_bot`` -> ``L_{\text{bot}}``.

A name that is TeX already (a backslash, ``|`` or ``#`` in it) keeps SymPy's own printing.
:func:`latex` is :func:`sympy.latex` with these names; the library prints every formula with it.
"""
from __future__ import annotations

import re

import sympy as sp

__all__ = ["symbol", "tex_name", "latex", "GREEK"]

GREEK = ("alpha beta gamma delta epsilon varepsilon zeta eta theta vartheta iota kappa lambda mu nu xi pi varpi "
         "rho varrho sigma varsigma tau upsilon phi varphi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma "
         "Upsilon Phi Psi Omega").split()
_FUNCTIONS = {"sin": r"\sin", "cos": r"\cos", "tan": r"\tan", "cot": r"\cot", "tg": r"\operatorname{tg}",
              "cotg": r"\operatorname{cotg}", "sec": r"\sec", "csc": r"\csc", "log": r"\log", "ln": r"\ln",
              "lim": r"\lim", "max": r"\max", "min": r"\min"}
_NAMED: dict[str, str] = {}         # name -> TeX, as the derivations give them

_ALTERNATIVES = "|".join(sorted([*GREEK, *_FUNCTIONS], key=len, reverse=True))
_TOKEN = re.compile(rf"({_ALTERNATIVES})(?![a-z])|({_ALTERNATIVES})|([A-Za-z]+)|(\d+)|(.)")
_PREFIX = re.compile(r"(sin|cos|tan|cot|tg|cotg)(?:\^?(\d+))?(?=[A-Za-z])")
_GROUP = re.compile(r"([_^])(\{[^{}]*\}|[^_^]+)")


def symbol(name: str, tex: str, **assumptions) -> sp.Symbol:
    """The symbol *name*, typeset as *tex* wherever the library prints it.

    >>> latex(2 * symbol("tanvarphi_lim45", r"\\tan\\varphi_{\\lim 45}"))
    '2 \\\\tan\\\\varphi_{\\\\lim 45}'
    """
    if _NAMED.setdefault(name, tex) != tex:
        raise ValueError(f"the symbol {name!r} is typeset {_NAMED[name]!r} already, not {tex!r}")
    return sp.Symbol(name, **assumptions)


def _piece(text: str, index: bool) -> str:
    """A run of a name as TeX: Greek names and functions as commands; in an index (*index*), a word of
    three letters or more upright."""
    out = []
    for m in _TOKEN.finditer(text):
        word = m.group(1) or m.group(2)
        if word:
            out.append(_FUNCTIONS.get(word) or "\\" + word)
            out.append(" ")
        elif m.group(3):
            w = m.group(3)
            out.append(rf"\text{{{w}}}" if index and len(w) >= 3 and w.islower() else w)
        else:
            out.append(m.group(0))
    return "".join(out).strip()


def tex_name(name: str) -> str | None:
    r"""The TeX of the symbol *name*: as a derivation named it, else by the rules above; None where the
    name is TeX already (SymPy prints it).

    >>> tex_name("tan^2varphi_1"), tex_name("Q60-lower"), tex_name("T_1(omega)")
    ('\\tan^{2}\\varphi_{1}', 'Q_{60}^{\\text{lower}}', 'T_{1}(\\omega)')
    """
    if name in _NAMED:
        return _NAMED[name]
    if re.search(r"[\\|#]", name):
        return None
    call = re.fullmatch(r"(.+?)\(([^()]*)\)", name)
    if call:
        return f"{tex_name(call.group(1))}({_piece(call.group(2), False)})"
    tag = re.fullmatch(r"(.+?)-([a-z]{2,})", name)
    name, sups = (tag.group(1), [rf"\text{{{tag.group(2)}}}"]) if tag else (name, [])
    prefix = _PREFIX.match(name)
    head_tex = ""
    if prefix:
        head_tex = _FUNCTIONS[prefix.group(1)] + (f"^{{{prefix.group(2)}}}" if prefix.group(2) else "")
        name = name[prefix.end():]
    head = re.match(r"[^_^]*", name).group(0)
    subs, found = [], []
    for m in _GROUP.finditer(name, len(head)):
        found.append((m.group(1), m.group(2).strip("{}")))
    numbered = re.fullmatch(r"([A-Za-z])(\d+)", head)
    if numbered and not any(op == "_" for op, _ in found):
        head, subs = numbered.group(1), [numbered.group(2)]
    subs += [_piece(g, True) for op, g in found if op == "_"]
    sups = [_piece(g, True) for op, g in found if op == "^"] + sups
    body = _piece(head, False)
    out = head_tex + (body if not head_tex or body.startswith("\\") else " " + body)
    if subs:
        out += "_{" + " ".join(subs) + "}"
    if sups:
        out += "^{" + ",".join(sups) + "}"
    return out


def _symbols(expr) -> set:
    try:
        return expr.atoms(sp.Symbol)
    except AttributeError:          # a number, a string
        return set()


def latex(expr, **settings) -> str:
    """:func:`sympy.latex` of *expr* with every symbol under its typeset name."""
    names = {s: t for s in _symbols(expr) if (t := tex_name(s.name)) is not None}
    return sp.latex(expr, symbol_names=names, **settings)
