# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""GRANSPH's tools in Python: the shared LAMMPS runner (lammps), the measures a study
and the GPU check take from a run (measures), the bench's cases (bench) and its memory
per particle (memory), the validation studies (validate), the GPU check (gpu_check),
terrain surfaces into dummy layers (terrain) and the linear stability of a layer on a
dummy floor (wall_stability).

The commands are tools/terrain, tools/research/validate, tools/research/wall-stability,
tools/gpu/gpu-check and bench/run_bench.py; each runs its module here
(`python3 -m gransph.validate ...` with tools/lib on PYTHONPATH does the same).
"""

import os

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
