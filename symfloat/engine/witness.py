"""First-principles witnesses: the defining quantity computed by another route.

A witness measures a quantity (a volume, a centroid, a moment) at concrete
cases by quadrature of its defining integral or by exact geometry, with
several methods and precisions, and compares each printed (or corrected)
formula it targets with the measurement.  It never evaluates the formula it
checks to obtain the measurement.

Each comparison becomes a record ``{method, abs_error, rel_error, seconds}``:
the error of the formula's value against that method's measurement (maximum
over the cases) and the time the method took (sum over the cases), with the
bound it is held to (:func:`record_agrees`), so that a record read back says
by itself whether the formula agrees with the witness.  Where a certified
enclosure decides, the records are its decision and the cheapest method's
proven error (:class:`MeasuredWitness`).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from flint import arb

from ..geometry.convex import hull_volume_centroid, section_area, side_faces, side_faces_by_sections
from ..model.claim import members
from .enclosure import Unsupported, ball, exact, integral, lower, upper, working_precision
from .measured import numbered
from .quadrature import DEFAULT_METHODS, TANH_SINH_15, TANH_SINH_50

__all__ = ["Case", "Outcome", "record_agrees", "record_decision", "undecided_reason", "CERTIFIED", "MeasuredWitness", "Precision", "SectionIntegral", "PlaneSections",
           "HullWitness", "SideFaces",
           "ExactHull", "HullSlices", "FaceSections", "ConvergenceOrder"]

REFERENCE_DIGITS = 60


@dataclass(frozen=True)
class Case:
    """One concrete instance: exact parameter values and, for geometric
    witnesses, the data (vertices) they come from."""

    params: dict
    data: object = None
    label: str = ""

    def __post_init__(self):
        object.__setattr__(self, "params", {k: sp.sympify(v) for k, v in self.params.items()})


@dataclass
class Outcome:
    """What one witness found for one targeted formula: ``agrees`` when every record agrees, ``undecided``
    when none refutes but a certified enclosure was too wide to decide (shown and counted, never passed)."""

    witness: str
    records: list = field(default_factory=list)
    agrees: bool = True
    note: str = ""
    measurable: bool = True     # False: the formula has nothing a number could check (it restates a definition)
    undecided: bool = False

    def judged(self):
        """``agrees``, ``undecided`` and a note set from the records' decisions (:func:`record_decision`)."""
        decisions = {record_decision(r) for r in self.records}
        self.agrees = decisions <= {"agrees"}
        self.undecided = "undecided" in decisions and "refuted" not in decisions
        return self


def record_decision(record: dict) -> str:
    """``agrees``, ``refuted`` or ``undecided``: what a witness record says of the formula it was made for.

    A certified record (``certified``: Arb's enclosure of the difference *reading - quantity*, see
    :class:`MeasuredWitness`) is **refuted** when the difference is proven larger than the print's own
    rounding, ``abs_error_lower > abs_tolerance``; it **agrees** when it is proven within that rounding
    plus ``width`` (the narrowness the working precision asks, 0 for exact arithmetic),
    ``abs_error <= abs_tolerance + width``; else it is **undecided** (``abs_error`` is ``null`` for a
    non-finite enclosure).  Any other record lies within or beyond the bound it carries:
    ``abs_tolerance`` (a printed number's precision; 0 for a count, which must be exact), else
    ``rel_tolerance`` (the method's), else a measured convergence ``order`` within ``slack`` of
    ``expected_order``.  A record with none of them agrees with nothing.

    >>> record_decision({"certified": True, "abs_error": 3e-80, "abs_error_lower": 0.0, "width": 1e-77,
    ...                  "abs_tolerance": 0.0})
    'agrees'
    >>> record_decision({"certified": True, "abs_error": 2e-3, "abs_error_lower": 1e-3, "width": 1e-77,
    ...                  "abs_tolerance": 5e-4})
    'refuted'
    >>> record_decision({"certified": True, "abs_error": None, "abs_error_lower": 0.0, "width": 1e-77,
    ...                  "abs_tolerance": 0.0})
    'undecided'
    >>> record_decision({"abs_error": 1e-3, "rel_error": 2e-2, "rel_tolerance": 1e-10})
    'refuted'
    >>> record_decision({"order": 3.96, "expected_order": 4, "slack": 0.15})
    'agrees'
    """
    if record.get("certified"):
        if record["abs_error_lower"] > record["abs_tolerance"]:
            return "refuted"
        if record["abs_error"] is not None and record["abs_error"] <= record["abs_tolerance"] + record["width"]:
            return "agrees"
        return "undecided"
    if "abs_tolerance" in record:
        within = record["abs_error"] <= record["abs_tolerance"]
    elif "rel_tolerance" in record:
        within = record["rel_error"] <= record["rel_tolerance"]
    elif "expected_order" in record:
        within = record["order"] is not None and abs(record["order"] - record["expected_order"]) <= record["slack"]
    else:
        within = False
    return "agrees" if within else "refuted"


def undecided_reason(record: dict) -> str:
    """Why a certified record is undecided, in words without formulas (an erratum's evidence quotes them): no
    finite enclosure (``abs_error`` is ``null``: a node without a rigorous rule, a quantity or a root not
    enclosed; the record's ``unsupported`` says which), else the width of the ball at its precision.

    >>> undecided_reason({"certified": True, "bits": 1024, "abs_error": 1e-3})
    'the enclosure of the difference is too wide at 1024 bits'
    >>> undecided_reason({"certified": True, "bits": 128, "abs_error": None,
    ...                   "unsupported": "no enclosure for a LambertW node (LambertW(1))"})
    'no finite enclosure of the difference at 128 bits'
    """
    if record["abs_error"] is None:
        return f"no finite enclosure of the difference at {record['bits']} bits"
    return f"the enclosure of the difference is too wide at {record['bits']} bits"


def record_agrees(record: dict) -> bool:
    """Whether a witness record agrees with its formula (:func:`record_decision`).

    >>> record_agrees({"abs_error": 1e-3, "rel_error": 2e-2, "abs_tolerance": 5e-3})
    True
    """
    return record_decision(record) == "agrees"


def _expected(reading, params):
    """Values of the chain members that become numbers at *params*, at
    :data:`REFERENCE_DIGITS` (computed once per case, whatever the methods)."""
    values = []
    for m in members(reading):
        if isinstance(m, sp.MatrixBase):
            v = m.xreplace(params)
            if not v.free_symbols:
                values.append([sp.N(c, REFERENCE_DIGITS) for c in v])
            continue
        v = sp.sympify(sp.sympify(m).xreplace(params))
        if not v.free_symbols:
            values.append([sp.N(v, REFERENCE_DIGITS)])
    return values


def _exact_members(reading, params):
    """The chain members that become numbers at *params*, each the list of its components (SymPy numbers,
    exact where the member is)."""
    values = []
    for m in members(reading):
        v = m.xreplace(params) if isinstance(m, sp.MatrixBase) else sp.sympify(sp.sympify(m).xreplace(params))
        if not v.free_symbols:
            values.append(list(v) if isinstance(v, sp.MatrixBase) else [v])
    return values


def _real(e):
    """A 60-digit mpf of a closed real SymPy number; a clear error otherwise."""
    if not (e.is_real or e.is_real is None and sp.im(e) == 0):
        raise ValueError(f"a witness target evaluates to {e}, which is not a real number")
    return mpmath.mpf(sp.Float(sp.re(e), REFERENCE_DIGITS)._mpf_)


def _errors(measured, expected):
    measured = measured if isinstance(measured, (tuple, list)) else [measured]
    with mpmath.workdps(REFERENCE_DIGITS):
        ab = max(abs(_real(e) - mpmath.mpf(m)) for m, e in zip(measured, expected))
        scale = max(abs(_real(e)) for e in expected)
        rel = ab / scale if scale else ab
    return float(ab), float(rel)


def _components(value) -> tuple:
    return tuple(value) if isinstance(value, (tuple, list)) else (value,)


def _as_ball(value, prec):
    """A reading's component (a SymPy number) or a measured one (a ball, or an exact Fraction) as a ball."""
    if isinstance(value, arb):
        return value
    if isinstance(value, (Fraction, int)):
        return exact(Fraction(value))
    return ball(value, prec)


def _difference(reading, measured, prec):
    """The ball of *reading* - *measured*: exact (radius 0 when they are equal) where both are exact rationals."""
    if isinstance(measured, (Fraction, int)) and isinstance(reading, sp.Rational):
        return exact(Fraction(int(reading.p), int(reading.q)) - Fraction(measured))
    return _as_ball(reading, prec) - _as_ball(measured, prec)


def _scale(case, values, prec) -> float:
    """The magnitude of the numbers a case computes with: its parameters, the reading, the measurement."""
    sizes = [upper(_as_ball(v, prec)) for v in values]
    sizes += [abs(float(v)) for v in case.params.values() if getattr(v, "is_number", False) and v.is_real]
    return max(sizes, default=0.0)


CERTIFIED = "Arb ball arithmetic"   # the certified method's name in a record


START_BITS = 128    # the certified method's first precision; doubled up to 8 times it while undecided


@dataclass(frozen=True)
class MeasuredWitness:
    """Common machinery: measure the cases by each method, enclose them in Arb, decide by the ball.

    ``cases`` is a tuple of :class:`Case`, or a function returning one: it is called on first use, so that
    declaring a witness costs nothing at import.

    **The protocol.**  A witness kind supplies ``measure(case, method)`` for each of its ``methods`` (float64,
    mpmath at n digits: what the numerics report compares) and, where a rigorous method exists,
    ``enclose(case, bits)``: the quantity at the case as an ``arb`` (a tuple of them for several values; an
    exact :class:`fractions.Fraction` where the quantity is exact, a ball of radius 0) computed at ``bits``
    bits (:mod:`symfloat.engine.enclosure`).  :meth:`run` then, for each targeted formula:

    * encloses each member of its reading at the case (:func:`~symfloat.engine.enclosure.ball`; exact where
      both sides are rational) and forms the ball *d* of reading - quantity;
    * decides by *d* (:func:`record_decision`): refuted when ``|d|`` is proven larger than the print's own
      rounding ``t`` (half a unit in the last printed digit, from ``allowances``; 0 for an exact formula),
      agreeing when ``|d| <= t + width`` with ``width = scale * 2^(-bits/2)`` (``scale`` the magnitude of
      the case's parameters, the reading and the quantity: half the working bits must survive), else
      **undecided**: the precision is doubled (from :data:`START_BITS` up to 8 times it) and the
      formula decided anew; still undecided at the cap, the record says so;
    * records the certified decision (``method`` :data:`CERTIFIED`, ``certified``, ``bits``, the proven
      bounds ``abs_error_lower <= |d| <= abs_error``, ``width``, ``abs_tolerance``) and, for the
      :attr:`cheapest` method, its **proven error** against the enclosure, ``|value - mid| + rad``
      (``proven``; a method finer than the enclosure shows about its radius), held to ``rel_tolerance``: the
      method's accuracy plus what the enclosure resolves, twice its relative radius (``|true - mid| + rad``)
      and ``2^(2-bits)`` for the rounding of the difference (a method that misses it fails its self-check).
      Where the ball decides, the finer methods would add nothing to the verdict and are not measured
      (``symfloat bench`` measures every method for the numerics report); a formula left **undecided**
      gets the proven error of every method.

    A kind without ``enclose`` (it returns ``None``), and a formula whose reading or quantity has no rigorous
    rule (``unsupported``), keep the former comparison: every method's measurement against the reading at
    :data:`REFERENCE_DIGITS`, under the method's ``rel_tolerance``."""

    name: str
    description: str
    targets: tuple
    cases: tuple

    methods = DEFAULT_METHODS

    @property
    def instances(self) -> tuple:
        """The cases (built now if they were declared as a function)."""
        if callable(self.cases):
            object.__setattr__(self, "cases", tuple(self.cases()))
        return self.cases

    @property
    def cheapest(self) -> tuple:
        """The method a decided check measures beside the enclosure, as a tuple (empty for a kind without
        methods): the first of the least working digits (``dps``; a method without them, exact rational
        arithmetic, after every other)."""
        return tuple(sorted(self.methods, key=lambda m: getattr(m, "dps", math.inf))[:1])

    def measure(self, case: Case, method):
        raise NotImplementedError  # pragma: no cover - abstract

    def enclose(self, case: Case, bits: int):
        """The quantity at *case* as a ball (or a tuple of balls, or exact), or ``None``: no rigorous method."""
        return None

    def run(self, readings: dict, allowances: dict | None = None) -> dict:
        """An :class:`Outcome` for each targeted reading of *readings* (name -> reading); *allowances* gives
        a printed number's rounding (name -> half a unit in its last digit)."""
        measured = {}

        def by(methods):
            """Each of *methods* -> (its values at the cases, the seconds they took), each measured once."""
            for method in methods:
                if method not in measured:
                    t0 = time.perf_counter()
                    values = [self.measure(case, method) for case in self.instances]
                    measured[method] = (values, time.perf_counter() - t0)
            return {method: measured[method] for method in methods}

        by(self.cheapest)       # first: an enclosure may be seeded from its measurement (a float64 root, cached)
        targets = [t for t in readings if t.split("#")[0] in self.targets]
        exact_readings = {t: [_exact_members(readings[t], case.params) for case in self.instances] for t in targets}
        for t in targets:
            for case, members_ in zip(self.instances, exact_readings[t]):
                if not members_:
                    raise ValueError(f"witness {self.name}: no member of {t} is a number at {case.label}")
        certified = self._certified(exact_readings, allowances or {})
        outcomes = {}
        for target in targets:
            if certified is None:
                out = self._compared(readings[target], by(self.methods))
            else:
                record, enclosures, bits = certified[target]
                if "unsupported" in record:   # a node without a rigorous rule: undecided, the methods compared
                    out = self._compared(readings[target], by(self.methods))
                    out.records.insert(0, record)
                else:                         # decided by the ball: the cheapest method's proven error beside it
                    methods = self.methods if record_decision(record) == "undecided" else self.cheapest
                    out = Outcome(self.name, [record] + self._proven(by(methods), enclosures, bits))
            out.judged()
            if out.undecided:
                out.note = f"{self.description}: undecided, {undecided_reason(out.records[0])}"
            elif not out.agrees:
                out.note = f"{self.description}: disagrees beyond the print's rounding or a method's accuracy"
            outcomes[target] = out
        return outcomes

    def _certified(self, exact_readings, allowances):
        """target -> (its certified record, the enclosures it was decided with, their bits); ``None`` when the
        kind has no rigorous method."""
        first = START_BITS
        pending, done, seconds = set(exact_readings), {}, 0.0
        bits = first
        while pending and bits <= 8 * first:
            t0 = time.perf_counter()
            try:
                enclosures = [self.enclose(case, bits) for case in self.instances]
                failure = ""
            except Unsupported as exc:
                enclosures, failure = None, str(exc)
            seconds += time.perf_counter() - t0
            if enclosures is not None and any(e is None for e in enclosures):
                return None
            if enclosures is not None and not all(_finite(e) for e in enclosures):
                enclosures, failure = None, f"no finite enclosure at {bits} bits"
            for target in sorted(pending):
                record = self._decision(exact_readings[target], enclosures, bits, allowances.get(target.split("#")[0]),
                                        seconds, failure)
                if record_decision(record) != "undecided" or bits * 2 > 8 * first or "unsupported" in record:
                    done[target] = (record, enclosures, bits)
            pending -= set(done)
            if failure:
                break
            bits *= 2
        return done

    def _decision(self, readings_by_case, enclosures, bits, allowance, seconds, failure):
        """The certified record of one target (see the class)."""
        t = upper(exact(Fraction(int(allowance.p), int(allowance.q)))) if allowance is not None else 0.0
        record = {"method": CERTIFIED, "certified": True, "bits": bits, "abs_error": None, "abs_error_lower": 0.0,
                  "rel_error": 0.0, "width": 0.0, "abs_tolerance": t, "seconds": seconds, "cases": len(self.instances)}
        if failure:
            record["unsupported"] = failure
            return record
        try:
            return self._bounds(record, readings_by_case, enclosures, bits)
        except Unsupported as exc:         # the reading has a node without a rigorous rule
            record["unsupported"] = str(exc)
            return record

    def _bounds(self, record, readings_by_case, enclosures, bits):
        worst_upper = worst_lower = worst_rel = 0.0
        width = float("inf")
        with working_precision(bits):
            for case, members_, value in zip(self.instances, readings_by_case, enclosures):
                measured = _components(value)
                pairs = [(r, m) for member in members_ for r, m in zip(member, measured)]
                width = min(width, math.ldexp(_scale(case, [v for pair in pairs for v in pair], bits), -bits // 2))
                for r, m in pairs:
                    d = _difference(r, m, bits)
                    worst_upper = max(worst_upper, upper(d))
                    worst_lower = max(worst_lower, lower(d))
                    size = upper(_as_ball(r, bits))
                    worst_rel = max(worst_rel, upper(d) / size if size else upper(d))
        finite = math.isfinite(worst_upper)
        record.update(abs_error=worst_upper if finite else None, abs_error_lower=worst_lower,
                      rel_error=worst_rel if finite else 0.0, width=width if math.isfinite(width) else 0.0)
        return record

    def _proven(self, measured, enclosures, bits):
        """Each method's proven error against the enclosures: ``|value - mid| + rad``, the largest over the
        cases and components (absolute, and relative to the quantity's magnitude)."""
        records = []
        for method, (values, seconds) in measured.items():
            worst_abs = worst_rel = resolution = 0.0
            with working_precision(bits):
                for value, enclosure in zip(values, enclosures):
                    for v, e in zip(_components(value), _components(enclosure)):
                        e = _as_ball(e, bits)
                        err = upper(_as_ball(_value_ball(v), bits) - e)
                        size = lower(e)
                        worst_abs = max(worst_abs, err)
                        worst_rel = max(worst_rel, err / size if size else err)
                        resolution = max(resolution, upper(e.rad()) / size if size else upper(e.rad()))
            records.append({"method": method.name, "abs_error": worst_abs, "rel_error": worst_rel, "seconds": seconds,
                            "cases": len(self.instances), "proven": True,
                            "rel_tolerance": max(method.tolerance, 1e-50) + 2 * resolution + math.ldexp(1, 2 - bits)})
        return records

    def _compared(self, reading, measured):
        """The former comparison (a kind without a rigorous method): each method against the reading."""
        expected_by_case = [_expected(reading, case.params) for case in self.instances]
        out = Outcome(self.name)
        for method, (values, seconds) in measured.items():
            worst_abs = worst_rel = 0.0
            for value, expected in zip(values, expected_by_case):
                for e in expected:
                    a, r = _errors(value, e)
                    worst_abs, worst_rel = max(worst_abs, a), max(worst_rel, r)
            out.records.append({"method": method.name, "abs_error": worst_abs,
                                "rel_error": worst_rel, "seconds": seconds,
                                "cases": len(self.instances), "rel_tolerance": max(method.tolerance, 1e-50)})
        return out


def _finite(value) -> bool:
    return all(not isinstance(v, arb) or v.is_finite() for v in _components(value))


def _value_ball(v) -> arb:
    """A method's measured value (an mpf, a float, an exact Fraction) as an exact ball (a binary number is
    exact; a Fraction is rounded at the working precision)."""
    if isinstance(v, (Fraction, int)):
        return exact(Fraction(v))
    if isinstance(v, float):
        return arb(v)
    sign, man, exp, _ = (v if isinstance(v, mpmath.mpf) else mpmath.mpf(v))._mpf_
    return arb(-int(man) if sign else int(man)) * arb(2) ** int(exp)


@dataclass(frozen=True)
class Precision:
    """Working precision of a declared witness: ``dps`` digits (float64 for 15) and the tolerance its
    measurement is trusted to."""

    dps: int
    tolerance: float

    @property
    def name(self):
        return "float64" if self.dps <= 15 else f"mpmath, {self.dps} digits"


@dataclass(frozen=True)
class SectionIntegral(MeasuredWitness):
    """Quadrature of a section area ``A(z)`` over ``bounds``.

    ``quantity`` is ``volume`` (∫A dz), ``moment`` (∫(z - o) A dz) or
    ``centroid`` (moment / volume: the distance of the centroid from the
    plane ``z = o``); ``o`` is ``origin``, by default the lower bound.
    Several bodies at once: ``area`` a tuple of section areas, or ``bounds``
    a tuple of ``(lower, upper)`` pairs; the value is then the tuple of the
    quantity for each area over each pair (areas outer), in that order.
    """

    area: sp.Expr = None
    z: sp.Symbol = None
    bounds: tuple = ()
    quantity: str = "volume"
    origin: object = None
    methods: tuple = DEFAULT_METHODS

    @property
    def parts(self) -> tuple:
        """``(area, (lower, upper))`` of each integral, in the order of the value's components."""
        areas = self.area if isinstance(self.area, tuple) else (self.area,)
        spans = self.bounds if isinstance(self.bounds[0], tuple) else (self.bounds,)
        return tuple((area, span) for area in areas for span in spans)

    def combined(self, values):
        """The measured value from the values of :attr:`parts`: a number for one part, else the tuple."""
        return tuple(values) if len(values) > 1 else values[0]

    def measure(self, case, method):
        return self.combined([self._one(area, span, case, method) for area, span in self.parts])

    def _one(self, area, bounds, case, method):
        lo, hi = (sp.sympify(b).xreplace(case.params) for b in bounds)
        origin = lo if self.origin is None else sp.sympify(self.origin).xreplace(case.params)
        area = area.xreplace(case.params)
        modules = "mpmath" if method.arithmetic == "mpmath" else "numpy"
        with mpmath.workdps(method.dps):
            lo_n, hi_n = (mpmath.mpf(sp.N(b, method.dps + 10)) for b in (lo, hi))
            f = sp.lambdify(self.z, area, modules)
            volume, _ = method.integrate(f, [lo_n, hi_n])
            if self.quantity == "volume":
                return volume
            g = sp.lambdify(self.z, (self.z - origin) * area, modules)
            moment, _ = method.integrate(g, [lo_n, hi_n])
            return moment if self.quantity == "moment" else moment / volume

    def enclose(self, case, bits):
        """The quantity by ``acb.integral`` (:func:`~symfloat.engine.enclosure.integral`), rigorous."""
        return self.combined([self._enclosed(area, span, case, bits) for area, span in self.parts])

    def _enclosed(self, area, bounds, case, bits):
        lo, hi = (sp.sympify(b).xreplace(case.params) for b in bounds)
        origin = lo if self.origin is None else sp.sympify(self.origin).xreplace(case.params)
        area = area.xreplace(case.params)
        volume = integral(area, self.z, lo, hi, bits)
        if self.quantity == "volume":
            return volume
        moment = integral((self.z - origin) * area, self.z, lo, hi, bits)
        with working_precision(bits):
            return moment if self.quantity == "moment" else moment / volume


def _combined(expr, areas, params):
    """*expr* (an expression or a tuple of them in ``measured("section 1")``, ... and the case's parameters)
    with the measured *areas* and the exact parameter values, in mpmath at the working precision."""
    items = expr if isinstance(expr, tuple) else (expr,)
    out = []
    for item in items:
        e = sp.sympify(item).xreplace(params)
        args = sorted(e.free_symbols, key=lambda q: q.name)
        sections = numbered("section", len(areas))
        if any(q not in sections for q in args):
            raise ValueError(f"{item} names {args}, not only the section areas and the case's parameters")
        value = sp.lambdify(args, e, "mpmath")(*(areas[sections.index(q)] for q in args))
        out.append(value if isinstance(value, mpmath.mpf) else mpmath.mpf(sp.Float(sp.N(value, mpmath.mp.dps + 10),
                                                                                     mpmath.mp.dps + 10)._mpf_))
    return tuple(out) if isinstance(expr, tuple) else out[0]


@dataclass(frozen=True)
class PlaneSections(MeasuredWitness):
    """Areas of plane sections of a solid, each by quadrature of the solid's chord
    widths across the section: ``width`` (in the plane position ``position`` and
    the chord coordinate ``across``) integrated over ``chord``, for each plane of
    ``planes``;
    ``combine`` turns the areas into the quantity the targets state: an expression (or a tuple) in
    ``measured("section 1")``, ``measured("section 2")``, ... (the area of each plane, in order) and the case's
    parameters (``sp.sqrt(measured("section 1") / pi)``, a radius).
    Witnesses the value-free displays (radii, section areas, their ratios)."""

    width: sp.Expr = None
    position: sp.Symbol = None
    across: sp.Symbol = None
    chord: tuple = ()
    planes: tuple = ()
    combine: object = None
    methods: tuple = (TANH_SINH_15, TANH_SINH_50)

    def measure(self, case, method):
        with mpmath.workdps(method.dps):
            areas = []
            for plane in self.planes:
                at = {**case.params, self.position: sp.sympify(plane).xreplace(case.params)}
                f = sp.lambdify(self.across, self.width.xreplace(at), "mpmath")
                lo, hi = (mpmath.mpf(sp.N(sp.sympify(e).xreplace(at), method.dps + 10)) for e in self.chord)
                areas.append(method.integrate(f, [lo, hi])[0])
            return self.combined(areas, case)

    def enclose(self, case, bits):
        """The planes' areas by ``acb.integral`` of the chord widths, combined in ball arithmetic."""
        areas = []
        for plane in self.planes:
            at = {**case.params, self.position: sp.sympify(plane).xreplace(case.params)}
            lo, hi = (sp.sympify(e).xreplace(at) for e in self.chord)
            areas.append(integral(self.width.xreplace(at), self.across, lo, hi, bits))
        items = self.combine if isinstance(self.combine, tuple) else (self.combine,)
        sections = dict(zip(numbered("section", len(areas)), areas))
        values = tuple(ball(sp.sympify(item).xreplace(case.params), bits, sections)
                       for item in items)
        return values if isinstance(self.combine, tuple) else values[0]

    def combined(self, areas, case):
        """The targets' quantity from the planes' *areas* at *case*, at the working precision."""
        return _combined(self.combine, areas, case.params)


@dataclass(frozen=True)
class ExactHull:
    """Hull faces in rational arithmetic: exact, no tolerance."""

    name: str = "exact hull faces, rational"
    tolerance: float = 0.0


@dataclass(frozen=True)
class HullSlices:
    """Slices of the hull (exact section areas at rationalised nodes)
    integrated by fixed-order Gauss–Legendre on the pieces between vertex
    heights, in ``dps``-digit arithmetic."""

    order: int = 3
    dps: int = 15
    tolerance: float = 1e-12

    @property
    def name(self):
        return f"slices, Gauss-Legendre n={self.order}, {self.dps} digits"

    def integrate(self, points, axis, weight_power):
        with mpmath.workdps(self.dps + 5):
            x, w = (np.polynomial.legendre.leggauss(self.order) if self.dps <= 15 else
                    _mp_leggauss(self.order))
            heights = sorted({p[axis] for p in points})
            total = mpmath.mpf(0)
            for a, b in zip(heights, heights[1:]):
                a, b = mpmath.mpf(a.numerator) / a.denominator, mpmath.mpf(b.numerator) / b.denominator
                half, mid = (b - a) / 2, (b + a) / 2
                for xi, wi in zip(x, w):
                    t = mid + half * mpmath.mpf(xi)
                    area = section_area(points, axis, _to_fraction(t))
                    total += half * mpmath.mpf(wi) * t ** weight_power * mpmath.mpf(area.numerator) / area.denominator
            return total


def _mp_leggauss(n):
    nodes = [mpmath.findroot(lambda t: mpmath.legendre(n, t), mpmath.cos(mpmath.pi * (k + 0.75) / (n + 0.5)))
             for k in range(n)]
    weights = [2 / ((1 - t ** 2) * mpmath.diff(lambda u: mpmath.legendre(n, u), t) ** 2) for t in nodes]
    return nodes, weights


def _mpf(q: Fraction):
    with mpmath.workdps(REFERENCE_DIGITS):
        return mpmath.mpf(q.numerator) / q.denominator


def _to_fraction(x):
    if isinstance(x, float):
        return Fraction(x)
    sign, man, exp, _ = mpmath.mpf(x)._mpf_
    return (-1) ** sign * Fraction(int(man)) * Fraction(2) ** int(exp)


@dataclass(frozen=True)
class HullWitness(MeasuredWitness):
    """Volume or centroid of the convex hull of ``case.data`` (3-D rational
    points).  ``quantity``: ``volume``, ``height`` (centroid coordinate along
    ``axis`` above the lowest vertex), ``moment`` (volume times height) or
    ``centroid`` (the vector)."""

    quantity: str = "volume"
    axis: int = 2
    methods: tuple = (ExactHull(), HullSlices(3, 15, 1e-12), HullSlices(3, 40, 1e-35))

    def measure(self, case, method):
        pts = case.data
        if isinstance(method, ExactHull):
            volume, centroid = hull_volume_centroid(pts)
            if self.quantity == "volume":
                return _mpf(volume)
            height = centroid[self.axis] - min(p[self.axis] for p in pts)
            if self.quantity in ("height", "moment"):
                return _mpf(height if self.quantity == "height" else height * volume)
            return tuple(_mpf(c) for c in centroid)
        with mpmath.workdps(method.dps + 5):
            if self.quantity == "volume":
                return method.integrate(pts, self.axis, 0)
            if self.quantity in ("height", "moment"):
                base = _mpf(min(p[self.axis] for p in pts))
                volume = method.integrate(pts, self.axis, 0)
                height = method.integrate(pts, self.axis, 1) / volume - base
                return height if self.quantity == "height" else height * volume
            volume = method.integrate(pts, 0, 0)
            return tuple(method.integrate(pts, ax, 1) / volume for ax in range(3))

    def enclose(self, case, bits):
        """The exact hull's quantity as exact rationals (balls of radius 0)."""
        volume, centroid = hull_volume_centroid(case.data)
        if self.quantity == "volume":
            return volume
        height = centroid[self.axis] - min(p[self.axis] for p in case.data)
        if self.quantity in ("height", "moment"):
            return height if self.quantity == "height" else height * volume
        return tuple(centroid)


@dataclass(frozen=True)
class FaceSections:
    """Side faces counted from two exact plane sections (:func:`~symfloat.geometry.convex.side_faces_by_sections`)."""

    name: str = "plane sections at 1/3 and 2/3 of the height, rational"
    tolerance: float = 0.0


@dataclass(frozen=True)
class SideFaces(MeasuredWitness):
    """The side faces of the convex hull of ``case.data`` (3-D rational points, each in one of the two extreme
    planes along ``axis``: a prismatoid) counted, and how many of them are triangles: ``(faces, triangles)``,
    from the exact hull's faces and, independently, from two plane sections."""

    axis: int = 2
    methods: tuple = (ExactHull(), FaceSections())

    def measure(self, case, method):
        count = side_faces if isinstance(method, ExactHull) else side_faces_by_sections
        return tuple(_mpf(Fraction(n)) for n in count(case.data, self.axis))

    def enclose(self, case, bits):
        """The counts of the exact hull's faces, exact."""
        return tuple(Fraction(n) for n in side_faces(case.data, self.axis))


@dataclass(frozen=True)
class ConvergenceOrder:
    """The measured order of a composite rule: the error of the rule applied
    to a smooth integrand with known integral, against the panel width, fitted
    by least squares on log–log axes.  Agrees when the fitted order lies within
    ``order ± slack``."""

    name: str
    description: str
    targets: tuple
    rule: object      # rule(f, a, b, panels) -> value, f an mpmath function
    integrand: object
    interval: tuple
    exact: object
    order: float
    panels: tuple = (2, 4, 8, 16, 32, 64)
    slack: float = 0.15
    dps: int = 40

    def run(self, readings, allowances=None):
        """An :class:`Outcome` for each targeted reading: the fitted order against ``order`` (a slope has no
        enclosure, so no certified decision; *allowances* are not used)."""
        records, errors = [], []
        with mpmath.workdps(self.dps):
            for n in self.panels:
                t0 = time.perf_counter()
                value = self.rule(self.integrand, *self.interval, n)
                seconds = time.perf_counter() - t0
                err = abs(value - self.exact)
                errors.append(err)
                records.append({"method": f"{self.description}, {n} panels ({self.dps} digits)",
                                "abs_error": float(err), "rel_error": float(err / abs(self.exact)),
                                "seconds": seconds, "cases": 1})
            xs = [mpmath.log(mpmath.mpf(1) / n) for n in self.panels]
            ys = [mpmath.log(e) for e in errors]
            mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
            slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
        measured = float(slope)
        agrees = abs(measured - self.order) <= self.slack
        for r in records:
            r.update(order=round(measured, 3), expected_order=self.order, slack=self.slack)
        note = f"measured order {measured:.3f} (expected {self.order:g})"
        return {t: Outcome(self.name, [dict(r) for r in records], agrees, note)
                for t in readings if t.split("#")[0] in self.targets}
