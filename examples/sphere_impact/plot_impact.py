#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""The ball's path and the bed at the end of a run (sphere_impact.png):

  plot_impact.py PATH.txt STATE.dump

PATH.txt is the sphere_impact.txt of a run (time, the ball's bottom, its vertical
speed), STATE.dump the sphere_impact.dump of a run with -var dump 1 (the README's
run with -var stop deepest: the state once the ball rests or turns)."""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_dump(path):
    with open(path) as f:
        lines = f.readlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    names = lines[start].split()[2:]
    data = np.loadtxt(lines[start + 1:])
    return {name: data[:, k] for k, name in enumerate(names)}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    path, dump = sys.argv[1:3]
    t, z, vz = np.loadtxt(path, unpack=True)
    atoms = read_dump(dump)
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))

    left.plot(1e3 * t, 1e3 * z, "k-")
    left.axhline(0.0, color="0.6", lw=0.8)
    left.set_xlabel("t (ms)")
    left.set_ylabel("the ball's bottom above the bed's surface (mm)")
    deepest = np.argmin(z)
    left.annotate(f"deepest {-1e3 * z[deepest]:.1f} mm at {1e3 * t[deepest]:.1f} ms",
                  (1e3 * t[deepest], 1e3 * z[deepest]), xytext=(10, -5),
                  textcoords="offset points", fontsize=8)

    # a slice one spacing thick through the ball's centre (y = 0)
    # (the spacing from the walls' lattice, which does not move)
    dx = np.min(np.diff(np.unique(np.round(atoms["x"][atoms["type"] == 2], 9))))
    near = (atoms["y"] > 0.0) & (atoms["y"] < dx)
    sand = near & (atoms["type"] == 1)
    walls = near & (atoms["type"] == 2)
    ball = near & (atoms["type"] == 3)
    speed = np.hypot(atoms["vx"], atoms["vz"])
    points = right.scatter(1e3 * atoms["x"][sand], 1e3 * atoms["z"][sand], c=speed[sand],
                           s=6, cmap="viridis", vmin=0.0)
    right.scatter(1e3 * atoms["x"][walls], 1e3 * atoms["z"][walls], s=6, color="0.8")
    right.scatter(1e3 * atoms["x"][ball], 1e3 * atoms["z"][ball], s=6, color="0.4")
    right.set_aspect("equal")
    right.set_xlabel("x (mm)")
    right.set_ylabel("z (mm)")
    right.set_title("the bed at the end (slice y in (0, dx)): walls light, ball dark",
                    fontsize=8)
    fig.colorbar(points, ax=right, label="grain speed in the slice's plane (m/s)")
    fig.tight_layout()
    fig.savefig("sphere_impact.png", dpi=120)


if __name__ == "__main__":
    main()
