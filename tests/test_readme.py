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
    assert r"refuted at h = 1, r = 2: printed \frac{9}{5}, derived \frac{27}{20}" in fresh      # the commands ran, and check's verdict
    assert without_timings(_shown("")) == without_timings(fresh)


# A threshold of the phase diagram, "s = 0.2376907611336 ± 1e-14": its digits and its error come from float64
# searches, whose last bits follow the processor's vector units; another machine prints a value within both errors.
THRESHOLD = re.compile(r"s = ([0-9.]+) ± ([0-9.e-]+)")


def _thresholds(text: str) -> tuple[str, list[tuple[float, float]]]:
    """*text* with every threshold's value and error replaced by a placeholder, and the thresholds."""
    found = [(float(v), float(e)) for v, e in THRESHOLD.findall(text)]
    return THRESHOLD.sub("s = V ± E", text), found


def _same_thresholds(shown: list, fresh: list) -> bool:
    """The thresholds pair off, each pair within both errors and the printed values' last place (1e-13)."""
    return len(shown) == len(fresh) and all(abs(a - b) <= ea + eb + 1e-13 for (a, ea), (b, eb) in zip(shown, fresh))


@pytest.mark.parametrize("name", [name for name in SESSIONS if name])
def test_the_scene_and_phase_examples_are_what_the_commands_print(name):
    fresh = session_text(name)
    assert fresh.count("\n$ ") == len(SESSIONS[name])                    # each command shown with its output
    (shown, shown_thresholds), (fresh, fresh_thresholds) = map(_thresholds, (_shown(name), fresh))
    assert without_timings(shown) == without_timings(fresh)
    assert _same_thresholds(shown_thresholds, fresh_thresholds)


def test_a_threshold_is_the_same_within_its_errors_and_no_further():
    # README's fold at s = 0.2376907611336: printed with 1e-14 on one processor and 2e-13 on another
    text, shown = _thresholds("s = 0.2376907611336 ± 1e-14  tilted")
    fresh = _thresholds("s = 0.2376907611338 ± 2e-13  tilted")[1]
    assert text == "s = V ± E  tilted" and _same_thresholds(shown, fresh)
    assert not _same_thresholds(shown, _thresholds("s = 0.2376907611341 ± 2e-13")[1])
    assert not _same_thresholds(shown, [])


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
