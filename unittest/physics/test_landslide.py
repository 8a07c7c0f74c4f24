"""examples/landslide runs: its site made by tools/terrain, read with the dummies' own
normals, the barrier built on it, the sand placed on the bed; a short run keeps every
grain and finite state (the fix stops on a non-finite one) and prints its result line."""

import os
import re
import sys
import tempfile

import gransph_run

EXAMPLE = os.path.join(gransph_run.TOP, "examples", "landslide")

with tempfile.TemporaryDirectory() as tmp:
    out = gransph_run.run(os.path.join(EXAMPLE, "in.landslide"),
                          {"steps": 300, "site": os.path.join(EXAMPLE, "make_site.sh")}, cwd=tmp)
checks = []
counts = {name: count for count, name in re.findall(r"^(\d+) atoms in group (\w+)$", out, re.M)}
checks.append(("terrain dummies read", int(counts.get("terrain", 0)) > 1000))
barrier = [int(n) for n in re.findall(r"^(\d+) atoms in group barrier$", out, re.M)]
# those created below the channel's rising bed are deleted, most stay
checks.append(("barrier dummies on the bed",
               len(barrier) == 2 and 0.6 * barrier[0] < barrier[1] < barrier[0]))
normals = re.search(r"^\s*(\d+) settings made for d2_wall_normal\[1\]", out, re.M)
checks.append(("the barrier's normals set", normals is not None and int(normals.group(1)) > 300))
result = re.search(r"^result: .* grains (\d+) left (\d+) steps (\d+)", out, re.M)
checks.append(("result line", result is not None))
if result:
    grains, left, steps = map(int, result.groups())
    checks.append(("grains placed on the bed", 300 < grains < 500))
    checks.append(("no grain lost", left == grains))
    checks.append(("300 steps", steps == 300))
failed = [name for name, ok in checks if not ok]
for name, ok in checks:
    print(f"{name:30s} {'ok' if ok else 'FAILED'}")
sys.exit(1 if failed else 0)
