#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
# Install GRANSPH's dependencies from Debian's registry and build Kokkos + LAMMPS.
#
# Everything lands outside the git tree, in $GRANSPH_DEPS (default ~/.cache/gransph):
#   src/     pinned Debian source packages (sha256-checked)
#   kokkos/  Kokkos 3.4.01 (from trilinos' packages/kokkos), OpenMP+Serial, installed
#   kokkos-cuda/  the same Kokkos for CUDA sm_80 (if nvcc exists), for a compile-only check
#   lammps/  LAMMPS 29Sep2021 update 2 source tree and its build tree (lammps/build)
# A second run with everything in place only re-checks and returns in seconds.
set -euo pipefail

GRANSPH_DEPS=${GRANSPH_DEPS:-$HOME/.cache/gransph}
JOBS=${JOBS:-$(nproc)}

LAMMPS_DEB=20220106.git7586adbb6a+ds1-2
LAMMPS_ORIG=lammps_20220106.git7586adbb6a+ds1.orig.tar.xz
LAMMPS_SHA256=65146c615ad24d8b8bc64f4e05e86226a7f1fdb45c0b5ea9416562b9f3863082
TRILINOS_DEB=13.2.0-4
TRILINOS_ORIG=trilinos_13.2.0.orig.tar.gz
TRILINOS_SHA256=0ddb47784ba7b8a6b9a07a4822b33be508feb4ccd54301b2a5d10c9e54524b90

APT_PACKAGES=(build-essential cmake ninja-build ccache dpkg-dev xz-utils
  libopenmpi-dev openmpi-bin libeigen3-dev libgtest-dev libgmock-dev libyaml-dev
  libpng-dev python3-numpy python3-matplotlib python3-gdal python3-stl
  python3-sphinx python3-myst-parser)

log() { printf '[deps] %s\n' "$*"; }

# shellcheck source=tools/stack/apt-mirror.sh
source "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/apt-mirror.sh"
# shellcheck source=tools/stack/arch.sh
source "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/arch.sh"

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

install_apt_packages() {
  local missing=()
  for p in "${APT_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
  done
  if ! grep -rqs '^Types:.*deb-src' /etc/apt/sources.list.d/ &&
     ! grep -qs '^deb-src .* bookworm ' /etc/apt/sources.list; then
    # the deb-src entry uses the mirror of the machine's own bookworm `deb` entry
    local mirror; mirror=$(debian_mirror_uri bookworm)
    log "enabling deb-src for bookworm ($mirror)"
    as_root tee /etc/apt/sources.list.d/gransph-src.sources >/dev/null <<SRC
Types: deb-src
URIs: $mirror
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
    missing+=(update-needed)
  fi
  if [ ${#missing[@]} -gt 0 ]; then
    log "installing apt packages: ${missing[*]}"
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${APT_PACKAGES[@]}" >/dev/null
  fi
}

# fetch_source PACKAGE DEBIAN_VERSION ORIG_TARBALL SHA256
fetch_source() {
  local pkg=$1 ver=$2 orig=$3 sum=$4
  mkdir -p "$GRANSPH_DEPS/src"
  if ! echo "$sum  $GRANSPH_DEPS/src/$orig" | sha256sum --check --status 2>/dev/null; then
    log "downloading Debian source package $pkg=$ver"
    (cd "$GRANSPH_DEPS/src" && apt-get source --download-only "$pkg=$ver" >/dev/null 2>&1)
    echo "$sum  $GRANSPH_DEPS/src/$orig" | sha256sum --check --quiet ||
      { echo "[deps] checksum mismatch for $orig" >&2; exit 1; }
  fi
}

build_kokkos() {
  local prefix=$GRANSPH_DEPS/kokkos stamp=$GRANSPH_DEPS/kokkos/.built-$TRILINOS_DEB
  [ -f "$stamp" ] && return
  log "building Kokkos 3.4.01 (OpenMP+Serial)"
  local work=$GRANSPH_DEPS/kokkos-src
  rm -rf "$work" "$prefix" && mkdir -p "$work"
  tar -xzf "$GRANSPH_DEPS/src/$TRILINOS_ORIG" -C "$work" --strip-components=2 \
      --wildcards '*/packages/kokkos/*'
  cmake -S "$work/kokkos" -B "$work/build" -G Ninja -D CMAKE_BUILD_TYPE=Release \
      -D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D CMAKE_INSTALL_PREFIX="$prefix" \
      -D BUILD_SHARED_LIBS=ON -D Kokkos_ENABLE_SERIAL=ON -D Kokkos_ENABLE_OPENMP=ON \
      -D CMAKE_CXX_STANDARD=14 >/dev/null
  cmake --build "$work/build" -j "$JOBS" >/dev/null
  cmake --install "$work/build" >/dev/null
  rm -rf "$work"
  touch "$stamp"
}

# A second Kokkos 3.4.01 for CUDA (sm_80), only for the compile check in
# unittest/cuda: there is no GPU here, but nvcc proves our device code compiles.
# 3.4.01 predates CUDA 13, hence tools/stack/patches/kokkos-3.4.01-cuda13.patch.
build_kokkos_cuda() {
  local nvcc; nvcc=$(PATH=$PATH:/usr/local/cuda/bin command -v nvcc) ||
    { log "nvcc not found (PATH, /usr/local/cuda/bin): skipping CUDA Kokkos and its compile check"; return 0; }
  local patch; patch=$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/patches/kokkos-3.4.01-cuda13.patch
  local prefix=$GRANSPH_DEPS/kokkos-cuda
  local stamp; stamp=$prefix/.built-$TRILINOS_DEB-$(sha256sum < "$patch" | cut -c1-16)
  [ -f "$stamp" ] && return
  log "building Kokkos 3.4.01 (CUDA sm_80 + Serial, $nvcc; ~1 min)"
  local work=$GRANSPH_DEPS/kokkos-cuda-src start=$SECONDS
  rm -rf "$work" "$prefix" && mkdir -p "$work"
  tar -xzf "$GRANSPH_DEPS/src/$TRILINOS_ORIG" -C "$work" --strip-components=2 \
      --wildcards '*/packages/kokkos/*'
  patch -d "$work/kokkos" -p1 --quiet < "$patch"
  # nvcc_wrapper runs the first nvcc in PATH; static libs: nothing links them here
  PATH=$(dirname "$nvcc"):$PATH cmake -S "$work/kokkos" -B "$work/build" -G Ninja \
      -D CMAKE_BUILD_TYPE=Release -D CMAKE_CXX_COMPILER="$work/kokkos/bin/nvcc_wrapper" \
      -D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D CMAKE_INSTALL_PREFIX="$prefix" \
      -D CMAKE_CXX_STANDARD=14 -D Kokkos_ENABLE_CUDA=ON -D Kokkos_ENABLE_SERIAL=ON \
      -D Kokkos_ARCH_AMPERE80=ON -D Kokkos_ENABLE_CUDA_LAMBDA=ON >/dev/null
  PATH=$(dirname "$nvcc"):$PATH cmake --build "$work/build" -j "$JOBS" >/dev/null
  cmake --install "$work/build" >/dev/null
  # the patched wrapper defaults to sm_80; CUDA 13 rejects the stock sm_35
  grep -q '^default_arch="sm_80"' "$prefix/bin/nvcc_wrapper" ||
    { echo "[deps] $prefix/bin/nvcc_wrapper does not default to sm_80" >&2; exit 1; }
  rm -rf "$work"
  touch "$stamp"
  log "CUDA Kokkos built in $((SECONDS - start)) s"
}

# The LAMMPS packages GRANSPH needs: KOKKOS (the /kk styles), PLUGIN (loads us),
# SPH (the sph/taitwater peer in bench/), GRANULAR (for comparisons), MOLECULE
# (LAMMPS' test_fix_timestep harness skips every test without it), RIGID (fix rigid
# moves bodies of dummy particles under the sand's load).
lammps_cmake_args() {
  echo -G Ninja -D CMAKE_BUILD_TYPE=Release -D CMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -D CMAKE_PREFIX_PATH="$GRANSPH_DEPS/kokkos" -D BUILD_SHARED_LIBS=on \
    -D BUILD_MPI=on -D BUILD_OMP=on -D LAMMPS_EXCEPTIONS=on \
    -D PKG_KOKKOS=on -D EXTERNAL_KOKKOS=on -D Kokkos_ENABLE_OPENMP=on \
    -D PKG_PLUGIN=on -D PKG_SPH=on -D PKG_GRANULAR=on -D PKG_MOLECULE=on -D PKG_RIGID=on \
    -D WITH_PNG=on -D WITH_JPEG=off -D WITH_FFMPEG=off -D WITH_GZIP=off
}

build_lammps() {
  local src=$GRANSPH_DEPS/lammps build=$GRANSPH_DEPS/lammps/build
  local cxx_flags; cxx_flags=$(gransph_arch_cxx_flags)
  local config; config=$( (lammps_cmake_args; echo "$cxx_flags") | sha256sum | cut -c1-16)
  # 29Sep2021 built with exceptions loses a one-rank error's message from a redirected
  # screen and the log file (its main() aborts without flushing them); later LAMMPS
  # flushes them first, and so does the source after this patch
  local patch; patch=$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/patches/lammps-29Sep2021-flush-before-abort.patch
  local source_tag; source_tag=$LAMMPS_DEB-$(sha256sum < "$patch" | cut -c1-16)
  local stamp=$build/.built-$source_tag-$config
  [ -f "$stamp" ] && [ -x "$build/lmp" ] && return
  if [ ! -f "$src/.unpacked-$source_tag" ]; then
    log "unpacking LAMMPS $LAMMPS_DEB"
    rm -rf "$src" && mkdir -p "$src"
    tar -xJf "$GRANSPH_DEPS/src/$LAMMPS_ORIG" -C "$src" --strip-components=1
    patch -d "$src" -p1 --quiet < "$patch"
    touch "$src/.unpacked-$source_tag"
  fi
  log "building LAMMPS (this takes ~6 min on 2 cores without a warm ccache)"
  # shellcheck disable=SC2046
  cmake -S "$src/cmake" -B "$build" $(lammps_cmake_args) -D "CMAKE_CXX_FLAGS=$cxx_flags" >/dev/null
  cmake --build "$build" -j "$JOBS" >/dev/null
  touch "$stamp"
}

install_apt_packages
fetch_source lammps "$LAMMPS_DEB" "$LAMMPS_ORIG" "$LAMMPS_SHA256"
fetch_source trilinos "$TRILINOS_DEB" "$TRILINOS_ORIG" "$TRILINOS_SHA256"
build_kokkos
build_kokkos_cuda
build_lammps
log "ready: LAMMPS in $GRANSPH_DEPS/lammps/build, Kokkos in $GRANSPH_DEPS/kokkos"
