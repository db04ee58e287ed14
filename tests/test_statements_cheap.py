"""A statement module is cheap to import (issue 28, item 2): it builds its SymPy expressions and nothing
else.  Measured as a ratio, not a time: in one fresh process, after a warm-up of SymPy, each statements
module is imported (with its ancestors, untimed) and then executed again twice; the cheaper run's CPU
seconds per SymPy node it builds (the nodes of its steps' claims and its quotes' readings) may not exceed
``LIMIT`` times the cheapest module's.  Building expressions costs 1 to 10 times the cheapest per node
(symbols with many assumptions cost more); integrating and simplifying at import, as Scheeffer I-III's
statements did for four closed forms, cost about 30 times."""
from __future__ import annotations

import json
import subprocess
import sys

from symfloat import registry

LIMIT = 25
# statements that still compute at import, each with what it computes (about 25 to 45 times the cheapest):
# every other module must stay within LIMIT
NOT_YET_CHEAP = {
    "euler-192-219": "its 38 integral steps evaluate their closed forms at import (doit, factor)",
    "euler-220-228": "its 43 integral steps work out their closed forms at import (factor)",
    "scheeffer-vi-ab": "twelve sp.solve calls at import (the density roots, the examples' ratios and limits)",
}
PROBE = r"""
import importlib, json, sys, time
import sympy as sp, symfloat, symfloat.model
from symfloat import registry
x = sp.Symbol("x", positive=True)          # warm SymPy up, so that the first module does not pay for it
sp.simplify(sp.Integral(sp.sqrt(x) * sp.sin(x), (x, 0, 1)).doit() + sp.Matrix([[x, 1], [1, x]]).det())


def size(d):                               # the SymPy nodes of every step's claim and every quote's readings
    from symfloat.model.claim import members
    exprs = [m for s in d.steps for m in members(s.claim)]
    exprs += [m for p in d.printed for r in (p.reading, p.erratum and p.erratum.corrected_reading) if r is not None
              for m in (members(r) if isinstance(r, (tuple, sp.Basic)) else [r])]
    return sum(1 for e in exprs if isinstance(e, sp.Basic) for _ in sp.preorder_traversal(e))


out = {}
for did in registry.select():
    d = registry.statements(did)           # the first import: its ancestors and the byte code, not timed
    module = registry.part(did, "statements")
    runs = []
    for _ in range(2):                     # the module's own work, twice: the cheaper run counts
        t = time.process_time()
        importlib.reload(module)
        runs.append(time.process_time() - t)
    out[did] = (min(runs), size(d))
print(json.dumps(out))
"""


def import_costs() -> dict[str, float]:
    """CPU seconds per SymPy node of executing each derivation's statements, in a fresh process."""
    run = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True, check=True)
    return {did: seconds / max(1, count) for did, (seconds, count) in json.loads(run.stdout).items()}


def test_no_statement_module_costs_much_more_than_the_cheapest():
    costs = import_costs()
    assert set(costs) == set(registry.ids())
    cheapest = min(costs.values())
    costly = {did: round(c / cheapest, 1) for did, c in costs.items() if c > LIMIT * cheapest}
    assert set(costly) <= set(NOT_YET_CHEAP), costly
