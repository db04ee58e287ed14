"""A witness record's errors in words, for the tables readers see (verify's table, notebooks, the site).

A certified record (Arb's decision by the ball of the difference, :func:`~symfloat.engine.witness.record_decision`)
shows its proven bound and its decision; a method's error proven against the enclosure is marked ``≤``; any
other record shows its error as measured.

>>> error_cells({"method": "Arb ball arithmetic", "certified": True, "bits": 256, "abs_error": 0.0,
...              "abs_error_lower": 0.0, "rel_error": 0.0, "width": 1e-38, "abs_tolerance": 0.0})
('≤ 0.0e+00 (agrees, 256 bits)', '≤ 0.0e+00')
>>> error_cells({"method": "float64", "abs_error": 2e-14, "rel_error": 1e-16, "proven": True})
('≤ 2.0e-14', '≤ 1.0e-16')
"""
from __future__ import annotations

from ..engine.witness import record_decision

__all__ = ["error_cells", "best_error"]


def error_cells(record: dict) -> tuple[str, str]:
    """The absolute and the relative error of *record* as the two cells of a table."""
    if record.get("certified"):
        if record["abs_error"] is None:
            return f"no finite bound ({record_decision(record)}, {record['bits']} bits)", "—"
        return (f"≤ {record['abs_error']:.1e} ({record_decision(record)}, {record['bits']} bits)",
                f"≤ {record['rel_error']:.1e}")
    mark = "≤ " if record.get("proven") else ""
    return f"{mark}{record['abs_error']:.1e}", f"{mark}{record['rel_error']:.1e}"


def best_error(numeric: list) -> str:
    """One cell for a formula's witnesses: the certified decision's relative bound where there is one (the
    largest, "undecided" when one is), else the smallest relative error of a method."""
    if not numeric:
        return "—"
    certified = [r for r in numeric if r.get("certified")]
    if any(record_decision(r) == "undecided" for r in certified):
        return f"undecided ({len(numeric)} methods)"
    if certified:
        return f"≤ {max(r['rel_error'] for r in certified):.1e}, proven ({len(numeric)} methods)"
    r = min(numeric, key=lambda r: r["rel_error"])
    return f"{r['rel_error']:.1e} ({len(numeric)} methods)"
