"""TeX typeset by KaTeX at build time, so that the site's mathematics needs no network and no script.

Every formula of the site (the transcriptions' dollars, the records' corrections, the notebooks'
readings) is rendered by KaTeX's server-side renderer, run by node (``typeset.js`` beside this
module; KaTeX itself is the checkout's ``node_modules``, installed from ``package.json`` and
``package-lock.json`` by ``npm ci``, which ``make`` runs).  The page gets KaTeX's HTML, laid out
with its stylesheet and fonts (copied into the site), and KaTeX's MathML for assistive technology,
whose annotation keeps the formula as transcribed.  One node process serves a whole build, one
JSON line per formula.

A transcription keeps its faults, and a few of them are not valid TeX (a ``\\left.`` whose
``\\right`` the scan lost, a group the scan cut off).  Such a formula is typeset after the smallest
repair that makes it TeX, tried in turn.  A formula no repair helps is shown as its TeX in a
``<code>`` marked ``tex-unrendered`` and counted (:data:`UNRENDERED`).

The module is also the Sphinx extension that renders MyST's math nodes this way (``setup``).
"""
from __future__ import annotations

import atexit
import html
import json
import os
import re
import shutil
import subprocess
from functools import lru_cache
from pathlib import Path

from ..errors import EnvironmentProblem

__all__ = ["typeset", "UNRENDERED", "katex_dist", "setup", "TypesetterMissing"]

UNRENDERED: set[str] = set()        # formulas shown as TeX because no repair made them typesettable
_SCRIPT = Path(__file__).with_name("typeset.js")


class TypesetterMissing(EnvironmentProblem):
    """node or KaTeX is not installed (exit status 2)."""


def _node_modules() -> Path:
    """The checkout's ``node_modules`` (or ``SYMFLOAT_NODE_MODULES``)."""
    return Path(os.environ.get("SYMFLOAT_NODE_MODULES") or Path(__file__).resolve().parents[2] / "node_modules")


def katex_dist() -> Path:
    """KaTeX's ``dist`` folder (its stylesheet and fonts, copied into the site)."""
    dist = _node_modules() / "katex" / "dist"
    if shutil.which("node") is None:
        raise TypesetterMissing("the site typesets its mathematics with KaTeX under node, and node is not "
                                "installed: install node (>= 18), then run 'npm ci' in the checkout")
    if not (dist / "katex.min.css").is_file():
        raise TypesetterMissing(f"no KaTeX in {dist.parent.parent}: run 'npm ci' in the checkout (or make)")
    return dist


class _Katex:
    """The node process that typesets, started on first use and ended when Python exits."""

    def __init__(self):
        self._process = None

    def __call__(self, tex: str, display: bool) -> dict:
        if self._process is None:
            katex_dist()
            self._process = subprocess.Popen(
                ["node", str(_SCRIPT)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, encoding="utf-8",
                env={**os.environ, "NODE_PATH": str(_node_modules())})
            atexit.register(self.close)
        self._process.stdin.write(json.dumps({"tex": tex, "display": display}) + "\n")
        self._process.stdin.flush()
        line = self._process.stdout.readline()
        if not line:
            raise TypesetterMissing("KaTeX's node process ended without an answer")
        return json.loads(line)

    def close(self):
        if self._process is not None:
            self._process.stdin.close()
            self._process.wait()
            self._process = None


_KATEX = _Katex()

_TOKEN = re.compile(r"\\begin\{[^}]*\}|\\end\{[^}]*\}|\\left\b|\\right\b|\\[{}]|[{}]")


def _close_open(tex: str) -> str:
    """Close what a cut-off formula left open (``{``, ``\\left``, ``\\begin{...}``), innermost first,
    with invisible closers.

    >>> _close_open(r"\\left. \\begin{aligned} \\sqrt{x")
    '\\\\left. \\\\begin{aligned} \\\\sqrt{x } \\\\end{aligned} \\\\right.'
    """
    stack = []
    for m in _TOKEN.finditer(tex):
        t = m.group(0)
        closer = {"{": "}", "\\left": "\\right."}.get(t) or (
            "\\end" + t[6:] if t.startswith("\\begin") else None)
        if closer:
            stack.append(closer)
        elif t in ("}", "\\right") or t.startswith("\\end"):
            want = {"}": "}", "\\right": "\\right."}.get(t, t)
            if stack and stack[-1] == want:
                stack.pop()
    return tex + "".join(" " + c for c in reversed(stack))


def _unsized(tex: str) -> str:
    """Every ``\\left``/``\\right`` dropped (their delimiters kept): for pairs the scan left crossing
    an environment's boundary."""
    return re.sub(r"\\(?:left|right)\s*(?:\.|(?=\\[{}]|[^\\\s]))", "", tex)


def _aligned(tex: str) -> str:
    """Rows with ``&`` or ``\\\\`` outside any environment set in ``aligned`` (a display the
    transcription wrote without its environment)."""
    return f"\\begin{{aligned}} {tex} \\end{{aligned}}"


_REPAIRS = (lambda t: t, _close_open, lambda t: _close_open(_unsized(t)), _aligned,
            lambda t: _aligned(_close_open(t)))


@lru_cache(maxsize=None)
def typeset(tex: str, display: bool = False) -> str:
    """*tex* (no dollars) as KaTeX's HTML and MathML, or as marked TeX code when it cannot be typeset."""
    body = tex.strip()
    for repair in _REPAIRS:
        answer = _KATEX(repair(body), display)
        if "html" in answer:
            return answer["html"]
    UNRENDERED.add(body)
    return f'<code class="tex-unrendered" title="TeX as transcribed: not typesettable">{html.escape(body)}</code>'


# ---------------------------------------------------------------- the Sphinx extension

def _inline(self, node):
    self.body.append(typeset(node.astext(), display=False))
    from docutils import nodes
    raise nodes.SkipNode


def _block(self, node):
    from docutils import nodes
    self.body.append(f'<div class="math-display">{typeset(node.astext(), display=True)}</div>\n')
    raise nodes.SkipNode


def setup(app):
    """Register the renderer ``katex`` (choose it with ``html_math_renderer = "katex"``)."""
    app.add_html_math_renderer("katex", (_inline, None), (_block, None))
    return {"parallel_read_safe": True, "parallel_write_safe": True}
