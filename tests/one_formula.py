"""A printed formula judged alone: the derivation's steps trusted, its other formulas and its witnesses left out,
so that a test can read a sentence through the vocabulary (or a mutant of it) and see the verdict it gets."""
import dataclasses

from symfloat.engine.check import check_derivation


def verdict_alone(derivation, name, reading):
    """The verdict on the printed formula *name* of *derivation* read as *reading* (its erratum dropped)."""
    printed = dataclasses.replace(derivation.get_printed(name), reading=reading, erratum=None)
    report = check_derivation(dataclasses.replace(derivation, printed=[printed], witnesses=[]), prove=False,
                              trust_steps=True)
    return report.formulas[0].verdict
