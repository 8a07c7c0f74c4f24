#!/usr/bin/env bash
# Build what is missing, then run every GRANSPH test (unit, force-style YAML,
# physics and MPI tests) with ctest.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$top/tools/build.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$top/build" && ctest --output-on-failure "$@"
