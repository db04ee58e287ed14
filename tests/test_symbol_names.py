"""Typeset names of symbols (symfloat/model/symbol_names.py): the translation of program names and the
names a derivation gives.  Expected TeX is what the issue asks a reader to see (tan²φ₁, tan φ_lim45, Q₆₀ lower)
or the standard TeX spelling of the name's parts."""
from __future__ import annotations

import re

import pytest
import sympy as sp

from symfloat import registry
from symfloat.model.claim import as_latex, expressions
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


# What a reader would read as a product of italic letters or a program's abbreviation once the commands and
# the upright words are set: a digit run into letters in a braced index (V_{3cx 3}: V_3 x_3 of VIII; T_{1n}),
# or two letters or more that are not points of a figure.  Points are capitals with at most the lower-case
# letters Euler gives points (Cc, Nn, Pp in §202 and §217; the triangle Ace of §§220-228); uv and xy index a
# product moment (Scheeffer's P_xy, I_uv), df is Scheeffer's element of area; in Euler's integrals (§§220-228)
# dx, dy, dY are differentials and a doubled letter is his square (bb - yy for b² - y², cyy for c y²).
_RUN = re.compile(r"(?<![_^])\d+[A-Za-z]+|[A-Za-z]{2,}")
_READABLE = re.compile(r"[A-Z][A-Za-z]*|uv|xy|df|d[xyY]|[a-z]?([a-z])\1")


def _unreadable(tex: str) -> list[str]:
    """The runs of *tex*, a symbol's typeset name, that a reader cannot read as mathematics."""
    bare = re.sub(r"\\(?:text|operatorname|mathrm)\{[^{}]*\}|\\[A-Za-z]+", " ", tex)
    return [run for run in _RUN.findall(bare) if not _READABLE.fullmatch(run)]


def _symbols(derivation: str) -> set:
    """Every symbol the derivation's statements make or its steps and quotes use."""
    d = registry.statements(derivation)
    made = {v for v in vars(registry.part(derivation, "statements")).values() if isinstance(v, sp.Symbol)}
    claims = [s.claim for s in d.steps] + [p.reading for p in d.printed]
    claims += [p.erratum.corrected_reading for p in d.printed if p.erratum is not None]
    used = {s for c in claims if c is not None for m in expressions(c) if hasattr(m, "atoms")
            for s in m.atoms(sp.Symbol)}
    return made | used


def test_the_check_of_a_name_sees_a_program_name():
    # the typeset names the rules gave before the derivations named these symbols (V_3cx_3, uD_t,
    # tanvarphi_la, T_1n, D_{sq}); a name of points or an index written out is read
    assert _unreadable(r"V_{3cx 3}") == ["3cx"] and _unreadable(r"uD_{t}") == ["uD"]
    assert _unreadable(r"\tan\varphi_{la}") == ["la"] and _unreadable(r"T_{1n}") == ["1n"]
    assert _unreadable(r"D_{sq}") == ["sq"]
    assert _unreadable(r"A_{IG_1H_1}") == _unreadable(r"I_{Ace}") == _unreadable(r"GM_{c}") == []
    assert _unreadable(r"(V_{3} x_{3})^{\text{VIII}}") == _unreadable(r"\tan\varphi_{\lim 45}") == []
    assert _unreadable(r"{\int_{0}^{b} \left(a - \tfrac{cyy}{bb}\right) dy \sqrt{bb-yy}}") == []   # Euler §227
    assert _unreadable(r"{\int_{0}^{b} y\,dz \sqrt{bb-yz}}") == ["dz", "yz"]


@pytest.mark.parametrize("derivation", registry.ids())
def test_every_symbol_of_the_library_has_a_name_a_reader_can_read(derivation):
    shown = {s.name: tex_name(s.name) for s in _symbols(derivation)}
    bad = {name: tex for name, tex in shown.items() if tex is not None and _unreadable(tex)}
    assert not bad, bad
