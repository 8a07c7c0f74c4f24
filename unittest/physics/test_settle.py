# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""A sand layer initially stress-free settles under gravity to the geostatic vertical stress:
sigma_zz = -rho g depth within 5% at mid-height (periodic sideways, so no wall
friction takes part of the weight)."""

import os
import tempfile

import numpy as np

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
DX, LAYERS, RHO0, G = 0.02, 10, 2450.0, 9.81

with tempfile.TemporaryDirectory() as tmp:
    gransph_run.run(os.path.join(HERE, "in.settle"), {"dx": DX, "layers": LAYERS}, cwd=tmp)
    d = gransph_run.read_dump(os.path.join(tmp, "settle.dump"))

H = DX * LAYERS
mid = np.abs(d["z"] - 0.5 * H) < 0.6 * DX        # the two layers around mid-height
expected = -RHO0 * G * (H - d["z"][mid])         # weight of the grains above, per area
measured = d["f_avg[4]"][mid]                    # sigma_zz
error = np.max(np.abs(measured - expected) / np.abs(expected))
print(f"mid-height sigma_zz {measured.mean():.1f} Pa, rho g depth {expected.mean():.1f} Pa, "
      f"max relative error {error:.3f}")
assert error < 0.05, "vertical stress is not geostatic"
# the layer has come to rest: K0 = nu/(1-nu) for elastic 1D compression, DP allows it
ratio = np.mean(d["f_avg[2]"][mid] / d["f_avg[4]"][mid])
print(f"sigma_xx/sigma_zz = {ratio:.3f} (elastic K0 = {0.3 / 0.7:.3f})")
assert 0.3 < ratio < 0.6, "horizontal stress is not near K0"
print("1 passed, 0 failed")
