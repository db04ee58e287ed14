"""Closed forms and roots that the statements state instead of computing them at import (issue 28, item 2) are
held by the check: each stated form passes the step that checks it, and the same form with one slip is refuted
there.  Euler §§192-219 and §§220-228 state the values of their integrals (SymPy's integrate and factor used to
work them out on import), §§220-228 also the integrands it writes for integration, Scheeffer VI.A-B the roots
that sp.solve used to find."""
import dataclasses

import sympy as sp

from symfloat.engine.check import check_derivation
from symfloat.model.claim import members
from symfloat.registry import statements


def _statuses(derivation_id, names, slip=None, by=None):
    """The statuses of the steps *names* of a derivation checked by sampling alone, with the last member of the
    step *slip* replaced by ``by(last member)``."""
    d = statements(derivation_id)
    steps = []
    for s in d.steps:
        if s.name == slip:
            ms = members(s.claim)
            s = dataclasses.replace(s, claim=(*ms[:-1], by(ms[-1])) if isinstance(s.claim, tuple)
                                    else sp.Eq(ms[0], by(ms[-1])))
        if s.name in names:
            steps.append(s)
    report = check_derivation(dataclasses.replace(d, steps=steps, printed=[], witnesses=[]), prove=False)
    return {r.name: r.status for r in report.steps}


def test_a_stated_integral_holds_and_a_slip_in_it_is_refuted():
    # the rectangle's K = ∫∫ x² = 4 b a³/3 (§213)
    assert _statuses("euler-192-219", {"rect-K"})["rect-K"] == "sampled"
    assert _statuses("euler-192-219", {"rect-K"}, "rect-K", lambda v: v * sp.Rational(3, 5))["rect-K"] == "refuted"


def test_a_stated_integral_in_theta_holds_and_a_slip_in_it_is_refuted():
    # U2 = ∫_0^b y² √(b²-y²) dy = π b⁴/16, stated with its form under y = b sin θ between
    assert _statuses("euler-220-228", {"U2"})["U2"] == "sampled"
    assert _statuses("euler-220-228", {"U2"}, "U2", lambda v: 2 * v)["U2"] == "refuted"


def test_the_integrands_written_for_integration_are_those_of_the_strips():
    y = statements("euler-220-228").get_step("U0").claim[1].variables[0]
    assert _statuses("euler-220-228", {"integrands"})["integrands"] == "sampled"
    slipped = _statuses("euler-220-228", {"integrands"}, "integrands",
                        lambda m: m + sp.Matrix([y] + [0] * (m.rows - 1)))
    assert slipped["integrands"] == "refuted"


def test_stated_roots_hold_and_a_slip_in_one_is_refuted():
    # the density roots s_-, s_+ of 12 s (1 - s) = (a/b)^2: density-factor puts them back
    roots = {"density-roots", "density-roots-lower", "density-factor"}
    assert _statuses("scheeffer-vi-ab", roots)["density-factor"] == "sampled"
    slipped = _statuses("scheeffer-vi-ab", roots, "density-roots", lambda v: v + sp.Rational(1, 100))
    assert slipped["density-factor"] == "refuted"
    # (a/b)^2 = 3/2 (1 - s)(9 s - 1) of Q60: Q60-check puts it back into t_1^2 = (top limit)^2 at omega = 60 deg
    s = statements("scheeffer-vi-ab").get_step("Q60").claim.rhs.free_symbols.pop()
    assert _statuses("scheeffer-vi-ab", {"Q60", "Q60-check"})["Q60-check"] == "sampled"
    slipped = _statuses("scheeffer-vi-ab", {"Q60", "Q60-check"}, "Q60", lambda v: v.subs(s, s + sp.Rational(1, 50)))
    assert slipped["Q60-check"] == "refuted"


def _reading_verdict(derivation_id, name, slip=None):
    """The verdict on the printed formula *name* checked by sampling alone, its first member replaced by
    ``slip(first member)``."""
    d = statements(derivation_id)
    [p] = [p for p in d.printed if p.name == name]
    if slip is not None:
        p = dataclasses.replace(p, reading=(slip(p.reading[0]), *p.reading[1:]))
    report = check_derivation(dataclasses.replace(d, steps=[], printed=[p], witnesses=[]), prove=False)
    return report.formulas[0].verdict


def test_a_stated_root_count_holds_and_a_slip_in_it_is_refuted():
    # Scheeffer IX states the count of the real roots of (136) at s = 73/100, n = 2 in z > 0 unevaluated
    # (the check counts it): one; on the whole line it has two (-0.9537 and 0.4049, nroots), so the slip is refuted
    assert _reading_verdict("scheeffer-ix", "monotone-one") == "verified"
    widened = _reading_verdict("scheeffer-ix", "monotone-one",
                               lambda c: c.func(c.args[0], c.args[1], -sp.oo, c.args[3], evaluate=False))
    assert widened == "erratum"            # refuted: the count stated no longer matches the print's one
