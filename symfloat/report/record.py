"""The verification record: ``symfloat verify --format json`` and its table."""
from __future__ import annotations

import json
from collections import Counter

from ..engine.check import DerivationReport

__all__ = ["verification_record", "verification_table", "VERDICTS"]

VERDICTS = ("verified", "erratum", "unverifiable", "trivial")


def _formula_entry(d: DerivationReport, f) -> dict:
    entry = {"id": f.id, "source": f.source, "locator": f.locator, "verdict": f.verdict,
             "evidence": f.evidence, "numeric": f.numeric, "derivation": d.id, "printed": f.excerpt}
    if f.reason:
        entry["reason"] = f.reason
    if f.erratum:
        entry["erratum"] = {"kind": f.erratum["kind"], "confidence": f.erratum["confidence"],
                            "corrected": f.erratum["corrected"]}
    return entry


def verification_record(reports: list[DerivationReport]) -> dict:
    """``{"formulas": [...], "summary": {...}}`` as in the design brief.

    ``summary.seconds`` is the checking time of the derivations (as recorded
    when they were checked, also for those now read from the cache)."""
    formulas = [_formula_entry(d, f) for d in reports for f in d.formulas]
    steps = Counter(s.status for d in reports for s in d.steps)
    verdicts = Counter(f["verdict"] for f in formulas)
    return {
        "formulas": formulas,
        "summary": {
            "formulas": len(formulas),
            **{v: verdicts.get(v, 0) for v in VERDICTS},
            "evidence": dict(sorted(Counter(f["evidence"] or "none" for f in formulas).items())),
            "steps": dict(sorted(steps.items())),
            "derivations": [d.id for d in reports],
            "failures": [msg for d in reports for msg in d.failures],
            "seconds": round(sum(d.seconds for d in reports), 3),
        },
    }


def record_json(reports) -> str:
    return json.dumps(verification_record(reports), indent=1, ensure_ascii=False) + "\n"


def _best(numeric):
    if not numeric:
        return "—"
    r = min(numeric, key=lambda r: r["rel_error"])
    return f"{r['rel_error']:.1e} ({len(numeric)} methods)"


def verification_table(reports: list[DerivationReport]) -> str:
    """A readable plain-text table, one row per printed formula, then the summary."""
    rows = [("formula", "locator", "verdict", "evidence", "best witness rel. error")]
    for d in reports:
        for f in d.formulas:
            verdict = f.verdict + (f" ({f.erratum['kind']})" if f.erratum else "")
            rows.append((f.id, f.locator, verdict, f.evidence or "—", _best(f.numeric)))
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    lines = ["  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in rows]
    lines.insert(1, "  ".join("-" * w for w in widths))
    s = verification_record(reports)["summary"]
    cached = sum(d.cached for d in reports)
    lines.append("")
    lines.append(f"{s['formulas']} printed formulas: {s['verified']} verified, {s['erratum']} errata, "
                 f"{s['unverifiable']} unverifiable, {s['trivial']} trivial; steps {s['steps']}; checking time {s['seconds']:.1f} s"
                 + (f" ({cached} of {len(s['derivations'])} derivations read from the cache)" if cached else ""))
    for msg in s["failures"]:
        lines.append(f"FAILURE: {msg}")
    return "\n".join(lines) + "\n"
