# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""examples/python/column_stress.py runs through tools/python (the LAMMPS Python module of
the stack's own LAMMPS source, nothing installed) and what it read into numpy with the
module's extract functions equals what LAMMPS printed in the same run's log: at the end
of every run, the floor's force (compute sph/wallforce, 4 values), the deposit's edge and
top (compute sph/runout) and the time; at the last, the sums over the grains of the 8
columns of the integrator's per-atom array f_sph and the minima of its normal stresses
(compute reduce), each to 1e-10 of its scale. The grains it kept are the run's grains, its
png is a PNG, and the comparison is shown to catch a value off by 1e-8."""

import os
import re
import subprocess
import sys
import tempfile

import numpy as np

import gransph_run

PYTHON = os.path.join(gransph_run.TOP, "tools", "python")
EXAMPLE = os.path.join(gransph_run.TOP, "examples", "python", "column_stress.py")
STEPS, CHUNK = 8000, 200             # the example's defaults: it runs as its README runs it
TOLERANCE = 1e-10


def thermo_blocks(log):
    """The thermo table of each run in the log: a dict of columns per run, by header name."""
    blocks, header, rows = [], None, []
    for line in log.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            header, rows = words, []
        elif header and line.startswith("Loop time"):
            blocks.append({name: np.array([r[k] for r in rows]) for k, name in enumerate(header)})
            header = None
        elif header and len(words) == len(header):
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                pass
    return blocks


def mismatches(pairs):
    """The (name, python, log, scale) pairs whose difference exceeds TOLERANCE * scale."""
    return [(n, a, b, s) for n, a, b, s in pairs if not abs(a - b) <= TOLERANCE * s]


check = gransph_run.Checks()
with tempfile.TemporaryDirectory() as tmp:
    proc = subprocess.run([PYTHON, EXAMPLE, "--out", tmp], capture_output=True, text=True,
                          timeout=600)
    output = proc.stdout + proc.stderr
    check("the example runs through tools/python", proc.returncode == 0 and "result:" in proc.stdout,
          f"exit {proc.returncode}: " + (output.strip().splitlines() or ["no output"])[-1])
    if proc.returncode != 0:
        sys.stderr.write(output[-4000:])
        check.finish()
    log_path = os.path.join(tmp, "log.column_stress")
    with open(log_path) as f:
        log = f.read()
    data = np.load(os.path.join(tmp, "column_stress.npz"))
    png = os.path.join(tmp, "column_stress.png")
    with open(png, "rb") as f:
        magic = f.read(8)
    check("the plot is a PNG", magic == b"\x89PNG\r\n\x1a\n" and os.path.getsize(png) > 10000,
          f"{os.path.getsize(png)} bytes")

# the LAMMPS that ran is the stack's: its version in the log
version = re.search(r"^LAMMPS \((.*)\)", log, re.M)
print(f"LAMMPS ({version.group(1) if version else '?'}), {proc.stdout.strip()}")

blocks = thermo_blocks(log)
runs = STEPS // CHUNK
check("one thermo table per run, one reading per run", len(blocks) == runs and len(data["step"]) == runs,
      f"{len(blocks)} tables, {len(data['step'])} readings, {runs} runs")
ends = {int(b["Step"][-1]): b for b in blocks}
check("the readings are at the runs' last steps", sorted(ends) == list(data["step"]),
      f"steps {[int(s) for s in data['step'][:3]]} ... {int(data['step'][-1])}")

# the global vectors, at the end of every run; the force's components against its size
pairs = []
for k, step in enumerate(data["step"]):
    row = {name: column[-1] for name, column in ends.get(int(step), {}).items()}
    if not row:
        continue
    force = data["floor"][k]
    scale = max(np.linalg.norm(force[:3]), 1e-30)
    pairs += [(f"step {step} c_floor[{i + 1}]", force[i], row[f"c_floor[{i + 1}]"], scale)
              for i in range(4)]
    pairs += [(f"step {step} c_deposit[{i + 1}]", data["deposit"][k][i], row[f"c_deposit[{i + 1}]"],
               abs(row[f"c_deposit[{i + 1}]"])) for i in (0, 5)]
    pairs.append((f"step {step} time", data["time"][k], row["Time"], abs(row["Time"])))
bad = mismatches(pairs)
check("wall force, deposit and time read in Python = the log's", len(pairs) == 7 * runs and not bad,
      f"{len(pairs)} values, largest relative difference "
      f"{max((abs(a - b) / s for _, a, b, s in pairs), default=np.inf):.1e}"
      + (f"; first off: {bad[0]}" if bad else ""))

# the per-atom array at the last step: sums over the grains of its columns (each against
# the sum of its magnitudes, since a shear stress sums to nearly zero) and minima
state = data["state"]
last = {name: column[-1] for name, column in blocks[-1].items()} if blocks else {}
created = [int(n) for n in re.findall(r"^\s*Created (\d+) atoms", log, re.M)]
check("the rows kept are the run's grains, all of them dense",
      len(created) == 2 and state.shape == (created[0], 8) and np.all(state[:, 0] > 0),
      f"{state.shape[0]} rows of {state.shape[1]}, created {created}")
per_atom = [(f"sum f_sph[{c + 1}]", state[:, c].sum(), last.get(f"c_sums[{c + 1}]", np.nan),
             np.abs(state[:, c]).sum()) for c in range(8)]
per_atom += [(f"min f_sph[{c + 2}]", state[:, c + 1].min(), last.get(f"c_lows[{c + 1}]", np.nan),
              np.abs(state[:, c + 1]).max()) for c in range(3)]
bad = mismatches(per_atom)
check("per-atom stress read in Python = the log's reductions", not bad and len(per_atom) == 11,
      f"{len(per_atom)} values, largest relative difference "
      f"{max(abs(a - b) / s for _, a, b, s in per_atom):.1e}" + (f"; first off: {bad[0]}" if bad else ""))
check("the stress is a collapsing column's: compressive, the floor carrying the sand",
      state[:, 3].min() < -1e3 and 0.5 < data["floor"][-1][3] / data["weight"] < 1.5,
      f"min szz {state[:, 3].min():.0f} Pa, floor force / weight {data['floor'][-1][3] / data['weight']:.3f}")

# the comparison can fail: one value off by 1e-8 of its scale is caught
name, a, b, s = per_atom[3]
check("a value off by 1e-8 is caught", len(mismatches([(name, a + 1e-8 * s, b, s)])) == 1,
      f"{name} {a:.6e} + 1e-8 of {s:.3e}")
check.finish()
