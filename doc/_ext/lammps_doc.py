# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""What GRANSPH's pages need of LAMMPS' manual when they are built on their own.

LAMMPS builds its manual with Sphinx from doc/src, where every command has a page and
``:doc:`fix <fix>``` links to it.  GRANSPH's pages live outside that tree, so this
extension gives them what LAMMPS' conf.py gives its own:

* a ``:doc:`` reference to a page that is not one of ours (``fix``, ``pair_coeff``,
  ``Run_options``, ...) becomes a link to that page of the LAMMPS manual,
  https://docs.lammps.org/<name>.html.  Where LAMMPS' own doc/src is at hand
  (``lammps_doc_src`` in conf.py, or the environment variable GRANSPH_LAMMPS_DOC_SRC),
  only names that are pages there are mapped: a misspelt page stays a broken reference,
  and a build with -W fails on it;
* the ``LAMMPS`` Pygments lexer of ``.. code-block:: LAMMPS`` (a small one: commands,
  comments, variables and numbers).
"""

import os
import re

from docutils import nodes
from pygments.lexer import RegexLexer, bygroups
from pygments.token import Comment, Keyword, Name, Number, String, Text, Whitespace

LAMMPS_MANUAL = "https://docs.lammps.org/{}.html"


class LAMMPSLexer(RegexLexer):
    """LAMMPS input scripts: the first word of a line is the command."""
    name = "LAMMPS"
    aliases = ["lammps"]
    filenames = ["in.*"]

    tokens = {
        "root": [
            (r"#.*?$", Comment.Single),
            (r"^(\s*)([a-z_][a-z0-9_/]*)", bygroups(Whitespace, Keyword)),
            (r'"[^"]*"', String),
            (r"'[^']*'", String),
            (r"\$\{[^}]*\}|\$[A-Za-z]|v_[A-Za-z0-9_\[\]]+|[cf]_[A-Za-z0-9_/\[\]]+",
             Name.Variable),
            (r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\b", Number),
            (r"&$", Text),
            (r"\s+", Whitespace),
            (r"[^\s#$\"']+", Text),
        ],
    }


def _lammps_pages(app):
    src = app.config.lammps_doc_src or os.environ.get("GRANSPH_LAMMPS_DOC_SRC", "")
    if not src:
        return None
    if not os.path.isdir(src):
        raise RuntimeError(f"lammps_doc_src {src!r} is not a folder (LAMMPS' doc/src)")
    return {f[:-4] for f in os.listdir(src) if f.endswith(".rst")}


def builder_inited(app):
    app.env.gransph_lammps_pages = _lammps_pages(app)


def missing_reference(app, env, node, contnode):
    """A :doc: reference that is not one of our pages: LAMMPS' page of that name."""
    if node.get("refdomain") != "std" or node.get("reftype") != "doc":
        return None
    target = node["reftarget"].strip("/")
    if not re.fullmatch(r"[A-Za-z0-9_]+", target):
        return None
    pages = getattr(env, "gransph_lammps_pages", None)
    if pages is not None and target not in pages:
        return None       # neither ours nor LAMMPS': Sphinx reports it
    ref = nodes.reference("", "", internal=False, refuri=LAMMPS_MANUAL.format(target),
                          reftitle=f"LAMMPS manual: {target}")
    ref += contnode
    return ref


def setup(app):
    app.add_config_value("lammps_doc_src", "", "env")
    app.add_lexer("LAMMPS", LAMMPSLexer)
    app.connect("builder-inited", builder_inited)
    app.connect("missing-reference", missing_reference)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
