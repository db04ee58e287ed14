"""Proof certificates: verdicts that no clock decides (issue: proof checks on any machine).

A claim's symbolic proof is replayed from its recorded certificate with no time limit; a search
happens only for a claim without one, and the clock can end a search, never a replay."""
import sympy as sp

from symfloat import Derivation
from symfloat.engine import identity
from symfloat.engine.check import check_derivation
from symfloat.engine.identity import Domain, check_identity
from symfloat.engine.proofs import Certificate, ProofBook, claim_digest

x, y = sp.symbols("x y", positive=True)
DOMAIN = Domain({x: (1, 5), y: (1, 5)})
# cancel, expand and radsimp leave sin^2 + cos^2 - 1 as it is; pythagoras reduces it to 0 (so does simplify)
TRIG = (sp.sin(x) ** 2 + sp.cos(x) ** 2, sp.Integer(1))


def test_a_search_records_the_strategy_that_proved_the_claim():
    res = check_identity(*TRIG, DOMAIN, "rad")
    assert res.status == "proved" and res.proof == "searched"
    assert res.certificate["strategy"] == res.strategy == "pythagoras"
    assert res.certificate["tried"] == ["cancel", "squares", "expand", "radsimp", "pythagoras"]
    assert res.certificate["digest"] == claim_digest([TRIG])


def test_pythagoras_proves_angle_sums_and_not_a_changed_coefficient():
    # Scheeffer VI.C-F's regular prism: n r^2 sin(pi/n) cos(pi/n) = n r^2 sin(2 pi/n) / 2, the sum
    # a (sin w + cos w) / 2 = sqrt(2) a sin(w + pi/4) / 2, and a tangent: tan w cos^3 w + sin^3 w = sin w
    # (identities simplify proved before, at about seven times the cost over the library)
    n, r, a, w = sp.symbols("n r a omega", positive=True)
    prove = identity._strategy("pythagoras")
    regular = n * r**2 * sp.sin(sp.pi / n) * sp.cos(sp.pi / n)
    assert prove(regular - n * r**2 * sp.sin(2 * sp.pi / n) / 2) == 0
    assert prove(a * (sp.sin(w) + sp.cos(w)) / 2 - sp.sqrt(2) * a * sp.sin(w + sp.pi / 4) / 2) == 0
    assert prove(sp.tan(w) * sp.cos(w) ** 3 + sp.sin(w) ** 3 - sp.sin(w)) == 0
    assert prove(regular - n * r**2 * sp.sin(2 * sp.pi / n) / 3) != 0                    # a changed coefficient
    assert prove(sp.sin(x) ** 2 + sp.cos(x) ** 2 - sp.Rational(101, 100)) != 0
    assert prove(sp.tan(w) * sp.cos(w) ** 3 + sp.sin(w) ** 3 - sp.cos(w)) != 0          # sin read as cos


def test_branches_proves_a_piecewise_identity_case_by_case_and_not_a_changed_coefficient():
    # Scheeffer IX's tables: a quantity defined by cases (s > 1/2 or not), the print's form against the derived
    # one, a case inside a case; cancel, squares, expand, radsimp and pythagoras leave the Piecewise as it is
    a, b, s = sp.symbols("a b s", positive=True)
    half = sp.Rational(1, 2)
    inner = sp.Piecewise((4 * a**2 * (1 - s) ** 2 / b**2, s > half), (4 * a**2 * s**2 / b**2, True))
    printed = sp.Piecewise((a**2 / b**2 - 6 * s * (1 - s), s > half), (0, True))
    derived = sp.Piecewise(((inner - 24 * s * (1 - s) + 4 * a**2 * (2 * s - s**2) / b**2) / 4, s > half), (0, True))
    prove = identity._strategy("branches")
    assert prove(printed - derived) == 0
    changed = sp.Piecewise((a**2 / b**2 - 7 * s * (1 - s), s > half), (0, True))
    assert prove(changed - derived) != 0                                 # a changed coefficient
    # the other case changed
    assert prove(sp.Piecewise((a, s > half), (0, True)) - sp.Piecewise((a, s > half), (1, True))) != 0
    res = check_identity(printed, derived, Domain({a: (1, 2), b: (1, 2), s: (0, 1)}), "cases")
    assert res.status == "proved" and res.strategy == "branches"
    assert res.certificate["tried"] == ["cancel", "squares", "expand", "radsimp", "pythagoras", "branches"]


def test_a_replay_runs_exactly_the_recorded_strategy_and_needs_no_clock(monkeypatch):
    digest = claim_digest([TRIG])
    book = ProofBook("t", {"rad": Certificate(digest, "simplify", ("simplify",))})
    # a machine a trillion times slower: every search would stop at once, a replay is unaffected
    monkeypatch.setenv("SYMFLOAT_SLOWDOWN", "1e12")
    res = check_identity(*TRIG, DOMAIN, "rad", book=book)
    assert (res.status, res.proof, res.strategy) == ("proved", "replayed", "simplify")


def test_the_clock_can_end_a_search_but_the_outcome_is_written_down(monkeypatch):
    monkeypatch.setenv("SYMFLOAT_SLOWDOWN", "1e12")
    res = check_identity(*TRIG, DOMAIN, "rad")
    assert res.status == "sampled" and res.proof == "searched"
    assert res.certificate["strategy"] is None
    assert all("time limit" in t for t in res.certificate["tried"])


def test_a_certificate_that_no_longer_proves_its_claim_is_a_failure():
    d = Derivation(id="t-replay", source="graefe", title="t", locator="§0", domain={x: (1, 5)})
    d.step("rad", TRIG, "algebra")
    # cancel is recorded for the very claim (same digest), but cancel cannot prove it
    book = ProofBook(d.id, {"step t-replay/rad#0": Certificate(claim_digest([TRIG]), "cancel", ("cancel",))})
    report = check_derivation(d, book=book)
    assert report.steps[0].status == "sampled"
    assert report.proofs["step t-replay/rad#0"]["how"] == "replay failed"
    assert any("no longer proves" in f for f in report.failures)


def test_a_changed_claim_is_searched_anew():
    old = ProofBook("t", {"c": Certificate(claim_digest([(x + y, y + x)]), None, ("recorded: none",))})
    res = check_identity((x + y) ** 2, x**2 + 2 * x * y + y**2, DOMAIN, "c", book=old)
    assert res.proof == "searched" and res.status == "proved"


def test_a_recorded_failed_search_is_replayed_as_sampling():
    claim = ((x + y) ** 2, x**2 + 2 * x * y + y**2)
    book = ProofBook("t", {"c": Certificate(claim_digest([claim]), None, ("cancel (recorded)",), "r")})
    res = check_identity(*claim, DOMAIN, "c", book=book)
    assert (res.status, res.proof, res.residual) == ("sampled", "replayed", "r")
    assert "cancel (recorded)" in res.tried


def test_every_claim_of_the_library_replays_a_committed_certificate(all_reports):
    searched = {r.id: r.searched() for r in all_reports if r.searched()}
    assert not searched, f"claims without a committed certificate (run `make run` and commit): {searched}"


def test_the_committed_certificates_are_exactly_the_ones_used(all_reports):
    for r in all_reports:
        path = ProofBook.path(r.id)
        assert path.exists(), f"{path} is missing: run `make run` and commit"
        assert path.read_text(encoding="utf-8") == ProofBook.text(r.certificates()), \
            f"{path} is stale: run `make run` and commit"


def test_a_use_of_another_derivation_must_name_a_step_of_an_ancestor():
    # hasab's step energy-is-13 uses scheeffer-i-iii:moment-13 (Scheeffer's (13)); a misspelt step or a
    # derivation hasab does not require is a failure of the check, not a silent link
    import dataclasses
    from symfloat.engine.check import check_derivation
    from symfloat.registry import cross_use_problems, load
    d, _ = load("hasab")
    assert cross_use_problems(d) == []
    step = next(s for s in d.steps if s.name == "energy-is-13")
    wrong = dataclasses.replace(d, steps=[dataclasses.replace(step, uses=("scheeffer-i-iii:moment-31",)),
                                          dataclasses.replace(step, name="other", uses=("euler-192-219:x",))],
                                printed=[], witnesses=[])
    assert cross_use_problems(wrong) == [
        "step 'energy-is-13' uses 'scheeffer-i-iii:moment-31', which names no step of scheeffer-i-iii",
        "step 'other' uses 'euler-192-219:x', but 'euler-192-219' is not among the derivations hasab requires"]
    report = check_derivation(wrong, prove=False, trust_steps=True)
    assert [m for m in report.failures if "moment-31" in m or "euler-192-219" in m] and len(report.failures) == 2
