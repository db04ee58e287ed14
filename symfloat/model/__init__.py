"""The formula model: sources, claims, derivations, printed formulas, errata.

Each name is imported from its module when first asked for (``from symfloat.model import Derivation``
works as before), so that a module that needs only :mod:`symfloat.model.prediction` (a scene's
solver and its argument parsing) does not pay for SymPy."""
from importlib import import_module

_MODULES = {"claim": ("Eq", "as_latex", "members"),
            "derivation": ("PRINTED_DIGITS", "Derivation", "Printed", "Step"),
            "prediction": ("Prediction", "Predictor", "Scene"),
            "erratum": ("Erratum",),
            "relation": ("Cases", "Holds", "Iff", "RealRoots"),
            "source": ("SOURCES", "Source", "get_source")}
_HOME = {name: module for module, names in _MODULES.items() for name in names}

__all__ = ["Derivation", "Eq", "Printed", "Step", "Erratum", "Source", "SOURCES", "get_source",
           "members", "as_latex", "PRINTED_DIGITS", "Prediction", "Predictor", "Scene",
           "Holds", "Iff", "Cases", "RealRoots"]


def __getattr__(name):
    if name in _HOME:
        return getattr(import_module(f".{_HOME[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
