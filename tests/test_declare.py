"""symfloat.engine.declare: a module's cases by parameter name (decimals exact), its witnesses and parts with its
defaults, a field given at the call overriding the module's."""
import pytest
import sympy as sp

from symfloat.engine.declare import cases_of, declarer, part_of
from symfloat.engine.floating_witness import Body, FloatingWitness
from symfloat.engine.measured import measured


class _Derivation:
    def __init__(self):
        self.witnesses = []

    def witness(self, w):
        self.witnesses.append(w)


def test_cases_are_exact_and_named_by_their_parameters():
    a, s = sp.symbols("a s", positive=True)
    case = cases_of(a, s)
    c = case("a = 11/10, s = 0.3", a="1.1", s="0.3")
    assert c.params == {a: sp.Rational(11, 10), s: sp.Rational(3, 10)} and c.data is None
    box = Body.box(1, 1, 1)
    assert case("own body", box, a=1).data == {"body": box}
    with pytest.raises(ValueError, match="rho"):
        case("a typo", rho="0.3")


def test_declared_witnesses_take_the_module_defaults_unless_told():
    s = sp.Symbol("s", positive=True)
    d = _Derivation()
    floating = declarer(d, FloatingWitness, body=Body.box(2, 1, 1), density=s)
    floating("draught", "", ("t",), (), measured("draught"))
    floating("lying", "", ["t"], (), measured("draught"), up=(0, 1, 0))
    first, second = d.witnesses
    assert first.up == (0, 0, 1) and second.up == (0, 1, 0) and second.targets == ("t",)
    assert first.body == second.body == Body.box(2, 1, 1) and first.density == s
    part = part_of(FloatingWitness, body=Body.box(2, 1, 1), density=s)
    p = part(quantity=measured("draught"), density=sp.Rational(1, 2))
    assert (p.name, p.targets, p.cases, p.density) == ("", (), (), sp.Rational(1, 2))
