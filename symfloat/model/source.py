"""Sources: the transcribed works symfloat reproduces.

The transcriptions ship with the package (``symfloat/sources``), copied byte
for byte from the project's shared folder, so that every quoted excerpt can be
checked verbatim on any installation.  A source is data: its transcription and
a metadata file ``<key>.source.json`` beside it (key, author, title, year,
language, file, how a place in it is cited, and optionally ``sections``: a regular
expression, one group, matching the heading lines that open its sections and
capturing their names; ``citation``: the rest of the bibliographic record, each a
string — ``place``, ``publisher``, ``series``, ``number`` (e.g. Euler's Eneström
number), ``edition`` (a modern edition), ``note`` — and ``provenance``: where the
transcription comes from).  Adding one adds two files and edits none.
"""
from __future__ import annotations

import json
import re
from dataclasses import dataclass
from functools import cache
from importlib import resources

__all__ = ["Source", "SOURCES", "get_source", "CITATION_FIELDS"]


@dataclass(frozen=True)
class Source:
    """A transcribed work: its key, bibliographic data, file and how a place in it is cited."""

    key: str
    author: str
    title: str
    year: int | None
    language: str
    filename: str
    locators: str = ""
    sections: str = ""          # a heading line's pattern (one group: the section's name); "" for one section
    citation: tuple = ()        # (field, text) pairs of the bibliographic record beyond author, title, year
    provenance: str = ""        # where the transcription comes from

    @property
    def short(self) -> str:
        """The source as a reader cites it briefly: its author's surname (Scheeffer), or for an anonymous text its
        title without a gloss (Hasáb úszása)."""
        return self.title.split(" (")[0] if self.author == "Anonymous" else self.author.split()[-1]

    @property
    def dated(self) -> str:
        """The short name with the year where the text has one (Scheeffer 1902; Hasáb úszása)."""
        return f"{self.short} {self.year}" if self.year else self.short

    def text(self) -> str:
        """The full transcription, exactly as shipped."""
        return _read(self.filename)

    def contains(self, excerpt: str) -> bool:
        """True when *excerpt* occurs verbatim in the transcription."""
        return bool(excerpt) and excerpt in self.text()


_FIELDS = {"key": str, "author": str, "title": str, "year": (int, type(None)), "language": str, "file": str,
           "locators": str}
_OPTIONAL = {"sections": str, "citation": dict, "provenance": str}
CITATION_FIELDS = ("place", "publisher", "series", "number", "edition", "note")


def _folders() -> list:
    """The package's ``sources/``, then those of the libraries ``SYMFLOAT_LIBRARY`` names."""
    from ..errors import InputError
    from ..project import library_folders
    try:
        extra = [folder / "sources" for folder in library_folders() if (folder / "sources").is_dir()]
    except InputError:      # reported by the command line, which checks the variable before any work
        extra = []
    return [resources.files("symfloat").joinpath("sources"), *extra]


@cache
def _read(filename: str) -> str:
    return next(f.joinpath(filename) for f in _folders() if f.joinpath(filename).is_file()).read_text(encoding="utf-8")


def _source(name: str, data) -> Source:
    """A source from its metadata file *name*, every field present and of its type."""
    if not isinstance(data, dict) or not set(_FIELDS) <= set(data) <= set(_FIELDS) | set(_OPTIONAL):
        raise ValueError(f"sources/{name}: the fields must be {', '.join(_FIELDS)} (and optionally "
                         f"{', '.join(_OPTIONAL)})")
    for field, kind in {**_FIELDS, **_OPTIONAL}.items():
        if field in data and (not isinstance(data[field], kind) or isinstance(data[field], bool)):
            raise ValueError(f"sources/{name}: {field} has the wrong type")
    if data.get("sections"):
        try:
            groups = re.compile(data["sections"]).groups
        except re.error as exc:
            raise ValueError(f"sources/{name}: sections is not a regular expression ({exc})") from None
        if groups != 1:
            raise ValueError(f"sources/{name}: sections must capture the section's name in one group")
    citation = data.get("citation", {})
    if not set(citation) <= set(CITATION_FIELDS) or not all(isinstance(v, str) for v in citation.values()):
        raise ValueError(f"sources/{name}: citation's fields are {', '.join(CITATION_FIELDS)}, each a string")
    if name != f"{data['key']}.source.json":
        raise ValueError(f"sources/{name}: the file must be named after its key, {data['key']}.source.json")
    if not any(f.joinpath(data["file"]).is_file() for f in _folders()):
        raise ValueError(f"sources/{name}: no transcription {data['file']}")
    return Source(data["key"], data["author"], data["title"], data["year"], data["language"], data["file"],
                  data["locators"], data.get("sections", ""),
                  tuple((k, citation[k]) for k in CITATION_FIELDS if k in citation), data.get("provenance", ""))


def _discover() -> dict[str, Source]:
    """Every ``sources/<key>.source.json`` with its transcription, in the order of the transcriptions'
    file names (the numbering of ``sources/INDEX.md``)."""
    found = [_source(f.name, json.loads(f.read_text(encoding="utf-8")))
             for folder in _folders() for f in folder.iterdir() if f.name.endswith(".source.json")]
    return {s.key: s for s in sorted(found, key=lambda s: s.filename)}


SOURCES: dict[str, Source] = _discover()


def get_source(key: str) -> Source:
    """The source with *key*; a clear ``KeyError`` names the known keys."""
    try:
        return SOURCES[key]
    except KeyError:
        raise KeyError(f"unknown source {key!r}; known: {', '.join(SOURCES)}") from None
