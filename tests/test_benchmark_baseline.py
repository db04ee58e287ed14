"""``benchmarks/baseline.py`` judges each of issue 29's targets by the figure and by the ratio to the issue's
commit measured in the same run, and keeps the row of a target it did not measure this time."""
import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _baseline():
    spec = importlib.util.spec_from_file_location("baseline", ROOT / "benchmarks" / "baseline.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module             # its dataclasses look their module up by name
    sys.path.insert(0, str(ROOT / "benchmarks"))          # it imports its neighbour commands.py, as when run
    try:
        spec.loader.exec_module(module)
    finally:
        sys.path.remove(str(ROOT / "benchmarks"))
    return module


def test_a_target_is_met_by_its_figure_and_its_ratio_or_by_the_ratio_only():
    b = _baseline()
    M = b.Measured
    text = b.section("f44b998", "abc1234", {
        # CPU 100 of 700: ratio 0.14 within 60/326 = 0.18, but 100 s is over the 60 s target
        "verify": (M(wall=720, cpu=700, load=0.1, said=""), M(wall=105, cpu=100, load=0.2, said="")),
        # wall 80 of 900: within both
        "clone": (M(wall=900, cpu=950, load=0.1, said=""), M(wall=80, cpu=85, load=0.1, said="")),
        # wall 500 of 1000: ratio 0.50 over 180/510 = 0.35
        "test": (M(wall=1000, cpu=1900, load=1.0, said="2 failed, 10 passed"),
                 M(wall=500, cpu=950, load=1.0, said="12 passed")),
    })
    rows = {line.split(" | ")[0].lstrip("| "): line for line in text.splitlines() if line.startswith("| ")}
    verify = rows[b.TARGETS[0].label]
    assert "| CPU | 326 | 60 | 700 | 100 | 0.14 | 0.18 | ratio only |" in verify
    assert rows[b.TARGETS[1].label].endswith("| 900 | 80 | 0.09 | 0.24 | yes |")
    assert rows[b.TARGETS[2].label].endswith("| 1000 | 500 | 0.50 | 0.35 | **no** |")
    assert "it said: “2 failed, 10 passed”" in text


def test_a_target_not_measured_keeps_its_row_and_note():
    b = _baseline()
    M = b.Measured
    old = b.section("f44b998", "abc1234", {"test": (M(1000, 1900, 1.0, "x"), M(500, 950, 1.0, "y"))})
    new = b.section("f44b998", "def5678", {"clone": (M(900, 950, 0.1, "a"), M(80, 85, 0.1, "b"))}, old)
    assert "| 1000 | 500 | 0.50 | 0.35 | **no** |" in new and "- test, abc1234 against f44b998: then 1000 s wall" in new
    assert "| 900 | 80 | 0.09 | 0.24 | yes |" in new
    assert new.index("- clone, def5678") < new.index("- test, abc1234")            # in the order of the targets


def test_the_section_is_replaced_in_place_and_the_commands_section_left_alone(tmp_path):
    b = _baseline()
    M = b.Measured
    out = tmp_path / "performance.md"
    out.write_text("# Performance\n\nthe commands' section\n", encoding="utf-8")
    for wall in (500, 400):
        b.write(out, b.section("f44b998", "abc1234", {"test": (M(1000, 1900, 1.0, ""), M(wall, 800, 1.0, ""))}),
                b.BEGIN, b.END)
    text = out.read_text(encoding="utf-8")
    assert text.count(b.BEGIN) == 1 and "| 1000 | 400 | 0.40 |" in text and "| 1000 | 500 |" not in text
    assert text.startswith("# Performance\n\n" + b.BEGIN) and text.endswith("the commands' section\n")


def test_what_a_command_said_is_cut_with_an_ellipsis_and_only_when_it_goes_on():
    # the main job's last line, 140 characters: cut at 120 with "…" (it ended in "; " before, as if whole)
    said = _baseline()._said
    line = "wrote docs/verification.json, docs/errata.json, docs/errata.md, docs/scheeffer-ix-grid.md, " \
           "docs/scheeffer-ix-grid.json; 17 notebooks changed"
    assert said(line).endswith("grid.json …”") and len(said(line)) < len(line)
    assert said("12 passed") == "; it said: “12 passed”" and said("") == ""
