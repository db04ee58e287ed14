"""``symfloat check`` and ``symfloat.check``: one printed formula against a formula or a definition."""
import json
import re
from fractions import Fraction
from importlib.resources import files

import pytest
from jsonschema import Draft202012Validator

import sympy as sp

import symfloat
from symfloat.cli import main
from symfloat.engine.formula_check import parse_domain
from symfloat.model.latex import read

CAP_CENTROID = r"\bar z = \frac{\int_{r-h}^{r} x \pi (r^2 - x^2) \, dx}{\int_{r-h}^{r} \pi (r^2 - x^2) \, dx}"
SCHEMA = json.loads(files("symfloat").joinpath("schemas", "check.schema.json").read_text(encoding="utf-8"))


def test_the_bar_is_kept():
    # \bar z and z are two quantities (the centroid and a coordinate): the reader must not merge them
    (bar,), = [r[0][:1] for r in read(r"\bar z = z").rows]
    assert bar.name == "zbar" and read(r"\bar z = z").rows[0][0][1].name == "z"


def test_a_misprinted_centroid_is_refuted_with_labelled_sides_and_corrected():
    r = symfloat.check(r"\bar z = \frac{3(2r-h)^2}{3(3r-h)}", CAP_CENTROID, where="h < r")
    assert r.verdict == "refuted"
    # at r = 2, h = 1 (the simplest admissible point): the print gives 3·9/(3·5) = 9/5, the moment over
    # the volume of the segment is 3·9/(4·5) = 27/20 (V = pi h^2 (3r - h)/3, M = pi h^2 (2r - h)^2/4)
    assert r.counterexample == {"point": {"h": "1", "r": "2"}, "printed": "9/5", "derived": "27/20",
                                "left": "27/20", "right": "9/5", "sides": ["derived", "printed"],    # \bar z first
                                "tex": {"point": {"h": "1", "r": "2"}, "printed": r"\frac{9}{5}",
                                        "derived": r"\frac{27}{20}", "left": r"\frac{27}{20}", "right": r"\frac{9}{5}"}}
    assert r.witness["agrees_with"] == "derived" and r.witness["measured"].startswith("1.35")
    best = r.corrections[0]
    assert best.text == r"\bar z = \frac{3(2r-h)^2}{4(3r-h)}" and best.status == "proved"
    assert best.kind == "print-like" and best.what == "digit"


def test_a_right_print_holds_by_proof_and_quadrature():
    r = symfloat.check(r"V = \frac{\pi h^2}{3} (3r - h)", r"V = \int_{r-h}^{r} \pi (r^2 - x^2) \, dx", where="h < r")
    assert (r.verdict, r.evidence, r.corrections) == ("holds", "symbolic", [])
    assert r.witness["agrees_with"] == "printed"
    # mutated: the exponent of h changed, the same definition refutes it
    wrong = symfloat.check(r"V = \frac{\pi h^3}{3} (3r - h)", r"V = \int_{r-h}^{r} \pi (r^2 - x^2) \, dx",
                           where="h < r")
    assert wrong.verdict == "refuted"
    assert [c.text for c in wrong.corrections][:1] == [r"V = \frac{\pi h^2}{3} (3r - h)"]


def test_an_ocr_confusion_is_proposed_as_scan_like():
    # Scheeffer (81a) as scanned: "b s" for "6 s" (docs/errata.json, scheeffer-IV-V)
    r = symfloat.check(r"T = 2 \cdot \left\{ b s (1 - s) - 1 \right\}", r"T = 2 (6 s (1 - s) - 1)",
                       domain={"s": (0, 1), "b": (0, 1)})
    assert r.verdict == "refuted"
    assert (r.corrections[0].change, r.corrections[0].kind) == ("b → 6", "scan-like")


def test_the_definitions_are_put_into_the_printed_members():
    # x_s = M/V printed, M and V defined: decided in a alone (it was refuted "at M = 1, V = 1, a = 2", the
    # printed M/V read as two free symbols beside the definitions of both)
    against = ["V = a^2", "M = a^3"]
    assert symfloat.check("x_s = M/V", [*against, "x_s = M/V"]).verdict == "holds"
    assert symfloat.check(r"x_s = \frac{M}{V}", [*against, "x_s = a"]).verdict == "holds"
    wrong = symfloat.check(r"x_s = \frac{M}{V}", [*against, "x_s = 2a"])        # mutated: the derived side doubled
    assert wrong.verdict == "refuted" and wrong.counterexample["point"] == {"a": "1"}
    assert (wrong.counterexample["printed"], wrong.counterexample["derived"]) == ("1", "2")


def test_where_restricts_a_defined_symbol_through_its_definition_and_domain_refuses_it(capsys):
    # --where 'M < 1' with M = a^3 keeps a below 1: the simplest failing point is a = 1/2, not a = 1 (it was
    # refused: "--where names M, which no formula has"); an interval for M is refused, a is what is sampled
    against = ["V = a^2", "M = a^3", "x_s = 2 a"]
    assert symfloat.check("x_s = M/V", against).counterexample["point"] == {"a": "1"}
    assert symfloat.check("x_s = M/V", against, where="M < 1").counterexample["point"] == {"a": "1/2"}
    assert main(["check", "x_s = M/V", *(f"--against={a}" for a in against), "--domain", "M=0:1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--domain gives M an interval, which --against defines" in err


def test_an_integral_in_the_print_is_read_as_an_integral():
    # it was one opaque symbol named "int_{0}^{r2\pi \text{tdt}}", sampled as a number of its own
    assert symfloat.check(r"V = \int_0^r 2 \pi t \, dt", r"V = \pi r^2").verdict == "holds"
    wrong = symfloat.check(r"V = \int_0^r 3 \pi t \, dt", r"V = \int_0^r 2 \pi x \, dx")   # mutated: 2 -> 3
    assert wrong.verdict == "refuted" and wrong.counterexample["point"] == {"r": "1"}
    assert wrong.counterexample["tex"]["printed"] == r"\frac{3 \pi}{2}"
    assert [c.text for c in wrong.corrections][:1] == [r"V = \int_0^r 2 \pi t \, dt"]


@pytest.mark.parametrize("printed, against, said", [
    (r"V = \int_0^r 2 \pi x \, dx", [r"V = \pi r^2", "x = 2"],
     "the printed formula integrates over x, which --against"),
    (r"V = \pi r^2", [r"V = \int_0^r 2 \pi x \, dx", "x = 2"], "--against defines x, the variable of an integral"),
])
def test_a_definition_of_an_integrals_variable_is_refused(printed, against, said, capsys):
    # both ended in a traceback ("Invalid limits given"), the definition put in for the variable of integration
    assert main(["check", printed, *(f"--against={a}" for a in against)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and said in err, err


def test_a_printed_decimal_stands_for_what_rounds_to_it(capsys):
    # Scheeffer's "0,245" for sqrt(0.06) = 0.24495 (docs/errata.json keeps it as right): within 0.0005, half a unit
    # in its last digit; it was refuted, "printed 49/200, derived sqrt(6)/10"
    r = symfloat.check("y = 0,245", r"y = \sqrt{6/100}")
    assert (r.verdict, r.evidence, r.rounding) == ("holds", "rounded (60 digits)", "0.0005")
    assert main(["check", "y = 0.333", "--against", "y = 1/3"]) == 0
    assert "holds: equal to within half a unit in the last printed digit, 0.0005" in capsys.readouterr().out
    # mutated: the printer's transposition 0,254 is refuted, shown as printed, and corrected by the swap
    wrong = symfloat.check("y = 0,254", r"y = \sqrt{6/100}")
    assert (wrong.verdict, wrong.rounding, wrong.counterexample["tex"]["printed"]) == ("refuted", "0.0005", "0,254")
    assert (wrong.corrections[0].text, wrong.corrections[0].what, wrong.corrections[0].status) == \
        ("y = 0,245", "swap", "rounded")
    # one more digit, a tighter rounding: 0.3333 is within 0.00005 of 1/3, 0.3334 is not
    assert symfloat.check("y = 0.3333", "y = 1/3", propose=False).verdict == "holds"
    assert symfloat.check("y = 0.3334", "y = 1/3", propose=False).verdict == "refuted"
    # a decimal beside symbols is taken as written
    assert symfloat.check("A = 3.14 r^2", r"A = \pi r^2", propose=False).verdict == "refuted"


def test_a_divergent_integral_is_not_a_value(capsys):
    # \int_0^a sin(a)/x dx diverges (SymPy: log(a) sin(a) + oo sign(sin a)); where sin a < 0 its value -oo passed
    # the sampler's finiteness test (it excluded oo, not -oo) and "agreed" with 5: the print was said to hold
    r = symfloat.check(r"A = \int_0^a \frac{\sin a}{x} \, dx", "A = 5")
    assert r.verdict == "undecided" and "finite value" in r.reason


def test_the_signs_a_keyboard_types_are_read(capsys):
    # × and ÷ were read as quantities ("refuted at a = 1, b = 1, × = 2"), · and − refused
    for printed, against in (("y = a × b", "y = ab"), ("y = a ÷ b", "y = a/b"), ("y = a · b − 1", "y = ab - 1")):
        r = symfloat.check(printed, against, propose=False)
        assert (r.verdict, r.printed) == ("holds", printed), printed
    assert symfloat.check("y = a × b", "y = a + b", propose=False).verdict == "refuted"     # mutated


def test_sides_that_differ_only_where_one_is_not_real_are_undecided():
    # sqrt(x - 3) and sqrt(3 - x) are both real only at x = 3: the sampled disagreement was shown as the
    # counterexample, "printed 0.9007...*I"; sqrt(-x) against 2 has no real point at all
    for printed, against in ((r"y = \sqrt{x-3}", r"y = \sqrt{3-x}"), (r"y = \sqrt{-x}", "y = 2")):
        r = symfloat.check(printed, against)
        assert (r.verdict, r.counterexample) == ("undecided", None), printed
        assert r.reason == "the sides differ only where one of them is not a real number"
    # where a real point exists it is shown: sqrt(x - 3) against 1 at x = 7/2 (sqrt(1/2))
    r = symfloat.check(r"y = \sqrt{x-3}", "y = 1", propose=False)
    assert r.verdict == "refuted" and "I" not in r.counterexample["printed"]


def test_a_value_without_a_closed_form_is_shown_at_the_simplest_point():
    # \int_0^a sqrt(1 + x^3) dx has only a hypergeometric closed form (SymPy: not "a number"): the counterexample
    # was a random point, a = 176/85; a = 1 fails already (1.1114... against 1)
    r = symfloat.check(r"A = \int_0^a \sqrt{1 + x^3} \, dx", "A = a", propose=False)
    assert r.verdict == "refuted" and r.counterexample["point"] == {"a": "1"}
    assert r.counterexample["printed"].startswith("1.111447970532575")


def test_a_correction_does_not_bring_a_defined_symbol_into_the_print():
    # y = x^2 against y = 1 was "corrected" to y = y^2 (x -> y: holds once y = 1 is put in, and says nothing)
    r = symfloat.check("y = x^2", "y = 1")
    assert r.verdict == "refuted" and not any("y^2" in c.text for c in r.corrections)
    r = symfloat.check(r"A = \int_0^a \frac{\sin x}{x} \, dx", "A = a")
    assert not any(r"\sin A" in c.text for c in r.corrections)


def test_many_symbols_are_sampled_without_listing_every_combination():
    # twenty symbols: 2^20 combinations of their two simplest values were listed and sorted (42 s); fifty hung
    from symfloat.engine.formula_check import _SMALL_POINTS, _simple_points
    from symfloat.engine.identity import Domain
    xs = [sp.Symbol(f"x_{i}") for i in range(50)]
    points = list(_simple_points(xs, Domain({x: (0, 4) for x in xs})))
    assert len(points) == _SMALL_POINTS and set(points[0].values()) == {1}
    assert sorted(points[1].values()) == [1] * 49 + [2]
    printed = "y = " + " + ".join(x.name for x in xs[:30])
    assert symfloat.check(printed, printed.replace("y =", "y = 0 +"), propose=False).verdict == "holds"


def test_domain_names_a_symbol_as_the_formulas_type_it_and_takes_decimals():
    r = symfloat.check(r"y = \alpha", r"y = \alpha + 1/10", domain=parse_domain(r"\alpha=0.5:0.75"), propose=False)
    assert r.counterexample["point"] == {"alpha": "2/3"}          # the simplest value inside (1/2, 3/4)
    assert parse_domain(r"\bar z=1e-3:1, x_{1}=0:1") == {"zbar": (Fraction(1, 1000), 1), "x_1": (0, 1)}


def test_a_definition_the_print_does_not_use_is_refused(capsys):
    # e^x = 1 + x against "y = 1": the definition of y reached nothing and the print was refuted against itself
    assert main(["check", "e^{x} = 1 + x", "--against", "y = 1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--against defines y, which the printed formula does not use" in err
    # a definition reached through another one is used
    assert symfloat.check("x_s = M", ["M = 2 V", "V = a^2", "x_s = 2 a^2"]).verdict == "holds"


def test_a_link_between_two_printed_members_shows_both(capsys):
    # y = a b = a + b against y = a b: the print's second link compares two printed members, 1 and 2 at a = b = 1
    r = symfloat.check("y = a b = a + b", "y = a b")
    assert r.verdict == "refuted" and r.counterexample["sides"] == ["printed", "printed"]
    assert (r.counterexample["left"], r.counterexample["right"], r.counterexample["derived"]) == ("1", "2", "")
    assert main(["check", "y = a b = a + b", "--against", "y = a b"]) == 1
    assert "verdict:  refuted at a = 1, b = 1: the printed sides are 1 and 2" in capsys.readouterr().out


def test_several_definitions_chain():
    r = symfloat.check(r"x_s = \frac{3 (2r - h)^2}{4 (3r + h)}",
                       [r"V = \frac{\pi h^2}{3} (3r - h)", r"M = \frac{\pi h^2}{4} (2r - h)^2", "x_s = M/V"],
                       where="0 < h < r")
    assert r.verdict == "refuted" and r.corrections[0].change == "+ → -"


def test_command_line_text_json_and_exit_status(tmp_path, capsys):
    assert main(["check", r"\bar z = \frac{3(2r-h)^2}{3(3r-h)}", "--against", CAP_CENTROID, "--where", "h < r"]) == 1
    out = capsys.readouterr().out
    assert r"refuted at h = 1, r = 2: printed \frac{9}{5}, derived \frac{27}{20}" in out and "[3 → 4; digit" in out
    target = tmp_path / "check.json"
    assert main(["check", r"V = \frac{\pi h^2}{3} (3r - h)", "--against", r"V = \int_{r-h}^{r} \pi (r^2 - x^2) \, dx",
                 "--format", "json", "--output", str(target), "--quiet"]) == 0
    record = json.loads(target.read_text(encoding="utf-8"))
    assert list(Draft202012Validator(SCHEMA).iter_errors(record)) == []
    record["verdict"], record["counterexample"] = "refuted", None          # the schema is not vacuous
    assert list(Draft202012Validator(SCHEMA).iter_errors(record))


def test_the_text_report_speaks_tex_and_words_not_sympy(tmp_path, capsys):
    # once "refuted at lambda = 1, rbar = 1: printed sqrt(2)*pi*..." and "holds: proved (cancel)"
    assert main(["check", r"y = \sqrt{2} \pi \lambda \bar r", "--against", r"y = \sqrt{3} \pi \lambda \bar r"]) == 1
    out = capsys.readouterr().out
    assert r"refuted at \lambda = 1, \bar{r} = 1: printed \sqrt{2} \pi, derived \sqrt{3} \pi" in out
    assert not re.search(r"sqrt\(|\*|(?<!\\)lambda|rbar", out)
    target = tmp_path / "check.json"
    assert main(["check", r"y = \sqrt{2} \lambda", "--against", r"y = 2 \lambda", "--format", "json", "--output",
                 str(target), "--quiet"]) == 1
    cx = json.loads(target.read_text(encoding="utf-8"))["counterexample"]
    assert (cx["printed"], cx["tex"]["printed"], cx["tex"]["point"]) == ("sqrt(2)", r"\sqrt{2}", {r"\lambda": "1"})
    assert main(["check", r"y = \frac{h^2 - 1}{h - 1}", "--against", "y = h + 1"]) == 0
    assert "holds: proved (the difference cancels over a common denominator)" in capsys.readouterr().out
    # a print that holds has a witness and no counterexample: its point is its own (once a TypeError)
    assert main(["check", r"V = \frac{\pi h^2}{3} (3r - h)", "--against", r"V = \int_{r-h}^{r} \pi (r^2 - x^2) \, dx"]) == 0
    assert "witness:  quadrature (mpmath tanh-sinh, 30 digits) at h = 1, r = 1: " in capsys.readouterr().out


@pytest.mark.parametrize("argv, says", [
    (["x = 1 +", "--against", "x = 1"], "the formula ends too early"),
    (["x = 1", "--against", "x = 1", "--domain", "y=0:1"], "--domain names y"),
    (["x = 1", "--against", "x = 1", "--domain", "x=2:1"], "--domain needs low < high"),
    (["x = 1", "--against", "x = 1", "--domain", "x=0:1, x=1:2"], "--domain gives x two intervals"),
    (["x = 1", "--against", "x = 1", "--domain", "x=a:1"], "an interval's ends are numbers"),
    (["x = 1", "--against", "x = 1", "--where", "x + 1"], "--where holds inequalities"),       # once ignored
    (["y = h", "--against", "y = r", "--where", "h < r < h"], "--where admits no point"),       # once "undecided"
    (["y = a", "--against", "a = b + 1", "--against", "b = a", "--against", "y = 2 b"],
     "--against defines a, b by itself"),
    (["x = __import__('os')", "--against", "x = 1"], "symfloat:"),
    (["x = h", "--against", "x = h", "--domain", "h=1/0:2"], "--domain divides by zero"),      # once a traceback
    (["x = h", "--against", "x = h", "--where", "0 < R"], "--where names R, which no formula has"),  # once ignored
    (["x = " + "(" * 200 + "h" + ")" * 200, "--against", "x = h"], "nested more than 50 deep"),  # RecursionError
    (["x = h" + "^h" * 3000, "--against", "x = h"], "nests too deeply"),                          # RecursionError
    (["x = " + "\\sqrt " * 3000 + "h", "--against", "x = h"], "nests too deeply"),              # RecursionError
    (["y = a", "--against", "a = 1", "--against", "a = 2"], "--against defines 'a' twice"),     # once the last won
    (["y = a", "--against", "1", "--against", "2"], "gives two values the print must have"),
])
def test_bad_input_is_one_line_and_exit_2(argv, says, capsys):
    assert main(["check", *argv]) == 2
    err = capsys.readouterr().err
    assert says in err and err.count("\n") == 1


def test_two_confusions_at_two_places_are_one_candidate():
    # Euler's scan reads "\mu V" as "\nu v" (docs/errata.json, euler §241): ν/μ and v/V together
    from symfloat.engine.corrections import candidates
    found = {c.text: c for c in candidates(r"D = \nu v")}
    assert r"D = \mu V" in found and found[r"D = \mu V"].kind == "scan-like"
    assert r"D = \mu V" not in {c.text for c in candidates(r"D = \nu w")}      # mutated: w/V is no confusion


def test_every_proof_strategy_has_its_words():
    """An erratum's evidence says how the correction is proved in words (PROOF_WORDS); a strategy of the
    identity check or the relation check without words would raise KeyError when an erratum is written."""
    from symfloat.engine import identity
    from symfloat.engine.proof_words import PROOF_WORDS
    relation_strategies = ("assumptions", "sign of factors", "sign cells")   # symfloat/engine/relation.py
    assert set(identity.STRATEGIES) | set(relation_strategies) <= set(PROOF_WORDS)


def test_a_bracketed_factor_at_the_end_is_no_equation_number():
    # h(2) and sin(2h) once lost their last bracket as a tag (118) does: 'y = h(2)' was refuted against 2h
    assert symfloat.check("y = h(2)", "y = 2h").verdict == "holds"
    assert symfloat.check(r"y = \sin(2h)", r"y = 2 \sin(h) \cos(h)").verdict == "holds"
    assert symfloat.check("y = h (2)", "y = 2h").verdict == "refuted"       # set apart, it is the number of y = h
    assert read(r"V = abc \quad (12a)").rows == read("V = abc").rows


def test_the_witness_reads_its_integral_and_skips_a_point_without_value():
    # the integral's own x beside a free x (once "Invalid limits"); 0/0 at h = 1 (once a NaN comparison)
    r = symfloat.check("y = x", r"y = \int_0^1 x \, dx")
    assert r.verdict == "refuted" and r.witness["measured"] == "0.5" and r.witness["agrees_with"] == "derived"
    r = symfloat.check(r"y = \frac{h^2-1}{h-1}", r"y = \int_0^h 1 \, dx + 1")
    assert r.verdict == "holds" and r.witness["point"] == {"h": "2"} and r.witness["agrees_with"] == "printed"


def test_the_simple_points_stay_few_whatever_the_symbols_and_the_domain():
    # six symbols on (0, 4), or one on (0, 10^6), once built every grid point (minutes, or out of memory)
    from symfloat.engine.formula_check import _GRID, _simple_points, _simple_values
    from symfloat.engine.identity import Domain
    import sympy as sp
    names = sp.symbols("a b c d f g", positive=True)
    points = list(_simple_points(names, Domain({s: (0, 4) for s in names}, ())))
    assert 2 ** len(names) <= len(points) <= _GRID and points[0] == {s: 1 for s in names}
    assert [str(v) for v in _simple_values(0, 10**6, 3)] == ["1", "2", "3"]
    r = symfloat.check("y = a+b+c+d+f+g", "y = a+b+c+d+f+2g", propose=False)
    assert r.verdict == "refuted" and r.counterexample["printed"] == "6" and r.counterexample["derived"] == "7"


def test_a_correction_is_never_a_thing_equal_to_itself():
    # 'y = h' against y = 2h once got 'h = h' and 'y = y' as corrections
    assert [c.text for c in symfloat.check("y = h", "y = 2h").corrections] == []


def test_a_power_too_large_to_compute_is_passed_over():
    # h^h^...^h forty high once hung at the shown point h = 2, h^{h^{100}} in the sampling, h^{h^8} for 50 s in
    # the corrections' sampling at h = 3/2 (SymPy raises 3/2 to 6561/256 by way of 3^6561 and factors it)
    import sympy as sp
    from fractions import Fraction
    from symfloat.engine.identity import computable
    from symfloat.model.compiled import _pow_exact
    h = sp.Symbol("h")
    assert computable(h ** h ** 3, {h: sp.Integer(2)}) and computable(h ** h ** 8, {h: sp.Integer(2)})
    assert not computable(h ** h ** 100, {h: sp.Integer(2)})                   # 2^(2^100): by its size
    assert not computable(h ** h ** 8, {h: sp.Rational(3, 2)})                 # 3^6561 on the way
    assert not computable(h ** h ** 100, {h: sp.Rational(2, 3)})               # a 160-bit denominator
    assert not isinstance(_pow_exact(Fraction(2), 2 ** 100), Fraction)         # a ball-backed real, not 2^(2^100)
    assert _pow_exact(Fraction(3, 2), 3) == Fraction(27, 8)
    r = symfloat.check("y = h" + "^h" * 40, "y = h", propose=False)
    assert r.verdict == "refuted" and r.counterexample["point"] == {"h": "1/2"}
    r = symfloat.check("y = h^{h^{8}}", "y = h", propose=True)
    assert r.verdict == "refuted" and r.counterexample["printed"] == str(2 ** 256)
    assert symfloat.check("y = h^{h^{100}}", "y = h").verdict == "undecided"


def test_the_shown_point_is_one_where_the_formula_is_real():
    # \sqrt{h-3} was shown at h = 1: printed \sqrt{2} i
    r = symfloat.check(r"y = \sqrt{h-3}", r"y = \sqrt{h-3}+1", propose=False)
    assert r.counterexample["point"] == {"h": "3"}
    assert (r.counterexample["printed"], r.counterexample["derived"]) == ("0", "1")


def test_a_greek_letter_typed_as_itself_is_its_command():
    # 'π r^2' was refuted against '\pi r^2' at π = 1: the reader took π for a symbol of that name
    import sympy as sp
    assert symfloat.check("y = π r^2", r"y = \pi r^2").verdict == "holds"
    assert read("V = α Δ").rows == read(r"V = \alpha \Delta").rows
    assert sp.pi in read("y = π").rows[0][0]


def test_a_print_that_holds_by_samples_names_their_arithmetic(capsys):
    # arctan h + arctan 1/h = pi/2 holds at every sample, at 60 digits (irrational values): it was shown as
    # "every one of 6 exact samples agrees"
    r = symfloat.check(r"y = \arctan(h) + \arctan(\frac{1}{h})", r"y = \frac{\pi}{2}")
    assert (r.verdict, r.evidence) == ("holds", "sampled (60 digits)")
    assert main(["check", r"y = \arctan(h) + \arctan(\frac{1}{h})", "--against", r"y = \frac{\pi}{2}"]) == 0
    assert "every one of 6 samples at 60 digits agrees" in capsys.readouterr().out
    assert main(["check", r"y = \frac{1}{0}", "--against", "y = 1"]) == 1
    assert "at no sampled point do both sides have a finite value" in capsys.readouterr().out


def test_a_value_too_large_to_print_is_shown_from_its_logarithm():
    # e^(e^(e^(e^h))) hung: SymPy printed a sampled value whose decimal exponent has 10^8 digits
    import sympy as sp
    from symfloat.engine.identity import _show
    assert _show(sp.Float("-1.2345e+123456789", 30)) == "-1.2345e+123456789"
    assert _show(sp.Float("1e300000", 30)) == "1.0e+300000" and _show(sp.Float("7.5e-9876543", 30)) == "7.5e-9876543"
    assert _show(sp.Rational(3, 7)) == "3/7" and _show(sp.pi) == "3.1415926535897932385"
    r = symfloat.check(r"y = \exp(\exp(\exp(\exp(h))))", "y = h", propose=False)
    assert r.verdict == "refuted" and r.counterexample["point"] == {"h": "1"}
