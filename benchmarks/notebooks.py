"""Benchmark: the cost of building and of executing each derivation notebook.

    python benchmarks/notebooks.py [--no-execute] [--output DIR] [--profile ID] [ID ...]

For each derivation (all 17 by default) the engine's report is read from the cache (verified first
if missing, not counted), then :func:`symfloat.report.notebooks.build_notebook` is timed in this
process with ``time.process_time`` (processor time: it does not grow with other work on a shared
machine), and :func:`symfloat.report.notebooks.execute_notebook` by the wall time of the kernel's
run (the kernel is another process).  Prints one row per notebook and the totals; targets: building
all 17 within 60 s of processor time, no one over 10 s, executing all 17 within 120 s.
``--output DIR`` writes the executed notebooks there (without the content stamp ``symfloat notebooks``
adds), to compare two runs cell by cell.  ``--profile ID`` prints the 30 costliest functions
(cumulative) of building that notebook.
"""
from __future__ import annotations

import argparse
import cProfile
import os
import pstats
import sys
import tempfile
import time
from pathlib import Path

import nbformat

from symfloat.engine.runner import verify
from symfloat.registry import select
from symfloat.report.notebooks import build_notebook, execute_notebook


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("ids", nargs="*")
    parser.add_argument("--no-execute", action="store_true", help="time the build only")
    parser.add_argument("--output", metavar="DIR", type=Path, help="write the executed notebooks into DIR")
    parser.add_argument("--profile", metavar="ID", help="profile building this notebook")
    args = parser.parse_args(argv)
    os.environ.setdefault("SYMFLOAT_CACHE", str(Path(".symfloat-cache").resolve()))
    ids = args.ids or select(None)
    reports = {r.id: r for did in ([args.profile] if args.profile else ids) for r in verify(did)}
    if args.profile:
        profile = cProfile.Profile()
        profile.runcall(build_notebook, args.profile, reports[args.profile])
        pstats.Stats(profile).sort_stats("cumulative").print_stats(30)
        return 0
    print(f"{'notebook':32} {'cells':>6} {'build (s CPU)':>14} {'execute (s)':>12}")
    total_build = total_exec = 0.0
    with tempfile.TemporaryDirectory() as tmp:
        for did in ids:
            start = time.process_time()
            nb = build_notebook(did, reports[did])
            build = time.process_time() - start
            total_build += build
            run = float("nan")
            if not args.no_execute:
                start = time.perf_counter()
                execute_notebook(nb, tmp)
                run = time.perf_counter() - start
                total_exec += run
                if args.output:
                    nbformat.write(nb, args.output / f"{did}.ipynb")
            print(f"{did:32} {len(nb.cells):6d} {build:14.1f} {run:12.1f}", flush=True)
    print(f"{'all':32} {'':6} {total_build:14.1f} {total_exec if not args.no_execute else float('nan'):12.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
