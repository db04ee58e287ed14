"""Derivation modules, one per source section; each defines ``DERIVATION``.

They use :mod:`symfloat` and nothing else, and only describe steps: importing
them is cheap, the engine does the checking.  Modules whose name starts with
``_`` are helpers, not derivations.  The ``derivations/`` folders of the
libraries named by ``SYMFLOAT_LIBRARY`` join this package's path
(:func:`symfloat.project.library_folders`, ``docs/tutorial.md``).
"""
from ..errors import InputError
from ..project import library_folders

try:
    __path__ += [str(folder / "derivations") for folder in library_folders() if (folder / "derivations").is_dir()]
except InputError:          # reported by the command line, which checks the variable before any work
    pass
