"""symfloat: machine-checked re-derivation of classical texts on floating
bodies and centroids."""
from .model import (PRINTED_DIGITS, SOURCES, Cases, Derivation, Eq, Erratum, Holds, Iff, Prediction, Printed,
                    RealRoots, Scene, Step, get_source)
from .engine.formula_check import check

__version__ = "0.1.0"
__all__ = ["PRINTED_DIGITS", "Cases", "Derivation", "Eq", "Erratum", "Holds", "Iff", "RealRoots", "Prediction", "Printed", "Scene", "Step", "SOURCES", "check", "get_source", "__version__"]
