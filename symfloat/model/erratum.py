"""Errata: what the print (or its transcription) gets wrong, and what is right."""
from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Erratum", "KINDS", "CONFIDENCES", "APPARATUS", "apparatus"]

KINDS = ("transcription", "misprint", "calculation", "consequential", "claim")
CONFIDENCES = ("high", "medium", "low")
# The two apparatus of the edition (docs/errata-kinds.md): the faults of the original print, and the
# corrections of this project's transcription of the scan; apparatus -> (title, its kinds).
APPARATUS = {"original": ("faults of the original", ("misprint", "calculation", "consequential", "claim")),
             "transcription": ("corrections of the transcription", ("transcription",))}


def apparatus(kind: str) -> str:
    """The apparatus an erratum of *kind* belongs to: ``original`` or ``transcription``.

    >>> apparatus("misprint"), apparatus("transcription")
    ('original', 'transcription')
    """
    return next(a for a, (_, kinds) in APPARATUS.items() if kind in kinds)


@dataclass(frozen=True)
class Erratum:
    """A declared fault of one printed formula.

    ``corrected`` is the human-readable correction (LaTeX or words);
    ``corrected_reading`` is its SymPy reading, which the engine must verify
    against the derivation before the erratum is accepted.  ``evidence`` says
    why the fault is of this *kind* (print or scan) and why the correction is
    right; the engine appends the counterexample it finds.  ``same_as`` books a
    repeat: the formula id (``derivation-id/name``) of the erratum that books
    the same fault once; kind and confidence must then be the same
    (:mod:`symfloat.report.repeats` checks it).
    """

    kind: str
    confidence: str
    corrected: str
    evidence: str
    corrected_reading: object = None
    same_as: str = ""

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"erratum kind {self.kind!r} not in {KINDS}")
        if self.confidence not in CONFIDENCES:
            raise ValueError(f"erratum confidence {self.confidence!r} not in {CONFIDENCES}")
        if not self.corrected or not self.evidence:
            raise ValueError("an erratum needs a correction and its evidence")
        if self.same_as and self.same_as.count("/") != 1:
            raise ValueError(f"same_as {self.same_as!r} is not a formula id 'derivation-id/name'")
