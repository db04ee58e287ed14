"""The ``symfloat`` command line.

    symfloat verify [SELECTOR] [--format table|json]
    symfloat errata [SELECTOR] [--format md|json] [--output FILE]
    symfloat notebooks [SELECTOR] [--output DIR]
    symfloat run
    symfloat scene BODY --density S [--dims ...] [--sides N] [--polygon "x,y ..."] [--format table|json]
                   [--plot FILE.png]
    symfloat phase cube|box [--dims a,b,c] [--steps N] [--format table|json] [--plot FILE.png]
    symfloat atlas box --ba A:B:N --ca A:B:N --density A:B:N --out DIR [--scheduler ADDRESS] [--workers N]
                   [--figures DIR]
    symfloat bench [--quick] [--output DIR]
    symfloat coverage [SOURCE] [--format table|json] [--readings] [--write] [--update-baseline]
    symfloat site [--out DIR]

Progress goes to stderr; ``--quiet`` (or ``SYMFLOAT_QUIET`` set to anything but ``0``) silences
it.  The default outputs (``docs/``, ``notebooks/``) are those of the project checkout, wherever
the command runs; a path given with ``--output`` or ``--plot`` is taken as given.  A selection
never overwrites the record of everything (``docs/errata.md``, ``docs/errata.json``,
``docs/verification.json``): ``errata SELECTOR`` prints its report, or writes it to ``--output``.

Exit status, the same for every subcommand (:mod:`symfloat.errors`): 0 success; 1 a check failed
(a verdict not as declared, an index sum, a duality, a coverage count); 2 bad input or an
environment problem (one line on stderr, nothing written); 130 interrupted (Ctrl-C: finished
checks stay cached).
"""
from __future__ import annotations

import argparse
import io
import os
import signal
import sys
import time
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

from .engine.cache import ReportCache
from .engine.runner import Progress, verify
from .errors import (EXIT_CHECK, EXIT_INPUT, EXIT_INTERRUPTED, EXIT_OK, CheckFailed, EnvironmentProblem, InputError,
                     SymfloatError)
from .project import GOLDEN, in_project, library_folders, project_root
from .registry import load, providing, select
from .report.errata import errata_json, errata_markdown
from .report.files import write_atomic, write_if_changed, writable_target
from .report.record import record_json, verification_table, write_record
from .report.stamp import stamp_of

EXIT_STATUS = ("Exit status: 0 success; 1 a check failed (verdict, index sum, duality, coverage); "
               "2 bad input or an environment problem; 130 interrupted")


def _one_line(message: str) -> str:
    """*message* on one line: line breaks a user typed into a value are shown escaped.

    >>> _one_line("bad value 'a\\nb'")
    "bad value 'a\\\\nb'"
    """
    return message.replace("\r", "\\r").replace("\n", "\\n")


class _Parser(argparse.ArgumentParser):
    """Usage errors as one line, exit status 2 (``--help`` still shows the usage)."""

    def error(self, message):
        self.exit(EXIT_INPUT, f"symfloat: {_one_line(message)} (see {self.prog} --help)\n")


# ---------------------------------------------------------------- shared policy

def _quiet(args) -> bool:
    return args.quiet or os.environ.get("SYMFLOAT_QUIET", "0") not in ("", "0")


def _say(args, message: str) -> None:
    """A progress line on stderr unless quiet."""
    if not _quiet(args):
        print(message, file=sys.stderr, flush=True)


def _cache(args) -> ReportCache:
    """The cache, checked usable before any work."""
    cache = ReportCache(enabled=not args.no_cache)
    cache.prepare()
    return cache


def _kernels_share(cache: ReportCache) -> None:
    """Point the processes that build the notebooks at the command's cache."""
    if cache.enabled:
        os.environ["SYMFLOAT_CACHE"] = str(cache.root.resolve())


def _selector(text):
    """``None`` or a source key / derivation-id prefix: ASCII letters, digits and ``-``."""
    if text is None:
        return None
    if not (0 < len(text) <= 80 and text.isascii() and all(c.isalnum() or c == "-" for c in text)):
        raise InputError(f"a selector is a source key or a derivation-id prefix such as graefe or graefe-s3, "
                         f"not {text[:40]!r}")
    return text


def _search_proofs_arg(p):
    p.add_argument("--search-proofs", action="store_true",
                   help="search every claim's symbolic proof anew instead of replaying its recorded "
                        "certificate (symfloat/derivations/proofs/), and record the outcome")


def _reports(args, selector=None, cache=None):
    return verify(selector, cache=cache or _cache(args), progress=Progress(quiet=_quiet(args)),
                  search_proofs=args.search_proofs, record_proofs=True)


def _failed(reports) -> int:
    return EXIT_CHECK if any(r.failures for r in reports) else EXIT_OK


def _not_golden(path: Path) -> Path:
    """*path*, unless it is one of the files that record everything (a selection must not replace them)."""
    root = project_root()
    if root is not None and path.resolve() in {(root / g).resolve() for g in GOLDEN}:
        raise InputError(f"{path} is the record of every source; a selection is printed, or written to "
                         f"another --output")
    return path


def _plot_target(path):
    """The ``--plot`` file: a ``.png`` whose directory exists and is writable (checked before solving)."""
    if path is None:
        return None
    if path.suffix.lower() != ".png":
        raise InputError(f"--plot writes a PNG image: give a file name ending in .png, not {str(path)[:60]!r}")
    return writable_target(path)


def _write_plot(draw, subject, path: Path, args) -> None:
    buffer = io.BytesIO()
    draw(subject, buffer)
    write_atomic(path, buffer.getvalue())
    _say(args, f"wrote {path}")


def _summary_by_source(reports) -> str:
    lines = []
    for source in dict.fromkeys(r.source for r in reports):
        fs = [f for r in reports if r.source == source for f in r.formulas]
        c = Counter(f.verdict for f in fs)
        secs = sum(r.seconds for r in reports if r.source == source)
        lines.append(f"{source}: {len(fs)} printed formulas — {c['verified']} verified, {c['erratum']} errata, "
                     f"{c['unverifiable']} unverifiable, {c['trivial']} trivial ({secs:.1f} s)")
    return "\n".join(lines)


# ---------------------------------------------------------------- the subcommands

def _verify_args(p):
    _search_proofs_arg(p)
    p.add_argument("selector", nargs="?", help="a source key (graefe) or a derivation-id prefix")
    p.add_argument("--format", choices=("table", "json"), default="table")


def _verify(args) -> int:
    reports = _reports(args, _selector(args.selector))
    print(record_json(reports) if args.format == "json" else verification_table(reports), end="")
    return _failed(reports)


def _errata_args(p):
    _search_proofs_arg(p)
    p.add_argument("selector", nargs="?", help="a source key or derivation-id prefix: print (or --output) "
                                               "the report of that selection")
    p.add_argument("--format", choices=("md", "json"), default="md")
    p.add_argument("--output", type=Path, help="file for the Markdown report (default: docs/errata.md of "
                                               "the checkout without a selector, stdout with one)")


def _errata(args) -> int:
    selector = _selector(args.selector)
    out = None
    if args.format == "md":
        if args.output is not None:
            out = _not_golden(writable_target(args.output)) if selector else writable_target(args.output)
        elif selector is None:
            out = writable_target(in_project("docs/errata.md"))
    reports = _reports(args, selector)
    if args.format == "json":
        print(errata_json(reports), end="")
    elif out is None:
        print(errata_markdown(reports), end="")
    else:
        write_if_changed(out, errata_markdown(reports))
        _say(args, f"wrote {out}")
    return _failed(reports)


def _notebooks_args(p):
    _search_proofs_arg(p)
    p.add_argument("selector", nargs="?")
    p.add_argument("--output", type=Path, help="directory (default: notebooks/ of the checkout)")


def _notebooks(args) -> int:
    selector = _selector(args.selector)
    folder = args.output or in_project("notebooks")
    writable_target(folder / "x.ipynb")
    ids = select(selector)
    cache = _cache(args)
    _kernels_share(cache)
    reports = _reports(args, selector, cache)
    from .report.notebooks import write_notebooks  # nbformat and nbclient: only when notebooks are written

    written = write_notebooks(ids, folder, None if _quiet(args) else
                              (lambda d: print(f"executed notebook {d}", file=sys.stderr, flush=True)))
    _say(args, f"{len(written)} of {len(ids)} notebooks changed in {folder}")
    return _failed(reports)


def _run(args) -> int:
    docs, notebooks = in_project("docs"), in_project("notebooks")
    for path in (docs / "errata.md", notebooks / "x.ipynb"):
        writable_target(path)
    cache = _cache(args)
    _kernels_share(cache)
    reports = _reports(args, cache=cache)
    write_record(docs / "verification.json", reports)
    write_if_changed(docs / "errata.json", errata_json(reports))
    write_if_changed(docs / "errata.md", errata_markdown(reports))
    quiet = _quiet(args)
    from .report.notebooks import write_notebooks

    written = write_notebooks([r.id for r in reports], notebooks, None if quiet else
                              (lambda d: print(f"executed notebook {d}", file=sys.stderr, flush=True)))
    documents = ["verification.json", "errata.json", "errata.md"]
    checked = {r.id for r in reports}
    for did in providing("report"):             # documents the derivations add (e.g. Scheeffer IX's grid)
        if did not in checked:
            continue
        for report in load(did)[0].provided["report"]:
            if stamp_of(docs / report.filename) != report.stamp():         # what it depends on changed
                write_if_changed(docs / report.filename, report.build(
                    progress=None if quiet else (lambda m, f=report.filename: print(f"{f}: {m}", file=sys.stderr))))
            documents.append(report.filename)
    from .report.figures import write_figures      # the pictures, from the data above (matplotlib: only here)
    from .report.phase_data import write_phase_data

    say = None if quiet else (lambda m: print(m, file=sys.stderr))
    documents += [f"figures/{name}" for name in write_phase_data(docs, say)]
    figures = write_figures(docs, say)
    print(_summary_by_source(reports))
    print(f"wrote {', '.join('docs/' + f for f in documents)}; {len(written)} notebooks changed; "
          f"{len(figures)} figures redrawn")
    for r in reports:
        for msg in r.failures:
            print(f"FAILURE: {msg}")
    return _failed(reports)


def _scene_args(p):
    from .solver.bodies import DOMAIN
    p.add_argument("body", help="cube, box, prism, cylinder or section")
    p.add_argument("--density", help="density s relative to water, 0 < s < 1 (decimal or p/q)")
    p.add_argument("--dims", help="box a,b,c; prism a,b (side, length); cylinder r,b; cube a (default 1)")
    p.add_argument("--sides", help="number of sides of the prism's regular base")
    p.add_argument("--polygon", help='section: convex polygon "x1,y1 x2,y2 ..."')
    p.add_argument("--format", choices=("table", "json"), default="table")
    p.add_argument("--plot", type=Path, help="draw the stable positions into this PNG file")
    p.epilog = f"Supported inputs: {DOMAIN}. Numbers are ASCII decimals or p/q, kept exact. {EXIT_STATUS}."


def _scene(args) -> int:
    from .report.scene import scene_json, scene_plot, scene_record, scene_table
    from .solver import make_scene, solve
    from .solver.coverage import cover

    start = time.perf_counter()
    scene = make_scene(args.body, args.density, args.dims, args.sides, args.polygon)
    plot = _plot_target(args.plot)
    solution = solve(scene)
    evaluated, unmatched = cover(solution)
    record = scene_record(solution, evaluated, unmatched, time.perf_counter() - start)
    print(scene_json(record) if args.format == "json" else scene_table(record))
    if plot:
        _write_plot(scene_plot, solution, plot, args)
    return EXIT_OK


def _phase_args(p):
    p.add_argument("body", help="cube or box")
    p.add_argument("--dims", help="box a,b,c")
    p.add_argument("--format", choices=("table", "json"), default="table")
    p.add_argument("--plot", type=Path, help="draw the phase diagram into this PNG file")
    p.add_argument("--steps", default="48", help="densities in the sweep, 4 to 2000 (default 48)")
    p.epilog = ("The sweep's densities k/(steps+1) must all lie in the scene's supported range "
                f"(symfloat scene --help). {EXIT_STATUS}.")


def _phase(args) -> int:
    from fractions import Fraction

    from .report.phase import phase_json, phase_plot, phase_table
    from .solver.bodies import SceneError, make_scene, parse_whole
    from .solver.phase import phase_diagram

    if args.body not in ("cube", "box"):
        raise SceneError(f"phase diagrams are drawn for cube and box, not {args.body[:40]!r}")
    steps = parse_whole(args.steps, "--steps", 4, 2000)
    for s in (Fraction(1, steps + 1), Fraction(steps, steps + 1)):       # both ends of the sweep
        try:
            make_scene(args.body, s, args.dims)
        except SceneError as exc:
            raise SceneError(f"--steps {steps}: {exc}") from None
    plot = _plot_target(args.plot)
    diagram = phase_diagram(args.body, args.dims, steps, progress=None if _quiet(args) else
                            (lambda msg: print(msg, file=sys.stderr)))
    print(phase_json(diagram) if args.format == "json" else phase_table(diagram))
    if plot:
        _write_plot(phase_plot, diagram, plot, args)
    if not diagram.duality_ok:                  # a failed self-check: exit 1
        raise CheckFailed("the duality s <-> 1 - s does not hold (see the thresholds marked NO DUAL)")
    return EXIT_OK


def _atlas_args(p):
    p.add_argument("body", help="box (edges 1, b/a, c/a; the cell b/a = c/a = 1 is the cube)")
    p.add_argument("--ba", required=True, help="b/a: a grid A:B:N (N values from A to B), a list v1,v2,... or a value")
    p.add_argument("--ca", required=True, help="c/a: the same forms")
    p.add_argument("--density", required=True, help="the sweep of densities, A:B:N or a list, symmetric about 1/2")
    p.add_argument("--out", required=True, type=Path, help="directory: parts/ (one Parquet file per cell), "
                                                          "atlas.parquet, checks.md")
    p.add_argument("--scheduler", help="address of a running Dask scheduler (default: a local cluster)")
    p.add_argument("--workers", help="worker processes of the local cluster (default: the machine's cores); "
                                     "0 computes here without Dask")
    p.add_argument("--figures", type=Path, help="directory for the slice figures atlas-c<c/a>.png")
    p.epilog = ("Cells already written in --out by the same code with the same density sweep are skipped (a "
                "stopped run resumes). "
                f"Needs the optional dependencies: pip install 'symfloat[atlas]'. {EXIT_STATUS}.")


def _scheduler(text):
    if text is None:
        return None
    if not (0 < len(text) <= 200 and text.isascii() and text.isprintable() and " " not in text):
        raise InputError(f"--scheduler is an address such as tcp://10.0.0.5:8786, not {text[:40]!r}")
    return text


def _atlas(args) -> int:
    from .solver.bodies import SceneError, parse_whole
    if args.body != "box":
        raise SceneError(f"the atlas is drawn for the box, not {args.body[:40]!r}")
    try:
        import dask.distributed  # noqa: F401
        import pyarrow  # noqa: F401
    except ImportError as exc:
        raise EnvironmentProblem(f"the atlas needs dask[distributed] and pyarrow ({exc.name} is missing): "
                                 f"pip install 'symfloat[atlas]'") from None
    from .atlas.command import run_atlas
    from .atlas.grid import check_domain, density_grid, shape_grid

    ba, ca, densities = shape_grid(args.ba, "--ba"), shape_grid(args.ca, "--ca"), density_grid(args.density)
    check_domain(ba, ca, densities)
    workers = None if args.workers is None else parse_whole(args.workers, "--workers", 0, 1024)
    scheduler = _scheduler(args.scheduler)
    if scheduler and workers is not None:
        raise InputError("--workers sizes the local cluster; with --scheduler the cluster has its own workers")
    writable_target(args.out / "atlas.parquet")
    if args.figures is not None:
        writable_target(args.figures / "atlas-c1.png")
    return run_atlas(args.out, ba, ca, densities, scheduler, workers, args.figures, quiet=_quiet(args),
                     say=lambda m: _say(args, m))


def _bench_args(p):
    p.add_argument("--quick", action="store_true", help="a few derivations and methods (for tests)")
    p.add_argument("--derivations", action="store_true",
                   help="measure what checking each derivation costs (cold, warm, by kind) and write that "
                        "table into performance.md")
    p.add_argument("--output", type=Path, help="directory for numerics.md and figures/ (default: docs/ of "
                                               "the checkout)")


def _bench(args) -> int:
    from .numerics.document import generate
    folder = args.output or in_project("docs")
    if args.derivations:
        return _bench_derivations(args, folder)
    writable_target(folder / "numerics.md")
    quiet = _quiet(args)
    written = generate(folder, quick=args.quick,
                       progress=lambda msg: quiet or print(msg, file=sys.stderr, flush=True))
    _say(args, f"{len(written)} numerics files changed in {folder}")
    return EXIT_OK


def _bench_derivations(args, folder: Path) -> int:
    import platform

    from .numerics.cost import cost_markdown, cost_rows, write_section
    path = writable_target(folder / "performance.md")
    rows = cost_rows(progress=lambda msg: _say(args, msg))
    machine = f"{platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}"
    write_atomic(path, write_section(path, cost_markdown(rows, machine)).encode("utf-8"))
    _say(args, f"wrote {path}")
    return EXIT_CHECK if any(r["failures"] for r in rows) else EXIT_OK


def _coverage_args(p):
    p.add_argument("source", nargs="?", help="a source key (default: all)")
    p.add_argument("--format", choices=("table", "json"), default="table")
    p.add_argument("--readings", action="store_true", help="also read every quote automatically and compare")
    p.add_argument("--write", action="store_true", help="write docs/coverage.md (and docs/readings.md)")
    p.add_argument("--update-baseline", action="store_true", help="rewrite docs/coverage-baseline.json "
                   "(and docs/readings-baseline.json) to the current lists")


def _coverage(args) -> int:
    from .report.ledger_command import run
    return run(args)


def _site_args(p):
    p.add_argument("--out", type=Path, help="folder for the static site (default: build/site of the checkout); "
                                            "an existing folder must be empty or hold an earlier site")


def _site(args) -> int:
    from .site.build import build_site          # Sphinx and MyST-NB: only when the site is built
    out = args.out or in_project("build/site")
    changed, warnings = build_site(out, in_project("docs"), in_project("notebooks"),
                                   progress=lambda msg: _say(args, msg))
    for w in warnings:
        _say(args, f"sphinx: {w}")
    _say(args, f"{len(changed)} files changed in {out}")
    return EXIT_OK


@dataclass(frozen=True)
class Command:
    help: str
    arguments: object       # adds the subcommand's own arguments to its parser
    run: object             # args -> exit status


COMMANDS = {
    "verify": Command("check derivations and print verdicts", _verify_args, _verify),
    "errata": Command("write docs/errata.md, or print a selection's errata (Markdown or JSON)",
                      _errata_args, _errata),
    "notebooks": Command("build and execute the derivation notebooks", _notebooks_args, _notebooks),
    "run": Command("verify everything and write every report and notebook", _search_proofs_arg, _run),
    "scene": Command("every equilibrium of one body at one density", _scene_args, _scene),
    "phase": Command("stable positions against density, thresholds located", _phase_args, _phase),
    "atlas": Command("the stability atlas of the box over (b/a, c/a, s), computed on Dask", _atlas_args, _atlas),
    "bench": Command("numerics benchmark: write docs/numerics.md and its figures", _bench_args, _bench),
    "coverage": Command("the coverage ledger: every math span and quantitative sentence quoted or waived; "
                        "with --readings the readings checked against the print", _coverage_args, _coverage),
    "site": Command("build the static web site (annotated edition, errata, notebooks, numerics) from the "
                    "committed records", _site_args, _site),
}


def _parser():
    common = _Parser(add_help=False)
    common.add_argument("--quiet", action="store_true", help="no progress on stderr (or SYMFLOAT_QUIET=1)")
    common.add_argument("--no-cache", action="store_true", help="re-check every derivation")
    p = _Parser(prog="symfloat", description="Machine-checked re-derivation of classical "
                "texts on floating bodies and centroids.", epilog=EXIT_STATUS + ".")
    sub = p.add_subparsers(dest="command", required=True)
    for name, command in COMMANDS.items():
        sp = sub.add_parser(name, parents=[common], help=command.help, epilog=EXIT_STATUS + ".")
        command.arguments(sp)
    return p


class _Interrupts:
    """Ctrl-C raises ``KeyboardInterrupt`` as usual and is remembered, so that an error it causes
    further down (a notebook kernel interrupted mid-cell) is still reported as an interruption."""

    def __init__(self):
        self.seen = False

    def __enter__(self):
        try:
            self.previous = signal.signal(signal.SIGINT, self._handle)
        except ValueError:                  # not the main thread: leave the handler alone
            self.previous = None
        return self

    def _handle(self, signum, frame):
        self.seen = True
        raise KeyboardInterrupt

    def __exit__(self, *exc):
        if self.previous is not None:
            signal.signal(signal.SIGINT, self.previous)
        return False


def main(argv=None) -> int:
    """Run one subcommand; every anticipated failure is one line on stderr and its exit status."""
    args = _parser().parse_args(argv)
    with _Interrupts() as interrupts:
        try:
            library_folders()                 # a further library of texts that is not there: one line, exit 2
            return COMMANDS[args.command].run(args)
        except KeyboardInterrupt:
            pass
        except SymfloatError as exc:
            print(f"symfloat: {_one_line(str(exc))}", file=sys.stderr)
            return exc.exit_code
        except BrokenPipeError:            # the reader of stdout went away (``| head``)
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
            return EXIT_OK
        except Exception:
            if not interrupts.seen:
                raise
    print("symfloat: interrupted (finished checks are kept in the cache)", file=sys.stderr)
    return EXIT_INTERRUPTED


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
