#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Draw layered_slope.png from the dumps of in.layered_slope (-var dump 1) at two or more
angles: each strip coloured by material (compute sph/material/atom: 1 the sand of
phi = 37 deg, 2 the weak layer of phi = 25 deg), every eighth column of grains at the
start drawn darker so that the shear shows, and the grains' mean velocity down the slope
row by row.

    for t in 23 27; do ../../tools/lmp -in in.layered_slope -var theta $t -var dump 1 \\
        && mv layered_slope.dump layered_slope.$t.dump; done
    ./plot_slope.py layered_slope.23.dump layered_slope.27.dump
"""

import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def read_last(path):
    """the last snapshot of a dump custom file as a dict of columns"""
    with open(path) as f:
        lines = f.read().splitlines()
    start = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    names = lines[start].split()[2:]
    data = np.array([[float(w) for w in l.split()] for l in lines[start + 1:]])
    return {n: data[:, k] for k, n in enumerate(names)}


def main():
    dumps = sys.argv[1:] or ["layered_slope.23.dump", "layered_slope.27.dump"]
    png = "layered_slope.png"
    fig, axes = plt.subplots(1, len(dumps) + 1, figsize=(3.6 * len(dumps) + 3.2, 3.4),
                             gridspec_kw={"width_ratios": [3] * len(dumps) + [2]})
    for ax, path in zip(axes, dumps):
        d = read_last(path)
        theta = re.search(r"\.(\d+(?:\.\d+)?)\.dump$", path)
        weak = d["c_material"].astype(int) == 2
        dx = np.min(np.diff(np.unique(np.round(d["f_start[2]"], 9))))
        band = (np.floor(d["f_start[1]"] / dx + 1e-6).astype(int) % 8) == 0
        colour = np.where(weak, np.where(band, "#6e1f17", "#c0504d"),
                          np.where(band, "#7a5c0b", "#e0b44c"))
        ax.scatter(d["xu"], d["y"], s=6, c=colour, linewidths=0)
        ax.axhline(0.0, color="k", lw=1.0)
        ax.set_aspect("equal")
        ax.set_xlabel("x down the slope (m)")
        ax.set_title(f"theta = {theta.group(1)} deg" if theta else path, fontsize=9)
        rows = np.round(d["f_start[2]"] / dx).astype(int)
        ys = [np.mean(d["y"][rows == r]) for r in np.unique(rows)]
        vs = [np.mean(d["vx"][rows == r]) for r in np.unique(rows)]
        axes[-1].plot(vs, ys, "o-", ms=3, label=ax.get_title())
        ylo, yhi = d["f_start[2]"][weak].min(), d["f_start[2]"][weak].max()
        axes[-1].axhspan(ylo - dx / 2, yhi + dx / 2, color="#c0504d", alpha=0.08)
    axes[0].set_ylabel("y, normal to the slope (m)")
    axes[-1].set_xlabel("velocity down the slope (m/s)")
    axes[-1].set_ylabel("y (m)")
    axes[-1].legend(fontsize=8)
    axes[-1].set_title("by row (red band: the weak layer)", fontsize=9)
    fig.suptitle("sand of phi = 37 deg (yellow) over a weak layer of phi = 25 deg (red); "
                 "dark columns: straight at the start", fontsize=9)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
