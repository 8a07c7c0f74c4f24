# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""doc/terrain.md's minimal terrain input runs as it stands there: the block after its
marker comment, saved as in.chute in an empty folder and run by tools/lmp, makes its site,
seeds the sand, runs to the end and sets the sand moving down the chute; tools/terrain
preview draws the site and the deposit it dumps."""

import os
import re
import subprocess
import tempfile

import gransph_run

DOC = os.path.join(gransph_run.TOP, "doc", "terrain.md")
MARKER = "<!-- the minimal terrain input"


def doc_input():
    with open(DOC) as f:
        text = f.read()
    at = text.index(MARKER)
    fence = text.index("```\n", at) + 4
    return text[fence:text.index("```", fence)]


def main():
    check = gransph_run.Checks()
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "in.chute")
        with open(path, "w") as f:
            f.write(doc_input())
        out = gransph_run.run(path, cwd=tmp)
        grains = re.search(r"^\s*(\d+) atoms in group sand", out, re.M)
        thermo = [l.split() for l in out.splitlines() if re.match(r"\s+\d+\s+[\d.e+-]+\s", l)]
        check("the input runs to its end", "Loop time" in out and thermo, f"{len(thermo)} thermo lines")
        check("it seeds sand on the terrain", grains and int(grains.group(1)) > 100,
              f"{grains.group(1) if grains else 0} grains")
        if thermo:
            front0, front1 = float(thermo[0][3]), float(thermo[-1][3])
            check("the sand moves down the chute", front1 > front0 + 1e-3,
                  f"front {front0:.4f} -> {front1:.4f} m")
        picture = os.path.join(tmp, "chute.png")
        proc = subprocess.run([os.path.join(gransph_run.TOP, "tools", "terrain"), "preview",
                               os.path.join(tmp, "chute.data"), "--dump", os.path.join(tmp, "chute.dump"),
                               "--out", picture], capture_output=True, text=True)
        drawn = proc.returncode == 0 and os.path.exists(picture) and os.path.getsize(picture) > 20000
        check("tools/terrain preview draws the site and the deposit", drawn,
              (proc.stdout + proc.stderr).strip()[-300:])
    check.finish()


if __name__ == "__main__":
    main()
