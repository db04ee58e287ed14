"""A witness record's errors in words, for the tables readers see (verify's table, notebooks, the site).

A certified record (Arb's decision by the ball of the difference, :func:`~symfloat.engine.witness.record_decision`)
shows its proven bound and its decision; a method's error proven against the enclosure is marked ``≤``; any
other record shows its error as measured.

>>> error_cells({"method": "Arb ball arithmetic", "certified": True, "bits": 256, "abs_error": 0.0,
...              "abs_error_lower": 0.0, "rel_error": 0.0, "width": 1e-38, "abs_tolerance": 0.0})
('≤ 0 (agrees, 256 bits)', '≤ 0')
>>> error_cells({"method": "float64", "abs_error": 2e-14, "rel_error": 1e-16, "proven": True})
('≤ 2.0 × 10⁻¹⁴', '≤ 1.0 × 10⁻¹⁶')
"""
from __future__ import annotations

from ..engine.witness import record_decision
from ..numbers import counted, scientific

__all__ = ["error_cells", "best_error"]


def error_cells(record: dict) -> tuple[str, str]:
    """The absolute and the relative error of *record* as the two cells of a table."""
    if record.get("certified"):
        if record["abs_error"] is None:
            return f"no finite bound ({record_decision(record)}, {record['bits']} bits)", "—"
        return (f"≤ {scientific(record['abs_error'])} ({record_decision(record)}, {record['bits']} bits)",
                f"≤ {scientific(record['rel_error'])}")
    mark = "≤ " if record.get("proven") else ""
    return f"{mark}{scientific(record['abs_error'])}", f"{mark}{scientific(record['rel_error'])}"


def best_error(numeric: list) -> str:
    """One cell for a formula's witnesses: the certified decision's relative bound where there is one (the
    largest, "undecided" when one is), else the smallest relative error of a method; and how many methods.

    >>> best_error([{"method": "mpmath, 30 digits", "abs_error": 1e-31, "rel_error": 2e-31}])
    '2.0 × 10⁻³¹ (1 method)'
    """
    if not numeric:
        return "—"
    methods = counted(len(numeric), "method")
    certified = [r for r in numeric if r.get("certified")]
    if any(record_decision(r) == "undecided" for r in certified):
        return f"undecided ({methods})"
    if certified:
        return f"≤ {scientific(max(r['rel_error'] for r in certified))}, proven ({methods})"
    r = min(numeric, key=lambda r: r["rel_error"])
    return f"{scientific(r['rel_error'])} ({methods})"
