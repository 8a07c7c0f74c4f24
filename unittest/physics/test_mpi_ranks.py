# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
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

check = gransph_run.Checks()
with tempfile.TemporaryDirectory() as tmp:
    for label, variables in VARIANTS:
        states = []
        for ranks in (1, 2):
            try:
                gransph_run.run(example, {"steps": steps, "dump": 1, **variables}, ranks=ranks,
                                args=args, cwd=tmp)
            except RuntimeError as error:
                # LAMMPS 29Sep2021's Kokkos crashes passing the normals to ghosts: the
                # pair style must refuse them there, and only there
                output = gransph_run.LAST_OUTPUT
                expected = "normals" in variables and args and "LAMMPS (29 Sep 2021" in output
                refused = "per-atom wall normals need LAMMPS newer than 29 Sep 2021" in output
                check(f"{label}, {ranks} ranks refused by LAMMPS 29Sep2021 + Kokkos",
                      bool(expected) and refused, str(error))
                break
            states.append(gransph_run.read_dump(os.path.join(tmp, "column_collapse.dump")))
        if len(states) < 2:
            continue
        one, two = states
        assert np.max(np.abs(one["vz"])) > 1e-3, "the column did not move: nothing was compared"
        gransph_run.check_same_state(check, f"{label} 1 - 2 ranks", one, two, 1e-9)
check.finish()
