# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""GRANSPH throughput on this machine: particle-steps and grain-steps per second of
the examples' inputs, for the plain styles on 1 and 2 MPI ranks and the /kk styles
on 2 OpenMP threads (the last two also with pair_style ... precision mixed), beside
LAMMPS' own SPH fluid on the column's particles and, with --against, beside the
plugin of an earlier commit.

  bench/run_bench.py [--case column|flume|jet]... [--size S]... [--repeat N] [--steps N]
                     [--against REF [--against-arch as-built|native|generic]]
  bench/run_bench.py --flow [--case column|flume|jet]... [--tend T] [--repeat N] [--against REF]
  bench/run_bench.py --memory [--size 7e5|3e6|1.5e6|1e5]... [--steps N] [--markdown FILE]

Cases (the examples' own inputs, for a fixed number of steps):
  column  examples/column_collapse, a = 0.5 (a sand column on three layers of dummy
          floor), at about 2e4, 1e5 and 4e5 particles; beside it sph/taitwater +
          fix sph on the same particles and the same pair set (in.taitwater_peer)
  flume   examples/flume_impact, elastoplastic, dx = 10 mm as in the paper (dummy-heavy:
          about 5 dummy particles per grain)
  jet     examples/jet_collision (grains only, free surfaces everywhere)
--size: only these sizes (of the column: 2e4, 1e5, 4e5; the flume, at the paper's
spacing, 1.2e5; the jet 1.1e5).
--repeat N: the best of N runs of each (default 3; a shared machine's noise only
ever slows a run down). Every run of one size goes round in turn, so that a slow
phase of the machine falls on all of them; each ratio is printed of the best values
and, beside it, as the median (and range) of the same ratio within each round.
--steps N: every run this many steps instead of each case's own (a smoke run: ctest
Bench:smoke runs the script so, that it cannot rot; its figures mean nothing).
--against REF: builds the plugin of git commit REF into bench/against/SHA/ (against
the same LAMMPS) and runs it, on REF's own example inputs, beside the current one:
the ratio is what a user gains over REF, in one run of this script.
--flow: the time to solution rather than the cost of a step: the column collapse
(a = 0.5) at 16 particles per radius through its collapse (to t = 0.3 s; in chunks of
1000 steps, so to the chunk after), the flume at dx = 25 mm, elastoplastic, from release
through the impact (to t = 0.8 s), and the jet collision at its example's dx = 8 mm to
the end of its measurement (t = 0.03 s); --tend T ends each there instead (ctest Bench:flow_smoke runs the flume so); each configuration run
to that time with its own defaults (timestep rule and constant, predictor); reported
as simulated seconds per wall-clock second (LAMMPS' loop times, setup excluded). With
--against it says what a user gains over REF on a whole flow, fewer steps included.
--against-arch: REF's plugin as its own CMakeLists builds it (as-built, default), or
for this machine (native) or any x86-64 (generic), to tell a code change's gain from
the instruction set's: e.g. --against HEAD --against-arch generic.
--memory: bytes per particle rather than time: the column's max RSS on one rank
(plain styles) at about 7e5 and 3e6 particles (--size: also 1.5e6, or 1e5 for a quick
look), after --steps steps (default 5), less that of the same input at a coarse
spacing, per particle, beside sph/taitwater's on the same lattice; also with a second
run that continues the first, and LAMMPS' own estimate (tools/lib/gransph/memory.py).
--markdown FILE writes its table in markdown too.
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

from . import TOP
from .lammps import GRAINS, LMP, LOOP, environment

HERE = os.path.join(TOP, "bench")    # the bench's own inputs and its builds of earlier commits
PEER = os.path.join(HERE, "in.taitwater_peer")
INPUTS = {"column": "examples/column_collapse/in.column_collapse",
          "flume": "examples/flume_impact/in.flume_impact",
          "jet": "examples/jet_collision/in.jet_collision"}

# case -> size label -> (variables, steps); about 2e4, 1e5, 4e5 particles of the column
SIZES = {
    "column": {"2e4": ({"dx": 0.0137}, 200), "1e5": ({"dx": 0.0067}, 60),
               "4e5": ({"dx": 0.0038}, 20)},
    "flume": {"1.2e5": ({"dx": 0.01, "model": "elastoplastic"}, 40)},    # the paper's dx
    "jet": {"1.1e5": ({"dx": 0.006}, 40)},
}
# --flow: whole flows to a simulated time (the input's variable that sets it), each
# configuration with its own timestep
FLOWS = {"column": ({"dx": 0.0125, "tmax": 0.3}, "tmax"),
         "flume": ({"dx": 0.025, "model": "elastoplastic", "tend": 0.8}, "tend"),
         "jet": ({"dx": 0.008, "t2": 0.03}, "t2")}
KK = ["-k", "on", "t", "2", "-sf", "kk"]
MIXED = "precision mixed"    # the pair style's option: the grains' sums in single precision
ENV = dict(environment(), OMP_PROC_BIND="spread", OMP_PLACES="threads")
# a run's last thermo line (step, then the simulated time, as the flume and jet inputs
# print it) and its loop time
LAST_TIME = re.compile(r"^\s*\d+\s+(\S+).*\nLoop time of", re.M)


class Run:
    """one configuration: a LAMMPS input, ranks, command-line flags and plugin build"""

    def __init__(self, name, script, ranks, flags=(), build=None, pair_options=None):
        self.name, self.script, self.ranks = name, script, ranks
        self.flags, self.build = list(flags), build
        self.pair_options = pair_options

    def once(self, variables, steps):
        """(atoms, grains, particle-steps per second) of one run"""
        out = self.output(variables, steps)
        seconds, nsteps, natoms = LOOP.findall(out)[-1]
        grains = GRAINS.findall(out) or [natoms]
        return int(natoms), int(grains[0]), int(nsteps) * int(natoms) / float(seconds)

    def flow(self, variables):
        """(steps, simulated seconds per second of all runs' loop times) of one run to the
        input's end, in a scratch folder (the flume writes its force history there)"""
        with tempfile.TemporaryDirectory() as scratch:
            out = self.output(variables, 0, cwd=scratch)
        loops = LOOP.findall(out)
        times = LAST_TIME.findall(out)
        if not times:
            sys.exit(f"no simulated time in the output of {self.name}:\n{out[-2000:]}")
        return (sum(int(n) for _, n, _ in loops),
                float(times[-1]) / sum(float(seconds) for seconds, _, _ in loops))

    def command(self, variables, steps, script=None):
        """the command line of one run (of `script` in place of the configuration's own)"""
        cmd = [LMP, "-in", script or self.script, "-var", "steps", str(steps), "-log", "none",
               "-echo", "none"] + self.flags
        if self.pair_options:
            variables = dict(variables, pair_options=self.pair_options)
        for name, value in variables.items():
            cmd += ["-var", name, str(value)]
        if self.ranks > 1:
            cmd = ["mpirun", "-np", str(self.ranks), "--bind-to", "core"] + cmd
        return cmd

    def env(self):
        """its environment: the plugin of its build"""
        return dict(ENV, **({"GRANSPH_BUILD": self.build} if self.build else {}))

    def output(self, variables, steps, cwd=None):
        """the screen output of one run, which must have timed a loop"""
        cmd = self.command(variables, steps)
        out = subprocess.run(cmd, capture_output=True, text=True, env=self.env(),
                             cwd=cwd or os.path.dirname(self.script)).stdout
        if not LOOP.search(out):
            sys.exit(f"no timing from: {' '.join(cmd)}\n{out[-2000:]}")
        return out


def build_against(ref, arch):
    """the plugin of commit REF, built into bench/against/SHA[-ARCH]/; its sources and build"""
    sha = subprocess.run(["git", "-C", TOP, "rev-parse", "--verify", ref + "^{commit}"],
                         capture_output=True, text=True, check=True).stdout.strip()
    where = os.path.join(HERE, "against", sha[:12] + ("" if arch == "as-built" else "-" + arch))
    src, build = os.path.join(where, "src"), os.path.join(where, "build")
    if not os.path.isdir(src):
        os.makedirs(src)
        archive = subprocess.Popen(["git", "-C", TOP, "archive", sha], stdout=subprocess.PIPE)
        subprocess.run(["tar", "-x", "-C", src], stdin=archive.stdout, check=True)
        if archive.wait() != 0:
            sys.exit(f"git archive {sha} failed")
    configure = ["cmake", "-S", src, "-B", build, "-G", "Ninja", "-D", "BUILD_TESTING=OFF"]
    if os.environ.get("GRANSPH_STACK") == "2026":    # inside tools/stack/sid-root.sh's root
        configure += ["-D", "LAMMPS_SOURCE_DIR=/opt/lammps", "-D", "LAMMPS_BUILD_DIR=/opt/lammps/build"]
    if arch == "native":    # CMAKE_CXX_FLAGS for commits before GRANSPH_ARCH
        configure += ["-D", "CMAKE_CXX_FLAGS=-march=native -ffp-contract=off", "-D", "GRANSPH_ARCH=native"]
    elif arch == "generic":    # a commit before GRANSPH_ARCH is generic as built
        configure += ["-D", "GRANSPH_ARCH=generic"]
    print(f"building the plugin of {ref} ({sha[:12]}, {arch}) in {build}", flush=True)
    for cmd in (configure, ["cmake", "--build", build, "--target", "gransphplugin"]):
        done = subprocess.run(cmd, capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit(f"{' '.join(cmd)} failed:\n{done.stdout[-3000:]}{done.stderr[-3000:]}")
    return src, build


def runs_of(case, against):
    """the configurations to time for one case"""
    script = os.path.join(TOP, INPUTS[case])
    runs = [Run("plain 1 rank", script, 1), Run("plain 2 ranks", script, 2),
            Run("kk 2 threads", script, 1, KK),
            Run("mixed plain 2 ranks", script, 2, pair_options=MIXED),
            Run("mixed kk 2 threads", script, 1, KK, pair_options=MIXED)]
    if against:
        src, build = against
        old = os.path.join(src, INPUTS[case])
        runs += [Run("REF plain 2 ranks", old, 2, build=build),
                 Run("REF kk 2 threads", old, 1, KK, build=build)]
    if case == "column":
        runs += [Run("taitwater 1 rank", PEER, 1), Run("taitwater 2 ranks", PEER, 2)]
    return runs


def ratios_of(names):
    """(label, numerator, denominator) of the ratios that the configurations allow"""
    wanted = [("best/tw(2)", "best", "taitwater 2 ranks"),
              ("mixed best/tw(2)", "mixed best", "taitwater 2 ranks"),
              ("kk/plain(2)", "kk 2 threads", "plain 2 ranks"),
              ("mixed/double best", "mixed best", "best"),
              ("best/REF best", "best", "REF best"),
              ("mixed best/REF best", "mixed best", "REF best")]
    return [r for r in wanted if r[2] in names or r[2] == "best" or
            r[2] == "REF best" and "REF plain 2 ranks" in names]


def rate(rates, name):
    if name == "best":
        return max(rates["plain 2 ranks"], rates["kk 2 threads"])
    if name == "mixed best":
        return max(rates["mixed plain 2 ranks"], rates["mixed kk 2 threads"])
    if name == "REF best":
        return max(rates["REF plain 2 ranks"], rates["REF kk 2 threads"])
    return rates[name]


def best_of(runs, measure, repeat, index):
    """every run measured `repeat` times, in turn; the rounds, each run's largest value
    `index` of what `measure(run)` returns, and that value of every run in each round"""
    rounds = [[measure(run) for run in runs] for _ in range(repeat)]
    best = {run.name: max(r[index] for r in results) for run, results in zip(runs, zip(*rounds))}
    in_rounds = [{run.name: result[index] for run, result in zip(runs, results)}
                 for results in rounds]
    return rounds, best, in_rounds


def print_ratios(best, in_rounds, width):
    """each ratio of the best values, and beside it the same ratio taken within each round
    (median, lowest-highest): a round runs its configurations one after the other, so a
    slow phase of the machine that lasts minutes falls on both sides of its ratios, where
    the best values may come from different phases"""
    for label, num, den in ratios_of(set(best)):
        paired = sorted(rate(r, num) / rate(r, den) for r in in_rounds)
        print(f"  {label:20s} {rate(best, num) / rate(best, den):{width}.2f}"
              f"   in rounds {statistics.median(paired):.2f} ({paired[0]:.2f}-{paired[-1]:.2f})")
    sys.stdout.flush()


def bench(case, label, variables, steps, repeat, against):
    runs = runs_of(case, against)
    rounds, best, in_rounds = best_of(runs, lambda run: run.once(variables, steps), repeat, 2)
    atoms = {r[0] for results in rounds for r in results}
    if len(atoms) != 1:
        sys.exit(f"{case} {label}: the runs have different particle counts: {sorted(atoms)}")
    natoms = atoms.pop()
    grains = rounds[0][0][1]
    print(f"\n{case}, {label}: {natoms} particles, {grains} grains, {steps} steps, "
          f"best of {repeat}")
    print(f"  {'configuration':20s} {'particle-steps/s':>17s} {'grain-steps/s':>14s}")
    for run in runs:
        # the peer's grains: its sand group, as ours
        print(f"  {run.name:20s} {best[run.name]:17.3e} {best[run.name] * grains / natoms:14.3e}")
    print_ratios(best, in_rounds, 17)


def flow(case, tend, repeat, against):
    """--flow: simulated seconds per wall-clock second of a whole flow, best of `repeat`"""
    variables, end = FLOWS[case]
    variables = dict(variables, **{end: tend or variables[end]})
    # the two-core configurations of GRANSPH (the peer fluid has no flow to time)
    runs = [run for run in runs_of(case, against)
            if (run.ranks == 2 or run.flags) and run.script != PEER]
    rounds, best, in_rounds = best_of(runs, lambda run: run.flow(variables), repeat, 1)
    steps = {run.name: result[0] for run, result in zip(runs, rounds[0])}
    print(f"\n{case} flow to t = {variables[end]} s ({variables}), best of {repeat}")
    print(f"  {'configuration':20s} {'steps':>8s} {'simulated s per s':>18s}")
    for run in runs:
        print(f"  {run.name:20s} {steps[run.name]:8d} {best[run.name]:18.3e}")
    print_ratios(best, in_rounds, 27)


def main():
    parser = argparse.ArgumentParser(prog="bench/run_bench.py", description=__doc__.split("\n")[0])
    parser.add_argument("--case", action="append", choices=list(SIZES))
    parser.add_argument("--size", action="append")
    parser.add_argument("--repeat", type=int)
    parser.add_argument("--steps", type=int)
    parser.add_argument("--flow", action="store_true")
    parser.add_argument("--tend", type=float)
    parser.add_argument("--against", metavar="REF")
    parser.add_argument("--against-arch", choices=["as-built", "native", "generic"],
                        default="as-built")
    parser.add_argument("--memory", action="store_true")
    parser.add_argument("--markdown", metavar="FILE")
    opts = parser.parse_args()
    if opts.memory:
        if opts.flow or opts.against or opts.tend or opts.repeat or set(opts.case or []) - {"column"}:
            parser.error("--memory measures the column and its peer once each: no --flow, "
                         "--tend, --against, --repeat or other --case")
        from . import memory
        memory.main(opts.size, opts.steps, opts.markdown)
        return
    if opts.markdown:
        parser.error("--markdown goes with --memory")
    opts.repeat = opts.repeat or 3
    if opts.flow and set(opts.case or []) - set(FLOWS):
        parser.error(f"--flow times the cases {', '.join(FLOWS)}")
    if opts.flow and (opts.size or opts.steps):
        parser.error("--flow runs each flow to its end time: no --size or --steps")
    if opts.tend and not opts.flow:
        parser.error("--tend goes with --flow")
    against = build_against(opts.against, opts.against_arch) if opts.against else None
    if against:
        print(f"REF = {opts.against}: its plugin ({opts.against_arch}) on its own inputs")
    if opts.flow:
        for case in opts.case or list(FLOWS):
            flow(case, opts.tend, opts.repeat, against)
        return
    for case in opts.case or list(SIZES):
        for label, (variables, steps) in SIZES[case].items():
            if opts.size and label not in opts.size:
                continue
            bench(case, label, variables, opts.steps or steps, opts.repeat, against)
    print("\n(particle-steps: all particles, grains and dummies; grain-steps: grains only. "
          "best = the faster of plain on 2 ranks and kk on 2 threads, in double precision; "
          "mixed best = the same under pair_style ... precision mixed)")


if __name__ == "__main__":
    main()
