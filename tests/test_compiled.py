"""Compiled readings (issue 28, item 4): a scene reads the predictors' readings as JSON trees, without SymPy and
without any statements module, and an entry is judged when read (:mod:`symfloat.model.compiled`)."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from fractions import Fraction

import pytest
import sympy as sp

from symfloat import registry
from symfloat.model import compiled
from symfloat.model.compiled import Compiled, Readings, Real, exact_sqrt, reading

def test_the_shipped_compiled_readings_are_current():
    # derivations/<pkg>/compiled.json is written by `symfloat run`; a statement or predictor changed since makes
    # it stale (a scene would still be right, compiling afresh, but slow)
    assert registry.compiled_readings() == [], "run `symfloat run` to write the compiled readings again"


def test_the_shipped_file_is_what_the_statements_compile_to():
    module = registry.part("hasab", "predictors")
    shipped = json.loads((module.READINGS.folder / "compiled.json").read_text(encoding="utf-8"))
    assert module.READINGS.compile() == shipped


PROBE = """
import contextlib, io, json, sys
from symfloat.cli import main
with contextlib.redirect_stdout(io.StringIO()) as out:
    code = main(sys.argv[1:])
print(json.dumps({"code": code, "modules": sorted(m for m in sys.modules
                                                 if m == "sympy" or m.endswith(".statements"))}))
"""


@pytest.mark.parametrize("argv", [["scene", "cube", "--density", "0.3"],
                                  ["scene", "box", "--dims", "1,2,3", "--density", "0.3"],
                                  ["scene", "section", "--polygon", "0,0 2,0 2,1 0,1", "--density", "0.3"]])
def test_a_scene_imports_neither_sympy_nor_a_statements_module(argv, tmp_path):
    # an empty cache: the shipped compiled readings are all a scene reads of the sources
    env = {**os.environ, "SYMFLOAT_CACHE": str(tmp_path), "SYMFLOAT_QUIET": "1"}
    done = subprocess.run([sys.executable, "-c", PROBE, *argv, "--format", "json"], capture_output=True, text=True,
                          check=True, env=env, cwd=tmp_path)
    ran = json.loads(done.stdout.strip().splitlines()[-1])
    assert ran["code"] == 0 and ran["modules"] == []


def _readings(monkeypatch, tmp_path):
    """Hasáb's readings as a scene would load them with no shipped file, the cache in *tmp_path* (the predictors
    imported first: importing them loads their readings, which would fill the cache before the test looks)."""
    module = registry.part("hasab", "predictors")
    monkeypatch.setenv("SYMFLOAT_CACHE", str(tmp_path))
    monkeypatch.setattr(compiled, "SHIPPED", "absent.json")
    return lambda: Readings(module.__file__, module.__package__, module.READINGS.spec)


def test_an_entry_is_compiled_once_and_then_read_from_the_cache(monkeypatch, tmp_path):
    load = _readings(monkeypatch, tmp_path)
    assert load().source == "statements" and load().source == "cache"


@pytest.mark.parametrize("forge", ["payload", "node", "key"])
def test_a_forged_entry_is_not_believed(forge, monkeypatch, tmp_path):
    load = _readings(monkeypatch, tmp_path)
    first = load()
    (path,) = (tmp_path / "compiled").glob("hasab.*.json")
    entry = json.loads(path.read_text(encoding="utf-8"))
    condition = entry["readings"]["CONDITION"]["value"]
    if forge == "payload":      # the printed condition's sign flipped; the content hash left as it was
        condition["expr"] = ["*", ["q", -1, 1], condition["expr"]]
    elif forge == "node":       # a node outside the whitelist, the hash made to match
        condition["expr"] = ["f", "__import__", ["q", 1, 1]]
        entry["sha256"] = compiled._digest({"readings": entry["readings"], "printed": entry["printed"]})
    else:                       # a well-formed entry under a key the present sources do not have
        entry["key"] = "0" * 32
        condition["expr"] = ["q", 1, 1]
        entry["sha256"] = compiled._digest({"readings": entry["readings"], "printed": entry["printed"]})
    path.write_text(json.dumps(entry), encoding="utf-8")
    again = load()
    assert again.source == "statements"             # compiled afresh, the forgery not read
    # the printed condition rho^2 - rho + 1/6 (hasab): -1/12 < 0 at rho = 1/2, 1/10 - ... > 0 at rho = 1/10
    assert again["CONDITION"](Fraction(1, 2)) == -1 == first["CONDITION"](Fraction(1, 2))
    assert again["CONDITION"](Fraction(1, 10)) == 1


def test_a_non_whitelisted_tree_does_not_parse():
    for bad in (["f", "eval", ["q", 1, 1]], ["x", 3], ["q", 1, 0], ["attr", "os"], [1, 2], ["q", 1.5, 1]):
        with pytest.raises(compiled.CompiledError):
            compiled._parse({"expr": bad}, 2)


def test_exact_evaluation_rational_and_irrational():
    # (a/b)^2 - 6 s (1 - s) at a = 1, b = 2, s = 3/10: 1/4 - 126/100 = -101/100 (Scheeffer (75), by hand)
    a, b, s = sp.symbols("a b s")
    margin = compiled.compile_expr((a / b) ** 2 - 6 * s * (1 - s), (a, b, s))
    assert margin(1, 2, Fraction(3, 10)) == Fraction(-101, 100)
    assert abs(margin(1.0, 2.0, 0.3) + 1.01) < 1e-15
    # an irrational value: its sign from Arb balls; exactly zero decided by SymPy (sqrt 2 sqrt 2 - 2 = 0)
    root2 = exact_sqrt(2)
    assert isinstance(root2, Real) and root2 > Fraction(1414, 1000) and root2 < Fraction(1415, 1000)
    assert (root2 * root2 - 2).sign() == 0 and root2 * root2 == 2
    assert exact_sqrt(Fraction(9, 4)) == Fraction(3, 2)


def test_the_compiled_readings_are_the_statements_readings():
    # every reading of a predictor evaluated by its tree and by Derivation.evaluator at an exact point agrees
    # exactly (the tree is the evaluator's expression, written as JSON and read back)
    st = registry.part("scheeffer-vi-cf", "statements")
    for name, symbols, member in (("75", ("a", "b", "s"), 0), ("78d", ("a", "b", "s"), 1)):
        syms = tuple(getattr(st, q) for q in symbols)
        tree = compiled.compile_expr(*reading(name, symbols, member)(st))
        theirs = st.DERIVATION.evaluator(name, syms, member)
        for point in ((1, 2, Fraction(3, 10)), (3, 2, Fraction(7, 10)), (1, 1, Fraction(1, 2))):
            assert tree(*point) == theirs(*point), (name, point)


def test_a_reading_is_refused_when_it_holds_an_unknown_node():
    x = sp.Symbol("x")
    with pytest.raises(compiled.CompiledError):
        compiled.compile_expr(sp.gamma(x), (x,))
    assert isinstance(compiled.compile_expr(sp.sqrt(x), (x,)), Compiled)


def test_the_compiled_readings_are_no_part_of_a_checks_key():
    # generated from the statements and predictors (which the key covers) and written after the checks: were
    # they keyed, writing them would make the checks just done stale
    folder = registry.manifest("scheeffer-ix").folder
    assert (folder / "compiled.json").is_file() and folder / "compiled.json" not in registry.files("scheeffer-ix")


def test_the_key_covers_what_compiling_runs_and_not_the_witnesses(tmp_path, monkeypatch):
    # a copy of Scheeffer IX's package: a witness edited keeps the key, a statement or predictor edited changes it
    import shutil
    folder = tmp_path / "scheeffer_ix"
    shutil.copytree(registry.manifest("scheeffer-ix").folder, folder, ignore=shutil.ignore_patterns("__pycache__"))
    before = compiled.key(folder)
    for name, changes in (("witnesses.py", False), ("proofs.json", False), ("statements.py", True),
                          ("predictors.py", True)):
        path = folder / name
        text = path.read_text(encoding="utf-8")
        path.write_text(text + ("\n# edited\n" if name.endswith(".py") else " "), encoding="utf-8")
        assert (compiled.key(folder) != before) == changes, name
        path.write_text(text, encoding="utf-8")
    assert compiled.key(folder) == before
    real = compiled.importlib.metadata.version            # another SymPy may shape a tree otherwise: a new key
    monkeypatch.setattr(compiled.importlib.metadata, "version", lambda name: "0.0" if name == "sympy" else real(name))
    assert compiled.key(folder) != before


def test_a_shipped_entry_is_judged_without_parsing_a_module(monkeypatch):
    # the entry records the files its key covers; a scene hashes them again instead of parsing the statements and
    # predictors to find them from their imports (tenths of a second a derivation): the same key
    for did in ("hasab", "scheeffer-ix", "scheeffer-vii-viii"):
        folder = registry.manifest(did).folder
        assert compiled._recorded_key(compiled._entry(folder / "compiled.json"), folder) == compiled.key(folder), did
    module = registry.part("hasab", "predictors")
    monkeypatch.setattr(compiled, "_imported_files", lambda path: pytest.fail(f"{path} parsed"))
    assert Readings(module.__file__, module.__package__, module.READINGS.spec).source == "shipped"


def test_a_recorded_key_is_not_believed_when_what_it_covers_changed(tmp_path):
    import shutil
    folder = tmp_path / "scheeffer_ix"
    shutil.copytree(registry.manifest("scheeffer-ix").folder, folder, ignore=shutil.ignore_patterns("__pycache__"))
    shipped = folder / "compiled.json"
    assert compiled._recorded_key(compiled._entry(shipped), folder) == compiled.key(folder)
    statements = folder / "statements.py"
    text = statements.read_text(encoding="utf-8")
    statements.write_text(text + "\nfrom symfloat.solver import cylinder\n", encoding="utf-8")   # a new import
    assert compiled._recorded_key(compiled._entry(shipped), folder) is None and compiled.key(folder) != compiled.key(
        registry.manifest("scheeffer-ix").folder)
    statements.write_text(text, encoding="utf-8")
    entry = json.loads(shipped.read_text(encoding="utf-8"))
    for covers in ([c for c in entry["covers"] if c != "scheeffer_ix/statements.py"],     # a file left out
                   [c for c in entry["covers"] if c != "symfloat/engine/roots.py"],        # the key no longer matches
                   entry["covers"] + ["../../etc/passwd"]):
        shipped.write_text(json.dumps({**entry, "covers": covers}), encoding="utf-8")
        assert compiled._recorded_key(compiled._entry(shipped), folder) is None, covers


THRESHOLDS_PROBE = """
import json, sys
from symfloat.comparison.thresholds import source_thresholds
from symfloat.registry import provided
found = source_thresholds("cube", (1, 1, 1), grid=8)
(did, tables), = provided("tables")
print(json.dumps({"derivations": sorted({t["derivation"] for t in found}), "tables": did,
                  "statements": sorted(m for m in sys.modules if m.endswith(".statements"))}))
"""


def test_the_phase_thresholds_and_the_atlas_tables_read_the_compiled_readings(tmp_path):
    # the sources' thresholds of a phase diagram sweep the predictors as a scene reads them; only the closed forms
    # (results of VI.C-F's steps, no reading) import a statements module, and the atlas's tables (IX) none
    env = {**os.environ, "SYMFLOAT_CACHE": str(tmp_path)}
    done = subprocess.run([sys.executable, "-c", THRESHOLDS_PROBE], capture_output=True, text=True, check=True,
                          env=env, cwd=tmp_path)
    ran = json.loads(done.stdout.strip().splitlines()[-1])
    assert {"scheeffer-ix", "scheeffer-vi-cf"} <= set(ran["derivations"]) and ran["tables"] == "scheeffer-ix"
    assert ran["statements"] == ["symfloat.derivations.scheeffer_vi_cf.statements"]
