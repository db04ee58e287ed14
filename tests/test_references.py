"""Cross-references of every source, resolved and checked against the derivations; point labels of the quotes."""
from pathlib import Path

from symfloat.report.labels import contradicting, contradictions, flagged, flags, points
import json

import pytest

from symfloat.report import references as refs_module
from symfloat.report.references import (STATUSES, check, judged, paragraphs, references, references_markdown, stale,
                                        status_counts, tags)

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def found():
    """Every source's references as the judged entries decide them, found once for the tests that read them
    unchanged (finding Scheeffer's costs about a second each time)."""
    return {s: references(s) for s in refs_module.SOURCES}


@pytest.fixture(scope="module")
def unjudged():
    """The references of Scheeffer, Graefe and Euler as the rules alone decide them (no judged entry)."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(refs_module, "judged", lambda source: ())
        return {s: references(s) for s in ("scheeffer", "graefe", "euler")}


@pytest.fixture(scope="module")
def failed_checks(found):
    """The failed self-checks of every source's references (each reference's and each source's judged entries)."""
    return check([r for s in refs_module.SOURCES for r in found[s]])


def test_tags_are_the_display_numbers():
    t = tags("scheeffer")
    # (2) closes the display "V_1 m > 0. \quad (2)" (line 60 of the transcription); (175) is the last number
    assert t["2"][0] == 60 and "175" in t and "10a" in t
    assert "8" not in t          # (8) is only referred to (tests/test_scheeffer_coverage.py, LACKING)
    assert t["38"][0] == 270     # the display closes with "(38^*)"


def test_eulers_paragraphs_include_those_set_after_a_plate_number():
    # "Tab. IX. §. 217. Ex hac ipsa ..." opens line 105 of the transcription
    assert paragraphs("euler")["217"][0] == 105 and paragraphs("euler")["192"][0] == 7


def test_references_resolve_or_are_flagged(found):
    refs = found["scheeffer"]
    by = {(r["line"], r["number"]): r for r in refs}
    # "(s. 7 u. 8)": no display carries (8) (judged in symfloat/sources/scheeffer.references.json)
    assert by[(88, "7")]["status"] in ("resolved", "plausible") and by[(88, "8")]["status"] == "target lost"
    assert by[(723, "73")]["target_line"] == 721                                                         # "aus 73 auch"
    assert by[(294, "38")]["target_line"] == 270                                                         # "aus 38 und 41"
    assert all(r["status"] in STATUSES for r in refs)
    assert all(r["target_line"] is not None or r["status"] in ("target lost", "figure lost", "wrong") for r in refs)


def test_the_booked_wrong_references_are_found_as_wrong(found, failed_checks):
    # each is an erratum of a derivation module: VI.B, VI.D (two), VI.F, VII, IX.C, X (two)
    wrong = {(r["line"], r["number"]) for r in found["scheeffer"] if r["status"] == "wrong"}
    assert wrong == {(705, "55"), (1068, "55"), (1279, "102a"), (1735, "164"), (1817, "104"), (1833, "19"),
                     (1270, "102b"),     # "nach 102 b)": judged, the second place of the "nach 102 a)" erratum
                     (948, "81"), (960, "81")}   # "Gleichung 81", "(nach 81)": (81) is the upright law, meant (81a)
    assert failed_checks == []          # none unbooked (the check of every source's references, these among them)


def test_eulers_paragraph_references(found):
    # "(§. 222.)" in §225 (line 183) and "quam §. 215. considerauimus" in §236 (line 272)
    refs = {(r["line"], r["number"]): r for r in found["euler"]}
    assert refs[(183, "222")]["target_line"] == 172 and refs[(272, "215")]["target_line"] == 99
    assert all(r["status"] == "resolved" for r in refs.values())
    # the heading of §221 set at the end of line 166 is no reference; nor is "acceptis." before a page number
    assert (166, "221") not in refs and not any(n == "114" for _, n in refs)


def test_a_note_that_reads_a_reference_otherwise_without_an_erratum_fails_the_self_check():
    r = {"source": "x", "line": 1, "reference": "nach 5", "status": "wrong",
         "reason": "UNBOOKED: x/y says \"'5' means (4)\""}
    assert check([r]) and not check([dict(r, reason="erratum x/y")])
    assert check([dict(r, reason="erratum x/y", status="")]) == ["x line 1: 'nach 5': no status"]


def test_a_made_up_label_in_a_quote_is_flagged():
    text = ("## I.\n\nEs sei (Fig. 1) A B die Wasserlinie. Dann ist $A B = 2 a$ und $Q_7 B = a$.\n\n"
            "## II.\n\nNun ist $A B = b$.\n")
    starts = [(0, "opening"), (0, "I"), (text.index("## II"), "II")]
    quote = text.index("Dann ist"), text.index("## II"), "probe"
    found = flagged(text, starts, [quote])
    assert [(f["label"], f["why"]) for f in found] == [("Q7", "never introduced")]   # A, B come with "Fig. 1"
    later = text.index("Nun ist"), len(text), "later"
    assert flagged(text, starts, [later]) == []          # A B carried over from the section before
    assert points("S_1 O H_2") == ("S1", "O", "H2") and points("S₁") == ("S1",)


def test_a_point_introduced_as_two_kinds_is_a_contradiction():
    text = ("## I.\n\nEs sei S der Schwerpunkt des Körpers (Fig. 1). Dann ist $S A = a$.\n\n"
            "Ferner sei M der Mittelpunkt der Kante (Fig. 1).\n")
    starts = [(0, "opening"), (0, "I")]
    assert contradicting(text, starts, []) == []
    # mutation: the next line uses the letter S for the midpoint instead of M
    mutated = text.replace("sei M der", "sei S der")
    found = contradicting(mutated, starts, [])
    assert [(f["label"], f["why"]) for f in found] == [("S", "introduced as the centre of gravity (line 3) and as "
                                                              "the midpoint")]


def test_a_letter_used_as_point_and_quantity_in_one_quote_is_a_contradiction():
    text = "## I.\n\nEs sei (Fig. 1) C D die Tiefe. Dann ist $V = D \\cdot CE$.\n"
    starts = [(0, "opening"), (0, "I")]
    quote = text.index("$V"), len(text), "probe"
    assert contradicting(text, starts, [quote]) == []
    mutated = text.replace("CE", "CD")              # mutation: the segment CD shares its D with the area D
    assert [(f["label"], f["quote"]) for f in contradicting(mutated, starts, [quote])] == [("D", "probe")]
    # a run whose letters are all symbols of the hand reading is a product (N D), not a segment
    product = text.replace("CE", "ND")
    assert contradicting(product, starts, [quote], products={"probe": {"N", "D", "V"}}) == []
    # Euler: M the ship's weight and the end of the ordinate QM in one formula (§201); D the half area and CD
    # the depth of the keel (§243)
    assert {(f["line"], f["label"]) for f in contradictions("euler")} == {(37, "M"), (294, "D")}


def test_labels_flagged_in_the_sources():
    # "v_3 + v_4 = E F" in I (line 72): E and F are named only in II (Fig. 4, line 88)
    assert {(f["line"], f["label"]) for f in flags("scheeffer")} >= {(72, "E"), (72, "F")}


def test_references_report_is_current():
    assert (ROOT / "docs" / "references.md").read_text(encoding="utf-8") == references_markdown(), \
        "docs/references.md is stale: run `symfloat coverage --write` and commit"


def test_a_cited_formula_the_citing_steps_do_not_use_is_suspect(monkeypatch):
    from types import SimpleNamespace

    import sympy as sp

    from symfloat.model.derivation import Step
    from symfloat.report import references as refs
    a, T, U, W, X, Y = sp.symbols("a T U W X Y")
    fake = SimpleNamespace(steps=[
        Step("target", (T, a + 1), "definition", result=T),
        Step("mid", (U, 2 * T), "algebra", uses=("target",), result=U),
        Step("use", (W, U + 1), "algebra", result=W),                 # rests on mid through the quantity U
        Step("other", (X, a), "definition", result=X),
        Step("stray", (Y, X + 1), "algebra", uses=("other",), result=Y)])
    monkeypatch.setattr(refs, "_derivation", lambda did: fake)
    target = refs.anchors("fake", SimpleNamespace(name="(1)", reading=(T, a + 1)))
    assert target == {("fake", "target")}
    assert refs.uses_target(refs.anchors("fake", SimpleNamespace(name="cites-1", reading=(W, U + 1))), target) is True
    # mutation: the citing quote reads a quantity whose steps never touch (1)
    assert refs.uses_target(refs.anchors("fake", SimpleNamespace(name="cites-1", reading=(Y, X + 1))), target) is False
    # a citing quote whose steps rest on nothing is not judged
    assert refs.uses_target(refs.anchors("fake", SimpleNamespace(name="cites-1", reading=(X, a))), target) is None


def test_references_whose_citing_steps_miss_the_target_are_suspect_until_judged(unjudged):
    missed = [r for s in ("scheeffer", "graefe", "euler") for r in unjudged[s] if "do not rest on" in r["reason"]]
    assert missed and all(r["status"] == "suspect" for r in missed)
    decided = {(j["line"], j["number"]) for j in judged("scheeffer")}
    assert {(r["line"], r["number"]) for r in missed} <= decided


def test_no_reference_is_left_undecided(found, failed_checks):
    everything = [r for s in refs_module.SOURCES for r in found[s]]
    assert not [r for r in everything if r["status"] == "suspect"]
    assert failed_checks == []
    counts = status_counts(found["scheeffer"])
    assert counts["references"] == sum(counts[st] for st in STATUSES)


def test_figures_are_lost_not_suspect(found):
    graefe = found["graefe"]
    # "Fig. 1." on line 54 stands alone where the figure was: a caption, not a reference
    assert [(r["line"], r["status"], r["target_line"]) for r in graefe] == [(51, "figure lost", 54),
                                                                            (141, "figure lost", 144)]
    by = {(r["line"], r["number"]): r for r in found["scheeffer"]}
    assert by[(50, "1")]["status"] == "figure lost" and "neither the figure nor its caption" in by[(50, "1")]["reason"]
    assert by[(1891, "21")]["status"] == "figure lost" and by[(1891, "21")]["target_line"] == 1997
    # "(s. Fig. 19)" in X: the legs BH, BG of the cube's face are in Fig. 23, not in the waterplane of VII
    assert by[(1833, "19")]["status"] == "wrong" and "scheeffer-x/fig19-reference" in by[(1833, "19")]["reason"]


def test_a_back_reference_naming_labels_foreign_to_the_figure_is_suspect(unjudged):
    # "wie in Fig. 3" (line 88, section II) names the old water line A_1 B_1, which section I writes "$A, B$ ,"
    # (the subscripts lost by the scan): the label check finds it; a judged entry explains it
    r = next(r for r in unjudged["scheeffer"] if (r["line"], r["number"]) == (88, "3"))
    assert r["status"] == "suspect" and "A1, B1" in r["reason"]


def _entry(**changes):
    base = dict(next(j for j in judged("scheeffer") if (j["line"], j["number"]) == (1088, "95")))
    return dict(base, **changes)


@pytest.mark.parametrize("changes, message", [
    ({}, None),
    ({"line": 1089}, "no such reference"),                            # a line with no reference
    ({"number": "96"}, "no such reference"),
    ({"passage": "ist Null. (95)"}, "is not on line 1082"),            # the passage misquoted
    ({"target": 1102, "passage": "(96)"}, "carries no tag (95)"),     # a passage of another display
    ({"line": 294, "reference": "aus 38 und 41", "number": "38", "target": 270, "passage": "(38^*)"},
     "the rules decide it"),                                          # a reference resolved without judgement
    ({"verdict": "wrong", "erratum": "scheeffer-vii-viii/103b"}, "is no erratum"),
    ({"verdict": "figure lost"}, "of kind equation judged 'figure lost'"),
])
def test_a_stale_judged_entry_fails_the_check(monkeypatch, changes, message):
    entry = _entry(**changes)
    monkeypatch.setattr(refs_module, "judged", lambda source: (entry,) if source == "scheeffer" else ())
    found = stale("scheeffer")
    assert (found == []) if message is None else any(message in m for m in found), found


def _plausible_entry(line, number, **changes):
    base = dict(next(j for j in judged("scheeffer") if (j["line"], j["number"]) == (line, number)))
    return dict(base, **changes)


@pytest.mark.parametrize("line, number, changes, message", [
    # "Aus Gleichung 103a folgt nun" (line 1457): (103a) on line 1172, tg phi_2 = F_1 b (1-s)/(F x_s)
    (1457, "103a", {}, None),
    (1457, "103a", {"target": 1166, "passage": r"V_3 = F \cdot x_s \cdot \operatorname{tg} \varphi_2"},
     "carries no tag (103a)"),                                         # the untagged display just before
    (1457, "103a", {"target": 1188, "passage": r"T_m - V_3 e_3 > 0 \quad (104)"},
     "carries no tag (103a)"),                                         # another numbered display
    (1457, "103a", {"passage": r"\frac{F_1 \cdot b (1 - s)}{F \cdot x_s} \quad (103b)"}, "is not on line 1172"),
    (1457, "103a", {"verdict": "target lost", "target": None, "passage": "Aus Gleichung 103a folgt nun"},
     "the rules found its target"),
    # "Umgekehrt folgt aus 57" (line 499): (57) closes with \tag{57} (line 497), which carries the number too
    (499, "57", {}, None),
    (499, "57", {"passage": r"12 s \cdot (1-s)"}, "carries no tag (57)"),
])
def test_a_judged_plausible_reference_must_name_its_target(monkeypatch, line, number, changes, message):
    entry = _plausible_entry(line, number, **changes)
    monkeypatch.setattr(refs_module, "judged", lambda source: (entry,) if source == "scheeffer" else ())
    found = stale("scheeffer")
    assert (found == []) if message is None else any(message in m for m in found), found


def test_plausible_references_are_judged(found, unjudged):
    # a side unquoted by the derivations: each use judged against its target in scheeffer.references.json
    plausible = {(r["line"], r["number"], r["reference"]) for r in unjudged["scheeffer"]
                 if r["status"] == "plausible"}
    assert plausible and plausible <= {(j["line"], j["number"], j["reference"]) for j in judged("scheeffer")}
    by = {(r["line"], r["number"], r["reference"]): r for r in found["scheeffer"]}
    assert all(by[k]["status"] in ("resolved", "wrong") for k in plausible)
    assert status_counts(found["scheeffer"])["plausible"] == 0
    # "also aus 86" (line 1020) reads (86) in its form (86a), the display with cotg^2(pi/n) it evaluates
    assert by[(1020, "86", "aus 86")]["target_line"] == 1002


def test_a_malformed_judged_entry_is_refused(monkeypatch, tmp_path):
    path = tmp_path / "scheeffer.references.json"
    path.write_text(json.dumps([_entry(verdict="target lost")]), encoding="utf-8")   # a lost target with a line
    monkeypatch.setattr(refs_module, "judged_file", lambda source: path)
    refs_module.judged.cache_clear()
    try:
        with pytest.raises(ValueError, match="malformed"):
            judged("scheeffer")
    finally:
        refs_module.judged.cache_clear()


def test_coverage_json_counts_the_references_by_status(capsys, monkeypatch):
    from symfloat.cli import main
    monkeypatch.chdir(ROOT)
    assert main(["coverage", "euler", "--format", "json"]) == 0
    counts = json.loads(capsys.readouterr().out)["references"]["euler"]
    assert counts == status_counts(references("euler")) and counts["references"] == 2 and counts["resolved"] == 2


def test_a_caption_naming_a_point_the_text_does_not_give_the_figure_is_suspect(monkeypatch, found):
    real = refs_module._captions("scheeffer")
    assert real["5"][0] == 1979                                   # "Fig. 5" alone on its line: no labels
    by = {(r["line"], r["number"]): r for r in found["scheeffer"]}
    assert by[(98, "5")]["status"] == "figure lost"
    # mutation: the caption of Fig. 5 read from the line that names the cube's triangle BHG (line 1785)
    text = refs_module.get_source("scheeffer").text()
    at = text.index("Es stelle Fig. 23")
    fake = dict(real, **{"5": (1979, at, text.index("\n", at))})
    monkeypatch.setattr(refs_module, "_captions", lambda source: fake if source == "scheeffer" else real)
    r = next(r for r in references("scheeffer") if (r["line"], r["number"]) == (98, "5"))
    assert r["status"] == "suspect" and "the caption names" in r["reason"] and "B" in r["reason"]
