"""Where the printed formulas a scene or a phase diagram reads are, as a reader cites them (the records name the
derivations that read them)."""
from __future__ import annotations

from .. import registry
from ..model.locator import citation

__all__ = ["cited", "source_of"]


def cited(predictions) -> str:
    """Where the printed formulas of *predictions* are, as a reader cites them: one source's places together,
    in the text's order (``Scheeffer 1902 IV, (79), VI.D, (123), (132a)``), the sources in the order of the
    derivations that read them (the record keeps the derivations' ids)."""
    places: dict[str, list] = {}
    for p in predictions:
        places.setdefault(registry.manifest(p["derivation"]).source, []).extend(p["locators"])
    return "; ".join(citation(source, locators) for source, locators in places.items())


def source_of(derivation_id: str) -> str:
    """The source a derivation reads, named as a reader cites it (``Scheeffer 1902``)."""
    return citation(registry.manifest(derivation_id).source, ())
