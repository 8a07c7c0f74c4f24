# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""doc/ builds with Sphinx as LAMMPS builds its manual, without one warning.

sphinx-build -W (every warning an error) builds the pages into a temporary folder, with
LAMMPS' own doc/src given where the build knows it (GRANSPH_LAMMPS_DOC_SRC, or the first
argument), so that a :doc: reference is either one of our pages or a real page of the
LAMMPS manual.  Then the same build is shown to fail: on a copy of doc/ with a reference
to a page that exists nowhere, and on one with a malformed directive.

Sphinx comes from Debian's python3-sphinx and python3-myst-parser (tools/stack/deps.sh installs
them): where they are missing this test fails, it does not skip."""

import os
import shutil
import subprocess
import sys
import tempfile

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DOC = os.path.join(TOP, "doc")
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable


def build(src, out):
    proc = subprocess.run([PYTHON, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
                           "-d", os.path.join(out, ".doctrees"), src, out],
                          capture_output=True, text=True)
    return proc.returncode, (proc.stdout + proc.stderr).strip()


def broken_copy(tmp, name, page, text):
    src = os.path.join(tmp, name)
    shutil.copytree(DOC, src, ignore=shutil.ignore_patterns("_build", "__pycache__"))
    with open(os.path.join(src, page), "a") as f:
        f.write(text)
    return src


def main():
    if len(sys.argv) > 1 and sys.argv[1]:
        os.environ.setdefault("GRANSPH_LAMMPS_DOC_SRC", sys.argv[1])
    lammps_doc = os.environ.get("GRANSPH_LAMMPS_DOC_SRC", "")
    if lammps_doc and not os.path.isdir(lammps_doc):
        print(f"LAMMPS' doc/src {lammps_doc} is missing: references to LAMMPS' pages are "
              "mapped without checking them")
        del os.environ["GRANSPH_LAMMPS_DOC_SRC"]
    for module, package in (("sphinx", "python3-sphinx"), ("myst_parser", "python3-myst-parser")):
        found = subprocess.run([PYTHON, "-c", f"import {module}"], capture_output=True)
        if found.returncode != 0:
            print(f"FAIL: {PYTHON} has no {module}: install Debian's {package} "
                  "(bash tools/stack/deps.sh does)")
            return 1
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        rc, log = build(DOC, os.path.join(tmp, "html"))
        ok = rc == 0
        print(f"{'ok' if ok else 'FAIL'}: doc/ builds with -W" + ("" if ok else ":\n" + log))
        failed += not ok
        pages = [p for p in os.listdir(os.path.join(tmp, "html")) if p.endswith(".html")] if ok else []
        print(f"   {len(pages)} pages")
        # the build can fail: a reference to no page, a malformed directive
        for name, page, text in (
                ("no_such_page", "fix_sph_move.rst",
                 "\nSee :doc:`fix sph/nosuch <fix_sph_nosuch>`.\n"),
                ("bad_directive", "compute_sph_runout.rst",
                 "\n.. code-block:: LAMMPS\n   :no-such-option:\n\n   run 10\n")):
            src = broken_copy(tmp, name, page, text)
            rc, log = build(src, os.path.join(tmp, name + "_html"))
            ok = rc != 0 and ("WARNING" in log or "ERROR" in log)
            said = next((l for l in log.splitlines() if "WARNING" in l or "ERROR" in l), "")
            print(f"{'ok' if ok else 'FAIL'}: a build with {name.replace('_', ' ')} fails"
                  + (f": {said[len(src) + 1:]}" if ok else f" (rc {rc}):\n{log}"))
            failed += not ok
    print("PASS" if not failed else f"{failed} check(s) failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
