# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
# Sphinx configuration of GRANSPH's pages, built as LAMMPS builds its manual
# (doc/utils/sphinx-config/conf.py.in of LAMMPS): reStructuredText pages in LAMMPS'
# format, math by MathJax, the LAMMPS lexer for input scripts.  References to LAMMPS'
# own pages (:doc:`fix <fix>`) link to the LAMMPS manual (_ext/lammps_doc.py).
#
#   sphinx-build -W -b html doc /tmp/gransph-doc     # what ctest Docs:sphinx runs

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "_ext"))

project = "GRANSPH"
author = "the GRANSPH authors"
copyright = "GRANSPH authors; GPL-2.0 (LICENSE)"

extensions = ["sphinx.ext.mathjax", "lammps_doc"]
# doc/terrain.md is Markdown, read by MyST (Debian's python3-myst-parser) where present
try:
    import myst_parser  # noqa: F401
    extensions.append("myst_parser")
    source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
except ImportError:
    source_suffix = {".rst": "restructuredtext"}

root_doc = "index"
exclude_patterns = ["_build", "_ext"]
highlight_language = "none"
pygments_style = "sphinx"
html_theme = "alabaster"
html_show_sourcelink = False
html_static_path = []
# MathJax from the LAMMPS manual's own place is not needed: the default CDN URL is only
# written into the HTML, the build itself is offline

# LAMMPS' doc/src, where at hand, so that only its real pages are mapped to its manual
lammps_doc_src = os.environ.get("GRANSPH_LAMMPS_DOC_SRC", "")
