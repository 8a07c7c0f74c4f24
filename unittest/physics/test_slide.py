# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Dynamic basal friction: a sand layer of 1 or 2 particles on its level dummy floor, set
sliding at 1 m/s, decelerates at mu g with the friction coefficient of Drucker-Prager's
plane-strain matching (3 alpha_phi = 0.569 for phi = 37 deg, 0.411 for a second material
at 25 deg) within 5%, at dx = 0.02 and 0.01 m, and keeps its height within 0.05 dx.
With the paper's explicit plastic step (plastic paper) the single layer decelerates at
0.45 g at dx = 0.01 (validation/basal_friction/basal_friction.md has the study over speeds and
spacings; the fastest, finest thin layers still fall short)."""

import math
import os
import tempfile

import numpy as np

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
# Chen2019's sand (phi = 37 deg) and the same at phi = 25 deg (sand25.gransph)
MATERIALS = {"Chen2019": ("sand.gransph", 37.0),
             "Sand25": (os.path.join(HERE, "sand25.gransph"), 25.0)}
V0 = 1.0

check = gransph_run.Checks()
with tempfile.TemporaryDirectory() as tmp:
    for material, (materials, phi_deg) in MATERIALS.items():
        phi = math.radians(phi_deg)
        MU = 3.0 * math.tan(phi) / math.sqrt(9.0 + 12.0 * math.tan(phi) ** 2)
        for dx in (0.02, 0.01):
            for layers in (1, 2):
                gransph_run.run(os.path.join(HERE, "in.basal_friction"),
                                {"layers": layers, "dx": dx, "v0": V0, "material": material,
                                 "materials": materials}, cwd=tmp)
                t, v, z, _ = np.loadtxt(os.path.join(tmp, "basal_friction.txt"), unpack=True)
                window = (v < 0.85 * V0) & (v > 0.3 * V0)
                assert window.sum() > 10, "the layer did not slow down through the window"
                mu = -np.polyfit(t[window], v[window], 1)[0] / 9.81
                case = f"{material}, {layers} layer(s), dx {dx}"
                check(f"{case}: decelerates at mu g = {MU:.3f} g within 5%",
                      abs(mu / MU - 1.0) < 0.05, f"{mu:.4f} g")
                check(f"{case}: keeps its height", abs(z[-1] / dx - 0.5 * layers) < 0.05,
                      f"mean height {z[-1] / dx:.3f} dx (at rest {0.5 * layers:.1f})")
check.finish()
