#!/usr/bin/python3
"""GRANSPH throughput on this machine: particle-steps per second of the column
collapse (examples/column_collapse) at three sizes, for the plain styles on 1
and 2 MPI ranks, the /kk styles on 2 OpenMP threads, and LAMMPS' own
sph/taitwater + fix sph on the same particles (in.taitwater_peer).

  bench/run_bench.py [--quick]     (--quick: the smallest size only)
"""

import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(HERE)
LMP = os.path.join(TOP, "tools", "lmp")
COLLAPSE = os.path.join(TOP, "examples", "column_collapse", "in.column_collapse")
PEER = os.path.join(HERE, "in.taitwater_peer")

# spacing -> about 2e4, 1e5, 4e5 particles (sand column plus its floor)
SIZES = [(0.0123, 200), (0.0062, 60), (0.0036, 20)]
RUNS = [
    ("plain, 1 rank", COLLAPSE, 1, []),
    ("plain, 2 ranks", COLLAPSE, 2, []),
    ("kk, 2 threads", COLLAPSE, 1, ["-k", "on", "t", "2", "-sf", "kk"]),
    ("taitwater, 1 rank", PEER, 1, []),
    ("taitwater, 2 ranks", PEER, 2, []),
]
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMP_PROC_BIND="spread", OMP_PLACES="threads")
LOOP = re.compile(r"Loop time of (\S+) on \d+ procs for (\d+) steps with (\d+) atoms")


def throughput(script, ranks, args, dx, steps):
    cmd = [LMP, "-in", script, "-var", "dx", str(dx), "-var", "steps", str(steps),
           "-log", "none", "-echo", "none"] + args
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks), "--bind-to", "core"] + cmd
    out = subprocess.run(cmd, capture_output=True, text=True, env=ENV, cwd=HERE).stdout
    loops = LOOP.findall(out)
    if not loops:
        sys.exit(f"no timing from: {' '.join(cmd)}\n{out[-2000:]}")
    seconds, nsteps, natoms = loops[-1]
    return int(natoms), int(nsteps) * int(natoms) / float(seconds)


def main():
    sizes = SIZES[:1] if "--quick" in sys.argv else SIZES
    print(f"{'particles':>10s} " + " ".join(f"{name:>20s}" for name, *_ in RUNS) +
          "   kk / taitwater(1)")
    for dx, steps in sizes:
        rates = [throughput(script, ranks, args, dx, steps) for _, script, ranks, args in RUNS]
        natoms = rates[0][0]
        row = " ".join(f"{r:20.3e}" for _, r in rates)
        print(f"{natoms:10d} {row}   {rates[2][1] / rates[3][1]:.2f}")
    print("(particle-steps per second; GRANSPH runs include the dummy floor particles)")


if __name__ == "__main__":
    main()
