"""The /kk styles on 2 OpenMP threads reproduce the plain styles to round-off:
positions, velocities, density and stress after a few hundred steps of the
column collapse (elastoplastic, dummy walls; also with the walls' velocity along
their normal only, from the dummies' centre or their own normals, with a floor of
a friction of its own, with the predictor extrapolated, and with the grains' sums in
single precision, also on a floor with a friction of its own), the jet collision
(phase change), and what compute sph/stress/atom makes of the column's stress."""

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
    ("column_collapse", {"steps": 300, "fix_options": "predictor extrapolated"}),
    ("column_collapse", {"steps": 300, "pair_options": "precision mixed"}),
    ("column_collapse", {"steps": 300, "pair_options": "precision mixed wall/friction floor 20",
                         "normals": 1}),
    ("jet_collision", {"steps": 300, "dx": 0.016}),
]
KOKKOS = ["-k", "on", "t", "2", "-sf", "kk"]

check = gransph_run.Checks()
with tempfile.TemporaryDirectory() as tmp:
    for case, variables in CASES:
        example = os.path.join(EXAMPLES, case, f"in.{case}")
        states = []
        for args in ([], KOKKOS):
            out = gransph_run.run(example, {**variables, "dump": 1}, args=args, cwd=tmp)
            assert not args or "sph/granular/kk" in out, "the Kokkos pair style was not used"
            states.append(gransph_run.read_dump(os.path.join(tmp, f"{case}.dump")))
        plain, kk = states
        assert np.max(np.abs(plain["vx"])) > 1e-3, "nothing moved: nothing was compared"
        options = " ".join(variables.get(k, "") for k in ("pair_options", "fix_options")).strip()
        label = case + (f" ({options})" if options else "") + \
            (" own normals" if variables.get("normals") else "") + " plain - kk"
        gransph_run.check_same_state(check, label, plain, kk, 1e-10)
check.finish()
