# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""The /kk styles on 2 OpenMP threads reproduce the plain styles to round-off:
positions, velocities, density and stress after a few hundred steps of the
column collapse (elastoplastic, dummy walls; also with the walls' velocity along
their normal only, from the dummies' centre or their own normals, with a floor of
a friction of its own, with the predictor extrapolated, and with the grains' sums in
single precision, also on a floor with a friction of its own), the jet collision
(phase change), what compute sph/stress/atom makes of the column's stress, and the
pressure of the artificial viscosity that compute sph/visc/atom reports."""

import os
import tempfile

import numpy as np

import gransph_run

EXAMPLES = os.path.join(gransph_run.TOP, "examples")
CASES = [
    ("column_collapse", {"steps": 300}),
    ("column_collapse", {"steps": 300, "pair_options": "wall/gradient normal"}),
    ("column_collapse", {"steps": 300, "pair_options": "wall/gradient normal", "normals": 1}),
    ("column_collapse", {"steps": 300, "pair_options": "wall/friction floor 20", "normals": 1}),
    ("column_collapse", {"steps": 300, "pair_options": "wall/friction floor 30 wall/friction/hold stick",
                         "normals": 1}),
    ("column_collapse", {"steps": 300, "fix_options": "predictor extrapolated"}),
    ("column_collapse", {"steps": 300, "pair_options": "precision mixed"}),
    ("column_collapse", {"steps": 300, "pair_options": "precision mixed wall/friction floor 20",
                         "normals": 1}),
    ("jet_collision", {"steps": 300, "dx": 0.016}),
]
KOKKOS = ["-k", "on", "t", "2", "-sf", "kk"]


def dump_of(case, variables, args, cwd):
    """Run one of CASES with the given command-line arguments; its final state."""
    example = os.path.join(EXAMPLES, case, f"in.{case}")
    gransph_run.run(example, {**variables, "dump": 1}, args=args, cwd=cwd)
    return gransph_run.read_dump(os.path.join(cwd, f"{case}.dump"))


def label_of(case, variables):
    options = " ".join(variables.get(k, "") for k in ("pair_options", "fix_options")).strip()
    return case + (f" ({options})" if options else "") + \
        (" own normals" if variables.get("normals") else "")


def main():
    check = gransph_run.Checks()
    with tempfile.TemporaryDirectory() as tmp:
        for case, variables in CASES:
            plain = dump_of(case, variables, [], tmp)
            kk = dump_of(case, variables, KOKKOS, tmp)
            assert "sph/granular/kk" in gransph_run.LAST_OUTPUT, "the Kokkos pair style was not used"
            assert np.max(np.abs(plain["vx"])) > 1e-3, "nothing moved: nothing was compared"
            gransph_run.check_same_state(check, label_of(case, variables) + " plain - kk", plain, kk, 1e-10)
    check.finish()


if __name__ == "__main__":
    main()
