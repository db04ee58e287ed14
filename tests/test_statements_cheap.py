"""A statement module is cheap to import (issue 28, item 2): it builds its SymPy expressions and nothing
else.  Measured as a ratio, not a time: in one fresh process (SymPy and the formula model imported first,
the statements in dependency order so that each pays for itself alone), the CPU seconds of each import per
statement it makes (steps and quotes); none may cost more than ``LIMIT`` times the cheapest.  Root
isolation, ``lambdify`` or a witness built at import costs tens to hundreds of times a quote."""
from __future__ import annotations

import json
import subprocess
import sys

from symfloat import registry

LIMIT = 12
PROBE = r"""
import json, sys, time
import sympy, symfloat, symfloat.model
from symfloat import registry
out = {}
for did in registry.select():
    if registry.manifest(did).folder.suffix == ".py":
        continue
    t = time.process_time()
    d = registry.statements(did)
    out[did] = (time.process_time() - t, len(d.steps) + len(d.printed))
print(json.dumps(out))
"""


def import_costs() -> dict[str, float]:
    """CPU seconds per statement of importing each derivation's statements, in a fresh process."""
    run = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True, check=True)
    return {did: seconds / max(1, count) for did, (seconds, count) in json.loads(run.stdout).items()}


def test_no_statement_module_costs_much_more_than_the_cheapest():
    costs = import_costs()
    assert set(costs) == {i for i in registry.ids() if registry.manifest(i).folder.suffix != ".py"}
    cheapest = min(costs.values())
    assert {did: round(c / cheapest, 1) for did, c in costs.items() if c > LIMIT * cheapest} == {}
