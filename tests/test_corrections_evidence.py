"""The erratum's evidence names the smallest correction the search finds, and whether it is the booked one."""
import dataclasses
import json
import re
from pathlib import Path

import sympy as sp

from symfloat import Derivation, Erratum
from symfloat.engine.check import check_derivation
from symfloat.engine.print_corrections import EVIDENCE_BUDGET

r, z, V = sp.symbols("r z V", positive=True)
SPHERE = r"$$I = \frac{2r}{3} \times 2r^2\pi = \frac{4r^3\pi}{3}.$$"   # graefe §2 sphere, verbatim


def _evidence(printed: str, reading, booked: str) -> str:
    """The evidence of an erratum declared on Graefe's sphere volume printed as *printed* (a mutation of
    the verbatim SPHERE, put in as if printed so), with the booked correction *booked*."""
    d = Derivation(id="test-sphere", source="graefe", title="sphere", locator="§2", domain={r: (1, 3)})
    d.step("volume", sp.Eq(V, sp.Integral(sp.pi * (r**2 - z**2), (z, -r, r))), "definition", result=V)
    d.step("value", (V, 4 * sp.pi * r**3 / 3), "integration")
    d.quote("sphere", "§2 sphere", SPHERE, reading=reading,
            erratum=Erratum("misprint", "high", booked, "test", corrected_reading=sp.Eq(V, 4 * r**3 * sp.pi / 3)))
    d.printed[0] = dataclasses.replace(d.printed[0], excerpt=printed)
    rep = check_derivation(d)
    assert rep.failures == [] and rep.formulas[0].verdict == "erratum"
    return rep.formulas[0].erratum["evidence"]


def test_a_one_digit_booked_correction_is_the_smallest_correction_found():
    # 4/5 for 4/3: the one-digit edit 5 -> 3 is the booked correction
    evidence = _evidence(r"$$V = \frac{4r^3\pi}{5}.$$", sp.Eq(V, 4 * r**3 * sp.pi / 5), r"V = \frac{4r^3\pi}{3}")
    assert (r"The smallest correction found: $V = \frac{4r^3\pi}{3}$ ($5$ → $3$: digit, print-like; confirmed by "
            r"sampling); it is the booked one.") in evidence


def test_a_found_correction_other_than_the_booked_one_says_so():
    # the same edit, where the erratum books another formula (the volume of a cube of side r as a wrong booking)
    evidence = _evidence(r"$$V = \frac{4r^3\pi}{5}.$$", sp.Eq(V, 4 * r**3 * sp.pi / 5), r"V = r^3")
    assert "($5$ → $3$: digit, print-like; confirmed by sampling); it is not the booked one." in evidence


def test_a_print_no_single_edit_repairs_says_that_the_search_found_nothing():
    # 2/5 for 4/3: two digits wrong, no single edit makes the print hold
    evidence = _evidence(r"$$V = \frac{2r^3\pi}{5}.$$", sp.Eq(V, 2 * r**3 * sp.pi / 5), r"V = \frac{4r^3\pi}{3}")
    assert f"The correction search: no edit among the {EVIDENCE_BUDGET} likeliest makes the print hold." in evidence
    assert "smallest correction found" not in evidence


def test_prose_is_not_searched():
    # the print as words: the search cannot read one formula in it and adds no sentence
    evidence = _evidence("Das Volumen ist vier Fünftel", sp.Eq(V, 4 * r**3 * sp.pi / 5), r"V = \frac{4r^3\pi}{3}")
    assert "The correction search" not in evidence and "smallest correction found" not in evidence


def test_a_booked_correction_that_cannot_be_read_is_not_called_another():
    # a booked text the reader cannot read (a macro it does not know): the search neither claims nor denies that
    # its correction is the booked one
    evidence = _evidence(r"$$V = \frac{4r^3\pi}{5}.$$", sp.Eq(V, 4 * r**3 * sp.pi / 5), r"V = \frob{r^3}")
    assert ("($5$ → $3$: digit, print-like; confirmed by sampling); whether it is the booked one cannot be read."
            in evidence)


def test_the_committed_errata_have_no_tex_outside_their_dollars():
    # the search's edits were written bare ("(\\nu → \\mu and v → V: glyph, ...)"), and a reader saw the commands
    errata = json.loads((Path(__file__).resolve().parents[1] / "docs" / "errata.json").read_text(encoding="utf-8"))
    bare = {e["id"]: outside for e in errata for field in ("evidence", "objection", "answer")
            if (outside := re.findall(r"\\[A-Za-z]+", re.sub(r"\$[^$]*\$", "", e.get(field) or "")))}
    assert bare == {}
    assert re.findall(r"\\[A-Za-z]+", re.sub(r"\$[^$]*\$", "", r"($\nu$ → $\mu$: glyph)")) == []   # the reading
    assert re.findall(r"\\[A-Za-z]+", re.sub(r"\$[^$]*\$", "", r"(\nu → \mu: glyph)")) == ["\\nu", "\\mu"]
