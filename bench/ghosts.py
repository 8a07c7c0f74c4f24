#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""bench/ghosts.py: what the ranks of a run on several GPUs would send each other, and an
estimate of weak scaling from it (`bench/ghosts.py --help`; the code is
tools/lib/gransph/ghosts.py). This launcher runs it as `python3 -m gransph.ghosts` with
tools/lib on PYTHONPATH."""

import os
import sys

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PATH = os.pathsep.join([os.path.join(TOP, "tools", "lib")] +
                       ([os.environ["PYTHONPATH"]] if os.environ.get("PYTHONPATH") else []))
os.execve(sys.executable, [sys.executable, "-m", "gransph.ghosts"] + sys.argv[1:],
          dict(os.environ, PYTHONPATH=PATH))
