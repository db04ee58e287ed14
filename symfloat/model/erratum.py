"""Errata: what the print (or its transcription) gets wrong, and what is right."""
from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Erratum", "KINDS", "CONFIDENCES", "APPARATUS", "apparatus", "apparatus_in_words"]

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


def apparatus_in_words(kinds) -> str:
    """How many of the errata of *kinds* (a kind each) each apparatus holds, in words.

    >>> apparatus_in_words(["misprint", "claim", "transcription"])
    '2 faults of the original, 1 correction of the transcription'
    """
    found = [apparatus(k) for k in kinds]
    out = []
    for a, (title, _) in APPARATUS.items():
        plural, rest = title.split(" ", 1)                 # "faults", "of the original"
        n = found.count(a)
        out.append(f"{n} {plural[:-1] if n == 1 else plural} {rest}")
    return ", ".join(out)


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
    (:mod:`symfloat.report.repeats` checks it).  A fault printed in several places is one erratum with
    all of them: ``fault`` is its words, verbatim (a part of the quoted excerpt; the whole excerpt when
    empty), ``places`` the locators of its other places, one entry per place
    (``tests/test_repeated_faults.py`` finds every occurrence of the fault in the transcription and
    holds each to the quote's locator or to one of its places).  ``objection`` is the strongest case
    that the print is right (the grammar or usage of its period, a second sense of a word, a convention of
    the author, a reading of a lost figure) and ``answer`` why it does not stand; an erratum whose
    objection cannot be answered is withdrawn or lowered to ``low``.
    """

    kind: str
    confidence: str
    corrected: str
    evidence: str
    corrected_reading: object = None
    same_as: str = ""
    fault: str = ""
    places: tuple[str, ...] = ()
    objection: str = ""
    answer: str = ""

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"erratum kind {self.kind!r} not in {KINDS}")
        if self.confidence not in CONFIDENCES:
            raise ValueError(f"erratum confidence {self.confidence!r} not in {CONFIDENCES}")
        if not self.corrected or not self.evidence:
            raise ValueError("an erratum needs a correction and its evidence")
        if bool(self.objection) != bool(self.answer):
            raise ValueError("an erratum's objection needs its answer, and an answer its objection")
        if self.same_as and self.same_as.count("/") != 1:
            raise ValueError(f"same_as {self.same_as!r} is not a formula id 'derivation-id/name'")
