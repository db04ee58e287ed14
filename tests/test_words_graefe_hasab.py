"""Graefe and Hasáb read their words through the vocabulary (issue 31, item 2): each sentence that names a
volume, a moment, a centroid or the energy is read from that quantity's definition, so the same sentence with
another quantity's words is refuted; and the repeated faults of issue 31, item 3 are booked once with their
places."""
import dataclasses
import re

import pytest
import sympy as sp

from symfloat.engine.check import check_derivation
from symfloat.model.locator import region
from symfloat.model.source import get_source
from symfloat.model.vocabulary import Is, StableIff
from symfloat.registry import load


def verdicts(d, quotes):
    """The verdicts of *quotes* (name -> (excerpt, words, statement)), each read through *d*'s vocabulary."""
    printed = [dataclasses.replace(d.printed[0], name=name, excerpt=excerpt, reading=d.reads(words, statement),
                                   erratum=None, unreadable="", lost="")
               for name, (excerpt, words, statement) in quotes.items()]
    report = check_derivation(dataclasses.replace(d, printed=printed, witnesses=[]), trust_steps=True, prove=False)
    return {f.id.split("/")[1]: f.verdict for f in report.formulas}


def test_the_ship_rule_reads_a_slab_s_volume_and_moment_from_their_definitions():
    # graefe lines 431-476: 'das Volumen dieses Theiles' is v' = 2m/3 {(a + c)/2 + 2b}, 'das Moment dieses
    # Theiles' m' = 4m²/3 {c/2 + b} (both printed there); the same sentences with the words exchanged are refuted
    d, package = load("graefe-s4-ship-centroid")
    s = package.statements
    v1, m1 = Is(2 * s.m / 3 * ((s.a + s.c) / 2 + 2 * s.b), at=s.SLAB_1), Is(4 * s.m ** 2 / 3 * (s.c / 2 + s.b), at=s.SLAB_1)
    m2 = Is(s.m2_v, at=s.SLAB_2)
    assert verdicts(d, {
        "volume": ("das Volumen dieses Theiles", "Volumen dieses Theiles", v1),
        "moment": ("das Moment dieses Theiles", "Moment dieses Theiles", m1),
        "volume-as-moment": ("das Moment dieses Theiles", "Moment dieses Theiles", v1),
        "moment-as-volume": ("das Volumen dieses Theiles", "Volumen dieses Theiles", m1),
        "second-slab": ("so ist sein Moment", "sein Moment", m2),
        "second-slab-as-volume": ("so ist sein Volumen", "sein Volumen", m2),
        "second-slab-at-the-first": ("so ist sein Moment", "sein Moment", Is(s.m2_v, at=s.SLAB_1)),
    }) == {"volume": "verified", "moment": "verified", "volume-as-moment": "erratum", "moment-as-volume": "erratum",
           "second-slab": "verified", "second-slab-as-volume": "erratum", "second-slab-at-the-first": "erratum"}


def test_the_prismatoid_formula_is_the_centroid_s_not_the_moment_s():
    # graefe line 240: 'Dies ist die Formel für den senkrechten Abstand des Schwerpunktes des Prismatoids', the
    # centroid's distance h (g/2 + D)/((G+g)/2 + 2D); line 228: the moment of the whole is the sum of the parts'
    d, package = load("graefe-s3-prismatoid-centroid")
    s = package.statements
    d_ = d.get_printed("centroid-words")
    formula = Is(d_.reading[1])
    parts = Is(d.get_printed("moment-theorem").reading[1])
    assert verdicts(d, {
        "centroid": ("des Schwerpunktes des Prismatoids", "Schwerpunktes des Prismatoids", formula),
        "moment": ("des Momentes des Prismatoids", "Momentes des Prismatoids", formula),
        "theorem": ("das Moment der Summe", "Moment der Summe", parts),
        "theorem-as-centroid": ("der Schwerpunkt der Summe", "Schwerpunkt der Summe", parts),
    }) == {"centroid": "verified", "moment": "erratum", "theorem": "verified", "theorem-as-centroid": "erratum"}
    assert s.X_A in d.definitions.values()


def test_hasab_reads_the_prism_s_centroid_the_immersed_part_s_and_the_energy():
    # hasab lines 13, 17, 21, 39: the prism's centroid 1/2 - rho above the water upright, (1/2 - rho) cos alpha
    # heeled; the immersed part's centroid rho/2 below it (E_0 / (l g rho)); the total energy 1/2 l g (rho - rho^2)
    # upright.  The centroid of the prism and of the immersed part exchanged, or the upright energy read heeled,
    # are refuted
    d, package = load("hasab")
    s = package.statements
    upright_G, upright_B = Is(s.half - s.rho, at=s.UPRIGHT), Is(s.E0v / (s.l * s.g * s.rho), at=s.UPRIGHT)
    energy = s.half * s.l * s.g * (s.rho - s.rho ** 2)
    assert verdicts(d, {
        "G": ("a súlypont távolsága", "súlypont", upright_G),
        "G-as-B": ("a bemerülő rész súlypontja", "bemerülő rész súlypontja", upright_G),
        "B": ("a bemerülő rész súlypontjának", "bemerülő rész súlypontjának", upright_B),
        "B-as-G": ("a hasáb súlypontjának", "súlypontjának", upright_B),
        "G-heeled": ("a súlypont távolsága", "súlypont", Is((s.half - s.rho) * sp.cos(s.al))),
        "E0": ("a teljes helyzeti energia kezdetben", "teljes helyzeti energia", Is(energy, at=s.UPRIGHT)),
        "E0-heeled": ("a teljes helyzeti energia", "teljes helyzeti energia", Is(energy)),
    }) == {"G": "verified", "G-as-B": "erratum", "B": "verified", "B-as-G": "erratum", "G-heeled": "verified",
           "E0": "verified", "E0-heeled": "erratum"}


def test_the_condition_is_the_stable_equilibrium_s():
    # hasab line 59: rho^2 - rho + 1/6 > 0 is the condition of the stable equilibrium (metacentric height > 0);
    # read as the equilibrium's, it fails at rho = 1/2, where the upright prism is in (unstable) equilibrium
    d, package = load("hasab")
    s = package.statements
    p = d.get_printed("equilibrium-condition")
    assert p.erratum.corrected_reading == d.reads("stabil", StableIff(s.quad > 0, {s.rho: (0, 1)}))
    assert verdicts(d, {
        "stable": ("stabil", "stabil", StableIff(s.quad > 0, {s.rho: (0, 1)})),
        "unstable": ("instabil", "instabil", StableIff(s.quad > 0, {s.rho: (0, 1)})),
    }) == {"stable": "verified", "unstable": "erratum"}


def _places(source, fault, locators):
    text = get_source(source).text()
    regions = [region(source, loc) for loc in locators]
    return [m.start() for m in re.finditer(re.escape(fault), text)
            if not any(r is not None and r[0] <= m.start() < r[1] for r in regions)]


def test_prismaoid_is_one_erratum_with_its_five_places():
    # graefe lines 47, 49, 51, 97, 105: 'Prismaoid' five times in §1, the heading quoted and four places listed
    d, _ = load("graefe-s1-prismatoid-volume")
    p = d.get_printed("prismatoid-name")
    text = get_source("graefe").text()
    lines = [text.count("\n", 0, m.start()) + 1 for m in re.finditer("Prismaoid", text)]
    assert lines == [47, 49, 51, 97, 105]
    assert (p.erratum.fault, len(p.erratum.places)) == ("Prismaoid", 4)
    assert _places("graefe", p.erratum.fault, (p.locator, *p.erratum.places)) == []
    # a place in another section would be left: the places name §1, not §2
    assert _places("graefe", "Prismatoids", ("§1",)) != []


@pytest.mark.parametrize("name", ["slab-c-e", "slab-e-g"])
def test_the_later_slabs_are_repeats_of_the_first_slab_s_misprint(name):
    # graefe lines 150-158: each slab is the prismatoid formula applied anew with 2m for 2m/3, the fault of I'
    d, _ = load("graefe-s2-volumes-simpson")
    first, repeat = d.get_printed("slab-a-c").erratum, d.get_printed(name).erratum
    assert repeat.same_as == "graefe-s2-volumes-simpson/slab-a-c"
    assert (repeat.kind, repeat.confidence) == (first.kind, first.confidence) == ("misprint", "high")
    assert all(d.get_printed(n).erratum.kind == "consequential" for n in ("sum-1", "sum-2", "simpson-rule"))
