"""Where the default outputs live: the library of texts being worked on, else the project checkout.

The default outputs (``docs/``, ``notebooks/``, ``build/site``, the cache ``.symfloat-cache``) belong
to the library that ``SYMFLOAT_LIBRARY`` names (the first, when it names several): a library's
records, notebooks, cache and site stay in its own folder and never enter the project's checkout.
Without a library they belong to the symfloat checkout: the directory holding ``pyproject.toml``
above the package (an editable or in-place install), or else the working directory when it is such
a checkout.  Outside one, a command that would write a default output refuses and asks for an
explicit path.
"""
from __future__ import annotations

import os
import re
from pathlib import Path

from .errors import InputError

__all__ = ["project_root", "in_project", "outputs_root", "in_outputs", "GOLDEN", "library_folders",
           "LIBRARY_VARIABLE"]

GOLDEN = ("docs/errata.md", "docs/errata.json", "docs/verification.json")   # the record of everything
_NAME = re.compile(r'^name\s*=\s*"symfloat"\s*$', re.MULTILINE)


def _is_checkout(directory: Path) -> bool:
    try:
        return bool(_NAME.search((directory / "pyproject.toml").read_text(encoding="utf-8")))
    except (OSError, UnicodeDecodeError):
        return False


def project_root() -> Path | None:
    """The symfloat checkout the package belongs to, else the working directory if it is one."""
    above = Path(__file__).resolve().parents[1]
    if _is_checkout(above):
        return above
    here = Path.cwd()
    return here if _is_checkout(here) else None


LIBRARY_VARIABLE = "SYMFLOAT_LIBRARY"


def library_folders() -> list[Path]:
    """Further libraries of texts, from ``SYMFLOAT_LIBRARY`` (folders separated by ``os.pathsep``): each
    holds ``sources/`` (transcriptions and their ``<key>.source.json``) and ``derivations/`` (derivation
    modules, their certificates in ``derivations/proofs/``), found beside the package's own.  A folder
    that does not exist is an :class:`InputError` (the command line checks before any work)."""
    folders = [Path(p) for p in os.environ.get(LIBRARY_VARIABLE, "").split(os.pathsep) if p]
    for folder in folders:
        shown = str(folder) if len(str(folder)) <= 120 else f"{str(folder)[:60]}...{str(folder)[-50:]}"
        try:
            if "\0" in str(folder) or not folder.is_dir():
                raise InputError(f"{LIBRARY_VARIABLE}: {shown} is not a folder")
            folder.resolve(strict=True)
        except OSError as exc:                  # a name too long for the file system, a loop of links
            raise InputError(f"{LIBRARY_VARIABLE}: {shown} is not a usable folder ({exc.strerror or exc})") from None
    return [folder.resolve() for folder in folders]


def _under(root: Path | None, relative: str | os.PathLike) -> Path:
    if root is None:
        raise InputError(f"not inside a symfloat checkout, so there is no default {relative}: "
                         f"give the output path (--output) or run in the checkout")
    return root / relative


def in_project(relative: str | os.PathLike) -> Path:
    """*relative* (``docs/errata.md``) inside the project checkout; outside one, an
    :class:`InputError` that asks for an explicit path."""
    return _under(project_root(), relative)


def outputs_root() -> Path | None:
    """Where default outputs go: the first library of ``SYMFLOAT_LIBRARY``, else the checkout (or ``None``)."""
    folders = library_folders()
    return folders[0] if folders else project_root()


def in_outputs(relative: str | os.PathLike) -> Path:
    """*relative* (``docs/errata.md``) under :func:`outputs_root`; outside a library and a checkout, an
    :class:`InputError` that asks for an explicit path."""
    return _under(outputs_root(), relative)
