# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""README.md's minimal input runs as it stands there: the indented block under "A minimal
input", saved as in.collapse in an empty folder and run by tools/lmp, collapses the
column: the deposit's edge (compute sph/runout) starts at the column's radius and ends
beyond it, inside the floor."""

import os
import re
import tempfile

import gransph_run

README = os.path.join(gransph_run.TOP, "README.md")
R0, FLOOR = 0.2, 0.4     # the input's column and floor radii (m)


def readme_input():
    """The first indented block after the heading, as a user copies it."""
    with open(README) as f:
        text = f.read()
    lines = text[text.index("## A minimal input"):].splitlines()
    start = next(k for k, l in enumerate(lines) if l.startswith("    plugin load"))
    block = []
    for line in lines[start:]:
        if not line.startswith("    "):
            break
        block.append(line[4:])
    return "\n".join(block) + "\n"


def main():
    check = gransph_run.Checks()
    text = readme_input()
    check("the block is a whole input", text.startswith("plugin load") and "\nrun " in text,
          f"{len(text.splitlines())} lines")
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "in.collapse")
        with open(path, "w") as f:
            f.write(text)
        out = gransph_run.run(path, cwd=tmp)
    thermo = [l.split() for l in out.splitlines() if re.match(r"\s+\d+\s+[\d.e+-]+\s+[\d.e+-]+\s*$", l)]
    check("it runs to its end", "Loop time" in out and len(thermo) > 2, f"{len(thermo)} thermo lines")
    if thermo:
        edge0, edge1 = float(thermo[0][2]), float(thermo[-1][2])
        check("the column collapses: its edge moves out from r0, inside the floor",
              abs(edge0 - R0) < 0.03 and R0 + 0.02 < edge1 < FLOOR,
              f"edge {edge0:.4f} -> {edge1:.4f} m at step {thermo[-1][0]}")
    check.finish()


if __name__ == "__main__":
    main()
