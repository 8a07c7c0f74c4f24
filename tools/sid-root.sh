#!/usr/bin/env bash
# The second stack: LAMMPS 4Jul2026 with KOKKOS on Kokkos 5.2.2 (OpenMP), in a
# Debian sid root, because Debian 12 cannot run the only Kokkos 5 we can get
# (sid's binary libkokkos-dev needs glibc 2.38 and GCC 13's libstdc++).
#
#   tools/sid-root.sh              make the root and build LAMMPS in it (cached;
#                                  a second call only checks and returns in seconds)
#   tools/sid-root.sh run CMD...   run CMD inside the root (as root, cwd /gransph),
#                                  with this source tree mounted at /gransph
#
# Everything lands in $GRANSPH_DEPS/sid (default ~/.cache/gransph/sid):
#   root/      the sid root (mmdebstrap, pinned package versions); inside it
#              /opt/lammps (LAMMPS 4Jul2026 source), /opt/lammps/build (its build),
#              /var/cache/ccache (the compiler cache of every build in the root)
#   src/       the LAMMPS orig tarball, sha256 from sid's Sources index
#   apt/       apt lists of sid for the host-side queries (pins, Sources)
#   times.log  how long each step took
# The Debian mirror is the one of this machine's own bookworm `deb` entry.
#
# Mounts: /proc, /sys, /dev and this source tree are mounted into the root only
# inside a private mount namespace (unshare --mount) that lives as long as one
# command, so no mount outlives it and the host never sees them: `rm -rf` of the
# root from the host is safe. Never delete the root from *inside* a `run`
# command: there /dev and the source tree are mounted in it.
set -euo pipefail

here=$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")
top=$(dirname "$here")
GRANSPH_DEPS=${GRANSPH_DEPS:-$HOME/.cache/gransph}
SID=$GRANSPH_DEPS/sid
ROOT=$SID/root
export JOBS=${JOBS:-$(nproc)}

# What the root is made from. The sid snapshot moves: a version that is gone
# stops the script with a message (update the pin, then rerun; the root is remade).
SID_PINS=(libkokkos-dev=5.2.2-2 libkokkos5.2=5.2.2-2 g++=4:16.1.0-3 gcc-16=16.2.0-4
  cmake=4.3.4-1 libopenmpi-dev=6.0.0~rc2-2 openmpi-bin=6.0.0~rc2-2
  libgtest-dev=1.18.0-1 libgmock-dev=1.18.0-1 libyaml-dev=0.2.5-2+b1 libeigen3-dev=5.0.1-3)
SID_UNPINNED=(ninja-build ccache pkgconf python3-numpy python3-matplotlib)
LAMMPS_DEB=20260704+dfsg-2
LAMMPS_ORIG=lammps_20260704+dfsg.orig.tar.gz

log() { printf '[sid] %s\n' "$*"; }
die() { printf '[sid] %s\n' "$*" >&2; exit 1; }
timed() { # timed LABEL CMD...: run CMD, append its wall time to times.log
  local label=$1 start=$SECONDS; shift
  "$@"
  printf '%s  %-40s %4d s\n' "$(date -u +%FT%TZ)" "$label" $((SECONDS - start)) >> "$SID/times.log"
}

[ "$(id -u)" -eq 0 ] || die "must run as root (mmdebstrap, chroot and unshare need it)"

# sid_run CMD...: CMD in the root, /proc /sys /dev and $top mounted in a private
# mount namespace that ends with CMD
sid_run() {
  unshare --mount --propagation private -- bash -euc '
    root=$1 top=$2; shift 2
    mount -t proc proc "$root/proc"
    mount --rbind /sys "$root/sys"
    mount --rbind /dev "$root/dev"
    mkdir -p "$root/gransph" && mount --bind "$top" "$root/gransph"
    cd "$root/gransph"
    exec chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb \
      PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
      CCACHE_DIR=/var/cache/ccache JOBS="$JOBS" GRANSPH_STACK=2026 \
      OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
      OMPI_MCA_rmaps_base_oversubscribe=1 ${SID_ENV:-} \
      bash -c "cd /gransph && exec \"\$@\"" _ "$@"
  ' _ "$ROOT" "$top" "$@"
}

# apt on the host, with sid lists of its own (nothing in /etc/apt changes)
APT_DIR=$SID/apt
sid_apt_opts() {
  echo -o Dir::Etc::SourceList="$APT_DIR/sources.list" -o Dir::Etc::SourceParts="$APT_DIR/parts" \
    -o Dir::State::Lists="$APT_DIR/lists" -o Dir::Cache="$APT_DIR/cache" \
    -o Dir::State::status=/dev/null -o Acquire::Check-Valid-Until=false \
    -o Acquire::Languages=none -o APT::Sandbox::User=root -o APT::Architecture="$(dpkg --print-architecture)"
}
sid_apt_update() {
  [ -n "$(find "$APT_DIR/lists" -name '*sid*Sources*' -mmin -360 2>/dev/null)" ] && return
  # shellcheck source=tools/apt-mirror.sh
  source "$here/apt-mirror.sh"
  local mirror; mirror=$(debian_mirror_uri bookworm)
  mkdir -p "$APT_DIR/lists/partial" "$APT_DIR/parts" "$APT_DIR/cache/archives/partial"
  local key=/usr/share/keyrings/debian-archive-keyring.gpg
  printf 'deb [signed-by=%s] %s sid main\ndeb-src [signed-by=%s] %s sid main\n' \
    "$key" "$mirror" "$key" "$mirror" > "$APT_DIR/sources.list"
  log "apt update of sid ($mirror)"
  # shellcheck disable=SC2046
  apt-get $(sid_apt_opts) update -qq
}

check_pins() {
  local p missing=()
  for p in "${SID_PINS[@]}"; do
    # (apt-cache show PKG=VER exits 0 for a version it does not have: ask madison)
    # shellcheck disable=SC2046
    apt-cache $(sid_apt_opts) madison "${p%%=*}" |
      awk -v v="${p#*=}" '$3 == v && /Packages/ {found = 1} END {exit !found}' || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    local p2
    for p2 in "${missing[@]}"; do
      # shellcheck disable=SC2046
      log "pinned ${p2} is no longer in sid; sid has ${p2%%=*} $(apt-cache $(sid_apt_opts) policy "${p2%%=*}" 2>/dev/null | awk '/Candidate/ {print $2}')"
    done
    die "update SID_PINS in tools/sid-root.sh (and check the port still builds)"
  fi
}

root_stamp() { printf '%s\n' "${SID_PINS[@]}" "${SID_UNPINNED[@]}" | sha256sum | cut -c1-16; }

make_root() {
  local stamp; stamp=$(root_stamp)
  [ -f "$ROOT/.gransph-root-$stamp" ] && return
  sid_apt_update
  check_pins
  # shellcheck source=tools/apt-mirror.sh
  source "$here/apt-mirror.sh"
  local mirror; mirror=$(debian_mirror_uri bookworm)
  command -v mmdebstrap >/dev/null || apt-get install -y -qq mmdebstrap >/dev/null
  log "making the sid root with mmdebstrap (~1-3 min, 1.2 GB)"
  rm -rf "$ROOT.tmp"
  # the registry's sid Release file is past its Valid-Until date, hence the option
  local include; include=$(IFS=,; echo "${SID_PINS[*]},${SID_UNPINNED[*]}")
  timed "mmdebstrap sid root" mmdebstrap --quiet --variant=buildd \
    --aptopt='Acquire::Check-Valid-Until "false"' --include="$include" \
    sid "$ROOT.tmp" "deb $mirror sid main"
  rm -rf "$ROOT" && mv "$ROOT.tmp" "$ROOT"
  fix_kokkos_config
  touch "$ROOT/.gransph-root-$stamp"
}

# The pinned versions are what is installed (a root made some other way must match).
verify_root_versions() {
  local p name ver have
  for p in "${SID_PINS[@]}"; do
    name=${p%%=*} ver=${p#*=}
    have=$(chroot "$ROOT" dpkg-query -W -f='${Version}' "$name" 2>/dev/null || true)
    [ "$have" = "$ver" ] || die "root has $name '$have', pinned $ver: delete $ROOT and rerun"
  done
}

# Packaging bug in sid's libkokkos-dev 5.2.2: its KokkosTargets-none.cmake names
# libkokkosalgorithms.a and libkokkossimd.a, which the package does not ship
# (algorithms and SIMD are header-only here), so any find_package(Kokkos) stops.
# Empty archives in their place let LAMMPS and the plugin configure.
fix_kokkos_config() {
  local lib f
  lib=$ROOT/usr/lib/$(chroot "$ROOT" dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
  for f in libkokkosalgorithms.a libkokkossimd.a; do
    grep -qs "$f" "$lib"/cmake/Kokkos/KokkosTargets-*.cmake || continue
    [ -e "$lib/$f" ] || { log "empty $f in the root (libkokkos-dev packaging bug)"; chroot "$ROOT" ar rcs "/usr/lib/${lib##*/}/$f"; }
  done
}

fetch_lammps() {
  local orig=$SID/src/$LAMMPS_ORIG sum src=$ROOT/opt/lammps
  # unpacked from a checked tarball before: nothing to fetch (no network needed)
  [ -f "$src/.unpacked-$LAMMPS_DEB" ] && return
  sid_apt_update
  # the sha256 sid's (signed) Sources index gives for the orig tarball
  # shellcheck disable=SC2046
  sum=$(apt-cache $(sid_apt_opts) showsrc lammps 2>/dev/null |
        awk -v v="$LAMMPS_DEB" -v f="$LAMMPS_ORIG" '/^Package:/ {ok = 0} /^Version:/ {ok = ($2 == v)}
          /^Checksums-Sha256:/ {c = 1; next} /^[^ ]/ {c = 0} ok && c && $3 == f {print $1; exit}')
  [ -n "$sum" ] || die "lammps $LAMMPS_DEB is no longer in sid's Sources: update LAMMPS_DEB/LAMMPS_ORIG in tools/sid-root.sh"
  if ! echo "$sum  $orig" | sha256sum --check --status 2>/dev/null; then
    log "downloading $LAMMPS_ORIG (213 MB)"
    mkdir -p "$SID/src"
    # the .dsc and .debian.tar.xz give 404 on the registry and apt-get then exits
    # non-zero after fetching the orig tarball: the checksum below decides
    # shellcheck disable=SC2046
    (cd "$SID/src" && timed "download LAMMPS orig" apt-get $(sid_apt_opts) source --download-only \
       "lammps=$LAMMPS_DEB" >/dev/null 2>&1 || true)
  fi
  echo "$sum  $orig" | sha256sum --check --quiet || die "checksum mismatch for $orig"
  log "unpacking LAMMPS $LAMMPS_DEB"
  rm -rf "$src" && mkdir -p "$src"
  timed "unpack LAMMPS" tar -xzf "$orig" -C "$src"
  touch "$src/.unpacked-$LAMMPS_DEB"
}

# KOKKOS (the /kk styles; OpenMP, Debian's Kokkos), PLUGIN (loads us), SPH (the
# sph/taitwater peer in bench/), GRANULAR, MOLECULE (the fix harness needs it).
# 4Jul2026 always has exceptions (no LAMMPS_EXCEPTIONS option any more).
lammps_cmake_args() {
  echo -G Ninja -D CMAKE_BUILD_TYPE=Release -D CMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -D BUILD_SHARED_LIBS=on -D BUILD_MPI=on -D BUILD_OMP=on \
    -D PKG_KOKKOS=on -D EXTERNAL_KOKKOS=on \
    -D PKG_PLUGIN=on -D PKG_SPH=on -D PKG_GRANULAR=on -D PKG_MOLECULE=on \
    -D WITH_PNG=off -D WITH_JPEG=off -D WITH_FFMPEG=off
}

build_lammps() {
  local config; config=$(lammps_cmake_args | sha256sum | cut -c1-16)
  local stamp=$ROOT/opt/lammps/build/.built-$LAMMPS_DEB-$config
  [ -f "$stamp" ] && [ -x "$ROOT/opt/lammps/build/lmp" ] && return
  log "building LAMMPS 4Jul2026 in the root (~16 min on 2 cores without a warm ccache)"
  # shellcheck disable=SC2046
  SID_ENV= timed "configure LAMMPS 4Jul2026" sid_run cmake -S /opt/lammps/cmake -B /opt/lammps/build \
    $(lammps_cmake_args) >/dev/null
  timed "build LAMMPS 4Jul2026 (-j$JOBS)" sid_run cmake --build /opt/lammps/build -j "$JOBS" >/dev/null
  touch "$stamp"
}

if [ "${1:-}" = run ]; then
  shift
  [ -f "$ROOT/.gransph-root-$(root_stamp)" ] || die "no sid root in $ROOT yet: run tools/sid-root.sh first"
  sid_run "$@"
  exit
fi

mkdir -p "$SID"
make_root
verify_root_versions
fix_kokkos_config
fetch_lammps
build_lammps
log "ready: LAMMPS 4Jul2026 in $ROOT/opt/lammps/build (inside the root: /opt/lammps/build)"
