r"""Mathematics inside the words of an erratum: its evidence, reason, objection and answer.

The convention (``docs/writing-derivations.md``): the words are plain prose, and every piece of
mathematics in them is TeX inline math between single dollars, ``at $\omega = 0$ ($\sin^2 45^\circ =
\tfrac12$)``; a dollar is never used otherwise.  ``docs/errata.md`` keeps the dollars (Markdown math),
the site typesets each span with KaTeX (:func:`spans` cuts the text).  The engine writes its part of the
evidence the same way: a sample point under the symbols' typeset names (:func:`tex_point`) and its
numbers as numbers (:func:`tex_number`).
"""
from __future__ import annotations

import math
import re
from decimal import Decimal, InvalidOperation

from .symbol_names import tex_name

__all__ = ["spans", "tex_number", "tex_point", "tex_error", "shown_value"]

_MATH = re.compile(r"\$([^$]+)\$")
_SHOWN_DIGITS = 10          # significant digits shown of a sampled value (it was computed to 20)


def spans(text: str) -> list[tuple[str, str]]:
    """*text* cut into ``("text", words)`` and ``("math", tex)`` pieces, in order.

    >>> spans("at $s = 1/2$ only")
    [('text', 'at '), ('math', 's = 1/2'), ('text', ' only')]
    """
    out, at = [], 0
    for m in _MATH.finditer(text):
        out += [("text", text[at:m.start()])] if m.start() > at else []
        out.append(("math", m.group(1)))
        at = m.end()
    return out + ([("text", text[at:])] if at < len(text) else [])


def tex_number(text: str) -> str:
    r"""A number as SymPy printed it (an integer, a fraction ``p/q`` or a decimal) as TeX: a fraction as
    ``\tfrac``, a decimal to ten significant digits, in powers of ten when it is very small or large.

    >>> tex_number("-235659137/1993622500"), tex_number("2.0500000000000000000"), tex_number("0.000034332035055300038590")
    ('-\\tfrac{235659137}{1993622500}', '2.05', '3.433203506 \\times 10^{-5}')
    """
    text = text.strip()
    if re.fullmatch(r"-?\d+/\d+", text):
        sign, (p, q) = ("-" if text.startswith("-") else ""), text.lstrip("-").split("/")
        return rf"{sign}\tfrac{{{p}}}{{{q}}}"
    try:
        value = Decimal(text)
    except InvalidOperation:
        raise ValueError(f"not a number: {text!r}") from None
    if value == value.to_integral_value() and "." not in text and "e" not in text.lower():
        return text
    if value == 0:
        return "0"
    exponent = value.adjusted()
    if -3 <= exponent < 6:
        shown = f"{value:.{max(_SHOWN_DIGITS - 1 - exponent, 0)}f}"
        return shown.rstrip("0").rstrip(".") if "." in shown else shown
    mantissa = f"{value.scaleb(-exponent):.{_SHOWN_DIGITS - 1}f}".rstrip("0").rstrip(".")
    return rf"{mantissa} \times 10^{{{exponent}}}"


def tex_error(value: float) -> str:
    r"""A relative error as TeX, two significant digits: ``2.9 \times 10^{-39}``, ``0``.

    >>> tex_error(2.9e-39), tex_error(0.0), tex_error(0.24), tex_error(float("inf"))
    ('2.9 \\times 10^{-39}', '0', '2.4 \\times 10^{-1}', '\\infty')
    """
    if value == 0:
        return "0"
    if math.isinf(value):
        return r"\infty"
    if math.isnan(value):
        return r"\text{not a number}"
    mantissa, exponent = f"{value:.1e}".split("e")
    return rf"{mantissa} \times 10^{{{int(exponent)}}}"


def tex_point(point: dict) -> str:
    r"""A sample point (symbol name -> number, as the identity check records it) as TeX: each symbol under
    its typeset name.

    >>> tex_point({"a": "119/94", "varphi_2": "71/530"})
    'a = \\tfrac{119}{94},\\ \\varphi_{2} = \\tfrac{71}{530}'
    """
    return r",\ ".join(f"{tex_name(name) or name} = {tex_number(value)}" for name, value in point.items())


def shown_value(text: str) -> str:
    r"""A value the identity check recorded, for the words of the evidence: a number as inline TeX, a truth
    value (a relation's, ``true`` or ``false (the failing part)``) as words.

    >>> shown_value("-77/380"), shown_value("false (the second row)")
    ('$-\\tfrac{77}{380}$', 'false (the second row)')
    """
    try:
        return f"${tex_number(text)}$"
    except ValueError:
        return text
