# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""bench/run_bench.py --memory: the memory a particle takes, GRANSPH's beside LAMMPS'
sph/taitwater peer on the same lattice (bench/README.md, "Memory per particle").

Each configuration runs on one rank, the bench's own inputs: the column collapse
(examples/column_collapse, a = 0.5) with the plain styles and with the /kk ones on the
host's Kokkos (one thread: its views' host and device copies are one allocation, so its
bytes are the layout a GPU holds, with the host's few arrays besides; with the bins a
GPU takes, KOKKOS_GPU_BINS), and
in.taitwater_peer on its particles, for a few steps (the setup, the neighbour lists and
the steps' arrays all exist then).
Its maximum resident set size (the kernel's ru_maxrss of the LAMMPS process) less that
of the same input at a coarse spacing (the baseline: the executable, its libraries, MPI
and LAMMPS' fixed arrays), divided by the difference in particles (grains and dummies),
is its bytes per particle. The same again with a second run that continues the first
(`run N` after the input: what an input that runs in chunks, as the column example
does until its pile rests, peaks at); and LAMMPS' own estimate ("Per MPI rank memory
allocation", which counts what the styles declare in their memory_usage()) beside it.
"""

import datetime
import os
import re
import subprocess
import sys
import tempfile

from . import TOP
from .bench import INPUTS, PEER, Run
from .lammps import GRAINS, LOOP

# the column's spacing dx at about these numbers of particles (a = 0.5, r0 = 0.2 m:
# 103,200, 690,888, 1,511,984 and 3,004,132 particles); the baseline's: 1,772 particles
SIZES = {"1e5": 0.0067, "7e5": 0.0031, "1.5e6": 0.0023, "3e6": 0.00179}
DEFAULT_SIZES = ["7e5", "3e6"]
BASELINE_DX = 0.05
STEPS = 5
# On a GPU the KOKKOS package bins atoms at the neighbour cutoff, not at half of it as on
# the host (NeighborKokkos::set_binsize_kokkos): the column's cutoff, 2h + skin, is 2.6 dx
KOKKOS_GPU_BINS = 2.6
CONFIGURATIONS = [("GRANSPH", os.path.join(TOP, INPUTS["column"]), []),
                  ("GRANSPH /kk", os.path.join(TOP, INPUTS["column"]), ["-k", "on", "t", "1", "-sf", "kk"]),
                  ("sph/taitwater", PEER, [])]

ESTIMATE = re.compile(r"Per MPI rank memory allocation \(min/avg/max\) = \S+ \| \S+ \| (\S+) Mbytes")
NEIGHBOURS = re.compile(r"Ave neighs/atom = (\S+)")
VERSION = re.compile(r"^LAMMPS \((.*)\)", re.M)


class Peak:
    """one run's largest resident set and what its screen output says of it"""

    def __init__(self, out, rss):
        self.rss = rss    # bytes
        self.natoms = int(LOOP.findall(out)[-1][2])
        grains = GRAINS.findall(out)
        self.grains = int(grains[0]) if grains else self.natoms
        self.estimate = float(ESTIMATE.findall(out)[-1]) * 2**20    # LAMMPS' Mbytes are MiB
        self.neighbours = float(NEIGHBOURS.findall(out)[-1])
        version = VERSION.search(out)
        self.version = version.group(1) if version else "?"


def peak(run, dx, steps, then=0):
    """The Peak of one run of `run`'s input at spacing dx for `steps` steps; with `then`,
    a second run of that many steps continues it. One process, no mpirun (whose own
    resident set the kernel would report), in a scratch folder."""
    if run.ranks != 1:
        raise ValueError("the memory of one rank is measured without mpirun")
    with tempfile.TemporaryDirectory() as scratch:
        script = None
        if then:    # LAMMPS' jump SELF in the included input jumps within that input
            script = os.path.join(scratch, "in.continued")
            with open(script, "w") as f:
                f.write(f"include {run.script}\nrun {then}\n")
        cmd = run.command({"dx": dx}, steps, script)
        with open(os.path.join(scratch, "screen"), "w+") as screen:
            proc = subprocess.Popen(cmd, stdout=screen, stderr=subprocess.STDOUT,
                                    env=run.env(), cwd=scratch)
            _, status, usage = os.wait4(proc.pid, 0)    # the rusage of this child alone
            proc.returncode = os.waitstatus_to_exitcode(status)
            screen.seek(0)
            out = screen.read()
    if proc.returncode != 0 or not LOOP.search(out):
        sys.exit(f"no run from: {' '.join(cmd)} (exit status {proc.returncode})\n{out[-2000:]}")
    return Peak(out, usage.ru_maxrss * 1024)    # Linux reports it in KiB


class Row:
    """one configuration at one size against its baseline"""

    def __init__(self, name, base, one, continued):
        self.name, self.base, self.one, self.continued = name, base, one, continued

    def bytes(self, peak=None):
        """bytes per particle of the run (or of `peak`, the continued run) above the baseline"""
        return ((peak or self.one).rss - self.base.rss) / (self.one.natoms - self.base.natoms)

    def estimate(self):
        return (self.one.estimate - self.base.estimate) / (self.one.natoms - self.base.natoms)

    def cells(self):
        one = self.one
        return [self.name, f"{one.natoms:,} ({one.grains:,})", f"{one.neighbours:.1f}",
                f"{one.rss / 2**20:,.0f}", f"{self.bytes():,.0f}",
                f"{self.bytes(self.continued):,.0f}", f"{self.estimate():,.0f}"]


HEADER = ["styles", "particles (grains)", "neighbours per particle", "max RSS (MiB)",
          "bytes per particle", "with a second run", "LAMMPS' estimate"]


def machine():
    """this machine in a few words: its CPU, cores and memory"""
    cpu = memory = "?"
    try:
        cpu = next(l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo")
                   if l.startswith("model name"))
        kib = next(int(l.split()[1]) for l in open("/proc/meminfo") if l.startswith("MemTotal"))
        memory = f"{kib / 2**20:.0f} GiB"
    except (OSError, StopIteration):
        pass
    return f"{cpu}, {os.cpu_count()} cores, {memory}"


def line(cells):
    """a row of the screen's table: the first cell left, the others right"""
    widths = [14, 22, 10, 11, 10, 10, 10]
    return "  ".join(f"{c:>{w}s}" if i else f"{c:{w}s}"
                     for i, (c, w) in enumerate(zip(cells, widths)))


def measure(sizes, steps):
    """the Rows of every configuration at every size, printed as they come"""
    rows = []
    print(line(["styles", "particles (grains)", "neighbours", "max RSS MiB", "bytes/part",
                "2nd run", "LAMMPS est"]), flush=True)
    for name, script, flags in CONFIGURATIONS:
        def run(dx):
            gpu_bins = ["-pk", "kokkos", "binsize", f"{KOKKOS_GPU_BINS * dx:g}"] if "kk" in flags else []
            return Run(f"{name} 1 rank", script, 1, flags + gpu_bins)
        base = peak(run(BASELINE_DX), BASELINE_DX, steps)
        print(f"{name} baseline: dx {BASELINE_DX}, {base.natoms:,} particles, "
              f"max RSS {base.rss / 2**20:.1f} MiB", flush=True)
        for size in sizes:
            one = peak(run(SIZES[size]), SIZES[size], steps)
            continued = peak(run(SIZES[size]), SIZES[size], steps, then=steps)
            row = Row(name, base, one, continued)
            print(line(row.cells()), flush=True)
            rows.append(row)
    return rows


def markdown(rows, steps, command):
    """the table in markdown, with the machine, the date and the command"""
    base = {row.name: row.base for row in rows}
    lines = [f"Bytes per particle (grains and dummies), max RSS of one rank (the /kk styles on the host's Kokkos, one thread), double "
             f"precision; {datetime.date.today().isoformat()}, {machine()}, LAMMPS "
             f"{rows[0].one.version}; `{command}` ({steps} steps, then {steps} more in a second "
             f"run that continues the first). Baseline, subtracted: the same input at dx "
             f"{BASELINE_DX} (" + "; ".join(
                 f"{name}: {b.natoms:,} particles, {b.rss / 2**20:.1f} MiB"
                 for name, b in base.items()) + ").", "",
             "| " + " | ".join(HEADER) + " |", "|" + "---|" * len(HEADER)]
    lines += ["| " + " | ".join(row.cells()) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def main(sizes, steps, markdown_file):
    sizes = sizes or DEFAULT_SIZES
    unknown = [s for s in sizes if s not in SIZES]
    if unknown:
        sys.exit(f"--memory sizes: {', '.join(SIZES)}, not {', '.join(unknown)}")
    steps = steps or STEPS
    command = " ".join(["bench/run_bench.py"] + sys.argv[1:])
    print(f"memory per particle: max RSS of one rank (/kk: on the host's Kokkos), {steps} steps "
          f"(and a second run of {steps} continuing it), less the baseline's at dx {BASELINE_DX}",
          flush=True)
    rows = measure(sizes, steps)
    print("\n(bytes per particle: (max RSS - the baseline's) / (particles - the baseline's), "
          "grains and dummies; 2nd run: the same when a second run continues the first; "
          "LAMMPS est: the same of LAMMPS' 'Per MPI rank memory allocation')")
    if markdown_file:
        with open(markdown_file, "w") as f:
            f.write(markdown(rows, steps, command))
        print(f"wrote {markdown_file}")
