"""symfloat: machine-checked re-derivation of classical texts on floating
bodies and centroids."""
from .model import PRINTED_DIGITS, SOURCES, Derivation, Eq, Erratum, Prediction, Printed, Scene, Step, get_source

__version__ = "0.1.0"
__all__ = ["PRINTED_DIGITS", "Derivation", "Eq", "Erratum", "Prediction", "Printed", "Scene", "Step", "SOURCES", "get_source", "__version__"]
