"""Error against run time: every witness of the registry re-run across methods.

Each witness of each derivation (found through :mod:`symfloat.registry`, so a
new derivation is benchmarked without being named here) is measured with every
method that applies to its kind:

* :class:`~symfloat.engine.witness.SectionIntegral` and
  :class:`~symfloat.engine.witness.PlaneSections`: mpmath tanh-sinh and
  Gauss–Legendre at 15, 30, 50 and 100 digits, fixed-order Gauss–Legendre in
  float64 at several orders, and, where the source's own method is a
  Newton–Cotes rule (the derivation speaks of Simpson's rule), composite
  Simpson and trapezoid in float64 at several panel counts;
* :class:`~symfloat.engine.witness.HullWitness`: exact rational hull faces, and
  slices by Gauss–Legendre at several orders and precisions; the counts of side faces
  (:class:`~symfloat.engine.witness.SideFaces`): the hull's faces and two plane sections, both exact;
* the straightedge constructions
  (:class:`~symfloat.engine.construction_witness.ConstructionWitness`): the witness's own computation at
  15 (float64), 30 and 50 digits, and at 100 digits where no exact reference exists;
* the declared witnesses of floating bodies (:mod:`symfloat.engine.floating_witness`: exact clipping, roots,
  limits and series) and of plane figures (:mod:`symfloat.engine.figure_witness`): the methods the witness
  declares (their precisions and steps are tied to its limits and series, so no others apply), the
  highest-precision one the reference where no exact reference exists.

Every witness with a certified method (``enclose``, issue 29) is enclosed in Arb ball arithmetic at
:data:`REFERENCE_BITS` bits; where every case has a finite enclosure, that enclosure is the reference of all
its targets, and the witness is also measured in Arb at 64 and 128 bits (:class:`Enclosure`).  A witness of
such a kind without an enclosure (a limit, a series, a tilt's wedges, split parts, a nested root search with a
guard, finite differences: :func:`no_enclosure`) is recorded with the reason in words
(:attr:`Bench.unenclosed`) and has no Arb rows.

The reference of a targeted formula is that enclosure; without one, the exact value of the formula's valid
reading (the reading as printed when no erratum is declared, the corrected reading otherwise) at the case's
parameters; where that reading is no closed number, the witness's most precise method (a measured reference,
not a proven one).  Each measurement records the relative error against the reference (worst over the
cases) -- a proven bound, ``|value - mid| + rad`` of the reference's ball and the value's own, where the
reference is an enclosure or exact (``proven``) -- and the wall time of all cases (median of repeats).

**Self-check** (:func:`self_check`, a failure is :class:`~symfloat.errors.CheckFailed`): every Arb ball of a
witness meets its reference enclosure (both contain the quantity), and every method the witness declares is
within its own tolerance of the enclosure, plus twice the enclosure's relative radius: an enclosure that
misses the value fails it.
"""
from __future__ import annotations

import statistics
import time
from dataclasses import dataclass, field
from fractions import Fraction

import mpmath
import sympy as sp
from flint import arb

from ..engine.check import _resolved, _substitute
from ..engine.construction_witness import ConstructionWitness
from ..engine.enclosure import Unsupported, exact, working_precision
from ..engine.figure_witness import CurveRoot, FigureWitness
from ..engine.floating_enclosure import ball_body, missing_method
from ..engine.floating_witness import Combined, FloatingWitness, Joined
from ..engine.quadrature import Composite, GaussLegendre64, GaussLegendreMP, TanhSinh
from ..engine.witness import (CERTIFIED, ConvergenceOrder, ExactHull, HullSlices, HullWitness, MeasuredWitness, PlaneSections,
                              Precision, SectionIntegral, SideFaces)
from ..errors import CheckFailed
from ..model.claim import members
from ..model.relation import is_relation
from ..registry import load, select

__all__ = ["Measurement", "Bench", "methods_for", "newton_cotes", "run_bench", "DIGITS", "REFERENCE_DPS",
           "FAMILIES", "DECLARED", "family_of", "Enclosure", "REFERENCE_BITS", "certified", "no_enclosure",
           "self_check", "UNBOUNDED"]

DIGITS = (15, 30, 50, 100)
REFERENCE_DPS = 100
REFERENCE_BITS = 256          # the Arb enclosure every method of a certified witness is measured against
UNBOUNDED = float("inf")      # the error of an Arb run whose ball is not finite (undecided at its bits)
ARB_BITS = (64, 128)
FLOAT64_ORDERS = (2, 3, 4, 6, 8, 12, 16)
PANELS = (2, 4, 8, 16, 32, 64)
FAMILIES = {
    SectionIntegral: "section-area quadrature",
    PlaneSections: "plane-section chords",
    HullWitness: "convex hulls",
    SideFaces: "convex hulls",
    ConstructionWitness: "straightedge constructions",
    FloatingWitness: "floating bodies by exact clipping",
    Joined: "floating bodies by exact clipping",
    FigureWitness: "plane figures",
    CurveRoot: "plane figures",
}
DECLARED = (FloatingWitness, Joined, Combined, FigureWitness, CurveRoot)   # measured with their own methods


@dataclass
class Measurement:
    """One witness measured with one method: relative errors per targeted
    formula (worst over the cases; absolute where the reference is 0; ``None``
    when the method failed; :data:`UNBOUNDED` for an Arb ball that is not finite) and the median wall time
    of all cases; ``proven`` when the reference is an enclosure or exact (the error a bound)."""

    derivation: str
    source: str
    family: str
    witness: str
    method: str
    seconds: float
    errors: dict
    note: str = ""
    proven: bool = True


@dataclass
class Bench:
    """All measurements, with the reference kind of every formula."""

    measurements: list = field(default_factory=list)
    references: dict = field(default_factory=dict)   # "derivation/formula" -> "Arb, 256 bits" | "exact" | ...
    witnesses: dict = field(default_factory=dict)    # "derivation/witness" -> what it measures, in words
    unenclosed: dict = field(default_factory=dict)   # "derivation/witness" -> (family, why it has no enclosure)


@dataclass(frozen=True)
class Enclosure:
    """The certified method as a benchmarked one: the witness's ``enclose`` at ``bits`` bits."""

    bits: int

    @property
    def name(self):
        return f"Arb ball arithmetic, {self.bits} bits"


def certified(w) -> bool:
    """Whether the witness kind of *w* has a certified method (its own ``enclose``)."""
    return isinstance(w, MeasuredWitness) and type(w).enclose is not MeasuredWitness.enclose


def family_of(w):
    """The witness family *w* is listed under (a :class:`Combined` witness under its first part's), or None."""
    if isinstance(w, Combined):
        return family_of(w.parts[0]) if w.parts else None
    return next((f for cls, f in FAMILIES.items() if isinstance(w, cls)), None)


def newton_cotes(d) -> bool:
    """Whether the derivation's own method is a Newton–Cotes rule (it speaks of Simpson's rule)."""
    text = " ".join([d.title, d.summary] + [p.excerpt for p in d.printed] + [s.note for s in d.steps])
    return "simpson" in text.lower()


def methods_for(w, d, digits=DIGITS, orders=FLOAT64_ORDERS, panels=PANELS) -> tuple:
    """The methods a witness's kind is measured with (see the module docstring), Arb's last where the kind has a
    certified method (:func:`bench_derivation` leaves them out for a witness without an enclosure)."""
    return _methods(w, d, digits, orders, panels) + (tuple(Enclosure(b) for b in ARB_BITS) if certified(w) else ())


def _methods(w, d, digits, orders, panels) -> tuple:
    if isinstance(w, (SectionIntegral, PlaneSections)):
        ms = [TanhSinh(f"tanh-sinh, {p} digits", 0, "mpmath", p) for p in digits]
        ms += [GaussLegendreMP(f"Gauss-Legendre (mpmath), {p} digits", 0, "mpmath", p) for p in digits]
        ms += [GaussLegendre64(f"Gauss-Legendre n={n}, float64", 0, "float64", 15, n) for n in orders]
        if newton_cotes(d):
            ms += [Composite(f"{rule} {n} panels, float64", 0, "float64", 15, rule, n)
                   for rule in ("Simpson", "trapezoid") for n in panels]
        return tuple(ms)
    if isinstance(w, SideFaces):
        return tuple(w.methods)                 # counts: the exact hull's faces and two exact sections
    if isinstance(w, HullWitness):
        return (ExactHull(),) + tuple(HullSlices(n, 15, 0) for n in (1, 2, 3)) + tuple(
            HullSlices(3, p, 0) for p in digits if p > 15)
    if isinstance(w, ConstructionWitness):
        return tuple(Precision(p, 0) for p in digits if p < REFERENCE_DPS)
    if isinstance(w, DECLARED):
        return tuple(w.methods)
    return ()


def _method_name(m):
    if isinstance(m, Composite):
        return m.name.replace("Simpson", "Simpson,").replace("trapezoid", "trapezoid,")
    return m.name


def _exact_mpf(x: arb):
    man, exp = x.man_exp()
    return mpmath.mpf((int(man), int(exp)))


def no_enclosure(w, case) -> str:
    """Why the certified witness *w* has no enclosure at *case*, in words (judged from its declaration): a
    floating witness by :func:`~symfloat.engine.floating_enclosure.missing_method`, a joined or combined one by
    its first part without one."""
    return _missing(w, case) or "no rigorous method at this case"


def _missing(w, case) -> str:
    if isinstance(w, (Combined, Joined)):
        if not all(certified(p) for p in w.parts):
            return "a part of a kind without a rigorous method"
        found = next((r for r in (_missing(p, case) for p in w.parts) if r), "")
        return found or ("a part with several values" if isinstance(w, Combined) else "")
    if isinstance(w, FloatingWitness):
        body = w.body if w.body is not None else case.data["body"]
        return missing_method(w, body, case) or (
            "a dimension that is no number at the case" if ball_body(body, case.params) is None else "")
    return ""


def _enclosures(w, bits):
    """``(values, "")``: the enclosure of every case of *w* at *bits*, each finite; ``(None, why)`` otherwise."""
    try:
        values = [w.enclose(case, bits) for case in w.instances]
    except Unsupported as exc:
        return None, f"undecided at {bits} bits ({exc})"
    except (ValueError, ArithmeticError) as exc:
        return None, f"no enclosure at {bits} bits ({type(exc).__name__}: {exc})"
    missing = next((case for case, v in zip(w.instances, values) if v is None), None)
    if missing is not None:
        return None, no_enclosure(w, missing)
    if not all(map(_finite, values)):
        return None, f"no finite enclosure at {bits} bits"
    return values, ""


def _ball_pair(v):
    """A measured value as ``(mid, rad)``: a ball's midpoint and radius, a number with radius 0."""
    if isinstance(v, arb):
        return _exact_mpf(v.mid()), _exact_mpf(v.rad())
    if isinstance(v, Fraction):
        return mpmath.mpf(v.numerator) / v.denominator, mpmath.mpf(0)
    return (mpmath.mpf(v) if not isinstance(v, sp.Basic) else mpmath.mpf(sp.N(v, REFERENCE_DPS + 10))), mpmath.mpf(0)


def _finite(value) -> bool:
    """Whether a measured value (or each of a tuple of them) is a finite number or ball: an enclosure
    that came out unbounded (or none at all: an undecided enclosure) measures nothing, so it has no error to
    report."""
    values = value if isinstance(value, (tuple, list)) else [value]
    return all(v is not None and (not isinstance(v, arb) or v.is_finite()) for v in values)


def _vector(value):
    values = value if isinstance(value, (tuple, list)) else [value]
    with mpmath.workdps(REFERENCE_DPS + 20):
        return [_ball_pair(v) for v in values]


def _rel_error(value, ref):
    """The proven error of *value* against the reference balls *ref*: ``|mid - mid'| + rad + rad'``,
    relative to the reference's size, the least magnitude of its largest ball (absolute where every ball
    holds 0 or is below 1e-80: a quantity that is 0, such as a product moment at an equilibrium)."""
    with mpmath.workdps(REFERENCE_DPS + 20):
        v = _vector(value)
        err = max(abs(a - m) + ra + rm for (a, ra), (m, rm) in zip(v, ref))
        scale = _size(ref)
        return float(err / scale if scale else err)


def _size(ref):
    """The least magnitude of the largest of the reference balls *ref*, 0 where it holds 0 or is below 1e-80."""
    with mpmath.workdps(REFERENCE_DPS + 20):
        scale = max(abs(m) - rm for m, rm in ref)
        return scale if scale > mpmath.mpf(10) ** (20 - REFERENCE_DPS) else 0


def _valid_reading(p):
    """The reading that holds (the corrected one of an erratum); a relation as its chain of 1/0 indicators
    (:meth:`~symfloat.model.relation.Relation.indicators`; None for a case table)."""
    reading = p.reading if p.erratum is None else p.erratum.corrected_reading
    return reading.indicators() if is_relation(reading) else reading


def _exact_reference(chain, params):
    """The first member of *chain* that is a closed exact number at *params*, at 110 digits."""
    for m in members(chain):
        v = m.xreplace(params) if isinstance(m, sp.MatrixBase) else sp.sympify(m).xreplace(params)
        if v.free_symbols or v.has(sp.Float):
            continue
        comps = list(v) if isinstance(v, sp.MatrixBase) else [v]
        with mpmath.workdps(REFERENCE_DPS + 20):
            try:
                vals = [(mpmath.mpf(sp.Float(sp.N(c, REFERENCE_DPS + 10), REFERENCE_DPS + 10)._mpf_), mpmath.mpf(0))
                        for c in comps]
            except TypeError:
                continue            # not a real number
        return vals
    return None


def _is_number(m, params):
    return not m.xreplace(params).free_symbols


def _results(d):
    results = {}
    for s in d.steps:
        if s.result is not None:
            results[s.result] = _substitute(members(s.claim)[-1], results)
    return results


def _timed(run, repeats):
    """Value and median wall time of *run*; cheap runs are repeated."""
    times, value = [], None
    while True:
        t0 = time.perf_counter()
        value = run()
        times.append(time.perf_counter() - t0)
        if len(times) >= repeats or sum(times) > 0.05:
            return value, statistics.median(times)


def _section_integral(w, case):
    """``method -> value`` for a :class:`SectionIntegral` case, the integrands built once."""
    parts = []
    for area, bounds in w.parts:
        lo, hi = (sp.sympify(b).xreplace(case.params) for b in bounds)
        origin = lo if w.origin is None else sp.sympify(w.origin).xreplace(case.params)
        area = area.xreplace(case.params)
        with mpmath.workdps(REFERENCE_DPS + 20):
            points = [mpmath.mpf(sp.N(b, REFERENCE_DPS + 20)) for b in (lo, hi)]
        parts.append(({mod: (sp.lambdify(w.z, area, mod), sp.lambdify(w.z, (w.z - origin) * area, mod))
                       for mod in ("mpmath", "numpy")}, points))

    def one(built, points, method):
        f, g = built["mpmath" if method.arithmetic == "mpmath" else "numpy"]
        with mpmath.workdps(method.dps):
            volume = method.integrate(f, points)[0]
            if w.quantity == "volume":
                return volume
            moment = method.integrate(g, points)[0]
            return moment if w.quantity == "moment" else moment / volume

    def value(method):
        return w.combined([one(built, points, method) for built, points in parts])
    return value


def _plane_sections(w, case):
    """``method -> value`` for a :class:`PlaneSections` case, the chord widths built once."""
    planes = []
    for plane in w.planes:
        at = {**case.params, w.position: sp.sympify(plane).xreplace(case.params)}
        with mpmath.workdps(REFERENCE_DPS + 20):
            chord = [mpmath.mpf(sp.N(sp.sympify(e).xreplace(at), REFERENCE_DPS + 20)) for e in w.chord]
        planes.append((sp.lambdify(w.across, w.width.xreplace(at), "mpmath"), chord))

    def value(method):
        with mpmath.workdps(method.dps):
            return w.combined([method.integrate(f, chord)[0] for f, chord in planes], case)
    return value


def _runner(w, case):
    if isinstance(w, SectionIntegral):
        inner = _section_integral(w, case)
    elif isinstance(w, PlaneSections):
        inner = _plane_sections(w, case)
    else:
        inner = lambda method: w.measure(case, method)  # noqa: E731
    return lambda method: _ball_run(w, case, method.bits) if isinstance(method, Enclosure) else inner(method)


def _ball_run(w, case, bits):
    """The enclosure of *case* at *bits*; a not finite ball where it is undecided there."""
    try:
        return w.enclose(case, bits)
    except (ValueError, ArithmeticError):          # Unsupported among them: undecided at these bits
        return arb.nan()


def _measure(runners, method, repeats):
    return _timed(lambda: [r(method) for r in runners], repeats)


def _witness_targets(d, w, results):
    """Targeted formula -> reference per case (or None where none is exact)."""
    targets = {}
    for p in d.printed:
        if p.name not in w.targets:
            continue
        chain = _valid_reading(p)
        if chain is None:
            continue
        chain = _resolved(chain, results)
        if not any(_is_number(m, case.params) for m in members(chain) for case in w.instances):
            continue            # the witness measures something the reading states only with free symbols
        targets[p.name] = [_exact_reference(chain, case.params) for case in w.instances]
    return targets


def _reference_run(w):
    """The method a witness without an enclosure is measured against where no reading is exact."""
    if isinstance(w, ConstructionWitness):
        return Precision(REFERENCE_DPS, 0)
    if isinstance(w, (HullWitness, SideFaces)):
        return ExactHull()
    if isinstance(w, DECLARED):
        return max(w.methods, key=lambda m: m.dps)
    return TanhSinh(f"tanh-sinh, {REFERENCE_DPS} digits", 0, "mpmath", REFERENCE_DPS)


def bench_derivation(d, bench: Bench, digits=DIGITS, orders=FLOAT64_ORDERS, panels=PANELS, repeats=3,
                     progress=None):
    """Measure every witness of derivation *d* into *bench* (see the module)."""
    results = _results(d)
    for w in d.witnesses:
        family = family_of(w)
        if family is None or isinstance(w, ConvergenceOrder):
            continue
        targets = _witness_targets(d, w, results)
        if not targets:
            continue
        bench.witnesses[f"{d.id}/{w.name}"] = w.description
        reference, why = _enclosures(w, REFERENCE_BITS) if certified(w) else (None, "")
        if why:
            bench.unenclosed[f"{d.id}/{w.name}"] = (family, why)
        methods = list(_methods(w, d, digits, orders, panels))
        methods += [Enclosure(b) for b in ARB_BITS] if reference is not None else []
        missing = reference is None and any(r is None for refs in targets.values() for r in refs)
        ref_method = _reference_run(w)
        runs, runners = {}, [_runner(w, case) for case in w.instances]
        for m in methods + ([ref_method] if missing and ref_method.name not in map(_method_name, methods) else []):
            try:
                runs[_method_name(m)] = _measure(runners, m, repeats) + ("",)
            except (ZeroDivisionError, ValueError, ArithmeticError, mpmath.libmp.NoConvergence) as exc:
                runs[_method_name(m)] = (None, 0.0, f"{type(exc).__name__}: {exc}"[:80])
        if reference is not None:
            balls = [_vector(v) for v in reference]
            for name in targets:
                _reference(bench, f"{d.id}/{name}", f"Arb, {REFERENCE_BITS} bits")
                targets[name] = balls
        elif missing:
            ref_values = runs[_method_name(ref_method)][0]
            for name, refs in targets.items():
                _reference(bench, f"{d.id}/{name}", "exact" if all(r is not None for r in refs)
                           else f"{getattr(ref_method, 'dps', REFERENCE_DPS)} digits")
                targets[name] = [r if r is not None else _vector(v) for r, v in zip(refs, ref_values)]
        else:
            for name in targets:
                _reference(bench, f"{d.id}/{name}", "exact")
        proven = not missing            # against an enclosure or exact readings: the errors are bounds
        if reference is not None:
            self_check(d.id, w, {_method_name(m): runs[_method_name(m)][0] for m in methods}, reference)
        for m in methods:
            values, seconds, note = runs[_method_name(m)]
            errors = {}
            for name, refs in targets.items():
                errors[name] = (None if values is None else UNBOUNDED if not all(map(_finite, values))
                                else max(_rel_error(v, r) for v, r in zip(values, refs)))
            if isinstance(m, Enclosure) and any(e == UNBOUNDED for e in errors.values()):
                note = f"no finite ball at {m.bits} bits"
            bench.measurements.append(Measurement(d.id, d.source, family, w.name, _method_name(m), seconds, errors,
                                                  note, proven))
        if progress:
            progress(f"{d.id}: {w.name} ({len(methods)} methods)")


def _parts(value):
    return tuple(value) if isinstance(value, (tuple, list)) else (value,)


def _meet(a, b) -> bool:
    """Whether two enclosures of one number (balls, or exact Fractions) have a point in common."""
    with working_precision(4 * REFERENCE_BITS):
        a, b = (x if isinstance(x, arb) else exact(Fraction(x)) for x in (a, b))
        return a.overlaps(b)


def _reference(bench, key, kind):
    """Add *kind* to the references of the formula *key* (several witnesses may target it)."""
    kinds = bench.references[key].split(" and ") if key in bench.references else []
    bench.references[key] = " and ".join(sorted({*kinds, kind}))


def self_check(did, w, values, reference):
    """Raise :class:`~symfloat.errors.CheckFailed` unless every Arb ball of *values* (method name -> the values
    of the cases) meets the *reference* enclosure of its case, and every method *w* declares is within its
    tolerance (relative to the largest component) plus twice the reference's relative radius of it."""
    tolerance = {m.name: m.tolerance for m in getattr(w, "methods", ()) if getattr(m, "tolerance", 0) > 0}
    for name, vals in values.items():
        if vals is None or not all(map(_finite, vals)):
            continue                    # a method that failed, an undecided ball: measured, nothing to check
        for case, v, ref in zip(w.instances, vals, reference):
            balls = _vector(ref)
            if name.startswith(CERTIFIED):
                if not all(_meet(a, b) for a, b in zip(_parts(v), _parts(ref))):
                    raise CheckFailed(f"{did}: {w.name}: the enclosure by {name} misses the one at "
                                      f"{REFERENCE_BITS} bits at {case.label or case.params}")
            elif name in tolerance:
                with mpmath.workdps(REFERENCE_DPS + 20):
                    scale = _size(balls)
                    resolution = max(rm for _, rm in balls) / scale if scale else max(rm for _, rm in balls)
                err = _rel_error(v, balls)
                if err > tolerance[name] + 2 * float(resolution):
                    raise CheckFailed(f"{did}: {w.name}: {name} is {err:.2e} from the enclosure at "
                                      f"{case.label or case.params}, beyond its tolerance {tolerance[name]:g}")


def run_bench(selector=None, *, quick=False, progress=None) -> Bench:
    """Benchmark every witness of the derivations *selector* picks, and the formulas their definition route
    measures (:mod:`symfloat.numerics.route_bench`); ``quick`` measures fewer methods (15 and 30 digits, three
    float64 orders, two panel counts)."""
    from .route_bench import ROUTE_DIGITS, bench_route
    bench = Bench()
    kwargs = dict(digits=(15, 30), orders=(2, 4, 8), panels=(4, 16), repeats=1) if quick else {}
    for did in select(selector):
        d, _ = load(did)
        bench_derivation(d, bench, progress=progress, **kwargs)
        bench_route(d, bench, digits=(15, 30) if quick else ROUTE_DIGITS, repeats=1 if quick else 3,
                    progress=progress)
    return bench
