"""The words of an erratum read as mathematics (issue 30): its evidence, reason, objection and answer are
prose with TeX between dollars (symfloat/model/evidence_tex.py), the engine's part included, and the site
typesets every formula in them, so that no ASCII maths (``sin^2``, ``>=``, ``sqrt``, ``omega``, ``phi_1``,
``1.6 * 11/32``) is left in the words a reader sees."""
from __future__ import annotations

import re
from html.parser import HTMLParser
from pathlib import Path
from types import SimpleNamespace

import pytest

from symfloat import registry
from symfloat.engine.check import _erratum
from symfloat.engine.witness import Outcome
from symfloat.model.erratum import Erratum
from symfloat.model.symbol_names import GREEK
from symfloat.site import typeset
from symfloat.site.difference import reads_as_words
from symfloat.site.edition import reason_of
from symfloat.site.errata_pages import erratum_page
from symfloat.site.records import Records, load_records
from symfloat.site.text import dollars_html, prose_html

ROOT = Path(__file__).resolve().parents[1]

# ASCII maths in words: a power, a relation typed as two characters, a root, degrees, a Greek letter's name,
# an index, a product star between numbers or letters, an integral's name, the old tangent; and maths in Unicode
# letters (y⁴dy/√(bb-yy), AB·ce, π/4, a ≤ b): a sign of the integral, a root, a superscript or subscript digit, a
# centred dot, a relation, a minus sign, a Greek letter.
ASCII_MATHS = re.compile(r"\^|>=|<=|!=|\bsqrt|\bdeg\b|\b(?:%s)(?![a-z])|[A-Za-z]_\w|\w ?\* ?\w|\bint_|\btg\b"
                         r"|[∫∑∏√∂∞⁰¹²³⁴⁵⁶⁷⁸⁹₀₁₂₃₄₅₆₇₈₉·±×÷≤≥≠≈−]|[α-ωΑ-Ω]" % "|".join(GREEK))


class _Words(HTMLParser):
    """The text of an HTML fragment outside KaTeX's output (its formulas, typeset)."""

    def __init__(self):
        super().__init__()
        self.depth, self.words = 0, []

    def handle_starttag(self, tag, attrs):
        if self.depth or "katex" in (dict(attrs).get("class") or "").split():
            self.depth += 1

    def handle_endtag(self, tag):
        self.depth = max(self.depth - 1, 0) if self.depth else 0

    def handle_data(self, data):
        if not self.depth:
            self.words.append(data)


def ascii_maths(text: str) -> list[str]:
    """The ASCII maths in the words of *text* as the site renders its dollars (typeset by KaTeX), before the site
    sets what ASCII maths is left (``prose_html``): an erratum's words are written in TeX."""
    rendered = dollars_html(text)
    parser = _Words()
    parser.feed(rendered)
    return [m.group(0) for m in ASCII_MATHS.finditer("".join(parser.words))] + \
        (["a formula KaTeX could not typeset"] if "tex-unrendered" in rendered else [])


@pytest.fixture(autouse=True)
def _katex():
    try:
        typeset.katex_dist()
    except typeset.TypesetterMissing as exc:
        pytest.skip(str(exc))


def test_the_check_sees_ascii_maths_and_passes_typeset_maths():
    # mutations: each ASCII form is caught; the same maths between dollars is not
    for ascii_text in ("at omega = 0", "sin^2 45 deg = 1/2", "(2s-1)(4s-3) >= 0", "tg phi_1 = sqrt(11/32)",
                       "r tg = 1.6 * 11/32", "s <= 1/4", "∫y⁴dy/√(bb-yy)", "area AB·ce", "π/4", "s ≤ 1/4"):
        assert ascii_maths(ascii_text), ascii_text
    assert ascii_maths(r"at $\omega = 0$ ($\sin^2 45^\circ = \tfrac12$), so $(2s-1)(4s-3) \ge 0$: only "
                       r"$s \ge \tfrac34$; $\operatorname{tg}\varphi_1 = \sqrt{11/32}$, $1.6 \cdot 11/32$") == []
    assert ascii_maths(r"a stray environment: $\frac{a}{b} \end{cases}$") == ["a formula KaTeX could not typeset"]
    # what an author left in ASCII the site still sets as a formula (Graefe §2's "factor 2m instead of 2m/3")
    assert 'class="katex' in prose_html("factor 2m instead of 2m/3") and "2m/3" in dollars_html("2m/3")


def test_the_engine_writes_the_point_under_typeset_names_and_its_numbers_as_numbers():
    p = SimpleNamespace(erratum=Erratum("misprint", "high", "x", r"The print swaps the cases at $s = \tfrac12$."),
                        unreadable="")
    ident = SimpleNamespace(counterexample={"point": {"a": "119/94", "varphi_2": "71/530"},
                                            "lhs": "-235659137/1993622500", "rhs": "0.000034332035055300038590"})
    corr = SimpleNamespace(holds=True, status="proved", strategy="cancel")
    witnesses = [Outcome("oblique-78c", [{"method": "mpmath, 40 digits", "rel_error": 2.9e-39}]),
                 Outcome("definition route", [{"method": "definitions, 15 digits", "rel_error": 0.0}])]
    evidence = _erratum(p, ident, corr, witnesses)["evidence"]
    # the point, the two sides and the errors as TeX; no slug of a witness, no strategy's program name
    assert (r"Engine: at $a = \tfrac{119}{94},\ \varphi_{2} = \tfrac{71}{530}$ the print gives "
            r"$3.433203506 \times 10^{-5}$ where the derivation gives $-\tfrac{235659137}{1993622500}$") in evidence
    assert r"a first-principles witness agrees with the correction to $2.9 \times 10^{-39}$ (mpmath" in evidence
    assert "the definition route agrees with the correction to $0$" in evidence
    assert "oblique-78c" not in evidence and "(cancel)" not in evidence and ascii_maths(evidence) == []


@pytest.mark.parametrize("derivation", registry.ids())
def test_every_erratum_reads_as_mathematics(derivation):
    left = {}
    for p in registry.statements(derivation).printed:
        e = p.erratum
        if e is None:
            continue
        # a correction in words (as the site shows it: with dollars, or sentences without commands) reads the same way
        for field, text in (("evidence", e.evidence), ("reason", reason_of({"evidence": e.evidence})),
                            ("objection", e.objection), ("answer", e.answer), ("as printed", p.unreadable),
                            ("correction", e.corrected if reads_as_words(e.corrected) else "")):
            found = ascii_maths(text)
            if found:
                left[f"{p.name} ({field})"] = found
    assert left == {}


@pytest.mark.parametrize("derivation", registry.ids())
def test_every_erratums_words_end_their_sentence(derivation):
    # the engine appends its own sentences ("Engine: at ...") to the evidence: an evidence without its full stop
    # ran into them (Scheeffer's Example 10: "... = 0.938$ Engine: at ...")
    unended = [f"{p.name} ({field})" for p in registry.statements(derivation).printed if p.erratum is not None
               for field in ("evidence", "objection", "answer")
               if (text := (getattr(p.erratum, field) or "").rstrip()) and not text.endswith((".", "?", "!", ".)"))]
    assert unended == []


def test_an_erratum_page_typesets_its_words_and_shows_the_objection():
    # a stand-in erratum of (81a) in the records' shape (docs/errata.json): evidence with TeX, an objection, its answer
    real = load_records(ROOT / "docs", ROOT / "notebooks")
    e = dict(next(e for e in real.errata if e["formula"] == "scheeffer-vi-cf/81a"),
             evidence=r"At $\omega = 0$ ($\sin^2 45^\circ = \tfrac12$) the print fails.",
             objection=r"The letter $b$ may be the height.", answer=r"Then $\tan^2\varphi_1$ would depend on a length.")
    records = Records(real.formulas, real.summary, [e], real.notebooks, cells=real.cells)
    page = erratum_page(e, records)
    evidence = page[page.index('<p class="evidence">'):page.index("</p>", page.index('<p class="evidence">'))]
    assert evidence.count('<span class="katex">') == 2 and r"\omega" not in evidence.split("<annotation")[0]
    assert "<h2>The strongest objection</h2>" in page and "The letter" in page and "<strong>Answer.</strong>" in page
    assert "$" not in re.sub(r'<annotation encoding="application/x-tex">.*?</annotation>', "", page)
