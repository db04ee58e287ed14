"""Verifying a selection of derivations, with cache and progress."""
from __future__ import annotations

import sys
import time

from ..registry import load, select
from .cache import ReportCache, derivation_key
from .check import DerivationReport, check_derivation

__all__ = ["verify", "Progress"]


class Progress:
    """One line per derivation on stderr; silent when ``quiet``."""

    def __init__(self, quiet: bool = False, stream=None):
        self.quiet = quiet
        self.stream = stream or sys.stderr

    def start(self, i, n, derivation_id):
        if not self.quiet:
            print(f"[{i}/{n}] {derivation_id} ...", end="", file=self.stream, flush=True)

    def tick(self):
        if not self.quiet:
            print(".", end="", file=self.stream, flush=True)

    def done(self, report: DerivationReport):
        if not self.quiet:
            how = "cached" if report.cached else f"{report.seconds:.1f} s"
            bad = f", {len(report.failures)} FAILURES" if report.failures else ""
            print(f" {how}{bad}", file=self.stream, flush=True)


def verify(selector: str | None = None, *, use_cache: bool = True, cache: ReportCache | None = None,
           progress: Progress | None = None) -> list[DerivationReport]:
    """Reports for the derivations *selector* picks, ancestors included."""
    cache = cache or ReportCache(enabled=use_cache)
    progress = progress or Progress(quiet=True)
    ids = select(selector)
    keys: dict[str, str] = {}
    reports = []
    for i, did in enumerate(ids, 1):
        d, module = load(did)
        keys[did] = derivation_key(module, [keys[r] for r in d.requires])
        progress.start(i, len(ids), did)
        data = cache.get(did, keys[did])
        if data is not None:
            report = DerivationReport.from_json(data)
            report.cached = True
        else:
            t0 = time.perf_counter()
            report = check_derivation(d, keys[did], progress=progress.tick)
            report.seconds = time.perf_counter() - t0
            if not report.failures:
                cache.put(did, keys[did], report.to_json())
        progress.done(report)
        reports.append(report)
    return reports
