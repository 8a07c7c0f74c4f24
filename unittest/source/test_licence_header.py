# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Every source file of the tree carries the licence notice near its top: the GPL-2.0
block of LAMMPS' form in C++ files, an SPDX line in scripts. Lists the files git tracks
(the tree's top: argument or this file's ../..) and exits 1 naming each one without it.

    python3 test_licence_header.py [TOP]
"""

import os
import subprocess
import sys

CPP = (".cpp", ".h", ".cu")
SCRIPT_DIRS = ("tools", "bench", "unittest", ".ci", "examples")


def is_source(top, path):
    """C++ sources, Python and shell files, and the executable scripts of the tools"""
    if path.startswith(("bench/against/", "validation/")):
        return False
    if path.endswith(CPP + (".py", ".sh")):
        return True
    full = os.path.join(top, path)
    if path.split("/")[0] not in SCRIPT_DIRS or not os.path.isfile(full):
        return False
    with open(full, "rb") as f:
        return f.read(2) == b"#!"


def has_notice(top, path):
    with open(os.path.join(top, path), errors="replace") as f:
        head = f.read(600)
    if path.endswith(CPP):
        return "GNU General Public License, version 2" in head
    return "SPDX-License-Identifier: GPL-2.0-only" in head


def main():
    top = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    files = subprocess.run(["git", "-C", top, "ls-files"], capture_output=True, text=True,
                           check=True).stdout.split()
    sources = [p for p in files if is_source(top, p)]
    missing = [p for p in sources if not has_notice(top, p)]
    for p in missing:
        print(f"no licence notice: {p}")
    print(f"{len(sources) - len(missing)} of {len(sources)} source files carry the licence notice")
    sys.exit(1 if missing or not sources else 0)


if __name__ == "__main__":
    main()
