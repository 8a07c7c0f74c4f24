# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""A run continues exactly across run commands and restarts: in.continuation run
in one piece, in two runs, and in two processes through a restart file gives the
same positions, velocities, density and stress to round-off (1e-12 of the largest
value of each), for both integrator fixes (and with the extrapolated predictor, which
keeps the rates of the last two steps, and with the grains' sums in single precision:
to 1e-12 with the pair style's rows unpruned, to single precision's round-off pruned),
with a second material for the upper half of the block (a grain's material comes back
from the restart file with its group), on 1 and 2 MPI ranks, with the CFL
timestep and a wall whose velocity changes every step. What invalidates the rates
of the last step is recomputed and said in the log; a grain created between two runs
is stepped from the second run's first step. Arguments are passed to LAMMPS
(e.g. -k on t 1 -sf kk)."""

import os
import sys
import tempfile

import numpy as np

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "in.continuation")
ARGS = sys.argv[1:]
FRESH = "the first step starts from the rates at t"

check = gransph_run.Checks()


def run(tmp, ranks, **variables):
    out = gransph_run.run(INPUT, variables, ranks=ranks, args=ARGS, cwd=tmp)
    return out, gransph_run.read_dump(os.path.join(tmp, "continuation.dump"))


# the integrator fixes, one with the predictor that keeps the rates of two steps, and one
# with the grains' sums in single precision; with the tolerance of each. A continued run
# prunes the pair style's rows anew at its setup (pair_style sph/granular prune), where
# one run may go on with those of an earlier step: the same pairs, but the sums may take
# them in another order, which moves single-precision sums by their round-off; with
# `prune 0` they continue exactly.
SETTINGS = [("elastoplastic", "", "", 1e-12), ("phasechange", "", "", 1e-12),
            ("elastoplastic", "predictor extrapolated", "", 1e-12),
            ("elastoplastic", "", "precision mixed prune 0", 1e-12),
            ("elastoplastic", "", "precision mixed", 1e-5),
            ("phasechange", f"material top {os.path.join(HERE, 'sand25.gransph')} Sand25", "", 1e-12)]

with tempfile.TemporaryDirectory() as tmp:
    for model, options, pair_options, tolerance in SETTINGS:
        for ranks in (1, 2):
            name = ", ".join([model] + [o.replace(HERE + "/", "") for o in (options, pair_options) if o]
                             + [f"{ranks} rank{'s' if ranks > 1 else ''}"])

            def run_case(mode):    # several materials start stress-free (no geostatic)
                return run(tmp, ranks, model=model, fix_options=options,
                           pair_options=pair_options, mode=mode,
                           geostatic=0 if "material" in options else 0.08)

            out, straight = run_case(mode=0)
            check(f"{name}: something happens",
                  np.max(np.abs(straight["vx"])) > 1e-2 and np.max(np.abs(straight["f_sph[4]"])) > 100,
                  f"max |vx| {np.max(np.abs(straight['vx'])):.3g} m/s, "
                  f"max |sigma_zz| {np.max(np.abs(straight['f_sph[4]'])):.3g} Pa")
            out, split = run_case(mode=1)
            diff = gransph_run.state_differences(straight, split)
            check(f"{name}: two runs = one", max(diff.values()) < tolerance and out.count(FRESH) == 1,
                  ", ".join(f"{g} {d:.1e}" for g, d in diff.items())
                  + f"; rates recomputed {out.count(FRESH)} time(s)")
            run_case(mode=2)
            out, restarted = run_case(mode=3)
            diff = gransph_run.state_differences(straight, restarted)
            check(f"{name}: restarted = one run", max(diff.values()) < tolerance and FRESH not in out,
                  ", ".join(f"{g} {d:.1e}" for g, d in diff.items()))

    # a restart file of the other predictor (extrapolated keeps more rates): the grains keep
    # the rates both have, so there is no fresh start, and the run, half under each
    # predictor, lies within the two predictors' own runs of each other
    straight = {options: run(tmp, 1, model="elastoplastic", fix_options=options, mode=0)[1]
                for options in ("", "predictor extrapolated")}
    between = max(gransph_run.state_differences(*straight.values()).values())
    for written, read in (("predictor extrapolated", ""), ("", "predictor extrapolated")):
        name = f"a restart file of '{written or 'the default'}' read with '{read or 'the default'}'"
        run(tmp, 1, model="elastoplastic", fix_options=written, mode=2)
        out, restarted = run(tmp, 1, model="elastoplastic", fix_options=read, mode=3)
        diff = gransph_run.state_differences(straight[read], restarted)
        check(f"{name}: rates kept", FRESH not in out and max(diff.values()) <= between,
              ", ".join(f"{g} {d:.1e}" for g, d in diff.items())
              + f" (the predictors' runs differ by {between:.1e})"
              + ("; fresh start" if FRESH in out else ""))

    # what the stored rates do not survive, said once in the log
    INVALIDATE = [
        ("a new pair style setting", "pair_style sph/granular 0.0125",
         "the pair style settings changed since the last step: " + FRESH),
        # the plain style's arrays of this option exist only once it is set
        ("wall/gradient normal set", "pair_style sph/granular 0.012 wall/gradient normal",
         "the pair style settings changed since the last step: " + FRESH),
        ("a new timestep", "timestep 1e-5", "the timestep changed since the last step: " + FRESH),
        ("a new grain", "include new_grain.in",
         "1 of 193 grains are new since the last step: their " + FRESH[4:]),
    ]
    with open(os.path.join(tmp, "new_grain.in"), "w") as f:
        f.write("create_atoms 1 single 0.15 0.02 0.05 units box\ngroup sand type 1\n"
                'print "new grain at time $(time:%.17g)"\n')
    runs = {}
    for name, command, message in INVALIDATE:
        out, _ = runs[name] = run(tmp, 1, mode=1, between=command)
        check(f"recomputed after {name}", out.count(message) == 1,
              message if message in out else "no message")

    # The grain created between the runs, clear of the sand and the floor, falls freely
    # from the first step of the second run, and the sand beside it goes on as in two runs
    # without it: the integrator lists its grains anew at each run's setup, not only when
    # a step reneighbours (a stale list, whose indices the setup's atom sort has shuffled,
    # moves the sand by 1e-3 of its size and leaves grains unstepped).
    out, dump = runs["a new grain"]
    t_created = float(out.split("new grain at time ")[-1].split()[0])
    t_end = float(out.split("\ntime ")[-1].split()[0])
    fall = -9.81 * (t_end - t_created)
    new = np.argmax(dump["id"])
    check("the new grain falls from the run's first step",
          abs(dump["vz"][new] - fall) < 1e-9 * abs(fall) and dump["vx"][new] == 0.0,
          f"vz {dump['vz'][new]:.12g} m/s, free fall {fall:.12g} m/s, vx {dump['vx'][new]:.3g}")
    _, split = run(tmp, 1, mode=1)
    sand = {name: np.delete(column, new) for name, column in dump.items()}
    diff = gransph_run.state_differences(split, sand)
    check("the sand beside the new grain goes on as without it", max(diff.values()) < 1e-12,
          ", ".join(f"{g} {d:.1e}" for g, d in diff.items()))
check.finish()
