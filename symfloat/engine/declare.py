"""What a witnesses module says many times, said once: its cases by parameter name, its witnesses and the parts
of its joined or combined witnesses with the module's defaults.

``cases_of(*parameters)`` makes exact cases: ``case(label, body=None, **values)``, each value a number or a
decimal string taken exactly (``s="0.3"`` is 3/10), keyed by the parameter's name; a body, where given, is the
case's own (``Case(..., {"body": body})``); ``rational_cases((label, {symbol: value}), ...)`` the same by symbol.
``declarer(derivation, kind, **defaults)`` declares witnesses of
one kind with the module's fields: ``declare(name, description, targets, cases, quantity, **fields)`` is
``derivation.witness(kind(name, description, targets, cases, quantity=quantity, **defaults, **fields))``, a field
given at the call overriding the module's; without ``quantity`` the module's, if it gives one (a kind that
measures no ``quantity``, like ``PlaneSections`` with its ``combine``, takes none).  ``part_of(kind, **defaults)``
makes the parts of a ``Joined`` or ``Combined`` witness: ``part(**fields)`` is ``kind("", "", (), (), **defaults,
**fields)`` (a part's name, targets and cases are the whole's).

>>> import sympy as sp
>>> a, s = sp.symbols("a s", positive=True)
>>> case = cases_of(a, s)
>>> c = case("a = 3/2, s = 3/10", a="1.5", s="0.3")
>>> c.params == {a: sp.Rational(3, 2), s: sp.Rational(3, 10)}, c.label
(True, 'a = 3/2, s = 3/10')
"""
from __future__ import annotations

import sympy as sp

from .witness import Case

__all__ = ["cases_of", "rational_cases", "declarer", "part_of"]


def cases_of(*parameters):
    """A maker of exact cases whose values are given by the names of *parameters* (see the module)."""
    by_name = {p.name: p for p in parameters}

    def case(label, body=None, **values):
        unknown = sorted(set(values) - set(by_name))
        if unknown:
            raise ValueError(f"case {label!r}: {unknown} name no parameter; known: {', '.join(sorted(by_name))}")
        return Case({by_name[k]: sp.Rational(v) for k, v in values.items()},
                    None if body is None else {"body": body}, label)
    return case


def rational_cases(*rows):
    """Cases from ``(label, {symbol: value})`` rows, each value made an exact SymPy rational (``"1/4"`` is 1/4):
    for parameters whose names are not Python names (``x'``), which :func:`cases_of` cannot take as keywords."""
    return tuple(Case({q: sp.Rational(v) for q, v in params.items()}, label=label) for label, params in rows)


def declarer(derivation, kind, **defaults):
    """A function declaring witnesses of *kind* on *derivation* with the module's *defaults* (see the module);
    ``cases`` may be a tuple or a function returning one (built when first measured)."""
    def declare(name, description, targets, cases, quantity=None, **fields):
        if quantity is not None:                        # else the module's, or the kind's own measure
            fields["quantity"] = quantity
        derivation.witness(kind(name, description, tuple(targets), cases if callable(cases) else tuple(cases),
                                **{**defaults, **fields}))
    return declare


def part_of(kind, **defaults):
    """A maker of parts of *kind* with the module's *defaults* (see the module)."""
    def part(**fields):
        return kind("", "", (), (), **{**defaults, **fields})
    return part
