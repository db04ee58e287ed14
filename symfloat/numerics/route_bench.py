"""The definition route benchmarked as a witness family (issue 29, item 3).

The route (:class:`~symfloat.engine.definitions.DefinitionRoute`) measures every printed formula that no declared
witness targets, from the derivation's own definitions, at seeded sample points.  Here each such formula's valid
reading (the print, or its correction where an erratum is declared; relations, which the route reads at other
points, left out) is measured at the route's own points with every method the route has:

* Arb ball arithmetic (:func:`~symfloat.engine.definition_enclosure.definition_ball`: every member a ball, its
  closed integrals by ``acb.integral``) at 64 and 128 bits;
* the definitions evaluated by mpmath (its quadrature for the integrals) at 15, 30 and 50 digits.

The reference is the enclosure at :data:`~symfloat.numerics.bench.REFERENCE_BITS` bits, so every error shown is
proven: ``|value - mid| + rad``, relative to the reference's size (an Arb row's error its own width and its
distance from the reference).  A formula without a finite enclosure at those bits (a multiple or nested integral,
a limit, a root count, a node without a rigorous rule) is counted by its reason and not measured.

**Self-check:** every Arb ball meets the reference at its point (both contain the quantity); a miss is
:class:`~symfloat.errors.CheckFailed`.
"""
from __future__ import annotations

from flint import ctx

from ..engine.definition_enclosure import definition_ball
from ..engine.definitions import DefinitionRoute, NothingToMeasure, _measured, route_readings
from ..engine.enclosure import Unsupported
from ..engine.identity import Domain
from ..errors import CheckFailed
from ..model.relation import is_relation
from .bench import REFERENCE_BITS, UNBOUNDED, Bench, Measurement, _finite, _meet, _rel_error, _timed, _vector

__all__ = ["ROUTE_FAMILY", "ROUTE_DIGITS", "ROUTE_BITS", "bench_route"]

ROUTE_FAMILY = "the definition route"
ROUTE_DIGITS = (15, 30, 50)
ROUTE_BITS = (64, 128)


def _readings(d):
    """``(target, formula, reading)`` for every formula the route measures: its valid reading (the correction
    where an erratum is declared, else the print) under the target name the check gives it, so that its points
    are the check's; relations left out."""
    for p, target, reading in route_readings(d):
        if target == (p.name if p.erratum is None else p.name + "#corrected") and not is_relation(reading):
            yield target, p, reading


def _in_words(why: str) -> str:
    """The reason a member has no rule in balls, in words: the route's own reasons as they are (a multiple
    integral, a root count, ...), a function or a value named in its SymPy form as its kind."""
    if why.startswith("no enclosure for"):
        return "a function with no rule in balls"
    if "is not a real number" in why:
        return "a member that is not real at a sample point"
    if why.startswith("the expression still names"):
        return "a member that names a symbol the sample point does not fix"
    return why


def _balls(measured, points, bits):
    """The measured components at each point as balls at *bits*; ``None`` where one is not finite."""
    try:
        values = [tuple(definition_ball(e, point, bits) for e in measured) for point in points]
    finally:
        ctx.cleanup()          # FLINT's caches of pi and quadrature nodes emptied, as after a route's check
    return values if all(_finite(v) for v in values) else None


def bench_route(d, bench: Bench, digits=ROUTE_DIGITS, repeats=3, progress=None) -> None:
    """Measure every formula the definition route measures in derivation *d* into *bench* (see the module);
    a formula without a finite enclosure is counted in ``bench.unenclosed`` with its reason."""
    route = DefinitionRoute(d.steps, Domain(d.domain, tuple(d.constraints)), d.id)
    for target, p, reading in _readings(d):
        key = f"{d.id}/{p.name}"
        try:
            measured, _, points = route.members_at(target, reading)
        except NothingToMeasure:
            continue
        try:
            reference = _balls(measured, points, REFERENCE_BITS)
            why = "" if reference is not None else "no finite enclosure at 256 bits"
        except Unsupported as exc:
            reference, why = None, _in_words(str(exc))
        except (ValueError, TypeError, ArithmeticError, NotImplementedError):
            reference, why = None, "a member SymPy cannot build at a sample point"
        if reference is None:
            bench.unenclosed[key] = (ROUTE_FAMILY, why)
            continue
        refs = [_vector(v) for v in reference]
        bench.references[key] = f"Arb, {REFERENCE_BITS} bits"
        for bits in ROUTE_BITS:
            values, seconds = _timed(lambda bits=bits: _balls(measured, points, bits), repeats)
            if values is not None and not all(_meet(a, b) for v, r in zip(values, reference) for a, b in zip(v, r)):
                raise CheckFailed(f"{key}: the definition route's enclosure at {bits} bits misses the one at "
                                  f"{REFERENCE_BITS} bits")
            error = UNBOUNDED if values is None else max(_rel_error(v, r) for v, r in zip(values, refs))
            bench.measurements.append(Measurement(d.id, d.source, ROUTE_FAMILY, p.name,
                                                  f"Arb ball arithmetic, {bits} bits", seconds, {p.name: error},
                                                  "" if values is not None else f"no finite ball at {bits} bits"))
        for dps in digits:
            try:
                values, seconds = _timed(lambda dps=dps: [tuple(_measured(e, point, dps) for e in measured)
                                                          for point in points], repeats)
                error, note = max(_rel_error(v, r) for v, r in zip(values, refs)), ""
            except (ValueError, TypeError, ArithmeticError, ZeroDivisionError) as exc:
                error, seconds, note = None, 0.0, f"{type(exc).__name__}: {exc}"[:80]
            bench.measurements.append(Measurement(d.id, d.source, ROUTE_FAMILY, p.name, f"definitions, {dps} digits",
                                                  seconds, {p.name: error}, note))
        if progress:
            progress(f"{d.id}: {p.name} (the definition route)")
