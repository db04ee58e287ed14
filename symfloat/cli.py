"""The ``symfloat`` command line.

    symfloat verify [SELECTOR] [--format table|json]
    symfloat errata [SELECTOR] [--format md|json|csv|latex] [--output FILE]
    symfloat notebooks [SELECTOR] [--output DIR]
    symfloat run [--output DIR]
    symfloat scene BODY --density S [--dims ...] [--sides N] [--polygon "x,y ..."] [--format table|json]
                   [--output FILE.png]
    symfloat phase cube|box [--dims a,b,c] [--steps N] [--format table|json] [--output FILE.png]
    symfloat atlas box --ba A:B:N --ca A:B:N --density A:B:N --output DIR [--scheduler ADDRESS] [--workers N]
                   [--figures DIR]
    symfloat bench [--quick] [--output DIR]
    symfloat coverage [SOURCE] [--format table|json] [--readings] [--write] [--update-baseline] [--output DIR]
    symfloat site [--output DIR]
    symfloat check PRINTED --against DEFINITION [--against ...] [--where INEQUALITIES] [--domain x=A:B,...]
                   [--format text|json] [--output FILE]

Progress goes to stderr; ``--quiet`` (or ``SYMFLOAT_QUIET`` set to anything but ``0`` or empty) silences
it.  The default outputs (``docs/``, ``notebooks/``, ``build/site``) are those of the library of texts
``SYMFLOAT_LIBRARY`` names, else of the project checkout, wherever the command runs
(:mod:`symfloat.project`); a path given with ``--output`` is taken as given, and checked before any work
(a file's folder must exist; :mod:`symfloat.files`).  A selection
never overwrites the record of everything (``docs/errata.md``, ``docs/errata.json``,
``docs/verification.json``): ``errata SELECTOR`` prints its report, or writes it to ``--output``.
Every file a command writes is named by ``--output`` (``--out`` and ``--plot``, the earlier names, are
kept as aliases for one release); ``symfloat --version`` names the version.

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

from . import __version__
from .engine.cache import ReportCache
from .errors import (EXIT_CHECK, EXIT_INPUT, EXIT_INTERRUPTED, EXIT_OK, CheckFailed, EnvironmentProblem, InputError,
                     SymfloatError)
from .files import write_atomic, write_if_changed, writable_folder, writable_target
from .project import GOLDEN, LIBRARY_VARIABLE, in_outputs, in_project, library_folders, outputs_root, project_root
from .registry import matching, provided, select

EXIT_STATUS = ("Exit status: 0 success; 1 a check failed (verdict, index sum, duality, coverage); "
               "2 bad input or an environment problem (an output whose folder is missing or takes no file: "
               "no folder is made for a file, an output folder may be new in an existing one; "
               "SYMFLOAT_WORKERS not 1 to 64, SYMFLOAT_SLOWDOWN not a number >= 1; a worker process killed, "
               "finished checks kept); 130 interrupted")


def verify(*args, **kwargs):
    """The engine's :func:`~symfloat.engine.runner.verify`, imported when a command checks (``--help`` does
    not load the engine)."""
    from .engine.runner import verify as run
    return run(*args, **kwargs)


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
                        "certificate (the derivation package's proofs.json), and record the outcome")


def _reports(args, selector=None, cache=None):
    from .engine.runner import Progress
    return verify(selector, cache=cache or _cache(args), progress=Progress(quiet=_quiet(args)),
                  search_proofs=args.search_proofs, record_proofs=True)


def _failed(reports) -> int:
    return EXIT_CHECK if any(r.failures for r in reports) else EXIT_OK


def _not_golden(path: Path) -> Path:
    """*path*, unless it is one of the files that record everything (a selection must not replace them)."""
    root = outputs_root()
    if root is not None and path.resolve() in {(root / g).resolve() for g in GOLDEN}:
        raise InputError(f"{path} is the record of every source; a selection is printed, or written to "
                         f"another --output")
    return path


def _plot_target(path):
    """The ``--output`` file: a ``.png`` whose directory exists and is writable (checked before solving)."""
    if path is None:
        return None
    if path.suffix.lower() != ".png":
        raise InputError(f"--output writes a PNG image: give a file name ending in .png, not {str(path)[:60]!r}")
    return writable_target(path)


def _write_plot(draw, subject, path: Path, args) -> None:
    buffer = io.BytesIO()
    draw(subject, buffer)
    write_atomic(path, buffer.getvalue())
    _say(args, f"wrote {path}")


def _summary_by_source(reports) -> str:
    from .model.erratum import apparatus
    from .numbers import counted
    lines = []
    for source in dict.fromkeys(r.source for r in reports):
        fs = [f for r in reports if r.source == source for f in r.formulas]
        c = Counter(f.verdict for f in fs)
        faults = Counter(apparatus(f.erratum["kind"]) for f in fs if f.verdict == "erratum" and f.erratum)
        secs = sum(r.seconds for r in reports if r.source == source)
        lines.append(f"{source}: {counted(len(fs), 'printed formula')} — {c['verified']} verified, "
                     f"{counted(faults['original'], 'fault')} of the original, "
                     f"{faults['transcription']} transcription corrected, "
                     f"{c['unverifiable']} unverifiable, {c['trivial']} trivial (checking time recorded {secs:.1f} s)")
    return "\n".join(lines)


# ---------------------------------------------------------------- the subcommands

def _verify_args(p):
    _search_proofs_arg(p)
    p.add_argument("selector", nargs="?", help="a source key (graefe) or a derivation-id prefix")
    p.add_argument("--format", choices=("table", "json"), default="table")


def _verify(args) -> int:
    from .report.record import record_json, verification_table
    start = time.perf_counter()
    reports = _reports(args, _selector(args.selector))
    print(record_json(reports) if args.format == "json" else
          verification_table(reports, elapsed=time.perf_counter() - start), end="")
    return _failed(reports)


def _errata_args(p):
    from .report.errata import ERRATA_FORMATS
    _search_proofs_arg(p)
    p.add_argument("selector", nargs="?", help="a source key or derivation-id prefix: print (or --output) "
                                               "the report of that selection")
    p.add_argument("--format", choices=tuple(ERRATA_FORMATS), default="md",
                   help="md (Markdown), json, csv (one row per erratum) or latex (a list to paste)")
    p.add_argument("--output", type=Path, help="file for the report (default: stdout; the Markdown report of "
                                               "everything, without a selector, goes to docs/errata.md)")


def _errata(args) -> int:
    from .report.errata import ERRATA_FORMATS
    selector = _selector(args.selector)
    out = None
    if args.output is not None:
        out = _not_golden(writable_target(args.output)) if selector else writable_target(args.output)
    elif selector is None and args.format == "md":
        out = writable_folder(in_outputs("docs")) / "errata.md"     # the checkout's own folder may be made
    checked, named = _reports(args, selector), set(matching(selector))
    reports = [r for r in checked if r.id in named]      # the selection's own errata, not its ancestors'
    text = ERRATA_FORMATS[args.format](reports)
    if out is None:
        print(text, end="")
    else:
        write_if_changed(out, text)
        _say(args, f"wrote {out}")
    return _failed(checked)


def _notebooks_args(p):
    _search_proofs_arg(p)
    p.add_argument("selector", nargs="?")
    p.add_argument("--output", type=Path, help="directory (default: notebooks/ of the checkout)")


def _notebooks(args) -> int:
    selector = _selector(args.selector)
    folder = writable_folder(args.output or in_outputs("notebooks"))
    ids = select(selector)
    cache = _cache(args)
    _kernels_share(cache)
    reports = _reports(args, selector, cache)
    from .report.notebooks import write_notebooks  # nbformat and nbclient: only when notebooks are written

    written = write_notebooks(ids, folder, None if _quiet(args) else
                              (lambda d: print(f"executed notebook {d}", file=sys.stderr, flush=True)))
    _say(args, f"{len(written)} of {len(ids)} notebooks changed in {folder}")
    return _failed(reports)


def _run_args(p):
    _search_proofs_arg(p)
    p.add_argument("--output", type=Path, help="folder under which docs/ and notebooks/ are written (default: "
                                               "the library of SYMFLOAT_LIBRARY, else the checkout)")


def _run(args) -> int:
    from .registry import compiled_readings
    from .report.errata import errata_json, errata_markdown
    from .report.record import write_record
    from .report.stamp import stamp_of
    own = _library_derivations()                   # before anything is made in the library's folder
    docs, notebooks = ((args.output / "docs", args.output / "notebooks") if args.output is not None
                       else (in_outputs("docs"), in_outputs("notebooks")))
    for folder in (docs, notebooks):
        writable_folder(folder)
    cache = _cache(args)
    _kernels_share(cache)
    reports = _reports(args, cache=cache) if own is None else _reports_of(args, own, cache)
    written = compiled_readings(write=True, among=own)   # the predictors' compiled readings, shipped in each package
    if written and not _quiet(args):
        print(f"compiled readings written: {', '.join(written)}", file=sys.stderr)
    changed = [name for name, wrote in (("verification.json", write_record(docs / "verification.json", reports)),
                                        ("errata.json", write_if_changed(docs / "errata.json", errata_json(reports))),
                                        ("errata.md", write_if_changed(docs / "errata.md", errata_markdown(reports))))
               if wrote]
    quiet = _quiet(args)
    from .report.notebooks import write_notebooks

    written = write_notebooks([r.id for r in reports], notebooks, None if quiet else
                              (lambda d: print(f"executed notebook {d}", file=sys.stderr, flush=True)))
    checked = {r.id for r in reports}
    for did, report in provided("report"):      # documents the derivations add (e.g. Scheeffer IX's grid)
        if did in checked and stamp_of(docs / report.filename) != report.stamp():   # what it depends on changed
            told = None if quiet else (lambda m, f=report.filename: print(f"{f}: {m}", file=sys.stderr))
            if write_if_changed(docs / report.filename, report.build(progress=told)):
                changed.append(report.filename)
    from .numbers import counted
    from .report.figures import write_figures      # the pictures, from the data above (matplotlib: only here)
    from .report.phase_data import write_phase_data

    say = None if quiet else (lambda m: print(m, file=sys.stderr))
    figures = []
    if own is None:                                # the project's phase diagrams and pictures, not a library's
        changed += [f"figures/{name}" for name in write_phase_data(docs, say)]
        figures = write_figures(docs, say)
    print(_summary_by_source(reports))
    print(f"{'wrote ' + ', '.join('docs/' + f for f in changed) if changed else 'no document changed'}; "
          f"{counted(len(written), 'notebook')} changed; {counted(len(figures), 'figure')} redrawn")
    for r in reports:
        for msg in r.failures:
            print(f"FAILURE: {msg}")
    return _failed(reports)


def _library_derivations() -> list[str] | None:
    """The derivations a run records: those of the library ``SYMFLOAT_LIBRARY`` names first (its records and
    notebooks are its own: the project's derivations they build on are checked, not recorded), or ``None``
    (every derivation, into the checkout) without a library."""
    from .registry import ids_in
    library = library_folders()[:1]
    if not library:
        return None
    own = ids_in(library[0])
    if not own:
        raise InputError(f"{LIBRARY_VARIABLE}: {library[0]} holds no derivation (derivations/<name>/manifest.toml), "
                         f"so a run has nothing of its own to record")
    return own


def _reports_of(args, own: list[str], cache) -> list:
    """The reports of the derivations *own*, in dependency order (each checked with its ancestors)."""
    found = {}
    for did in own:
        found.update((r.id, r) for r in _reports(args, did, cache))
    return [found[did] for did in select() if did in own]


def _scene_args(p):
    from .solver.bodies import DOMAIN
    p.add_argument("body", help="cube, box, prism, cylinder or section")
    p.add_argument("--density", help="density s relative to water, 0 < s < 1 (decimal or p/q)")
    p.add_argument("--dims", help="box a,b,c; prism a,b (side, length); cylinder r,b; cube a (default 1)")
    p.add_argument("--sides", help="number of sides of the prism's regular base")
    p.add_argument("--polygon", help='section: convex polygon "x1,y1 x2,y2 ..." (vertices in order)')
    p.add_argument("--format", choices=("table", "json"), default="table")
    p.add_argument("--output", "--plot", type=Path, dest="output",
                   help="draw the stable positions into this PNG file (--plot: the earlier name)")
    p.add_argument("--certify", action="store_true",
                   help="prove that no other equilibrium exists (an exclusion search over the sphere of up "
                        "vectors in ball arithmetic; cube, box, prism; tens of seconds to minutes)")
    p.epilog = f"Supported inputs: {DOMAIN}. Numbers are ASCII decimals or p/q, kept exact. {EXIT_STATUS}."


def _scene(args) -> int:
    from .report.scene import scene_json, scene_plot, scene_record, scene_table
    from .solver import make_scene, solve
    from .solver.certificate import certify
    from .solver.exclusion import exclusion_search
    from .comparison.coverage import cover

    start = time.perf_counter()
    scene = make_scene(args.body, args.density, args.dims, args.sides, args.polygon)
    if args.certify and scene.body not in ("cube", "box", "prism"):
        raise InputError(f"--certify: the exclusion search covers cubes, boxes and prisms, not a {scene.body}")
    plot = _plot_target(args.output)
    solution = solve(scene)
    certify(solution)
    if args.certify:
        solution.checks["completeness"] = exclusion_search(solution).record()
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
    p.add_argument("--output", "--plot", type=Path, dest="output",
                   help="draw the phase diagram into this PNG file (--plot: the earlier name)")
    p.add_argument("--steps", default="48", help="densities in the sweep, 4 to 2000 (default 48)")
    p.epilog = ("The sweep's densities k/(steps+1) must all lie in the scene's supported range "
                f"(symfloat scene --help). {EXIT_STATUS}.")


def _phase(args) -> int:
    from fractions import Fraction

    from .report.phase import phase_json, phase_plot, phase_table
    from .solver.bodies import SceneError, make_scene, parse_whole
    from .comparison.thresholds import phase_with_sources

    if args.body not in ("cube", "box"):
        raise SceneError(f"phase diagrams are drawn for cube and box, not {args.body[:40]!r}")
    steps = parse_whole(args.steps, "--steps", 4, 2000)
    make_scene(args.body, "1/2", args.dims)          # the body itself: its --dims are blamed, not --steps
    for s in (Fraction(1, steps + 1), Fraction(steps, steps + 1)):       # both ends of the sweep
        try:
            make_scene(args.body, s, args.dims)
        except SceneError as exc:
            raise SceneError(f"--steps {steps}: {exc}") from None
    plot = _plot_target(args.output)
    diagram = phase_with_sources(args.body, args.dims, steps, progress=None if _quiet(args) else
                                 (lambda msg: print(msg, file=sys.stderr)))
    print(phase_json(diagram) if args.format == "json" else phase_table(diagram))
    if plot:
        _write_plot(phase_plot, diagram, plot, args)
    if not diagram.duality_ok:                  # a failed self-check: exit 1
        raise CheckFailed("the duality s <-> 1 - s does not hold (see the thresholds marked NO DUAL)")
    return EXIT_OK


def _atlas_args(p):
    p.add_argument("body", help="box (edges 1, b/a, c/a; the cell b/a = c/a = 1 is the cube)")
    p.add_argument("--ba", required=True, help="b/a: a grid A:B:N (N values from A to B), a list v1,v2,... or a value "
                                               "(at most 2000 values; at most 10000 shapes b/a x c/a)")
    p.add_argument("--ca", required=True, help="c/a: the same forms")
    p.add_argument("--density", required=True, help="the sweep of densities, A:B:N or a list, symmetric about 1/2")
    p.add_argument("--output", "--out", required=True, type=Path, dest="output",
                   help="directory: parts/ (one Parquet file per cell), atlas.parquet, checks.md (--out: the "
                        "earlier name)")
    p.add_argument("--scheduler", help="address of a running Dask scheduler (default: a local cluster)")
    p.add_argument("--workers", help="worker processes of the local cluster, 0 to 64 (default: the machine's cores); "
                                     "0 computes here without Dask")
    p.add_argument("--figures", type=Path, help="directory for the slice figures atlas-c<c/a>.png")
    p.epilog = ("Cells already written in --output by the same code with the same density sweep are skipped (a "
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
    from .engine.runner import MAX_WORKERS

    ba, ca, densities = shape_grid(args.ba, "--ba"), shape_grid(args.ca, "--ca"), density_grid(args.density)
    check_domain(ba, ca, densities)
    workers = None if args.workers is None else parse_whole(args.workers, "--workers", 0, MAX_WORKERS)
    scheduler = _scheduler(args.scheduler)
    if scheduler and workers is not None:
        raise InputError("--workers sizes the local cluster; with --scheduler the cluster has its own workers")
    writable_folder(args.output)
    if args.figures is not None:
        writable_folder(args.figures)
    return run_atlas(args.output, ba, ca, densities, scheduler, workers, args.figures, quiet=_quiet(args),
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
    folder = args.output or in_outputs("docs")
    if args.derivations:
        return _bench_derivations(args, folder)
    writable_folder(folder)
    quiet = _quiet(args)
    written = generate(folder, quick=args.quick,
                       progress=lambda msg: quiet or print(msg, file=sys.stderr, flush=True))
    _say(args, f"{len(written)} numerics files changed in {folder}")
    return EXIT_OK


def _bench_derivations(args, folder: Path) -> int:
    import platform

    from .numerics.cost import cost_markdown, cost_rows, write_section
    path = writable_folder(folder) / "performance.md"
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
    p.add_argument("--output", type=Path, help="folder of the documents and baselines read and written instead "
                                               "of docs/ (of the library, else of the checkout)")


def _coverage(args) -> int:
    from .report.ledger_command import run
    if args.output is not None:
        if args.write or args.update_baseline:
            writable_folder(args.output)
        elif not args.output.is_dir():
            raise InputError(f"--output '{args.output}': " + ("not a folder" if args.output.exists() else
                                                               "no such folder") + " to read the baselines from")
    return run(args)


def _check_args(p):
    p.add_argument("printed", help=r"the printed formula in LaTeX, e.g. '\bar z = \frac{3(2r-h)^2}{3(3r-h)}'")
    p.add_argument("--against", action="append", required=True,
                   help=r"a formula or definition in LaTeX (S = expression, integrals \int_a^b f \, dx "
                        "allowed); repeat for several")
    p.add_argument("--where", default="", help="inequalities that restrict the domain, e.g. '0 < h < r'")
    p.add_argument("--domain", help="sampling intervals, e.g. 'r=1:3, h=0:1' (default 0:4 for every symbol)")
    p.add_argument("--format", choices=("text", "json"), default="text")
    p.add_argument("--output", type=Path, help="write the report to this file instead of stdout")
    p.epilog = ("Exit status: 0 the print holds; 1 it is refuted or undecided; 2 bad input (a formula the reader "
                "does not accept, a definition the print does not use, an output whose folder is missing); "
                "130 interrupted.")


def _check(args) -> int:
    from .engine.formula_check import check, parse_domain
    from .report.formula_check import check_json, check_text
    out = writable_target(args.output) if args.output is not None else None
    result = check(args.printed, args.against, where=args.where, domain=parse_domain(args.domain))
    text = check_json(result) if args.format == "json" else check_text(result)
    if out is None:
        print(text, end="")
    else:
        write_atomic(out, text.encode("utf-8"))
        _say(args, f"wrote {out}")
    return EXIT_OK if result.verdict == "holds" else EXIT_CHECK


def _site_args(p):
    p.add_argument("--output", "--out", type=Path, dest="output",
                   help="folder for the static site (default: build/site of the library or the checkout; --out: "
                        "the earlier name); an existing folder must be empty or hold an earlier site")


def _site(args) -> int:
    from .site.build import build_site          # Sphinx and MyST-NB: only when the site is built
    out = writable_folder(args.output) if args.output else in_outputs("build/site")
    kinds = in_project("docs/errata-kinds.md") if project_root() is not None else None
    changed, warnings = build_site(out, in_outputs("docs"), in_outputs("notebooks"), kinds,
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
    "run": Command("verify everything and write every report and notebook", _run_args, _run),
    "scene": Command("every equilibrium of one body at one density", _scene_args, _scene),
    "phase": Command("stable positions against density, thresholds located", _phase_args, _phase),
    "atlas": Command("the stability atlas of the box over (b/a, c/a, s), computed on Dask", _atlas_args, _atlas),
    "bench": Command("numerics benchmark: write docs/numerics.md and its figures", _bench_args, _bench),
    "coverage": Command("the coverage ledger: every math span and quantitative sentence quoted or waived; "
                        "with --readings the readings checked against the print", _coverage_args, _coverage),
    "site": Command("build the static web site (annotated edition, errata, notebooks, numerics) from the "
                    "committed records", _site_args, _site),
    "check": Command("check one printed formula (LaTeX) against a formula or a definition; a refuted print "
                     "gets a counterexample and the likeliest corrections", _check_args, _check),
}


_CACHED = ("verify", "errata", "notebooks", "run")       # the commands that read checked reports from the cache


def _command_in(argv) -> str | None:
    """The subcommand *argv* names (its first word that is not an option), or None."""
    return next((a for a in argv if not a.startswith("-")), None)


def _parser(only=None):
    """The command line; with *only*, the options of that subcommand alone are built (the others import
    what their options list, e.g. the errata formats or the scene's domain, which ``--help`` does not need)."""
    common = _Parser(add_help=False)
    common.add_argument("--quiet", action="store_true", help="no progress on stderr (or SYMFLOAT_QUIET=1)")
    p = _Parser(prog="symfloat", description="Machine-checked re-derivation of classical "
                "texts on floating bodies and centroids.", epilog=EXIT_STATUS + ".")
    p.add_argument("--version", action="version", version=f"symfloat {__version__}")
    sub = p.add_subparsers(dest="command", required=True)
    for name, command in COMMANDS.items():
        sp = sub.add_parser(name, parents=[common], help=command.help, epilog=EXIT_STATUS + ".")
        sp.add_argument("--no-cache", action="store_true",      # accepted everywhere, shown where it acts
                        help="re-check every derivation" if name in _CACHED else argparse.SUPPRESS)
        if only is None or only == name:
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
    args = _parser(_command_in(sys.argv[1:] if argv is None else argv) or "").parse_args(argv)
    with _Interrupts() as interrupts:
        try:
            library_folders()                 # a further library of texts that is not there: one line, exit 2
            from .engine.environment import check_environment
            check_environment()               # SYMFLOAT_WORKERS, SYMFLOAT_SLOWDOWN: likewise
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
    print("symfloat: interrupted" + (" (finished checks are kept in the cache)" if args.command in _CACHED else ""),
          file=sys.stderr)
    return EXIT_INTERRUPTED


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
