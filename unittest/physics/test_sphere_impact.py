# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""examples/sphere_impact runs: a steel ball of fix rigid dropped into the sand bed at a
coarse resolution (D / 5, a bed 3 D wide and 1.5 D deep) falls under its own weight
until it meets the sand, enters the bed and is stopped by the grains before tmax (the
run ends once it rests or turns upwards, -var stop deepest) and prints its result line;
the same run on 2 MPI ranks gives the same state. A bad `stop` is refused with a message.

Arguments are passed to LAMMPS (e.g. -k on t 1 -sf kk): every run then takes them, and
the state of the first also equals the plain styles'."""

import os
import sys
import tempfile

import numpy as np

import gransph_run

ARGS = sys.argv[1:]
EXAMPLE = os.path.join(gransph_run.TOP, "examples", "sphere_impact", "in.sphere_impact")
D = 0.0254
DX = D / 5
WIDTH = 3                              # the bed's width in D, its depth half that
VARIABLES = {"dx": DX, "width": WIDTH, "h": 0.1, "stop": "deepest", "dump": 1, "tmax": 0.1}

check = gransph_run.Checks()
states, results = {}, {}
with tempfile.TemporaryDirectory() as tmp:
    runs = [("1 rank", 1, ARGS), ("2 ranks", 2, ARGS)] + ([("plain", 1, [])] if ARGS else [])
    for label, ranks, args in runs:
        out = gransph_run.run(EXAMPLE, VARIABLES, ranks=ranks, args=args, cwd=tmp)
        results[label] = gransph_run.result_line(out)
        states[label] = gransph_run.read_dump(os.path.join(tmp, "sphere_impact.dump"))
        if label == "1 rank":
            t, z_bottom, vz = np.loadtxt(os.path.join(tmp, "sphere_impact.txt"), unpack=True)
    code, error = gransph_run.first_error(tmp, f"variable stop index sideways\n"
                                               f"include {EXAMPLE}\n", args=ARGS)

words = results["1 rank"]
d, steps, t_end = (float(words[words.index(key) + 1]) for key in ("d", "steps", "time"))
# before it comes within the kernel's reach of the sand (0.6 dx of fall) only its weight
# acts: vz falls by g t, from the first step on (the first step itself changes vz by about
# 0.65 g dt more than g dt: about 5e-5 m/s of 1.34, not traced)
falling = z_bottom > 1.5 * DX
falling[0] = False
fall_error = np.max(np.abs(vz[falling] - vz[1] + 9.81 * (t[falling] - t[1])))
check("the ball falls under its own weight", falling.sum() > 5 and fall_error < 1e-9,
      f"{falling.sum()} samples, largest difference {fall_error:.1e} m/s")
check(f"the ball entered the bed and stopped above its floor ({WIDTH / 2:g} D deep)",
      0.1 * DX < d < WIDTH / 2 * D - DX, f"deepest {1e3 * d:.2f} mm, dx {1e3 * DX:.2f} mm")
check("the grains stopped it before tmax (at rest or turning)", t_end < 0.1,
      f"ended at {t_end} s, vz {vz[-1]:.2e} m/s")
diffs = gransph_run.dump_differences(states["1 rank"], states["2 ranks"])
check("2 ranks = 1 rank (the dump's 10 digits)", max(diffs.values()) < 1e-8,
      f"largest relative difference {max(diffs.values()):.1e}")
step_2 = results["2 ranks"][results["2 ranks"].index("steps") + 1]
check("2 ranks stop at the same step", float(step_2) == steps, f"{step_2} and {steps:.0f}")
if ARGS:
    diffs = gransph_run.dump_differences(states["1 rank"], states["plain"])
    check(f"{' '.join(ARGS)} = plain (the dump's 10 digits)", max(diffs.values()) < 1e-8,
          f"largest relative difference {max(diffs.values()):.1e}")
check("a bad stop is refused", code != 0 and "stop is rest or deepest" in error, error)
check.finish()
