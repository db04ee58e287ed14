"""Relations as readings (symfloat.model.relation) and their check (symfloat.engine.relation).

Each true relation is paired with mutations that must be refuted; the expected thresholds are closed
forms worked by hand: s^2 - s + 1/6 vanishes at (3 -+ sqrt 3)/6 = 0.2113..., 0.7886...; s (1 - s) has
its maximum 1/4 at s = 1/2; x^3 - 3 n x + 2 has a double root at n = 1 (discriminant 108 (n^3 - 1)).
"""
import pytest
import sympy as sp

from symfloat import Derivation
from symfloat.engine.check import check_derivation
from symfloat.engine.identity import Domain
from symfloat.engine.relation import check_relation
from symfloat.model import Cases, Holds, Iff, RealRoots
from symfloat.model.claim import as_latex

s, n, x = sp.symbols("s n x", positive=True)
z = sp.Symbol("z", real=True)
DOMAIN = Domain({s: (0, 1), n: (1, 10)})
LOW = (3 - sp.sqrt(3)) / 6
CUBIC = z ** 3 - 3 * n * z + 2


def status(r, seed="t"):
    return check_relation(r, {}, DOMAIN, seed).status


@pytest.mark.parametrize("relation, expected", [
    (Holds(s * (1 - s) <= sp.Rational(1, 4)), "proved"),
    (Holds(s * (1 - s) < sp.Rational(1, 4), {s: sp.Interval.Ropen(0, sp.Rational(1, 2))}), "proved"),
    (Holds(s ** 2 - s + sp.Rational(1, 6) > 0, {s: (0, sp.Rational(21, 100))}), "proved"),
    (Holds(1 / (s - 2) < 0), "proved"),
    (Iff(s ** 2 - s + sp.Rational(1, 6) > 0, sp.Or(s < LOW, s > 1 - LOW)), "sampled"),
    (Holds(n ** 2 - 6 * s * (1 - s) >= 0, where=(n >= sp.Rational(3, 2),)), "sampled"),
    (Cases(((n < 1, sp.Eq(RealRoots(CUBIC, z, -sp.oo, sp.oo), 1)),
            (n > 1, sp.Eq(RealRoots(CUBIC, z, -sp.oo, sp.oo), 3))), {n: (0, 3)}, exhaustive=False), "sampled"),
    (Holds(sp.sin(x) <= 1, {x: sp.Interval(0, sp.pi / 2)}), "sampled"),
])
def test_true_relations_hold(relation, expected):
    assert status(relation) == expected


@pytest.mark.parametrize("relation, why", [
    (Holds(s * (1 - s) < sp.Rational(1, 4)), "strict at the maximum s = 1/2: a root of the sign cells"),
    (Holds(s ** 2 - s + sp.Rational(1, 6) > 0, {s: (0, sp.Rational(22, 100))}), "the domain passes 0.2113"),
    (Holds(s ** 2 - s + sp.Rational(1, 6) > 0, {s: sp.Interval.Lopen(0, LOW)}), "closed at the root itself"),
    (Iff(s ** 2 - s + sp.Rational(1, 6) > 0, sp.Or(s < sp.Rational(21, 100), s > 1 - LOW)),
     "a threshold 0.0013 off: the cell between is found from the numeric roots"),
    (Iff(s ** 2 - s + sp.Rational(1, 6) > 0, sp.Or(s < LOW, s >= 1 - LOW)), "the closed end at the root"),
    (Holds(n ** 2 - 6 * s * (1 - s) > 0, where=(n >= 1,)), "n = 1, s = 1/2 on the boundary"),
    (Holds(n ** 2 - 6 * s * (1 - s) > 0, where=(n >= sp.Rational(6, 5),)),
     "1.44 < 1.5 only near s = 1/2: found along s through a random point"),
    (Cases(((n < 1, sp.Eq(RealRoots(CUBIC, z, -sp.oo, sp.oo), 1)),
            (n > 1, sp.Eq(RealRoots(CUBIC, z, -sp.oo, sp.oo), 2))), {n: (0, 3)}, exhaustive=False),
     "a wrong root count"),
    (Cases(((n < 1, sp.Eq(RealRoots(CUBIC, z, -sp.oo, sp.oo), 1)),
            (n > 1, sp.Eq(RealRoots(CUBIC, z, -sp.oo, sp.oo), 3))), {n: (0, 3)}), "n = 1 is in no case"),
    (Cases(((n <= 1, sp.true), (n >= 1, sp.true)), {n: (0, 3)}), "both cases at n = 1"),
    (Holds(sp.sin(x) < 1, {x: sp.Interval(0, sp.pi / 2)}), "equality at the closed end pi/2"),
])
def test_mutated_relations_are_refuted(relation, why):
    r = check_relation(relation, {}, DOMAIN, "t")
    assert r.status == "refuted", why
    assert r.counterexample["point"] and "false" in r.counterexample["lhs"]


def test_counterexample_names_the_failing_row():
    table = Cases(((n < 2, sp.Eq(RealRoots(CUBIC, z, -sp.oo, sp.oo), 1)), (n >= 2, sp.true)), {n: (0, 3)})
    r = check_relation(table, {}, DOMAIN, "t")
    assert r.status == "refuted" and "row 1" in r.counterexample["lhs"]
    assert 1 < sp.Rational(r.counterexample["point"]["n"]) < 2


def test_no_valid_point_is_undecided_never_a_pass():
    r = check_relation(Holds(s < sp.Rational(1, 2), where=(s > 2,)), {}, DOMAIN, "t")
    assert r.status == "undecided" and not r.holds


def test_decided_when_built_is_trivial():
    assert status(Holds(s > 0)) == "trivial"          # s is positive: SymPy made it True


def test_deterministic():
    rel = Holds(n ** 2 - 6 * s * (1 - s) > -1)
    a, b = check_relation(rel, {}, DOMAIN, "seed"), check_relation(rel, {}, DOMAIN, "seed")
    assert (a.status, a.samples) == (b.status, b.samples)


def test_real_roots_counts_open_interval():
    assert RealRoots(z ** 3 - z, z, -1, 1) == 1                   # -1 and 1 are the ends, not inside
    assert RealRoots((z - 1) ** 2 * (z + 2), z, -sp.oo, sp.oo) == 2
    assert RealRoots(CUBIC, z, -sp.oo, sp.oo).free_symbols == {n}


def test_relation_reading_in_a_derivation():
    """A relation reading is verified, an erratum's relation is refuted and its correction holds, and
    the derived value of a result symbol is inserted before the check."""
    from symfloat import Eq, Erratum
    e = sp.Symbol("e")
    d = Derivation(id="test-relation", source="metazentrum", title="t", locator="t", domain={s: (0, 1)})
    d.step("e", Eq(e, s * (1 - s)), "definition", result=e)
    d.quote("bound", "t", "Stabilität", reading=Holds(e <= sp.Rational(1, 4)))
    d.quote("wrong", "t", "Stabilität", reading=Holds(e < sp.Rational(1, 5)),
            erratum=Erratum("claim", "high", "e <= 1/4", "the maximum is 1/4 at s = 1/2",
                            corrected_reading=Holds(e <= sp.Rational(1, 4))))
    rep = check_derivation(d, prove=False)
    verdicts = {f.id.split("/")[1]: (f.verdict, f.evidence) for f in rep.formulas}
    assert verdicts == {"bound": ("verified", "symbolic"), "wrong": ("erratum", "symbolic")}
    assert not rep.failures
    assert "the print gives true" in rep.formulas[1].erratum["evidence"]
    assert r"\leq" in as_latex(d.printed[0].reading)


def test_a_row_that_never_occurs_is_undecided():
    table = Cases(((n < 1, sp.Eq(RealRoots(CUBIC, z, -sp.oo, sp.oo), 1)), (n > 5, sp.true)), {n: (0, 3)},
                  exhaustive=False)
    r = check_relation(table, {}, DOMAIN, "t")
    assert r.status == "undecided" and "row 2" in r.tried[-1]


def test_sign_of_factors_proves_in_several_variables():
    """c a / 4 + r c > 0 for a, c, r on positive intervals: SymPy's assumptions decide the factored sign once
    the symbols are positive; a factor of unknown sign leaves it to sampling, which refutes a wrong claim."""
    a, c, r = sp.symbols("a c r", real=True)
    dom = Domain({a: (1, 2), c: (0, 3), r: (0, 1)})
    proved = check_relation(Holds(c * a / 4 + r * c > 0), {}, dom, "t")
    assert (proved.status, proved.strategy) == ("proved", "sign of factors")
    assert check_relation(Holds(c * (a - 1) > 0), {}, dom, "t").status == "sampled"
    assert check_relation(Holds(c * (a - sp.Rational(3, 2)) > 0), {}, dom, "t").status == "refuted"


@pytest.mark.parametrize("kind", [sp.StrictLessThan, sp.LessThan, sp.StrictGreaterThan, sp.GreaterThan,
                                  sp.Equality, sp.Unequality])
def test_sign_at_60_digits_agrees_with_the_exact_truth(kind):
    """The 60-digit sign (symfloat.engine.sign) gives SymPy's exact truth wherever it answers, and leaves a
    difference that is zero to the exact evaluation: tan(1/3) = 0.3463... < 2/3, tan(3/2) = 14.10... > 3,
    and a difference that is exactly zero (s + 1 against itself at s = 1), where the sign must not answer."""
    from symfloat.engine.sign import decided
    for lhs, rhs, at in ((sp.tan(s), 2 * s, sp.Rational(1, 3)), (sp.tan(s), 2 * s, sp.Rational(3, 2)),
                         (s + 1, s + 1, sp.Integer(1))):
        rel = kind(lhs, rhs, evaluate=False)
        exact = bool(kind(lhs.subs(s, at), rhs.subs(s, at)))
        known = decided(rel, {s: at})
        assert known is (None if lhs.subs(s, at) == rhs.subs(s, at) else exact)
