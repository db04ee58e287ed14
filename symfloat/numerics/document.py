"""The numerics benchmark (``symfloat bench``): docs/numerics.md and docs/figures/numerics-*.png.

1. error against run time of every witness across methods and precisions (:mod:`.bench`);
2. convergence orders against theory, kinks and their remedy (:mod:`.orders`);
3. stiff and extreme cases of the closed forms, with stable equivalents (:mod:`.forms`);
4. the solver's error next to bifurcation densities against 50-digit references (:mod:`.conditioning`);
5. the discriminant forms of Scheeffer IX and their stable equivalents (:mod:`.discriminant`).

Derivations and their witnesses are found through the registry, so a new
derivation is benchmarked without being named here.
"""
from __future__ import annotations

import math
import re
from collections import Counter
from pathlib import Path

import matplotlib.pyplot as plt
import sympy as sp

from ..files import write_if_changed
from ..model.myst import inline, unescaped
from ..prose import typeset
from ..model.source import SOURCES
from ..model.span import math_spans, widened
from ..model.symbol_names import latex
from ..registry import manifest, statements
from ..numbers import method_words, scientific, written
from .bench import FAMILIES, Bench, run_bench
from .conditioning import CASES, conditioning_markdown, conditioning_rows
from .discriminant import table_markdown as discriminant_markdown
from .forms import CATASTROPHIC, STABLE_TOLERANCE, evaluate, forms, scan
from .orders import HEELS, PANELS, convergence_witnesses, gauss_legendre_degrees, kink_study, registry_orders
from .report import (THRESHOLDS, cheapest, family_figure, fingerprint, fmt_err, fmt_proven, fmt_time,
                     method_rows, write_png_if_changed)
from .route_bench import ROUTE_FAMILY

__all__ = ["generate", "quick_selection"]

QUICK_KINK_PANELS = (4, 8, 16, 32, 64, 128)


def _smallest(ids):
    from ..registry import files
    return min(ids, key=lambda i: (sum(f.stat().st_size for f in files(i) if f.suffix == ".py"), i))


def quick_selection() -> tuple[tuple[str, ...], str]:
    """What ``bench --quick`` measures, chosen without naming a derivation: for each witness family (the
    classes listed under one name in :data:`~symfloat.numerics.bench.FAMILIES`) the smallest derivation
    module (source size, a proxy for its cost) whose source declares such a witness, and the smallest module
    that provides closed forms for the stiffness scan."""
    from ..registry import files, ids as all_ids, providing
    ids = all_ids()
    sources = {i: "".join(f.read_text(encoding="utf-8") for f in files(i) if f.suffix == ".py") for i in ids}
    picked = set()
    for family in dict.fromkeys(FAMILIES.values()):
        names = [f"{cls.__name__}(" for cls, f in FAMILIES.items() if f == family]
        declaring = [i for i in ids if any(n in sources[i] for n in names)]
        if declaring:
            picked.add(_smallest(declaring))
    return tuple(sorted(picked)), _smallest(providing("forms"))


def _slug(text):
    return "".join(c if c.isalnum() else "-" for c in text.lower()).strip("-")


def _table(head, rows):
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def _source(key: str) -> str:
    """A source by its author and title, for a heading."""
    source = SOURCES[key]
    return f"{source.author}, *{source.title}*"


def _derivation(did: str) -> str:
    """A derivation by its title (what its notebook's heading says); a reference integrand of the study as
    such."""
    return "a reference integrand" if did == "(reference)" else typeset(statements(did).title)


def _cell(text: str) -> str:
    """Words with their ``$...$`` mathematics for a table cell, whole."""
    return inline(text, None, cell=True)


def _measures(description: str) -> str:
    """What a witness measures, as its declaration says it in words and ASCII mathematics, for a table cell
    with the mathematics typeset (:func:`~symfloat.prose.typeset`, as the notebooks show it)."""
    return _cell(typeset(description))


def _printed_of(key: str):
    """``(derivation id, its Printed formula)`` of *key* (``derivation/name``, ``name#corrected`` for the
    correction's reading); ``None`` for the formula where *name* is a step of the derivation, no printed one."""
    did, name = key.split("/", 1)
    try:
        return did, statements(did).get_printed(name.split("#")[0])
    except KeyError:
        return did, None


def _place(key: str) -> str:
    """The printed formula *key* by its derivation's title and its place in the source; a step that is no
    printed formula by the title alone."""
    did, p = _printed_of(key)
    return _cell(_derivation(did) + ("" if p is None else f", {p.locator}"))


_REWRITES = {"factor": "factored", "cancel": "cancelled", "together": "over one denominator", "expand": "expanded"}


def _formula(key: str) -> str:
    """The printed formula *key* for a table cell: its place in the source and its print, typeset
    (:func:`_printed`); a step of a derivation that is no printed formula by the derivation's title."""
    did, p = _printed_of(key)
    if p is None:
        return _cell(_derivation(did))
    corrected = " (as corrected)" if key.endswith("#corrected") else ""
    return f"{_cell(p.locator)}{corrected}: {inline(_printed(manifest(did).source, p.excerpt), 160, cell=True)}"


_TAG = re.compile(r"\\(?:tag|label)\{[^}]*\}")


def _printed(source: str, excerpt: str) -> str:
    """The excerpt as the transcription prints it, widened to whole formulas (an excerpt may begin or end
    inside one, as the edition quotes it), each formula inline: a table cell is no place for a display (its
    ``\\tag``, which inline mathematics does not take, left out; the place is in the cell already); the words
    without the transcription's Markdown escapes (:func:`~symfloat.model.myst.inline` escapes them again)."""
    text = SOURCES[source].text()
    at = text.find(excerpt)
    if at < 0:
        return excerpt
    spans = math_spans(source)
    a, b = widened(at, at + len(excerpt), [(m.start, m.end, m.kind) for m in spans])
    out, last = [], a
    for m in spans:
        if a <= m.start and m.end <= b:
            out += [unescaped(text[last:m.start]), "$", _TAG.sub("", m.math).strip(), "$"]
            last = m.end
    return "".join(out + [unescaped(text[last:b])])


def _unenclosed_words(bench, family, ms) -> list:
    """The paragraph of a family that counts its witnesses without an Arb enclosure, and the table that
    names them and says why, in words."""
    witnesses = {f"{m.derivation}/{m.witness}" for m in ms}
    missing = {k: why for k, (f, why) in bench.unenclosed.items() if f == family and k in witnesses}
    if not missing:
        return [f"Arb encloses all {len(witnesses)} witnesses of this family.", ""]
    rows = [(_cell(_derivation(key.split("/")[0])), _measures(bench.witnesses[key]), why)
            for key, why in sorted(missing.items(), key=lambda kv: (kv[1], kv[0]))]
    return [f"Arb encloses {len(witnesses) - len(missing)} of the {len(witnesses)} witnesses of this family. "
            f"The other {len(missing)} have no rigorous method, so no Arb rows, and their methods are measured "
            f"against the exact reading (else their most precise method):", "",
            _table(("derivation", "what the witness measures", "why it has no enclosure"), rows), ""]


def _route_words(bench, ms) -> list:
    """The paragraph of the definition route: what it measures, and how many formulas have no enclosure, by
    reason."""
    formulas = {f"{m.derivation}/{m.witness}" for m in ms}
    missing = [why for f, why in bench.unenclosed.values() if f == ROUTE_FAMILY]
    counts = "; ".join(f"{why}: {n}" for why, n in sorted(Counter(missing).items(), key=lambda x: (-x[1], x[0])))
    words = (f"The route measures every formula no declared witness targets, from the derivation's own "
             f"definitions at its seeded points (a relation's sides are read elsewhere and not shown here). Arb "
             f"encloses {len(formulas)} of the {len(formulas) + len(missing)} formulas it measures; each of their "
             f"methods is measured against the enclosure at 256 bits (its bits are those the route asks for, the "
             f"integrals' guard bits above them).")
    if missing:
        words += f" The other {len(missing)} have no enclosure and are left out here — {counts}."
    return [words, ""]


def _rows(ms):
    return [(method_words(r[0]), r[1], fmt_err(r[2]), fmt_err(r[3]), fmt_time(r[4]), fmt_proven(r[5], r[1]))
            for r in method_rows(ms)]


def _section_bench(bench, figures):
    kinds = list(bench.references.values())
    n_ball, n_exact = sum(v.startswith("Arb") for v in kinds), kinds.count("exact")
    lines = ["## 1. Error against run time", "",
             "Every witness of every derivation is re-run with every method that applies to it: mpmath tanh-sinh "
             "and Gauss–Legendre at 15, 30, 50 and 100 digits and fixed-order Gauss–Legendre in float64 for "
             "section integrals and plane sections (plus composite Simpson and trapezoid in float64 where the "
             "source's own method is Simpson's rule); exact hull faces and Gauss–Legendre slices for hulls; the "
             "witness's own computation at 15 (float64), 30 and 50 digits for straightedge constructions; the "
             "methods a declared witness of a floating body or a plane figure names (float64 and 40 or 50 digits, "
             "tied to its limit and series steps); the formulas the definition route measures, from the derivation's "
             "own definitions at its seeded points, in Arb at 64 and 128 bits and by mpmath at 15, 30 and 50 "
             "digits. Every witness whose kind has a certified method is enclosed in "
             "Arb ball arithmetic (FLINT) at 256 bits, its own rigorous enclosure of the quantity; where every case "
             "has a finite enclosure, that ball is the reference of every method of the witness, and Arb at 64 and "
             "128 bits is a row of its own (its time, and as error its proven width: its radius plus the distance "
             "of its midpoint from the 256-bit ball's, the ball's radius included; 'no bound' where the ball is not "
             "finite at those bits). The error of every other method is relative and proven, |value − mid| + rad "
             "against that ball, so that the true error is at most the figure shown. A witness without an "
             "enclosure is measured against the exact value of its formula's valid reading (the print, or its "
             "correction where an erratum is declared) at the case's parameters, also a proven error, else against "
             "its most precise method, a measured error (the column 'error proven' counts the witnesses whose "
             "errors are proven bounds); each family names its witnesses without an enclosure and why, in words. "
             f"{n_ball} formulas are measured against an enclosure, {n_exact} against an exact reading and "
             f"{len(kinds) - n_ball - n_exact} against a measured reference (the reference column of the tables "
             "below says which). Self-check: every Arb ball of a witness meets its 256-bit enclosure, and every "
             "method the witness declares lies within its own tolerance of it; a miss stops the benchmark with an "
             "error. Times are wall times of all cases of a witness, median of repeats (they vary from run to run, "
             "and so may the choice of the cheapest method; nothing else does). A worst error that does not fall "
             "with the precision is the witness's own approximation (a limit by Richardson extrapolation) or, against an exact reading, the printed number's own rounding "
             "(Scheeffer's worked examples print four or five digits; the verdict allows for them by the printed "
             "digits), not the method's rounding.", ""]
    head = ("method", "witnesses", "worst rel. error", "median rel. error", "median time", "error proven")
    for family in (*dict.fromkeys(FAMILIES.values()), ROUTE_FAMILY):
        ms = [m for m in bench.measurements if m.family == family]
        if not ms:
            continue
        name = f"numerics-{_slug(family)}.png"
        figures[name] = family_figure(family, ms, "formula" if family == ROUTE_FAMILY else "witness")
        lines += [f"### {family}", "", f"![{family}](figures/{name})", "", _table(head, _rows(ms)), ""]
        lines += _route_words(bench, ms) if family == ROUTE_FAMILY else _unenclosed_words(bench, family, ms)
    lines += ["### Per source", ""]
    for source in dict.fromkeys(m.source for m in bench.measurements):
        ms = [m for m in bench.measurements if m.source == source]
        lines += [f"#### {_source(source)}", "", _table(head, _rows(ms)), ""]
    lines += ["### Cheapest method per formula", "",
              f"The fastest method whose relative error is within {' and '.join(map(written, THRESHOLDS))} "
              "(methods compared by their median time over the witness family; among those within a factor 2 "
              "of the fastest, the lowest precision and fewest nodes, so that timing noise does not change the "
              "choice); the time shown is that of the witness whose method it is; "
              "'none' when no method reaches it (float64-only witnesses, or a 100-digit reference that is itself "
              "the only run at that precision).", ""]
    best = {t: cheapest(bench, t) for t in THRESHOLDS}
    for source in dict.fromkeys(m.source for m in bench.measurements):
        keys = list(dict.fromkeys(f"{m.derivation}/{n}" for m in bench.measurements if m.source == source
                                  for n in m.errors))
        rows = []
        for key in keys:
            cells = [_formula(key), bench.references.get(key, "")]
            for t in THRESHOLDS:
                b = best[t][key]
                cells.append("none" if b is None else f"{method_words(b[0])}, {fmt_time(b[2])}")
            rows.append(cells)
        head = ("formula", "reference", *(f"≤ {written(t)}" for t in THRESHOLDS))
        lines += [f"#### {_source(source)}", "", _table(head, rows), ""]
    return lines


def _orders_figure(rows, kinks, conv):
    fig, ax = plt.subplots(figsize=(7.5, 5))
    smooth = next(r for r in rows if r.witness == "exponential")
    ax.loglog(PANELS, smooth.simpson_errors, "d-", label=f"Simpson, exp on [0, 1] (smooth): {smooth.simpson:.2f}")
    chord = next(r for r in rows if r.witness == "circle chord")
    ax.loglog(PANELS, chord.simpson_errors, "o-", label=f"Simpson, circle chord (√ zero at the ends): "
                                                         f"{chord.simpson:.2f}")
    for k, mark in zip(kinks, ("s-", "^-")):
        ax.loglog(k.panels, k.simpson, mark, label=f"Simpson, cube {k.heel}: {k.simpson_order:.2f}")
        ax.loglog(k.panels, k.trapezoid, mark.replace("-", ":"), label=f"trapezoid, cube {k.heel}: "
                                                                       f"{k.trapezoid_order:.2f}")
    ax.set_xlabel("panels")
    ax.set_ylabel("relative error (split at the kinks: exact, not shown)")
    ax.set_title("Measured orders (slope of the fit)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fp = fingerprint(_orders_figure, [(r.witness, [fmt_err(e) for e in r.simpson_errors]) for r in rows],
                     [(k.heel, [fmt_err(e) for e in k.simpson + k.trapezoid]) for k in kinks], conv)
    return fig, fp


def _fo(x):
    return "exact" if x is None else f"{x:.2f}"


def _section_orders(selector, figures, progress, quick):
    progress("orders: Gauss–Legendre degrees, registry integrands, kinks")
    degrees = gauss_legendre_degrees()
    conv = convergence_witnesses(selector)
    rows = registry_orders(selector)
    kinks = [kink_study(h, panels=QUICK_KINK_PANELS) if quick else kink_study(h) for h in HEELS]
    figures["numerics-orders.png"] = _orders_figure(rows, kinks, conv)
    lines = ["## 2. Convergence orders", "",
             "Orders are least-squares slopes of log(error) against log(h) at 40 digits (or in exact rational "
             "arithmetic for the cube), over the panel counts shown; 'exact' means the rule is exact on that "
             "integrand (errors at the rounding floor).", "",
             "![orders](figures/numerics-orders.png)", "",
             "### Gauss–Legendre: degree of exactness", "",
             _table(("nodes n", "highest degree integrated exactly (50 digits)", "theory 2n − 1"),
                    [(n, k, 2 * n - 1) for n, k in degrees]), "",
             "### The registry's convergence witnesses", "",
             _table(("derivation", "what the witness measures", "Simpson: theory", "Simpson: measured",
                     "trapezoid (theory 2): measured"),
                    [(_cell(_derivation(c[0])), _measures(c[2]), c[3], f"{c[4]:.2f}", _fo(c[5])) for c in conv]), "",
             "### Simpson and trapezoid on every quadrature witness's integrand (first case)", "",
             _table(("derivation", "what the witness measures", "integrand", "theory", "Simpson", "trapezoid"),
                    [(_cell(_derivation(r.derivation)), _measures(r.measures), _cell(f"${r.integrand}$"), _cell(r.theory),
                      _fo(r.simpson), _fo(r.trapezoid))
                     for r in rows]), "",
             "### Kinks: the water plane passing a vertex", "",
             "A unit cube turned by a rational rotation; its displacement below a draught by quadrature of the "
             "section area A(z) from the lowest vertex, against the exact volume of the clipped hull. The draught "
             "puts the first vertex height at 2/3 of the interval. Simpson and trapezoid run in exact rational "
             "arithmetic (pure truncation error); 'split' applies Simpson on each piece between vertex heights "
             "(the same total panel count, at least two per piece).", ""]
    smooth = next(r for r in rows if r.witness == "exponential")
    lines += [f"Simpson measures {_fo(smooth.simpson)} on the smooth exp; across the kinks it falls to "
              + " and ".join(f"{_fo(k.simpson_order)} ({k.heel})" for k in kinks)
              + ": one panel pair straddles each kink, where the rule's error is of the order of the jump times "
              "$h^{j+1}$ for a jump in the $j$-th derivative. The trapezoid rule keeps its 2 (its own error is "
              "$h^2$ already). Split at the vertex heights every piece is a quadratic, which Simpson integrates "
              "exactly and Gauss–Legendre with $n \\ge 2$ to rounding.", ""]
    for k in kinks:
        lines += [f"#### Cube {k.heel}", "",
                  f"Draught {k.draught} (heights from the cube's frame); vertex heights inside: "
                  f"{', '.join(str(c) for c in k.kinks)}; "
                  f"exact displacement {k.exact}. Measured order: Simpson {_fo(k.simpson_order)} "
                  f"(4 on smooth integrands), trapezoid {_fo(k.trapezoid_order)}.", "",
                  _table(("panels", "Simpson, whole draught", "trapezoid, whole draught", "Simpson, split at kinks"),
                         [(n, fmt_err(a), fmt_err(b), fmt_err(c))
                          for n, a, b, c in zip(k.panels, k.simpson, k.trapezoid, k.simpson_split)]), "",
                  _table(("Gauss–Legendre n (float64)", "whole draught", "split at kinks"),
                         [(n, fmt_err(a), fmt_err(b)) for n, a, b in k.gauss]), ""]
    return lines


def _section_forms(selector, progress):
    progress("stiff cases: closed forms, float64 against 50 digits")
    lines = ["## 3. Stiff and extreme cases of the closed forms", "",
             "Each closed form is evaluated as printed in float64 and at 50 digits (the same float64 inputs, taken "
             r"exactly), over the sweeps shown. 'digits lost' is $\log_{10}$(worst relative error / $2^{-53}$); more "
             "than 6 is "
             f"flagged catastrophic (relative error above {scientific(CATASTROPHIC)}). Each flagged form has a stable "
             f"equivalent, tested to stay within {written(STABLE_TOLERANCE)} over every sweep.", ""]
    rows = []
    for f in forms():
        r = evaluate(f)
        for label, (e, p) in r.naive.items():
            lost = max(0.0, math.log10(e / 2.0 ** -53)) if e > 0 else 0.0
            st = r.stable.get(label)
            rows.append((_cell(f.name), _place(f.locator), _cell(label), fmt_err(e), f"{lost:.1f}",
                         "**yes**" if e > CATASTROPHIC else "no",
                         ", ".join(written(v) for v in p) if p else "",
                         _cell(f.stable_text) if f.stable_text else "—", fmt_err(st[0]) if st else "—"))
    lines += [_table(("form", "where", "sweep", "worst rel. error (printed)", "digits lost", "catastrophic",
                      "worst at", "stable form", "worst rel. error (stable)"), rows), ""]
    progress("stiff cases: scanning every closed form in the density")
    found = scan(selector)
    flagged = [r for r in found if r.worst > CATASTROPHIC]
    lines += ["### Every closed form in the density, found in the derivations", "",
              f"All {len(found)} distinct closed forms in the density ($s$, $\\varrho$) among the valid readings "
              "of the derivations (with derived quantities inserted, as the library stores them: SymPy distributes "
              r"rational factors, so $b(1 - s)/2$ is held as $b/2 - bs/2$), evaluated with the density $10^{-15} \ldots "
              r"10^{-1}$ "
              "from 0 and from 1 and the other parameters at the middle of their sampling intervals. "
              f"{len(found) - len(flagged)} lose at most 6 digits; the {len(flagged)} below lose more, and the first "
              "of SymPy's factor, cancel, together, expand that stays within the stable tolerance is given.", "",
              _table(("derivation", "formula", "form as stored", "worst rel. error", "at density", "stable rewrite",
                      "its worst rel. error"),
                     [(_cell(_derivation(r.derivation)), _formula(f"{r.derivation}/{r.formula}"),
                       _cell(f"${latex(r.expr)}$"), fmt_err(r.worst), written(r.at),
                       r.rewrite and _cell(f"{_REWRITES[r.rewrite]}: ${latex(getattr(sp, r.rewrite)(r.expr))}$")
                       or "none found",
                       fmt_err(r.rewrite_worst) if r.rewrite else "—") for r in flagged]), ""]
    return lines


def generate(docs=Path("docs"), *, quick=False, progress=lambda msg: None) -> list[Path]:
    """Run the benchmark and write ``docs/numerics.md`` and its figures; return the files written
    (timings alone never cause a write).  ``quick`` benchmarks only :func:`quick_selection` with fewer
    methods."""
    docs = Path(docs)
    quick_ids, quick_scan = quick_selection() if quick else ((None,), None)
    selectors = quick_ids
    bench = Bench()
    for sel in selectors:
        part = run_bench(sel, quick=quick, progress=progress)
        seen = {(m.derivation, m.witness) for m in bench.measurements}
        bench.measurements += [m for m in part.measurements if (m.derivation, m.witness) not in seen]
        bench.references.update(part.references)
        bench.witnesses.update(part.witnesses)
        bench.unenclosed.update(part.unenclosed)
    figures = {}
    lines = ["# Numerics of the witnesses", "",
             "Generated by `symfloat bench`" + (" --quick" if quick else "") + ". How fast each "
             "method reaches a given accuracy on the witnesses of the library; whether the rules converge at "
             "their theoretical orders (and what a kink does); which closed forms lose digits in float64 at "
             "the ends of their ranges; how the solver's error grows next to bifurcation densities and whether "
             "its reported bound holds; and the stiff discriminant forms of Scheeffer IX.", ""]
    lines += _section_bench(bench, figures)
    lines += _section_orders(selectors[0] if quick else None, figures, progress, quick)
    lines += _section_forms(quick_scan, progress)
    progress("the solver near bifurcation densities")
    lines += [conditioning_markdown(conditioning_rows(CASES[:1], (1e-4, 1e-8)) if quick else conditioning_rows())]
    lines += ["## 5. The discriminant forms of Scheeffer IX", "",
              r"The double-root machinery (146)–(160) with $t = (128\sigma - 9)/27$, $\sigma = 1 - s$, evaluated as "
              r"printed in float64 against 50 digits, towards its singular points $s \to 23/32$ ($t \to 1$), "
              r"$s \to 1$ ($t \to -1/3$) and $s \to 119/128$ ($t \to 0$), beside stable forms of the same "
              "quantities.", "",
              discriminant_markdown()]
    written = []
    if write_if_changed(docs / "numerics.md", "\n".join(lines).rstrip() + "\n"):
        written.append(docs / "numerics.md")
    for name, (fig, fp) in figures.items():
        if write_png_if_changed(docs / "figures" / name, fig, fp):
            written.append(docs / "figures" / name)
    return written
