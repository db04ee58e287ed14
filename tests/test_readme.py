"""The README's console examples are what the commands print (symfloat/session.py), timings aside."""
import re
from pathlib import Path

import pytest

from symfloat.files import without_timings
from symfloat.session import END, SESSIONS, begin, session_text

README = Path(__file__).resolve().parents[1] / "README.md"


def _shown(name: str) -> str:
    text = README.read_text(encoding="utf-8")
    start = text.index(begin(name))
    return text[start:text.index(END, start) + len(END)]


def test_the_readme_session_is_what_the_commands_print(cache_dir, graefe_reports, monkeypatch):
    monkeypatch.setenv("SYMFLOAT_CACHE", str(cache_dir))
    fresh = session_text()
    assert "refuted at h = 1, r = 2: printed 9/5, derived 27/20" in fresh      # the commands ran, and check's verdict
    assert without_timings(_shown("")) == without_timings(fresh)


@pytest.mark.parametrize("name", [name for name in SESSIONS if name])
def test_the_scene_and_phase_examples_are_what_the_commands_print(name):
    fresh = session_text(name)
    assert fresh.count("\n$ ") == len(SESSIONS[name])                    # each command shown with its output
    assert without_timings(_shown(name)) == without_timings(fresh)


def test_every_console_example_that_shows_output_is_generated():
    """A console block with a line of output (not a command, ``$ ...``, or its continuation) stands inside
    a session block; a list of commands alone may be written by hand."""
    text = README.read_text(encoding="utf-8")
    generated = [(m.start(), text.index(END, m.start())) for m in re.finditer(r"<!-- session[ :(]", text)]
    assert len(generated) == len(SESSIONS)
    for block in re.finditer(r"```console\n(.*?)```", text, re.S):
        lines = block.group(1).splitlines()
        shows_output = any(not (line.startswith("$ ") or (k and lines[k - 1].endswith("\\"))) for k, line in enumerate(lines))
        if shows_output:
            assert any(a < block.start() < b for a, b in generated), block.group(1)[:80]
