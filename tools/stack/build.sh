#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
# Fetch and build the dependencies, then build GRANSPH.
#   tools/stack/build.sh                      LAMMPS 29Sep2021 + Kokkos 3.4 (tools/stack/deps.sh), in build/
#   GRANSPH_STACK=2026 tools/stack/build.sh   LAMMPS 4Jul2026 + Kokkos 5.2 in the Debian sid root
#                                       (tools/stack/sid-root.sh), in build-2026/
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
if [ "${GRANSPH_STACK:-2021}" = 2026 ]; then
  bash "$top/tools/stack/sid-root.sh"
  # inside the root this tree is /gransph and LAMMPS is /opt/lammps
  bash "$top/tools/stack/sid-root.sh" run bash -c '
    cmake -S /gransph -B /gransph/build-2026 -G Ninja \
      -D LAMMPS_SOURCE_DIR=/opt/lammps -D LAMMPS_BUILD_DIR=/opt/lammps/build >/dev/null &&
    cmake --build /gransph/build-2026 -j "$JOBS"'
  exit
fi
bash "$top/tools/stack/deps.sh"
cmake -S "$top" -B "$top/build" -G Ninja -D GRANSPH_DEPS="${GRANSPH_DEPS:-$HOME/.cache/gransph}" >/dev/null
cmake --build "$top/build" -j "${JOBS:-$(nproc)}"
