"""The atlas grid from the command line: exact values, checked before any work.

A grid is written ``A:B:N`` (N evenly spaced values from A to B, both included), as a
comma-separated list ``1,2,5,20``, or as one value ``2``.  Every number is an ASCII decimal or
``p/q`` literal read exactly (:func:`symfloat.solver.bodies.parse_number`, no evaluation).

>>> parse_grid("1:2:3", "--ba")
[Fraction(1, 1), Fraction(3, 2), Fraction(2, 1)]
>>> parse_grid("1,2,5,20", "--ca")
[Fraction(1, 1), Fraction(2, 1), Fraction(5, 1), Fraction(20, 1)]
>>> density_grid("1/10:9/10:5")
[Fraction(1, 10), Fraction(3, 10), Fraction(1, 2), Fraction(7, 10), Fraction(9, 10)]
"""
from __future__ import annotations

from fractions import Fraction

from ..solver.bodies import SceneError, make_scene, parse_number, parse_whole

__all__ = ["parse_grid", "density_grid", "shape_grid", "cell_body", "check_domain", "MAX_POINTS", "MAX_RATIO",
           "MAX_CELLS"]

MAX_POINTS = 2000           # values on one axis
MAX_CELLS = 10000           # shapes b/a x c/a in one atlas (about 60 worker-hours at 22 s a cell, docs/atlas.md)
MAX_RATIO = Fraction(1000)  # an aspect ratio b/a or c/a


def parse_grid(text, what: str) -> list[Fraction]:
    """The values of a grid ``A:B:N``, ``v1,v2,...`` or ``v`` (exact, increasing, distinct)."""
    t = str(text).strip()
    if t.count(":") == 2:
        a_text, b_text, n_text = t.split(":")
        a, b = parse_number(a_text, f"{what} start"), parse_number(b_text, f"{what} end")
        n = parse_whole(n_text, f"{what} count", 1, MAX_POINTS)
        if n == 1 and a != b:
            raise SceneError(f"{what} {t[:40]!r}: one value needs start = end (or write the value alone)")
        if n > 1 and not a < b:
            raise SceneError(f"{what} {t[:40]!r}: the start must be smaller than the end")
        return [a] if n == 1 else [a + (b - a) * k / (n - 1) for k in range(n)]
    if ":" in t:
        raise SceneError(f"{what} is a grid A:B:N (N values from A to B), a list v1,v2,... or one value, "
                         f"not {t[:40]!r}")
    items = t.split(",")
    if len(items) > MAX_POINTS:
        raise SceneError(f"{what} lists {len(items)} values; at most {MAX_POINTS}")
    values = [parse_number(x, what) for x in items]
    if any(not x < y for x, y in zip(values, values[1:])):
        raise SceneError(f"{what} {t[:40]!r}: list the values in increasing order, each once")
    return values


def shape_grid(text, what: str) -> list[Fraction]:
    """An aspect-ratio axis (``--ba``, ``--ca``): values in (0, MAX_RATIO]."""
    values = parse_grid(text, what)
    if values[0] <= 0 or values[-1] > MAX_RATIO:
        raise SceneError(f"{what} ratios must lie in (0, {MAX_RATIO}], got {text!s:.40}")
    return values


def density_grid(text) -> list[Fraction]:
    """The sweep of densities: at least 2 values in (0, 1), symmetric about 1/2 (A + B = 1), so
    that the duality s <-> 1 - s of the centrally symmetric box can be checked on the sweep."""
    values = parse_grid(text, "--density")
    if len(values) < 2:
        raise SceneError("--density needs at least 2 values (A:B:N with N >= 2)")
    if not 0 < values[0] < values[-1] < 1:
        raise SceneError(f"--density values must lie strictly between 0 and 1 (water = 1), got {text!s:.40}")
    if any(x + y != 1 for x, y in zip(values, reversed(values))):
        raise SceneError(f"--density must be symmetric about 1/2 (A + B = 1, each s with its 1 - s) for the "
                         f"duality check, got {text!s:.40}")
    return values


def cell_body(ba: Fraction, ca: Fraction) -> tuple[str, tuple[Fraction, Fraction, Fraction]]:
    """The body of a shape cell: edges ``1, b/a, c/a`` along x, y, z; the cell 1, 1 is the cube.

    >>> cell_body(Fraction(1), Fraction(1))
    ('cube', (Fraction(1, 1), Fraction(1, 1), Fraction(1, 1)))
    """
    dims = (Fraction(1), Fraction(ba), Fraction(ca))
    return ("cube" if dims[1] == dims[2] == 1 else "box"), dims


def check_domain(ba_values, ca_values, densities) -> None:
    """At most :data:`MAX_CELLS` shapes, and every shape at both ends of the sweep is a scene the solver
    answers (else one line)."""
    if len(ba_values) * len(ca_values) > MAX_CELLS:
        raise SceneError(f"the grid has {len(ba_values)} x {len(ca_values)} = {len(ba_values) * len(ca_values)} "
                         f"shapes; an atlas takes at most {MAX_CELLS} (split it into several --out folders)")
    for ba in ba_values:
        for ca in ca_values:
            body, dims = cell_body(ba, ca)
            for s in (densities[0], densities[-1]):
                try:
                    make_scene(body, s, dims)
                except SceneError as exc:
                    raise SceneError(f"shape b/a = {ba}, c/a = {ca}: {exc}") from None
