"""The same short column collapse on 1 and 2 MPI ranks gives the same state
(positions, velocities, density, stress) to round-off."""

import os
import sys
import tempfile

import numpy as np

import gransph_run

example = os.path.join(gransph_run.TOP, "examples", "column_collapse", "in.column_collapse")
steps = int(sys.argv[1]) if len(sys.argv) > 1 else 300
args = sys.argv[2:]    # e.g. -k on t 2 -sf kk

states = []
with tempfile.TemporaryDirectory() as tmp:
    for ranks in (1, 2):
        gransph_run.run(example, {"steps": steps, "dump": 1}, ranks=ranks, args=args, cwd=tmp)
        states.append(gransph_run.read_dump(os.path.join(tmp, "column_collapse.dump")))

one, two = states
differences = gransph_run.dump_differences(one, two)
failed = 0
for name, diff in differences.items():
    ok = diff < 1e-9
    failed += not ok
    print(f"{name:12s} max difference / max value = {diff:.2e} {'ok' if ok else 'FAILED'}")
moved = np.max(np.abs(one["vz"]))
assert moved > 1e-3, "the column did not move: nothing was compared"
print(f"{len(differences) - failed} passed, {failed} failed")
sys.exit(1 if failed else 0)
