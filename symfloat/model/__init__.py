"""The formula model: sources, claims, derivations, printed formulas, errata."""
from .claim import Eq, as_latex, members
from .derivation import PRINTED_DIGITS, Derivation, Printed, Step
from .prediction import Prediction, Predictor, Scene
from .erratum import Erratum
from .relation import Cases, Holds, Iff, RealRoots
from .source import SOURCES, Source, get_source

__all__ = ["Derivation", "Eq", "Printed", "Step", "Erratum", "Source", "SOURCES", "get_source",
           "members", "as_latex", "PRINTED_DIGITS", "Prediction", "Predictor", "Scene",
           "Holds", "Iff", "Cases", "RealRoots"]
