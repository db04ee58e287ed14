"""The identity checker proves, refutes with a counterexample, and says when
it cannot decide."""
import sympy as sp

from symfloat.engine.identity import Domain, _ball_value, check_identity
from symfloat.engine.timelimit import TimeLimitExceeded, time_limit

x, y, r = sp.symbols("x y r", positive=True)
DOMAIN = Domain({x: (1, 5), y: (1, 5), r: (1, 3)}, (x < y,))


def test_rational_identity_is_proved():
    res = check_identity((x + y) ** 3, x**3 + 3 * x**2 * y + 3 * x * y**2 + y**3, DOMAIN, "t1")
    assert res.status == "proved" and res.evidence == "symbolic" and res.exact


def test_wrong_coefficient_is_refuted_with_counterexample():
    res = check_identity((x + y) ** 3, x**3 + 3 * x**2 * y + 4 * x * y**2 + y**3, DOMAIN, "t2")
    assert res.status == "refuted"
    point = {sp.Symbol(k, positive=True): sp.Rational(v) for k, v in res.counterexample["point"].items()}
    assert ((x + y) ** 3 - (x**3 + 3 * x**2 * y + 4 * x * y**2 + y**3)).xreplace(point) != 0


def test_transcendental_identity_sampled_at_high_precision():
    res = check_identity(sp.Integral(sp.pi * (r**2 - x**2), (x, -r, r)), 4 * sp.pi * r**3 / 3, DOMAIN, "t3")
    assert res.holds and not res.exact


def test_transcendental_mismatch_in_the_40th_digit_is_refuted():
    res = check_identity(sp.pi * r, sp.pi * r * (1 + sp.Rational(1, 10**40)), DOMAIN, "t4")
    assert res.status == "refuted"


def test_constraints_are_honoured():
    # sqrt(y - x) is real only because the domain says x < y
    res = check_identity(sp.sqrt(y - x) ** 2, y - x, DOMAIN, "t5")
    assert res.holds


def test_sampling_is_reproducible():
    a = check_identity(x * y, x * y + 1, DOMAIN, "same-seed")
    b = check_identity(x * y, x * y + 1, DOMAIN, "same-seed")
    assert a.counterexample == b.counterexample


def test_undecided_when_no_sample_satisfies_the_assumptions():
    empty = Domain({x: (1, 5), y: (1, 5)}, (x > y + 10,))
    res = check_identity(x + y, y + x + 1, empty, "t6")  # no sample, no proof
    assert res.status == "undecided" and res.samples == 0


def test_time_limit_interrupts():
    import time
    try:
        with time_limit(0.05):
            time.sleep(1)
    except TimeLimitExceeded:
        return
    raise AssertionError("the time limit did not fire")


def test_the_cancel_strategy_is_zero_exactly_where_sympys_cancel_is():
    from symfloat.engine.identity import _strategy
    x, y = sp.symbols("x y", positive=True)
    cancel = _strategy("cancel")
    proved = x / (x + 1) + 1 / (x + 1) - 1 + (x ** 2 - y ** 2) / (x - y) - x - y
    assert cancel(proved) == 0 == sp.cancel(sp.together(proved))
    changed = proved + sp.Rational(1, 3) / (x + 1)                # a coefficient changed: not zero
    assert cancel(changed) != 0 and sp.simplify(cancel(changed) - sp.cancel(sp.together(changed))) == 0
    # where the numerator expands to a nonzero polynomial the result is SymPy's cancel
    a, b = sp.symbols("a b")                                      # no sign known: sqrt(a) sqrt(b) != sqrt(a b)
    roots = sp.sqrt(a) * sp.sqrt(b) - sp.sqrt(a * b)
    assert roots != 0
    assert cancel(roots) == sp.cancel(sp.together(roots))


def test_a_replay_is_reused_for_the_very_same_claim_and_no_other():
    """A certificate replayed once per claim (``_replayed``): a claim met again is proved by the same steps, but
    claims that print alike (one digest) and differ in their symbols' assumptions are not the same claim."""
    from symfloat.engine.identity import _replayed
    from symfloat.engine.proofs import Certificate, ProofBook, claim_digest
    # log(x y) = log x + log y: SymPy's expand splits the logarithm for positive x, y only
    u, v = sp.symbols("u v", positive=True)
    p, q = sp.symbols("u v")
    domain = Domain({u: (1, 5), v: (1, 5), p: (1, 5), q: (1, 5)})
    digest = claim_digest([(sp.log(u * v), sp.log(u) + sp.log(v))])
    assert digest == claim_digest([(sp.log(p * q), sp.log(p) + sp.log(q))])
    book = ProofBook("test", {k: Certificate(digest, "expand", ("expand",), "") for k in ("a", "b", "c")})
    before = _replayed.cache_info().hits
    first = check_identity(sp.log(u * v), sp.log(u) + sp.log(v), domain, "a", book=book)
    again = check_identity(sp.log(u * v), sp.log(u) + sp.log(v), domain, "b", book=book)
    assert first.status == again.status == "proved" and first.proof == again.proof == "replayed"
    assert _replayed.cache_info().hits == before + 1
    other = check_identity(sp.log(p * q), sp.log(p) + sp.log(q), domain, "c", book=book)
    assert other.proof == "replay failed" and other.status == "sampled" and "log(u*v)" in other.residual


# ---- sampled values from balls (symfloat.engine.identity._sample) ------------------------------------------------

def _count_sympy_values(monkeypatch) -> list:
    """Count the values SymPy's substitution-and-N path gives (the rest came from balls)."""
    import symfloat.engine.identity as identity
    asked, value = [], identity._value

    def counted(expr):
        asked.append(expr)
        return value(expr)
    monkeypatch.setattr(identity, "_value", counted)
    return asked


def test_an_irrational_value_is_read_from_its_ball_and_agrees_as_sympy_says(monkeypatch):
    from symfloat.engine.identity import _sample
    pairs = [(sp.sqrt(2) * sp.sqrt(3) * x * y, sp.sqrt(6) * y * x)]
    asked = _count_sympy_values(monkeypatch)
    by_sympy = _sample(pairs, DOMAIN, "b1", 6, balls=False)
    assert len(asked) == 12
    # from balls: one value asked of SymPy, whether the first value a ball gave was rational after all (no)
    assert _sample(pairs, DOMAIN, "b1", 6) == by_sympy == ("sampled", 6, False, None) and len(asked) == 13


def test_a_difference_in_the_40th_digit_is_refuted_from_balls_and_reported_as_sympy_reports_it():
    from symfloat.engine.identity import _sample
    pairs = [(sp.sqrt(2) * x, sp.sqrt(2) * x * (1 + sp.Rational(1, 10**40)))]
    refuted = _sample(pairs, DOMAIN, "b2", 6)
    assert refuted[0] == "refuted" and refuted == _sample(pairs, DOMAIN, "b2", 6, balls=False)


def test_a_rational_value_a_ball_cannot_see_is_found_exact_by_sympy():
    # log(exp(z)) for a symbol z without assumptions: no compiled reading gives its rational value, its ball is a
    # 60-digit float; SymPy's substitution gives the rational, so the sampling is exact, as it was without balls
    from symfloat.engine.identity import _sample
    z = sp.Symbol("z")
    result = _sample([(sp.log(sp.exp(z)) + x, z + x)], Domain({z: (1, 2), x: (1, 2)}), "b3", 6)
    assert result == ("sampled", 6, True, None)


class _SquaredGamma(sp.Function):
    """Gamma(x)^2 with a rule into Gamma only at a number, as Euler's IY (whose expansion expands a power)."""

    def _eval_rewrite_as_gamma(self, x, **hints):
        return sp.gamma(x) ** 2 if x.is_number else None


def test_a_value_with_no_ball_form_in_its_symbols_gets_its_ball_at_the_point():
    x = sp.Symbol("x", positive=True)
    # Gamma(3/2)^2 + 1 = pi/4 + 1 (Gamma(3/2) = sqrt(pi)/2): the ball's midpoint to 60 digits
    v = _ball_value(_SquaredGamma(x) + 1, {x: sp.Rational(3, 2)})
    assert v is not None and abs(v - (sp.pi / 4 + 1).evalf(70)) < sp.Float(10) ** -55
    assert abs(_ball_value(_SquaredGamma(x), {x: sp.Rational(5, 2)}) - (9 * sp.pi / 16).evalf(70)) < 1e-55
    # a node with no ball rule at any point (hyper) gives none, and SymPy's N is left to value it
    assert _ball_value(sp.hyper((x, 1), (2,), sp.Rational(1, 2)), {x: sp.Rational(1, 3)}) is None
