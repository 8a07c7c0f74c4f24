# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""fix sph/outflow: sand flowing off a floor smaller than its runout leaves the box.
Without the fix the run stops, saying that atoms left the box and that fix sph/outflow
removes them (the integrator says it before LAMMPS' own "Lost atoms"); with it (1 and
2 ranks, with and without `every`) the run ends cleanly, and the fix's count and mass
are those of the sand atoms that are gone, none of the floor's; bad input stops with
an error that names the problem."""

import os
import re
import subprocess
import tempfile

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "in.outflow")

check = gransph_run.Checks()


def run_lmp(tmp, path, variables=None, ranks=1):
    """return code and output of a run that may fail"""
    cmd = [gransph_run.LMP, "-in", path, "-log", "none", "-echo", "none"]
    for name, value in (variables or {}).items():
        cmd += ["-var", name, str(value)]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    # line-buffered: an error ends in MPI_Abort, which does not flush a pipe
    proc = subprocess.run(["stdbuf", "-oL"] + cmd, cwd=tmp, capture_output=True, text=True, timeout=300)
    return proc.returncode, proc.stdout + proc.stderr


with tempfile.TemporaryDirectory() as tmp:
    code, out = run_lmp(tmp, INPUT, {"outflow": 0})
    check("without the fix the sand is lost, and the error says what to do",
          code != 0 and re.search(r"ERROR: Fix sph/\w+: \d+ atoms left the box .*fix sph/outflow", out),
          next((l for l in out.splitlines() if "ERROR" in l), "no error"))

    for ranks, every in ((1, 0), (2, 25)):
        name = f"{ranks} rank(s), every {every or 'reneighboring'}"
        code, out = run_lmp(tmp, INPUT, {"every": every}, ranks)
        errors = [l for l in out.splitlines() if "ERROR" in l or "WARNING" in l]
        check(f"{name}: no error or warning", code == 0 and not errors, errors[0] if errors else "clean run")
        if code != 0:
            continue
        w = gransph_run.result_line(out)
        sand0, sand1, floor0, floor1 = int(w[2]), int(w[3]), int(w[5]), int(w[6])
        removed, mass, grain = float(w[8]), float(w[10]), float(w[11])
        check(f"{name}: count = sand atoms gone > 0", removed == sand0 - sand1 > 0,
              f"removed {removed:g}, sand {sand0} -> {sand1}")
        check(f"{name}: floor untouched", floor0 == floor1, f"floor {floor0} -> {floor1}")
        check(f"{name}: removed mass", abs(mass - removed * grain) < 1e-9 * mass,
              f"{mass:g} kg for {removed:g} grains of {grain:g} kg")
        if every:
            steps = [int(n) for n in re.findall(r"Loop time of \S+ on \d+ procs for (\d+) steps", out)]
            builds = [int(n) for n in re.findall(r"Neighbor list builds = (\d+)", out)]
            check(f"{name}: reneighbors at least every {every} steps",
                  all(b >= s // every for s, b in zip(steps, builds)),
                  f"{builds} builds in {steps} steps")

    BASE = """plugin load gransphplugin.so
units si
boundary f f f
region box block 0 1 0 1 0 1 units box
create_box 1 box
{region}
fix out all sph/outflow {args}
"""
    CASES = [
        ("no region", dict(args=""), "need a region ID"),
        ("unknown region", dict(args="nosuch"), "region nosuch does not exist"),
        ("unknown keyword", dict(args="in foo 1"), "unknown keyword foo"),
        ("every without value", dict(args="in every"), "keyword every needs a value"),
        ("every < 1", dict(args="in every 0"), "every must be >= 1"),
    ]
    path = os.path.join(tmp, "in.case")
    for name, fields, expected in CASES:
        with open(path, "w") as f:
            f.write(BASE.format(region="region in block 0.1 0.9 0.1 0.9 0.1 0.9 units box", **fields))
        code, out = run_lmp(tmp, path)
        errors = [l for l in out.splitlines() if "ERROR" in l]
        check(name, code != 0 and errors and re.search(expected, errors[0]), errors[0] if errors else "no error")

    # a region reaching beyond a fixed boundary cannot protect atoms leaving there
    with open(path, "w") as f:
        f.write(BASE.format(region="region in block INF INF 0.1 0.9 0.1 0.9 units box", args="in")
                + "mass 1 1\nrun 0\nrun 0\n")
    code, out = run_lmp(tmp, path)
    check("region beyond a fixed boundary is warned about, once for two runs",
          code == 0 and out.count("WARNING: Fix sph/outflow: region in extends beyond a fixed boundary") == 1,
          next((l for l in out.splitlines() if "WARNING" in l or "ERROR" in l), "no warning"))

check.finish()
