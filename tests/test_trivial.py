"""A claim whose members are identical as built proves nothing: the engine calls it
``trivial`` (never ``symbolic``), and no reading of the library is one, unless the
print itself says a thing equals itself."""
import dataclasses

import pytest
import sympy as sp

from symfloat import Derivation, Erratum
from symfloat.engine.check import check_derivation
from sympy.logic.boolalg import BooleanAtom

from symfloat.model.claim import identical_links, members
from symfloat.model.relation import Holds, Iff, is_relation
from symfloat.registry import load, select

g, V, P = sp.symbols("g V P", positive=True)
MID = r"dessen Inhalt, weil auf der halben Höhe der Pyramide  $ABCO$ ,  $= \frac{g}{4}$"  # graefe §1, verbatim
HALF_SQUARED = sp.Pow(sp.Rational(1, 2), 2, evaluate=False)


def mid_section(reading, erratum=None, step_claim=None):
    """Graefe §1: the mid-section of the pyramid over g is g (1/2)^2 = g/4."""
    d = Derivation(id="test-mid", source="graefe", title="mid-section", locator="§1", domain={g: (1, 20)})
    d.step("area", sp.Eq(V, sp.Integral(g * sp.Symbol("t") ** 2 * 4, (sp.Symbol("t"), 0, sp.Rational(1, 2)))
                         * sp.Rational(3, 2)), "definition", result=V)
    if step_claim is not None:
        d.step("claimed", step_claim, "algebra")
    d.quote("mid-section-g", "§1 prismatoid volume", MID, reading=reading, erratum=erratum)
    return check_derivation(d)


def test_evaluated_print_is_trivial_not_symbolic():
    # g*(1/2)**2 is g/4 as soon as SymPy builds it: the comparison happened on construction
    rep = mid_section((g * sp.Rational(1, 2) ** 2, g / 4))
    f = rep.formulas[0]
    assert (f.verdict, f.evidence) == ("trivial", None)
    assert "identical as built" in f.reason and rep.failures == []


def test_unevaluated_print_is_checked():
    rep = mid_section((sp.Mul(g, HALF_SQUARED, evaluate=False), g / 4))
    f = rep.formulas[0]
    assert f.verdict == "verified" and f.evidence in ("symbolic", "sampled") and rep.failures == []


def test_unevaluated_wrong_print_is_refuted():
    # mutation: (1/2)^3 printed instead of (1/2)^2 is no longer hidden by construction
    wrong = sp.Mul(g, sp.Pow(sp.Rational(1, 2), 3, evaluate=False), evaluate=False)
    rep = mid_section((wrong, g / 4))
    assert rep.formulas[0].verdict == "erratum"
    assert any("no erratum is declared" in m for m in rep.failures)


def test_unevaluated_expr_is_stripped_before_sampling():
    rep = mid_section((g * sp.UnevaluatedExpr(sp.Rational(1, 2)) ** 2, g / 4))
    assert rep.formulas[0].verdict == "verified"
    rep = mid_section((g * sp.UnevaluatedExpr(sp.Rational(1, 2)) ** 2, g / 3))
    assert rep.formulas[0].verdict == "erratum"


def test_result_symbol_against_its_value_is_not_trivial():
    # V = g/4 compares the derived value of V (an integral) with the print
    rep = mid_section(sp.Eq(V, g / 4))
    assert rep.formulas[0].verdict == "verified"
    rep = mid_section(sp.Eq(V, g / 3))
    assert rep.formulas[0].verdict == "erratum"


def test_erratum_on_a_trivial_reading_is_a_failure():
    err = Erratum("misprint", "high", "g/4", "test", corrected_reading=(g / 4, g / 4))
    rep = mid_section((g * sp.Rational(1, 2) ** 2, g / 4), err)
    assert any("compares a thing with itself" in m for m in rep.failures)
    rep = mid_section((sp.Mul(g, sp.Pow(sp.Rational(1, 2), 3, evaluate=False), evaluate=False), g / 4), err)
    assert any("correction compares a thing with itself" in m for m in rep.failures)


def test_trivial_step_and_trivial_link():
    rep = mid_section(sp.Eq(V, g / 4), step_claim=(g * sp.Rational(1, 2) ** 2, g / 4))
    assert rep.steps[-1].status == "trivial"
    # a chain with one link identical as built: the other link decides, the idle one is named
    rep = mid_section((V, g / 4, g * sp.Rational(1, 2) ** 2))
    f = rep.formulas[0]
    assert f.verdict == "verified"
    assert any("link 2 not checked" in t for t in f.identity["tried"])
    rep = mid_section((V, g / 3, g * sp.Rational(1, 3)))
    assert rep.formulas[0].verdict == "erratum"


def test_matrices_compare_entrywise():
    m = sp.Matrix([g / 4, g])
    assert identical_links((m, sp.Matrix([g * sp.Rational(1, 2) ** 2, g]))) == [True]
    assert identical_links((m, sp.Matrix([g / 4, 2 * g]))) == [False]


# The library: every reading, corrected reading and step checks something, except
# prints that are trivial themselves (a definition of notation), listed with their reason.
TRIVIAL_PRINTS = {
    "scheeffer-iv-v/Tx-Ty": "(45) names the moments: int_1 y^2 df = T_x, int_1 x^2 df = T_y",
}


def _links(reading) -> list:
    """The members whose consecutive pairs a reading compares: a chain's members; a relation's conditions
    (``Iff(a, b)``: a and b; a condition that SymPy decided on building is compared with its own value)."""
    if not is_relation(reading):
        return members(reading)
    if isinstance(reading, Iff):
        return list(reading.parts())
    decided = [p for p in reading.parts() if isinstance(p, BooleanAtom)]
    return [decided[0], decided[0]] if decided else []


def _offenders(d):
    """``(what, links)`` for every claim of *d* with a link identical as built."""
    claims = []
    for p in d.printed:
        if p.reading is not None:
            claims.append((f"{p.name}", _links(p.reading)))
        if p.erratum is not None and p.erratum.corrected_reading is not None:
            claims.append((f"{p.name}#corrected", _links(p.erratum.corrected_reading)))
    for s in d.steps:
        if s.why != "definition":
            claims.append((f"step {s.name}", [m for m in members(s.claim)
                                               if not (s.result is not None and m == s.result)]))
    out = []
    for what, ms in claims:
        same = identical_links(ms)
        if any(same) and f"{d.id}/{what}" not in TRIVIAL_PRINTS:
            out.append((what, [i + 1 for i, t in enumerate(same) if t]))
    return out


@pytest.mark.parametrize("derivation_id", select())
def test_no_claim_of_the_library_compares_a_thing_with_itself(derivation_id):
    d, _ = load(derivation_id)
    assert _offenders(d) == []


def test_the_library_test_sees_a_trivial_relation():
    # mutation: a relation decided as SymPy builds it (x > x - 1 is True) or an Iff of a condition with itself
    x = sp.Symbol("x", real=True)
    assert any(identical_links(_links(Holds(x > x - 1))))
    assert any(identical_links(_links(Iff(x > 0, x > 0))))
    assert not any(identical_links(_links(Iff(x > 0, x ** 3 > 0))))


def test_the_library_test_sees_a_trivial_reading():
    # mutation: Graefe §1 step 'mid-sections' (g (1/2)^2 = g/4) read with SymPy's evaluation on is caught
    d, _ = load("graefe-s1-prismatoid-volume")
    s = next(s for s in d.steps if s.name == "mid-sections")
    mutated = type(d)(id=d.id, source=d.source, title=d.title, locator=d.locator, domain=d.domain)
    mutated.steps = [dataclasses.replace(s, claim=(g * sp.Rational(1, 2) ** 2, g / 4))]
    assert _offenders(mutated) == [("step mid-sections", [1])]
    mutated.steps = [s]
    assert _offenders(mutated) == []


def test_no_verdict_of_the_library_rests_on_a_trivial_comparison(all_reports):
    """The checked record: no formula verdict or step status comes from a comparison of a thing
    with itself, and no identity record skipped a link as identical (unless the print is trivial)."""
    idle = [f.id for r in all_reports for f in r.formulas
            if f.verdict == "trivial" or any("identical as built" in t for t in (f.identity or {}).get("tried", []))]
    assert [i for i in idle if i not in TRIVIAL_PRINTS] == []
    assert [f"{r.id}/{s.name}" for r in all_reports for s in r.steps if s.status == "trivial"] == []
