# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""A rigid block resting on a bed of sand (in.rigid_rest): a block of dummy particles
moved by fix rigid, twice the sand's density, set on a periodic bed with its geostatic
stress, comes to rest with the bed's force on it (the pair style's forces on its
dummies, averaged over the last quarter of 4,000 steps) equal to its weight within 1%,
having sunk less than 0.2 dx, both models."""

import os
import tempfile

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    check = gransph_run.Checks()
    with tempfile.TemporaryDirectory() as tmp:
        for model in ("elastoplastic", "phasechange"):
            out = gransph_run.run(os.path.join(HERE, "in.rigid_rest"), {"model": model},
                                  cwd=tmp)
            words = gransph_run.result_line(out)
            weight, force, sink = (float(words[words.index(k) + 1])
                                   for k in ("weight", "force", "settlement"))
            check(f"{model}: the bed carries the block's weight within 1%",
                  abs(force / weight - 1.0) < 0.01,
                  f"{force:.3f} N against {weight:.3f} N ({100 * (force / weight - 1):+.2f}%)")
            check(f"{model}: the block sank less than 0.2 dx", 0.0 <= sink < 0.2,
                  f"{sink:.4f} dx")
    check.finish()


if __name__ == "__main__":
    main()
