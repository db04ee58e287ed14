"""The symbols of a committed notebook under their typeset names.

A notebook writes a symbol as SymPy printed it when the notebook was made; a notebook made before
the library typeset the symbol's name (:mod:`symfloat.model.symbol_names`) has SymPy's printing of
the program name, ``tan^{2varphi}_{1}``.  The site writes such a symbol under its typeset name,
``\\tan^{2}\\varphi_{1}``, inside the math spans only, so that every notebook shows what one made
now shows.
"""
from __future__ import annotations

import re
from functools import cache

import sympy as sp

from ..model.claim import expressions
from ..model.symbol_names import tex_name
from ..registry import statements

__all__ = ["renaming", "typeset_names"]

_MATH = re.compile(r"\$\$.+?\$\$|\$[^$\n]+\$", re.S)


def _claims(d):
    for step in d.steps:
        yield step.claim
    for p in d.printed:
        yield p.reading
        yield p.erratum.corrected_reading if p.erratum is not None else None


@cache
def renaming(derivation: str):
    """A function that writes, in the math spans of a Markdown text, the derivation's symbols under their
    typeset names where SymPy's printing of the program name differs (None when none does).  The symbols are
    those of its statements (steps, readings, names): no other module of the package declares any."""
    d = statements(derivation)
    found = {sym for claim in _claims(d) if claim is not None for m in expressions(claim)
             if hasattr(m, "atoms") for sym in m.atoms(sp.Symbol)}
    found |= {sym for sym, _, _ in d.names}
    table = {}
    for sym in found:
        new = tex_name(sym.name)
        if new is not None and new != sp.latex(sym):
            table[sp.latex(sym)] = "{" + new + "}"
    if not table:
        return None
    names = "|".join(map(re.escape, sorted(table, key=len, reverse=True)))
    # not inside a word or after a command's backslash; after a matrix row's double backslash a name begins
    pattern = re.compile(rf"(?<![A-Za-z])(?<!(?<!\\)\\)({names})(?![A-Za-z0-9'])")
    return lambda text: _MATH.sub(lambda math: pattern.sub(lambda m: table[m.group(1)], math.group(0)), text)


def typeset_names(derivation: str, tex: str) -> str:
    """*tex*, a formula of the derivation's notebook, with its symbols under their typeset names."""
    rename = renaming(derivation)
    return rename(f"$${tex}$$")[2:-2] if rename else tex
