"""Derivations, one per source section; each is a package with a ``manifest.toml`` (see
:mod:`symfloat.registry`).  Packages already moved live in the checkout's top-level ``derivations/``,
which joins this package's path; modules still here define ``DERIVATION`` in one file.  Modules whose
name starts with ``_`` are helpers, not derivations.  The ``derivations/`` folders of the libraries
named by ``SYMFLOAT_LIBRARY`` join this package's path (:func:`symfloat.project.library_folders`,
``docs/tutorial.md``).
"""
from pathlib import Path

from ..errors import InputError
from ..project import library_folders

_MOVED = Path(__file__).resolve().parents[2] / "derivations"
if _MOVED.is_dir():
    __path__.append(str(_MOVED))
try:
    __path__ += [str(folder / "derivations") for folder in library_folders() if (folder / "derivations").is_dir()]
except InputError:          # reported by the command line, which checks the variable before any work
    pass
