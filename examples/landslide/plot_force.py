#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Draw the barrier's force histories of several runs of in.landslide (their
landslide.force files, one per run, each copied aside) into barrier_force.png:

    plot_force.py fixed.force "fixed" spring1000.force "spring 1000 N/m" ...
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main(args):
    if len(args) < 2 or len(args) % 2:
        sys.exit(__doc__)
    fig, ax = plt.subplots(figsize=(7, 3.5))
    for path, label in zip(args[::2], args[1::2]):
        t, force = np.loadtxt(path, unpack=True)
        ax.plot(t, force, lw=1, label=label)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("normal force on the barrier (N)")
    ax.set_xlim(0.6, None)
    ax.legend()
    fig.tight_layout()
    fig.savefig("barrier_force.png", dpi=120)


if __name__ == "__main__":
    main(sys.argv[1:])
