"""A library of texts keeps to its own folder (issue 34, item 3): with SYMFLOAT_LIBRARY its records, notebooks
and cache go under the library's folder, never into the project's checkout; its source may be in any language;
its notebooks re-run from their own folder without the variable."""
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

from symfloat.engine.cache import ReportCache
from symfloat.model import span
from symfloat.project import in_outputs, project_root
from symfloat.site import typeset

TUTORIAL = Path(__file__).resolve().parents[1] / "docs" / "tutorial"


def test_default_outputs_go_under_the_library(tmp_path, monkeypatch):
    monkeypatch.delenv("SYMFLOAT_CACHE", raising=False)
    monkeypatch.setenv("SYMFLOAT_LIBRARY", str(tmp_path))
    assert in_outputs("docs/errata.md") == tmp_path.resolve() / "docs" / "errata.md"
    assert ReportCache().root == tmp_path.resolve() / ".symfloat-cache"
    monkeypatch.delenv("SYMFLOAT_LIBRARY")
    assert in_outputs("docs/errata.md") == project_root() / "docs" / "errata.md"     # without one: the checkout


def test_claim_words_for_every_language_and_a_librarys_own(tmp_path, monkeypatch):
    # the tutorial's source is English; German, Latin, Hungarian were the only lists (KeyError 'English')
    assert span.is_quantitative("the segment floats stable for every height", "English")
    assert not span.is_quantitative("the segment of a sphere", "English")
    assert span.is_quantitative("il y a 0,25 de plus", "French")           # no list: its decimals count
    assert not span.is_quantitative("le segment est stable ici", "French")
    (tmp_path / "sources").mkdir()
    (tmp_path / "sources" / "claim-words.json").write_text(json.dumps({"languages": {"French": "stable"}}))
    monkeypatch.setenv("SYMFLOAT_LIBRARY", str(tmp_path))
    span.claim_words.cache_clear()
    try:
        assert span.is_quantitative("le segment est stable ici", "French")
    finally:
        monkeypatch.delenv("SYMFLOAT_LIBRARY")
        span.claim_words.cache_clear()


def _symfloat(library, *argv, cwd):
    env = {k: v for k, v in os.environ.items() if k != "SYMFLOAT_CACHE"}
    env.update(SYMFLOAT_LIBRARY=str(library), SYMFLOAT_QUIET="1", SYMFLOAT_SLOWDOWN="1e9")
    return subprocess.run([sys.executable, "-m", "symfloat", *argv], env=env, capture_output=True, text=True,
                          check=False, cwd=cwd)


@pytest.fixture(scope="module")
def library(tmp_path_factory):
    """The tutorial's library copied to a folder of its own, its notebook written there by ``symfloat notebooks``
    run from outside it (once for both tests below: the command checks the library's derivation first);
    the library's folder, and the checkout's notebooks before and after the command."""
    where = tmp_path_factory.mktemp("library")
    library = where / "library"
    shutil.copytree(TUTORIAL, library)
    notebooks = project_root() / "notebooks"
    before = sorted(p.name for p in notebooks.iterdir())
    out = _symfloat(library, "notebooks", "cap", cwd=where)
    assert out.returncode == 0, out.stderr
    return library, before, sorted(p.name for p in notebooks.iterdir())


def test_a_library_without_derivations_has_no_run(tmp_path):
    out = _symfloat(tmp_path, "run", cwd=tmp_path)
    assert out.returncode == 2 and out.stderr.startswith("symfloat: SYMFLOAT_LIBRARY: ")
    assert "holds no derivation" in out.stderr and out.stderr.count("\n") == 1 and out.stdout == ""
    assert list(tmp_path.iterdir()) == []                  # refused before anything is made there (a cache folder was)


def test_a_librarys_notebook_and_cache_stay_in_its_folder_and_rerun_there(library):
    library, before, after = library
    written = library / "notebooks" / "cap-centroid.ipynb"
    assert written.is_file() and (library / ".symfloat-cache").is_dir()
    assert after == before                                                             # nothing in the checkout
    # re-run where it lies, without SYMFLOAT_LIBRARY: the notebook finds its library from its folder
    nb = nbformat.read(written, as_version=4)
    env_before = os.environ.pop("SYMFLOAT_LIBRARY", None)
    try:
        NotebookClient(nb, timeout=300, kernel_name="python3",
                       resources={"metadata": {"path": str(written.parent)}}).execute()
    finally:
        if env_before is not None:
            os.environ["SYMFLOAT_LIBRARY"] = env_before
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"]
    assert errors == []


def test_a_librarys_site_is_built_from_its_own_records_under_its_folder(library, tmp_path):
    pytest.importorskip("sphinx", reason="the site extra is not installed (pip install 'symfloat[site]')")
    pytest.importorskip("myst_nb", reason="the site extra is not installed (pip install 'symfloat[site]')")
    try:
        typeset.katex_dist()
    except typeset.TypesetterMissing as exc:
        pytest.skip(str(exc))
    library = library[0]                            # with its notebook written
    checkout = project_root()
    records = sorted((checkout / "docs").rglob("*")), sorted((checkout / "notebooks").iterdir())
    # the main job writes the library's records: its own derivation's alone (it once checked every derivation of
    # the project too, four minutes, and wrote their notebooks and the project's phase diagrams into the library)
    made = _symfloat(library, "run", cwd=tmp_path)
    assert made.returncode == 0, made.stderr
    record = json.loads((library / "docs" / "verification.json").read_text())
    assert record["summary"]["derivations"] == ["cap-centroid"]
    assert sorted(p.name for p in (library / "notebooks").iterdir()) == ["cap-centroid.ipynb"]
    assert not (library / "docs" / "figures").exists()
    assert (sorted((checkout / "docs").rglob("*")), sorted((checkout / "notebooks").iterdir())) == records
    before = (checkout / "build" / "site").is_dir() and sorted((checkout / "build" / "site").rglob("*"))
    out = _symfloat(library, "site", cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    site = library / "build" / "site"
    assert (site / "index.html").is_file()
    assert ((checkout / "build" / "site").is_dir() and sorted((checkout / "build" / "site").rglob("*"))) == before
    index = (site / "index.html").read_text(encoding="utf-8")
    # the library's one source and its one erratum; none of the project's sources, its numerics or its about page
    assert "edition/cap.html" in index and "edition/scheeffer.html" not in index
    assert not (site / "numerics.html").exists() and not (site / "about.html").exists()
    assert (site / "errata" / "cap-centroid-1.html").is_file() and (site / "errata-kinds.html").is_file()
    assert (site / "notebooks" / "cap-centroid.html").is_file()
