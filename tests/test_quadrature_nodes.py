"""The Gauss–Legendre nodes from FLINT are mpmath's own to the working precision, and the rule built on them
integrates as mpmath's does."""
import mpmath
import pytest
from mpmath.calculus.quadrature import GaussLegendre

from symfloat.engine.quadrature import ArbGaussLegendre, gauss_legendre


@pytest.mark.parametrize("degree, prec", [(1, 53), (3, 120), (5, 200)])
def test_the_nodes_and_weights_are_mpmaths(degree, prec):
    with mpmath.workprec(prec + 20):           # as mpmath's get_nodes calls calc_nodes
        ours = sorted(ArbGaussLegendre(mpmath.mp).calc_nodes(degree, prec))
        theirs = sorted(GaussLegendre(mpmath.mp).calc_nodes(degree, prec))
        assert len(ours) == len(theirs) == 3 * 2 ** (degree - 1)
        # mpmath's Newton steps stop at 2^-(prec+8); FLINT's roots are correct to the working precision
        assert all(abs(x - y) + abs(v - w) <= mpmath.ldexp(1, -prec) for (x, v), (y, w) in zip(ours, theirs))


def test_the_rule_is_exact_for_a_polynomial_of_its_degree_and_shares_its_nodes():
    # 3 nodes integrate x^5 exactly: int_0^2 x^5 dx = 64/6
    with mpmath.workdps(30):
        value = mpmath.quad(lambda x: x ** 5, [0, 2], method=gauss_legendre, maxdegree=1)
        assert abs(value - mpmath.mpf(64) / 6) < mpmath.mpf(10) ** -28
        assert gauss_legendre(mpmath.mp) is gauss_legendre(mpmath.mp)      # nodes computed once per process
        assert any(degree == 1 for degree, _ in gauss_legendre(mpmath.mp).standard_cache)
