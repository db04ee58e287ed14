"""Printed symbols matched to a derivation's: by canonical name, or as the one symbol that adds an index.

Used where a formula read from the print (:mod:`symfloat.model.latex`) is compared with the derivation's
hand reading: the readings report (:mod:`symfloat.report.readings`, which names the rules) and the
corrections of a refuted print (:mod:`symfloat.engine.print_corrections`).
"""
from __future__ import annotations

import re

import sympy as sp

from .latex import Unreadable, canonical, read

__all__ = ["formula_symbols", "match_symbols"]

_WORDS = re.compile(r"(tan|sin|cos|cot|tg|varphi|varrho|vartheta|phi|rho|theta|omega|alpha|beta|mu|psi|sigma)")


def formula_symbols(hand_symbols) -> dict:
    """Hand symbols whose names read as formulas (``tan^2varphi_1``), with the formula."""
    out = {}
    for s in hand_symbols:
        if not re.search(r"(tan|sin|cos|cot|tg)", s.name):
            continue
        tex = _WORDS.sub(lambda m: "\\" + m.group(1) + " ", s.name)
        try:
            r = read(tex)
        except (Unreadable, ValueError, TypeError, IndexError):
            continue
        if len(r.rows) == 1 and len(r.rows[0][0]) == 1 and not isinstance(r.rows[0][0][0], sp.Symbol):
            out[s] = r.rows[0][0][0]
    return out


def _extends(printed: str, hand: str) -> bool:
    """Whether *hand* is the printed name with an index added (``G`` → ``G_pf``, ``T_1`` → ``T_1n``,
    ``T_1`` → ``T_1^iso``, ``u_m`` → ``u_m'``)."""
    rest = hand[len(printed):]
    return hand.startswith(printed) and bool(rest) and (rest[0] in "_^'" or ("_" in printed and rest.isalnum()))


def match_symbols(auto_symbols, hand_symbols, rules):
    """Map each printed (auto) symbol to the hand symbol it stands for: the same canonical name, else the
    one hand symbol that extends it (longest printed names first)."""
    by_name = {canonical(h.name): h for h in hand_symbols}
    mapping = {a: a if a in hand_symbols else by_name[a.name] for a in auto_symbols
               if a in hand_symbols or a.name in by_name}
    taken = set(mapping.values())
    for a in sorted(set(auto_symbols) - set(mapping), key=lambda a: -len(a.name)):
        indexed = [h for n, h in by_name.items() if h not in taken and _extends(a.name, n)]
        if len(indexed) == 1:
            mapping[a] = indexed[0]
            taken.add(indexed[0])
            rules.add("context-index")
    return mapping
