#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Draw the landslide's deposit from landslide.dump (run in.landslide with -var dump 1):
a side view (x, z) over the bed's centre line and a top view (x, y), the barrier marked,
into deposit.png."""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

XB, HB = 1.05, 0.2    # the barrier's face and height (in.landslide)


def bed(x, y=0.0):
    """the bed of make_site.sh"""
    return np.where(x < 0.6, 0.84 * (0.8 - x), 1.05 * np.maximum(1 - x, 0) ** 2) + 3 * y ** 2


def read_sand(path):
    with open(path) as f:
        lines = f.readlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    names = lines[start].split()[2:]
    data = np.loadtxt(lines[start + 1:], ndmin=2)
    return {n: data[:, k] for k, n in enumerate(names)}


def main(path="landslide.dump", out="deposit.png"):
    sand = read_sand(path)
    x, y, z = sand["x"], sand["y"], sand["z"]
    fig, (side, top) = plt.subplots(2, 1, figsize=(8, 6))
    xs = np.linspace(0, 1.3, 400)
    side.plot(xs, bed(xs), "k-", lw=1, label="bed (y = 0)")
    side.fill_between([XB, XB + 0.06], 0, HB, color="0.5", label="barrier")
    side.scatter(x, z, s=4, c=np.abs(y), cmap="viridis", label="grains")
    side.set_ylabel("z (m)")
    side.set_aspect("equal")
    side.set_xlim(0, 1.3)
    side.legend(loc="upper right", fontsize=8)
    top.axvspan(XB, XB + 0.06, color="0.5")
    sc = top.scatter(x, y, s=4, c=z - bed(x, y), cmap="magma")
    fig.colorbar(sc, ax=top, label="height above the bed (m)")
    top.set_xlabel("x (m)")
    top.set_ylabel("y (m)")
    top.set_aspect("equal")
    top.set_xlim(0, 1.3)
    fig.suptitle(f"landslide deposit: {len(x)} grains")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(*sys.argv[1:])
