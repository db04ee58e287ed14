"""The verification record: ``symfloat verify --format json`` and its table."""
from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

from ..engine.check import DerivationReport
from ..engine.witness import record_decision
from ..files import write_if_changed
from ..numbers import counted, steps_in_words
from .cross_references import readable
from .witness_words import best_error

__all__ = ["verification_record", "verification_table", "record_differences", "record_json", "write_record",
           "VERDICTS", "HARDWARE_DOUBLES"]

VERDICTS = ("verified", "erratum", "unverifiable", "trivial")


def _formula_entry(d: DerivationReport, f, by_id: dict) -> dict:
    entry = {"id": f.id, "source": f.source, "locator": f.locator, "verdict": f.verdict,
             "evidence": f.evidence, "numeric": f.numeric, "derivation": d.id, "printed": f.excerpt}
    if f.reason:
        entry["reason"] = readable(d, f.reason, by_id)
    if not f.numeric_content:
        entry["numeric_content"] = False
    if f.erratum:
        entry["erratum"] = {"kind": f.erratum["kind"], "confidence": f.erratum["confidence"],
                            "corrected": f.erratum["corrected"]}
        if f.corrected_numeric:
            entry["erratum"]["numeric"] = f.corrected_numeric     # the witnesses of the corrected reading
    return entry


def verification_record(reports: list[DerivationReport]) -> dict:
    """``{"formulas": [...], "summary": {...}}`` as in the design brief.

    ``summary.seconds`` is the checking time of the derivations (as recorded
    when they were checked, also for those now read from the cache)."""
    by_id = {d.id: d for d in reports}
    formulas = [_formula_entry(d, f, by_id) for d in reports for f in d.formulas]
    steps = Counter(s.status for d in reports for s in d.steps)
    verdicts = Counter(f["verdict"] for f in formulas)
    numeric_content = [f for d in reports for f in d.formulas
                       if f.verdict in ("verified", "erratum") and f.numeric_content]
    return {
        "formulas": formulas,
        "summary": {
            "formulas": len(formulas),
            **{v: verdicts.get(v, 0) for v in VERDICTS},
            "evidence": dict(sorted(Counter(f["evidence"] or "none" for f in formulas).items())),
            "cross_checked": {"formulas": sum(bool(f.numeric or f.corrected_numeric) for f in numeric_content),
                              "with_numeric_content": len(numeric_content)},
            "certified": dict(sorted(Counter(record_decision(r) for d in reports for f in d.formulas
                                             for r in f.numeric + f.corrected_numeric if r.get("certified")).items())),
            "steps": dict(sorted(steps.items())),
            "derivations": [d.id for d in reports],
            "failures": [msg for d in reports for msg in d.failures],
            "seconds": round(sum(d.seconds for d in reports), 3),
        },
    }


def record_json(reports) -> str:
    return json.dumps(verification_record(reports), indent=1, ensure_ascii=False) + "\n"


def write_record(path, reports) -> bool:
    """Write the record to *path* unless the file there differs from it only in what may differ between
    machines (:func:`record_differences`: timings, float64 figures within their reproducibility), so that
    re-running unchanged derivations on another machine or numpy release changes no file."""
    text = record_json(reports)
    try:
        if not record_differences(json.loads(Path(path).read_text(encoding="utf-8")), json.loads(text)):
            return False
    except (OSError, ValueError, KeyError):
        pass
    return write_if_changed(path, text)


def verification_table(reports: list[DerivationReport], elapsed: float | None = None) -> str:
    """A readable plain-text table, one row per printed formula, then the summary; *elapsed* is how long
    this command took, shown beside the checking time recorded (which a cached report keeps from when it
    was checked)."""
    rows = [("formula", "locator", "verdict", "evidence", "best witness rel. error")]
    for d in reports:
        for f in d.formulas:
            verdict = f.verdict + (f" ({f.erratum['kind']})" if f.erratum else "")
            witness = (best_error(f.numeric) if f.numeric or not f.corrected_numeric
                       else f"{best_error(f.corrected_numeric)}, of the correction")
            rows.append((f.id, f.locator, verdict, f.evidence or "—", witness))
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    lines = ["  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in rows]
    lines.insert(1, "  ".join("-" * w for w in widths))
    s = verification_record(reports)["summary"]
    cached = sum(d.cached for d in reports)
    lines.append("")
    now = f"took {elapsed:.1f} s now; " if elapsed is not None else ""
    lines.append(f"{counted(s['formulas'], 'printed formula')}: {s['verified']} verified, "
                 f"{counted(s['erratum'], 'erratum', 'errata')}, {s['unverifiable']} unverifiable, "
                 f"{s['trivial']} trivial; steps: {steps_in_words(s['steps'])}; {now}checking time "
                 f"{'recorded ' if cached else ''}{s['seconds']:.1f} s"
                 + (f" ({cached} of {len(s['derivations'])} derivations read from the cache, their time as "
                    f"recorded when they were checked)" if cached else ""))
    x = s["cross_checked"]
    if x["with_numeric_content"]:
        lines.append(f"numeric cross-checks: {x['formulas']} of {x['with_numeric_content']} verified formulas and "
                     f"errata have a witness ({x['formulas'] / x['with_numeric_content']:.0%})")
    if s["certified"]:
        lines.append("certified witness decisions (Arb): " + ", ".join(f"{n} {k}" for k, n in s["certified"].items())
                     + ("" if "undecided" not in s["certified"] else " (undecided: no finite enclosure, or one "
                        "still too wide to decide at the largest precision; not counted as agreement)"))
    for msg in s["failures"]:
        lines.append(f"FAILURE: {msg}")
    return "\n".join(lines) + "\n"


# What a witness record's figures may differ by between two machines.  A figure computed in hardware doubles
# (float64, and the definition route's 15 digits) has last bits that depend on the processor's vector units
# (numpy's AVX-512 routines for sin, cos and exp on one machine and not on another) and on the numpy and BLAS
# releases (summation order), not on the mathematics; so does an enclosure whose ball was started at a float64
# root.  Three rules, one per kind of record:
#
# - a certified record (Arb) is a proven interval [abs_error_lower, abs_error] around one true difference:
#   two of them are the same when they say the same (agrees, refuted, undecided) and the intervals meet;
#   intervals that do not meet mean that one of them is wrong;
# - a figure in hardware doubles that lies within its method's tolerance says "agrees", and its digits are
#   the machine's; two such are the same, whatever their digits;
# - a figure in hardware doubles beyond its tolerance (an erratum's witness measures the print's error, far
#   larger than the quantity) is the same as another within 64 units in the last place of the larger of the
#   numbers it is made from: the measured quantity and the disagreement itself.
#
# Every other figure (mpmath at n digits, exact arithmetic) is reproducible and compared exactly.
FLOAT64_REPRODUCIBLE = 64 * 2.0 ** -52
_FIGURES = ("abs_error", "abs_error_lower", "rel_error")
HARDWARE_DOUBLES = ("float64", "definitions, 15 digits")     # the route's 15 digits are mpmath's fp context


def _in_hardware_doubles(record: dict) -> bool:
    return any(name in str(record.get("method", "")) for name in HARDWARE_DOUBLES)


def _same_numeric(a: dict, b: dict) -> bool:
    a, b = {k: v for k, v in a.items() if k != "seconds"}, {k: v for k, v in b.items() if k != "seconds"}
    if a.keys() != b.keys():
        return False
    rest = {k: v for k, v in a.items() if k not in _FIGURES} == {k: v for k, v in b.items() if k not in _FIGURES}
    if a.get("certified"):
        if a["abs_error"] is None or b["abs_error"] is None:
            return rest and a == b
        meet = a["abs_error_lower"] <= b["abs_error"] and b["abs_error_lower"] <= a["abs_error"]
        return rest and meet and record_decision(a) == record_decision(b)
    if not _in_hardware_doubles(a):
        return a == b
    if record_decision(a) == record_decision(b) == "agrees":
        return rest
    scale = abs(a["abs_error"] / a["rel_error"]) if a["rel_error"] else 1.0     # the committed quantity's size
    close = (abs(a["abs_error"] - b["abs_error"]) <= FLOAT64_REPRODUCIBLE * max(scale, abs(a["abs_error"]))
             and abs(a["rel_error"] - b["rel_error"]) <= FLOAT64_REPRODUCIBLE * max(1.0, abs(a["rel_error"])))
    return close and rest


def _witness_differences(name: str, committed: list, fresh: list) -> list[str]:
    out = [f"{name}: {len(committed)} witness records committed, {len(fresh)} now"] if len(committed) != len(fresh) else []
    return out + [f"{name}: witness {x.get('method')} differs" for x, y in zip(committed, fresh)
                  if not _same_numeric(x, y)]


def record_differences(committed: dict, fresh: dict) -> list[str]:
    """Where two verification records differ in what must not change: everything but timings, witness
    figures compared to what another machine reproduces (:func:`_same_numeric`).

    >>> e = {"method": "Gauss-Legendre n=8, float64", "abs_error": 1e-14, "rel_error": 1e-15, "seconds": 1}
    >>> rec = lambda n: {"formulas": [{"id": "f", "numeric": [n]}], "summary": {"seconds": 2}}
    >>> record_differences(rec(e), rec({**e, "abs_error": 1.05e-14, "seconds": 3}))
    []
    >>> record_differences(rec(e), rec({**e, "abs_error": 2e-13}))
    ['f: witness Gauss-Legendre n=8, float64 differs']

    An erratum's witness measures the print's error, here 23344 times the quantity (euler §234,
    K-table 3/2); its float64 figures agree to their own last places, not the quantity's:

    >>> k = {"method": "float64", "abs_error": 0.5162813701345467, "rel_error": 23343.999999999913}
    >>> record_differences(rec(k), rec({**k, "abs_error": 0.5162813701345466, "rel_error": 23343.999999999905}))
    []
    >>> record_differences(rec(k), rec({**k, "rel_error": 23343.99999}))
    ['f: witness float64 differs']

    A float64 figure within its tolerance agrees on every machine, its digits the machine's (Scheeffer
    VI.A–B (72a): a root's error, 1.4e-13 on one processor and 8.1e-14 on another); two enclosures of one
    difference must meet:

    >>> t = {"method": "float64", "abs_error": 6.6e-15, "rel_error": 1.4e-13, "rel_tolerance": 1e-9}
    >>> record_differences(rec(t), rec({**t, "abs_error": 3.8e-15, "rel_error": 8.1e-14}))
    []
    >>> record_differences(rec(t), rec({**t, "rel_error": 2e-9}))
    ['f: witness float64 differs']
    >>> c = {"method": "Arb", "certified": True, "abs_error": 2.1e-32, "abs_error_lower": 0.0, "rel_error": 1.7e-32,
    ...      "width": 6.5e-20, "abs_tolerance": 0.0}
    >>> record_differences(rec(c), rec({**c, "abs_error": 2.2e-32}))
    []
    >>> r = {**c, "abs_error": 2e-3, "abs_error_lower": 1e-3}
    >>> record_differences(rec(r), rec({**r, "abs_error": 9e-4, "abs_error_lower": 8e-4}))
    ['f: witness Arb differs']
    """
    out = []
    old = {f["id"]: f for f in committed["formulas"]}
    new = {f["id"]: f for f in fresh["formulas"]}
    out += [f"{i}: only in the committed record" for i in old.keys() - new.keys()]
    out += [f"{i}: not in the committed record" for i in new.keys() - old.keys()]
    for i in sorted(old.keys() & new.keys()):
        a, b = old[i], new[i]
        for key in sorted((a.keys() | b.keys()) - {"numeric", "erratum"}):
            if a.get(key) != b.get(key):
                out.append(f"{i}: {key} differs")
        ea, eb = a.get("erratum") or {}, b.get("erratum") or {}
        if {k: v for k, v in ea.items() if k != "numeric"} != {k: v for k, v in eb.items() if k != "numeric"}:
            out.append(f"{i}: erratum differs")
        out += _witness_differences(i, a.get("numeric", []), b.get("numeric", []))
        out += _witness_differences(f"{i} (corrected)", ea.get("numeric", []), eb.get("numeric", []))
    sa = {k: v for k, v in committed["summary"].items() if k != "seconds"}
    sb = {k: v for k, v in fresh["summary"].items() if k != "seconds"}
    out += [f"summary: {k} differs" for k in sorted(sa.keys() | sb.keys()) if sa.get(k) != sb.get(k)]
    return out
