#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""bench/run_bench.py: GRANSPH's throughput on this machine (`bench/run_bench.py --help`;
the code is tools/lib/gransph/bench.py, which runs LAMMPS as tools/research/validate and
tools/gpu/gpu-check do). This launcher runs it as `python3 -m gransph.bench` with
tools/lib on PYTHONPATH."""

import os
import sys

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PATH = os.pathsep.join([os.path.join(TOP, "tools", "lib")] +
                       ([os.environ["PYTHONPATH"]] if os.environ.get("PYTHONPATH") else []))
os.execve(sys.executable, [sys.executable, "-m", "gransph.bench"] + sys.argv[1:],
          dict(os.environ, PYTHONPATH=PATH))
