# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Restart files and the pair style's settings record.

restart/legacy-VERSION.restart was written by in.write with the code before the settings
record (commit 96d7c69) on this stack's LAMMPS, and restart/legacy-VERSION.dump is what
that code's in.continue made of it. This code must read the file (its settings in the
layout of before), continue the last step (no fresh start), and reach the same state to
round-off; a file it writes itself (the record) must do the same; and a record of a
version it does not know stops the run with an error that names the version.
Round-off here is what 100 steps of sand at the yield surface make of sums taken in
another order (the pruned rows now hold a grain's grains first, which the fixtures' code
did not): up to 1e-7 of a column's largest value; a value read wrongly moves the state by
orders more.
restart/side_by_side-VERSION.* are the same from commit 4c401ce, whose start values held a
grain's and a dummy particle's columns side by side, with the floor accelerating (floor_ax
20): the dummies' wall velocities of the last step must be read from their old columns."""

import os
import re
import tempfile

import numpy as np

import gransph_run

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "restart")
FRESH = "the first step starts from the rates at t"
RECORD_MARK = (0x48505347).to_bytes(4, "little")
# the files of earlier code: what they are, and the floor's acceleration of in.write
FIXTURES = {"legacy": ("a file of before the settings record", 0),
            "side_by_side": ("a file of start values side by side", 20)}


def lammps_version(output):
    match = re.search(r"LAMMPS \((\d+) (\w{3}) (\d{4})", output)
    assert match, "no LAMMPS version in the output"
    return "".join(match.groups())


def continued(tmp, restart, floor_ax=0):
    """in.continue from `restart`: its output and final dump."""
    dump = os.path.join(tmp, "continued.dump")
    out = gransph_run.run(os.path.join(HERE, "in.continue"),
                          {"restart": restart, "dump": dump, "floor_ax": floor_ax}, cwd=tmp)
    return out, gransph_run.read_dump(dump)


TOLERANCE = 1e-5    # of each column's largest value


def difference(a, b):
    """the largest difference of two dumps' columns, each relative to its largest value
    in b (infinite where their columns or ids differ)"""
    if a.keys() != b.keys() or not np.array_equal(a["id"], b["id"]):
        return np.inf
    return max(np.max(np.abs(a[k] - b[k])) / max(np.max(np.abs(b[k])), 1e-300) for k in b)


def main():
    check = gransph_run.Checks()
    with tempfile.TemporaryDirectory() as tmp:
        own = os.path.join(tmp, "own.restart")
        out = gransph_run.run(os.path.join(HERE, "in.write"), {"restart": own}, cwd=tmp)
        version = lammps_version(out)
        fixtures = {name: [os.path.join(HERE, f"{name}-{version}.{kind}") for kind in ("restart", "dump")]
                    for name in FIXTURES}
        missing = [f for files in fixtures.values() for f in files if not os.path.exists(f)]
        check(f"fixtures for LAMMPS {version}", not missing, ", ".join(missing) or "all there")
        if missing:
            check.finish()

        for name, (what, floor_ax) in FIXTURES.items():
            restart, expected = fixtures[name]
            out, state = continued(tmp, restart, floor_ax)
            check(f"{what}: the run continues its last step", FRESH not in out,
                  "no fresh start (the settings read as those the last step ran with)")
            moved = difference(state, gransph_run.read_dump(expected))
            check(f"{what}: the same state as the code before made of it", moved <= TOLERANCE,
                  f"{len(state['id'])} grains, {len(state)} columns, within {moved:.1e}")

        reference = gransph_run.read_dump(fixtures["legacy"][1])
        out, state = continued(tmp, own)
        check("the record: the run continues its last step", FRESH not in out, "no fresh start")
        moved = difference(state, reference)
        check("the record: the same state", moved <= TOLERANCE,
              f"{len(state['id'])} grains, {len(state)} columns, within {moved:.1e}")

        with open(own, "rb") as f:
            data = bytearray(f.read())
        at = data.find(RECORD_MARK + (1).to_bytes(4, "little"))
        check("the record is in the file", at >= 0, "its mark and version 1")
        data[at + 4:at + 8] = (7).to_bytes(4, "little")
        future = os.path.join(tmp, "future.restart")
        with open(future, "wb") as f:
            f.write(data)
        code, error = gransph_run.first_error(
            tmp, f"plugin load gransphplugin.so\nread_restart {future}\n")
        check("a record of an unknown version", code != 0 and "record version 7" in error, error)
    check.finish()


if __name__ == "__main__":
    main()
