"""TeX to MathML at build time, so that the site's mathematics needs no network and no script.

Every formula of the site (the transcriptions' dollars, the records' corrections, the notebooks'
readings) is converted by :mod:`latex2mathml`; the browser lays out MathML itself.  A transcription
keeps its faults, and a few of them are not valid TeX (``y''^2``, a ``\\left.`` whose ``\\right`` the
scan lost).  Such a formula is converted after the smallest repair that makes it TeX, tried in
turn; the MathML keeps the formula as transcribed in its ``alttext``.  A formula no repair helps is
shown as its TeX in a ``<code>`` marked ``tex-unrendered`` and counted (:data:`UNRENDERED`).

The module is also the Sphinx extension that renders MyST's math nodes this way (``setup``).
"""
from __future__ import annotations

import html
import re
from functools import lru_cache

__all__ = ["to_mathml", "UNRENDERED", "setup"]

UNRENDERED: set[str] = set()        # formulas shown as TeX because no repair made them convertible


def _brace_primes(tex: str) -> str:
    """``y''^2`` -> ``{y''}^2`` (latex2mathml takes the primes for a first superscript)."""
    return re.sub(r"([A-Za-z](?:_\{?[A-Za-z0-9]\}?)?'+)\^", r"{\1}^", tex)


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


_REPAIRS = (lambda t: t, _brace_primes, _close_open, lambda t: _close_open(_brace_primes(t)),
            lambda t: _close_open(_unsized(_brace_primes(t))))


_LEAKED = re.compile(r">[^<]*\\[A-Za-z]")


@lru_cache(maxsize=None)
def to_mathml(tex: str, display: bool = False) -> str:
    """*tex* (no dollars) as a ``<math>`` element, or as marked TeX code when it cannot be converted
    (a command latex2mathml does not know would otherwise be shown as text).

    >>> to_mathml("x^2")
    '<math xmlns="http://www.w3.org/1998/Math/MathML" display="inline" alttext="x^2"><mrow><msup><mi>x</mi><mn>2</mn></msup></mrow></math>'
    """
    from latex2mathml.converter import convert

    body = tex.strip()
    for repair in _REPAIRS:
        try:
            out = convert(repair(body), display="block" if display else "inline")
        except Exception:           # latex2mathml raises many kinds on TeX it cannot read
            continue
        if _LEAKED.search(out):     # a command it did not know, passed through as text
            continue
        alt = html.escape(" ".join(body.split()), quote=True)
        return out.replace(">", f' alttext="{alt}">', 1)
    UNRENDERED.add(body)
    return f'<code class="tex-unrendered" title="TeX as transcribed: not convertible">{html.escape(body)}</code>'


# ---------------------------------------------------------------- the Sphinx extension

def _inline(self, node):
    self.body.append(to_mathml(node.astext(), display=False))
    from docutils import nodes
    raise nodes.SkipNode


def _block(self, node):
    from docutils import nodes
    self.body.append(f'<div class="math-display">{to_mathml(node.astext(), display=True)}</div>\n')
    raise nodes.SkipNode


def setup(app):
    """Register the renderer ``mathml`` (choose it with ``html_math_renderer = "mathml"``)."""
    app.add_html_math_renderer("mathml", (_inline, None), (_block, None))
    return {"parallel_read_safe": True, "parallel_write_safe": True}
