"""The same short column collapse on 1 and 2 MPI ranks gives the same state
(positions, velocities, density, stress) to round-off; also with the floor's own wall
normals (which ghost dummies must carry) under wall/gradient normal."""

import os
import sys
import tempfile

import numpy as np

import gransph_run

example = os.path.join(gransph_run.TOP, "examples", "column_collapse", "in.column_collapse")
steps = int(sys.argv[1]) if len(sys.argv) > 1 else 300
args = sys.argv[2:]    # e.g. -k on t 2 -sf kk
VARIANTS = [("default", {}),
            ("own wall normals", {"pair_options": "wall/gradient normal", "normals": 1})]

failed = passed = 0
with tempfile.TemporaryDirectory() as tmp:
    for label, variables in VARIANTS:
        states = []
        for ranks in (1, 2):
            gransph_run.run(example, {"steps": steps, "dump": 1, **variables}, ranks=ranks,
                            args=args, cwd=tmp)
            states.append(gransph_run.read_dump(os.path.join(tmp, "column_collapse.dump")))
        one, two = states
        assert np.max(np.abs(one["vz"])) > 1e-3, "the column did not move: nothing was compared"
        for name, diff in gransph_run.dump_differences(one, two).items():
            ok = diff < 1e-9
            passed += ok
            failed += not ok
            print(f"{label:16s} {name:12s} max difference / max value = {diff:.2e} "
                  f"{'ok' if ok else 'FAILED'}")
print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
