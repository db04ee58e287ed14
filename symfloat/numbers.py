"""Numbers as a reader writes them: ``1.9 × 10⁻¹⁶`` and ``10⁻¹²``, not a program's ``1.9e-16``, in the tables of
the notebooks, the site and ``docs/numerics.md`` (Unicode superscripts: light in a table of thousands of cells, read
alike on GitHub and in the site)."""
from __future__ import annotations

import math
import re

__all__ = ["scientific", "written", "duration", "counted", "steps_in_words", "method_words", "signs"]

_SUPERSCRIPTS = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def _power(mantissa: str, exponent: int) -> str:
    if exponent == 0:
        return mantissa
    power = "10" + str(exponent).translate(_SUPERSCRIPTS)
    return power if mantissa == "1" else "-" + power if mantissa == "-1" else f"{mantissa} × {power}"


def scientific(x: float, digits: int = 2) -> str:
    """*x* to *digits* significant digits as a reader writes it, with a power of ten where it has one.

    >>> scientific(1.234e-15), scientific(-0.5, 1), scientific(2.5), scientific(0.0), scientific(math.inf)
    ('1.2 × 10⁻¹⁵', '-5 × 10⁻¹', '2.5', '0', '∞')
    """
    if x == 0:
        return "0"
    if not math.isfinite(x):
        return "∞" if x > 0 else "-∞" if x < 0 else "undefined"
    mantissa, exponent = f"{x:.{digits - 1}e}".split("e")
    return _power(mantissa, int(exponent))


def written(x: float) -> str:
    """A float as Python writes it shortest (the digits that tell it from its neighbours), its power of ten as a
    reader writes it.

    >>> written(1e-12), written(1 - 1e-16), written(0.75), written(1.5e-8), written(1.0000000000000004e-05)
    ('10⁻¹²', '0.9999999999999999', '0.75', '1.5 × 10⁻⁸', '1.0000000000000004 × 10⁻⁵')
    """
    text = repr(float(x))
    if "e" not in text:
        return text
    mantissa, exponent = text.split("e")
    return _power(mantissa, int(exponent))


def duration(seconds: float) -> str:
    """A time to three significant digits in the unit that keeps it a plain number.

    >>> duration(5.47e-05), duration(0.00388), duration(2.345), duration(123.4)
    ('54.7 µs', '3.88 ms', '2.35 s', '123 s')
    """
    for unit, scale in (("s", 1), ("ms", 1e-3)):
        if seconds >= scale:
            return f"{seconds / scale:.3g} {unit}"
    return f"{seconds * 1e6:.3g} µs"


def counted(n, noun: str, plural: str = "") -> str:
    """*n* with its noun, singular for one.

    >>> counted(1, "case"), counted(3, "case"), counted(1, "erratum", "errata"), counted(0, "erratum", "errata")
    ('1 case', '3 cases', '1 erratum', '0 errata')
    """
    return f"{n} {noun if n == 1 else plural or noun + 's'}"


def steps_in_words(steps: dict) -> str:
    """A derivation's steps counted by status (status -> number), the most first.

    >>> steps_in_words({"applied": 6, "definition": 15, "proved": 26, "sampled": 1})
    '26 proved, 15 definitions, 6 applied, 1 sampled'
    """
    plural = {"definition": "definitions"}
    return ", ".join(counted(n, k, plural.get(k, k)) for k, n in sorted(steps.items(), key=lambda kv: (-kv[1], kv[0])))


def method_words(method: str) -> str:
    """A numeric method's name as a reader writes it, its nodes counted in words; the records keep the name the
    method is made with (``Gauss-Legendre n=4``) as its key.

    >>> method_words("slices, Gauss-Legendre n=4, 30 digits")
    'slices, Gauss–Legendre with 4 nodes, 30 digits'
    """
    return re.sub(r"Gauss-Legendre n=(\d+)", r"Gauss–Legendre with \1 nodes", method).replace("Gauss-", "Gauss–")


_ROOT = re.compile(r"sqrt\((\d+)\)")


def signs(text: str) -> str:
    """*text* of a record (SymPy's closed forms, ``s -+ 1e-06``) as a table shows it: a square root, a minus and a
    plus-or-minus as their signs; the record keeps its own text.

    >>> signs("1/2 - sqrt(3)/6"), signs("at s -+ 1e-06")
    ('1/2 − √3/6', 'at s ± 1e-06')
    """
    return _ROOT.sub(r"√\1", text).replace(" -+ ", " ± ").replace(" - ", " − ")
