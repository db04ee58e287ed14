"""Neville's table at 0 (symfloat/engine/extrapolation.py), shared by the definition route's limits and the
floating witnesses' limits in their tilt."""
from fractions import Fraction

from symfloat.engine.extrapolation import at_zero, neville_row


def test_the_polynomial_through_the_nodes_is_read_at_zero_exactly():
    # f(h) = 3 - 2h + 5h^2: three nodes give its constant term 3 exactly (rational arithmetic); two nodes give the
    # line through them, 3 - 2h + 5h^2 at h = 1, 1/2 is 6, 13/4, whose line meets 0 at 1/2, not 3
    f = lambda h: 3 - 2 * h + 5 * h * h
    nodes = [Fraction(1), Fraction(1, 2), Fraction(1, 4)]
    assert at_zero(nodes, [f(h) for h in nodes]) == 3
    assert at_zero(nodes[:2], [f(h) for h in nodes[:2]]) == Fraction(1, 2)


def test_a_row_grows_by_one_estimate_per_node():
    nodes, row = [], []
    for h in (Fraction(1, 3), Fraction(1, 5), Fraction(1, 9)):
        nodes.append(h)
        row = neville_row(nodes, row, 7 + h)              # a line: exact from the second node on
        assert len(row) == len(nodes)
    assert row[1:] == [7, 7] and row[0] == 7 + Fraction(1, 9)
