"""The sidebar's table of contents, resolved once per folder and branch instead of once per page.

Sphinx resolves the whole table of contents for every page's sidebar (the theme's ``toctree()``), walking
every document the tables include (some 240 here) to keep the top level: a tenth of the site's build.  Where
the sidebar shows the top level alone (the root's toctrees, or the template's call, have ``maxdepth`` 1),
what a page gets depends only on its folder (the links are relative), on which top-level entry holds it (that
entry is marked current) and on whether the page is a top-level entry itself; pages alike in these share one
resolved fragment.  Any other depth is resolved per page, as Sphinx does.  What a page shows does not change.
"""
from __future__ import annotations

import posixpath

from sphinx.environment.adapters.toctree import _get_toctree_ancestors
from sphinx import addnodes

__all__ = ["setup"]


def _top_level_only(env, kwargs) -> bool:
    """Whether the sidebar's table shows the top level alone."""
    depth = kwargs.get("maxdepth") or 0
    if depth:
        return int(depth) == 1
    return all(t.get("maxdepth", -1) == 1 for t in env.master_doctree.findall(addnodes.toctree))


def _shared_toctree(app, pagename, templatename, context, doctree):
    resolve = context.get("toctree")
    if resolve is None:
        return
    env = app.builder.env
    top = {ref for t in env.master_doctree.findall(addnodes.toctree) for _, ref in t["entries"]}
    resolved = app.builder.__dict__.setdefault("_symfloat_toctrees", {})

    def toctree(**kwargs):
        if not _top_level_only(env, kwargs):
            return resolve(**kwargs)
        branch = frozenset(_get_toctree_ancestors(env.toctree_includes, pagename)) & top
        key = (posixpath.dirname(pagename), branch, pagename if pagename in top | {env.config.root_doc} else None,
               tuple(sorted(kwargs.items())))
        if key not in resolved:
            resolved[key] = resolve(**kwargs)
        return resolved[key]

    context["toctree"] = toctree


def setup(app):
    app.connect("html-page-context", _shared_toctree)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
