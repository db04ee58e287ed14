"""Offline HTML of the notebooks: ``jupyter nbconvert --to html`` with the mathematics as MathML.

nbconvert's HTML loads MathJax (and require.js, Mermaid) from a CDN.  :func:`install` (run by
``make .venv/.installed``) puts into the environment a template ``symfloat`` (the lab template
without those scripts, in ``share/jupyter/nbconvert/templates``) and a configuration
(``etc/jupyter/jupyter_nbconvert_config.json``) that makes it the HTML exporter's template and adds
:class:`OfflineMath`, which writes every ``$…$`` and ``$$…$$`` of the Markdown cells as MathML
(latex2mathml) when the notebook is converted.  Browsers typeset MathML themselves, so the page
needs nothing from the network.  The files are in ``symfloat/report/nbconvert/``.
"""
from __future__ import annotations

import html
import re
import shutil
import sys
from pathlib import Path

from latex2mathml.converter import convert
from nbconvert.preprocessors import Preprocessor

__all__ = ["OfflineMath", "mathml", "template_folder", "install"]

_MATH = re.compile(r"\$\$(?P<display>.+?)\$\$|\$(?P<inline>[^$\n]+?)\$", re.S)
_CODE = re.compile(r"(```.*?```|`[^`\n]*`)", re.S)


def template_folder() -> Path:
    """The folder holding the nbconvert template ``symfloat`` and the configuration that selects it."""
    return Path(__file__).resolve().parent / "nbconvert"


def install(prefix: str | Path = sys.prefix) -> None:
    """Put the template and the configuration into the environment at *prefix* (Jupyter reads its
    configuration from ``<prefix>/etc/jupyter`` and its templates from ``<prefix>/share/jupyter``).
    Refuses to replace a different nbconvert configuration already there."""
    prefix, here = Path(prefix), template_folder()
    config = prefix / "etc" / "jupyter" / "jupyter_nbconvert_config.json"
    ours = (here / "jupyter_nbconvert_config.json").read_text(encoding="utf-8")
    if config.is_file() and config.read_text(encoding="utf-8") != ours:
        raise RuntimeError(f"{config} exists with another configuration: merge {here / config.name} into it")
    config.parent.mkdir(parents=True, exist_ok=True)
    config.write_text(ours, encoding="utf-8")
    shutil.copytree(here / "symfloat", prefix / "share" / "jupyter" / "nbconvert" / "templates" / "symfloat",
                    dirs_exist_ok=True)


def _math(match: re.Match) -> str:
    display = match["display"] is not None
    tex = (match["display"] if display else match["inline"]).strip()
    try:
        out = convert(tex, display="block" if display else "inline")
    except Exception:        # noqa: BLE001 - a formula latex2mathml cannot read stays readable as its TeX
        out = f"<code>{html.escape(tex)}</code>"
    return f"\n\n<div class=\"math\">{out}</div>\n\n" if display else out


_HEADING = re.compile(r"(?m)^(#{1,6}) (.*\$.*)$")


def _heading(match: re.Match) -> str:
    """A Markdown heading with a formula as an HTML heading (nbconvert keeps only the text of a Markdown
    heading's markup, so its MathML would lose its layout)."""
    level, text, out, at = len(match[1]), match[2], [], 0
    for m in _MATH.finditer(text):                 # the words escaped for HTML, the formulas as MathML
        out += [html.escape(text[at:m.start()], quote=False), _math(m)]
        at = m.end()
    return f"<h{level}>{''.join(out)}{html.escape(text[at:], quote=False)}</h{level}>"


def mathml(markdown: str) -> str:
    """*markdown* with its ``$…$`` and ``$$…$$`` formulas as MathML (code spans left alone).

    >>> mathml("the arm $m$ and `$x$`")
    'the arm <math xmlns="http://www.w3.org/1998/Math/MathML" display="inline"><mrow><mi>m</mi></mrow></math> and `$x$`'
    >>> mathml("### Step 2: the value of $e$")
    '<h3>Step 2: the value of <math xmlns="http://www.w3.org/1998/Math/MathML" display="inline"><mrow><mi>e</mi></mrow></math></h3>'
    >>> "&gt;" in mathml("### $a > 0$ & more")
    False
    """
    markdown = _HEADING.sub(_heading, markdown)
    return "".join(part if _CODE.fullmatch(part) else _MATH.sub(_math, part) for part in _CODE.split(markdown))


class OfflineMath(Preprocessor):
    """The Markdown cells' formulas as MathML (see the module docstring)."""

    def preprocess_cell(self, cell, resources, index):
        if cell.cell_type == "markdown":
            cell.source = mathml(cell.source)
        return cell, resources
