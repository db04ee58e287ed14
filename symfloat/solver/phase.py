"""Phase diagrams: the stable positions of a cube or box against the density.

The sweep solves the scene at densities ``s_k = k / (steps + 1)``; between
neighbours whose sets of stable positions differ, each threshold is located
by bisection on the density with the position *tracked* (Newton's method from
the last stable point): the predicate "the tracked equilibrium exists and is
stable" flips exactly at the threshold, so the bracket shrinks to ``1e-13``.
The thresholds are then compared with the closed forms the sources print.
Boxes are centrally symmetric, so the stable set at ``1 - s`` is the stable
set at ``s`` turned upside down; the sweep still solves both halves (the
duality is checked, not assumed).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np
import sympy as sp

from ..geometry.floating import box
from .bodies import make_scene
from .critical import newton
from .solve import body_scale, solve

__all__ = ["Threshold", "PhaseDiagram", "phase_diagram", "position_label", "source_thresholds"]

BRACKET = 1e-13


def position_label(up, family: str) -> str:
    """A name for a position class that does not change along a branch: which components of the
    (representative) up vector vanish or are equal."""
    u = [abs(x) for x in up]
    nonzero = [i for i in range(3) if u[i] > 1e-9]
    axes = "".join("xyz"[i] for i in nonzero)
    if family == "ring":
        return f"ring around {'xyz'[int(np.argmax(u))]}"
    if len(nonzero) == 1:
        return f"face {axes} up"
    values = [u[i] for i in nonzero]
    equal = max(values) - min(values) <= 1e-9
    if len(nonzero) == 2:
        return f"edge up ({axes})" if equal else f"tilted in the {axes[0]}-{axes[1]} plane"
    if equal:
        return "corner up"
    pairs = [(i, j) for i in range(3) for j in range(i + 1, 3) if abs(u[i] - u[j]) <= 1e-9]
    return f"tilted, |u_{'xyz'[pairs[0][0]]}| = |u_{'xyz'[pairs[0][1]]}|" if pairs else "tilted (general)"


@dataclass
class Threshold:
    density: float
    bracket: float
    label: str
    change: str                 # "stable below" or "stable above"
    source: list = field(default_factory=list)


@dataclass
class PhaseDiagram:
    body: str
    dims: tuple
    densities: list
    stable: list                # per density: sorted labels of the stable positions
    thresholds: list
    duality_ok: bool
    seconds: float


def _stable(scene):
    sol = solve(scene)
    return {position_label(e.up, e.family): e for e in sol.equilibria if e.stability == "stable"}


def _tracked_stable(poly, u, s, label, family, scale) -> tuple[bool, np.ndarray]:
    """Whether the equilibrium tracked from *u* exists at density *s*, keeps its label and is
    stable.  The sign of the second variation decides (no indifference band), so the predicate
    flips at the threshold itself.  A ring must stay a ring: off every axis, one null direction,
    positive across."""
    loc, ok = newton(poly, u, s, scale)
    if not ok:
        return False, u
    w = sorted(loc.eigen()[0], key=abs)
    if family == "ring":
        tilted = position_label(loc.u, "isolated").startswith("tilted")
        off_axis = min(np.linalg.norm(np.abs(loc.u) - e) for e in np.eye(3)) > 1e-6
        return tilted and off_axis and w[1] > 0, loc.u
    return position_label(loc.u, family) == label and min(w) > 0, loc.u


def _locate(poly, scale, label, eq, s_in, s_out) -> tuple[float, float]:
    """Bisection between *s_in* (label stable) and *s_out* (not) with tracking."""
    u = np.array(eq.up)
    lo, hi = s_in, s_out
    while abs(hi - lo) > BRACKET:
        mid = (lo + hi) / 2
        ok, u_mid = _tracked_stable(poly, u, mid, label, eq.family, scale)
        if ok:
            lo, u = mid, u_mid
        else:
            hi = mid
    err = abs(hi - lo) / 2
    if eq.family == "ring":
        # a family is born from (or dies into) a point where the potential is quartic: Newton stops
        # early there, and the density is known only to about the square of the family's tilt
        tilt = min(math.acos(min(1.0, abs(float(x)))) for x in u)
        err = max(err, tilt ** 2)
    return (lo + hi) / 2, err


def source_thresholds(body: str, dims) -> list[dict]:
    """Thresholds in the density that the sources print in closed form, for this body: each
    ``{"value", "expression", "locator", "derivation"}`` (values from the derivations' results)."""
    from ..registry import load
    out = []
    if body == "cube" or (body == "box" and len(set(dims)) == 1):
        d, _ = load("scheeffer-vi-cf")
        results = {str(k): v for k, v in d.results().items()}
        for name, locator in (("s_-", "(79)"), ("s_+", "(79)"), ("s_80-", "(80)"), ("s_80+", "(80)"),
                              ("s_e-", "VI.D"), ("s_e+", "VI.D")):
            if name in results:
                expr = sp.nsimplify(results[name])
                out.append({"value": float(sp.N(expr, 30)), "expression": str(expr), "locator": locator,
                            "derivation": "scheeffer-vi-cf"})
    return out


def phase_diagram(body: str, dims=None, steps: int = 48, progress=None) -> PhaseDiagram:
    start = time.perf_counter()
    base = make_scene(body, "1/2", dims)
    poly = box(*base.dims)
    scale = body_scale(base)
    densities = [Fraction(k, steps + 1) for k in range(1, steps + 1)]
    stable = []
    for i, s in enumerate(densities, 1):
        if progress:
            progress(f"[{i}/{len(densities)}] density {float(s):.4f}")
        stable.append(_stable(make_scene(body, s, base.dims)))
    thresholds = []
    for k in range(len(densities) - 1):
        a, b = stable[k], stable[k + 1]
        sa, sb = float(densities[k]), float(densities[k + 1])
        for label in sorted(set(a) - set(b)):
            value, err = _locate(poly, scale, label, a[label], sa, sb)
            thresholds.append(Threshold(value, err, label, "stable below"))
        for label in sorted(set(b) - set(a)):
            value, err = _locate(poly, scale, label, b[label], sb, sa)
            thresholds.append(Threshold(value, err, label, "stable above"))
    known = source_thresholds(body, base.dims)
    for t in thresholds:
        t.source = [k for k in known if abs(k["value"] - t.density) <= 1e-9]
    labels = [sorted(x) for x in stable]
    duality_ok = all(labels[k] == labels[len(labels) - 1 - k] for k in range(len(labels)))
    thresholds.sort(key=lambda t: (t.density, t.label))
    return PhaseDiagram(body, tuple(str(d) for d in base.dims), [float(s) for s in densities], labels, thresholds,
                        duality_ok, time.perf_counter() - start)
