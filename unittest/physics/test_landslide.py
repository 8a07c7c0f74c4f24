# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""examples/landslide runs: its site made by tools/terrain, read with the dummies' own
normals, the barrier built on it, the sand placed on the bed; a short run keeps every
grain and finite state (the fix stops on a non-finite one) and prints its result line;
the same run on 2 MPI ranks gives the same state; with -var spring the barrier becomes a
rigid body on a spring (fix rigid, fix spring), on 2 ranks.

Arguments are passed to LAMMPS (e.g. -k on t 1 -sf kk): every run then takes them, and
the state of the first also equals the plain styles'."""

import os
import re
import shutil
import sys
import tempfile

import numpy as np

import gransph_run

ARGS = sys.argv[1:]
EXAMPLE = os.path.join(gransph_run.TOP, "examples", "landslide")
VARIABLES = {"steps": 300, "site": os.path.join(EXAMPLE, "make_site.sh"), "dump": 1}

states, outputs = {}, {}
with tempfile.TemporaryDirectory() as tmp:
    runs = [("1 rank", 1, ARGS), ("2 ranks", 2, ARGS)] + ([("plain", 1, [])] if ARGS else [])
    for label, ranks, args in runs:
        outputs[label] = gransph_run.run(os.path.join(EXAMPLE, "in.landslide"), VARIABLES,
                                         ranks=ranks, args=args, cwd=tmp)
        states[label] = gransph_run.read_dump(os.path.join(tmp, "landslide.dump"))
    # the example from a copy of its folder, as a user runs it: its site script finds
    # tools/terrain through tools/lmp
    copy = os.path.join(tmp, "copy")
    shutil.copytree(EXAMPLE, copy)
    gransph_run.run(os.path.join(copy, "in.landslide"), {"steps": 5}, args=ARGS, cwd=copy)
    from_copy = os.path.exists(os.path.join(copy, "landslide_site.data"))
    # the barrier on a spring (a rigid body), on 2 ranks
    spring = gransph_run.run(os.path.join(EXAMPLE, "in.landslide"),
                             dict(VARIABLES, spring=1000), ranks=2, args=ARGS, cwd=tmp)
out = outputs["1 rank"]
checks = []
moved = np.max(np.abs(states["1 rank"]["vx"])) > 1e-3
checks.append(("the sand moved", moved))
checks.append(("the example runs from a copy of its folder", from_copy))
diffs = gransph_run.dump_differences(states["1 rank"], states["2 ranks"])
checks.append(("2 ranks = 1 rank (the dump's 10 digits)", moved and max(diffs.values()) < 1e-8))
if ARGS:
    diffs = gransph_run.dump_differences(states["1 rank"], states["plain"])
    checks.append((f"{' '.join(ARGS)} = plain (the dump's 10 digits)",
                   max(diffs.values()) < 1e-8))
counts = {name: count for count, name in re.findall(r"^(\d+) atoms in group (\w+)$", out, re.M)}
checks.append(("terrain dummies read", int(counts.get("terrain", 0)) > 1000))
barrier = [int(n) for n in re.findall(r"^(\d+) atoms in group barrier$", out, re.M)]
# those created below the channel's rising bed are deleted, most stay
checks.append(("barrier dummies on the bed",
               len(barrier) == 2 and 0.6 * barrier[0] < barrier[1] < barrier[0]))
terrain_normals = re.search(r"^Fix sph/normals: (\d+) wall normals from landslide_site.normals$",
                            out, re.M)
checks.append(("every terrain dummy's normal read", terrain_normals is not None
               and terrain_normals.group(1) == counts.get("terrain")))
normals = re.search(r"^Fix sph/normals: (\d+) wall normals \(-1 0 0\) for group barrier$", out,
                    re.M)
checks.append(("the barrier's normals set", normals is not None
               and barrier and int(normals.group(1)) == barrier[-1]))
result = re.search(r"^result: .* grains (\d+) left (\d+) steps (\d+)", out, re.M)
checks.append(("result line", result is not None))
if result:
    grains, left, steps = map(int, result.groups())
    checks.append(("grains placed on the bed", 300 < grains < 500))
    checks.append(("no grain lost", left == grains))
    checks.append(("300 steps", steps == 300))
checks.append(("the barrier as a rigid body on a spring",
               re.search(r"^\s*1 rigid bodies with \d+ atoms$", spring, re.M) is not None
               and re.search(r"^barrier: spring 1000 N/m", spring, re.M) is not None))
failed = [name for name, ok in checks if not ok]
for name, ok in checks:
    print(f"{name:30s} {'ok' if ok else 'FAILED'}")
sys.exit(1 if failed else 0)
