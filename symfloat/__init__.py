"""symfloat: machine-checked re-derivation of classical texts on floating
bodies and centroids."""
from .model import SOURCES, Derivation, Erratum, Printed, Step, get_source

__version__ = "0.1.0"
__all__ = ["Derivation", "Erratum", "Printed", "Step", "SOURCES", "get_source", "__version__"]
