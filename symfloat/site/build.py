"""``symfloat site``: stage the pages from the committed records, build them with Sphinx, sync the output.

Sphinx with MyST-NB: MyST pages for the edition and the errata (written here from the records),
the executed notebooks rendered as committed (execution off), the numerics report and its figures,
the pictures of the derivations (:mod:`.figures`).
Mathematics is typeset by KaTeX at build time (:mod:`symfloat.site.typeset`; its stylesheet and fonts are
copied into the site); the theme is Sphinx's own
``alabaster``; nothing on a page loads from the network.

A library of texts (``SYMFLOAT_LIBRARY``) gets its own site from its own records: the pages
``about`` (``site.md``) and ``numerics`` (``numerics.md``) are shown when its ``docs/`` has them, and
the criteria of the errata's kinds (``errata-kinds.md``, written once for every erratum) are its own
or else the project's.

Determinism: the pages are staged and built in a temporary folder (Sphinx's environment pickles
and doctrees stay there), the build stamp ``.buildinfo`` is dropped, no date is printed, and the
result is synced into the output folder file by file: an unchanged file is not rewritten, a file
the build no longer makes is removed.  The output folder is the site's alone: a folder that is
not empty and holds no earlier site is refused.
"""
from __future__ import annotations

import os
import shutil
import tempfile
from collections import Counter
from importlib import resources
from io import StringIO
from pathlib import Path

from ..errors import EnvironmentProblem, InputError
from ..leftovers import sweep_orphans
from ..model.source import SOURCES
from ..files import write_atomic
from .edition import MARKS, edition_page, mark_of
from .notebooks import staged_notebook
from .errata_pages import errata_index, erratum_page, facet_pages
from .figures import PAGE as FIGURES, figures_page, notebook_links, pictures
from .records import Records, load_records, slug
from .typeset import katex_dist

__all__ = ["build_site", "stage", "MARKER", "SiteError"]

MARKER = ".symfloat-site"
_LEFT_OUT = {".buildinfo"}
_OPTIONAL = {"about": "site.md", "numerics": "numerics.md"}     # a page shown when the records' docs have it
# The printed formulas counted by their marks on the home page, in a sentence ("82 with a fault of the original")
_COUNTED = {"verified": "verified", "fault": "with a fault of the original",
            "transcription": "with a correction of the transcription", "unverifiable": "not decided",
            "trivial": "with nothing to check"}


class SiteError(EnvironmentProblem):
    """The site cannot be built here (exit status 2)."""


_CONF = '''\
"""Sphinx configuration written by symfloat site (symfloat/site/build.py)."""
project = "symfloat"
extensions = ["myst_nb", "symfloat.site.typeset", "symfloat.site.search", "symfloat.site.navigation"]
myst_enable_extensions = ["dollarmath", "amsmath"]
myst_dmath_double_inline = True
nb_execution_mode = "off"
nb_render_markdown_format = "myst"
nb_merge_streams = True
html_math_renderer = "katex"
html_theme = "alabaster"
html_theme_options = {"show_powered_by": False, "sidebar_width": "220px", "page_width": "1100px"}
html_static_path = ["_static"]
html_css_files = ["katex/katex.min.css", "symfloat.css"]
html_js_files = ["symfloat.js"]
html_copy_source = False
html_show_sourcelink = False
html_show_sphinx = False
html_show_copyright = False
html_last_updated_fmt = None
html_show_search_summary = False    # a hit's summary would fetch its page, which a browser refuses from disk
html_title = "symfloat: the sources, re-derived"
exclude_patterns = ["_build"]
'''


def _asset(name: str) -> str:
    return resources.files("symfloat.site").joinpath("assets", name).read_text(encoding="utf-8")


def _index(records: Records, with_figures: bool, pages: list[str]) -> str:
    s = records.summary
    rows, total = [], Counter()
    for key, source in SOURCES.items():
        fs = [f for f in records.formulas if f["source"] == key]
        if fs:
            n = Counter(mark_of(f, records) for f in fs)
            total.update(n)
            rows.append(f"| [{source.author}, *{source.title}*](edition/{key}.md) | {len(fs)} | "
                        + " | ".join(str(n[m]) for m in MARKS) + " |")
    return "\n".join([
        "# symfloat: the sources, re-derived", "",
        "Every printed formula of the library's texts re-derived step by step, its verdict with the evidence "
        "and the independent numeric witnesses, and the errata in two apparatus: the faults of the original "
        "print, and the corrections of the transcription.", "",
        f"{s['formulas']} printed formulas: " + ", ".join(f"{total[m]} {_COUNTED[m]}" for m in _COUNTED
                                                         if total[m]) + ".", "",
        "| source (annotated edition) | formulas | " + " | ".join(f"{MARKS[m][0]} {MARKS[m][1].split(':')[0]}"
                                                                for m in MARKS) + " |",
        "|---|---:|" + "---:|" * len(MARKS), *rows, "",
        "```{toctree}", ":maxdepth: 1", "", "edition/index", "errata/index", "notebooks/index",
        *([FIGURES] if with_figures else []),
        *(Path(name).stem for name in records.reports), *pages, "```", ""])


def _reports(docs: Path) -> tuple[str, ...]:
    """The Markdown documents the derivations add to the main job's output (``provides("report", ...)``,
    e.g. Scheeffer IX's grid) that are present under *docs*, in the registry's order."""
    from ..registry import provided
    return tuple(r.filename for _, r in provided("report")
                 if r.filename.endswith(".md") and (docs / r.filename).is_file())


def stage(folder: Path, docs: Path, notebooks: Path, kinds: Path | None) -> Records:
    """Write the Sphinx source tree of the site into *folder*; return the records it shows (*kinds*: the
    criteria of the errata's kinds where *docs* has none)."""
    records = load_records(docs, notebooks)
    slugs = [slug(e["id"]) for e in records.errata]
    if len(set(slugs)) != len(slugs):
        raise SiteError("two errata ids give the same page name")
    records.reports = _reports(docs)
    found = pictures(docs)
    pages = {page: (docs / name).read_text(encoding="utf-8") for page, name in _OPTIONAL.items()
             if (docs / name).is_file()}
    pages["errata-kinds"] = (docs / "errata-kinds.md" if (docs / "errata-kinds.md").is_file() else kinds).read_text(
        encoding="utf-8")
    order = [page for page in ("numerics", "errata-kinds", "about") if page in pages]
    files = {"conf.py": _CONF, "index.md": _index(records, bool(found), order),
             "_static/symfloat.css": _asset("symfloat.css"), "_static/symfloat.js": _asset("symfloat.js"),
             **{f"{page}.md": text for page, text in pages.items()}}
    if found:
        files[f"{FIGURES}.md"] = figures_page(found, records.notebooks)
    for name in records.reports:
        files[name] = (docs / name).read_text(encoding="utf-8")
    keys = [k for k in SOURCES if any(f["source"] == k for f in records.formulas)]
    files["edition/index.md"] = "\n".join(
        ["# The annotated edition", "", "One page per source: the transcription with each printed formula "
         "marked by its verdict.", "", "```{toctree}", ":maxdepth: 1", "", *keys, "```", ""])
    for k in keys:
        files[f"edition/{k}.md"] = edition_page(SOURCES[k], records)
    files["errata/index.md"] = errata_index(records)
    files.update({f"errata/{name}": page for name, page in facet_pages(records).items()})
    for e in records.errata:
        files[f"errata/{slug(e['id'])}.md"] = erratum_page(e, records)
    files["notebooks/index.md"] = "\n".join(
        ["# The derivations", "", "The executed notebooks as the main job committed them (not re-run here): each "
         "step with its justification, each printed formula with its reading, verdict and witnesses."
         + (" The phase diagrams and Scheeffer IX's case tables are drawn in [the derivations in pictures]"
            f"(../{FIGURES}.md)." if found else ""), "",
         "```{toctree}", ":maxdepth: 1", "", *records.notebooks, "```", ""])
    drawn = notebook_links(found)
    for d, path in records.notebooks.items():
        source = next(f["source"] for f in records.formulas if f["derivation"] == d)
        files[f"notebooks/{d}.ipynb"] = staged_notebook(path, records, d, SOURCES[source].text(), drawn.get(d, ()))
    for name, text in files.items():
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_text(text, encoding="utf-8")
    if (docs / "figures").is_dir():
        shutil.copytree(docs / "figures", folder / "figures")
    katex = katex_dist()
    (folder / "_static" / "katex" / "fonts").mkdir(parents=True)
    shutil.copy(katex / "katex.min.css", folder / "_static" / "katex")
    for font in sorted((katex / "fonts").glob("*.woff2")):        # the format every current browser takes first
        shutil.copy(font, folder / "_static" / "katex" / "fonts")
    return records


def _sphinx(src: Path, out: Path, doctrees: Path) -> list[str]:
    """Build *src* into *out*; the warnings, one per line."""
    from sphinx.application import Sphinx
    from sphinx.util.console import nocolor
    nocolor()
    warnings = StringIO()
    app = Sphinx(str(src), str(src), str(out), str(doctrees), "html", status=None, warning=warnings,
                 freshenv=True, parallel=0)
    app.build(force_all=True)
    return [w for w in warnings.getvalue().splitlines() if w.strip()]


def _files(folder: Path) -> dict[str, Path]:
    return {p.relative_to(folder).as_posix(): p for p in sorted(folder.rglob("*")) if p.is_file()}


def _sync(built: Path, out: Path) -> list[str]:
    """Make *out* equal to *built*, touching only what differs; the changed names."""
    new, old = _files(built), _files(out)
    changed = []
    for name, path in new.items():
        if name in _LEFT_OUT:
            continue
        data = path.read_bytes()
        if name not in old or old[name].read_bytes() != data:
            (out / name).parent.mkdir(parents=True, exist_ok=True)
            write_atomic(out / name, data)
            changed.append(name)
    for name, path in old.items():
        if (name not in new or name in _LEFT_OUT) and name != MARKER:
            path.unlink()
            changed.append(name)
    for d in sorted((p for p in out.rglob("*") if p.is_dir()), key=lambda p: -len(p.parts)):
        if not any(d.iterdir()):
            d.rmdir()
    return changed


def _check_tools() -> None:
    import importlib.util
    missing = [name for name in ("sphinx", "myst_nb") if importlib.util.find_spec(name) is None]
    if missing:
        raise SiteError(f"the site needs {', '.join(missing)}: pip install 'symfloat[site]'")
    katex_dist()                        # node and KaTeX, or one line saying how to install them


def build_site(out: Path, docs: Path, notebooks: Path, kinds: Path | None, progress=None) -> tuple[list[str], list[str]]:
    """Build the site into *out* from the records of *docs* and *notebooks* (*kinds*: the criteria of the
    errata's kinds where *docs* has none); (the files changed there, Sphinx's warnings)."""
    _check_tools()
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise InputError(f"{out} is a file: the site is written into a folder")
    if out.exists() and any(out.iterdir()) and not (out / MARKER).is_file():
        raise InputError(f"{out} is not empty and holds no earlier site ({MARKER}): give a new or empty folder")
    for needed in (docs / "verification.json", docs / "errata.json"):
        if not needed.is_file():
            raise InputError(f"no {needed}: the site is built from the committed records")
    if not (docs / "errata-kinds.md").is_file() and (kinds is None or not Path(kinds).is_file()):
        raise InputError(f"no {docs / 'errata-kinds.md'}: the errata's pages link to the criteria of their kinds")
    sweep_orphans(tempfile.gettempdir(), "symfloat-site-")      # the build folders of killed builds
    with tempfile.TemporaryDirectory(prefix=f"symfloat-site-{os.getpid()}-") as tmp:
        src, html, doctrees = Path(tmp, "src"), Path(tmp, "html"), Path(tmp, "doctrees")
        src.mkdir()
        progress and progress("staging the pages from the records")
        try:
            stage(src, docs, notebooks, kinds)
        except ValueError as exc:           # an excerpt not in its transcription, a stale waiver
            raise SiteError(f"the records do not match the transcriptions: {exc}") from None
        progress and progress("building with Sphinx")
        warnings = _sphinx(src, html, doctrees)
        out.mkdir(parents=True, exist_ok=True)
        (out / MARKER).write_text("built by symfloat site; the folder is replaced by the next build\n",
                                  encoding="utf-8")
        return _sync(html, out), warnings
