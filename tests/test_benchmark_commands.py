"""``benchmarks/commands.py`` rewrites its section of docs/performance.md: a row it did not measure this
time (a skipped command) is kept as the section had it, never dropped."""
import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _commands():
    spec = importlib.util.spec_from_file_location("commands", ROOT / "benchmarks" / "commands.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_a_skipped_command_keeps_its_row_and_note(tmp_path, monkeypatch):
    commands = _commands()
    old = commands.section([("symfloat --help", 0.2, 0.3),
                            ("make test (pytest -q)", 382.4, 180.0, "671 CPU-seconds over both workers")])
    out = tmp_path / "performance.md"
    out.write_text("# Performance\n\n" + old + "\nafter\n", encoding="utf-8")
    monkeypatch.setattr(commands, "rows", lambda skip_run, skip_test, quick: [("symfloat --help", 0.1, 0.3)])
    assert commands.main(["--skip-run", "--skip-test", "--output", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert "| `symfloat --help` | 0.1 | 0.3 | yes |" in text            # measured now: replaced
    assert "| `make test (pytest -q)` | 382.4 | 180 | **no** |" in text  # skipped: kept, with its note
    assert "`make test (pytest -q)`: 671 CPU-seconds over both workers." in text
    assert text.endswith("\nafter\n") and text.count(commands.BEGIN) == 1
