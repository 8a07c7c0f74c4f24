# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""The pair style's pruned rows (pair_style sph/granular prune) leave out no pair that
interacts: in.continuation, a block squeezed past yield on a floor that accelerates
sideways and sheared at 50/s (so that neighbours pass each other, and pairs enter the
support, between LAMMPS' list builds), gives the same state to round-off with the rows
of LAMMPS' neighbour list (prune 0), with the default margin, with a margin so small
that the rows are made anew at nearly every step because atoms moved (more often than
LAMMPS builds its list: compute pair's count says so), and with one wider than the
neighbour skin; on 1 and 2 MPI ranks. (Rows made anew at list builds only leave out
pairs here: the stress moves by 4e-3 of its largest value.) Arguments are passed to
LAMMPS (e.g. -k on t 1 -sf kk)."""

import os
import re
import sys
import tempfile

import gransph_run

INPUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "in.continuation")
ARGS = sys.argv[1:]
STEPS = 200
SHEAR = 50
MARGINS = [("the default margin", ""), ("margin 0.002 h", "prune 0.002"),
           ("margin 1 h (wider than the skin)", "prune 1")]

check = gransph_run.Checks()


def run(tmp, ranks, pair_options):
    """the sand's dump, how often the rows were pruned (summed over the ranks) and how
    often LAMMPS built its list"""
    out = gransph_run.run(INPUT, {"steps": STEPS, "shear": SHEAR, "pair_options": pair_options}, ranks=ranks,
                          args=ARGS, cwd=tmp)
    last = re.findall(rf"^\s*{STEPS}\s+\S+\s+\S+\s+(\S+)\s*$", out, re.M)
    builds = re.findall(r"Neighbor list builds = (\d+)", out)
    if not last or not builds:
        raise RuntimeError(f"no pruning count or list builds in:\n{out[-2000:]}")
    return (gransph_run.read_dump(os.path.join(tmp, "continuation.dump")), float(last[-1]),
            int(builds[-1]))


with tempfile.TemporaryDirectory() as tmp:
    for ranks in (1, 2):
        where = f"{ranks} rank{'s' if ranks > 1 else ''}"
        listed, unpruned, builds = run(tmp, ranks, "prune 0")
        check(f"{where}: prune 0 makes no rows", unpruned == 0, f"made {unpruned:g} times")
        for label, options in MARGINS:
            state, prunings, builds = run(tmp, ranks, options)
            diff = gransph_run.state_differences(state, listed)
            check(f"{where}, {label} = prune 0", max(diff.values()) < 1e-10,
                  ", ".join(f"{g} {d:.1e}" for g, d in diff.items()))
            if options == "prune 0.002":
                check(f"{where}, {label}: made anew as atoms moved",
                      prunings > ranks * (builds + 10),
                      f"made {prunings:g} times (over {ranks} rank(s)) in {STEPS} steps, "
                      f"{builds} list builds")
check.finish()
