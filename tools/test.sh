#!/usr/bin/env bash
# Build what is missing, then run every GRANSPH test (unit, force-style YAML,
# physics and MPI tests) with ctest, on both stacks:
#   2021: LAMMPS 29Sep2021 + Kokkos 3.4 (OpenMP+Serial) on this machine, build/
#   2026: LAMMPS 4Jul2026 + Kokkos 5.2.2 (OpenMP) in the Debian sid root of
#         tools/sid-root.sh, build-2026/
# GRANSPH_STACKS selects them (default "2021 2026"; e.g. GRANSPH_STACKS=2021).
# Arguments go to ctest on each stack (e.g. -R Physics -j2).
set -uo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
failed=()
for stack in ${GRANSPH_STACKS:-2021 2026}; do
  start=$SECONDS
  echo "=== GRANSPH tests on the $stack stack"
  case $stack in
    2021)
      bash "$top/tools/build.sh" && (cd "$top/build" && ctest --output-on-failure "$@") ;;
    2026)
      GRANSPH_STACK=2026 bash "$top/tools/build.sh" &&
        bash "$top/tools/sid-root.sh" run bash -c 'cd /gransph/build-2026 && ctest --output-on-failure "$@"' _ "$@" ;;
    *)
      echo "unknown stack '$stack' (GRANSPH_STACKS takes 2021 and 2026)" >&2; false ;;
  esac || failed+=("$stack")
  echo "=== $stack stack: $((SECONDS - start)) s"
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "FAILED on: ${failed[*]}" >&2
  exit 1
fi
