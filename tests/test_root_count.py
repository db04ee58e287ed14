"""symfloat.engine.root_count: real roots in an interval counted from polyroots and inclusion discs.

Expected counts come from the factored polynomials written in each test (roots read off the factors)."""
import mpmath
import pytest

from symfloat.engine.root_count import count_real_roots

INF = mpmath.inf


def coefficients(*roots, lead=1):
    """The coefficients (highest power first) of lead * prod (x - r) for the given real or complex roots."""
    c = [mpmath.mpf(lead)]
    for r in roots:
        c = [a - r * b for a, b in zip(c + [0], [0] + c)]
    return [mpmath.mpf(mpmath.re(v)) for v in c]


@pytest.mark.parametrize("dps", [15, 30])
def test_a_cubic_with_known_roots(dps):
    with mpmath.workdps(dps):
        cubic = coefficients(-2, mpmath.mpf(1) / 3, 5)          # (x + 2)(x - 1/3)(x - 5)
        assert count_real_roots(cubic, -INF, INF)[0] == 3
        assert count_real_roots(cubic, 0, INF)[0] == 2
        assert count_real_roots(cubic, -3, 1)[0] == 2
        assert count_real_roots(cubic, 1, 4)[0] == 0
        count, radius = count_real_roots(cubic, -1, 1)
        assert count == 1 and 0 < radius < mpmath.mpf(10) ** (5 - dps)


def test_complex_roots_are_not_counted():
    with mpmath.workdps(15):
        # (x - 1)(x^2 + 2x + 5): roots 1, -1 +- 2i
        assert count_real_roots(coefficients(1, -1 + 2j, -1 - 2j), -INF, INF)[0] == 1
        # a pair 1e-4 off the axis is told from a double root at 15 digits; 1e-6 off it is not: the coefficients'
        # rounding (1e-13 of their size, 16) moves a double root by sqrt(2e-12) ~ 1.4e-6
        assert count_real_roots(coefficients(2 + 1e-4j, 2 - 1e-4j), -INF, INF)[0] == 0
        assert count_real_roots(coefficients(2 + 1e-6j, 2 - 1e-6j), -INF, INF)[0] is None


def test_two_close_real_roots_are_parted_only_where_the_precision_allows():
    # (x - 1)(x - 1 - 1e-20): apart by 1e-20; a rounding of the coefficients by 10^(2 - dps) moves them by about
    # 10^(1 - dps/2): 15 and 40 digits cannot part them, 50 digits can
    for dps in (15, 40):
        with mpmath.workdps(dps):
            assert count_real_roots(coefficients(1, 1 + mpmath.mpf(10) ** -20), -5, 5)[0] is None
    with mpmath.workdps(50):
        assert count_real_roots(coefficients(1, 1 + mpmath.mpf(10) ** -20), -5, 5)[0] == 2


@pytest.mark.parametrize("dps", [15, 30])
def test_a_double_root_or_a_root_on_an_end_is_undecided(dps):
    with mpmath.workdps(dps):
        assert count_real_roots(coefficients(1, 1, -2), -INF, INF)[0] is None       # (x - 1)^2 (x + 2)
        assert count_real_roots(coefficients(1, 1, -2), -3, 0)[0] == 1              # the double root outside
        assert count_real_roots(coefficients(0, 3), 0, 4)[0] is None                 # 0 on the open end
        assert count_real_roots(coefficients(0, 3), -1, 4)[0] == 2


def test_degenerate_polynomials():
    with mpmath.workdps(15):
        assert count_real_roots([0, 0, 2], -INF, INF) == (0, 0)                     # a nonzero constant
        assert count_real_roots([0, 2, -1], 0, 1)[0] == 1                           # 2x - 1, leading zero dropped
        with pytest.raises(ValueError):
            count_real_roots([0, 0], -1, 1)
