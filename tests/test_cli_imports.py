"""The command line loads what a command needs (issue 28, item 4): ``symfloat --help`` and ``--version`` import
neither SymPy nor NumPy nor the checking engine (measured by the modules a fresh process holds, not by a clock);
a subcommand's own help builds its options."""
import functools
import json
import os
import subprocess
import sys

HEAVY = ("sympy", "numpy", "mpmath", "symfloat.engine.check", "symfloat.engine.runner", "symfloat.solver",
         "symfloat.report.errata")
PROBE = """
import contextlib, io, json, sys
from symfloat.cli import main
with contextlib.redirect_stdout(io.StringIO()) as out:
    try:
        main(sys.argv[1:])
    except SystemExit:
        pass
print(json.dumps({"modules": sorted(sys.modules), "out": out.getvalue()}))
"""


@functools.cache
def _run(*argv):
    """The modules a fresh process holds after ``symfloat *argv*``, and what it printed (each command line run
    once per test run: the tests below ask some of them twice)."""
    done = subprocess.run([sys.executable, "-c", PROBE, *argv], capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


def test_help_and_version_load_no_mathematics():
    for argv in (["--help"], ["--version"]):
        ran = _run(*argv)
        assert ran["out"] and not set(HEAVY) & set(ran["modules"]), (argv, set(HEAVY) & set(ran["modules"]))
    assert "scene" in _run("--help")["out"]          # the commands are still listed


def test_a_subcommands_help_lists_its_options():
    ran = _run("scene", "--help")
    assert "--density" in ran["out"] and "Supported inputs" in ran["out"]
    assert "--density" not in _run("errata", "--help")["out"]
    assert "latex" in _run("errata", "--help")["out"]        # the formats come from the errata writer


def test_a_scenes_arguments_and_solver_load_no_sympy():
    """The scene's options (with the domain its epilog states) and the whole solver, its exact second
    variation (FLINT) and its certificates included, are parsed and imported without SymPy; only the
    comparison with the printed formulas needs it."""
    ran = _run("scene", "--help")
    assert "Supported inputs" in ran["out"] and "sympy" not in ran["modules"]
    probe = ("import sys, symfloat.solver.solve, symfloat.solver.exact, symfloat.solver.certificate; "
             "print('sympy' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "False"


def test_a_scene_loads_no_module_only_other_bodies_use(tmp_path):
    """A cube's or a box's scene imports neither the cylinder's slice quadrature (its nodes computed on import) nor
    the statements of a derivation; a cylinder's does import the quadrature."""
    import os
    env = {**os.environ, "SYMFLOAT_CACHE": str(tmp_path), "SYMFLOAT_QUIET": "1"}
    for argv in (["scene", "cube", "--density", "0.3"], ["scene", "box", "--dims", "1,2,3", "--density", "0.3"]):
        done = subprocess.run([sys.executable, "-c", PROBE, *argv, "--format", "json"], capture_output=True, text=True,
                              check=True, env=env, cwd=tmp_path)
        modules = set(json.loads(done.stdout)["modules"])
        assert "symfloat.geometry.cylinder" not in modules, argv
        assert not {m for m in modules if m.endswith(".statements")}, argv
    ran = _run("scene", "cylinder", "--dims", "1,2", "--density", "0.3", "--format", "json")
    assert "symfloat.geometry.cylinder" in ran["modules"]


def test_sympy_keeps_the_cache_symfloat_sizes_unless_the_environment_sizes_it():
    # symfloat/__init__.py sets SYMPY_CACHE_SIZE before SymPy is imported (SymPy reads it once, at its import)
    probe = "import symfloat, sympy.core.cache as c; print(c.SYMPY_CACHE_SIZE)"
    env = {k: v for k, v in os.environ.items() if k != "SYMPY_CACHE_SIZE"}
    sizes = [subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True,
                            env={**env, **extra}).stdout.strip() for extra in ({}, {"SYMPY_CACHE_SIZE": "500"})]
    assert sizes == ["100000", "500"]
