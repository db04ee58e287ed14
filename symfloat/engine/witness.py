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
by itself whether the formula agrees with the witness.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from ..geometry.convex import hull_volume_centroid, section_area, side_faces, side_faces_by_sections
from ..model.claim import members
from .quadrature import DEFAULT_METHODS, TANH_SINH_15, TANH_SINH_50

__all__ = ["Case", "Outcome", "record_agrees", "MeasuredWitness", "Precision", "SectionIntegral", "PlaneSections", "SECTION",
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
    """What one witness found for one targeted formula."""

    witness: str
    records: list = field(default_factory=list)
    agrees: bool = True
    note: str = ""
    measurable: bool = True     # False: the formula has nothing a number could check (it restates a definition)


def record_agrees(record: dict) -> bool:
    """Whether a witness record lies within the bound it carries: ``abs_tolerance`` (a printed number's
    precision; 0 for a count, which must be exact), else ``rel_tolerance`` (the method's), else a
    measured convergence ``order`` within ``slack`` of ``expected_order``.  A record with none of them
    agrees with nothing.

    >>> record_agrees({"abs_error": 1e-3, "rel_error": 2e-2, "rel_tolerance": 1e-10})
    False
    >>> record_agrees({"abs_error": 1e-3, "rel_error": 2e-2, "abs_tolerance": 5e-3})
    True
    >>> record_agrees({"order": 3.96, "expected_order": 4, "slack": 0.15})
    True
    """
    if "abs_tolerance" in record:
        return record["abs_error"] <= record["abs_tolerance"]
    if "rel_tolerance" in record:
        return record["rel_error"] <= record["rel_tolerance"]
    if "expected_order" in record:
        return record["order"] is not None and abs(record["order"] - record["expected_order"]) <= record["slack"]
    return False


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


@dataclass(frozen=True)
class MeasuredWitness:
    """Common machinery: time each method over the cases, compare targets.

    ``cases`` is a tuple of :class:`Case`, or a function returning one: it is
    called on first use, so that declaring a witness costs nothing at import."""

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

    def measure(self, case: Case, method):
        raise NotImplementedError  # pragma: no cover - abstract

    def run(self, readings: dict) -> dict:
        measured = {}
        for method in self.methods:
            t0 = time.perf_counter()
            values = [self.measure(case, method) for case in self.instances]
            measured[method] = (values, time.perf_counter() - t0)
        outcomes = {}
        for target in readings:
            if target.split("#")[0] not in self.targets:
                continue
            expected_by_case = [_expected(readings[target], case.params) for case in self.instances]
            for case, expected in zip(self.instances, expected_by_case):
                if not expected:
                    raise ValueError(f"witness {self.name}: no member of {target} is a number at {case.label}")
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
                if not record_agrees(out.records[-1]):
                    out.agrees = False
            if not out.agrees:
                out.note = f"{self.description}: disagrees beyond the methods' tolerances"
            outcomes[target] = out
        return outcomes


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


SECTION = sp.symbols("section_area0:16")    # the areas of the planes of a PlaneSections witness, in order


def _combined(expr, areas, params):
    """*expr* (an expression or a tuple of them in :data:`SECTION` and the case's parameters) with the measured
    *areas* and the exact parameter values, in mpmath at the working precision."""
    items = expr if isinstance(expr, tuple) else (expr,)
    out = []
    for item in items:
        e = sp.sympify(item).xreplace(params)
        args = sorted(e.free_symbols, key=lambda q: q.name)
        if any(q not in SECTION[:len(areas)] for q in args):
            raise ValueError(f"{item} names {args}, not only the section areas and the case's parameters")
        value = sp.lambdify(args, e, "mpmath")(*(areas[SECTION.index(q)] for q in args))
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
    ``SECTION[i]``, the area of the i-th plane, and the case's parameters (``sp.sqrt(SECTION[0] / pi)``, a
    radius).
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

    def run(self, readings):
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
