# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Thin layers set sliding on a level dummy floor: validation/basal_friction/."""

import math
import os

from .. import TOP
from .common import MU_PLANE_STRAIN, wall_time


def basal_friction(args, report):
    """Layers of 1 to 8 particles set sliding on a level dummy floor: the deceleration,
    fitted while the layer slows from 0.85 to 0.3 of its initial speed, as a friction
    coefficient a / g, against the model's mu; and the layer's mean height."""
    import numpy as np
    inp = os.path.join(TOP, "unittest", "physics", "in.basal_friction")
    report.append("## Dynamic basal friction of thin layers\n")
    report.append("A layer of sand (Drucker-Prager, plane-strain matching, "
                  f"mu = 3 alpha_phi = {MU_PLANE_STRAIN:.3f}) on a level floor of dummy particles, "
                  "periodic sideways, settled under gravity and set sliding at v0: its deceleration "
                  "a / g, fitted while it slows from 0.85 v0 to 0.3 v0, is the friction coefficient "
                  "the floor gives it; `z` is its mean height above the floor in spacings after "
                  "the slide (at rest: layers / 2). While it is faster than v0 / 2, the share of the "
                  "samples (every 20 steps) in which the layer is stress-free and its largest mean "
                  "pressure, against the mean pressure its weight gives (rho g dx layers / 2), show "
                  "whether it slides or hops over the floor's lattice of dummy particles. Input: "
                  "unittest/physics/in.basal_friction.\n")
    report.append("| v0 (m/s) | dx (m) | layers | v0 / sqrt(g dx) | a / g | against mu | z / dx | "
                  "stress-free | largest p / weight's | steps | wall time (s) |")
    report.append("|---|---|---|---|---|---|---|---|---|---|---|")
    for v0 in (0.5, 1.0, 2.0):
        for dx in (0.02, 0.01, 0.005):
            for layers in (1, 2, 4, 8):
                variables = {"v0": v0, "dx": dx, "layers": layers}
                if args.pair_options:
                    variables["pair_options"] = args.pair_options
                if args.fix_options:
                    variables["fix_options"] = args.fix_options
                _, workdir = args.runner.run("basal_friction", variables, 1,
                                 f"basal_friction{args.suffix}_v{v0}_dx{dx}_n{layers}",
                                 input_file=inp)
                t, v, z, p = np.loadtxt(os.path.join(workdir, "basal_friction.txt"), unpack=True)
                window = (v < 0.85 * v0) & (v > 0.3 * v0)
                mu = -np.polyfit(t[window], v[window], 1)[0] / 9.81
                fast = v > 0.5 * v0
                weight = 2450.0 * 9.81 * dx * layers / 2
                report.append(f"| {v0} | {dx} | {layers} | {v0 / math.sqrt(9.81 * dx):.1f} | {mu:.3f} | "
                              f"{mu / MU_PLANE_STRAIN - 1:+.1%} | {z[-1] / dx:.3f} | "
                              f"{np.mean(p[fast] <= 0.0):.0%} | {p[fast].max() / weight:.1f} | "
                              f"{20 * (len(t) - 1)} | {wall_time(workdir):.0f} |")
        report.write(f"basal_friction/basal_friction{args.suffix}.md")
