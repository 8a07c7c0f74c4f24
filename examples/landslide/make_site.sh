#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
# The site of in.landslide, made by the input (shell ./make_site.sh DX): a chute whose bed
# falls at 40 degrees (slope 0.84) to x = 0.6 m, bends into the level along a parabola
# z = 1.05 (1 - x)^2 and is level from x = 1 m, with a channel 3 y^2 across it, as an
# elevation grid on 1 cm cells; beneath it three layers of dummy particles DX apart
# (atom type 2) that follow the surface, with their outward normals (doc/terrain.md).
set -e
dx=${1:-0.02}
# tools/lmp says where GRANSPH is (GRANSPH_TOP): the example runs from a copy of its folder
terrain=${GRANSPH_TOP:-$(dirname "$0")/../..}/tools/terrain
"$terrain" grid --function "where(x < 0.6, 0.84*(0.8 - x), 1.05*maximum(1 - x, 0)**2) + 3*y**2" \
  --xlim -0.1 1.4 --ylim -0.2 0.2 --cell 0.01 landslide_site.asc
"$terrain" layers landslide_site.asc landslide_site.data --dx "$dx" --height 0.3 \
  --xlim 0 1.35 --ylim -0.18 0.18 --type 2
