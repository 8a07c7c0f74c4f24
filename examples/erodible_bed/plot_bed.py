#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Draw erodible_bed.png from erodible_bed.dump (in.erodible_bed -var dump 1): the grains
at the start and at rest, coloured by material (compute sph/material/atom: 1 the column,
2 the erodible bed), in the slope's frame (x down the slope, y its normal).

    ../../tools/lmp -in in.erodible_bed -var dump 1 && ./plot_bed.py [dump] [png] [title]
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def snapshots(path):
    """the first and the last snapshot of a dump custom file, each a dict of columns"""
    with open(path) as f:
        lines = f.read().splitlines()
    starts = [i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")]
    out = []
    for start in (starts[0], starts[-1]):
        names = lines[start].split()[2:]
        count = int(lines[start - 5])    # ITEM: NUMBER OF ATOMS, then the box's 4 lines
        data = np.array([[float(w) for w in l.split()] for l in lines[start + 1:start + 1 + count]])
        out.append({n: data[:, k] for k, n in enumerate(names)})
    return out


def main():
    dump = sys.argv[1] if len(sys.argv) > 1 else "erodible_bed.dump"
    png = sys.argv[2] if len(sys.argv) > 2 else "erodible_bed.png"
    title = sys.argv[3] if len(sys.argv) > 3 else ""
    first, d = snapshots(dump)
    colour = lambda snap: np.where(snap["c_material"].astype(int) == 1, "#d4a017", "#b03a2e")
    material = d["c_material"].astype(int)     # 1 the column (yellow), 2 the bed (red)
    disp = np.hypot(d["x"] - d["f_start[1]"], d["y"] - d["f_start[2]"])
    moved = (material == 2) & (disp > 0.01)
    mobile = (material == 1) | moved
    xmax = min(np.percentile(d["x"][mobile], 99.5) + 0.15, d["x"].max())
    xmin = first["x"].min() - 0.03
    ytop = max(first["y"].max(), d["y"].max()) + 0.02
    fig, axes = plt.subplots(2, 1, figsize=(10, 4.2), sharex=True)
    for ax, snap, label in ((axes[0], first, "at the start"), (axes[1], d, "at rest")):
        keep = snap["x"] < xmax
        ax.scatter(snap["x"][keep], snap["y"][keep], s=3, c=colour(snap)[keep], linewidths=0)
        ax.axhline(0.0, color="k", lw=0.8)
        ax.axvline(0.0, color="0.6", lw=0.6, ls="--")
        ax.set_aspect("equal")
        ax.set_ylim(-0.01, ytop)
        ax.set_xlim(xmin, xmax)
        ax.set_ylabel("y (m)")
        ax.set_title(label, fontsize=9, loc="left")
    if moved.any():
        axes[1].scatter(d["x"][moved], d["y"][moved], s=5, facecolors="none",
                        edgecolors="k", linewidths=0.3)
    axes[1].set_xlabel("x down the slope from the column's foot (m)")
    fig.suptitle(title or "column (yellow) onto an erodible bed (red; circled: moved > 1 cm)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
