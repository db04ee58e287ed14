"""The words of the derivation notebooks (symfloat/prose.py): the ASCII mathematics of a derivation's
notes, witnesses and errata typeset so that a Greek letter or a function is its sign, never its name set as
italic letters, and the "About this section" text without the names of the program."""
from __future__ import annotations

import inspect
import re
from pathlib import Path

import nbformat
import pytest

from symfloat import registry
from symfloat.model.symbol_names import GREEK
from symfloat.registry import load
from symfloat.report.notebook_view import reading_markdown, step_title
from symfloat.prose import displayed, typeset, without_program_names

ROOT = Path(__file__).resolve().parents[1]

# the names the site's browser test looks for as runs of italic letters in a formula (tests/test_site.py)
_NAMES = sorted([g for g in GREEK if g[0].islower()] + ["sin", "cos", "tan", "cot", "tg", "log", "lim"],
                key=len, reverse=True)
_BARE = re.compile("(" + "|".join(_NAMES) + ")")
_MATH = re.compile(r"\$\$(.+?)\$\$|\$([^$\n]+?)\$", re.S)


def _bare_names(markdown: str) -> list[str]:
    """The runs of letters in the formulas of *markdown* that spell a Greek letter or a function: what KaTeX
    sets as italic letters once the commands and the upright words are set."""
    found = []
    for m in _MATH.finditer(markdown):
        letters = re.sub(r"\\(?:text|operatorname|mathrm)\{[^{}]*\}|\\[A-Za-z]+", " ", m.group(1) or m.group(2))
        found += [run for run in re.findall(r"[A-Za-z]+", letters) if _BARE.search(run)]
    return found


def test_the_check_sees_a_name_set_as_letters():
    # what the Scheeffer VI.A-B and VI.C-F notebooks showed before (found by the browser test)
    assert _bare_names(r"B = (M_xi, $M_{eta}$) and $\tan^{2} \varphi_{lim}$") == ["eta", "lim"]
    assert _bare_names(r"$\int_{0}^{alpha} 2 \sin t\,dt$ and $I_{\text{rhomb}}$") == ["alpha"]
    assert all(_DOUBLE.search(t) for t in ("y^{2}^{n}", "J_{1K}_{1}", "x_{3}^{1}'")) and not _DOUBLE.search("y^{2n}")


@pytest.mark.parametrize("text, tex", [
    ("B = (M_xi, M_eta, M_z)/V_t", r"$B = (M_{\xi}, M_{\eta}, M_{z})/V_{t}$"),   # Scheeffer VI.A-B: one formula
    ("S_omega = sin^2(45 deg + omega*)", r"$S_{\omega} = \sin^{2}(45 ^{\circ} + \omega^{*})$"),   # VI.C-F (78d)
    ("(tan^2 phi_lim(45 deg) - tan^2 phi_1)/2", r"\varphi_{\lim}(45 ^{\circ})"),
    ("= int_0^alpha 2 sin t (t - sin t) dt > 0", r"\int_{0}^{\alpha}"),
    ("I_rhomb = ab^3/3", r"I_{\text{rhomb}}"),                        # Euler §§192-219, rhombus-twice: not rho·m·b
    ("tg^2 phi_1 = -2 V_1 h_A / T_1", r"\operatorname{tg}^{2} \varphi_{1}"),     # Scheeffer's German tangent
    ("dT_mu/dmu of the tensor", r"dT_{\mu}/d\mu"),                    # Scheeffer VII-VIII (108)
    ("w = (cos phi, sin phi) in the plane", r"$w = (\cos \varphi, \sin \varphi)$"),   # both, one formula
    # Scheeffer IX: an equation number is the source's, not a factor (read "6s(1-s)(123)" and "2(164a - 166)")
    ("(a/b)^2 > 6s(1 - s) (123); cot^2 phi_3 = 2 (164a-166)", r"$(a/b)^{2} > 6s(1 - s)$ (123)"),
    ("cot^2 phi_3 = 12(a/b)^2 s(1-s) - 2 (164a-166), and x = D/(2a)", r"- 2$ (164a-166), and $x = D/(2a)$"),
    # two equation numbers joined by a slash (Scheeffer VI.C-F's "(77)/(78a)") name two places, not a quotient
    ("its bounds are those of (77)/(78a), (1 - s)(7s - 1) for s > 1/2", "those of (77)/(78a), $(1 - s)(7s - 1)"),
    # Euler §§229-243 writes κ, ⁿ and braced exponents: one formula each, not pieces between words
    ("x = a + Y ± a(1 − yⁿ/bⁿ)^κ", r"$x = a + Y \pm a(1 - y^{n}/b^{n})^{\kappa }$"),
    ("Y = c_1 yⁿ/bⁿ + c_2 y²ⁿ/b²ⁿ", r"y^{2n}/b^{2n}$"),
    ("y = b t^{1/n} turns it into b^{p+1}/n", r"$y = b t^{1/n}$"),
    ("int_{1/2 - c}^{1/2} z dz = (c - c^2)/2", r"$\int_{1/2 - c}^{1/2} z dz"),       # Scheeffer X, moment-z
    ("J_1K_1 and x_3^1'", r"$J_{1}K_{1}$ and $x_{3}^{1\prime}$"),                  # VII-VIII: no double index
    ("x^1_3' and I^rect_1'", r"$x^{1\prime}_{3}$ and $I^{\text{rect}\prime}_{1}$"),   # the exponent's prime, not the index's
])
def test_greek_names_and_functions_are_signs(text, tex):
    shown = typeset(text)
    assert tex in shown and not _bare_names(shown), shown


def _texts(derivation: str):
    """Every text of the derivation its notebook typesets: summary, assumptions, the About section, the notes
    of steps and printed formulas, the errata's evidence and the witnesses' descriptions."""
    d, module = load(derivation)
    yield "about", without_program_names(inspect.cleandoc(module.__doc__ or ""))
    yield "summary", d.summary
    yield from (("assumption", a) for a in d.assumptions)
    yield from ((f"step {s.name}", s.note) for s in d.steps if s.note)
    yield from ((f"note {p.name}", p.note) for p in d.printed if p.note)
    yield from ((f"erratum {p.name}", p.erratum.evidence) for p in d.printed
                if p.erratum is not None and p.erratum.evidence)
    yield from (("witness", w.description) for w in d.witnesses)


@pytest.mark.parametrize("text, shown", [
    # a segment named by its two points is a name inside a formula (Euler §§192-219's notes, Scheeffer X's BH)
    ("M (GZ - phi GM)/phi^3 of the heeled box", r"$M (GZ - \varphi GM)/\varphi^{3}$ of the heeled box"),
    ("the distance BH = ρ < a", r"the distance $BH = \rho < a$"),
    ("EF lies at the distance Cc = (c - a)/3 from ef", r"EF lies at the distance $Cc = (c - a)/3$ from ef"),
    # a sum, difference or quotient of letters is a formula without a Greek letter or an index (Scheeffer IX)
    ("n + 1/n, the same at both double roots", r"$n + 1/n$, the same at both double roots"),
    # much greater than (Hasab's long prism): a relation, not two signs ">" set side by side
    ("length l >> 1, water density 1", r"length $l \gg 1$, water density 1"),
    ("z_+ - z_-, 4 z_+ - 3 at the roots", r"$z_+ - z_-$, $4 z_+ - 3$ at the roots"),
    # a product written with a dot, a Python power and a comma inside a formula's bracket
    ("the product u.(G - B)", r"the product $u\cdot(G - B)$"),
    ("the moment is (2*a**2)/6", r"the moment is $(2\cdot a^{2})/6$"),
    ("'sqrt{2}^1': a stray mark", r"'$\sqrt{2}^{1}$': a stray mark"),
    ("its derivative is (du/dtheta).(G - B)", r"its derivative is $(du/d\theta)\cdot(G - B)$"),
    ("b^{p+1}/n · B((p+1)/n, q+1), the Beta function", r"$b^{p+1}/n \cdot B((p+1)/n, q+1)$, the Beta function"),
    # what stays words: a segment alone, a chapter's numeral, a sign in brackets, a range of pages, a coordinate
    # pair of numbers, and a quotation of the source, kept verbatim; a point or a length named by one letter is a
    # formula of its own (it was left as a word before, the point M in roman type beside $BM$)
    ("from AB up to M, by Scheeffer IX and VI, sections I-III",
     "from AB up to $M$, by Scheeffer IX and VI, sections I-III"),
    ("G lies below (+) or above (-) B", "$G$ lies below (+) or above (-) $B$"),
    ("the slab a-c, (step e2-e3), (sign-of-P)", "the slab a-c, (step e2-e3), (sign-of-P)"),
    ("('Ac = a - c et Oc = c')", "('Ac = a - c et Oc = c')"),
    ("pages 3 - 5, the points (0, 0) and (G below, G above B)",
     "pages 3 - 5, the points (0, 0) and ($G$ below, $G$ above $B$)"),
    ("quoted in §3 ('zusammen fanden h/3{2D - (G+g)/2}'), so", "quoted in §3 ('zusammen fanden h/3{2D - (G+g)/2}'), so"),
    ("the rectangle's moments over the rhombus' (same a, b)",
     "the rectangle's moments over the rhombus' (same $a$, $b$)"),
    # the article is a word (a box, A opening a sentence, a before a formula), and so are a chapter's numeral, a
    # label, an abbreviation and the s of a possessive
    ("A box with edges a, b, c (density s) floats. A lies on B, the slab from a to c",
     "A box with edges $a$, $b$, $c$ (density $s$) floats. $A$ lies on $B$, the slab from $a$ to $c$"),
    ("A c read as o, a $Y$-dependent centroid, the scan confuses a and c",
     "A $c$ read as $o$, a $Y$-dependent centroid, the scan confuses $a$ and $c$"),
    ("Scheeffer 1902, X: rows I and V of (162); II. Body frame; case (b), i.e. Euler’s case",
     "Scheeffer 1902, X: rows I and V of (162); II. Body frame; case (b), i.e. Euler’s case"),
    ("x = (a + b) c, the x axis", "$x = (a + b) c$, the $x$ axis"),
    # two and three primes (Graefe §4's radii and slabs: y'' stayed a word beside $y'$)
    ("y, y', y'' are the radii; the v''' printed next", "$y$, $y'$, $y''$ are the radii; the $v'''$ printed next"),
    # a quotation holding a formula with a prime (Scheeffer IX.B's answer): its quote marks were read around '$F'
    # and the dollars after it paired wrongly, a sentence set as one formula
    ("its reason, '$F'(z)$ zunimmt', holds for $z < 0$, and", "its reason, '$F'(z)$ zunimmt', holds for $z < 0$, and"),
    # a relation sign in ASCII, alone or before a number, and a function's value (Graefe §2 and §3, Scheeffer VI.A-B
    # and VII-VIII): "degree <= 3", "the sections A(0), A(h)", "counts it with '>='" were words
    ("a polynomial of degree <= 3 in z; both terms >= 0", r"a polynomial of degree $\le 3$ in $z$; both terms $\ge 0$"),
    ("unsymmetric, k != 0; the sections A(0), A(h/2) of A(z)",
     r"unsymmetric, $k \ne 0$; the sections $A(0)$, $A(h/2)$ of $A(z)$"),
    ("(65) counts it with '>=' (the example >)", r"(65) counts it with '$\ge$' (the example $>$)"),
    # a sign that opens a formula after a word (Metazentrum's "b tg phi < d and < 2c - d", Scheeffer VI.C-F's
    # "> 0 stable, = 0 neutral", the quoted "'= 0'" of IV-V and VII-VIII): the sign and its number were words
    ("(b tg phi < d and < 2c - d); > 0 stable, = 0 neutral; the '= 0' is imposed",
     r"($b \operatorname{tg} \varphi < d$ and $< 2c - d$); $> 0$ stable, $= 0$ neutral; the '$= 0$' is imposed"),
    # an interval in brackets (Hasáb's body coordinates, Scheeffer IX's (79), Euler's rectangle): the brackets and
    # the numbers were words; a link, a citation and a code span stay as they are
    ("xi in [-1/2, 1/2], eta in [0, 1]", r"$\xi$ in $[-1/2, 1/2]$, $\eta$ in $[0, 1]$"),
    ("positive outside [s_1, s_2] (79)", r"positive outside $[s_{1}, s_{2}]$ (79)"),
    ("a rectangle [x_1, x_2] x [y_1, y_2] placed", r"a rectangle $[x_{1}, x_{2}] \times [y_{1}, y_{2}]$ placed"),
    ("the [notes](notes.html), [see, §4] and ``[-b s, b (1 - s)]``",
     r"the [notes](notes.html), [see, §4] and $[-b s, b (1 - s)]$"),
    # a product of dimensions written with ×, and a quotient of differentials (Metazentrum's box, Scheeffer IX's
    # base, Scheeffer X's dE/dt and IV-V's dT/dmu were words; "2a x 2b x 2c" read x as the variable)
    ("a homogeneous box 2a × 2b × 2c; the base a × c about",
     r"a homogeneous box $2a \times 2b \times 2c$; the base $a \times c$ about"),
    ("L - R = (positive factor) × dE/dt, dividing dT/dmu, do/die",
     r"$L - R$ = (positive factor) × $dE/dt$, dividing $dT/d\mu$, do/die"),
    # a name of three points after a function or before a relation (Euler's angle ACP, Scheeffer X's angle BHG) and a
    # segment's derivative (Scheeffer VI.C-F's GZ'), which cut their formulas in two; alone, or a numeral, words
    # a letter read for another (Euler §§220-228: "The a for x at the head of the line") is a name, not the article
    ("The a for x at the head of the line; a for all", "The $a$ for $x$ at the head of the line; a for all"),
    ("n = cos ACP = sqrt(1 - m^2), angle BHG = omega, E'' = GZ' = T_1; the arc AEB of section VII",
     r"$n = \cos ACP = \sqrt{1 - m^{2}}$, angle $BHG = \omega$, $E'' = GZ' = T_{1}$; the arc AEB of section VII"),
    # a chapter's numeral after a numbered formula (the errata's "formula 17 of X", Scheeffer X being the chapter) is
    # words, a letter after other words a name; an ASCII minus-or-plus (Scheeffer VI.A-B's 2r = b (0.4 -+ sqrt 0.06))
    # is its sign
    ("formula 17 of X and (171) of X; the value of X", "formula 17 of X and (171) of X; the value of $X$"),
    ("the roots 1/2 -+ sqrt(1/12) and 1/2 +- c", r"the roots $1/2 \mp \sqrt{1/12}$ and $1/2 \pm c$"),
    # Unicode indices and letter powers written against a name are the formula's (Euler's tan² φ₀ and K₀, the
    # integrals ∫₀ᵇ yᵖ), bars against what they hold are absolute values (Scheeffer X's |u_x| = |u_y|, IV-V's
    # |S S_2|) while a table's bars stand apart; an angle in words has its sign
    ("at tan² φ₀ = 2g, K₀ printed, ∫₀ᵇ yᵖ dy", r"at $\tan^{2} \varphi_{0} = 2g$, $K_{0}$ printed, $\int_{0}^{b} y^{p} dy$"),
    ("makes |u_x| = |u_y|; so e_2 = |S S_2| | K₀ rebuilt |",
     r"makes $|u_{x}| = |u_{y}|$; so $e_{2} = |S S_{2}|$ | $K_{0}$ rebuilt |"),
    ("at 45 deg (the negation), exact 20 deg 3' 34.50'', tan phi(45 deg)",
     r"at 45° (the negation), exact 20° 3' 34.50'', $\tan \varphi(45 ^{\circ})$"),
    ("the +- read through the square (Scheeffer VII-VIII's note)", "the ± read through the square (Scheeffer VII-VIII's note)"),
    # an x between numbers is a product (Euler §§192-219's witness "the box 1 x 1 x 2"), and the a before a number
    # the article
    ("a 3 x 3 grid, the box 1 x 1 x 2 by exact clipping, x = 2 x 3",
     r"a 3 × 3 grid, the box 1 × 1 × 2 by exact clipping, $x = 2 \times 3$"),
])
def test_formulas_and_words_are_told_apart(text, shown):
    assert typeset(text) == shown


# what TeX refuses: an index or exponent given twice (y^{2}^{n}, J_{1K}_{1}, x_{3}^{1}')
_DOUBLE = re.compile(r"\^\{[^{}]*\}(?:\^|')|_\{[^{}]*\}_")


@pytest.mark.parametrize("derivation", registry.ids())
def test_no_formula_of_a_notebooks_words_spells_a_greek_letter(derivation):
    shown = [(where, typeset(text)) for where, text in _texts(derivation)]
    bad = [(where, _bare_names(text)) for where, text in shown if _bare_names(text)]
    assert not bad, bad[:5]
    double = [(where, m.group(0)) for where, text in shown for math in _MATH.finditer(text)
              for m in [_DOUBLE.search(math.group(0))] if m]
    assert not double, double[:5]


def test_the_about_section_names_no_module_of_the_program():
    # Scheeffer VI.A-B's About: "clip the real polyhedra (symfloat.geometry.floating) and float the real
    # cylinder (Body.cylinder, quadrature of exact slices)"; IX's "(``crossing``)"; IV-V's steps by their slugs
    about = without_program_names("clip the polyhedra (symfloat.geometry.floating) and float the cylinder "
                                  "(Body.cylinder, quadrature of exact slices); to the water (``crossing``); "
                                  "(12) (section II, module ``scheeffer-i-iii``, steps ``moment-13``); on (``Omega``)")
    assert about == ("clip the polyhedra and float the cylinder (quadrature of exact slices); to the water; "
                     "(12) (section II); on (``Omega``)")
    for derivation in registry.ids():
        text = without_program_names(inspect.cleandoc(load(derivation)[1].__doc__ or ""))
        assert not re.search(r"symfloat\.|\(``[a-z]+_[a-z_]+``\)", text), derivation


def test_an_inequality_read_as_an_equation_says_so():
    # Hasáb's printed condition "rho^2 - rho + 1/6 > 0" is read as the equal signs of two margins, its remark's
    # "... < rho_viz" as the bound R_u; a formula printed as an equation is "read as printed"
    d, _ = load("hasab")
    shown = {p.name: reading_markdown(d, p) for p in d.printed}
    assert "The print states an inequality; it is read as the equation below" in shown["condition"]
    assert "The print states an inequality" in shown["remark"]
    said = {p.name for p in d.printed if "The print states an inequality" in shown[p.name]}
    equations = {p.name for p in d.printed if p.reading is not None and not re.search(r"[<>]|\\[lg]eq?\b", p.excerpt)}
    assert equations and not said & equations
    assert all("Read as printed:" in shown[name] for name in said | equations)     # the site finds the reading there


def test_a_dummy_named_like_a_symbol_gets_the_same_python_name_whatever_the_order():
    # Scheeffer IX swaps a and b (and a and c) through two dummies, both Dummy("k"): the names must not follow the
    # order of a set (the committed notebook read k_ in one process and k in another); a dummy beside a symbol of
    # its name comes after the symbol, two dummies in the order they were made
    import sympy as sp

    from symfloat.report.notebook_code import Code
    k, kd = sp.Symbol("k", positive=True), sp.Dummy("k", positive=True)
    names = [Code(order).names for order in ([k, kd], [kd, k])]
    assert names[0] == names[1] and names[0][k] == "k" and names[0][kd] == "k_"
    first, second = sp.Dummy("k"), sp.Dummy("k")
    names = [Code(order).names for order in ([first, second], [second, first])]
    assert names[0] == names[1] and names[0][first] == "k" and names[0][second] == "k_"


def test_a_dummy_is_declared_as_a_dummy_not_as_the_symbol_of_its_name():
    # Scheeffer IX's setup cell read "k_ = Symbol('k')" beside "k = symbols(...)": in the kernel k_ was k, so a
    # swap of a and b through k_ (Subs(e, (a, b, k_), (k_, a, b))) would also have turned every k of e into b
    import sympy as sp

    from symfloat.report.notebook_code import Code
    a, b, k, kd, lone = sp.Symbol("a"), sp.Symbol("b"), sp.Symbol("k"), sp.Dummy("k"), sp.Dummy("t", positive=True)
    code = Code([a, b, k, kd, lone])
    kernel: dict = {}
    exec("from sympy import Symbol, symbols, Dummy, Subs\n" + code.declarations(), kernel)   # noqa: S102 - code printed here
    ka, kk, t = kernel[code.names[kd]], kernel[code.names[k]], kernel[code.names[lone]]
    assert isinstance(ka, sp.Dummy) and ka != kk and ka.name == "k"
    assert isinstance(t, sp.Dummy) and t.is_positive and t != sp.Symbol("t", positive=True)
    A, B = kernel[code.names[a]], kernel[code.names[b]]
    assert sp.Subs(A * kk, (A, B, ka), (ka, A, B)).doit() == B * kk       # the swap leaves k alone


def test_a_label_before_its_formula_is_the_whole_title_and_a_cut_phrase_ends_with_an_ellipsis():
    # Scheeffer IV-V's step noted "area element: $df_2 = |dp/du x dp/dv| df = df/cos phi_1$" was titled "Area
    # element: …" (the note is longer than 70 characters and "area element" two words); Euler §§229-243's
    # "Euler's N: ∫dy(1 − y^n/b^n)^κ ..." likewise
    titles = {}
    for did in ("scheeffer-iv-v", "euler-229-243", "graefe-s4-applications"):
        d, _ = load(did)
        titles.update({s.note.strip()[:12].lower(): step_title(d, s) for s in d.steps if s.note})
    assert titles["area element"] == "Area element" and titles["euler's n: ∫"] == "Euler's $N$"
    assert not [t for t in titles.values() if t.endswith((":", ": …"))]
    # a long phrase with no label is still cut at a space and marked as cut
    assert titles["the factor b"].startswith("The factor $b c/a^{2}") and titles["the factor b"].endswith(" …")


def test_a_title_two_steps_share_does_not_point_to_its_own_step():
    # "Step 7: The formula agrees with the centroid by its definition (step 7)": 40 headings named their own number
    from symfloat.report.notebook_view import step_titles
    d, _ = load("graefe-s4-applications")
    titles = step_titles(d)
    shared = [s.name for s in d.steps if step_title(d, s) == "The formula agrees with the centroid by its definition"]
    assert len(shared) > 1 and not any("(step" in titles[name] for name in shared)


def test_a_ratios_colon_does_not_end_a_title():
    # Euler §213's proportion "I : K = EF^2 : AB^2" was titled "§213: I : K = EF²" (and a space), half of it
    d, _ = load("euler-192-219")
    step = next(s for s in d.steps if s.note.startswith("§213: I : K"))
    assert step_title(d, step) == "§213: $I : K = EF^{2} : AB^{2}$"        # a ratio's colon inside the formula


def test_no_markdown_cell_shows_a_line_as_code():
    # Graefe §4's "About this section" indented its formulas, and Markdown showed them as code, TeX as written
    indented = [(path.name, line) for path in sorted((ROOT / "notebooks").glob("*.ipynb"))
                for cell in nbformat.read(path, as_version=4).cells if cell.cell_type == "markdown"
                for line in cell.source.splitlines() if re.match(r"( {4,}|\t)\S", line)]
    assert not indented, indented[:3]
    about = displayed(typeset(inspect.cleandoc(load("graefe-s4-ship-centroid")[1].__doc__)))
    assert "$$X V = m^{2}/3" in about and not re.search(r"^ {4}", about, re.M)


def test_the_about_text_shows_no_code():
    # Graefe §§2-4 showed ``a, b, c, d, e, f, g``, ``2m``, ``ABC`` and a derivation's id as code, Scheeffer IV-V
    # ``F_1, 0, 0, T_1, T_1^1, P``: mathematics is typeset, and a name of the program is no reader's word
    shown = [(path.name, m.group(0)) for path in sorted((ROOT / "notebooks").glob("*.ipynb"))
             for cell in nbformat.read(path, as_version=4).cells if cell.source.startswith("## About this section")
             for m in re.finditer(r"`[^`\n]+`", cell.source)]
    assert not shown, shown[:5]
    assert typeset("``a, b, …, g`` and ``ABC``, ``crossing``") == r"$a, b, \ldots, g$ and $ABC$, ``crossing``"


_ASCII_MATHS = re.compile(r"\^|∫∫|\b[A-Za-z]_[A-Za-z0-9{]|(?<![-\w])[A-Za-z]\d\b(?!-\w)"     # V1: V_1
                          r"|(?<![\w$'])(?:[A-Z][a-z]|[a-z][A-Za-z]) [=<>] [A-Za-z0-9(]"     # Oc = c, ab = y
                          r"|(?<!\.)\.\.\d"                                                  # $n = 3$..12
                          r"|<=|>=|!=| -\+ "                                                  # degree <= 3, 0.4 -+ c
                          r"|(?<![\w'])[A-Za-z]\([a-z0-9]\)"                                  # A(z), Y(y)
                          r"|\[-?\d+(?:/\d+)?, -?\d+(?:/\d+)?\]")                              # [-1/2, 1/2]


def _words_of(line: str) -> str:
    """*line* without its formulas and code: what a reader sees set as words."""
    return re.sub(r"`[^`]*`", "", re.sub(r"\$[^$]*\$", "", re.sub(r"\$\$.*?\$\$", "", line)))


def test_no_words_of_a_notebook_write_mathematics_in_ascii():
    # a witness's note ("> ∫∫ (x - x_C)^2 over the quadrilateral: disagrees ...", Euler §§192-219) and the helper
    # names of Graefe §1 ("|(b - a) x (d - a)|^2") were shown as written, and Graefe §4's step titles said
    # "Circle of radius^2 =": the source's quotations ("> " and no note) are verbatim and not looked at.  The title
    # ("# ") is the derivation's name in plain text, which the site also puts in the page's title and sidebar: it
    # has no ASCII mathematics either (Euler §§229-243's was "The family x = a + Y ± a(1 − yⁿ/bⁿ)^κ, ...")
    found = [(path.name, line) for path in sorted((ROOT / "notebooks").glob("*.ipynb"))
             for cell in nbformat.read(path, as_version=4).cells if cell.cell_type == "markdown"
             for line in re.sub(r"\$\$.*?\$\$", "", cell.source, flags=re.S).splitlines()
             if (not line.startswith(">") or ": disagrees" in line or line.startswith("> definition route"))
             and not line.startswith("|") and _ASCII_MATHS.search(_words_of(line))]
    assert not found, found[:8]
    assert _ASCII_MATHS.search(_words_of("# The family x = a + Y ± a(1 − yⁿ/bⁿ)^κ, the number μ"))
    assert _ASCII_MATHS.search(_words_of("> ∫∫ (x - x_C)^2 over the quadrilateral: disagrees"))
    assert not _ASCII_MATHS.search(_words_of(r"> $\int\int (x - x_{C})^{2}$ over the quadrilateral: disagrees"))
    # Scheeffer I-III's notes wrote "the volume V1, centroid S1 at u = e1" and "T1/V1 - e1": names without their
    # index set as an index (a step's name, e2-e3, is a name of the program, not mathematics)
    assert _ASCII_MATHS.search(_words_of("the old submerged part (volume V1, centroid S1)"))
    assert not _ASCII_MATHS.search(_words_of("the old submerged part (volume $V_{1}$, centroid $S_{1}$), step e2-e3"))
    # Euler's notes wrote his segments' lengths in words ("by Oc = c from the middle O", "since wn = wN - Nn")
    assert _ASCII_MATHS.search(_words_of("by Oc = c from the middle O")) and _ASCII_MATHS.search("since wn = wN - Nn")
    assert not _ASCII_MATHS.search(_words_of("by $Oc = c$ from the middle O, as it is"))
    # Scheeffer VI.C-F's ranges of n were cut after their first number ("checked for $n = 3$..12")
    assert _ASCII_MATHS.search(_words_of("checked for $n = 3$..12"))
    assert not _ASCII_MATHS.search(_words_of(r"checked for $n = 3, \ldots, 12$ and so on..."))
    # Graefe §2 wrote "degree <= 3", Graefe §3 "the section area A(z)", Hasáb "xi in [-1/2, 1/2]" in words
    for words in ("of degree <= 3 in $z$", "the section area A(z) is", r"$\xi$ in [-1/2, 1/2] (across)"):
        assert _ASCII_MATHS.search(_words_of(words)), words
    assert not _ASCII_MATHS.search(_words_of(r"of degree $\le 3$, the area $A(z)$, $\xi$ in $[-1/2, 1/2]$ (b)"))


_LISTED_APART = re.compile(r"(?<![\w$'])(?:[A-Za-z], ){2,}\$[A-Za-z] (?:[<>=]|\\(?:le|ge)\b)")


def test_names_listed_before_a_relation_are_set_with_it():
    # the assumptions of Graefe §1 and §3 and of Euler §§229-243 read "G, g, D, $h > 0$" and "a, b, $c > 0$":
    # two names in words and the third in a formula
    found = [(path.name, line) for path in sorted((ROOT / "notebooks").glob("*.ipynb"))
             for cell in nbformat.read(path, as_version=4).cells if cell.cell_type == "markdown"
             for line in cell.source.splitlines() if not line.startswith(">") and _LISTED_APART.search(line)]
    assert not found, found[:8]
    assert _LISTED_APART.search("- G, g, D, $h > 0$") and not _LISTED_APART.search("- $G, g, D, h > 0$")
    assert not _LISTED_APART.search("(it runs through A, $x = 0$ at $y = 0$)")


def test_a_quadrature_rule_is_named_in_words():
    # the witnesses' tables (notebooks, the site, docs/numerics.md) named Gauss–Legendre's rule by its key in the
    # records, "Gauss-Legendre n=3, 15 digits"; the key stays in the records, the reader sees its nodes
    from symfloat.numbers import method_words
    assert method_words("Gauss-Legendre n=3, 15 digits") == "Gauss–Legendre with 3 nodes, 15 digits"
    assert method_words("Gauss-Legendre (mpmath), 30 digits") == "Gauss–Legendre (mpmath), 30 digits"
    shown = [path for path in [*sorted((ROOT / "notebooks").glob("*.ipynb")), ROOT / "docs" / "numerics.md"]
             if re.search(r"Gauss.Legendre n=\d", path.read_text(encoding="utf-8"))]
    assert "Gauss-Legendre n=3" in (ROOT / "docs" / "verification.json").read_text(encoding="utf-8") and not shown
