#!/usr/bin/env bash
# Fetch and build the dependencies (tools/deps.sh), then build GRANSPH in build/.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$top/tools/deps.sh"
cmake -S "$top" -B "$top/build" -G Ninja -D GRANSPH_DEPS="${GRANSPH_DEPS:-$HOME/.cache/gransph}" >/dev/null
cmake --build "$top/build" -j "${JOBS:-$(nproc)}"
