"""Float64 closed forms of Scheeffer IX.B: the stable forms stay within 1e-13 relative of a 50-digit
evaluation across 23/32 < s < 1, where the printed forms lose most of their digits near the ends."""
import math

from symfloat.numerics.parallelepiped import QUANTITIES, error_table, printed, reference, stable


def test_stable_forms_within_1e_13_everywhere():
    table = error_table()
    worst = max(v[1] for row in table.values() for v in row.values())
    assert worst < 1e-13


def test_stable_forms_on_a_dense_grid():
    for k in range(1, 400):
        s = 23 / 32 + (1 - 23 / 32) * k / 400
        st, ref = stable(s), reference(s)
        for q in QUANTITIES:
            assert abs(st[q] - float(ref[q])) <= 1e-13 * abs(float(ref[q])), (s, q)


def test_printed_forms_are_stiff_at_the_ends():
    table = error_table()
    near_threshold = [row for s, row in table.items() if 0 < s - 23 / 32 < 1e-4]
    near_one = [row for s, row in table.items() if 0 < 1 - s < 1e-8]
    assert max(r["S-2"][0] for r in near_threshold) > 1e-1        # S - 2 from (151): total cancellation
    assert max(r["n1"][0] for r in near_threshold) > 1e-10        # sqrt(S^2 - 4) cancels as S -> 2
    assert min(r["n2"][0] for r in near_one) > 1e-3               # (S - sqrt(S^2 - 4))/2 as S -> infinity
    assert max(r["1-z1"][0] for r in near_one) > 1e-8             # 7 - 3t - 3 sqrt((5-t)(1-t)) -> 0
    assert max(r["n1"][0] for s, r in table.items() if abs(s - 119 / 128) < 1e-8) > 1e-10   # 0/0 at t = 0


def test_forms_agree_where_nothing_is_stiff():
    s = 0.85
    p, st = printed(s), stable(s)
    assert all(abs(p[q] - st[q]) < 1e-12 * abs(st[q]) for q in QUANTITIES)


def test_removable_singularity_at_t_zero():
    # s = 119/128 is t = 0: (151) divides 0 by 0, the stable form gives S - 2 = 1
    st = stable(119 / 128)
    assert abs(st["S-2"] - 1) < 1e-15 and math.isfinite(st["n1"])
