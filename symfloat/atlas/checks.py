"""Checks of a finished atlas that can fail, and the printed statements it is held against.

Failing checks (the command exits 1 when one fails):

* **cells**: every cell was computed and every interval's sample solved (a solver self-check that
  failed, in the sweep or at a sample, is recorded in the row's ``failure``);
* **Poincaré–Hopf**: the index sum at every other sample is 2, families counted with the winding round them
  (a sample without a sum fails);
* **sweep**: the stable set at an interval's midpoint is the one the sweep saw inside it;
* **duality s ↔ 1 − s**, per cell, inside the swept range: the sweep mirrors and every threshold has
  its dual (the phase machinery's check), and the intervals mirror:
  boundary k at ``1 -`` boundary m-1-k within their errors, the same stable positions in
  interval k and in interval n-1-k (the box turned upside down is the same box);
* **same box, edges renamed**: two cells that are one box (1 x 2 x 1 and 1 x 1 x 2) have the same
  boundaries within their errors and the same number of stable classes between them;
* **cube**: the cell b/a = c/a = 1 has the thresholds of ``symfloat phase cube`` (48 densities)
  inside the atlas's density range, and no other, each within the two errors;
* **long box** (Scheeffer IX's printed tables, :func:`tables_prediction` in
  ``derivations/scheeffer_ix/predictors.py``): where the longest edge is at least ``LONG`` times the
  middle one, the stable positions with the long edge horizontal are those the tables give for
  the cross-section at every interval's sample density (tilt within ``MATCH_RAD``);
* **printed thresholds located**: where a printed threshold is not found, the solver's stable set
  beside it (at ``s -+ 1e-6``) does not change in that position (else the bisection missed it).

Reported, not failing (a printed claim may be wrong): every printed prediction read at the
samples, by derivation — agreeing, disagreeing where the derivation declares an erratum of the
formula, disagreeing otherwise; Scheeffer VII–VIII's tilted parallelepipeds first — and the printed
thresholds inside the swept range that the phase machinery did not find, each with what the solver
sees beside it (the position stable on neither side, or on both: no change of the stable set there).
"""
from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass, field
from fractions import Fraction

from ..numbers import signs
from ..report.citations import cited, source_of

__all__ = ["Check", "run_checks", "checks_markdown", "LONG", "MATCH_RAD"]

LONG = 5
MATCH_RAD = 1e-6
THRESHOLD_SLACK = 1e-8      # beyond the atlas's stated error: the tables' thresholds are bisected on floats


@dataclass
class Check:
    name: str
    fails_command: bool
    ok: bool
    summary: str
    details: list = field(default_factory=list)


def _cells(rows) -> dict:
    out = {}
    for r in rows:
        out.setdefault((Fraction(r["b_a_exact"]), Fraction(r["c_a_exact"])), []).append(r)
    return out


def _cell_name(cell) -> str:
    return f"b/a = {cell[0]}, c/a = {cell[1]}"


def _labels(row) -> list:
    return sorted({c["position"] for c in row["stable"]})


def _check_cells(cells) -> Check:
    whole = [f"{_cell_name(c)}: {rs[0]['failure']}" for c, rs in cells.items() if rs[0]["interval"] is None]
    rows = [f"{_cell_name(c)}, sample s = {r['sample_density']!r}: {r['failure']}" for c, rs in cells.items()
            for r in rs if r["interval"] is not None and r["failure"]]
    total = sum(len(rs) for rs in _good(cells).values())
    return Check("cells", True, not (whole or rows), f"{len(cells) - len(whole)} of {len(cells)} cells computed; "
                 f"{total - len(rows)} of {total} interval samples solved", whole + rows)


def _good(cells):
    """The cells whose phase diagram was computed (their rows may still hold a failed sample)."""
    return {c: rs for c, rs in cells.items() if rs[0]["interval"] is not None}


def _check_index(cells) -> Check:
    rows = [(c, r) for c, rs in _good(cells).items() for r in rs if not r["failure"]]
    bad = [f"{_cell_name(c)}, s = {r['sample_density']:.6f}: index sum {r['index_sum']}" for c, r in rows
           if r["index_sum"] != 2]
    rings = sum(any(x["family"] == "ring" for x in r["stable"]) for _, r in rows)
    return Check("Poincaré–Hopf", True, not bad, f"{len(rows) - len(bad)} samples sum to 2 ({rings} of them with a "
                 f"stable family, counted with the winding round it), {len(bad)} do not", bad)


def _check_sweep(cells) -> Check:
    rows = [(c, r) for c, rs in _good(cells).items() for r in rs if not r["failure"]]
    bad = [f"{_cell_name(c)}, interval {r['s_from']:.6f}..{r['s_to']:.6f}: midpoint {_labels(r)} differs from "
           f"the sweep inside it" for c, r in rows if not r["sweep_agrees"]]
    points = sum(r["sweep_points"] for _, r in rows)
    return Check("sweep", True, not bad, f"{points} sweep densities inside {len(rows)} intervals agree with the "
                 f"midpoints" if not bad else f"{len(bad)} intervals disagree with their sweep", bad)


def _check_duality(cells) -> Check:
    bad = []
    for c, rs in _good(cells).items():
        if not rs[0]["duality_holds"]:
            bad.append(f"{_cell_name(c)}: the sweep's stable sets do not mirror, or thresholds without a dual: "
                       f"{'; '.join(rs[0]['thresholds_without_dual'])}")
        n = len(rs)
        for k, r in enumerate(rs):
            m = rs[n - 1 - k]
            if not (r["failure"] or m["failure"]) and _labels(r) != _labels(m):
                bad.append(f"{_cell_name(c)}: {_labels(r)} at s = {r['sample_density']:.6f} but {_labels(m)} at "
                           f"s = {m['sample_density']:.6f}")
            if k and abs(r["s_from"] - (1 - m["s_to"])) > r["s_from_error"] + m["s_to_error"] + 1e-12:
                bad.append(f"{_cell_name(c)}: boundary {r['s_from']:.13f} has no dual (1 − {m['s_to']:.13f})")
    good = _good(cells)
    return Check("duality s ↔ 1 − s", True, not bad, f"{len(good) - len({b.split(':')[0] for b in bad})} of "
                 f"{len(good)} cells dual", bad)


def _check_permutations(cells) -> Check:
    """Cells that are one box with its edges named in another order (1 x 2 x 1 and 1 x 1 x 2) must
    have the same boundaries within their errors and the same number of stable classes between."""
    same = {}
    for c in _good(cells):
        same.setdefault(tuple(sorted((Fraction(1), *c))), []).append(c)
    pairs = [(g[0], other) for g in same.values() for other in g[1:]]
    bad = []
    for first, second in pairs:
        a, b = cells[first], cells[second]
        ends_a = [(r["s_from"], r["s_from_error"]) for r in a[1:]]
        ends_b = [(r["s_from"], r["s_from_error"]) for r in b[1:]]
        if len(ends_a) != len(ends_b):
            bad.append(f"{_cell_name(first)} has {len(ends_a)} boundaries, {_cell_name(second)} {len(ends_b)}")
            continue
        for (x, ex), (y, ey) in zip(ends_a, ends_b):
            if abs(x - y) > ex + ey + 1e-12:
                bad.append(f"{_cell_name(first)}: boundary at {x:.13f} ± {ex:.0e}; {_cell_name(second)}: "
                           f"{y:.13f} ± {ey:.0e} (differ by {abs(x - y):.1e})")
        if [r["stable_classes"] for r in a] != [r["stable_classes"] for r in b]:
            bad.append(f"{_cell_name(first)} and {_cell_name(second)}: different numbers of stable classes")
    summary = (f"{len(pairs)} pairs of cells that are the same box with its edges renamed" if pairs else
               "not applicable: no two cells are the same box")
    return Check("same box, edges renamed", True, not bad, summary, bad)


def _check_cube(cells, reference, lo, hi) -> Check:
    cube = _good(cells).get((Fraction(1), Fraction(1)))
    if cube is None or reference is None:
        return Check("cube", True, True, "not applicable: the grid has no cell b/a = c/a = 1")
    mine = [(r["s_from"], r["s_from_error"], ch["position"], ch["change"]) for r in cube for ch in r["from_changes"]]
    theirs = [(t["density"], t["error"], t["position"], t["change"]) for t in reference["thresholds"]
              if lo + t["error"] < t["density"] < hi - t["error"]]

    def near(a, b):
        return a[2:] == b[2:] and abs(a[0] - b[0]) <= a[1] + b[1] + 1e-9

    bad = [f"phase cube has {t[2]}: {t[3]} at {t[0]:.13f} ± {t[1]:.0e}; the atlas does not" for t in theirs
           if not any(near(t, m) for m in mine)]
    bad += [f"the atlas has {m[2]}: {m[3]} at {m[0]:.13f} ± {m[1]:.0e}; phase cube does not" for m in mine
            if not any(near(m, t) for t in theirs)]
    return Check("cube", True, not bad, f"{len(theirs)} thresholds of `phase cube` in the range, "
                 f"{len(mine)} in the cube cell, {len(bad)} unmatched", bad)


def _ix_tables():
    """The printed case tables of the long box a derivation provides (``provides("tables", ...)``)."""
    from ..registry import provided
    (_, tables), = provided("tables")
    return tables


def _long_axes(cell):
    """``(long, a, b)`` axes of a long box: the long edge, the larger and the smaller edge of its section;
    None when the longest edge is shorter than LONG times the middle one."""
    dims = [Fraction(1), cell[0], cell[1]]
    order = sorted(range(3), key=lambda k: (dims[k], k))
    small, middle, long = order
    if dims[long] < LONG * dims[middle]:
        return None
    return long, middle, small, dims


def _in_plane(row, long, a, b, square) -> list[float]:
    out = []
    for c in row["stable"]:
        u = c["up"]
        if abs(u[long]) > 1e-9:
            continue
        phi = math.atan2(abs(u[a]), abs(u[b]))
        out.append(min(phi, math.pi / 2 - phi) if square else phi)
    return sorted(out)


def _printed_tilts(tables, s, ratio, square) -> list[float]:
    printed = [p["phi"] for p in tables(s, ratio) if p["stability"] == "stable"]
    if square:
        printed = {round(min(p, math.pi / 2 - p), 12) for p in printed}
    return sorted(printed)


def _signature(tilts) -> tuple[int, int]:
    """(stable positions with a face down, oblique ones) of one section."""
    faces = sum(1 for p in tilts if min(p, abs(math.pi / 2 - p)) < MATCH_RAD)
    return faces, len(tilts) - faces


def _table_thresholds(tables, ratio, square, lo, hi, grid: int = 2000) -> list[float]:
    """Densities in (lo, hi) where the printed tables' stable set of the section changes kind or
    count: a scan of *grid* densities, each change bisected to 1e-14."""
    at = lambda s: _signature(_printed_tilts(tables, s, ratio, square))  # noqa: E731
    points = [lo + (hi - lo) * k / grid for k in range(grid + 1)]
    states = [at(s) for s in points]
    out = []
    for k in range(grid):
        if states[k] != states[k + 1]:
            a, b = points[k], points[k + 1]
            while b - a > 1e-14:
                mid = (a + b) / 2
                a, b = (mid, b) if at(mid) == states[k] else (a, mid)
            out.append((a + b) / 2)
    return out


def _long_thresholds(tables, c, rs, long, a, b, ratio, square, lo, hi) -> list[str]:
    """The tables' thresholds against the atlas's boundaries where the in-plane stable set changes
    kind or count, both ways, within the atlas's error + ``THRESHOLD_SLACK``."""
    rows = [r for r in rs if not r["failure"]]
    mine = [(r["s_from"], r["s_from_error"]) for p, r in zip(rows, rows[1:])
            if _signature(_in_plane(p, long, a, b, square)) != _signature(_in_plane(r, long, a, b, square))]
    theirs = _table_thresholds(tables, ratio, square, lo, hi)
    bad = [f"{_cell_name(c)}: the tables change their stable set at s = {t:.13f}; the atlas has no boundary there"
           for t in theirs if not any(abs(t - m) <= e + THRESHOLD_SLACK for m, e in mine)]
    bad += [f"{_cell_name(c)}: the atlas's stable set changes at s = {m:.13f} ± {e:.0e}; the tables' does not"
            for m, e in mine if not any(abs(t - m) <= e + THRESHOLD_SLACK for t in theirs)]
    return bad


def _check_long(cells, lo, hi) -> Check:
    tables = _ix_tables()
    checked, bad, cells_long = 0, [], 0
    for c, rs in _good(cells).items():
        axes = _long_axes(c)
        if axes is None:
            continue
        cells_long += 1
        long, a, b, dims = axes
        ratio, square = float(dims[a] / dims[b]), dims[a] == dims[b]
        bad += _long_thresholds(tables, c, rs, long, a, b, ratio, square, lo, hi)
        for r in rs:
            if r["failure"]:
                continue
            checked += 1
            printed = _printed_tilts(tables, r["sample_density"], ratio, square)
            found = _in_plane(r, long, a, b, square)
            if len(found) != len(printed) or any(abs(x - y) > MATCH_RAD for x, y in zip(found, printed)):
                bad.append(f"{_cell_name(c)}, s = {r['sample_density']:.6f}: the tables give stable tilts "
                           f"{[round(math.degrees(p), 4) for p in printed]}°, the atlas "
                           f"{[round(math.degrees(p), 4) for p in found]}°")
    summary = (f"{cells_long} long cells (longest edge ≥ {LONG} × the middle one): {checked} interval samples "
               f"and every threshold of the tables against the atlas, {len(bad)} disagreements" if checked
               else f"not applicable: no cell has its longest edge "
               f"≥ {LONG} × the middle one")
    return Check("long box (Scheeffer IX)", True, not bad, summary, bad)


def _predictions(cells, lo, hi) -> list[Check]:
    """Per derivation: predictions that agree, that disagree where the derivation declares an erratum
    of the formula (expected), and that disagree where it does not (a finding)."""
    by = {}
    for c, rs in _good(cells).items():
        for r in rs:
            for p in r["predictions"]:
                entry = by.setdefault(p["derivation"], {"agree": 0, "erratum": 0, "disagree": [], "read": []})
                entry["read"].append(p)
                if p["agrees"]:
                    entry["agree"] += 1
                elif "erratum" in p["verdicts"]:
                    entry["erratum"] += 1
                else:
                    verdicts = "/".join(p["verdicts"])
                    entry["disagree"].append(f"{_cell_name(c)}, s = {r['sample_density']:.6f}: "
                                             f"{', '.join(p['locators'])} ({verdicts}): {p['disagreement']}")
    out = []
    for did in sorted(by):
        e = by[did]
        out.append(Check(f"printed: {cited(e['read'])}", False, not e["disagree"],
                         f"{e['agree']} predictions agree; {e['erratum']} disagree where an erratum is declared; "
                         f"{len(e['disagree'])} disagree otherwise", e["disagree"]))
    missing = sorted({f"{_cell_name(c)}: {_cited_entry(m)}" for c, rs in _good(cells).items()
                      for m in rs[0]["sources_not_found"]
                      if lo < _printed_value(m) < hi})
    kinds = Counter(_seen(m) for m in missing)
    explained = [m for m in missing if _seen(m).endswith(("the print silent beyond", "erratum declared"))]
    out.append(Check("printed thresholds", False, len(explained) == len(missing),
                     f"{len(missing)} printed thresholds inside the swept range that the phase machinery does "
                     f"not find" + (": " + ", ".join(f"{n} where the solver finds the position {k}"
                                                    if k.startswith("stable") else f"{n} {k}"
                                                    for k, n in sorted(kinds.items())) if kinds else ""),
                     missing))
    unlocated = [m for m in missing if _seen(m) == "change not located"]
    out.append(Check("printed thresholds located", True, not unlocated,
                     f"{len(unlocated)} printed thresholds where the solver's stable set changes but no threshold "
                     f"was located", unlocated))
    return out


def _cited_entry(entry: str) -> str:
    """An entry of ``sources_not_found`` (``"scheeffer-x X: corner up ..."``, the derivation's id first) with the
    source it reads named as a reader cites it (``"Scheeffer 1902 X: corner up ..."``)."""
    derivation, rest = entry.split(" ", 1)
    return f"{source_of(derivation)} {rest}"


def _printed_value(entry: str) -> float:
    """The density of an entry of ``sources_not_found``: ``"... at VALUE [seen: why]"``."""
    return float(entry.split(" [", 1)[0].rsplit(" at ", 1)[1])


def _seen(entry: str) -> str:
    """What the solver sees beside the printed threshold of an entry of ``sources_not_found``."""
    return entry.split(" [", 1)[1].split(":", 1)[0]


def run_checks(rows, meta, reference=None) -> list[Check]:
    cells = _cells(rows)
    densities = [float(Fraction(s)) for s in meta["densities"]]
    lo, hi = densities[0], densities[-1]
    return [_check_cells(cells), _check_index(cells), _check_sweep(cells), _check_duality(cells),
            _check_permutations(cells), _check_cube(cells, reference, lo, hi), _check_long(cells, lo, hi)] + \
        _predictions(cells, lo, hi)


def checks_markdown(checks, meta, limit: int = 40) -> str:
    lines = ["# Checks of the atlas", "",
             f"Grid: b/a ∈ {{{', '.join(meta['b_a'])}}}, c/a ∈ {{{', '.join(meta['c_a'])}}}, "
             f"{len(meta['densities'])} densities from {meta['densities'][0]} to {meta['densities'][-1]}.", "",
             "| check | fails the command | result | summary |", "|---|---|---|---|"]
    for c in checks:
        result = "holds" if c.ok else ("FAILS" if c.fails_command else "disagreements")
        lines.append(f"| {c.name} | {'yes' if c.fails_command else 'no (reported)'} | {result} | {c.summary} |")
    for c in checks:
        if c.details:
            lines += ["", f"## {c.name}", ""] + [f"- {signs(d)}" for d in c.details[:limit]]
            if len(c.details) > limit:
                lines.append(f"- … and {len(c.details) - limit} more")
    return "\n".join(lines) + "\n"
