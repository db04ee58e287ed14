"""Scenes from user input: parsing without eval, the stated domain, and the body each scene floats.

Every number is parsed by :class:`fractions.Fraction` from an ASCII decimal or ``p/q`` literal
(no expression evaluation), so scenes are exact.  Input outside the domain below raises
:class:`SceneError` with one message that states the range; nothing is solved.

The domain is what the solver answers to its stated accuracy (the Poincaré–Hopf index sum
closes, every position carries its error bound); it was measured, and the tests sample it
(``tests/test_input_domain.py``):

* a number: at most 64 characters, exponent within ±400, finite;
* sizes: every dimension, and the largest polygon coordinate, at most 1e6; the longest
  dimension at least 1e-6 (choose units so);
* the thinnest layer: ``min(s, 1 - s) * thinnest / longest >= 1e-4``, where *thinnest* and
  *longest* are the body's smallest width and largest extent (box: its edges; prism: the base's
  width and diameter and the length; cylinder: ``2r`` and ``b``; section: the polygon's width
  and diameter).  The draught (or freeboard) of the body lying flat is then at least 1e-4 of
  its size; at 1e-7 the index sum of the cube no longer closes (``1e-15`` and dims
  ``1,1e-9,1`` gave wrong answers), and at aspect ratios below 3e-5 the waterplane can no
  longer be named;
* a prism has 3 to 128 sides and a section 3 to 64 vertices (a 128-gon prism takes about
  7 s, a 64-gon section about 4 s; time grows with the square of the count).
"""
from __future__ import annotations

import dataclasses
import functools
import math
import re
from fractions import Fraction

from ..errors import InputError
from ..geometry.convex import hull_2d, polygon_area
from ..geometry.floating import box, regular_prism, right_prism
from ..model.prediction import BODIES, Scene

__all__ = ["SceneError", "parse_number", "parse_whole", "parse_dims", "parse_polygon", "make_scene",
           "thinness", "polyhedron", "centred_polygon", "MAX_SIDES", "MAX_VERTICES", "MAX_SIZE", "MIN_SIZE",
           "MIN_LAYER", "DOMAIN", "least_layer"]

_LITERAL = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE]([+-]?[0-9]+))?(?:/[0-9]+)?", re.ASCII)
_WHOLE = re.compile(r"[0-9]+", re.ASCII)
DIMS = {"cube": 1, "box": 3, "prism": 2, "cylinder": 2, "section": 0}
MAX_LITERAL = 64            # characters of one number
MAX_EXPONENT = 400          # |e| of a decimal exponent (every value beyond is outside every range)
MAX_SIDES = 128
MAX_VERTICES = 64
MAX_SIZE = Fraction(10**6)
MIN_SIZE = Fraction(1, 10**6)
MIN_LAYER = 1e-4            # min(s, 1 - s) * thinnest / longest
DOMAIN = (f"sizes up to {float(MAX_SIZE):g}, the longest at least {float(MIN_SIZE):g}; "
          f"min(s, 1 - s) x thinnest/longest >= {MIN_LAYER:g}; prism 3 to {MAX_SIDES} sides; "
          f"section 3 to {MAX_VERTICES} vertices")


class SceneError(InputError):
    """Bad scene input; the message says what and why (exit status 2)."""


def parse_number(text, what: str) -> Fraction:
    """A finite rational number from an ASCII decimal (``0.22``, ``1e-3``) or ``p/q`` literal.

    >>> parse_number(" 2/9 ", "density")
    Fraction(2, 9)
    >>> parse_number("0.5/2", "density")        # a decimal over a whole number
    Fraction(1, 4)
    """
    t = str(text).strip()
    if t.lower().lstrip("+-") in ("nan", "inf", "infinity"):
        raise SceneError(f"{what} must be a finite number, not {_shown(text)}")
    match = _LITERAL.fullmatch(t) if len(t) <= MAX_LITERAL else None
    if match is None:
        raise SceneError(f"{what} must be a number like 0.22, 1e-3 or 2/9 (ASCII digits, at most "
                         f"{MAX_LITERAL} characters), not {_shown(text)}")
    if match.group(1) is not None and abs(int(match.group(1))) > MAX_EXPONENT:
        raise SceneError(f"{what} {_shown(text)} is out of range (exponent beyond ±{MAX_EXPONENT})")
    numerator, _, denominator = t.partition("/")
    if denominator and int(denominator) == 0:
        raise SceneError(f"{what} {_shown(text)} divides by zero")
    return Fraction(numerator) / int(denominator or 1)


def parse_whole(text, what: str, low: int, high: int) -> int:
    """A whole number written in ASCII digits, ``low <= n <= high``.

    >>> parse_whole("48", "--steps", 4, 2000)
    48
    """
    t = str(text).strip()
    if not (len(t) <= MAX_LITERAL and _WHOLE.fullmatch(t)):
        raise SceneError(f"{what} must be a whole number from {low} to {high}, not {_shown(text)}")
    n = int(t)
    if not low <= n <= high:
        raise SceneError(f"{what} must lie between {low} and {high}, got {n}")
    return n


def _shown(text) -> str:
    """The user's text for a message: quoted, on one line, at most 40 characters."""
    t = repr(str(text))
    return t if len(t) <= 40 else t[:36] + "...'"


def parse_dims(text: str | None, count: int, body: str) -> tuple[Fraction, ...]:
    """``count`` positive dimensions separated by commas."""
    if text is None:
        raise SceneError(f"{body} needs --dims with " + ("one positive number" if count == 1 else
                                                          f"{count} positive numbers"))
    parts = str(text).split(",")
    if len(parts) != count:
        wanted = "one number" if count == 1 else f"{count} comma-separated numbers"
        raise SceneError(f"{body} needs --dims with {wanted}, got {_shown(text)}")
    dims = tuple(parse_number(p, f"{body} dimension") for p in parts)
    if any(d <= 0 for d in dims):
        raise SceneError(f"{body} dimensions must be positive, got {_shown(text)}")
    return dims


def parse_polygon(text: str | None) -> tuple[tuple[Fraction, Fraction], ...]:
    """``"x1,y1 x2,y2 ..."``: the vertices of a convex polygon in order (either orientation); a ring closed by
    repeating its first vertex at the end (as GeoJSON writes one) is read without the repetition."""
    if not text or not str(text).strip():
        raise SceneError('section needs --polygon "x1,y1 x2,y2 ..." with at least 3 vertices')
    items = str(text).split()
    if len(items) > MAX_VERTICES:
        raise SceneError(f"the polygon has {len(items)} vertices; the solver takes at most {MAX_VERTICES}")
    points = []
    for item in items:
        xy = item.split(",")
        if len(xy) != 2:
            raise SceneError(f"polygon vertex {_shown(item)} is not of the form x,y")
        points.append((parse_number(xy[0], "polygon coordinate"), parse_number(xy[1], "polygon coordinate")))
    if len(points) > 3 and points[0] == points[-1]:
        points.pop()
    return _convex(points)


def _convex(points):
    if len(points) < 3:
        raise SceneError("the polygon needs at least 3 vertices")
    if len(points) > MAX_VERTICES:
        raise SceneError(f"the polygon has {len(points)} vertices; the solver takes at most {MAX_VERTICES}")
    if len(set(points)) != len(points):
        raise SceneError("the polygon repeats a vertex")
    if max(abs(c) for p in points for c in p) > MAX_SIZE:
        raise SceneError(f"polygon coordinates must lie within ±{float(MAX_SIZE):g} (choose units so)")
    if polygon_area(points) < 0:
        points = points[::-1]
    hull = hull_2d(points)
    if polygon_area(points) == 0:
        raise SceneError("the polygon has zero area (its vertices lie on one line)" if len(hull) < 3 else
                         "the polygon is self-intersecting: give the vertices in order around it")
    if len(hull) != len(points):
        raise SceneError("the polygon is not convex (or has collinear vertices): the solver needs a "
                         "strictly convex cross-section")
    start = points.index(hull[0])
    if points[start:] + points[:start] != hull:
        raise SceneError("the polygon is self-intersecting: give the vertices in order around it")
    return tuple(points)


def _polygon_extent(points) -> tuple[float, float]:
    """Width (the smallest distance between two parallel supporting lines: for a convex polygon,
    one of them carries an edge) and diameter of a convex polygon, computed from its exact vertices
    (squares of distances in rational arithmetic: distinct vertices that round to one float, 1e-400
    apart, still have an edge of non-zero length).

    >>> _polygon_extent([(Fraction(0), Fraction(0)), (Fraction(4), Fraction(0)), (Fraction(0), Fraction(3))])
    (2.4, 5.0)
    """
    n = len(points)
    diameter2 = max((px - qx) ** 2 + (py - qy) ** 2 for px, py in points for qx, qy in points)
    width2 = None
    for i in range(n):
        (ax, ay), (bx, by) = points[i], points[(i + 1) % n]
        height = max(abs((bx - ax) * (py - ay) - (by - ay) * (px - ax)) for px, py in points)
        w2 = height ** 2 / ((bx - ax) ** 2 + (by - ay) ** 2)
        width2 = w2 if width2 is None or w2 < width2 else width2
    return math.sqrt(width2), math.sqrt(diameter2)


def thinness(scene: Scene) -> tuple[float, float]:
    """``(thinnest, longest)``: the body's smallest width and largest extent.

    >>> thinness(Scene("box", Fraction(1, 2), (Fraction(1), Fraction(2), Fraction(3))))
    (1.0, 3.0)
    """
    if scene.body == "section":
        return _polygon_extent(centred_polygon(scene))
    if scene.body == "prism":
        n, a, b = scene.sides, float(scene.dims[0]), float(scene.dims[1])
        outer, inner = a / (2 * math.sin(math.pi / n)), a / (2 * math.tan(math.pi / n))
        width = 2 * inner if n % 2 == 0 else inner + outer
        diameter = 2 * outer if n % 2 == 0 else 2 * outer * math.cos(math.pi / (2 * n))
        return min(width, b), max(diameter, b)
    if scene.body == "cylinder":
        r, b = (float(x) for x in scene.dims)
        return min(2 * r, b), max(2 * r, b)
    return float(min(scene.dims)), float(max(scene.dims))


def least_layer(scene: Scene) -> float:
    """The least ``min(s, 1 - s)`` the solver handles for the scene's shape: ``MIN_LAYER`` over
    thinnest/longest (:data:`DOMAIN`).

    >>> least_layer(Scene("box", Fraction(1, 2), (Fraction(1), Fraction(1, 100), Fraction(1))))
    0.01
    """
    thinnest, longest = thinness(scene)
    return MIN_LAYER * longest / thinnest


def _in_domain(scene: Scene, density_text) -> Scene:
    """*scene* when the solver answers it to its stated accuracy, else :class:`SceneError`."""
    sizes = scene.dims
    if any(d > MAX_SIZE for d in sizes):
        raise SceneError(f"{scene.body} dimensions must be at most {float(MAX_SIZE):g} (choose units so)")
    thinnest, longest = thinness(scene)
    if longest < float(MIN_SIZE) * (1 - 1e-12):                     # the bound itself is inside
        raise SceneError(f"the {scene.body} measures {longest:.3g} across; the solver needs at least "
                         f"{float(MIN_SIZE):g} (choose units so)")
    ratio = thinnest / longest
    if ratio < 2 * MIN_LAYER:
        shown = f"{ratio:.3g}" if ratio > 0 else "below 1e-300"
        raise SceneError(f"the {scene.body} is too thin: thinnest/longest = {shown}; the solver handles "
                         f"{2 * MIN_LAYER:g} and more (min(s, 1 - s) x thinnest/longest >= {MIN_LAYER:g})")
    s, low = scene.density, least_layer(scene)
    if float(min(s, 1 - s)) < low * (1 - 1e-12):      # the bound itself is inside
        allowed = "so only s = 1/2" if low >= 0.5 * (1 - 1e-12) else f"so {low:.3g} <= s <= 1 - {low:.3g}"
        raise SceneError(f"density {density_text} is outside the range the solver handles for this "
                         f"{scene.body}: min(s, 1 - s) x thinnest/longest must be at least {MIN_LAYER:g} "
                         f"(thinnest/longest = {ratio:.3g}), {allowed}")
    return scene


def make_scene(body: str, density, dims=None, sides=None, polygon=None) -> Scene:
    """A validated :class:`Scene` from strings or numbers (as the command line gives them)."""
    if body not in BODIES:
        raise SceneError(f"unknown body {_shown(body)}; choose one of {', '.join(BODIES)}")
    if density is None:
        raise SceneError("--density is required (0 < s < 1, water = 1)")
    s = parse_number(density, "density") if isinstance(density, str) else Fraction(density)
    shown = _shown(density) if isinstance(density, str) else str(s)
    if not 0 < s < 1:
        raise SceneError(f"density must lie strictly between 0 and 1 (water = 1), got {shown}")
    if body == "section":
        if dims:
            raise SceneError("section takes --polygon, not --dims")
        if sides is not None:
            raise SceneError("section takes no --sides")
        points = (parse_polygon(polygon) if isinstance(polygon, str) or polygon is None
                  else _convex([tuple(Fraction(c) for c in p) for p in polygon]))
        return _in_domain(Scene("section", s, (), None, points), shown)
    if polygon:
        raise SceneError(f"{body} takes --dims, not --polygon")
    n = None
    if body == "prism":
        if sides is None:
            raise SceneError(f"prism needs --sides N (3 <= N <= {MAX_SIDES})")
        n = parse_whole(sides, "--sides", 3, MAX_SIDES)
    elif sides is not None:
        raise SceneError(f"{body} takes no --sides")
    if body == "cube":
        d = (Fraction(1),) if dims is None else parse_dims(dims, 1, body) if isinstance(dims, str) else \
            tuple(Fraction(x) for x in dims)
        if len(d) not in (1, 3) or len(set(d)) != 1 or d[0] <= 0:
            raise SceneError("cube takes --dims a (one positive edge) or nothing (edge 1)")
        return _in_domain(Scene("cube", s, (d[0],) * 3), shown)
    count = DIMS[body]
    d = parse_dims(dims, count, body) if isinstance(dims, str) or dims is None else tuple(Fraction(x) for x in dims)
    if len(d) != count or any(x <= 0 for x in d):
        raise SceneError(f"{body} needs {count} positive dimensions")
    return _in_domain(Scene(body, s, d, n), shown)


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
    """The convex polyhedron of a cube, box, prism or section scene (a section is a prism of length 1); in float64
    it makes itself again at any digits from the scene (``at_digits``)."""
    if scene.body in ("cube", "box"):
        body = box(*scene.dims, dps=dps)
    elif scene.body == "prism":
        body = regular_prism(scene.sides, scene.dims[0], scene.dims[1], dps=dps)
    elif scene.body == "section":
        body = right_prism(centred_polygon(scene), 1, dps=dps)
    else:
        raise SceneError(f"{scene.body} is not a polyhedron")
    return body if dps is not None else dataclasses.replace(body, at_digits=functools.partial(polyhedron, scene))
