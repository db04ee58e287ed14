"""Sources: the transcribed works symfloat reproduces.

The transcriptions ship with the package (``symfloat/sources``), copied byte
for byte from the project's shared folder, so that every quoted excerpt can be
checked verbatim on any installation.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from importlib import resources

__all__ = ["Source", "SOURCES", "get_source"]


@dataclass(frozen=True)
class Source:
    """A work from ``sources/INDEX.md``: its key, bibliographic data and file."""

    key: str
    author: str
    title: str
    year: int | None
    language: str
    filename: str

    def text(self) -> str:
        """The full transcription, exactly as shipped."""
        return _read(self.filename)

    def contains(self, excerpt: str) -> bool:
        """True when *excerpt* occurs verbatim in the transcription."""
        return bool(excerpt) and excerpt in self.text()


@cache
def _read(filename: str) -> str:
    return resources.files("symfloat").joinpath("sources", filename).read_text(encoding="utf-8")


SOURCES: dict[str, Source] = {
    s.key: s
    for s in (
        Source("scheeffer", "Eugen Scheeffer", "Über stabiles Schwimmen homogener Körper", 1902,
               "German", "000_1e9760952686f295.txt"),
        Source("graefe", "V. v. Graefe",
               "Ueber eine allgemeine Formel zur Bestimmung des Schwerpunctes von Körpern", 1866,
               "German", "001_7d23c66f8db6d29e.txt"),
        Source("euler", "Leonhard Euler", "Scientia navalis, Cap. III: De stabilitate situs aequilibrii",
               1749, "Latin", "002_9b5669e726e363a9.txt"),
        Source("metazentrum", "(web lesson)", "Auftrieb Stabilität", None, "German",
               "003_02a33f8f897eb570.txt"),
        Source("hasab", "(solved problem)", "Hasáb úszása (long square prism)", None, "Hungarian",
               "004_212cb4aaa01f7969.txt"),
    )
}


def get_source(key: str) -> Source:
    """The source with *key*; a clear ``KeyError`` names the known keys."""
    try:
        return SOURCES[key]
    except KeyError:
        raise KeyError(f"unknown source {key!r}; known: {', '.join(SOURCES)}") from None
