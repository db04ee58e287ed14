"""``symfloat site``: the pages it makes from the committed records, their links, their mathematics,
their determinism, and what a real browser (headless Chromium driven by Playwright) sees.

Expected values come from the committed records: docs/verification.json (verdicts, excerpts),
docs/errata.json, the notebooks, and the transcriptions in symfloat/sources.
"""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from collections import Counter
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest
from PIL import Image

pytest.importorskip("sphinx", reason="the site extra is not installed (pip install 'symfloat[site]')")
pytest.importorskip("myst_nb", reason="the site extra is not installed (pip install 'symfloat[site]')")

from symfloat.model.source import SOURCES  # noqa: E402
from symfloat.model.symbol_names import GREEK  # noqa: E402
from symfloat.model.span import math_intervals  # noqa: E402
from symfloat.site import search, typeset  # noqa: E402
from symfloat.numbers import duration  # noqa: E402
from symfloat.site.build import MARKER, _sync  # noqa: E402
from symfloat.site.edition import (edition_page, fault_words, formula_anchor, mark_of, places,  # noqa: E402
                                   reason_of, replaced)
from symfloat.site.errata_pages import errata_index, erratum_title, facet_pages  # noqa: E402
from symfloat.site.difference import corrected_html, highlighted  # noqa: E402
from symfloat.site.notebooks import staged_notebook  # noqa: E402
from symfloat.site.records import load_records, slug  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
DOCS, NOTEBOOKS = ROOT / "docs", ROOT / "notebooks"


@pytest.fixture(scope="module")
def records():
    return load_records(DOCS, NOTEBOOKS)


@pytest.fixture(scope="module")
def edition(records):
    """The edition page of a source (by key), made once for this module's tests: the page depends on the
    records alone, and Scheeffer's takes seconds."""
    made = {}

    def page(key: str) -> str:
        if key not in made:
            made[key] = edition_page(SOURCES[key], records)
        return made[key]
    return page


# ---------------------------------------------------------------- pages, without Sphinx

_KATEX = '<span class="katex'


def _need_katex():
    try:
        typeset.katex_dist()
    except typeset.TypesetterMissing as exc:
        pytest.skip(str(exc))


def test_every_formula_of_the_transcriptions_is_typeset():
    _need_katex()
    typeset.UNRENDERED.clear()
    count = 0
    for source in SOURCES.values():
        text = source.text()
        for a, b, kind in math_intervals(text):
            assert typeset.typeset(text[a:b].strip("$"), kind == "display").startswith(_KATEX), text[a:b]
            count += 1
    assert count > 2000 and not typeset.UNRENDERED


def test_faulty_tex_is_repaired_or_shown_marked():
    _need_katex()
    # Scheeffer's y''^2 and a formula the scan cut off (an open \left, environment and root)
    assert typeset.typeset("y''^2 = r^2").startswith(_KATEX)
    assert typeset.typeset(r"\left. \begin{aligned} & \sqrt{x").startswith(_KATEX)
    shown = typeset.typeset(r"\frac{a}{b} \end{cases}")
    assert shown.startswith('<code class="tex-unrendered"') and r"\frac{a}{b}" in shown


def test_an_aligned_display_is_set_in_rows():
    _need_katex()
    # Scheeffer (5): two rows aligned at "=", no ampersand left as text
    html = typeset.typeset(r"\begin{aligned} m &= v \cos \varphi - u \sin \varphi \\ n &= v \sin \varphi + u \cos "
                           r"\varphi \end{aligned} \quad (5)", display=True)
    shown = re.sub(r"<annotation.*?</annotation>", "", html)
    assert shown.count('class="vlist-r"') >= 1 and "&amp;" not in shown and "<mtable" in shown
    assert html.count("<mtr>") == 2


def test_the_edition_marks_every_quoted_formula_by_its_verdict(records, edition):
    page = edition("scheeffer")
    formulas = [f for f in records.formulas if f["source"] == "scheeffer"]
    assert len(formulas) > 400
    ids = set(re.findall(r'id="([^"]*)"', page))                              # the page read once, not per formula
    marks = set(re.findall(r'<a class="(?:q|more) v-(\w+)" href="#([^"]*)"', page))
    for f in formulas:
        anchor = formula_anchor(f["id"])
        assert anchor in ids, f["id"]
        assert (mark_of(f, records), anchor) in marks, f["id"]
    # (78c) is a misprint of the original (the record's erratum), Scheeffer's square moments (VI.C) are verified
    assert f'<a class="q v-fault" href="#{formula_anchor("scheeffer-vi-cf/78c")}"' in page
    assert f'<a class="q v-verified" href="#{formula_anchor("scheeffer-vi-cf/square-moments")}"' in page
    note = page[page.index(f'id="{formula_anchor("scheeffer-vi-cf/78c")}"'):]
    note = note[:note.index("</details>")]
    witness = next(f for f in records.formulas if f["id"] == "scheeffer-vi-cf/78c")["numeric"][0]
    assert "misprint, medium confidence" in note and "6.0 × 10⁻¹" in note     # the record's error of the print
    assert duration(witness["seconds"]) in note                # and the witness's time, as recorded (74 ms)
    assert '../errata/scheeffer-78c-1.html' in note and "../notebooks/scheeffer-vi-cf.html#" in note
    assert "\\frac" not in re.sub(r'<annotation.*?</annotation>|title="[^"]*"', "", page, flags=re.S)


def test_the_two_apparatus_are_marked_apart(records, edition):
    # docs/errata.json: (81a) is the scan's "b" for "6" (transcription), (78c) a misprint of the print
    page = edition("scheeffer")
    scan, printer = formula_anchor("scheeffer-vi-cf/81a"), formula_anchor("scheeffer-vi-cf/78c")
    assert f'<a class="q v-transcription" href="#{scan}"' in page and f'<a class="q v-fault" href="#{printer}"' in page
    legend = page[page.index('<p class="legend">'):]
    legend = legend[:legend.index("</p>")]
    faults = sum(mark_of(f, records) == "fault" for f in records.formulas if f["source"] == "scheeffer")
    scans = sum(mark_of(f, records) == "transcription" for f in records.formulas if f["source"] == "scheeffer")
    assert f"✗ fault of the original</span> {faults}" in legend and f"✎ transcription corrected</span> {scans}" in legend
    words = re.sub(r"<[^>]+>", "", legend)                                   # the legend's visible text
    assert faults and scans and "waived" not in words and "bare-symbol" not in words and "a lone symbol" in words
    index = errata_index(records)
    original = index.index("## Faults of the original")
    transcription = index.index("## Corrections of the transcription")
    # the entries' links (an erratum's words may cite (81a): Scheeffer VI.D's 'Gleichung 81' for (81a))
    assert index.index("[Scheeffer, (81a)]", transcription) > transcription
    assert original < index.index("[Scheeffer, (78c)]") < transcription
    assert "[Scheeffer, (81a)]" not in index[original:transcription]


def test_the_errata_lists_name_sources_as_a_reader_cites_them(records):
    # symfloat/sources/*.source.json: Scheeffer 1902, Graefe 1866, Euler 1749; the lesson and the long prism are
    # anonymous, named by their titles
    index, facets = errata_index(records), facet_pages(records)
    by_source = next(line for line in index.splitlines() if line.startswith("- source: "))
    assert "[Scheeffer 1902](source-scheeffer.md)" in by_source and "[Hasáb úszása](source-hasab.md)" in by_source
    assert "[scheeffer]" not in by_source and "Anonymous" not in index
    assert facets["source-euler.md"].startswith("# Errata: Euler 1749\n")
    assert "- [Auftrieb Stabilität, " in facets["source-metazentrum.md"]


def test_the_correction_is_shown_in_place(edition):
    page = edition("scheeffer")
    at = page.index(f'id="{formula_anchor("scheeffer-vi-cf/81a")}"')
    note = page[at:page.index("</details>\n</details>", at)]
    evidence = note.index('<details class="evidence">')
    # before the evidence: what the transcription reads and what the original very probably printed, the
    # change (the 6 the scan read as b) marked, kind, confidence and a one-sentence reason
    head = note[:evidence]
    assert head.index("The transcription reads") < head.index("The original very probably printed")
    assert re.search(r'<span class="enclosing changed">.*?6', head) and "transcription, high confidence." in head
    reason = head[head.index('<p class="reason">'):]
    reason = reason[reason.index("</strong>"):reason.index("</p>")]
    shown = re.sub(r"<[^>]+>", "", re.sub(r'<span class="katex-mathml">.*?</math></span>', "", reason, flags=re.S))
    assert shown.count(". ") == 0 and len(shown) < 400                      # one sentence, as the reader sees it
    assert "sampled" not in head and "witness" not in head                  # the evidence waits behind its summary
    assert "<table" in note[evidence:]
    misprint = page[page.index(f'id="{formula_anchor("scheeffer-vi-cf/78c")}"'):]
    assert misprint.index("Printed</span>") < misprint.index("Corrected</span>") < misprint.index('class="evidence"')


def test_the_home_page_counts_the_formulas_in_a_sentence(records):
    # it read "82 fault of the original, 109 transcription corrected" (the marks' labels as counted nouns) and named
    # the command and the record files that built it
    from symfloat.site.build import _index
    page = _index(records, False, [])
    line = next(x for x in page.splitlines() if x.endswith(".") and "printed formulas:" in x)
    marks = Counter(mark_of(f, records) for f in records.formulas)
    assert line.startswith(f"{len(records.formulas)} printed formulas: {marks['verified']} verified, "
                           f"{marks['fault']} with a fault of the original, "
                           f"{marks['transcription']} with a correction of the transcription, ")
    assert "symfloat site" not in page and "docs/" not in page


def test_places_have_anchors_and_the_sources_a_citation(edition):
    euler, scheeffer = edition("euler"), edition("scheeffer")
    assert 'id="s-224"' in euler and 'href="#s-224"' in euler                # Euler's paragraph §224
    assert "Eneström E110" in euler and "Petropoli" in euler and "1749" in euler
    for anchor in ("eq-78c", "eq-81a", "eq-5", "s-ix", "s-viii", "example-1"):     # (78c), (81 a), (5), IX, VIII, Ex. 1
        assert f'id="{anchor}"' in scheeffer and f'href="#{anchor}"' in scheeffer, anchor
    assert scheeffer.count('id="eq-78c"') == 1 and "Sections (10)" in scheeffer
    hasab, web = edition("hasab"), edition("metazentrum")
    # a text without numbered places has no contents, and no empty box where they would be
    assert '<nav class="contents"' in scheeffer and '<nav class="contents"' not in hasab + web
    assert "n.d.." not in hasab + web and "n.d. " in web          # a record without a year: one full stop
    assert "1987-04-183-1.eps" not in hasab.split('<div class="edition">')[1]     # a file name, not the text's words
    assert "ID:(1610, 0)" not in web and "(web lesson)" not in web
    # nor the element numbers the web page sets after a symbol ("die Höhe des Metazentrums ($z_M$)8671")
    assert not re.search(r"\)(8671|8670|8674)\b", re.sub(r"<[^>]*>", "", web))


def test_a_fault_printed_at_several_places_is_marked_at_each(records, edition):
    # metazentrum half-length: 'der Mittlere Länge des Parallelepipeds' stands at eight places of the lesson
    # (symfloat/sources/003_02a33f8f897eb570.txt, lines 155, 168, 243, 540, 578, 616, 677, 683;
    # tests/test_repeated_faults.py), one erratum with its places; the place of line 243 lies inside the quote of
    # another erratum (shift-depends-on, the sentence that makes the shift depend on a), whose mark covers it
    page = edition("metazentrum")
    fid = "metazentrum/half-length"
    anchor = formula_anchor(fid)
    assert fault_words(records.formula(fid), records) == "der Mittlere Länge des Parallelepipeds"
    # a marked stretch may run through several links (cut where other marks begin); its sign ends the last one
    first = re.findall(rf'<a class="q v-fault" href="#{anchor}"[^>]*>(?:(?!</a>).)*?'
                       r'<span class="visually-hidden"> \(fault of the original\)</span></a>', page, flags=re.S)
    again = re.findall(rf'<a class="q again v-fault" href="#{anchor}" title="The same fault printed here too[^"]*">'
                       r'((?:(?!</a>).)*?)</a>', page, flags=re.S)
    shown = re.sub(r"<[^>]+>", "", "".join(again))
    assert len(first) == 1 and shown.count("(fault of the original, printed here too)") == 6
    assert f'href="#{formula_anchor("metazentrum/shift-depends-on")}"' in page
    assert shown.count("Parallelepipeds") == 6
    assert page.count(f'id="{anchor}"') == 1                                 # the one note of the one erratum
    # a fault printed once has no other place; a place inside its quote is not marked again
    assert fault_words(records.formula("scheeffer-vi-cf/78c"), records) == ""
    assert places("ab x ab", "ab", (0, 2)) == [(5, 7)] and places("$a + b$ c", "b", (8, 9)) == [(0, 7)]
    # no words, no places: the empty pattern would match between every two characters of the page
    assert places("ab x ab", "", (0, 2)) == []


def _note(page: str, fid: str) -> str:
    note = page[page.index(f'id="{formula_anchor(fid)}"'):]
    return note[:note.index("</details>\n</details>")]


def test_a_reading_too_long_for_a_note_is_left_to_the_notebook(records, edition):
    # Scheeffer X's range of x (a dry-corner count at four points, 6,673 characters of TeX in the notebook) was set
    # in its note as 430 kB of KaTeX; the notebook shows it, and the note links there. A short reading is set.
    page = edition("scheeffer")
    assert len(records.cells["scheeffer-x/x-range"].reading) > 2000
    long, short = _note(page, "scheeffer-x/x-range"), _note(page, "scheeffer-vi-cf/square-moments")
    assert "a formula too long to set in a note; the derivation's notebook shows it" in long
    assert '<div class="reading">' not in long and len(long) < 20_000 and "the derivation step by step" in long
    assert '<div class="reading"><span class="katex-display">' in short


def test_lost_text_and_missing_figures_are_marked(edition):
    page = edition("graefe")
    # the lemma of Graefe §1 is lost in the transcription: its formula is unverifiable, with that reason
    anchor = formula_anchor("graefe-s1-prismatoid-volume/lemma-statement")
    assert re.search(rf'<a class="q v-unverifiable" href="#{anchor}" title="[^"]*text lost in the transcription',
                     page)
    assert '<span class="figure-missing"' in page


def test_the_reason_in_one_sentence_does_not_end_inside_a_quotation():
    # Scheeffer VI.D's third erratum read "... 'Ein Würfel schwimmt in aufrechter Lage stabil, wenn sein spec."
    quoted = "(81) is the law, 'wenn sein spec. Gewicht s > 0,7887 ist', its number alone. The tilt is (81a)."
    assert reason_of({"evidence": quoted}) == quoted.removesuffix(" The tilt is (81a).")
    minutes = "$\\varphi_1 = 30^\\circ\\, 22'\\, 59''$ is right. The printed $18^\\circ\\, 58'$ is not."
    assert reason_of({"evidence": minutes}) == "$\\varphi_1 = 30^\\circ\\, 22'\\, 59''$ is right."     # no quotation


def test_an_erratum_says_that_the_print_is_refuted_and_how_its_correction_holds(records):
    # 145 of 191 erratum pages said "The printed formula: proved symbolically" beside a witness that refutes it:
    # the record's evidence of an erratum is its correction's
    from symfloat.site.errata_pages import erratum_page
    fault = next(e for e in records.errata if e["id"] == "euler-s212-1")
    transcription = next(e for e in records.errata if e["id"] == "euler-s223-3")
    assert records.formula(fault["formula"])["evidence"] == "symbolic"
    assert "<p>The verdict: the print refuted, its correction proved symbolically." in erratum_page(fault, records)
    assert "<p>The verdict: the transcription refuted, its correction proved symbolically." in \
        erratum_page(transcription, records)
    assert not any("The printed formula: proved" in erratum_page(e, records) for e in records.errata[:40])


def test_every_erratum_page_has_a_title_of_its_own(records):
    # 134 of 191 pages shared their title with another ("Correction of the transcription: Euler, §223" three times)
    titles = [erratum_title(e, records) for e in records.errata]
    assert len(set(titles)) == len(titles) == len(records.errata)
    euler = [t for t in titles if t.startswith("Correction of the transcription: Euler, §223")]
    assert euler == [f"Correction of the transcription: Euler, §223 ({k} of 3)" for k in (1, 2, 3)]
    assert any(re.fullmatch(r"Fault of the original: [^()]+", t) for t in titles)      # one alone: no count


def test_corrections_are_formulas_or_words():
    assert "<math" in corrected_html(r"\operatorname{tg}^2 \varphi_1 = 2 \cdot \left\{ 6 s (1 - s) - 1 \right\}")
    words = corrected_html("e > 0 in the stable case, e < 0 in the unstable case")
    assert "<math" not in words and "stable case" in words
    mixed = corrected_html(r"wenn wir für  $a, b, c$  jetzt  $c, d, e$  setzen")
    assert mixed.count("<math") == 2 and "setzen" in mixed


def test_a_correction_marks_whole_words_and_the_changed_part_of_a_formula():
    # Scheeffer X's heading (scheeffer-x-6): one word changed in the scan; letter by letter the diff marked "leichg"
    heading = highlighted("Die Gewichtslagen eines schwimmenden Würfels.",
                          r"\text{Die Gleichgewichtslagen eines schwimmenden Würfels.}")
    assert heading == r"\text{Die \htmlClass{changed}{Gleichgewichtslagen} eines schwimmenden Würfels.}"
    # a sentence around a formula: its words whole, the formula's letters one by one (scheeffer-118-1)
    area = highlighted(r"wo das Zeichen  $\int$  auf die Fläche  $G H D = F$  auszudehnen ist.",
                       r"\text{auf die Fläche } A G H C D = F")
    assert area == r"\text{auf die Fläche } \htmlClass{changed}{A} G H \htmlClass{changed}{C} D = F"
    # a display between $$ is a formula (graefe-s2-simpson-s-rule-1): the new denominator is marked
    simpson = highlighted(r"$$I' = 2m \left\{ \frac{a+c}{2} + 2b \right\}.$$",
                          r"I' = \frac{2m}{3} \left\{ \frac{a+c}{2} + 2b \right\}")
    assert simpson == r"I' = \frac{2m}{\htmlClass{changed}{3}} \left\{ \frac{a+c}{2} + 2b \right\}"
    assert highlighted("Nach 55 ist ferner", r"\text{Nach 55 ist ferner}") == r"\text{Nach 55 ist ferner}"
    # a change that runs from one \text{} through a formula into the next is marked piece by piece (scheeffer-ix-b-3:
    # the correction's added clause was not marked at all, being no whole group)
    clause = highlighted(r"so ist  $F(z)$  positiv",
                         r"\text{so ist } F(z) \text{ positiv; hat } G = 0 \text{ eine Wurzel}")
    assert clause == (r"\text{so ist } F(z) \text{ positiv\htmlClass{changed}{; hat} } \htmlClass{changed}{G = 0} "
                      r"\text{ \htmlClass{changed}{eine Wurzel}}")


def test_a_correction_that_is_a_sentence_is_set_as_prose_and_wraps():
    # a correction in \text{} with formulas between its words (Scheeffer IX.B's clause, 60 characters and more)
    # was one line of KaTeX, cut off or set tiny on a phone; as prose with inline formulas it wraps
    sentence = corrected_html(r"\text{so ist } F(z) \text{ positiv, wenn } s > 1 \text{ ist}",
                              r"so ist  $F(z)$  negativ, wenn  $s > 1$  ist")
    assert sentence.startswith('<p class="math-words">so ist ') and sentence.count("<math") == 2
    assert '<span class="changed">positiv</span>' in sentence            # the change marked in the words
    # a formula with words in it stays a display: a case table, a formula with a word or two
    cases = corrected_html(r"x = \begin{cases} 1 & \text{für } s > 0 \\ 0 & \text{sonst} \end{cases}")
    assert cases.startswith('<div class="math-display">')
    assert corrected_html(r"\frac{a}{b} \text{ circa}").startswith('<div class="math-display">')


def test_a_correction_that_rewrites_its_fault_is_marked_against_the_fault(records):
    # Scheeffer (51): the correction rewrites "folglich das Gleichgewicht stabil" and reuses words from earlier in
    # the sentence; against the whole sentence "folglich" and "Gleichgewicht" were marked as new
    (erratum,) = [e for e in records.errata if e["formula"] == "scheeffer-iv-v/51-verdict"]
    assert replaced(erratum) == "folglich das Gleichgewicht stabil"
    marked = highlighted(replaced(erratum), erratum["corrected"])
    assert r"\text{folglich das Gleichgewicht \htmlClass{changed}{für jede andere Achse} stabil" in marked
    # a correction that does not keep its fault's words (graefe's title: "Prismaoid") is read against the print
    (title,) = [e for e in records.errata if e["formula"] == "graefe-s1-prismatoid-volume/prismatoid-name"]
    assert replaced(title) == title["printed"].strip()


def test_a_cut_quotation_in_a_notebook_is_widened_to_whole_formulas(records):
    # euler-220-228 quotes §224 from inside one formula into the middle of the next
    staged = json.loads(staged_notebook(NOTEBOOKS / "euler-220-228.ipynb", records, "euler-220-228",
                                        SOURCES["euler"].text()))
    cell = next("".join(c["source"]) for c in staged["cells"] if c.get("id", "").startswith("formula-Aa-Ace-product-"))
    assert cell.startswith("(euler-220-228--formula-Aa-Ace-product-")
    quoted = cell.split("</blockquote>")[0]                     # the quotation, before the reading's notes
    assert '<blockquote class="printed">' in quoted and "\n> " not in quoted
    assert cell.count("<math") >= 2


def test_sync_touches_only_what_changed(tmp_path):
    built, out = tmp_path / "built", tmp_path / "out"
    (built / "a").mkdir(parents=True)
    (built / "a" / "x.html").write_text("x")
    (built / "y.html").write_text("y")
    out.mkdir()
    (out / "stale.html").write_text("old")
    assert sorted(_sync(built, out)) == ["a/x.html", "stale.html", "y.html"]
    assert _sync(built, out) == []
    (built / "y.html").write_text("y2")
    assert _sync(built, out) == ["y.html"] and (out / "y.html").read_text() == "y2"


# ---------------------------------------------------------------- the built site

def _build(out: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "symfloat", "site", "--out", str(out)], cwd=ROOT,
                          capture_output=True, text=True, env={**os.environ, "SYMFLOAT_QUIET": "0"})


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    _need_katex()
    out = tmp_path_factory.mktemp("site") / "html"
    done = _build(out)
    assert done.returncode == 0, done.stderr
    assert "sphinx:" not in done.stderr, done.stderr          # Sphinx warned about nothing
    return out


# The names a formula must not spell in italic letters (t·a·n·v·a·r·p·h·i for tan φ): the lower-case Greek
# letters and the functions, longest first.  Read from the static HTML by _Page and in the browser by _BARE_NAMES.
_NAMES = sorted([g for g in GREEK if g[0].islower()] + ["sin", "cos", "tan", "cot", "tg", "log", "lim"],
                key=len, reverse=True)
_BARE = re.compile("|".join(_NAMES))
_LETTER = re.compile("[A-Za-z]")
_RUNS = ("math", "mrow", "mtd", "mstyle", "mpadded")     # the MathML elements whose children are read as runs


class _Page(HTMLParser):
    """Links, ids and the visible text of one page (scripts, styles and MathML left out; so is a notebook's
    code, ``<pre>``, where a function the derivation defines prints itself as TeX, e.g. Euler §§229-243's Beta
    integral ``r"\\int_0^{%s} ... \\frac{y^{%s}}{%s^{%s}}"``).

    Also what the browser's ``_BARE_NAMES`` finds, read from the MathML KaTeX wrote at build time (``bare``:
    a run of single-letter ``<mi>`` children of a ``<math>``, ``<mrow>``, ``<mtd>``, ``<mstyle>`` or ``<mpadded>``
    inside a ``katex-mathml`` span that spells a name, and a ``&`` in a ``katex-html`` span's text), and the
    measures by which the browser test chooses erratum pages: ``formulas``, ``widest_display`` (the characters
    of the widest display formula's MathML, its TeX annotation left out), ``widest_row`` (the visible characters
    of the longest table row) and ``longest_word`` (the longest run of prose or link text without a space)."""

    def __init__(self):
        super().__init__()
        self.links, self.ids, self.text, self._hidden = [], set(), [], 0
        self.bare, self.formulas, self.widest_display, self.widest_row, self._prose = [], 0, 0, 0, []
        self._spans = []        # the open <span>s: "katex-mathml", "katex-html" or ""
        self._shown = []        # the text of each open katex-html span
        self._math = []         # the open elements of a formula's MathML: [tag, run of letters, text]
        self._found, self._annotation, self._display, self._row = [], "", False, None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if a.get("id"):
            self.ids.add(a["id"])
        for key in ("href", "src"):
            if a.get(key) and not (tag == "math" or key == "href" and tag == "link" and a.get("rel") == "search"):
                self.links.append((tag, a[key]))
        if tag in ("script", "style", "math", "pre"):
            self._hidden += 1
        if self._math or tag == "math" and "katex-mathml" in self._spans:
            if not self._math:
                self.formulas += 1
                self._found, self._annotation, self._display = [], "", a.get("display") == "block"
            self._math.append([tag, "", ""])
        elif tag == "span":
            classes = (a.get("class") or "").split()
            kind = next((k for k in ("katex-mathml", "katex-html") if k in classes), "")
            self._spans.append(kind)
            if kind == "katex-html":
                self._shown.append([])
        elif tag == "tr":
            self._row = 0

    def handle_endtag(self, tag):
        if tag in ("script", "style", "math", "pre"):
            self._hidden -= 1
        if self._math:
            self._end_of_mathml(tag)
        elif tag == "span" and self._spans:
            if self._spans.pop() == "katex-html":
                shown = "".join(self._shown.pop())
                if "&" in shown:
                    self.bare.append(f"a visible & in {shown}")
        elif tag == "tr" and self._row is not None:
            self.widest_row, self._row = max(self.widest_row, self._row), None

    def _end_of_mathml(self, tag):
        """An element of a formula's MathML ends: a single letter <mi> lengthens its parent's run, any other
        child ends it, and so does the parent's own end (the browser's run over children and a final null)."""
        element, run, text = self._math.pop()
        if element in _RUNS:
            self._end_of_run(run)
        if self._math:
            parent = self._math[-1]
            parent[2] += text
            if parent[0] in _RUNS:
                if element == "mi" and _LETTER.fullmatch(text):
                    parent[1] += text
                else:
                    self._end_of_run(parent[1])
                    parent[1] = ""
        if element == "annotation":
            self._annotation = text
        if not self._math:          # the <math> ended
            self.bare += [f"{run} in {self._annotation or text}" for run in self._found]
            if self._display:
                self.widest_display = max(self.widest_display, len(text) - len(self._annotation))

    def _end_of_run(self, run):
        if _BARE.search(run):
            self._found.append(run)

    def handle_data(self, data):
        if self._math:
            self._math[-1][2] += data
        for shown in self._shown:
            shown.append(data)
        if not self._hidden:
            self.text.append(data)
            if self._row is not None:
                self._row += len(data)
            if not self._shown:
                self._prose.append(data)

    @property
    def longest_word(self) -> int:
        return max(map(len, "".join(self._prose).split()), default=0)


_KATEX_HTML = re.compile(r'<span class="katex-html" aria-hidden="true">')
_TAG = re.compile(r"<[^>]*>")


def _katex_html_as_text(html: str) -> str:
    """*html* with the markup of each of KaTeX's HTML renderings (a ``katex-html`` span's boxes and glyphs) taken
    out and its text kept: all :class:`_Page` reads of it.  That markup is most of a page's tags; the site's
    parse takes 8 s instead of 17 with it out, and reads the same."""
    out, pos = [], 0
    while match := _KATEX_HTML.search(html, pos):
        tag = search.closing_span(html, match.end())
        out += [html[pos:match.start()], '<span class="katex-html">', _TAG.sub("", html[match.end():tag.start()]),
                "</span>"]
        pos = tag.end()
    out.append(html[pos:])
    return "".join(out)


def _parsed(html: str) -> _Page:
    page = _Page()
    page.feed(_katex_html_as_text(html))
    return page


@pytest.fixture(scope="module")
def pages(site) -> dict[str, _Page]:
    """Every page of the built site, parsed once for the tests that read them (a notebook's or an edition's
    page runs to megabytes)."""
    return {path.relative_to(site).as_posix(): _parsed(path.read_text(encoding="utf-8"))
            for path in sorted(site.rglob("*.html"))}


def test_the_site_has_its_pages_and_every_internal_link_resolves(site, pages, records):
    for key in ("scheeffer", "graefe", "euler", "metazentrum", "hasab"):
        assert f"edition/{key}.html" in pages
    assert all(f"errata/{slug(e['id'])}.html" in pages for e in records.errata)
    assert all(f"notebooks/{d}.html" in pages for d in records.notebooks)
    for facet in ("source-scheeffer", "kind-misprint", "confidence-high"):
        assert f"errata/{facet}.html" in pages
    pictures = [link for tag, link in pages["figures.html"].links if tag == "img"]
    assert sorted(pictures) == ["_images/phase-cube.png", "_images/phase-square-log.png",
                                "_images/scheeffer-ix-grid.png"]
    # the notebooks of the cube and of IX link to their pictures
    assert any(link.startswith("../figures.html#picture-phase-cube") for _, link in pages["notebooks/scheeffer-vi-cf.html"].links)
    assert any(link.startswith("../figures.html#picture-scheeffer-ix-grid")
               for _, link in pages["notebooks/scheeffer-ix.html"].links)
    assert (site / MARKER).is_file() and not (site / ".buildinfo").exists()
    broken = []
    for name, page in pages.items():
        for tag, link in page.links:
            parts = urlsplit(link)
            if parts.scheme or link.startswith("//"):
                broken.append((name, link, "leaves the site"))        # nothing is loaded or linked outside
                continue
            target = (site / name).parent / unquote(parts.path) if parts.path else site / name
            target = target.resolve()
            if not target.is_file():
                broken.append((name, link, "no such file"))
            elif parts.fragment and target.suffix == ".html":
                ids = pages[target.relative_to(site.resolve()).as_posix()].ids
                if unquote(parts.fragment) not in ids:
                    broken.append((name, link, "no such anchor"))
    assert not broken, broken[:10]


_NAVIGATION = re.compile(r"<h3>Navigation</h3>(.*?)</ul>", re.S)
_CURRENT = re.compile(r'<li class="toctree-l1 current"><a class="[^"]*" href="([^"#]*)')


def test_the_sidebar_marks_the_branch_that_holds_each_page(site, pages):
    # symfloat.site.navigation resolves the sidebar's table once per folder and branch: every page's current
    # top-level entry is still its own folder's index, or the page itself where it is a top-level page
    unmarked = {"index.html", "genindex.html", "search.html"}
    for name in pages:
        listed = _NAVIGATION.search((site / name).read_text(encoding="utf-8")).group(1)
        current = _CURRENT.findall(listed)
        if name in unmarked:
            assert current == [], name
            continue
        assert len(current) == 1, (name, current)
        target = Path(os.path.normpath(Path(name).parent / (current[0] or Path(name).name))).as_posix()
        assert target == (f"{name.split('/')[0]}/index.html" if "/" in name else name), (name, target)
    assert len(pages) > 200


def test_no_tex_is_left_where_mathematics_should_be(pages):
    for name, page in pages.items():
        text = "".join(page.text)
        for raw in ("$$", "\\frac", "\\left", "\\begin{"):
            assert raw not in text, (name, raw, text[max(text.find(raw) - 80, 0):text.find(raw) + 80])


def _search_index(site: Path) -> dict:
    text = (site / "searchindex.js").read_text(encoding="utf-8")
    return json.loads(text[text.index("(") + 1:text.rindex(")")])


def test_the_search_index_holds_words_not_formulas(site):
    index = _search_index(site)
    terms = index["terms"]
    assert {"schwerpunkt", "metazentrum", "ellipsi"} <= set(terms)     # German, Latin and English words, stemmed
    # terms the index held before (KaTeX's glyphs, MathML's letters run together, TeX's commands); a notebook's
    # code is shown as code and stays searchable ("sum_of_cubes_ab")
    junk = {"nghnghngh", "dfu3v3tan", "y3y_3y3", "correctedwith", "readsco", "frac", "tfrac", "varphi", "mathrm"}
    assert not junk & set(terms), sorted(junk & set(terms))
    # the Scheeffer edition is found by a word of its transcription, which is in its raw HTML alone
    found = terms["gleichgewichtslag"]
    assert index["docnames"].index("edition/scheeffer") in (found if isinstance(found, list) else [found])


def test_a_formula_is_cut_out_of_the_words_and_nothing_else():
    page = ('<p>Die <span class="katex"><span class="katex-mathml"><math><mi>tan</mi></math></span>'
            '<span class="katex-html"><span class="mord">nghngh</span></span></span> Neigung <code>x</code>'
            '<code class="tex-unrendered" title="t">\\frac{a}{b</code> ist <span class="x">klein</span>.</p>')
    assert search.words_of(page) == "Die Neigung x ist klein ."
    with pytest.raises(ValueError, match="not closed"):
        search.words_of('<span class="katex"><span>')


def test_no_name_is_spelled_in_italic_letters(pages):
    # the browser's bare-name check (_BARE_NAMES) read from the static HTML of every page, shown to fail on its control
    bare = [(name, b) for name, page in pages.items() for b in page.bare]
    assert not bare, bare[:5]
    control = _parsed(_CONTROL)
    assert sorted(b.split(" ")[0] for b in control.bare) == ["a", "tau", "xtan"]
    assert "a visible & in x & y" in control.bare and "<span" not in _katex_html_as_text(_CONTROL).split("x ")[1]
    assert control.bare[0] == "xtan in xtan=tau" and control.formulas == 1


@pytest.mark.slow     # a second full build (about 25 s of CPU); the default run checks _sync's determinism above
def test_rebuilding_the_same_records_gives_the_same_files(site, tmp_path):
    again = tmp_path / "again"
    done = _build(again)
    assert done.returncode == 0, done.stderr
    first = {p.relative_to(site): p.read_bytes() for p in site.rglob("*") if p.is_file()}
    second = {p.relative_to(again): p.read_bytes() for p in again.rglob("*") if p.is_file()}
    assert first.keys() == second.keys()
    assert [name for name in first if first[name] != second[name]] == []


def test_without_katex_the_build_says_so_in_one_line(tmp_path):
    done = subprocess.run([sys.executable, "-m", "symfloat", "site", "--out", str(tmp_path / "out")], cwd=ROOT,
                          capture_output=True, text=True, env={**os.environ, "SYMFLOAT_NODE_MODULES": str(tmp_path)})
    assert done.returncode == 2 and done.stderr.count("\n") == 1 and "npm ci" in done.stderr, done.stderr
    assert not (tmp_path / "out").exists()


def test_a_folder_that_is_not_a_site_is_refused(tmp_path):
    (tmp_path / "notes.txt").write_text("mine")
    done = _build(tmp_path)
    assert done.returncode == 2 and done.stderr.count("\n") == 1 and MARKER in done.stderr
    assert (tmp_path / "notes.txt").read_text() == "mine"


# ---------------------------------------------------------------- in a real browser

def _browser(playwright):
    """Debian's chromium if installed (or SYMFLOAT_CHROMIUM), else Playwright's own; None if neither."""
    path = os.environ.get("SYMFLOAT_CHROMIUM") or shutil.which("chromium") or shutil.which("chromium-browser")
    try:
        return playwright.chromium.launch(**({"executable_path": path} if path else {}))
    except Exception:          # Playwright's browser not downloaded either
        return None


# The TeX that the browser shows as text on a page (none where MathML was made), outside a notebook's code
# (``<pre>``: a function the derivation defines may print itself as TeX there).  The text is read from the
# rendered text nodes (those innerText takes: not under display: none, visibility: hidden or a closed
# <details>), joined without separators, so nothing on the page changes and it is not laid out again.  A text
# that is a closed <details>'s own child lies in its hidden part, though the <details> (its summary) is seen.
_VISIBLE_TEX = r"""() => {
  const seen = [];
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    const parent = node.parentElement;
    if (parent.closest("pre") || parent.localName === "details" && !parent.open) continue;
    if (parent.checkVisibility({visibilityProperty: true})) seen.push(node.data);
  }
  const text = seen.join("");
  return ["$$", "\\frac"].filter(raw => text.includes(raw));
}"""


# Runs of single-letter identifiers in a formula's MathML (KaTeX's, beside the glyphs) that spell the name of a
# Greek letter or a function: a name set as italic letters (t·a·n·v·a·r·p·h·i) instead of its sign (tan φ).
# _Page reads the same from the static HTML of every page (test_no_name_is_spelled_in_italic_letters).
_BARE_NAMES = r"""names => {
  const bare = new RegExp("(" + names.join("|") + ")");
  const found = [];
  for (const math of document.querySelectorAll(".katex-mathml math")) {
    for (const parent of [math, ...math.querySelectorAll("mrow, mtd, mstyle, mpadded")]) {
      let run = "";
      for (const child of [...parent.children, null]) {
        if (child && child.tagName.toLowerCase() === "mi" && /^[A-Za-z]$/.test(child.textContent)) {
          run += child.textContent;
          continue;
        }
        if (bare.test(run)) found.push(run + " in " + (math.querySelector("annotation") || math).textContent);
        run = "";
      }
    }
  }
  for (const shown of document.querySelectorAll(".katex-html")) {
    if (shown.textContent.includes("&")) found.push("a visible & in " + shown.textContent);
  }
  return found;
}"""

# How far the page scrolls sideways at the viewport's width (it never should: a long formula scrolls in its box).
_OVERFLOW = "() => document.documentElement.scrollWidth - window.innerWidth"
# All three in one call: the visible TeX, the bare names (given the names) and the overflow.
_SEEN = f"names => ({{tex: ({_VISIBLE_TEX})(), bare: ({_BARE_NAMES})(names), overflow: ({_OVERFLOW})()}})"
_WIDTHS = (1400, 420)       # a desktop's and a phone's; a page's text is read at the first it is laid out at
# The pages photographed for the README at both widths (site-NAME.png, site-NAME-420.png), on the loop's visit
_SHOTS = {"index.html": "home", "edition/scheeffer.html": "edition-scheeffer",
          "errata/scheeffer-81a-1.html": "erratum", "notebooks/scheeffer-vi-cf.html": "notebook"}
_EDITION = "edition/scheeffer.html"
# A page that shows raw TeX, logs an error, spells names in italic letters (x·t·a·n, t·a·u) and a visible &, and
# scrolls sideways on a phone: the checks in the browser and the static one must find each.
_CONTROL = ("<p>$$\\frac{a}{b}$$</p><script>console.error('control')</script>"
            '<span class="katex"><span class="katex-mathml"><math><mrow><mi>x</mi><mi>t</mi><mi>a</mi>'
            '<mi>n</mi><mo>=</mo><mi>t</mi><mi>a</mi><mi>u</mi></mrow></math></span>'
            '<span class="katex-html" aria-hidden="true"><span class="base">x <span>&amp;</span> y</span></span></span>'
            '<div style="width: 600px">wide</div>')
_PICTURES = {"figures.html": 3, "scheeffer-ix-grid.html": 1}    # page -> the pictures of the derivations it shows


def _screenshot(page, folder: Path, name: str) -> None:
    """The viewport of *page* as ``site-NAME.png`` (``-420`` at the phone's width) in *folder*; with
    ``SYMFLOAT_SCREENSHOTS`` the README's copy, 256 colours, tens of KB."""
    width = page.viewport_size["width"]
    file = folder / f"site-{name}{'' if width == _WIDTHS[0] else f'-{width}'}.png"
    page.screenshot(path=str(file))
    assert file.stat().st_size > 20_000
    if os.environ.get("SYMFLOAT_SCREENSHOTS"):
        Image.open(file).convert("RGB").quantize(256, method=Image.Quantize.MEDIANCUT,
                                                 dither=Image.Dither.NONE).save(file, optimize=True)


def _edition_marks(page) -> None:
    """Every mark of the edition carries a sign and words besides its colour; KaTeX laid the formulas out
    (a fraction of (78c) has height)."""
    legend = page.inner_text("p.legend")
    assert all(f"{sign} {words}" in legend for sign, words in
               (("✗", "fault of the original"), ("✎", "transcription corrected"), ("✓", "verified")))
    badges = page.evaluate("Array.from(document.querySelectorAll('.badge')).map(b => b.textContent)")
    assert badges and all(re.fullmatch(r"\S \w.+", b) for b in badges), badges[:3]
    heights = page.evaluate("Array.from(document.querySelectorAll('.katex-html .mfrac')).slice(0, 50)"
                            ".map(e => e.getBoundingClientRect().height)")
    assert heights and max(heights) > 10, heights[:5]
    # Scheeffer IX.C's table of the third domain, a corrected transcription: its case tables reach far below the
    # line, so they are shaded whole and underlined at their foot, not crossed by the line's underline (symfloat.js)
    tall = page.evaluate("""id => Array.from(document.querySelectorAll(`a.q[href="#${id}"] .katex-html > .base.tall`))
                              .map(b => getComputedStyle(b).borderBottomStyle)""",
                         formula_anchor("scheeffer-ix/table-third"))
    assert len(tall) >= 2 and set(tall) == {"dashed"}, tall


# A display formula or a table shown (not in a closed note) that scrolls in its box without the shade that says so
_UNMARKED = """() => Array.from(document.querySelectorAll('.katex-display, .body table, table.witnesses'))
  .filter(b => !b.closest('details:not([open])') && b.scrollLeft + b.clientWidth < b.scrollWidth - 1
               && !b.classList.contains('scrolls')).length"""


def _displays_fit(page) -> None:
    """At the phone's width a display wider than its column is set smaller (symfloat.js): the display of (78c),
    wider than the column at its full size, is seen whole; one still too wide is shaded at its right edge,
    and the shade goes when it is scrolled to its end.  Waited for, not timed: the page fits its displays when
    it loads and after a change of width settles."""
    from playwright.sync_api import TimeoutError as Unsettled
    try:
        page.wait_for_function(f"() => ({_UNMARKED})() === 0", timeout=20000)
    except Unsettled:
        pass
    unmarked = page.evaluate(_UNMARKED)
    assert unmarked == 0, f"{unmarked} displays scroll in their box with no shade"
    mark = page.locator(f'a.q[href="#{formula_anchor("scheeffer-vi-cf/78c")}"] .katex-display').first
    whole, size = mark.evaluate("b => [b.scrollWidth <= b.clientWidth + 1, b.style.fontSize]")
    assert whole and size.endswith("px"), (whole, size)
    shaded = page.locator(".katex-display.scrolls")
    assert shaded.count() > 0
    first = shaded.first.element_handle()
    first.evaluate("b => { b.scrollLeft = b.scrollWidth; }")
    page.wait_for_function("b => !b.classList.contains('scrolls')", arg=first, timeout=5000)


def _in_chromium(site: Path, names: list[str], both: set[str] | None = None) -> None:
    """Open the pages *names* of the built site in headless Chromium and check each (no console error or failed
    load, no visible TeX, no bare name, no sideways overflow), take the README's screenshots and check the
    pictures, the edition's marks and search; then show that the checks fail on control pages.  The pages in
    *both* (``None``: every page) are laid out at both widths, their text read at the desktop's; the others at
    the phone's alone, where a page is narrowest (its column at 1400 px is wider than the whole phone), so an
    overflow at the desktop's width would show there too."""
    sync_api = pytest.importorskip("playwright.sync_api", reason="playwright is not installed (test extra)")
    with sync_api.sync_playwright() as p:
        browser = _browser(p)
        if browser is None:
            pytest.skip("no Chromium: install Debian's chromium or run 'python -m playwright install chromium'")
        page = browser.new_page(viewport={"width": 1400, "height": 900})
        errors = []
        page.on("console", lambda m: m.type == "error" and errors.append((page.url, m.text)))
        page.on("pageerror", lambda e: errors.append((page.url, str(e))))
        page.on("requestfailed", lambda r: errors.append((page.url, f"failed to load {r.url}")))
        # screenshots for the README at 1400 and 420 px, taken where the loop lays their pages out: the home
        # page, the Scheeffer edition with the note of (78c) opened from its mark, an erratum's page, a notebook
        folder = DOCS / "figures" if os.environ.get("SYMFLOAT_SCREENSHOTS") else site.parent
        note = f"#{formula_anchor('scheeffer-vi-cf/78c')}"
        assert {*_SHOTS, *_PICTURES} <= set(names)
        bare, wide = [], []
        for name in names:
            # laid out once at each of its widths, the first the width the page before ended with (a notebook's
            # page takes seconds to lay out, the edition's 15 MB more): every check and picture of a page is
            # taken on this one visit
            widths = _WIDTHS if both is None or name in both else _WIDTHS[1:]
            if page.viewport_size["width"] not in widths:
                page.set_viewport_size({"width": widths[0], "height": 900})
            page.goto((site / name).as_uri(), wait_until="load")
            for width in sorted(widths, key=lambda w: w != page.viewport_size["width"]):
                if page.viewport_size["width"] != width:
                    page.set_viewport_size({"width": width, "height": 900})
                if width == widths[0]:
                    seen = page.evaluate(_SEEN, _NAMES)
                    assert not seen["tex"], (name, seen["tex"])
                    bare += [(name, b) for b in seen["bare"]]
                    overflow = seen["overflow"]
                    if name == _EDITION:
                        _edition_marks(page)
                else:
                    overflow = page.evaluate(_OVERFLOW)
                if name == _EDITION and width == _WIDTHS[1]:
                    _displays_fit(page)
                if overflow > 0:
                    wide.append((name, width, overflow))
                if name in _SHOTS and name != _EDITION:
                    _screenshot(page, folder, _SHOTS[name])
            if name in _PICTURES:       # the pictures of the derivations load: the browser decoded each one
                widths = page.evaluate("Array.from(document.images).map(i => [i.getAttribute('src'), i.naturalWidth])")
                assert len(widths) == _PICTURES[name] and all(w > 0 for _, w in widths), (name, widths)
            if name == _EDITION:        # following a mark opens its note, shown at both widths
                page.locator(f'a.q[href="{note}"]').first.click()
                page.wait_for_function("id => document.getElementById(id).open", arg=note[1:], timeout=5000)
                for width in sorted(_WIDTHS, key=lambda w: w != page.viewport_size["width"]):
                    page.set_viewport_size({"width": width, "height": 900})
                    page.evaluate("id => document.getElementById(id).scrollIntoView()", note[1:])
                    page.evaluate("window.scrollBy(0, -160)")
                    page.wait_for_function(f"() => ({_UNMARKED})() === 0", timeout=20000)   # the note's fitted
                    _screenshot(page, folder, _SHOTS[name])
        assert not errors, errors[:5]
        assert not bare, bare[:5]
        assert not wide, wide[:10]
        # search from disk: hits listed, no error (Sphinx's summaries, which would fetch each page, are off)
        page.set_viewport_size({"width": _WIDTHS[0], "height": 900})
        page.goto((site / "search.html").as_uri() + "?q=Schwerpunkt")
        # Sphinx lists the hits one by one, 5 ms apart, and says so when it has listed them all: waited for, not timed
        page.wait_for_function("() => (document.querySelector('#search-results .search-summary') || {}).innerText"
                               "?.startsWith('Search finished')", timeout=20000)
        hits = page.locator("#search-results li").count()
        assert hits > 3 and f"found {hits} pages" in page.inner_text("#search-results .search-summary"), hits
        assert not errors, errors[:3]
        # the same checks see a page that shows raw TeX, logs an error and scrolls sideways on a phone
        control = site.parent / "control.html"
        control.write_text(_CONTROL, encoding="utf-8")
        page.goto(control.as_uri(), wait_until="load")
        seen = page.evaluate(_SEEN, _NAMES)
        assert seen["tex"] == ["$$", "\\frac"] and errors == [(control.as_uri(), "control")]
        assert [b.split(" ")[0] for b in seen["bare"]] == ["xtan", "tau", "a"] and seen["overflow"] <= 0
        page.set_viewport_size({"width": _WIDTHS[1], "height": 900})
        assert page.evaluate(_OVERFLOW) > 0
        page.set_viewport_size({"width": _WIDTHS[0], "height": 900})
        # and no TeX where the reader sees none: a notebook's code, hidden text, a closed note, MathML's annotation
        hidden = site.parent / "control-hidden.html"
        hidden.write_text("<pre>$$\\frac{a}{b}$$</pre><p style='display: none'>$$\\frac{a}{b}$$</p>"
                          "<p style='visibility: hidden'>$$\\frac{a}{b}$$</p>"
                          "<details><summary>note</summary>$$\\frac{a}{b}$$</details>"
                          '<math><semantics><mi>x</mi><annotation encoding="application/x-tex">\\frac{a}{b}'
                          "</annotation></semantics></math><p id='shown'>$$ and \\frac{a}{b}</p>", encoding="utf-8")
        page.goto(hidden.as_uri(), wait_until="load")
        assert page.evaluate(_VISIBLE_TEX) == ["$$", "\\frac"]            # the last paragraph's
        page.evaluate("document.getElementById('shown').remove()")
        assert page.evaluate(_VISIBLE_TEX) == []
        browser.close()


def _sample(pages: dict[str, _Page], made: list[str], top: int) -> set[str]:
    """The pages of one template (*made*: the errata's, the notebooks') most likely to show what the browser
    catches, chosen from the built HTML: the first and the last by name and the *top* by each measure (ties by
    name; pages that measure 0 are not ranked) of sideways overflow at 420 px (the widest display formula, the
    longest word or link, the widest table row) and of bare names and visible TeX (the most formulas)."""
    chosen = {min(made), max(made)}
    for measure in ("widest_display", "longest_word", "widest_row", "formulas"):
        ranked = sorted((-getattr(pages[name], measure), name) for name in made)
        chosen.update(name for size, name in ranked[:top] if size < 0)
    return chosen


def test_every_page_but_a_sample_of_errata_and_notebooks_in_headless_chromium(site, pages, records):
    # the pages of one erratum each, and of one notebook each, are made from one template apiece: a sample of each
    # is laid out (their bare names and TeX are read from the HTML of every page by the static tests above);
    # every other page is visited
    errata = sorted(f"errata/{slug(e['id'])}.html" for e in records.errata)
    notebooks = sorted(f"notebooks/{d}.html" for d in records.notebooks)
    # the top three errata (a page lays out in a tenth of a second), the top notebook by each measure (seconds)
    sample = _sample(pages, errata, 3) | _sample(pages, notebooks, 1) | {name for name in _SHOTS if name in pages}
    assert len(errata) > 100 and len(notebooks) > 15 and len(sample & set(errata)) < 20
    assert len(sample & set(notebooks)) <= 7 < len(notebooks)
    # at both widths the pages photographed at both; every other page at the phone's width alone
    _in_chromium(site, sorted(set(pages) - set(errata) - set(notebooks) | sample), both=set(_SHOTS))


@pytest.mark.slow     # every erratum and notebook page too, and every page at both widths (about 80 s more)
def test_every_page_in_headless_chromium(site, pages):
    _in_chromium(site, sorted(pages))
