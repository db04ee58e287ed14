"""The engine can fail: wrong prints become errata or failures, never
'verified'; every derived step of the library, with one coefficient changed,
is refuted with a counterexample."""
import dataclasses

import sympy as sp
import pytest

from symfloat import Derivation, Eq, Erratum
from symfloat.engine.check import _check_chain, check_derivation
from symfloat.engine.identity import Domain
from symfloat.engine.witness import Case, SectionIntegral, record_decision
from symfloat.model.claim import members
from symfloat.registry import load, select

r, z, V = sp.symbols("r z V", positive=True)
SPHERE = r"$$I = \frac{2r}{3} \times 2r^2\pi = \frac{4r^3\pi}{3}.$$"   # graefe §2 sphere, verbatim


def sphere_derivation(reading, erratum=None):
    """A one-formula derivation of the sphere volume (Graefe §2)."""
    d = Derivation(id="test-sphere", source="graefe", title="sphere", locator="§2", domain={r: (1, 3)})
    d.step("volume", sp.Eq(V, sp.Integral(sp.pi * (r**2 - z**2), (z, -r, r))), "definition", result=V)
    d.step("value", (V, 4 * sp.pi * r**3 / 3), "integration")
    d.quote("sphere", "§2 sphere", SPHERE, reading=reading, erratum=erratum)
    d.witness(SectionIntegral("quad", "sphere volume by quadrature", ("sphere",),
                              (Case({r: sp.Rational(3, 2)}),), area=sp.pi * (r**2 - z**2), z=z,
                              bounds=(-r, r), quantity="volume"))
    return d


def test_correct_print_is_verified_with_witness_records():
    rep = check_derivation(sphere_derivation(sp.Eq(V, 4 * r**3 * sp.pi / 3)))
    f = rep.formulas[0]
    assert (f.verdict, f.evidence, rep.failures) == ("verified", "symbolic", [])
    assert len(f.numeric) >= 2 and all(n["rel_error"] < 1e-12 for n in f.numeric)


def test_wrong_print_without_erratum_is_a_failure():
    rep = check_derivation(sphere_derivation(sp.Eq(V, 4 * r**3 * sp.pi / 5)))
    assert rep.formulas[0].verdict == "erratum"
    assert any("no erratum is declared" in m for m in rep.failures)


def test_wrong_print_with_erratum_is_an_erratum_with_evidence():
    err = Erratum("misprint", "high", r"\frac{4r^3\pi}{3}", "test", corrected_reading=sp.Eq(V, 4 * r**3 * sp.pi / 3))
    rep = check_derivation(sphere_derivation(sp.Eq(V, 4 * r**3 * sp.pi / 5), err))
    f = rep.formulas[0]
    assert rep.failures == [] and f.verdict == "erratum"
    assert "the print gives" in f.erratum["evidence"]
    certified = [n for n in f.numeric if n.get("certified")]      # the witness sees the fault: 4/5 for 4/3, 40 % off
    assert certified and all(record_decision(n) == "refuted" and n["rel_error"] > 0.1 for n in certified)
    assert all(record_decision(n) == "agrees" for n in f.corrected_numeric)


def test_erratum_declared_on_a_correct_print_is_a_failure():
    err = Erratum("misprint", "high", "x", "test", corrected_reading=sp.Eq(V, 4 * r**3 * sp.pi / 3))
    rep = check_derivation(sphere_derivation(sp.Eq(V, 4 * r**3 * sp.pi / 3), err))
    assert any("declared but the print holds" in m for m in rep.failures)


def test_wrong_correction_is_a_failure():
    err = Erratum("misprint", "high", "x", "test", corrected_reading=sp.Eq(V, r**3 * sp.pi))
    rep = check_derivation(sphere_derivation(sp.Eq(V, 4 * r**3 * sp.pi / 5), err))
    assert any("correction does not hold" in m for m in rep.failures)


def test_excerpt_must_be_verbatim():
    with pytest.raises(ValueError, match="not verbatim"):
        sphere_derivation(sp.Eq(V, 4 * r**3 * sp.pi / 3)).quote("x", "§2", SPHERE.replace("2r", "3r"), reading=V)


def bump_coefficient(expr):
    """*expr* with the numeric coefficient of one term increased by one."""
    if expr.is_Add:
        term = sorted(expr.args, key=sp.default_sort_key)[0]
        c, rest = term.as_coeff_Mul()
        return expr - term + (c + 1) * rest
    c, rest = expr.as_coeff_Mul()
    return (c + 1) * rest


def _checked_steps():
    for did in select():
        d, _ = load(did)
        for s in d.steps:
            if s.why in ("definition", "lemma") or isinstance(members(s.claim)[-1], sp.MatrixBase):
                continue
            yield pytest.param(d, s, id=f"{did}/{s.name}")


@pytest.mark.parametrize("derivation,step", list(_checked_steps()))
def test_every_step_with_a_changed_coefficient_is_refuted(derivation, step):
    claim = members(step.claim)
    mutated = claim[:-1] + (bump_coefficient(claim[-1]),)
    results = {}
    for s in derivation.steps:          # results established before this step
        if s is step:
            break
        if s.result is not None:
            results[s.result] = members(s.claim)[-1].xreplace(results)
    names = {step.result} if step.result is not None else set()
    res = _check_chain(mutated, names, results, Domain(derivation.domain, tuple(derivation.constraints)),
                       f"mutant/{step.name}", book=None, proofs={}, prove=False)
    assert res.status == "refuted" and res.counterexample, (step.name, res)


def _example_derivation(printed_value, erratum=None):
    """A worked-example number: the sphere volume at r = 3/2 printed to 4 decimals."""
    d = Derivation(id="test-example", source="graefe", title="example", locator="§2", domain={r: (1, 3)})
    d.step("value", sp.Eq(V, 4 * sp.pi * r**3 / 3), "definition", result=V)
    d.quote("n", "§2 sphere", SPHERE, reading=(4 * sp.pi * sp.Rational(27, 8) / 3, printed_value),
            tolerance=sp.Rational(1, 20000), erratum=erratum)
    return d


def test_printed_number_within_its_precision_is_verified_numerically():
    # 4/3 pi (3/2)^3 = 14.137166941... (independent: 4.5 * pi)
    rep = check_derivation(_example_derivation(sp.Rational("14.1372")))
    assert (rep.formulas[0].verdict, rep.formulas[0].evidence, rep.failures) == ("verified", "numeric", [])


def test_printed_number_off_in_the_last_digit_is_refuted():
    err = Erratum("calculation", "high", "14.1372", "test",
                  corrected_reading=(4 * sp.pi * sp.Rational(27, 8) / 3, sp.Rational("14.1372")))
    rep = check_derivation(_example_derivation(sp.Rational("14.1374"), err))
    assert rep.failures == [] and rep.formulas[0].verdict == "erratum"
    assert "allowed difference" in rep.formulas[0].erratum["evidence"]


def _solve_derivation(pick):
    """x^2 = 2 solved for x (the positive root picked), then x^4 = 4 claimed from it."""
    x, X = sp.Symbol("x", positive=True), sp.Symbol("X")
    d = Derivation(id="test-solve", source="graefe", title="solve", locator="§2", domain={})
    d.solve("root", Eq(x ** 2, 2), x, X, pick=pick, note="the positive root")
    d.step("fourth", (X ** 4, 4), "algebra", uses=("root",))
    return d


def test_a_solve_step_is_proved_by_putting_the_solution_back():
    """d.solve: sp.solve's root establishes X (a definition) and '<name>-check' proves it as an identity."""
    rep = check_derivation(_solve_derivation(max))
    steps = {s.name: s.status for s in rep.steps}
    assert steps == {"root": "definition", "root-check": "proved", "fourth": "proved"}, steps
    assert rep.failures == []


def test_a_wrong_solution_is_refuted_by_its_check():
    """A pick that returns no solution (the root plus 1/10) is refuted by the check step, not trusted."""
    rep = check_derivation(_solve_derivation(lambda sols: max(sols) + sp.Rational(1, 10)))
    steps = {s.name: s.status for s in rep.steps}
    assert steps["root-check"] not in ("proved", "sampled", "definition") and rep.failures, steps


def test_refuted_print_without_erratum_names_its_sides_and_the_smallest_correction():
    # Graefe's sphere with the denominator misprinted 5 for 3 (a mutation of the verbatim SPHERE)
    d = Derivation(id="test-sphere", source="graefe", title="sphere", locator="§2", domain={r: (1, 3)})
    d.step("volume", sp.Eq(V, sp.Integral(sp.pi * (r**2 - z**2), (z, -r, r))), "definition", result=V)
    d.step("value", (V, 4 * sp.pi * r**3 / 3), "integration")
    d.quote("sphere", "§2 sphere", SPHERE, reading=sp.Eq(V, 4 * r**3 * sp.pi / 5))
    d.printed[0] = dataclasses.replace(d.printed[0], excerpt=r"$$V = \frac{4r^3\pi}{5}.$$")   # as if printed so
    message = next(m for m in check_derivation(d).failures if "no erratum is declared" in m)
    assert "printed: " in message and "derived: " in message and "{'point'" not in message
    # the print gives 4/5 of the volume 4 pi r^3/3 at the counterexample; the edit 5 -> 3 repairs it
    assert r"the smallest correction found is V = \frac{4r^3\pi}{3}. (5 → 3: digit, print-like; proved)" in message
