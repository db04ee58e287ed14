"""The derivation notebooks show a derivation step by step, in the derivation's names, each step a
cell of plain SymPy that checks it, with stable cell ids and no timings (built here, and the small
Graefe §1 executed, once as derived and once with a step changed)."""
import copy
import dataclasses
import json
import re
import subprocess
import sys

import nbformat
import pytest
import sympy as sp
from nbclient.exceptions import CellExecutionError

from symfloat.engine.identity import Domain
from symfloat import registry
from symfloat.model.claim import members
from symfloat.registry import load
from symfloat.report.notebook_cells import CellWriter
from symfloat.report.notebook_code import Code, bound_names, definitions_source, small_point, strategy_helper
from symfloat.report.notebook_view import NotebookView, correction_markdown, named
from symfloat.report.notebooks import build_notebook, cell_id, execute_notebook

S1 = "graefe-s1-prismatoid-volume"
SLUG = re.compile(r"[a-z0-9]+(-[a-z0-9]+)+")


@pytest.fixture(scope="module")
def s1_report(graefe_reports):
    return next(r for r in graefe_reports if r.id == S1)


@pytest.fixture(scope="module")
def s1_notebook(s1_report):
    return build_notebook(S1, s1_report)


def test_every_step_is_a_heading_in_words_with_its_chain_and_a_sympy_cell(s1_notebook):
    d, _ = load(S1)
    by_id = {c.id: c for c in s1_notebook.cells}
    for i, s in enumerate(d.steps, 1):
        md = by_id[cell_id("step", s.name)]
        assert md.cell_type == "markdown" and md.source.startswith(f"### Step {i}: ")
        assert "$$" in md.source                                  # the expressions before and after
        code = by_id[cell_id("step-check", s.name)].source
        assert "view." not in code and "symfloat" not in code       # plain SymPy, no call into the library
        assert "chain = [" in code or code.startswith("derived[")
    for p in d.printed:
        assert by_id[cell_id("formula", p.name)].source.startswith(f"### {p.locator}")
    setup = by_id[cell_id("setup")].source
    assert setup.startswith("from sympy import (") and "symbols(" in setup and "def insert(expr):" in setup


def test_no_title_is_a_slug(s1_notebook):
    d, _ = load(S1)
    titles = [line.split(": ", 1)[1] for c in s1_notebook.cells if c.cell_type == "markdown"
              for line in c.source.splitlines() if line.startswith("### Step ")]
    assert len(titles) == len(d.steps)
    names = {s.name for s in d.steps} | {p.name for p in d.printed}
    assert not [t for t in titles if SLUG.fullmatch(t) or t in names]
    assert not [c.source for c in s1_notebook.cells if c.cell_type == "markdown" and "`" + "view" in c.source]


def test_the_site_finds_each_printed_formula_by_its_cell(s1_notebook):
    from symfloat.site.records import formula_cells
    d, _ = load(S1)
    cells = formula_cells(S1, json.loads(nbformat.writes(s1_notebook)))
    assert {f"{S1}/{p.name}" for p in d.printed} == set(cells)
    for p in d.printed:
        assert cells[f"{S1}/{p.name}"].cell == cell_id("formula", p.name)
        assert (cells[f"{S1}/{p.name}"].reading is not None) == (p.reading is not None)


def test_a_proved_step_calls_the_strategy_of_its_certificate(s1_notebook, s1_report):
    # Graefe §1, step mid-sections: g (1/2)^2 = g/4, its certificate's strategy applied to the difference
    by_id = {c.id: c for c in s1_notebook.cells}
    code = by_id[cell_id("step-check", "mid-sections")].source
    strategy = s1_report.proofs[f"step {S1}/mid-sections#0"]["strategy"]
    call = {"cancel": "cancel(together(", "expand": "expand(powsimp(expand(", "simplify": "simplify(",
            "radsimp": "cancel(radsimp(together(", "pythagoras": "pythagoras(", "branches": "branches("}[strategy]
    assert f"proof = {call}values[0] - values[1]" in code and "assert proof == 0" in code
    assert "g*(UnevaluatedExpr(Rational(1, 2)))**2" in code    # the print's arithmetic (1/2)^2 kept as printed


def test_a_notebook_defines_pythagoras_as_the_engine_runs_it():
    # the first cell of a notebook whose proofs replay pythagoras holds the engine's own source with the SymPy
    # names it uses; run alone with those names, it proves sin^2 + cos^2 = 1 and leaves sin 2x - sin x cos x
    source, names = strategy_helper("pythagoras")
    space = {name: getattr(sp, name) for name in names}
    exec(source, space)                                 # the project's own source, as the notebook holds it
    x = sp.Symbol("x")
    assert space["pythagoras"](sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1) == 0
    assert space["pythagoras"](sp.sin(2 * x) - sp.sin(x) * sp.cos(x)) != 0
    assert strategy_helper("cancel") == ("", set())


def test_a_notebook_defines_branches_as_the_engine_runs_it():
    # the same for the piecewise strategy: its source alone, with the SymPy names it uses, proves a claim by
    # cases and not one whose second case differs
    source, names = strategy_helper("branches")
    assert names == {"Piecewise", "cancel", "piecewise_fold", "together"}
    space = {name: getattr(sp, name) for name in names}
    exec(source, space)
    s = sp.Symbol("s")
    cases = sp.Piecewise((s * (1 - s), s > sp.Rational(1, 2)), (0, True))
    assert space["branches"](cases - sp.Piecewise((s - s**2, s > sp.Rational(1, 2)), (0, True))) == 0
    assert space["branches"](cases - sp.Piecewise((s - s**2, s > sp.Rational(1, 2)), (s, True))) != 0


def test_cell_ids_follow_content_not_position(s1_notebook, s1_report):
    ids = [c.id for c in s1_notebook.cells]
    assert len(ids) == len(set(ids))
    assert all(re.fullmatch(r"[A-Za-z0-9_-]{1,64}", i) for i in ids)
    rebuilt = build_notebook(S1, s1_report)                             # rebuilt: identical, code included
    assert [(c.id, c.source) for c in rebuilt.cells] == [(c.id, c.source) for c in s1_notebook.cells]
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
    d, module = load(S1)
    view = NotebookView(d, report)
    assert view.failures == []
    text = view.step_markdown("mid-sections")
    assert text.startswith("Justification: ") and "identical as built" not in text
    text = view.step_markdown("pyramid-over-g")
    assert "definition" in text and "| method | cases | abs. error | rel. error |" in text
    summary = view.summary_markdown()
    assert "0 trivial" in summary
    shown = "\n".join(view.formula_markdown(p.name) for p in module.DERIVATION.printed) + text + summary
    assert not re.search(r"\b[0-9]+(\.[0-9]+)? (ms|s)\b|seconds|\btime\b", shown)


def test_a_steps_witnesses_of_a_wrong_print_say_whose_errors_they_are(graefe_reports):
    # Graefe §2's slab a-c is derived by a step and printed with an erratum (its committed notebook's verdict):
    # the step's table measures the print (Scheeffer IX.A's T_1 showed a relative error of 0.5 under a step that
    # holds, unexplained); §1's pyramid over g is printed right
    s2 = "graefe-s2-volumes-simpson"
    wrong = NotebookView(load(s2)[0], next(r for r in graefe_reports if r.id == s2)).step_markdown("slab-a-c")
    assert "as printed, which has an erratum (the errors are the print's" in wrong and "| method |" in wrong
    right = NotebookView(load(S1)[0], next(r for r in graefe_reports if r.id == S1)).step_markdown("pyramid-over-g")
    assert "| method |" in right and "which has an erratum" not in right


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


def test_the_notebook_runs_and_a_changed_step_stops_it(s1_notebook, s1_report, tmp_path, monkeypatch):
    # as derived, every assertion of the notebook holds
    execute_notebook(copy.deepcopy(s1_notebook), tmp_path)
    # Graefe §1, step mid-sections says g (1/2)^2 = g/4; written g/3, the notebook must stop at that step
    d, _ = load(S1)
    i = next(i for i, s in enumerate(d.steps) if s.name == "mid-sections")
    step = d.steps[i]
    g = sp.Symbol("g", positive=True)
    wrong = tuple(m.xreplace({g / 4: g / 3}) if m == g / 4 else m for m in step.claim)
    assert wrong != tuple(step.claim)
    monkeypatch.setattr(d, "steps", d.steps[:i] + [dataclasses.replace(step, claim=wrong)] + d.steps[i + 1:])
    nb = build_notebook(S1, s1_report)
    with pytest.raises(CellExecutionError) as failed:
        execute_notebook(nb, tmp_path)
    assert failed.value.ename == "AssertionError"
    ran = [c for c in nb.cells if c.cell_type == "code" and c.get("outputs")]
    assert ran[-1].id == cell_id("step-check", "mid-sections")           # stopped at the changed step


def test_every_member_is_printed_as_sympy_that_reads_back(s1_report):
    d, _ = load(S1)
    writer = CellWriter(d, s1_report)
    for s in d.steps:
        for m in (s.claim if isinstance(s.claim, tuple) else (s.claim.lhs, s.claim.rhs)):
            text, evaluated = writer.code.member(m)
            with sp.evaluate(evaluated):
                back = eval(text, dict(writer.code.namespace))
            assert back == m or (isinstance(m, sp.MatrixBase) and list(back) == list(m))


def test_a_counterexample_is_a_small_point_inside_the_assumptions():
    x, y = sp.symbols("x y", positive=True)
    domain = Domain({x: (0, 3), y: (sp.Rational(1, 10), 1)}, (x > 2 * y,))
    # x^2 = 4 y^2 fails off x = 2 y.  By hand: the candidates for x are 1, 2, 3/2, ... and for y 1/2, 2/3,
    # 1/3, ... (smallest denominator first); (1, 1/2) and (1, 2/3) break x > 2 y, (2, 1/2) is the first to keep it
    point = small_point({x, y}, domain, lambda p: p[x] ** 2 != 4 * p[y] ** 2)
    assert point == {x: 2, y: sp.Rational(1, 2)}
    # where the claim holds at every admissible point, no counterexample is offered
    assert small_point({x, y}, domain, lambda p: False) is None


@pytest.mark.slow
@pytest.mark.parametrize("derivation", ["scheeffer-iv-v", "euler-220-228"])
def test_a_scheeffer_and_an_euler_notebook_run_top_to_bottom(derivation, check, tmp_path):
    report = next(r for r in check(derivation) if r.id == derivation)
    nb = execute_notebook(build_notebook(derivation, report), tmp_path)
    nbformat.write(nb, tmp_path / f"{derivation}.ipynb")
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert all("view." not in c.source for c in code)
    assert not [o for c in code for o in c.get("outputs", []) if o.get("output_type") == "error"]


def test_nbconvert_writes_html_that_loads_nothing_from_the_network(s1_notebook, tmp_path):
    # `jupyter nbconvert --to html` in the project's environment (make .venv/.installed installs the template
    # and the configuration, symfloat.report.notebook_html.install): MathML, no script or style from a CDN
    path = tmp_path / "s1.ipynb"
    nbformat.write(s1_notebook, path)
    done = subprocess.run([sys.executable, "-m", "jupyter", "nbconvert", "--to", "html", str(path)],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    page = (tmp_path / "s1.html").read_text(encoding="utf-8")
    assert not re.findall(r"<script[^>]*\bsrc=|<link[^>]*href=\"https?:", page)
    assert "mathjax" not in page.lower()
    assert page.count("<math") >= sum(c.source.count("$$") // 2 for c in s1_notebook.cells if c.cell_type == "markdown")
    assert "<mfrac>" in page and "$$" not in page          # the steps' fractions typeset, no TeX left over


def test_a_function_the_derivation_defines_is_defined_in_the_notebook_with_sympy_alone():
    # Euler SS229-243 writes its Beta integrals as its own functions Ib, IY (derivations/euler_229_243/statements.py);
    # the notebook's setup carries their definitions, so a cell that states Ib(...) runs with SymPy alone
    from symfloat.derivations.euler_229_243.statements import IY, Ib
    source = definitions_source({Ib, IY})
    assert "import symfloat" not in source and "from symfloat" not in source
    kernel: dict = {}
    exec(source, kernel)                                   # noqa: S102 - the package's own source, as the kernel runs it
    args = (1, sp.Rational(1, 2), 2, 3)
    # int_0^3 y (1 - y^2/9)^(1/2) dy = 3 (by hand: u = 1 - y^2/9, 9/2 int_0^1 u^(1/2) du = 3)
    assert abs(kernel["Ib"](*args).evalf(30) - 3) < sp.Float("1e-25")
    assert kernel["Ib"](*args).evalf(30) == Ib(*args).evalf(30)
    assert bound_names(source) >= {"Ib", "IY"}
    code = Code({sp.Symbol("p", positive=True)}, defined={Ib})
    assert code.source(Ib(sp.Symbol("p", positive=True), 1, 2, 3)) == "Ib(p, 1, 2, 3)"     # reads back as built


def test_a_step_without_sympy_source_leaves_the_steps_needing_its_value_as_comments(s1_report, tmp_path, monkeypatch):
    # Graefe S1: if step pyramid-over-g (V_1) had no SymPy source, the steps using V_1 cannot run in the kernel
    # (its derived lacks V_1): they are comments that say so, and the notebook still runs to its end
    real = CellWriter._step

    def unstated(self, s):
        if s.name == "pyramid-over-g":
            raise ValueError("no source")
        return real(self, s)
    monkeypatch.setattr(CellWriter, "_step", unstated)
    nb = build_notebook(S1, s1_report)
    by_id = {c.id: c.source for c in nb.cells}
    assert by_id[cell_id("step-check", "pyramid-over-g")].startswith("# no SymPy source reads back")
    for name in ("pyramid-over-g-value", "volume"):                                # they use V_1 (step 11)
        assert by_id[cell_id("step-check", name)].startswith("# this step needs the value of V_1 (step 11)")
    # and the volume I (step 19), built on V_1, is missing in turn
    assert by_id[cell_id("step-check", "volume-collected")].startswith("# this step needs the value of I_ (step 19)")
    assert by_id[cell_id("step-check", "mid-sections")].startswith("chain = [")     # no V_1 in it: SymPy
    execute_notebook(nb, tmp_path)


def test_an_erratum_is_shown_in_its_apparatus(graefe_reports):
    # the faults of the original and the corrections of the transcription are kept apart (issue 30, item 2):
    # a transcription erratum says what the original very probably printed, a fault of the original its kind
    seen = set()
    for report in graefe_reports:
        d, _ = load(report.id)
        view = NotebookView(d, report)
        errata = [f for f in report.formulas if f.erratum]
        for f in errata:
            text = view.formula_markdown(f.id.split("/", 1)[1])
            transcription = f.erratum["kind"] == "transcription"
            assert ("Correction of the transcription" in text) == transcription
            assert (f"Fault of the original ({f.erratum['kind']}," in text) == (not transcription)
            seen.add(f.erratum["kind"] == "transcription")
        if errata:
            n = sum(f.erratum["kind"] == "transcription" for f in errata)
            faults = f"{len(errata) - n} fault{'s' * (len(errata) - n != 1)}"
            corrections = f"{n} correction{'s' * (n != 1)}"
            named = f"{len(errata)} errat{'um' if len(errata) == 1 else 'a'}"
            assert f"{named} ({faults} of the original, {corrections} of the transcription)" in view.summary_markdown()
        # the steps counted as the verify table counts them: "13 proved, 5 definitions" (it wrote "5 definition")
        assert re.search(r"^\d+ steps: \d+ \w+", view.summary_markdown())
        assert not re.search(r"\b(?!1\b)\d+ definition\b", view.summary_markdown())
    assert seen == {True, False}              # Graefe has both (docs/errata.md: misprints and transcriptions)


def test_a_cells_printing_is_one_piece_however_the_kernel_flushed_it():
    # Scheeffer VI.C-F, step 9 printed "the difference, simplified by SymPy's simplify:" and " 0\n..." as two
    # pieces in one run and as one in the next (a slow simplify): the notebook must not depend on that
    from symfloat.report.notebooks import _coalesced
    out = nbformat.v4.new_output
    pieces = [out("stream", name="stdout", text="the difference, simplified:"), out("stream", name="stdout", text=" 0\n"),
              out("stream", name="stderr", text="warning\n"), out("stream", name="stdout", text="at {a: 1} : [1, 1]\n")]
    joined = _coalesced(pieces)
    assert [(o.name, o.text) for o in joined] == [("stdout", "the difference, simplified: 0\n"),
                                                   ("stderr", "warning\n"), ("stdout", "at {a: 1} : [1, 1]\n")]


def test_the_declarations_run_and_give_every_symbol_ten_to_a_line():
    # Scheeffer VI.C-F declared 38 symbols in one line of some 400 characters, past the cell's width
    syms = {sp.Symbol(f"A_{i}") for i in range(21)} | {sp.Symbol("b", positive=True)}
    code = Code(syms)
    text = code.declarations()
    assert [len(line.split(" = ")[0].split(", ")) for line in text.splitlines()] == [1, 10, 10, 1]   # b; the 21 A_i
    kernel: dict = {}
    exec("from sympy import Symbol, symbols\n" + text, kernel)            # noqa: S102 - code printed here
    assert all(kernel[code.names[s]] == s for s in syms)                  # a single symbol too (not 'b, = ...')


@pytest.mark.parametrize("derivation", registry.ids())
def test_every_symbol_is_declared_under_a_python_name_not_its_tex(derivation):
    # Euler §§220-228 declared its integrals as Symbol('{\\int_{0}^{b} \\frac{yy\\,dy}{\\sqrt{bb-yy}}}') and
    # Scheeffer I-III its wedge integrals as Symbol('\\int_3{x^2df}'): now int_y2_dy_over_R, int_x2_df_3, with
    # the typeset name registered where the symbol is made
    d, _ = load(derivation)
    exprs = [m for s in d.steps for m in members(s.claim)]
    code = Code({s for e in exprs if hasattr(e, "atoms") for s in e.atoms(sp.Symbol)} | set(d.domain))
    tex = [line for line in code.declarations().splitlines() if "\\" in line]
    assert not tex, tex[:3]


def test_a_product_sympy_would_multiply_out_is_kept_as_built_in_plain_sympy():
    # Scheeffer VI.C-F (moment-derivative) integrates the print's 2 sin t (t - sin t); SymPy, run, distributes
    # the 2 over t - sin t, so the step's cell was a comment: now that product alone is kept as built
    t, n, F = sp.Symbol("t", real=True), sp.Symbol("n", positive=True), sp.Symbol("F", positive=True)
    kept = sp.Mul(2, t - sp.sin(t), sp.sin(t), evaluate=False)
    expr = -F ** 2 * sp.Integral(kept, (t, 0, 2 * sp.pi / n)) / (6 * n ** 2)
    code = Code({t, n, F})
    assert eval(str(kept), {"__builtins__": {}, **code.namespace}) != kept      # noqa: S307 - run, 2(t - sin t) is lost
    text, evaluated = code.member(expr)
    assert evaluated and "Mul(2, t - sin(t), sin(t), evaluate=False)" in text
    assert eval(text, {"__builtins__": {}, **code.namespace}) == expr          # noqa: S307 - code printed here
