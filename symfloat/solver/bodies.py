"""Scenes from user input: parsing without eval, validation, and the body each scene floats.

Every number is parsed by :class:`fractions.Fraction` from a decimal or
``p/q`` literal (no expression evaluation), so scenes are exact; a bad value
raises :class:`SceneError` with one message.
"""
from __future__ import annotations

import re
from fractions import Fraction

from ..geometry.convex import hull_2d, polygon_area
from ..geometry.floating import box, regular_prism, right_prism
from ..model.prediction import BODIES, Scene

__all__ = ["SceneError", "parse_number", "parse_dims", "parse_polygon", "make_scene", "polyhedron",
           "centred_polygon"]

_LITERAL = re.compile(r"^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?(/\d+)?$")
DIMS = {"cube": 1, "box": 3, "prism": 2, "cylinder": 2, "section": 0}
MAX_SIDES = 100_000


class SceneError(ValueError):
    """Bad scene input; the message says what and why."""


def parse_number(text: str, what: str) -> Fraction:
    """A finite rational number from a decimal (``0.22``, ``1e-3``) or ``p/q`` literal."""
    t = str(text).strip()
    if t.lower().lstrip("+-") in ("nan", "inf", "infinity"):
        raise SceneError(f"{what} must be a finite number, not {text!r}")
    if not _LITERAL.match(t):
        raise SceneError(f"{what} must be a number like 0.22, 1e-3 or 2/9, not {text!r}")
    try:
        return Fraction(t)
    except (ValueError, ZeroDivisionError):
        raise SceneError(f"{what} must be a number like 0.22, 1e-3 or 2/9, not {text!r}") from None


def parse_dims(text: str | None, count: int, body: str) -> tuple[Fraction, ...]:
    """``count`` positive dimensions separated by commas."""
    if text is None:
        raise SceneError(f"{body} needs --dims with {count} positive numbers")
    parts = [p for p in str(text).split(",")]
    if len(parts) != count:
        raise SceneError(f"{body} needs --dims with {count} comma-separated numbers, got {text!r}")
    dims = tuple(parse_number(p, f"{body} dimension") for p in parts)
    if any(d <= 0 for d in dims):
        raise SceneError(f"{body} dimensions must be positive, got {text!r}")
    return dims


def parse_polygon(text: str | None) -> tuple[tuple[Fraction, Fraction], ...]:
    """``"x1,y1 x2,y2 ..."``: the vertices of a convex polygon in order (either orientation)."""
    if not text:
        raise SceneError('section needs --polygon "x1,y1 x2,y2 ..." with at least 3 vertices')
    points = []
    for item in str(text).split():
        xy = item.split(",")
        if len(xy) != 2:
            raise SceneError(f"polygon vertex {item!r} is not of the form x,y")
        points.append((parse_number(xy[0], "polygon coordinate"), parse_number(xy[1], "polygon coordinate")))
    return _convex(points)


def _convex(points):
    if len(points) < 3:
        raise SceneError("the polygon needs at least 3 vertices")
    if len(set(points)) != len(points):
        raise SceneError("the polygon repeats a vertex")
    if polygon_area(points) < 0:
        points = points[::-1]
    if polygon_area(points) == 0:
        raise SceneError("the polygon has zero area")
    hull = hull_2d(points)
    if len(hull) != len(points):
        raise SceneError("the polygon is not convex (or has collinear vertices): the solver needs a "
                         "strictly convex cross-section")
    start = points.index(hull[0])
    if points[start:] + points[:start] != hull:
        raise SceneError("the polygon is self-intersecting: give the vertices in order around it")
    return tuple(points)


def make_scene(body: str, density, dims=None, sides=None, polygon=None) -> Scene:
    """A validated :class:`Scene` from strings or numbers (as the command line gives them)."""
    if body not in BODIES:
        raise SceneError(f"unknown body {body!r}; choose one of {', '.join(BODIES)}")
    if density is None:
        raise SceneError("--density is required (0 < s < 1, water = 1)")
    s = parse_number(density, "density") if isinstance(density, str) else Fraction(density)
    if not 0 < s < 1:
        raise SceneError(f"density must lie strictly between 0 and 1 (water = 1), got {density}")
    if body == "section":
        if dims:
            raise SceneError("section takes --polygon, not --dims")
        return Scene("section", s, (), None, parse_polygon(polygon) if isinstance(polygon, str) or polygon is None
                     else _convex([tuple(Fraction(c) for c in p) for p in polygon]))
    if polygon:
        raise SceneError(f"{body} takes --dims, not --polygon")
    n = None
    if body == "prism":
        if sides is None:
            raise SceneError("prism needs --sides N (N >= 3)")
        try:
            n = int(str(sides))
        except ValueError:
            raise SceneError(f"--sides must be a whole number >= 3, not {sides!r}") from None
        if not 3 <= n <= MAX_SIDES:
            raise SceneError(f"--sides must lie between 3 and {MAX_SIDES}, got {n}")
    elif sides is not None:
        raise SceneError(f"{body} takes no --sides")
    if body == "cube":
        d = (Fraction(1),) if dims is None else parse_dims(dims, 1, body) if isinstance(dims, str) else \
            tuple(Fraction(x) for x in dims)
        if len(d) not in (1, 3) or len(set(d)) != 1 or d[0] <= 0:
            raise SceneError("cube takes --dims a (one positive edge) or nothing (edge 1)")
        return Scene("cube", s, (d[0],) * 3)
    count = DIMS[body]
    d = parse_dims(dims, count, body) if isinstance(dims, str) or dims is None else tuple(Fraction(x) for x in dims)
    if len(d) != count or any(x <= 0 for x in d):
        raise SceneError(f"{body} needs {count} positive dimensions")
    return Scene(body, s, d, n)


def centred_polygon(scene: Scene) -> list[tuple[Fraction, Fraction]]:
    """The section polygon moved so that its centroid is the origin (the body frame)."""
    pts = list(scene.polygon)
    n = len(pts)
    area = polygon_area(pts)
    cx = sum((pts[i][0] + pts[(i + 1) % n][0]) * (pts[i][0] * pts[(i + 1) % n][1] - pts[(i + 1) % n][0] * pts[i][1])
             for i in range(n)) / (6 * area)
    cy = sum((pts[i][1] + pts[(i + 1) % n][1]) * (pts[i][0] * pts[(i + 1) % n][1] - pts[(i + 1) % n][0] * pts[i][1])
             for i in range(n)) / (6 * area)
    return [(x - cx, y - cy) for x, y in pts]


def polyhedron(scene: Scene, dps=None):
    """The convex polyhedron of a cube, box, prism or section scene (a section is a prism of length 1)."""
    if scene.body in ("cube", "box"):
        return box(*scene.dims, dps=dps)
    if scene.body == "prism":
        return regular_prism(scene.sides, scene.dims[0], scene.dims[1], dps=dps)
    if scene.body == "section":
        return right_prism(centred_polygon(scene), 1, dps=dps)
    raise SceneError(f"{scene.body} is not a polyhedron")
