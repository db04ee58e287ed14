"""symfloat: machine-checked re-derivation of classical texts on floating
bodies and centroids.

The names a derivation uses (``from symfloat import Derivation, Eq, Erratum``) come from
:mod:`symfloat.model`, and :func:`check` (one printed formula against its derivation) from
:mod:`symfloat.engine.formula_check`, each imported when first asked for, so that a command that needs
no formula (``symfloat --help``, a scene's solver) does not pay for SymPy.

SymPy keeps 1,000 results of each cached function by default (``SYMPY_CACHE_SIZE``, read once, when SymPy is
first imported); a derivation's checks ask the same questions of far more expressions than that, and checking
every derivation cold costs 6% less with 100,000 (``docs/performance.md``, "Thirteenth round").  Set here, before
anything imports SymPy, unless the environment sets it; the record is the same either way."""
import os
from importlib import import_module

os.environ.setdefault("SYMPY_CACHE_SIZE", "100000")

__version__ = "0.1.0"
_MODEL = ("PRINTED_DIGITS", "Cases", "Derivation", "Eq", "Erratum", "Holds", "Iff", "RealRoots", "Prediction",
          "Printed", "Scene", "Step", "SOURCES", "get_source")
__all__ = [*_MODEL, "check", "__version__"]


def __getattr__(name):
    if name in _MODEL:
        return getattr(import_module(".model", __name__), name)
    if name == "check":
        return import_module(".engine.formula_check", __name__).check
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
