"""Typeset names of symbols (symfloat/model/symbol_names.py): the translation of program names and the
names a derivation gives.  Expected TeX is what the issue asks a reader to see (tan²φ₁, tan φ_lim45, Q₆₀ lower)
or the standard TeX spelling of the name's parts."""
from __future__ import annotations

import pytest
import sympy as sp

from symfloat.model.claim import as_latex
from symfloat.model.symbol_names import latex, symbol, tex_name


@pytest.mark.parametrize("name, tex", [
    ("tan^2varphi_1", r"\tan^{2}\varphi_{1}"),             # Scheeffer VI.C's tan^2 phi_1
    ("tanvarphi_lim45", r"\tan\varphi_{\lim 45}"),
    ("cot^2varphi_3", r"\cot^{2}\varphi_{3}"),
    ("Q60-lower", r"Q_{60}^{\text{lower}}"),               # Scheeffer VI.A-B's boundary with the lower base
    ("S_omegac", r"S_{\omega c}"),
    ("T_1(omega)", r"T_{1}(\omega)"),
    ("L_bot^C", r"L_{\text{bot}}^{C}"),
    ("E_0^{hasab}", r"E_{0}^{\text{hasab}}"),
    ("varphi_1", r"\varphi_{1}"),                           # SymPy's own spelling, kept
    ("x", "x"),
])
def test_program_names_are_translated(name, tex):
    assert tex_name(name) == tex


def test_a_name_that_is_tex_already_keeps_sympys_printing():
    assert tex_name(r"\mathbf{A}") is None and tex_name(r"|\vec{n}|^2") is None
    assert latex(sp.Symbol(r"\mathbf{A}")) == sp.latex(sp.Symbol(r"\mathbf{A}"))


def test_the_library_prints_every_symbol_under_its_name():
    t, q = sp.Symbol("tan^2varphi_1"), sp.Symbol("Q60-lower")
    shown = latex(t + q ** 2)
    assert r"\tan^{2}\varphi_{1}" in shown and r"Q_{60}^{\text{lower}}" in shown
    assert "varphi}" not in shown and "2varphi" not in shown        # SymPy alone prints tan^{2varphi}_{1}
    assert r"\tan^{2}\varphi_{1}" in as_latex(sp.Eq(t, 1, evaluate=False))


def test_a_derivation_names_a_symbol_where_it_makes_it():
    v = symbol("Vtest_wedge-volume", r"V_{\triangle}")
    assert latex(2 * v) == r"2 V_{\triangle}" and tex_name("Vtest_wedge-volume") == r"V_{\triangle}"
    with pytest.raises(ValueError):
        symbol("Vtest_wedge-volume", r"V_{w}")                  # one name, one typeset form
