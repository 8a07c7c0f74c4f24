# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
# Sourced by tools/stack/deps.sh and tools/stack/sid-root.sh: the instruction set LAMMPS and the
# plugin are compiled for.
#   GRANSPH_ARCH=native   (default) this machine's: AVX2, FMA, AVX-512 where the CPU has them
#   GRANSPH_ARCH=generic  the compiler's default target (x86-64: SSE2), for a build that
#                         runs on any machine of the architecture
# Either way without contracting a * b + c into one fused multiply-add: FMA rounds once
# where the source rounds twice, so results would move in their last digits with the
# instruction set; with it, the force-style YAML reference of the paper's settings
# (PairStyle:sph_granular_paper, 5e-13) failed after its run. Measured, contraction gained
# nothing (bench/README.md). The fused multiply-adds that the source writes stay: the
# host's lanes (src/GRANSPH/gransph_lanes.h, native builds on CPUs with AVX2 and FMA) add
# the grains' sums so, and the references hold.
# A build for another GRANSPH_ARCH is a build of its own (the LAMMPS stamps hash the
# flags, ccache keys on them).
gransph_arch() {
  case ${GRANSPH_ARCH:-native} in
    native|generic) echo "${GRANSPH_ARCH:-native}" ;;
    *) echo "GRANSPH_ARCH must be native or generic, not '${GRANSPH_ARCH}'" >&2; return 1 ;;
  esac
}

# the C++ compiler flags for it; give them to CMake as one argument:
#   cmake ... -D "CMAKE_CXX_FLAGS=$(gransph_arch_cxx_flags)"
gransph_arch_cxx_flags() {
  local arch; arch=$(gransph_arch) || return 1
  if [ "$arch" = native ]; then echo "-march=native -ffp-contract=off"; else echo "-ffp-contract=off"; fi
}
