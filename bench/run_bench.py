#!/usr/bin/python3
"""GRANSPH throughput on this machine: particle-steps per second of the column
collapse (examples/column_collapse) at three sizes, for the plain styles on 1
and 2 MPI ranks, the /kk styles on 2 OpenMP threads, and LAMMPS' own
sph/taitwater + fix sph on the same particles (in.taitwater_peer).

  bench/run_bench.py [--size {2e4,1e5,4e5}]... [--repeat N]

--size: only these sizes (default all three). --repeat N: the best of N runs
of each (default 3; a shared machine's noise only ever slows a run down).
"""

import argparse
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(HERE)
LMP = os.path.join(TOP, "tools", "lmp")
COLLAPSE = os.path.join(TOP, "examples", "column_collapse", "in.column_collapse")
PEER = os.path.join(HERE, "in.taitwater_peer")

# about 2e4, 1e5, 4e5 particles (sand column plus its floor): spacing, steps
SIZES = {"2e4": (0.0137, 200), "1e5": (0.0067, 60), "4e5": (0.0038, 20)}
RUNS = [
    ("plain, 1 rank", COLLAPSE, 1, []),
    ("plain, 2 ranks", COLLAPSE, 2, []),
    ("kk, 2 threads", COLLAPSE, 1, ["-k", "on", "t", "2", "-sf", "kk"]),
    ("taitwater, 1 rank", PEER, 1, []),
    ("taitwater, 2 ranks", PEER, 2, []),
]
RATIOS = [("plain(1)/tw(1)", 0, 3), ("kk/tw(1)", 2, 3), ("kk/tw(2)", 2, 4)]
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMP_PROC_BIND="spread", OMP_PLACES="threads")
LOOP = re.compile(r"Loop time of (\S+) on \d+ procs for (\d+) steps with (\d+) atoms")
CREATED = re.compile(r"Created (\d+) atoms")


def run_once(script, ranks, args, dx, steps):
    """(atoms, grains, particle-steps per second) of one run"""
    cmd = [LMP, "-in", script, "-var", "dx", str(dx), "-var", "steps", str(steps),
           "-log", "none", "-echo", "none"] + args
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks), "--bind-to", "core"] + cmd
    out = subprocess.run(cmd, capture_output=True, text=True, env=ENV, cwd=HERE).stdout
    loops = LOOP.findall(out)
    if not loops:
        sys.exit(f"no timing from: {' '.join(cmd)}\n{out[-2000:]}")
    seconds, nsteps, natoms = loops[-1]
    grains = int(CREATED.findall(out)[0])    # the column is created first
    return int(natoms), grains, int(nsteps) * int(natoms) / float(seconds)


def throughputs(dx, steps, repeat):
    """(atoms, grains, best rate) of every run in RUNS; the repeats go round all runs
    in turn, so that a slow phase of the machine does not fall on one run only"""
    rounds = [[run_once(script, ranks, args, dx, steps) for _, script, ranks, args in RUNS]
              for _ in range(repeat)]
    return [(runs[0][0], runs[0][1], max(rate for *_, rate in runs)) for runs in zip(*rounds)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--size", action="append", choices=list(SIZES))
    parser.add_argument("--repeat", type=int, default=3)
    opts = parser.parse_args()
    sizes = [SIZES[name] for name in (opts.size or SIZES)]
    print(f"{'particles':>10s} {'grains':>8s} " +
          " ".join(f"{name:>19s}" for name, *_ in RUNS) + " " +
          " ".join(f"{name:>15s}" for name, *_ in RATIOS))
    for dx, steps in sizes:
        results = throughputs(dx, steps, opts.repeat)
        natoms, grains = results[0][0], results[0][1]
        if any(r[0] != natoms for r in results):
            sys.exit(f"dx {dx}: the runs have different particle counts: {results}")
        rates = [r[2] for r in results]
        print(f"{natoms:10d} {grains:8d} " + " ".join(f"{r:19.3e}" for r in rates) + " " +
              " ".join(f"{rates[a] / rates[b]:15.2f}" for _, a, b in RATIOS), flush=True)
    print("(particle-steps per second, all particles counted: the grains and the floor; "
          f"best of {opts.repeat} runs)")


if __name__ == "__main__":
    main()
