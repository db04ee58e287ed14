"""Every input field against thousands of generated inputs (hypothesis), and the stated domain.

Properties: a field's value is accepted into the stated domain (``symfloat.solver.bodies``) or
refused with one line (a :class:`SceneError`, exit status 2) -- never another exception, never a
traceback, always within the deadline; inside the domain the solver answers with its index check
closed.  The default run draws a few hundred inputs per field; ``pytest -m slow`` draws thousands.
"""
import contextlib
import io
import math
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

import symfloat.cli as cli
import symfloat.solver as solver_package
from symfloat.solver import solve
from symfloat.solver.selfcheck import IndexCheckError
from symfloat.solver.bodies import (MAX_SIDES, MAX_SIZE, MAX_VERTICES, MIN_LAYER, SceneError, make_scene,
                                    parse_number, parse_whole, thinness)

_HEALTH = [HealthCheck.too_slow, HealthCheck.function_scoped_fixture]
QUICK = settings(max_examples=300, deadline=2000, database=None, suppress_health_check=_HEALTH)
LONG = settings(max_examples=5000, deadline=2000, database=None, suppress_health_check=_HEALTH)

# ------------------------------------------------------------------ generated text

whitespace = st.text(alphabet=" \t\n\r\u00a0\u2003", max_size=3)
numbers = st.one_of(
    st.decimals(allow_nan=False, allow_infinity=False).map(str),
    st.floats().map(repr),                                              # nan, inf, -0.0, 5e-324, 1.8e308
    st.fractions().map(str),
    st.builds(lambda m, e: f"{m}e{e}", st.integers(-10**6, 10**6), st.integers(-10**4, 10**4)),
    st.builds(lambda m, e: f"{m}e{e}", st.sampled_from(["1", "9.99", "0.5"]), st.sampled_from(
        [-400, -330, -310, -300, -17, -15, -9, -7, -5, -4, -3, 0, 3, 5, 6, 7, 300, 308, 309, 400, 401, 10**9])),
    st.builds(lambda p, q: f"{p}/{q}", st.integers(-10**30, 10**30), st.integers(0, 10**30)),
    st.builds(lambda m, q: f"{m}/{q}", st.sampled_from(["0.5", ".5", "1e5", "2.5e-3", "1.", "nan"]),
              st.integers(0, 10**6)),                                   # a decimal over a whole number
    st.builds(lambda k: "0." + "9" * k, st.integers(1, 70)),            # 1 - 10^-k, near the upper end
    st.text(alphabet=st.characters(categories=["Nd"]), min_size=1, max_size=4),   # unicode digits
    st.text(max_size=20),
    st.text(min_size=60, max_size=3000),
    st.builds(lambda n: "9" * n, st.integers(60, 10**4)),
)
padded = st.builds(lambda a, x, b: a + x + b, whitespace, numbers, whitespace)


def _refusal_is_one_line(exc):
    message = str(exc)
    assert message and "\n" not in message and len(message) < 400, message


def _accepted(scene):
    """The stated domain, computed here from the scene's exact numbers."""
    s = scene.density
    assert 0 < s < 1
    assert all(0 < d <= MAX_SIZE for d in scene.dims)
    assert all(abs(c) <= MAX_SIZE for p in scene.polygon for c in p)
    thinnest, longest = thinness(scene)
    assert float(min(s, 1 - s)) * thinnest / longest >= MIN_LAYER * (1 - 1e-12)


# ------------------------------------------------------------------ parsers

def _number_property(text):
    try:
        value = parse_number(text, "density")
    except SceneError as exc:
        _refusal_is_one_line(exc)
        return
    numerator, _, denominator = text.strip().partition("/")
    assert isinstance(value, Fraction) and value == Fraction(numerator) / Fraction(denominator or 1)
    assert text.strip().isascii()


@QUICK
@given(padded)
@example("1e-400")
@example("1e999999999")
@example("١٢")
@example("0.99999999999999999")
@example("0.5/2")          # once a traceback: Fraction() takes no decimal over a whole number
@example("1e5/3")
@example("1.5/0")
def test_a_number_is_exact_or_refused_in_one_line(text):
    _number_property(text)


@pytest.mark.slow
@LONG
@given(padded)
def test_a_number_is_exact_or_refused_in_one_line_long(text):
    _number_property(text)


def _whole_property(text):
    try:
        n = parse_whole(text, "--steps", 4, 2000)
    except SceneError as exc:
        _refusal_is_one_line(exc)
        return
    assert 4 <= n <= 2000 and n == int(text.strip()) and text.strip().isascii()


@QUICK
@given(st.one_of(padded, st.integers(-10**6, 10**6).map(str)))
@example("48")
@example("٤٨")
def test_a_count_is_a_whole_number_in_range_or_refused(text):
    _whole_property(text)


# ------------------------------------------------------------------ scenes

bodies = st.sampled_from(["cube", "box", "prism", "cylinder", "section", "ball", "", "CUBE"])
dims = st.one_of(st.none(), st.lists(padded, min_size=0, max_size=4).map(",".join),
                 st.lists(st.sampled_from(["1", "1e-3", "2", "1e6", "1e-6", "1e-9", "0.5"]), min_size=1,
                          max_size=3).map(",".join))
sides = st.one_of(st.none(), padded, st.integers(-5, 300).map(str))


@st.composite
def polygons(draw):
    """Convex polygons with near-duplicate and near-collinear vertices, and arbitrary text."""
    kind = draw(st.sampled_from(["regular", "perturbed", "text", "big"]))
    if kind == "text":
        return draw(st.text(max_size=200))
    n = draw(st.integers(3, 70 if kind == "big" else 12))
    scale = draw(st.sampled_from(["1", "1e-7", "1e-3", "1e3", "1e6", "1e7"]))
    points = [(round(math.cos(2 * math.pi * k / n) * 10**6), round(math.sin(2 * math.pi * k / n) * 10**6))
              for k in range(n)]
    eps = draw(st.sampled_from([0, 1, 10**-3, 10**-9]))
    out = []
    for i, (x, y) in enumerate(points):
        out.append((Fraction(x, 10**6) * Fraction(scale), Fraction(y, 10**6) * Fraction(scale)))
        if kind == "perturbed" and draw(st.booleans()):
            nx, ny = points[(i + 1) % n]
            mid = (Fraction(x + nx, 2 * 10**6) * Fraction(scale), Fraction(y + ny, 2 * 10**6) * Fraction(scale))
            out.append((mid[0] * (1 + Fraction(eps)), mid[1] * (1 + Fraction(eps))))   # near-collinear
            if draw(st.booleans()):
                out.append((out[-1][0] + Fraction(eps) / 10**6, out[-1][1]))           # near-duplicate
    return " ".join(f"{x},{y}" for x, y in out)


def _scene_property(body, density, dims, sides, polygon):
    try:
        scene = make_scene(body, density, dims, sides, polygon)
    except SceneError as exc:
        _refusal_is_one_line(exc)
        return
    _accepted(scene)


@QUICK
@given(bodies, padded, dims, sides, st.one_of(st.none(), polygons()))
@example("cube", "1e-15", None, None, None)
@example("box", "0.3", "1,1e-9,1", None, None)
@example("box", "0.5", "1e400,1,1", None, None)
@example("box", "0.5", "1e-400,1,1", None, None)
@example("section", "0.5", None, None, "1e300,0 0,1e300 -1e300,0")
@example("section", "0.5", None, None, "0,0 1,0 1e-300,1e-300")
@example("cylinder", "0.3", "1e-200,1", None, None)
@example("prism", "0.5", "1,1", "100000", None)
def test_a_scene_is_in_the_domain_or_refused_in_one_line(body, density, dims, sides, polygon):
    _scene_property(body, density, dims, sides, polygon)


@pytest.mark.slow
@LONG
@given(bodies, padded, dims, sides, st.one_of(st.none(), polygons()))
def test_a_scene_is_in_the_domain_or_refused_in_one_line_long(body, density, dims, sides, polygon):
    _scene_property(body, density, dims, sides, polygon)


@pytest.mark.parametrize("args", [
    ("cube", "1e-15"), ("cube", "1e-17"), ("cube", "1e-400"), ("cube", "0.99999999999999999"),
    ("box", "0.3", "1,1e-9,1"), ("box", "0.5", "1e-300,1,1e300"), ("box", "0.5", "1e400,1,1"),
    ("box", "0.5", "1e-400,1,1"), ("cylinder", "0.3", "1e-200,1"), ("box", "1e-3", "1,1e-2,1"),
])
def test_the_reported_failures_are_refused(args):
    # symfloat issue 17: each of these gave a traceback or a wrong answer with a failing index check
    with pytest.raises(SceneError):
        make_scene(*args)


def test_the_domain_edges_are_where_stated():
    # min(s, 1 - s) x thinnest/longest >= 1e-4: a cube from 1e-4 to 1 - 1e-4, a 1 x 1/100 x 1 box from 1/100
    make_scene("cube", "1e-4")
    make_scene("cube", "0.9999")
    with pytest.raises(SceneError, match=r"0.0001 <= s <= 1 - 0.0001"):
        make_scene("cube", "0.99991")
    make_scene("box", "0.01", dims="1,0.01,1")
    with pytest.raises(SceneError, match=r"0.01 <= s"):
        make_scene("box", "0.0099", dims="1,0.01,1")
    make_scene("prism", "0.5", dims="1,1", sides=str(MAX_SIDES))
    with pytest.raises(SceneError):
        make_scene("prism", "0.5", dims="1,1", sides=str(MAX_SIDES + 1))
    regular = " ".join(f"{math.cos(2 * math.pi * k / MAX_VERTICES):.9f},{math.sin(2 * math.pi * k / MAX_VERTICES):.9f}"
                       for k in range(MAX_VERTICES + 1))
    with pytest.raises(SceneError, match="at most 64"):
        make_scene("section", "0.5", polygon=regular)


# ------------------------------------------------------------------ the solver inside the domain

def _index_closes(scene):
    sol = solve(scene)
    checks = sol.checks
    if "poincare_hopf_index_sum" in checks and checks["poincare_hopf_index_sum"] is not None:
        assert checks["poincare_hopf_index_sum"] == checks["expected_index_sum"], (scene, checks)
    if "minima_minus_maxima" in checks:
        assert checks["minima_minus_maxima"] == checks["expected_index_sum"], (scene, checks)
    for e in sol.equilibria:
        assert math.isclose(math.hypot(*e.up), 1, rel_tol=1e-12)
        assert not e.waterplane.startswith(("0-", "1-", "2-")), (scene, e.waterplane)


ratios = st.sampled_from(["1", "1/2", "1/10", "1/100", "1/1000", "1/4000"])
edges = st.sampled_from(["lower", "upper", "0.5", "0.3"])     # densities at the stated bound and inside


def _density(edge, thin):
    """A density at the stated bound min(s, 1 - s) x thin = 1e-4 (lower or upper end), or inside."""
    bound = Fraction(1, 10**4) / Fraction(thin) if thin else Fraction(1, 10**4)
    bound = min(bound, Fraction(1, 2))
    if edge == "lower":
        return bound
    return 1 - bound if edge == "upper" else min(max(Fraction(edge), bound), 1 - bound)


in_domain = st.one_of(
    st.builds(lambda e: ("cube", _density(e, 1), None, None, None), edges),
    st.builds(lambda r, e, big: ("box", _density(e, Fraction(r)), f"{big},{Fraction(r) * Fraction(big)},{big}",
                                 None, None), ratios, edges, st.sampled_from(["1", "1e-6", "1e6"])),
    st.builds(lambda n, e: ("prism", _density(e, None), "1,2", str(n), None), st.sampled_from([3, 4, 5, 7, 12]),
              st.sampled_from(["0.3", "0.5", "0.999"])),
    st.builds(lambda r, e: ("cylinder", _density(e, min(2 * Fraction(r), 1) / max(2 * Fraction(r), 1)),
                            f"{r},1", None, None), ratios, edges),
    st.builds(lambda r, e: ("section", _density(e, Fraction(r) / (1 + Fraction(r))), None, None,
                            f"0,0 1,0 1,{r} 0,{r}"), ratios, edges),
    st.builds(lambda e: ("section", _density(e, Fraction(1, 3)), None, None, "0,0 1,0 0,1"), edges),
)


def _in_domain_property(case):
    body, s, d, n, polygon = case
    _index_closes(make_scene(body, s, d, n, polygon))      # every case is inside the stated domain


@settings(max_examples=4, deadline=None, database=None)
@given(in_domain)
@example(("cube", "1e-4", None, None, None))
@example(("box", "0.01", "1,0.01,1", None, None))
def test_inside_the_domain_the_index_check_closes(case):
    _in_domain_property(case)


@pytest.mark.slow
@settings(max_examples=150, deadline=None, database=None)
@given(in_domain)
def test_inside_the_domain_the_index_check_closes_long(case):
    _in_domain_property(case)


@pytest.mark.parametrize("density", ["0.3", "0.5"])
def test_the_prism_over_a_32_gon_closes_its_index_check(density):
    # a known fault until the search took a position symmetry fixes for an equilibrium born next to its neighbour:
    # lying on a face and lying on an edge, pi/32 apart and both soft in roll, each was found where the slope along
    # a mirror changes sign beside the other, so the edge-down class was counted twice and the sum was 34, not 2
    # (symfloat/solver/solve.py, _symmetric); drawn at random by the property above it failed one run in two
    scene = make_scene("prism", _density(density, None), "1,2", "32")
    _index_closes(scene)
    ups = [e.up for e in solve(scene).equilibria]
    assert len(ups) == len(set(ups)) == 3           # upright, lying on a face, lying on an edge: once each


def test_the_prism_over_an_octagon_at_one_half_closes_its_index_check():
    # a known fault until the points were polished on the body made again at 30 digits: the float64 octagon's
    # rounded vertices break its mirrors by 1e-16, and the stable class beside the 16 arcs at s = 1/2 (smallest
    # eigenvalue 9e-7 of the size) moved 2e-11 off its mirror, beyond its error, and was counted 32 times, not 16:
    # the sum was 18, not 2 (symfloat/solver/critical.py, polyhedron_at)
    scene = make_scene("prism", _density("0.5", None), "1,2", "8")
    _index_closes(scene)
    stable = [e for e in solve(scene).equilibria if e.stability == "stable" and e.family == "isolated"]
    assert [e.copies for e in stable] == [16] and stable[0].up[1] == 0.0      # on the mirror y = 0


def test_a_ring_closed_by_its_first_vertex_is_the_polygon():
    # "0,0 2,0 2,1 0,1 0,0", as GeoJSON closes a ring, was refused: "the polygon repeats a vertex"
    assert make_scene("section", "3/10", polygon="0,0 2,0 2,1 0,1 0,0").polygon == \
        make_scene("section", "3/10", polygon="0,0 2,0 2,1 0,1").polygon
    with pytest.raises(SceneError, match="repeats a vertex"):              # a repetition elsewhere still is refused
        make_scene("section", "3/10", polygon="0,0 2,0 2,1 2,0 0,1")
    with pytest.raises(SceneError, match="repeats a vertex"):              # a closed segment is no polygon
        make_scene("section", "3/10", polygon="0,0 2,0 0,0")


def test_a_polygon_whose_vertices_round_to_one_float_is_refused_or_answered():
    # symfloat issue 32: both were ZeroDivisionError in _polygon_extent (float edges of length 0)
    with pytest.raises(SceneError, match="measures 0 across"):
        make_scene("section", "1/2", polygon="0,0 1e-400,0 0,1e-400")
    near = make_scene("section", "1/2", polygon=f"0,0 1,0 1,1 0.{'9' * 59},1.{'0' * 58}1 0,1")
    assert Fraction(near.polygon[3][1]) - 1 == Fraction(1, 10**59)
    width, diameter = thinness(near)
    # the unit square with a bump of 1e-59: width 1 (between y = 0 and the top, within 1e-59), diameter
    # the diagonal from (0, 0) to (1 - 1e-59, 1 + 1e-59), sqrt(2) to double precision
    assert width == pytest.approx(1, abs=1e-15) and diameter == pytest.approx(2 ** 0.5, abs=1e-15)


# ------------------------------------------------------------------ the command line, every field

class _Work(Exception):
    """Raised instead of the expensive work once the input is accepted."""


def _exit_status(argv):
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        try:
            code = cli.main(argv)
        except SystemExit as exc:                # argparse's usage errors
            code = exc.code
        except _Work:
            return None, err.getvalue()
    return code, err.getvalue()


fields = st.one_of(padded, st.text(max_size=40), polygons())


@st.composite
def command_lines(draw):
    command = draw(st.sampled_from(["scene", "phase", "verify", "errata", "notebooks", "bench"]))
    if command in ("verify", "errata", "notebooks", "bench"):
        argv = [command]
        if command != "bench":
            argv.append(draw(st.one_of(st.text(max_size=30), st.sampled_from(["graefe", "graefe-s1", "x"]))))
        if draw(st.booleans()):
            argv.append(f"--output={draw(st.one_of(st.text(max_size=40), st.sampled_from(['.', 'out.md', '/dev/null/x'])))}")
        return argv
    argv = [command, draw(st.one_of(bodies, st.text(max_size=10)))]
    for flag in ("--density", "--dims", "--sides", "--polygon", "--steps", "--plot", "--format"):
        if draw(st.booleans()):
            argv += [f"{flag}={draw(fields)}"]
    return argv


def _cli_property(argv):
    code, err = _exit_status([*argv, "--quiet"])
    assert "Traceback" not in err
    if code is None:
        return                                       # accepted: the work would start here
    assert code == 2, (argv, code, err)
    assert err.startswith("symfloat: ") and err.count("\n") == 1, err


@pytest.fixture
def no_work(monkeypatch, tmp_path):
    def work(*a, **k):
        raise _Work
    monkeypatch.setattr(solver_package, "solve", work)
    monkeypatch.setattr(cli, "verify", work)
    monkeypatch.setattr(cli, "select", work)            # importing derivations is work too
    monkeypatch.setattr("symfloat.comparison.thresholds.phase_with_sources", work)
    monkeypatch.setattr("symfloat.numerics.document.generate", work)
    monkeypatch.setenv("SYMFLOAT_CACHE", str(tmp_path / "cache"))
    monkeypatch.chdir(tmp_path)


@QUICK
@given(command_lines())
@example(["scene", "cube", "--density=1e-17"])
@example(["scene", "cube", "--density=0.3", "--plot=x\x00.png"])
@example(["phase", "box", "--dims=1,0.01,1", "--steps=2000"])
@example(["errata", ""])
@example(["errata", "0", "--output=\x00"])
def test_every_field_of_the_command_line_is_answered_or_refused_in_one_line(no_work, argv):
    _cli_property(argv)


@pytest.mark.slow
@LONG
@given(command_lines())
def test_every_field_of_the_command_line_long(no_work, argv):
    _cli_property(argv)


# ------------------------------------------------------------------ environment variables and paths

env_values = st.one_of(
    st.text(max_size=20),
    st.text(alphabet=st.characters(categories=["Nd", "No"]), min_size=1, max_size=6),   # ², ٣, unicode digits
    st.builds(lambda k: "9" * k, st.integers(1, 6000)),                                 # past int()'s 4300 digits
    st.sampled_from(["0", "1", "2", "64", "65", "-1", "1e9", "inf", "nan", "0.5", "1e400", " 2", "2\n"]),
)
components = st.one_of(
    st.text(alphabet=st.characters(blacklist_categories=["Cs"], blacklist_characters="/\x00"), min_size=1,
            max_size=12).filter(lambda c: c != ".."),
    st.builds(lambda k: "a" * k, st.integers(250, 300)),                               # around NAME_MAX = 255
    st.sampled_from([".", "proc", "dev", "null", "nonexistent"]),
)
# relative paths stay in the test's own folder (a cache is created where SYMFLOAT_CACHE says); the absolute
# ones can take nothing: /proc, a path through a device, a name longer than any file system allows
paths = st.one_of(
    st.lists(components, min_size=1, max_size=4).map("/".join),
    st.builds(lambda root, parts: root + "/".join(parts), st.sampled_from(["/proc/", "/dev/null/", "/" + "a" * 300 + "/"]),
              st.lists(components, min_size=0, max_size=2)),
)


@st.composite
def environments(draw):
    """A command and values for the environment variables a command reads, or a path for its output."""
    env = {}
    for variable in ("SYMFLOAT_WORKERS", "SYMFLOAT_SLOWDOWN", "SYMFLOAT_QUIET"):
        if draw(st.booleans()):
            env[variable] = draw(env_values)
    for variable in ("SYMFLOAT_CACHE", "SYMFLOAT_LIBRARY"):
        if draw(st.booleans()):
            env[variable] = draw(paths)
    argv = draw(st.sampled_from([["verify", "graefe-s1"], ["errata", "graefe-s1", "--output"],
                                 ["scene", "cube", "--density", "0.3", "--plot"], ["notebooks", "graefe-s1", "--output"]]))
    if argv[-1].startswith("--"):
        argv = [*argv, draw(paths) + (".png" if argv[0] == "scene" else "")]
    return env, argv


def _environment_property(env, argv, monkeypatch):
    for variable, value in env.items():
        monkeypatch.setenv(variable, value.replace("\x00", ""))
    code, err = _exit_status([*argv, "--quiet"])
    assert "Traceback" not in err
    if code is None:
        return                                       # accepted: the work would start here
    assert code == 2, (env, argv, code, err)
    assert err.startswith("symfloat: ") and err.count("\n") == 1, err


@QUICK
@given(case=environments())
@example(case=({"SYMFLOAT_WORKERS": "²"}, ["verify", "graefe-s1"]))
@example(case=({"SYMFLOAT_WORKERS": "9" * 5000}, ["verify", "graefe-s1"]))
@example(case=({"SYMFLOAT_SLOWDOWN": "fast"}, ["verify", "graefe-s1"]))
@example(case=({"SYMFLOAT_CACHE": "/tmp/" + "a" * 300}, ["verify", "graefe-s1"]))
@example(case=({"SYMFLOAT_LIBRARY": "/tmp/" + "a" * 300}, ["verify", "graefe-s1"]))
@example(case=({}, ["scene", "cube", "--density", "0.3", "--plot", "a" * 300 + ".png"]))
@example(case=({}, ["errata", "graefe-s1", "--output", "/proc/x.md"]))
def test_every_environment_variable_and_path_is_accepted_or_refused_in_one_line(no_work, monkeypatch, case):
    with monkeypatch.context() as m:
        _environment_property(*case, m)
