"""Building an atlas on Dask: one task per shape cell, parts written as they arrive.

The cells of the grid are submitted to a Dask cluster (:mod:`distributed`): a local cluster
with one single-threaded worker process per core by default, or an existing scheduler given by
its address.  The workers only compute (:func:`symfloat.atlas.cell.compute_cell`); this process
writes each returned cell as its part file, so the workers need no shared disk, and a run that
is stopped keeps every finished cell.  ``workers=0`` computes the cells here, one after the other,
without Dask (the serial reference the tests compare the cluster with).  The cube cell is also
compared with the cube's own phase diagram (``symfloat phase cube``), computed once as a task and
kept in ``parts/cube-reference.json``.
"""
from __future__ import annotations

import json
import logging
import os
import statistics
import sys
import time
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

from ..errors import EnvironmentProblem
from ..files import write_atomic
from .cell import compute_cell
from .dataset import part_done, solver_stamp, write_combined, write_part

__all__ = ["Build", "build", "timed", "cube_reference", "CUBE_REFERENCE", "ProgressBar"]

CUBE_REFERENCE = "parts/cube-reference.json"


@dataclass
class Build:
    cells: list                 # (b/a, c/a) in grid order
    computed: list              # the cells computed in this run
    skipped: list               # the cells found written
    costs: dict = field(default_factory=dict)       # cell -> {"seconds", "cpu_seconds", "thresholds", "intervals"}
    wall: float = 0.0
    workers: int = 0
    path: Path | None = None

    def summary(self) -> str:
        head = (f"{len(self.cells)} cells: {len(self.computed)} computed, {len(self.skipped)} already written"
                + (f"; {self.wall:.1f} s wall on {self.workers} worker(s)" if self.computed else ""))
        if not self.costs:
            return head
        seconds = [c["seconds"] for c in self.costs.values()]
        cpu = [c["cpu_seconds"] for c in self.costs.values()]
        thresholds = sum(c["thresholds"] for c in self.costs.values())
        return (head + f"; per cell {statistics.median(seconds):.1f} s median, {max(seconds):.1f} s max on its "
                f"worker, {statistics.median(cpu):.1f} s processor time median; {thresholds} thresholds")


def cube_reference() -> dict:
    """The thresholds of ``symfloat phase cube`` (its default sweep of 48 densities)."""
    from ..comparison.thresholds import phase_with_sources
    diagram = phase_with_sources("cube")
    return {"command": "symfloat phase cube", "steps": 48, "code": solver_stamp(),
            "duality_holds": bool(diagram.duality_ok),
            "thresholds": [{"density": t.density, "error": t.bracket, "position": t.label, "change": t.change}
                           for t in diagram.thresholds]}


class ProgressBar:
    """``[#####-----] 3/8 cells`` on stderr, redrawn in place on a terminal, one line per step elsewhere."""

    def __init__(self, total: int, enabled: bool, width: int = 30):
        self.total, self.enabled, self.width, self.done = total, enabled, width, 0
        self.tty = enabled and sys.stderr.isatty()
        self.start = time.perf_counter()

    def step(self, what: str) -> None:
        self.done += 1
        if not self.enabled:
            return
        filled = round(self.width * self.done / max(1, self.total))
        elapsed = time.perf_counter() - self.start
        left = elapsed / self.done * (self.total - self.done)
        line = (f"[{'#' * filled}{'-' * (self.width - filled)}] {self.done}/{self.total} {what} "
                f"({elapsed:.0f} s, about {left:.0f} s left)")
        print(("\r" + line) if self.tty else line, end="" if self.tty else "\n", file=sys.stderr, flush=True)
        if self.tty and self.done == self.total:
            print(file=sys.stderr, flush=True)


def _client(scheduler: str | None, workers: int):
    from dask.distributed import Client, LocalCluster
    if scheduler:
        try:
            return Client(scheduler, timeout="10s"), None
        except (OSError, TimeoutError, ValueError) as exc:
            raise EnvironmentProblem(f"cannot reach the Dask scheduler at {scheduler[:80]!r}: {exc}") from None
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0",
                           silence_logs=logging.ERROR)
    return Client(cluster), cluster


def timed(cell, ba, ca, densities):
    """``cell(ba, ca, densities)`` with the processor time it took added to its cost (``cpu_seconds``:
    unlike the wall time, it does not grow with other work on a shared machine)."""
    start = time.process_time()
    rows, cost = cell(ba, ca, densities)
    return rows, {**cost, "cpu_seconds": time.process_time() - start}


def _stale(reference: Path) -> bool:
    """Whether the cube's reference is missing or was computed by other solver code."""
    try:
        return json.loads(reference.read_text(encoding="utf-8")).get("code") != solver_stamp()
    except (OSError, ValueError):
        return True


def _name(cell) -> str:
    return f"b/a = {cell[0]}, c/a = {cell[1]}"


def build(out: Path, ba_values, ca_values, densities, scheduler: str | None = None, workers: int | None = None,
          progress: bool = False, cell=compute_cell) -> Build:
    """Compute the missing cells of the grid into *out* and write ``atlas.parquet``; *cell* computes
    one cell, ``cell(b/a, c/a, densities) -> (rows, cost)``."""
    out = Path(out)
    cells = [(Fraction(ba), Fraction(ca)) for ca in ca_values for ba in ba_values]
    todo = [c for c in cells if not part_done(out, *c, densities)]
    result = Build(cells, todo, [c for c in cells if c not in todo])
    reference = out / CUBE_REFERENCE
    want_cube = (Fraction(1), Fraction(1)) in cells and _stale(reference)
    bar = ProgressBar(len(todo) + want_cube, progress)
    start = time.perf_counter()

    def finished(c, value):
        rows, cost = value
        write_part(out, *c, densities, rows)
        result.costs[c] = cost
        bar.step(_name(c))

    def cube_finished(value):
        write_atomic(reference, (json.dumps(value, indent=1, sort_keys=True) + "\n").encode())
        bar.step("the cube's own phase diagram")

    if workers == 0 and not scheduler:
        result.workers = 1
        for c in todo:
            finished(c, timed(cell, *c, densities))
        if want_cube:
            cube_finished(cube_reference())
    elif todo or want_cube:
        from dask.distributed import as_completed
        client, cluster = _client(scheduler, workers or os.cpu_count() or 1)
        try:
            result.workers = len(client.scheduler_info()["workers"])
            futures = {client.submit(timed, cell, *c, densities, pure=False): c for c in todo}
            if want_cube:
                futures[client.submit(cube_reference, pure=False)] = None
            for future in as_completed(futures):
                if futures[future] is None:
                    cube_finished(future.result())
                else:
                    finished(futures[future], future.result())
        finally:
            client.close()
            if cluster is not None:
                cluster.close()
    result.wall = time.perf_counter() - start
    result.path = write_combined(out, cells, densities)
    return result
