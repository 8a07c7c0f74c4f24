# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""The sound speed of the CFL timestep (eq. 19): by default (`cfl/sound reference`) the
step is C h / sqrt(E / rho0) on every step of a column collapse, plain and /kk; with
`cfl/sound local` it shrinks below that as grains at the surface dilate."""

import math
import os

import gransph_run

COLUMN = os.path.join(gransph_run.TOP, "examples", "column_collapse", "in.column_collapse")
DX, STEPS = 0.02, 1000
E, RHO0 = 20.0e6, 2450.0    # Chen2019 of potentials/sand.gransph
KOKKOS = ["-k", "on", "t", "2", "-sf", "kk"]


def timesteps(fix_options, args):
    """the dt column of the thermo lines"""
    out = gransph_run.run(COLUMN, {"steps": STEPS, "dx": DX, "fix_options": fix_options},
                          args=args)
    lines = out.splitlines()
    head = next(k for k, line in enumerate(lines) if line.split()[:3] == ["Step", "v_time", "Dt"])
    return [float(line.split()[2]) for line in lines[head + 1:head + 1 + STEPS // 500 + 1]]


check = gransph_run.Checks()
expected = 0.2 * 1.2 * DX / math.sqrt(E / RHO0)
for label, args in (("plain", []), ("kk", KOKKOS)):
    reference = timesteps("", args)
    worst = max(abs(dt / expected - 1.0) for dt in reference)
    # thermo prints 8 digits
    check(f"{label} default (reference): dt = 0.2 h / sqrt(E / rho0) on {len(reference)} outputs", worst < 1e-7,
          f"largest relative difference {worst:.1e} (expected {expected:.6e} s)")
    local = timesteps("cfl/sound local", args)
    check(f"{label} local: dt below the reference step once grains dilate",
          local[0] == reference[0] and local[-1] < expected * (1.0 - 1e-3),
          f"dt {local[0]:.6e} at the start, {local[-1]:.6e} s at step {STEPS}")
check.finish()
