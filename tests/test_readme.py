"""The README's session is what the commands print (symfloat/session.py), timings aside."""
from pathlib import Path

from symfloat.files import without_timings
from symfloat.session import BEGIN, END, session_text

README = Path(__file__).resolve().parents[1] / "README.md"


def test_the_readme_session_is_what_the_commands_print(cache_dir, graefe_reports, monkeypatch):
    monkeypatch.setenv("SYMFLOAT_CACHE", str(cache_dir))
    text = README.read_text(encoding="utf-8")
    shown = text[text.index(BEGIN):text.index(END) + len(END)]
    fresh = session_text()
    assert "refuted at h = 1, r = 2: printed 9/5, derived 27/20" in fresh      # the commands ran, and check's verdict
    assert without_timings(shown) == without_timings(fresh)
