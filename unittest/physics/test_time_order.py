# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""The predictor-corrector integrator is second order in time, with either predictor
(fix keyword predictor midpoint, the default, and extrapolated): the error of an
elastic standing wave at a fixed time falls by 4 each time dt halves."""

import math
import os
import tempfile

import numpy as np

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
DTS = [4e-5, 2e-5, 1e-5, 0.5e-5]    # the last one is the reference
T = 2.0e-3                           # about one period of the wave

failed = passed = 0
for predictor in ("midpoint", "extrapolated"):
    states = []
    with tempfile.TemporaryDirectory() as tmp:
        for dt in DTS:
            gransph_run.run(os.path.join(HERE, "in.elastic_wave"),
                            {"dt": dt, "T": T, "material": os.path.join(HERE, "elastic.gransph"),
                             "fix_options": f"predictor {predictor}"}, cwd=tmp)
            states.append(gransph_run.read_dump(os.path.join(tmp, "wave.dump")))
    ref = states[-1]
    assert np.max(np.abs(ref["vx"])) > 1e-3, "the wave died out: nothing was measured"
    errors = [max(np.max(np.abs(s["vx"] - ref["vx"])) / np.max(np.abs(ref["vx"])),
                  np.max(np.abs(s["f_sph[2]"] - ref["f_sph[2]"])) / np.max(np.abs(ref["f_sph[2]"])))
              for s in states[:-1]]
    orders = [math.log2(errors[k] / errors[k + 1]) for k in range(len(errors) - 1)]
    print(f"predictor {predictor}")
    for dt, e in zip(DTS, errors):
        print(f"  dt {dt:.1e}  relative error {e:.3e}")
    print("  observed orders", " ".join(f"{p:.2f}" for p in orders))
    # Richardson: with the finest run as reference the last order reads high; both must be ~2
    bad = sum(not (1.8 < p < 3.2) for p in orders)
    failed += bad
    passed += len(orders) - bad
print(f"{passed} passed, {failed} failed")
raise SystemExit(1 if failed else 0)
