# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Run LAMMPS with GRANSPH through tools/lmp and read what it wrote."""

import os
import subprocess
import sys

import numpy as np

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
LMP = os.path.join(TOP, "tools", "lmp")

# The small inputs' geometry: a 5 cm cube of sand (type 1, group sand) on three layers
# of dummy floor (type 2, group floor), 1 cm spacing, in a 10 x 10 x 13 cm box.
SAND_BLOCK = """region box block 0 0.1 0 0.1 -0.03 0.1 units box
create_box 2 box
lattice sc 0.01 origin 0.5 0.5 0.5
region sand block 0 0.05 0 0.05 0 0.05 units box
region floor block 0 0.05 0 0.05 -0.03 0 units box
create_atoms 1 region sand
create_atoms 2 region floor
group sand type 1
group floor type 2
"""

# An empty periodic 2d box with the plugin loaded, for inputs that fail at a command.
EMPTY_2D_BOX = """plugin load gransphplugin.so
dimension 2
boundary p p p
region box block 0 1 0 1 -0.5 0.5 units box
create_box 1 box
"""


LAST_OUTPUT = ""    # what the last run() printed, stdout and stderr


def run(input_file, variables=None, ranks=1, args=(), cwd=None):
    """Run input_file with -var name value pairs; return stdout, fail on error."""
    cmd = [LMP, "-in", os.path.abspath(input_file), "-log", "none", "-echo", "none"]
    for name, value in (variables or {}).items():
        cmd += ["-var", name, str(value)]
    cmd += list(args)
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    global LAST_OUTPUT
    LAST_OUTPUT = proc.stdout + proc.stderr
    if proc.returncode != 0 or "ERROR" in proc.stdout:
        sys.stderr.write(proc.stdout[-4000:] + proc.stderr[-4000:])
        raise RuntimeError(f"LAMMPS failed: {' '.join(cmd)}")
    return proc.stdout


def output_of(directory, text, args=()):
    """Run the input `text` from `directory` as a batch job does, its screen and log
    written to files (screen.txt, log.txt: no pipe, no line buffering, so that a
    one-rank error's message must reach them before LAMMPS aborts); return LAMMPS' exit
    code and all it wrote to the screen."""
    path = os.path.join(directory, "in.case")
    with open(path, "w") as f:
        f.write(text)
    screen = os.path.join(directory, "screen.txt")
    cmd = [LMP, "-in", path, "-log", os.path.join(directory, "log.txt"), "-echo", "none"] + list(args)
    with open(screen, "w") as out:
        proc = subprocess.run(cmd, cwd=directory, stdout=out, stderr=subprocess.STDOUT, timeout=120)
    with open(screen) as f:
        return proc.returncode, f.read()


def first_error(directory, text, args=()):
    """Run the input `text` from `directory`; return LAMMPS' exit code and its first
    ERROR line ('' if none)."""
    code, out = output_of(directory, text, args)
    errors = [l for l in out.splitlines() if "ERROR" in l]
    return code, errors[0] if errors else ""


def read_dump(path):
    """Last snapshot of a 'dump custom' file as a dict of columns, sorted by id."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    names = lines[start].split()[2:]
    data = np.array([[float(w) for w in l.split()] for l in lines[start + 1:]])
    data = data[np.argsort(data[:, names.index("id")])]
    return {n: data[:, k] for k, n in enumerate(names)}


def stress_atom_difference(a, b, compute="stress"):
    """Largest difference between two dumps of compute sph/stress/atom `compute`, per
    column, against the largest principal stress. The major direction and the Lode angle
    are undefined where principal stresses coincide (a stress-free grain, whose stress is
    round-off): each is weighed by the gap that defines it, |dn| (sigma_1 - sigma_2) and
    |dlode| (sigma_1 - sigma_3), the stress difference that turns it that much. The
    direction's sign is a convention: compared up to sign."""
    col = lambda d, k: d[f"c_{compute}[{k}]"]
    scale = max(np.max(np.abs(col(a, k))) for k in (3, 4, 5))
    out = {}
    for k in (1, 2, 3, 4, 5):
        out[str(k)] = np.max(np.abs(col(a, k) - col(b, k))) / scale
    for k in (10, 11):
        out[str(k)] = np.max(np.abs(col(a, k) - col(b, k)))
    na = np.stack([col(a, k) for k in (6, 7, 8)], axis=1)
    nb = np.stack([col(b, k) for k in (6, 7, 8)], axis=1)
    dn = np.minimum(np.linalg.norm(na - nb, axis=1), np.linalg.norm(na + nb, axis=1))
    out["6-8"] = np.max(dn * (col(a, 3) - col(a, 4))) / scale
    dlode = np.radians(np.abs(col(a, 9) - col(b, 9)))
    out["9"] = np.max(dlode * (col(a, 3) - col(a, 5))) / scale
    return out


def dump_differences(a, b):
    """Largest difference between two dumps of the same atoms, per column, against the
    column's largest value; the columns of compute sph/stress/atom (named c_stress[k])
    as stress_atom_difference weighs them."""
    assert np.array_equal(a["id"], b["id"]), "the dumps hold different atoms"
    out = {}
    for name in a:
        if not name.startswith("c_stress["):
            out[name] = np.max(np.abs(a[name] - b[name])) / max(np.max(np.abs(a[name])), 1e-30)
    if "c_stress[1]" in a:
        for column, diff in stress_atom_difference(a, b).items():
            out[f"c_stress[{column}]"] = diff
    return out


# the state of in.continuation's dump, by group of columns
STATE_GROUPS = {"position": ["x", "y", "z"], "velocity": ["vx", "vy", "vz"],
                "density": ["f_sph[1]"], "stress": [f"f_sph[{k}]" for k in range(2, 8)]}


def state_differences(a, b):
    """Largest difference of each group of STATE_GROUPS over the group's largest value
    (so that a component that vanishes by symmetry is weighed against its group)."""
    assert np.array_equal(a["id"], b["id"]), "the dumps hold different atoms"
    result = {}
    for group, names in STATE_GROUPS.items():
        scale = max(np.max(np.abs(a[n])) for n in names)
        result[group] = max(np.max(np.abs(a[n] - b[n])) for n in names) / scale
    return result


def check_same_state(check, label, a, b, tolerance):
    """One check per dump column: the largest difference of a and b against the column's
    largest value (dump_differences) within tolerance."""
    for name, diff in dump_differences(a, b).items():
        check(f"{label} {name}", diff < tolerance, f"max difference / max value = {diff:.2e}")


def result_line(stdout):
    """The words of the line that starts with 'result:'."""
    for line in stdout.splitlines():
        if line.startswith("result:"):
            return line.split()
    raise RuntimeError("no 'result:' line in the output")


def result_numbers(words):
    """The numbers of a result line's words, each under the word before it (the first
    time a word names one)."""
    numbers = {}
    for key, value in zip(words[1:-1], words[2:]):
        try:
            numbers.setdefault(key, float(value))
        except ValueError:
            pass
    return numbers


class Checks:
    """Named pass/fail checks that print as they go and end with the
    'N passed, N failed' line ctest's output is read for."""

    def __init__(self):
        self.passed = self.failed = 0

    def __call__(self, name, ok, detail):
        print(f"{'ok    ' if ok else 'FAILED'} {name}: {detail}", flush=True)
        self.passed += bool(ok)
        self.failed += not ok

    def finish(self):
        print(f"{self.passed} passed, {self.failed} failed")
        raise SystemExit(1 if self.failed else 0)

