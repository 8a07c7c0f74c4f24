# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""fix sph/normals: the normals its keywords set, on the atoms they name, stay with their
atoms across ranks (2 ranks give 1 rank's state: ghosts carry the normals that a wall
with a friction of its own reads) and restart files (a run continued from one equals
the run that went on); arguments (e.g. -k on t 1 -sf kk) go to every run."""

import os
import sys
import tempfile

import numpy as np

import gransph_run

ARGS = sys.argv[1:]
INPUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "in.normals")
NORMALS = ["f_normals[1]", "f_normals[2]", "f_normals[3]"]


def dumps(tmp, ranks):
    out = gransph_run.run(INPUT, ranks=ranks, args=ARGS, cwd=tmp)
    states = {n: gransph_run.read_dump(os.path.join(tmp, n + ".dump")) for n in ("before", "after")}
    gransph_run.run(INPUT, {"stage": "read"}, ranks=ranks, args=ARGS, cwd=tmp)
    states["continued"] = gransph_run.read_dump(os.path.join(tmp, "continued.dump"))
    return out, states


check = gransph_run.Checks()
with tempfile.TemporaryDirectory() as tmp:
    out, one = dumps(tmp, 1)
    _, two = dumps(tmp, 2)

before = one["before"]
n = np.stack([before[c] for c in NORMALS], axis=1)
floor = before["z"] < 0
expected = np.where((floor & (before["x"] < 0.05))[:, None], [0, 0.6, 0.8],
                    np.where(floor[:, None], [0, 0, 1], [0, 0, 0]))
check("each keyword's normal on its atoms, none on the grains",
      np.array_equal(n, expected), f"{int(floor.sum())} dummies, {int((~floor).sum())} grains")
check("the log counts them", "Fix sph/normals: 300 wall normals (0 0 1) for group floor" in out
      and "Fix sph/normals: 150 wall normals (0 0.6 0.8) for group left" in out,
      [l for l in out.splitlines() if l.startswith("Fix sph/normals")])
moved = float(np.max(np.abs(one["after"]["vx"])))
for stage in ("before", "after", "continued"):
    diffs = gransph_run.dump_differences(one[stage], two[stage])
    worst = max(diffs, key=diffs.get)
    check(f"2 ranks = 1 rank ({stage})", moved > 1e-3 and diffs[worst] < 1e-10,
          f"worst {worst} {diffs[worst]:.2e}")
for label, states in (("1 rank", one), ("2 ranks", two)):
    same = all(np.array_equal(states["after"][c], states["continued"][c]) for c in states["after"])
    check(f"a restart continues to the bit, normals and all ({label})", moved > 1e-3 and same,
          f"sand moved at up to {moved:.3f} m/s")
check.finish()
