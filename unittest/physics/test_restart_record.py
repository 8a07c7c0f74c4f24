# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Restart files and the pair style's settings record.

restart/legacy-VERSION.restart was written by in.write with the code before the settings
record (commit 96d7c69) on this stack's LAMMPS, and restart/legacy-VERSION.dump is what
that code's in.continue made of it. This code must read the file (its settings in the
layout of before), continue the last step (no fresh start), and reach the same state
bit for bit; a file it writes itself (the record) must do the same; and a record of a
version it does not know stops the run with an error that names the version.
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


def same(a, b):
    return all(np.array_equal(a[k], b[k]) for k in a) and a.keys() == b.keys()


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
            check(f"{what}: the same state as the code before made of it",
                  same(state, gransph_run.read_dump(expected)),
                  f"{len(state['id'])} grains, {len(state)} columns bit for bit")

        reference = gransph_run.read_dump(fixtures["legacy"][1])
        out, state = continued(tmp, own)
        check("the record: the run continues its last step", FRESH not in out, "no fresh start")
        check("the record: the same state", same(state, reference),
              f"{len(state['id'])} grains, {len(state)} columns bit for bit")

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
