"""The errata report: ``docs/errata.md`` and ``symfloat errata --format json|csv|latex``, in two apparatus.

The faults of the original (misprint, calculation, consequential, claim) and the corrections of the
transcription are listed apart (:data:`symfloat.model.erratum.APPARATUS`; the criteria are in
``docs/errata-kinds.md``).  The JSON stays one array, in source order; each entry names its
``apparatus``.  A correction of the transcription shows the transcription as it reads and what
the original very probably printed.
"""
from __future__ import annotations

import csv
import io
import json
import re
import unicodedata
from collections import Counter

from ..engine.check import DerivationReport
from .cross_references import readable
from ..model.erratum import APPARATUS, apparatus, apparatus_in_words
from ..numbers import counted
from ..model.source import get_source

__all__ = ["errata_entries", "errata_json", "errata_markdown", "errata_csv", "errata_latex", "erratum_slug",
           "ERRATA_FORMATS", "apparatus_counts"]


def erratum_slug(source: str, locator: str) -> str:
    """The stem of an erratum's id: lower-case ASCII letters, digits and single hyphens, ``§`` as ``s`` (as
    the derivation ids write it), accents dropped; usable as a key, a file name and an anchor.

    >>> erratum_slug("graefe", "§1 prismatoid volume"), erratum_slug("hasab", "Megjegyzés"), erratum_slug("scheeffer", "(78c)")
    ('graefe-s1-prismatoid-volume', 'hasab-megjegyzes', 'scheeffer-78c')
    """
    text = unicodedata.normalize("NFKD", f"{source}-{locator}".replace("§", "s")).encode("ascii", "ignore").decode()
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")


def errata_entries(reports: list[DerivationReport]) -> list[dict]:
    """One entry per erratum, in source order; ids ``<slug of source and locator>-n``, the earlier form
    ``source-locator-n`` kept as ``alias``."""
    counter: Counter = Counter()
    slugs: Counter = Counter()
    by_id = {r.id: r for r in reports}
    entries = []
    for d in reports:
        for f in d.formulas:
            if f.verdict != "erratum" or not f.erratum:
                continue
            counter[(f.source, f.locator)] += 1
            slugs[erratum_slug(f.source, f.locator)] += 1
            entries.append({
                "id": f"{erratum_slug(f.source, f.locator)}-{slugs[erratum_slug(f.source, f.locator)]}",
                "alias": f"{f.source}-{f.locator}-{counter[(f.source, f.locator)]}",
                "source": f.source, "locator": f.locator, "printed": f.excerpt,
                "corrected": f.erratum["corrected"], "kind": f.erratum["kind"],
                "confidence": f.erratum["confidence"], "evidence": readable(d, f.erratum["evidence"], by_id),
                "derivation": d.id, "formula": f.id, "apparatus": apparatus(f.erratum["kind"]),
                **({"places": f.erratum["places"]} if f.erratum.get("places") else {}),
                **{k: readable(d, f.erratum[k], by_id) for k in ("objection", "answer") if f.erratum.get(k)},
            })
    return entries


def errata_json(reports) -> str:
    return json.dumps(errata_entries(reports), indent=1, ensure_ascii=False) + "\n"


_CSV_FIELDS = ("id", "source", "locator", "kind", "confidence", "printed", "corrected", "evidence", "derivation")


def errata_csv(reports) -> str:
    """One row per erratum (RFC 4180, a header row first): id, source, locator, kind, confidence, the printed
    and corrected text, the evidence, the derivation."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(_CSV_FIELDS)
    for e in errata_entries(reports):
        writer.writerow([e[k] for k in _CSV_FIELDS])
    return out.getvalue()


_TEX_SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_",
                "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}"}


def _tex_text(text: str) -> str:
    """*text* as LaTeX prose: its special characters escaped."""
    return "".join(_TEX_SPECIAL.get(c, c) for c in text)


_MATH = re.compile(r"\$\$(.+?)\$\$|\$(.+?)\$", re.S)


def _tex_of(text: str) -> str:
    r"""A printed or corrected text as LaTeX: the transcription's math kept (a display as ``\[...\]``), its
    words escaped; a text without dollars is one formula when it reads as one (a backslash, a relation, an
    index), else words.

    >>> _tex_of(r"so ist $x_s = \frac{3}{8} r$ & mehr"), _tex_of("x_s = 3 r / 8"), _tex_of("only for s > 1/2 and more")
    ('so ist $x_s = \\frac{3}{8} r$ \\& mehr', '$x_s = 3 r / 8$', 'only for s > 1/2 and more')
    """
    if "$" not in text:
        words = re.sub(r"\\[A-Za-z]+(\{[^{}]*\})?", "", text)
        if re.search(r"[\\=^_]", text) and len(re.findall(r"[A-Za-z]{3,}", words)) <= 2:
            return f"${text.strip()}$"
        return _tex_text(text)
    out, at = [], 0
    for m in _MATH.finditer(text):
        out.append(_tex_text(text[at:m.start()]))
        out.append(f"\\[{m[1].strip()}\\]" if m[1] is not None else f"${m[2]}$")
        at = m.end()
    out.append(_tex_text(text[at:]))
    return " ".join("".join(out).split())


_LABELS = {"original": ("Printed:", "Corrected:"),
           "transcription": ("Transcribed:", "The original very probably printed:")}


def errata_latex(reports) -> str:
    r"""An errata list an editor can paste into a LaTeX document (``\usepackage{amsmath}``), in the two parts of
    the Markdown report (the faults of the original, then the corrections of the transcription): per source a
    subsection, per erratum an item with its locator, kind, confidence and id, what is printed (or transcribed)
    and what should stand, each its own paragraph (``\par``: a ``\\`` after a display is an error)."""
    entries = errata_entries(reports)
    out = ["% Errata generated by `symfloat errata --format latex`; do not edit by hand."]
    for part, (key, (title, _)) in zip(("I", "II"), APPARATUS.items()):
        chosen = [e for e in entries if e["apparatus"] == key]
        if not chosen:
            continue
        shown, right = _LABELS[key]
        out += ["", f"\\section*{{Part {part}: {title[0].upper() + title[1:]} ({len(chosen)})}}"]
        for source in dict.fromkeys(e["source"] for e in chosen):
            src = get_source(source)
            year = f", {src.year}" if src.year else ""
            out += ["", f"\\subsection*{{{_tex_text(src.author)}, \\emph{{{_tex_text(src.title)}}}{year}}}",
                    "\\begin{itemize}"]
            for e in (e for e in chosen if e["source"] == source):
                out += [f"  \\item \\textbf{{{_tex_text(e['locator'])}}} ({e['kind']}, confidence {e['confidence']}; "
                        f"\\texttt{{{_tex_text(e['id'])}}}).\\par",
                        f"  {shown} {_tex_of(e['printed'])}\\par",
                        f"  {right} {_tex_of(e['corrected'])}"]
            out.append("\\end{itemize}")
    return "\n".join(out) + "\n"


def _fence(text: str) -> str:
    return "\n".join("    " + line for line in text.splitlines())


def apparatus_counts(entries) -> str:
    """``"N faults of the original, M corrections of the transcription"`` of *entries*."""
    return apparatus_in_words(e["kind"] for e in entries)


def errata_markdown(reports: list[DerivationReport]) -> str:
    """The errata in two parts, the faults of the original and the corrections of the transcription,
    each grouped by source, then locator: the printed (or transcribed) excerpt beside the correction,
    with kind, confidence and evidence."""
    entries = errata_entries(reports)
    out = ["# Errata", "",
           "Generated by `symfloat errata` from the derivations; do not edit by hand.",
           "Each entry quotes the transcription verbatim, gives the correction the derivation proves, its",
           "kind and confidence. Part I lists the faults of the original print (`misprint`, `calculation`,",
           "`consequential`, `claim`); part II the corrections of this project's transcription of the scan",
           "(`transcription`), with what the original very probably printed. The criteria for kind and",
           "confidence: `docs/errata-kinds.md`.", ""]
    kinds = Counter(e["kind"] for e in entries)
    out.append(f"{counted(len(entries), 'erratum', 'errata')}: {apparatus_counts(entries)} ("
               + ", ".join(f"{n} {k}" for k, n in sorted(kinds.items())) + ").")
    for part, (key, (title, _)) in zip(("I", "II"), APPARATUS.items()):
        chosen = [e for e in entries if e["apparatus"] == key]
        out += ["", f"# Part {part}: {title[0].upper() + title[1:]} ({len(chosen)})"]
        for source in dict.fromkeys(e["source"] for e in chosen):
            src = get_source(source)
            year = f", {src.year}" if src.year else ""
            out += ["", f"## {source}: {src.author}, *{src.title}*{year}"]
            group = [e for e in chosen if e["source"] == source]
            for locator in dict.fromkeys(e["locator"] for e in group):
                out += ["", f"### {locator}"]
                for e in (e for e in group if e["locator"] == locator):
                    shown, right = _LABELS[key]
                    out += ["", f"**{e['id']}** — {e['kind']}, confidence {e['confidence']}"
                                f" (derivation `{e['derivation']}`)", "",
                            shown, "", _fence(e["printed"]), "",
                            right, "", _fence(e["corrected"]), "",
                            f"Evidence: {e['evidence']}"]
                    if e.get("places"):
                        out += ["", f"Also printed at: {', '.join(e['places'])}."]
                    if e.get("objection"):
                        out += ["", f"Objection: {e['objection']}", "", f"Answer: {e['answer']}"]
    return "\n".join(out) + "\n"


ERRATA_FORMATS = {"md": errata_markdown, "json": errata_json, "csv": errata_csv, "latex": errata_latex}
