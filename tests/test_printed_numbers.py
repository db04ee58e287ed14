"""A printed number's tolerance follows from its printed digits: half a unit of the last one."""
import pytest
import sympy as sp

from symfloat import PRINTED_DIGITS, Derivation
from symfloat.engine.check import check_derivation
from symfloat.model.derivation import printed_tolerance

s = sp.Symbol("s", positive=True)
# scheeffer X, verbatim: "(172) ... oder < 0,7735"; the threshold is (4 + sqrt 2)/7 = 0.77346...
EXCERPT = r"\frac{4 + \sqrt{2}}{7} \quad \text{oder} < 0,7735"


def test_half_a_unit_of_the_last_printed_digit():
    assert printed_tolerance(EXCERPT, (s, sp.Rational("0.7735"))) == sp.Rational(1, 20000)
    # scheeffer VI.B Example 7: "0,4 + \sqrt{0,06} = 0,645": the stated value decides, not 0,4
    assert printed_tolerance(r"$$0,4 + \sqrt{0,06} = 0,645$$", (s, sp.Rational("0.645"))) == sp.Rational(1, 2000)


def test_a_number_the_reading_does_not_state_is_refused():
    # mutation: the reading says 0.7736, which the excerpt does not print
    with pytest.raises(ValueError, match="no decimal number of the excerpt"):
        printed_tolerance(EXCERPT, (s, sp.Rational("0.7736")))


def _check(printed):
    d = Derivation(id="test-printed", source="scheeffer", title="172", locator="X", domain={})
    d.step("threshold", (s, (4 + sp.sqrt(2)) / 7), "definition", result=s)
    p = d.quote("172-number", "X (172)", EXCERPT, reading=(s, sp.Rational(printed)), tolerance=PRINTED_DIGITS)
    return p, check_derivation(d).formulas[0]


def test_the_quote_takes_the_tolerance_and_the_engine_judges_with_it():
    p, f = _check("0.7735")
    assert p.tolerance == sp.Rational(1, 20000) and f.verdict == "verified"
