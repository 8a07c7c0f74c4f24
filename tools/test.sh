#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
# Build what is missing, then run every GRANSPH test (unit, force-style YAML,
# physics and MPI tests) with ctest, on both stacks:
#   2021: LAMMPS 29Sep2021 + Kokkos 3.4 (OpenMP+Serial) on this machine, build/
#   2026: sid's LAMMPS (4Jul2026 on) + Kokkos 5 (OpenMP) in the Debian sid root of
#         tools/stack/sid-root.sh, build-2026/; its lock (package versions, LAMMPS version
#         and tarball sha256) is printed first
# GRANSPH_STACKS selects them (default "2021 2026"; e.g. GRANSPH_STACKS=2021).
# Arguments go to ctest on each stack (e.g. -R Physics -j1).
# ctest runs as many tests at once as there are cores (CTEST_PARALLEL_LEVEL, or -j):
# most tests are one LAMMPS process at a time and Python between runs, so on two cores
# the suite takes about half the time (a test's 2-rank runs then share the cores with
# another test: slower, not different).
# Each stack's time is printed per step: dependencies, plugin, tests.
set -uo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export CTEST_PARALLEL_LEVEL=${CTEST_PARALLEL_LEVEL:-$(nproc)}

times=()
step() { # step NAME CMD...: run CMD, note its wall time
  local name=$1 start=$SECONDS; shift
  "$@"; local rc=$?
  times+=("$name $((SECONDS - start)) s")
  return $rc
}

stack_2021() {
  step deps bash "$top/tools/stack/deps.sh" &&
    step plugin bash "$top/tools/stack/build.sh" &&
    step tests ctest --test-dir "$top/build" --output-on-failure "$@"
}

stack_2026() {
  step deps bash "$top/tools/stack/sid-root.sh" &&
    echo "=== the 2026 stack is made of (its lock, from tools/stack/sid-root.sh lock):" &&
    bash "$top/tools/stack/sid-root.sh" lock &&
    step plugin env GRANSPH_STACK=2026 bash "$top/tools/stack/build.sh" &&
    step tests bash "$top/tools/stack/sid-root.sh" run bash -c 'cd /gransph/build-2026 &&
      CTEST_PARALLEL_LEVEL=$1 ctest --output-on-failure "${@:2}"' _ "$CTEST_PARALLEL_LEVEL" "$@"
}

failed=()
for stack in ${GRANSPH_STACKS:-2021 2026}; do
  start=$SECONDS times=()
  echo "=== GRANSPH tests on the $stack stack"
  case $stack in
    2021|2026) "stack_$stack" "$@" ;;
    *) echo "unknown stack '$stack' (GRANSPH_STACKS takes 2021 and 2026)" >&2; false ;;
  esac || failed+=("$stack")
  summary=$(IFS=';'; echo "${times[*]}")
  echo "=== $stack stack: $((SECONDS - start)) s (${summary//;/, })"
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "FAILED on: ${failed[*]}" >&2
  exit 1
fi
