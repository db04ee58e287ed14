"""The derivations, one package per source section, installed as ``symfloat.derivations``.

This folder is mapped into the package (``setup.py``), so no module named ``derivations`` lands at
the top of site-packages.  Each package holds a ``manifest.toml`` and its parts
(:mod:`symfloat.registry`, ``docs/writing-derivations.md``).  The ``derivations/`` folders of the
libraries named by ``SYMFLOAT_LIBRARY`` join this package's path
(:func:`symfloat.project.library_folders`, ``docs/tutorial.md``).
"""
from ..errors import InputError
from ..project import library_folders

try:
    __path__ += [str(folder / "derivations") for folder in library_folders() if (folder / "derivations").is_dir()]
except InputError:          # reported by the command line, which checks the variable before any work
    pass
