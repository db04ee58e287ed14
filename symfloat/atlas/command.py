"""``symfloat atlas box``: build (or resume) the atlas, check it, draw it."""
from __future__ import annotations

import json
from pathlib import Path

from ..errors import EXIT_CHECK, EXIT_OK
from ..files import write_if_changed
from .checks import checks_markdown, run_checks
from .dataset import read_atlas
from .run import CUBE_REFERENCE, build

__all__ = ["run_atlas"]


def run_atlas(out: Path, ba, ca, densities, scheduler, workers, figures, quiet: bool, say) -> int:
    result = build(out, ba, ca, densities, scheduler=scheduler, workers=workers, progress=not quiet)
    say(result.summary())
    say(f"wrote {result.path}")
    rows, meta = read_atlas(result.path)
    reference_path = Path(out) / CUBE_REFERENCE
    reference = json.loads(reference_path.read_text(encoding="utf-8")) if reference_path.is_file() else None
    checks = run_checks(rows, meta, reference)
    report = checks_markdown(checks, meta)
    write_if_changed(Path(out) / "checks.md", report)
    if figures is not None:
        from .figure import write_slices
        for path in write_slices(rows, meta, figures, reference):
            say(f"wrote {path}")
    print(report, end="")
    failed = [c.name for c in checks if c.fails_command and not c.ok]
    if failed:
        say(f"symfloat: atlas checks failed: {', '.join(failed)} (see {Path(out) / 'checks.md'})")
        return EXIT_CHECK
    return EXIT_OK
