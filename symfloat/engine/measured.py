"""What a witness measures, named in words: the one placeholder of every witness kind.

A witness's quantity is a SymPy expression in the case's parameters and in *measured* quantities, each
named by :func:`measured` in the words the witness kind documents:

* a floating body (:mod:`symfloat.engine.floating_witness`): ``measured("immersed volume")``,
  ``measured("B - G, x")``, any name of its ``QUANTITIES``, ``TILT_QUANTITIES``, ``BODY_FRAME_QUANTITIES``
  and ``SPLIT_QUANTITIES``;
* witnesses combined (``Combined``): ``measured("part 1")``, ``measured("part 2")``, ... the value of each
  part, in order;
* plane sections (``PlaneSections``): ``measured("section 1")``, ... the area of each plane, in order;
* a plane figure (``FigureWitness``): ``measured("integral", of=f)``, the integral of ``f`` over the figure,
  and ``measured("centroid, 1")``, ``measured("centroid, 2")``, its centroid along the witness's first and
  second coordinate.

>>> import sympy as sp
>>> a = sp.Symbol("a")
>>> q = measured("part 1") - measured("part 2") / a
>>> sorted(s.name for s in q.free_symbols if isinstance(s, Measured))
['part 1', 'part 2']
>>> measured("part 1") == sp.Symbol("part 1")       # a measured quantity is no parameter of the same name
False

Each witness kind checks the names it is given against the ones it measures when the witness is declared,
and a name it does not know is an error that lists the known ones.
"""
from __future__ import annotations

import sympy as sp

__all__ = ["Measured", "MeasuredIntegral", "measured", "numbered", "measured_names", "in_words"]


class Measured(sp.Symbol):
    """A measured quantity in a witness's quantity, named in words (a symbol of its own class, so that it is
    never confused with a case's parameter of the same name)."""


class MeasuredIntegral(sp.Function):
    """The integral of its argument over a plane figure's witness figure (kept unevaluated in a quantity)."""

    nargs = 1


def measured(name: str, of=None):
    """The quantity *name* a witness measures; with *of*, the integral of *of* over the witness's figure
    (``measured("integral", of=(x - measured("centroid, 1")) ** 2)``)."""
    if of is not None:
        if name != "integral":
            raise ValueError(f"measured({name!r}, of=...): only an integral takes an integrand")
        return MeasuredIntegral(sp.sympify(of))
    if not isinstance(name, str) or not name:
        raise ValueError(f"a measured quantity is named in words, not {name!r}")
    return Measured(name)


def numbered(word: str, count: int) -> tuple:
    """``measured("word 1")``, ..., ``measured("word count")``: the placeholders of numbered parts."""
    return tuple(Measured(f"{word} {i}") for i in range(1, count + 1))


def in_words(quantity, where: str):
    """*quantity*, refused when it is a bare string: a measured quantity is written ``measured(name)`` (one
    spelling, whether it stands alone or in an expression)."""
    if isinstance(quantity, str):
        raise ValueError(f"{where or 'a witness'}: write the measured quantity as measured({quantity!r}), not as "
                         f"the string {quantity!r}")
    return quantity


def measured_names(expr) -> set:
    """The names of the measured quantities *expr* reads."""
    return {s.name for s in sp.sympify(expr).free_symbols if isinstance(s, Measured)}
