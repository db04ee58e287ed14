"""docs/tutorial.md, followed as a newcomer would: a further library of texts (docs/tutorial/) read
through SYMFLOAT_LIBRARY, its one deliberate misprint found, and a wrong correction refused."""
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

TUTORIAL = Path(__file__).resolve().parents[1] / "docs" / "tutorial"


def _symfloat(library, cache, *argv):
    env = {**os.environ, "SYMFLOAT_LIBRARY": str(library), "SYMFLOAT_CACHE": str(cache), "SYMFLOAT_QUIET": "1",
           "SYMFLOAT_SLOWDOWN": "1e9"}     # the committed certificates alone decide, as in every test
    return subprocess.run([sys.executable, "-m", "symfloat", *argv], env=env, capture_output=True, text=True,
                          check=False)


def test_the_tutorial_finds_its_misprint(tmp_path):
    out = _symfloat(TUTORIAL, tmp_path, "verify", "cap", "--format", "json")
    assert out.returncode == 0, out.stderr
    verdicts = {f["id"]: f["verdict"] for f in json.loads(out.stdout)["formulas"]}
    # docs/tutorial/sources/cap.txt: the centroid's denominator 4 (3r + h) is the deliberate misprint
    assert verdicts == {"cap-centroid/volume": "verified", "cap-centroid/moment": "verified",
                        "cap-centroid/centroid": "erratum", "cap-centroid/hemisphere": "verified"}
    errata = _symfloat(TUTORIAL, tmp_path, "errata", "cap")
    assert errata.returncode == 0 and "x_s = 3 (2r - h)^2 / (4 (3r - h))" in errata.stdout


def test_the_tutorial_shows_what_the_command_prints(tmp_path):
    # docs/tutorial.md's table of `symfloat verify cap`, row by row: everything but the figures' digits
    # (the hemisphere's witness once said "2 methods" there, where the command says "1 method")
    def rows(text):
        return [re.sub(r"≤ [^,]*,", "≤ …,", line).split() for line in text.splitlines()
                if line.startswith("cap-centroid/")]
    shown = (TUTORIAL.parent / "tutorial.md").read_text(encoding="utf-8").split("symfloat verify cap\n", 1)[1]
    out = _symfloat(TUTORIAL, tmp_path, "verify", "cap")
    assert out.returncode == 0, out.stderr
    assert rows(shown.split("```", 1)[0]) == rows(out.stdout) != []


def test_a_wrong_correction_is_refused(tmp_path):
    library = tmp_path / "library"
    shutil.copytree(TUTORIAL, library)
    module = library / "derivations" / "cap_centroid" / "statements.py"
    text = module.read_text(encoding="utf-8")
    wrong = text.replace("corrected_reading=(X, 3 * (2 * r - h) ** 2 / (4 * (3 * r - h)))",
                         "corrected_reading=(X, 3 * (2 * r - h) ** 2 / (4 * (3 * r + h)))")
    assert wrong != text
    module.write_text(wrong, encoding="utf-8")
    out = _symfloat(library, tmp_path / "cache", "verify", "cap")
    assert out.returncode == 1
    assert "cap-centroid" in out.stdout + out.stderr


def test_a_library_folder_that_is_not_there_is_one_line(tmp_path):
    out = _symfloat(tmp_path / "missing", tmp_path, "verify", "cap")
    assert out.returncode == 2
    assert out.stderr == f"symfloat: SYMFLOAT_LIBRARY: {tmp_path / 'missing'} is not a folder\n"


def test_an_authors_error_is_one_line_naming_the_module(tmp_path):
    # mutation: h loses its sampling interval; the check cannot draw a point, and says where
    library = tmp_path / "library"
    shutil.copytree(TUTORIAL, library)
    module = library / "derivations" / "cap_centroid" / "statements.py"
    text = module.read_text(encoding="utf-8")
    broken = text.replace("domain={r: (1, 3), h: (0, 1)},", "domain={r: (1, 3)},")
    assert broken != text
    module.write_text(broken, encoding="utf-8")
    out = _symfloat(library, tmp_path / "cache", "verify", "cap")
    assert out.returncode == 1 and "Traceback" not in out.stderr
    assert out.stderr.startswith("symfloat: derivation cap-centroid could not be checked: ValueError: symbol h has "
                                 "no sampling interval") and out.stderr.count("\n") == 1
