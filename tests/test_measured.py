"""One placeholder for every witness kind (symfloat.engine.measured): a measured quantity is named in words,
is no parameter of the same name, and a name a kind does not measure is refused when the witness is declared
(expected values: a unit cube floating at density 1/2 has the draught 1/2 and the immersed volume 1/2)."""
import pytest
import sympy as sp

from symfloat.engine.figure_witness import Figure, FigureWitness
from symfloat.engine.floating_witness import Body, Combined, FloatingWitness
from symfloat.engine.measured import Measured, measured, numbered
from symfloat.engine.witness import Case, PlaneSections

x, y, z, t = sp.symbols("x y z t")
ONE = (Case({}, label="unit cube"),)


def _cube(quantity, density=sp.Rational(1, 2)):
    return FloatingWitness("", "", (), ONE, body=Body.box(1, 1, 1), density=density, quantity=quantity)


def test_a_measured_quantity_is_a_word_and_no_parameter():
    assert measured("immersed volume").name == "immersed volume"
    assert measured("draught") != sp.Symbol("draught")
    assert numbered("part", 2) == (measured("part 1"), measured("part 2"))
    assert isinstance(measured("centroid, 1"), Measured)
    with pytest.raises(ValueError):
        measured("")
    with pytest.raises(ValueError):
        measured("draught", of=x)                     # only an integral takes an integrand


def test_a_floating_quantity_has_one_spelling():
    # the bare string is refused wherever a floating quantity is named: alone, in a tuple, a root's, a guard's
    from symfloat.engine.floating_witness import At, Difference, Root
    for wrong in ("draught", (measured("draught"), "immersed volume")):
        with pytest.raises(ValueError, match=r"measured\('(draught|immersed volume)'\)"):
            _cube(wrong)
    with pytest.raises(ValueError, match="measured"):
        Root("face clearance", x, (0, 1))
    with pytest.raises(ValueError, match="measured"):
        Root(measured("face clearance"), x, (0, 1), guard=("top clearance",))
    with pytest.raises(ValueError, match="measured"):
        At("G above B", {x: 0})
    with pytest.raises(ValueError, match="measured"):
        Difference("I max", x, 1)
    assert _cube(measured("draught")).quantity == measured("draught") == FloatingWitness(
        "", "", (), ONE, body=Body.box(1, 1, 1), density=sp.Rational(1, 2)).quantity      # the default


def test_each_kind_reads_its_names_and_refuses_the_others():
    w = _cube(2 * measured("immersed volume") - measured("draught"))
    assert float(w.measure(w.instances[0], w.methods[0])) == pytest.approx(0.5, abs=1e-12)
    with pytest.raises(ValueError, match="unknown quantity"):
        _cube(measured("part 1"))
    parts = (_cube(measured("draught")), _cube(measured("draught"), sp.Rational(1, 4)))
    both = Combined("both", "", (), ONE, parts=parts, values=(measured("part 1") - measured("part 2"),))
    assert float(both.measure(both.instances[0], both.methods[0])) == pytest.approx(0.25, abs=1e-12)
    with pytest.raises(ValueError, match="part 3"):
        Combined("three", "", (), ONE, parts=parts, values=(measured("part 3"),))
    square = Figure.polygon([(0, 0), (1, 0), (1, 1), (0, 1)])
    with pytest.raises(ValueError, match="immersed volume"):
        FigureWitness("f", "", (), ONE, figure=square, coords=(x, y), quantity=measured("immersed volume"))
    with pytest.raises(ValueError, match="part 1"):
        FigureWitness("f", "", (), ONE, figure=square, coords=(x, y),
                      quantity=measured("integral", of=x * measured("part 1")))
    f = FigureWitness("f", "", (), ONE, figure=square, coords=(x, y),
                      quantity=measured("integral", of=(x - measured("centroid, 1")) ** 2))
    assert float(f.measure(f.instances[0], f.methods[0])) == pytest.approx(1 / 12, abs=1e-12)
    planes = dict(width=sp.Integer(1), position=z, across=t, chord=(0, 1), planes=(0, 1))
    s = PlaneSections("s", "", (), ONE, combine=measured("section 1") + measured("section 2"), **planes)
    assert float(s.measure(s.instances[0], s.methods[0])) == pytest.approx(2, abs=1e-12)
    s3 = PlaneSections("s", "", (), ONE, combine=measured("section 3"), **planes)
    with pytest.raises(ValueError):
        s3.measure(s3.instances[0], s3.methods[0])
