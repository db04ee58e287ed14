"""The numerics benchmark (`symfloat bench`): structure and accuracy, never timings."""
import math
import re

import pytest
from PIL import Image

from symfloat.cli import main
from symfloat.engine.witness import SectionIntegral
from symfloat.errors import CheckFailed
from symfloat.numerics.bench import DECLARED, Bench, methods_for, newton_cotes, run_bench
from symfloat.numerics.forms import CATASTROPHIC, STABLE_TOLERANCE, evaluate, forms, scan
from symfloat.numerics.orders import (HEELS, convergence_witnesses, gauss_legendre_degrees, kink_study,
                                      registry_orders)
from symfloat.numerics.report import kind, pareto, write_png_if_changed
from symfloat.registry import ids, load
from symfloat.model.myst import inline


@pytest.fixture(scope="module")
def quick_docs(tmp_path_factory):
    out = tmp_path_factory.mktemp("numerics")
    assert main(["bench", "--quick", "--quiet", "--output", str(out)]) == 0
    return out


def test_quick_command_writes_the_document_and_figures(quick_docs):
    text = (quick_docs / "numerics.md").read_text(encoding="utf-8")
    for heading in ("## 1. Error against run time", "### Cheapest method per formula", "## 2. Convergence orders",
                    "### Kinks", "## 3. Stiff and extreme cases"):
        assert heading in text
    for family in ("floating bodies by exact clipping", "plane figures", "section-area quadrature"):
        table = text.split(f"### {family}\n", 1)[1].split("\n### ", 1)[0]
        row = next(line for line in table.splitlines() if line.startswith("| Arb ball arithmetic, 128 bits |"))
        assert "failed" not in row and "no bound" not in row and row.endswith("| yes |"), (family, row)
        assert "failed" not in table, family
    # the metacentre's limit, named by its derivation's title and what it measures, its mathematics typeset, with
    # the reason in words
    assert ("| Metacentre and stability function of a rectangular hull | $z_{M} = \\lim m/\\varphi + z_{G}$: "
            "righting arm of "
            "the clipped heeled box, extrapolated | a limit in the tilt (Neville extrapolation: no bound) |") in text
    figures = sorted(p.name for p in (quick_docs / "figures").glob("numerics-*.png"))
    assert "numerics-orders.png" in figures and "numerics-section-area-quadrature.png" in figures
    for name in figures:
        assert f"figures/{name}" in text
        assert Image.open(quick_docs / "figures" / name).text["Fingerprint"]


def test_the_document_names_sources_derivations_and_formulas_in_words(quick_docs):
    """A reader of docs/numerics.md (and of the site's page made from it) sees no derivation's id, no witness's
    or formula's name, no formula in Python's notation and none of the program's files, issues or exceptions:
    sources by author and title, derivations by title, formulas by their place and their print, typeset
    (provenance: the quick selection's Graefe §2 and the metacentre, whose formulas, witnesses and closed forms
    appear in every section; section 4's prose named issue 14, two test files, a module and an exception)."""
    text = (quick_docs / "numerics.md").read_text(encoding="utf-8")
    shown = re.sub(r"\(figures/[^)]*\)", "", text)             # a figure's file name is no text a reader sees
    assert not [did for did in ids() if did in shown]
    # nor the project's workings: an issue's number, a file of the program or its tests, an exception's name
    assert not re.findall(r"\bissue \d+|\b(?:symfloat|tests)/[\w/]+\.py\b|\b[A-Z]\w*Error\b|`np\.", shown)
    assert "sqrt(" not in shown and "| kantorovich |" not in shown      # section 4's densities and methods
    assert "**" not in shown.replace("**yes**", "").replace("**catastrophic**", "") and "`factor`" not in shown
    assert "#### V. v. Graefe, *Ueber eine allgemeine Formel zur Bestimmung des Schwerpunctes von Körpern*" in text
    assert "| §1 prismatoid volume: $I = \\frac{h}{3} \\left\\{ g + G = " in text        # place and print
    assert "| Sphere, paraboloid, ellipsoid and Simpson's rule from the prismatoid formula | " \
           "$\\int \\pi (r^{2} - (z - r)^{2}) dz$ over the diameter | $\\pi \\left(1 - \\left(z - 1\\right)^{2}\\right)$ |" in text
    assert "factored: $- \\frac{g l \\varrho \\left(\\varrho - 1\\right)}{2}$" in text
    # numbers as a reader writes them, with powers of ten, never a program's 1.2e-15 (every table of the document)
    assert not re.findall(r"\d\.?\d*e[-+]\d", shown) and re.search(r"\d × 10[⁻⁰-⁹¹²³]+ \|", shown)


def test_a_formula_in_a_table_cell_keeps_its_bars_out_of_the_tables_syntax():
    assert inline("$|x| + \\|v\\|$ and a|b", None, cell=True) == "$\\vert x\\vert  + \\Vert v\\Vert$ and a\\|b"
    assert kind("definitions, 15 digits") == "the derivation's definitions, 15 digits"


def test_figure_with_the_same_fingerprint_is_not_rewritten(tmp_path):
    import matplotlib.pyplot as plt
    path = tmp_path / "f.png"
    assert write_png_if_changed(path, plt.figure(), "abc")
    assert not write_png_if_changed(path, plt.figure(), "abc")
    assert write_png_if_changed(path, plt.figure(), "abd")


def test_a_familys_faint_points_are_one_collection_whatever_their_number():
    # a scatter per point made the figure take seconds to save; the points are one collection, in their order
    import matplotlib.pyplot as plt
    from symfloat.numerics.bench import Measurement
    from symfloat.numerics.report import family_figure

    def collections(n):
        ms = [Measurement("d", "s", "f", f"w{i}", method, 10.0 ** -(1 + i % 5), {"x": 10.0 ** -(3 + i % 7)})
              for i in range(n) for method in ("float64", "tanh-sinh, 30 digits")]
        fig, _ = family_figure("f", ms)
        count = len(fig.axes[0].collections)
        plt.close(fig)
        return count

    assert collections(3) == collections(300)


def test_pareto_front():
    pts = [(1.0, 1e-3), (2.0, 1e-10), (3.0, 1e-5), (0.5, 1e-1), (4.0, 1e-30)]
    assert pareto(pts) == [3, 0, 1, 4]


@pytest.fixture(scope="module")
def graefe_bench():
    return run_bench("graefe-s2", quick=True)


def test_every_witness_is_measured_with_every_applicable_method(graefe_bench):
    d, _ = load("graefe-s2-volumes-simpson")
    assert newton_cotes(d)          # Graefe §2 integrates by Simpson's rule: Newton–Cotes rules are benchmarked
    for w in d.witnesses:
        if isinstance(w, SectionIntegral):
            names = {m.method for m in graefe_bench.measurements if m.witness == w.name}
            assert {"Simpson, 4 panels, float64", "trapezoid, 16 panels, float64", "tanh-sinh, 30 digits",
                    "Gauss-Legendre n=8, float64"} <= names
            # 4 + 4 mpmath precisions, 7 float64 orders, 12 composite rules, Arb at 64 and 128 bits
            assert len(methods_for(w, d)) == 29 and "Arb ball arithmetic, 128 bits" in names


def test_accuracy_of_the_methods_against_the_enclosure(graefe_bench):
    """Graefe §2's section integrals are enclosed by acb.integral at 256 bits: every method's error is proven
    against that ball."""
    assert all(v == "Arb, 256 bits" for k, v in graefe_bench.references.items() if k.startswith("graefe-s2"))
    for m in graefe_bench.measurements:
        if m.derivation != "graefe-s2-volumes-simpson":
            continue
        worst = max(m.errors.values())
        if m.method == "tanh-sinh, 30 digits" or m.method == "mpmath, 30 digits":
            assert worst < 1e-28, (m.witness, m.method, worst)
        if m.method.startswith("Simpson") and m.witness.startswith("slab"):
            assert worst < 1e-14    # the slabs' sections are cubic: Simpson is exact
        if m.method == "Arb ball arithmetic, 128 bits":
            assert worst < 2.0 ** -100, (m.witness, worst)     # a proven bound: midpoint error plus radius


def test_gauss_legendre_is_exact_to_degree_2n_minus_1():
    assert gauss_legendre_degrees(range(1, 9)) == [(n, 2 * n - 1) for n in range(1, 9)]


def test_measured_orders_match_theory():
    for _, _, _, expected, simpson, trapezoid in convergence_witnesses("graefe-s2"):
        assert abs(simpson - expected) < 0.15 and abs(trapezoid - 2) < 0.1
    rows = {r.witness: r for r in registry_orders("graefe-s2")}
    assert rows["sphere-volume"].simpson is None and abs(rows["sphere-volume"].trapezoid - 2) < 0.05
    assert rows["paraboloid-volume"].trapezoid is None          # linear section: both rules exact
    chord = rows["circle chord"]                                 # square-root zeros at the ends: h^1.5
    assert abs(chord.simpson - 1.5) < 0.05 and abs(chord.trapezoid - 1.5) < 0.05


@pytest.mark.parametrize("heel, order", list(zip(HEELS, (2.0, 3.0))))
def test_kink_lowers_simpson_and_splitting_restores_it(heel, order):
    k = kink_study(heel, panels=(4, 8, 16, 32, 64, 128), gauss=(2, 4))
    assert abs(k.simpson_order - order) < 0.1
    assert abs(k.trapezoid_order - 2) < 0.1
    assert k.kinks and all(e == 0 for e in k.simpson_split)      # piecewise quadratic: exact once split
    assert all(split < 1e-15 < whole for _, whole, split in k.gauss)


@pytest.fixture(scope="module")
def stiff():
    return [evaluate(f) for f in forms()]


def test_catastrophic_forms_are_flagged(stiff):
    flagged = {r.form.locator for r in stiff if r.catastrophic}
    assert flagged == {"scheeffer-vi-cf/89a", "scheeffer-vi-cf/cube-78", "scheeffer-vi-ab/density-range",
                       "hasab/upright-roots", "scheeffer-vi-cf/83"}
    assert not next(r for r in stiff if r.form.name.startswith("n-gon moment")).catastrophic


def test_stable_forms_stay_within_1e_13(stiff):
    for r in stiff:
        if r.catastrophic:
            assert r.form.stable is not None, r.form.name
        if r.form.stable is not None:
            assert r.worst_stable <= STABLE_TOLERANCE, (r.form.name, r.stable)
        else:
            assert r.worst_naive <= STABLE_TOLERANCE


def test_the_printed_forms_lose_the_digits_reported(stiff):
    excess = next(r for r in stiff if r.form.name.startswith("excess"))
    assert excess.worst_naive > 1                      # n = 10^6: alpha^4/180 ~ 8e-24 is below float64's resolution
    cube = next(r for r in stiff if "(78)" in r.form.name)
    assert math.log10(cube.worst_naive / 2 ** -53) > 6
    assert CATASTROPHIC == pytest.approx(1.11e-10, rel=1e-2)


def test_scan_finds_the_density_forms_and_their_rewrites():
    rows = scan("hasab")
    assert len(rows) >= 5
    flagged = {r.formula: r for r in rows if r.worst > CATASTROPHIC}
    # E0 = l g (rho - rho^2)/2, held expanded: at rho -> 1 the difference loses ~8 digits; factored it does not
    assert "E0-total" in flagged and flagged["E0-total"].rewrite == "factor"
    assert all(r.rewrite and r.rewrite_worst <= STABLE_TOLERANCE for r in flagged.values())


def test_cheapest_prefers_lower_precision_among_near_equal_times():
    from symfloat.numerics.bench import Bench, Measurement
    from symfloat.numerics.report import cheapest

    def meas(method, seconds, error):
        return Measurement("d", "src", "fam", "w", method, seconds, {"f": error})
    # one witness: its times are the family medians
    bench = Bench([meas("mpmath, 50 digits", 0.010, 1e-50), meas("mpmath, 30 digits", 0.012, 1e-31),
                   meas("float64", 0.001, 1e-16), meas("tanh-sinh, 30 digits", 0.5, 1e-31)])
    assert cheapest(bench, 1e-30)["d/f"][0] == "mpmath, 30 digits"     # within a factor 2: lower precision
    assert cheapest(bench, 1e-12)["d/f"][0] == "float64"
    assert cheapest(bench, 1e-60)["d/f"] is None


def test_declared_witnesses_are_measured_with_their_own_methods():
    """The metazentrum box's declared floating-body witnesses (exact clipping) are benchmarked with the methods
    they declare, each within its own tolerance of the exact values of the readings (metazentrum, 'Metazentrum
    eines Quaders'): a witness family dropped from the bench, or a method measured against the wrong
    reference, fails here."""
    d, _ = load("metazentrum")
    bench = run_bench("metazentrum", quick=True)
    declared = {w.name: w for w in d.witnesses if isinstance(w, DECLARED)}
    for w in declared.values():             # the declared methods, then the ball methods where the kind has one
        own = methods_for(w, d)
        assert own[:len(w.methods)] == tuple(w.methods)
        assert all(m.name.startswith("Arb") for m in own[len(w.methods):])
    ms = [m for m in bench.measurements if m.family == "floating bodies by exact clipping"]
    assert len({m.witness for m in ms}) >= 8 and all(m.witness in declared for m in ms)
    # the heeled metacentre and radius are limits in the tilt (Neville extrapolation): no enclosure, said in words,
    # their methods against the exact reading; every other witness against its 256-bit enclosure, Arb a row
    limits = {"metacentre-heel", "radius-heel"}
    assert {k: why for k, (f, why) in bench.unenclosed.items() if f == "floating bodies by exact clipping"} == {
        f"metazentrum/{w}": "a limit in the tilt (Neville extrapolation: no bound)" for w in limits}
    enclosed = {m.witness for m in ms} - limits
    for name, kind in bench.references.items():    # a formula's reference kinds, from each witness targeting it
        if not any(name.split("/")[1] in w.targets for w in declared.values()):
            continue                                # a formula the definition route measures
        kinds = {"exact" if w.name in limits else "Arb, 256 bits" for w in declared.values()
                 if name.split("/")[1] in w.targets and w.name in {m.witness for m in ms}}
        assert kind == " and ".join(sorted(kinds)), (name, kind)
    arb_rows = {(m.witness, m.method) for m in ms if m.method.startswith("Arb")}
    assert arb_rows == {(w, f"Arb ball arithmetic, {b} bits") for w in enclosed for b in (64, 128)}
    for m in ms:
        worst = max(m.errors.values())
        assert m.proven and worst is not None, (m.witness, m.method)
        if m.method.startswith("Arb"):      # its proven width: radius plus distance from the 256-bit ball
            assert worst < 2.0 ** (-40 if "64" in m.method else -100), (m.witness, m.method, worst)
        else:
            tolerance = next(x.tolerance for x in declared[m.witness].methods if x.name == m.method)
            assert worst < tolerance, (m.witness, m.method, worst)


def test_an_enclosure_that_misses_the_value_fails_the_self_check(monkeypatch):
    """Mutation: every floating enclosure moved by 1e-20 of its value (the balls still meet one another) puts the
    40-digit clipping 1e-20 from the reference, beyond its tolerance 1e-30: the benchmark stops with CheckFailed
    (exit status 1) instead of reporting the error."""
    from flint import arb

    from symfloat.engine.floating_witness import FloatingWitness
    from symfloat.errors import CheckFailed
    enclose = FloatingWitness.enclose

    def moved(self, case, bits):
        value = enclose(self, case, bits)
        shift = lambda v: v * (1 + arb(10) ** -20) + arb(10) ** -20 if isinstance(v, arb) else v  # noqa: E731
        return tuple(map(shift, value)) if isinstance(value, tuple) else None if value is None else shift(value)
    monkeypatch.setattr(FloatingWitness, "enclose", moved)
    with pytest.raises(CheckFailed, match="beyond its tolerance"):
        run_bench("metazentrum", quick=True)


def test_an_arb_ball_that_misses_the_reference_fails_the_self_check():
    """Mutation: a 128-bit ball moved off the 256-bit enclosure of the same quantity fails the self-check; the
    ball as computed passes it (metazentrum's displaced volume, 16)."""
    from flint import arb

    from symfloat.errors import CheckFailed
    from symfloat.numerics.bench import self_check
    d, _ = load("metazentrum")
    w = next(w for w in d.witnesses if w.name == "displaced-volume")
    reference = [w.enclose(case, 256) for case in w.instances]
    ball = [w.enclose(case, 128) for case in w.instances]
    self_check("metazentrum", w, {"Arb ball arithmetic, 128 bits": ball}, reference)
    with pytest.raises(CheckFailed, match="misses"):
        self_check("metazentrum", w, {"Arb ball arithmetic, 128 bits": [b + arb(2) ** -20 for b in ball]}, reference)


def test_straightedge_constructions_are_benchmarked_like_computations():
    """Graefe §3's straightedge constructions (ConstructionWitness: meeting lines, Heron areas) are measured at the
    bench's precisions against the exact values of the readings they target (ratios and lengths of §3's
    tetrahedron lemma at the cases' integer vertices): a family dropped from the bench fails here."""
    bench = run_bench("graefe-s3", quick=True)
    ms = [m for m in bench.measurements if m.family == "straightedge constructions"]
    assert {"lines-construction", "lines-oc", "triangles-ratio-1"} <= {m.witness for m in ms}
    assert {m.method for m in ms} == {"float64", "mpmath, 30 digits", "Arb ball arithmetic, 64 bits",
                                      "Arb ball arithmetic, 128 bits"}
    for m in ms:
        worst = max(e for e in m.errors.values() if e is not None)
        bound = {"float64": 1e-12, "mpmath, 30 digits": 1e-26, "Arb ball arithmetic, 64 bits": 2.0 ** -40}
        assert worst < bound.get(m.method, 2.0 ** -100), (m.witness, m.method, worst)


def test_a_combined_witness_is_listed_with_its_parts():
    """Graefe §4's triaxial stump combines roots along its principal ellipses (CurveRoot, plane figures);
    metazentrum's heeled metacentre combines clipped-box measurements: each is listed under its parts' family."""
    from symfloat.engine.floating_witness import Combined
    from symfloat.numerics.bench import family_of
    graefe, _ = load("graefe-s4-applications")
    meta, _ = load("metazentrum")
    stump = next(w for w in graefe.witnesses if isinstance(w, Combined) and w.name.startswith("triaxial-stump"))
    heel = next(w for w in meta.witnesses if w.name == "metacentre-heel")
    assert family_of(stump) == "plane figures" and family_of(heel) == "floating bodies by exact clipping"


def test_a_derivations_cost_is_measured_with_its_witnesses_timed_where_they_run():
    # `symfloat bench --derivations` times each witness by wrapping its run; the wrapper must take what the
    # checker passes (the readings and the print's rounding), or the derivation cannot be checked at all
    from symfloat.numerics.cost import measure
    row = measure("graefe-s2-volumes-simpson")
    assert row["failures"] == 0 and row["witness_seconds"] and row["cold"] > 0
    assert row["formulas"] == 21


def test_the_definition_route_is_a_family_measured_against_its_enclosure(monkeypatch):
    """Every formula the definition route measures in Graefe §1 (no declared witness targets it) is measured in
    Arb at 64 and 128 bits and by its definitions at 15 and 30 digits, against its enclosure at 256 bits: each
    error a proven bound, falling with the precision; an Arb ball moved off the reference stops the bench."""
    from symfloat.numerics import route_bench
    from symfloat.numerics.route_bench import ROUTE_FAMILY, bench_route
    d, _ = load("graefe-s1-prismatoid-volume")
    bench = Bench()
    bench_route(d, bench, digits=(15, 30), repeats=1)
    ms = [m for m in bench.measurements if m.family == ROUTE_FAMILY]
    formulas = {m.witness for m in ms}
    assert formulas and all(bench.references[f"{d.id}/{f}"] == "Arb, 256 bits" for f in formulas)
    assert {m.method for m in ms} == {"Arb ball arithmetic, 64 bits", "Arb ball arithmetic, 128 bits",
                                      "definitions, 15 digits", "definitions, 30 digits"}
    worst = {method: max(e for m in ms if m.method == method for e in m.errors.values()) for method in
             ("definitions, 15 digits", "definitions, 30 digits")}
    assert worst["definitions, 15 digits"] < 1e-12 and worst["definitions, 30 digits"] < 1e-27
    assert all(m.proven for m in ms)
    ball = route_bench.definition_ball
    monkeypatch.setattr(route_bench, "definition_ball",
                        lambda e, point, bits: ball(e, point, bits) + (1e-10 if bits == 64 else 0))
    with pytest.raises(CheckFailed, match="misses the one at 256 bits"):
        bench_route(d, Bench(), digits=(15,), repeats=1)
