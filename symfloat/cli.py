"""The ``symfloat`` command line.

    symfloat verify [SELECTOR] [--format table|json]
    symfloat errata [--format md|json] [--output FILE]
    symfloat notebooks [SELECTOR] [--output DIR]
    symfloat run
    symfloat scene BODY --density S [--dims ...] [--sides N] [--polygon "x,y ..."] [--format table|json]
                   [--plot FILE.png]
    symfloat phase cube|box [--dims a,b,c] [--format table|json] [--plot FILE.png]
    symfloat bench [--quick] [--output DIR]

Progress goes to stderr; ``--quiet`` (or ``SYMFLOAT_QUIET=1``) silences it.
Exit status: 0 when every check behaves as declared, 1 when a check fails
unexpectedly, 2 on bad input.
"""
from __future__ import annotations

import argparse
import os
import sys
from collections import Counter
from pathlib import Path

from .engine.cache import ReportCache
from .engine.runner import Progress, verify
from .registry import SelectorError, select
from .report.errata import errata_json, errata_markdown
from .report.files import write_if_changed
from .report.notebooks import write_notebooks
from .report.record import record_json, verification_table

DOCS = Path("docs")


class _Parser(argparse.ArgumentParser):
    """Usage errors as one line, exit status 2 (``--help`` still shows the usage)."""

    def error(self, message):
        self.exit(2, f"symfloat: {message} (see symfloat {self.prog.split()[-1]} --help)\n")


def _parser():
    common = _Parser(add_help=False)
    common.add_argument("--quiet", action="store_true", help="no progress on stderr")
    common.add_argument("--no-cache", action="store_true", help="re-check every derivation")
    p = _Parser(prog="symfloat", description="Machine-checked re-derivation of classical "
                                "texts on floating bodies and centroids.")
    sub = p.add_subparsers(dest="command", required=True)
    v = sub.add_parser("verify", parents=[common], help="check derivations and print verdicts")
    v.add_argument("selector", nargs="?", help="a source key (graefe) or a derivation-id prefix")
    v.add_argument("--format", choices=("table", "json"), default="table")
    e = sub.add_parser("errata", parents=[common], help="write docs/errata.md or print the errata as JSON")
    e.add_argument("selector", nargs="?")
    e.add_argument("--format", choices=("md", "json"), default="md")
    e.add_argument("--output", type=Path, help="file for the Markdown report (default docs/errata.md)")
    n = sub.add_parser("notebooks", parents=[common], help="build and execute the derivation notebooks")
    n.add_argument("selector", nargs="?")
    n.add_argument("--output", type=Path, default=Path("notebooks"))
    sub.add_parser("run", parents=[common], help="verify everything and write every report and notebook")
    sc = sub.add_parser("scene", parents=[common], help="every equilibrium of one body at one density")
    sc.add_argument("body", help="cube, box, prism, cylinder or section")
    sc.add_argument("--density", help="density s relative to water, 0 < s < 1 (decimal or p/q)")
    sc.add_argument("--dims", help="box a,b,c; prism a,b (side, length); cylinder r,b; cube a (default 1)")
    sc.add_argument("--sides", help="number of sides of the prism's regular base")
    sc.add_argument("--polygon", help='section: convex polygon "x1,y1 x2,y2 ..."')
    sc.add_argument("--format", choices=("table", "json"), default="table")
    sc.add_argument("--plot", type=Path, help="draw the stable positions into this PNG file")
    ph = sub.add_parser("phase", parents=[common], help="stable positions against density, thresholds located")
    ph.add_argument("body", help="cube or box")
    ph.add_argument("--dims", help="box a,b,c")
    ph.add_argument("--format", choices=("table", "json"), default="table")
    ph.add_argument("--plot", type=Path, help="draw the phase diagram into this PNG file")
    ph.add_argument("--steps", type=int, default=48, help="densities in the sweep (default 48)")
    b = sub.add_parser("bench", parents=[common], help="numerics benchmark: write docs/numerics.md and its figures")
    b.add_argument("--quick", action="store_true", help="a few derivations and methods (for tests)")
    b.add_argument("--output", type=Path, default=DOCS, help="directory for numerics.md and figures/")
    return p


def _progress(args):
    return Progress(quiet=args.quiet or os.environ.get("SYMFLOAT_QUIET") == "1")


def _reports(args, selector=None):
    return verify(selector, cache=ReportCache(enabled=not args.no_cache), progress=_progress(args))


def _failed(reports) -> bool:
    return any(r.failures for r in reports)


def _summary_by_source(reports) -> str:
    lines = []
    for source in dict.fromkeys(r.source for r in reports):
        fs = [f for r in reports if r.source == source for f in r.formulas]
        c = Counter(f.verdict for f in fs)
        secs = sum(r.seconds for r in reports if r.source == source)
        lines.append(f"{source}: {len(fs)} printed formulas — {c['verified']} verified, {c['erratum']} errata, "
                     f"{c['unverifiable']} unverifiable ({secs:.1f} s)")
    return "\n".join(lines)


def _scene(args) -> int:
    import time

    from .report.scene import scene_json, scene_plot, scene_record, scene_table
    from .solver import make_scene, solve
    from .solver.coverage import cover

    start = time.perf_counter()
    scene = make_scene(args.body, args.density, args.dims, args.sides, args.polygon)
    solution = solve(scene)
    evaluated, unmatched = cover(solution, ReportCache(enabled=not args.no_cache))
    record = scene_record(solution, evaluated, unmatched, time.perf_counter() - start)
    print(scene_json(record) if args.format == "json" else scene_table(record))
    if args.plot:
        scene_plot(solution, args.plot)
        print(f"wrote {args.plot}", file=sys.stderr)
    return 0


def _phase(args) -> int:
    from .report.phase import phase_json, phase_plot, phase_table
    from .solver.bodies import SceneError
    from .solver.phase import phase_diagram

    if args.body not in ("cube", "box"):
        raise SceneError(f"phase diagrams are drawn for cube and box, not {args.body!r}")
    if args.steps < 4 or args.steps > 2000:
        raise SceneError("--steps must lie between 4 and 2000")
    diagram = phase_diagram(args.body, args.dims, args.steps, progress=None if args.quiet else
                            (lambda msg: print(msg, file=sys.stderr)))
    print(phase_json(diagram) if args.format == "json" else phase_table(diagram))
    if args.plot:
        phase_plot(diagram, args.plot)
        print(f"wrote {args.plot}", file=sys.stderr)
    if not diagram.duality_ok:                  # a failed self-check: exit 1
        print("symfloat: the duality s <-> 1 - s does not hold (see the thresholds marked NO DUAL)", file=sys.stderr)
        return 1
    return 0


def main(argv=None) -> int:
    args = _parser().parse_args(argv)
    from .solver.bodies import SceneError
    from .solver.selfcheck import SelfCheckError
    try:
        if args.command == "scene":
            return _scene(args)
        if args.command == "phase":
            return _phase(args)
        if args.command == "verify":
            reports = _reports(args, args.selector)
            print(record_json(reports) if args.format == "json" else verification_table(reports), end="")
        elif args.command == "errata":
            reports = _reports(args, args.selector)
            if args.format == "json":
                print(errata_json(reports), end="")
            else:
                out = args.output or DOCS / "errata.md"
                write_if_changed(out, errata_markdown(reports))
                print(f"wrote {out}", file=sys.stderr)
        elif args.command == "notebooks":
            ids = select(args.selector)
            _reports(args, args.selector)
            progress = None if args.quiet else (lambda d: print(f"executing notebook {d}", file=sys.stderr))
            written = write_notebooks(ids, args.output, progress)
            print(f"{len(written)} of {len(ids)} notebooks changed in {args.output}", file=sys.stderr)
            reports = []
        elif args.command == "bench":
            from .numerics.document import generate
            quiet = args.quiet or os.environ.get("SYMFLOAT_QUIET") == "1"
            written = generate(args.output, quick=args.quick,
                               progress=lambda msg: quiet or print(msg, file=sys.stderr, flush=True))
            print(f"{len(written)} numerics files changed in {args.output}", file=sys.stderr)
            reports = []
        else:  # run
            reports = _reports(args)
            write_if_changed(DOCS / "verification.json", record_json(reports))
            write_if_changed(DOCS / "errata.json", errata_json(reports))
            write_if_changed(DOCS / "errata.md", errata_markdown(reports))
            progress = None if args.quiet else (lambda d: print(f"executing notebook {d}", file=sys.stderr))
            written = write_notebooks([r.id for r in reports], "notebooks", progress)
            if any(r.id == "scheeffer-ix" for r in reports):
                from .report.ix_grid import boundary_cells, grid_markdown, grid_rows
                grid = grid_rows(progress=None if args.quiet else (lambda m: print(f"IX grid {m}", file=sys.stderr)),
                                 extra=boundary_cells())
                write_if_changed(DOCS / "scheeffer-ix-grid.md", grid_markdown(grid))
            print(_summary_by_source(reports))
            print(f"wrote docs/verification.json, docs/errata.json, docs/errata.md, docs/scheeffer-ix-grid.md; "
                  f"{len(written)} notebooks changed")
            for r in reports:
                for msg in r.failures:
                    print(f"FAILURE: {msg}")
    except (SelectorError, SceneError) as exc:
        print(f"symfloat: {exc}", file=sys.stderr)
        return 2
    except SelfCheckError as exc:          # a failed index sum or duality: a check failed, exit 1
        print(f"symfloat: {exc}", file=sys.stderr)
        return 1
    return 1 if _failed(reports) else 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
