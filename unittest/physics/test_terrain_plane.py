# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""A terrain wall carries a layer as a box floor does: a sand layer (4 particles deep,
free ends and sides) on a plane inclined at 20 degrees that tools/terrain builds
from an elevation grid (three layers of dummies with their normals, gravity vertical)
has the same stress at its base, within 2%, as the same layer on today's level lattice
box floor under gravity tilted by 20 degrees (in.terrain_plane): the mean normal and
shear stress in the slope's frame over the bottom row of the layer's middle, averaged
over its last 1000 steps, both models. The layer's free ends and sides slump, and its
middle creeps down the slope at a few cm/s: as fast on either floor (within 10%; the
phase-change model's differ by 6%), and far below the 0.7 m/s of a frictionless slide
over that time (0.21 s).

Needs tools/terrain's GDAL reader (python3-gdal: tools/stack/deps.sh, tools/stack/sid-root.sh)."""

import math
import os
import subprocess
import sys
import tempfile

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
TERRAIN = os.path.join(gransph_run.TOP, "tools", "terrain")
DX, THETA = 0.02, 20.0
# in.terrain_plane's layer: L = 30 dx along, W = 16 dx across, floors 4 dx beyond it
L, W, MARGIN, H = 30 * DX, 16 * DX, 4 * DX, 4 * DX


def make_terrain(tmp):
    """terrain.data: the box case's floor turned by theta about y (same extent along the
    slope and across), in a box that holds the layer before and after its turn"""
    t = math.radians(THETA)
    subprocess.run([TERRAIN, "grid", f"--function=-tan({THETA}*pi/180)*x", "--xlim", "-0.3",
                    "1.0", "--ylim", "-0.3", "0.6", "--cell", "0.01", "plane.asc"],
                   cwd=tmp, check=True)
    box = (-2 * MARGIN, L + 2 * MARGIN, -2 * MARGIN, W + 2 * MARGIN,
           -(L + MARGIN) * math.sin(t) - 5 * DX, H + 2 * DX)
    subprocess.run([TERRAIN, "layers", "plane.asc", "terrain.data", "--dx", str(DX),
                    "--xlim", str(-MARGIN * math.cos(t)), str((L + MARGIN) * math.cos(t)),
                    "--ylim", str(-MARGIN), str(W + MARGIN), "--box"] + [str(b) for b in box],
                   cwd=tmp, check=True)


def main():
    check = gransph_run.Checks()
    with tempfile.TemporaryDirectory() as tmp:
        make_terrain(tmp)
        for model in ("elastoplastic", "phasechange"):
            result = {}
            for floor in ("box", "terrain"):
                out = gransph_run.run(os.path.join(HERE, "in.terrain_plane"),
                                      {"floor": floor, "model": model, "dx": DX,
                                       "theta": THETA}, cwd=tmp)
                words = gransph_run.result_line(out)
                result[floor] = {k: float(words[words.index(k) + 1])
                                 for k in ("snn", "snt", "vt", "grains")}
                print(" ".join(words), flush=True)
            box, terrain = result["box"], result["terrain"]
            check(f"{model}: same grains", box["grains"] == terrain["grains"] > 1000,
                  f"{box['grains']:.0f} and {terrain['grains']:.0f}")
            for key, name in (("snn", "normal"), ("snt", "shear")):
                rel = abs(terrain[key] - box[key]) / abs(box[key])
                check(f"{model}: base {name} stress on the terrain plane = box floor",
                      rel < 0.02 and box[key] != 0.0,
                      f"{terrain[key]:.1f} against {box[key]:.1f} Pa ({100 * rel:.2f}%)")
            creep = abs(terrain["vt"] - box["vt"]) / abs(box["vt"])
            check(f"{model}: the middle creeps alike on both floors",
                  creep < 0.1 and 0.0 < box["vt"] < 0.1,
                  f"{terrain['vt']:.4f} and {box['vt']:.4f} m/s down the slope")
    check.finish()


if __name__ == "__main__":
    sys.exit(main())
