# Sourced by tools/deps.sh and tools/sid-root.sh: the instruction set LAMMPS and the
# plugin are compiled for.
#   GRANSPH_ARCH=native   (default) this machine's: AVX2 and FMA where the CPU has them
#   GRANSPH_ARCH=generic  the compiler's default target (x86-64: SSE2, no FMA), for a
#                         build that runs on any machine of the architecture
# A build for another GRANSPH_ARCH is a build of its own (the LAMMPS stamps hash the
# flags, ccache keys on them).
gransph_arch() {
  case ${GRANSPH_ARCH:-native} in
    native|generic) echo "${GRANSPH_ARCH:-native}" ;;
    *) echo "GRANSPH_ARCH must be native or generic, not '${GRANSPH_ARCH}'" >&2; return 1 ;;
  esac
}

# the CMake arguments that set it for LAMMPS (empty for generic)
gransph_arch_cmake_args() {
  local arch; arch=$(gransph_arch) || return 1
  [ "$arch" = native ] && echo "-D CMAKE_CXX_FLAGS=-march=native"
  return 0
}
