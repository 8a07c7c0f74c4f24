# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Two-way coupling with LAMMPS rigid bodies (in.rigid_momentum): a cube of dummy
particles moved by fix rigid or fix rigid/small, thrown at a block of sand without
gravity, takes from the grains the exact reverse of the force it gives them, so that
the momentum of grains plus body (the body's after its next half-kick: fix rigid is
velocity Verlet) stays what it was to 1e-10 of the body's initial momentum over 2,000
steps, on 1 and 2 MPI ranks and under the /kk styles. The body must have slowed down
(by more than 10%) and turned, and the sand moved. The run continues exactly across run
commands (the dummies' first half-kick of the second run takes the last step's force,
not the setup's) and to round-off across a restart (a new fix rigid recomputes its
body from the atoms), both checked on the final state of grains and body.

Arguments are passed to LAMMPS (e.g. -k on t 1 -sf kk); with them, the run also equals
the plain styles' to round-off. Neither LAMMPS version has a Kokkos rigid fix: under
-sf kk fix rigid runs on the host."""

import os
import re
import sys
import tempfile

import numpy as np

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "in.rigid_momentum")
ARGS = sys.argv[1:]
V0 = 2.0


def run(tmp, ranks, args=ARGS, **variables):
    out = gransph_run.run(INPUT, dict(variables, v0=V0), ranks=ranks, args=args, cwd=tmp)
    momentum = np.array([[float(w) for w in m.groups()] for m in
                         re.finditer(r"^momentum: (\S+) (\S+) (\S+) (\S+)$", out, re.M)])
    return momentum, gransph_run.read_dump(os.path.join(tmp, "rigid.dump"))


def main():
    check = gransph_run.Checks()
    with tempfile.TemporaryDirectory() as tmp:
        for rigid in ("rigid", "rigid/small"):
            straight = None
            for ranks in (1, 2):
                name = f"fix {rigid}, {ranks} rank{'s' if ranks > 1 else ''}"
                momentum, state = run(tmp, ranks, rigid=rigid, mode=0)
                steps, p = momentum[:, 0], momentum[:, 1:]
                p0 = np.linalg.norm(p[0])
                drift = np.max(np.linalg.norm(p - p[0], axis=1)) / p0
                check(f"{name}: momentum of grains + body conserved",
                      len(steps) >= 20 and steps[-1] == 2000 and drift < 1e-10,
                      f"largest change {drift:.1e} of |p| over {steps[-1]:.0f} steps")
                body = state["type"] == 3
                vx = np.mean(state["vx"][body])
                spread = np.ptp(state["vx"][body])
                sand = np.max(np.abs(state["vx"][~body]))
                check(f"{name}: the body slowed and turned, the sand moved",
                      vx < 0.9 * V0 and spread > 1e-3 and sand > 0.1,
                      f"body vx {vx:.3f} m/s (thrown at {V0}), its spread {spread:.2e} m/s "
                      f"(rotation), sand max |vx| {sand:.3f} m/s")
                if straight is None:
                    straight = state
                else:
                    diffs = gransph_run.dump_differences(straight, state)
                    check(f"fix {rigid}: 2 ranks = 1 rank", max(diffs.values()) < 1e-10,
                          f"largest difference {max(diffs.values()):.1e}")
            if ARGS:    # e.g. the /kk styles: against the plain ones
                _, plain = run(tmp, 1, args=(), rigid=rigid, mode=0)
                diffs = gransph_run.dump_differences(plain, straight)
                check(f"fix {rigid}: {' '.join(ARGS)} = plain", max(diffs.values()) < 1e-10,
                      f"largest difference {max(diffs.values()):.1e}")
            _, split = run(tmp, 1, rigid=rigid, mode=1)
            diffs = gransph_run.dump_differences(straight, split)
            check(f"fix {rigid}: two runs = one", max(diffs.values()) < 1e-12,
                  f"largest difference {max(diffs.values()):.1e}")
            run(tmp, 1, rigid=rigid, mode=2)
            _, restarted = run(tmp, 1, rigid=rigid, mode=3)
            diffs = gransph_run.dump_differences(straight, restarted)
            check(f"fix {rigid}: restarted = one run", max(diffs.values()) < 1e-9,
                  f"largest difference {max(diffs.values()):.1e}")
    check.finish()


if __name__ == "__main__":
    main()
