"""The derivation notebooks show a derivation step by step, in the derivation's names,
with stable cell ids and no timings (built, not executed, here: fast)."""
import re

import pytest
import sympy as sp

from symfloat.registry import load
from symfloat.report.notebook_view import NotebookView, correction_markdown, named
from symfloat.report.notebooks import build_notebook, cell_id

S1 = "graefe-s1-prismatoid-volume"


@pytest.fixture(scope="module")
def s1_notebook():
    return build_notebook(S1)


def test_every_step_is_a_heading_with_its_chain_and_a_check_cell(s1_notebook):
    d, _ = load(S1)
    by_id = {c.id: c for c in s1_notebook.cells}
    for i, s in enumerate(d.steps, 1):
        md = by_id[cell_id("step", s.name)]
        assert md.cell_type == "markdown" and md.source.startswith(f"### Step {i}: {s.name}")
        assert "$$" in md.source                                  # the expressions before and after
        code = by_id[cell_id("step-check", s.name)]
        assert code.source == f"view.step({s.name!r})"
    for p in d.printed:
        assert by_id[cell_id("formula", p.name)].source.startswith(f"### {p.locator}: `{p.name}`")


def test_cell_ids_follow_content_not_position(s1_notebook):
    ids = [c.id for c in s1_notebook.cells]
    assert len(ids) == len(set(ids))
    assert all(re.fullmatch(r"[A-Za-z0-9_-]{1,64}", i) for i in ids)
    assert [c.id for c in build_notebook(S1).cells] == ids           # rebuilt: identical
    assert cell_id("step", "lemma") != cell_id("step", "lemma-2")


def test_long_expressions_read_in_their_names(s1_notebook):
    by_id = {c.id: c for c in s1_notebook.cells}
    volume = by_id[cell_id("step", "volume-ABCD")].source
    # the triple product is named, not written out in coordinates (Graefe §1, step volume-ABCD)
    assert r"|[\vec{AB},\vec{AC},\vec{AD}]|" in volume and "x_{A}" not in volume
    names = by_id[cell_id("names")].source
    assert names.count(r"|[\vec{AB},\vec{AC},\vec{AD}]| =") == 1        # defined once, in coordinates
    parallelogram = by_id[cell_id("step", "mid-section-is-parallelogram")].source
    assert r"\vec{ab} = \vec{dc} = \tfrac{1}{2}\vec{AB}" in parallelogram


def test_printed_arithmetic_is_shown_as_printed(s1_notebook):
    by_id = {c.id: c for c in s1_notebook.cells}
    # Graefe §1: "= g/4" because the mid-section is g scaled by (1/2)^2 (step mid-sections)
    assert r"g \left(\frac{1}{2}\right)^{2} = \frac{g}{4}" in by_id[cell_id("step", "mid-sections")].source


def test_named_leaves_unnamed_expressions_alone():
    d, _ = load(S1)
    x = sp.Symbol("x")
    assert named(d.names, x ** 2 + 1) == x ** 2 + 1
    assert named([], sp.Matrix([x])) == sp.Matrix([x])


def test_a_claim_in_words_is_prose():
    assert correction_markdown("claim", "e > 0 in the stable case") == "e > 0 in the stable case"
    assert correction_markdown("misprint", r"\frac{g}{4}") == r"$$ \frac{g}{4} $$"
    # a claim's correction written in LaTeX (metazentrum, the displaced volume) is shown as mathematics
    assert correction_markdown("claim", r"V_b \leq V_s") == r"$$ V_b \leq V_s $$"


def test_view_shows_justification_and_witnesses_without_timings(graefe_reports):
    report = next(r for r in graefe_reports if r.id == S1)
    _, module = load(S1)
    view = NotebookView(module, report)
    assert view.failures == []
    text = view.step_markdown("mid-sections")
    assert text.startswith("Justification: ") and "identical as built" not in text
    text = view.step_markdown("pyramid-over-g")
    assert "definition" in text and "| method | cases | abs. error | rel. error |" in text
    summary = view.summary_markdown()
    assert "0 trivial" in summary
    shown = "\n".join(view.formula_markdown(p.name) for p in module.DERIVATION.printed) + text + summary
    assert not re.search(r"\b[0-9]+(\.[0-9]+)? (ms|s)\b|seconds|\btime\b", shown)


def test_a_failing_cell_is_one_line_and_a_failed_check(monkeypatch, tmp_path):
    # a notebook whose cell raises must stop the main job with exit status 1 and one line naming the
    # derivation and the error, not a kernel traceback
    import nbformat
    from symfloat.errors import CheckFailed, EXIT_CHECK
    from symfloat.report import notebooks
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("1 / 0")])
    monkeypatch.setattr(notebooks, "build_notebook", lambda did, folder=None: nb)
    monkeypatch.chdir(tmp_path)
    with pytest.raises(CheckFailed) as caught:
        notebooks._executed_text("graefe-s1-prismatoid-volume", "stamp", tmp_path)
    assert str(caught.value) == ("notebook graefe-s1-prismatoid-volume: a cell failed with ZeroDivisionError: "
                                 "division by zero") and caught.value.exit_code == EXIT_CHECK
