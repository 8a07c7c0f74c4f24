#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
# The second stack: current LAMMPS (4Jul2026 or newer) with KOKKOS on Kokkos 5 (OpenMP),
# in a Debian sid root, because Debian 12 cannot run the only Kokkos 5 we can get
# (sid's binary libkokkos-dev needs glibc 2.38 and GCC 13's libstdc++).
#
#   tools/stack/sid-root.sh [--refresh]   make the root and build LAMMPS in it; with both in
#                                   place it uses them as they are, needs no network and
#                                   returns in seconds
#   tools/stack/sid-root.sh --plan [--refresh]
#                                   say what that would do, and change nothing
#   tools/stack/sid-root.sh lock          write and print the lock file: what the stack is made of
#   tools/stack/sid-root.sh run CMD...    run CMD inside the root (as root, cwd /gransph),
#                                   with this source tree mounted at /gransph
#
# Pinned is only what the port depends on: Kokkos major KOKKOS_MAJOR and LAMMPS from
# LAMMPS_MIN on. A LAMMPS newer than the newest of GRANSPH_TESTED_LAMMPS in
# cmake/GRANSPHLammps.cmake is built anyway, with a loud warning. Compilers, cmake,
# Open MPI, gtest and Eigen are sid's current ones; SID_TESTED names the versions last
# seen to pass, and every run warns about each one the root has in another version.
# Sid moves daily, so a root in place is never remade unasked: GRANSPH_SID_REFRESH=1
# (or --refresh) compares it, and the LAMMPS in it, with what sid offers now, and remakes
# what differs.
#
# Everything lands in $GRANSPH_DEPS/sid (default ~/.cache/gransph/sid):
#   root/      the sid root (mmdebstrap); inside it /opt/lammps (the LAMMPS source,
#              its record .gransph-source), /opt/lammps/build (its build),
#              /var/cache/ccache (the compiler cache of every build in the root, carried
#              over when the root is remade)
#   root.lock  what the stack is made of: the versions of the root's main packages, the
#              LAMMPS version, its tarball and sha256, warnings; root.packages: all of
#              the root's packages
#   src/       the LAMMPS orig tarball, and lammps.source: its Debian version, name and
#              the sha256 of sid's signed Sources index
#   apt/       apt lists of sid for the host-side queries
#   times.log  how long each step took
# The Debian mirror is the one of this machine's own bookworm `deb` entry.
# GRANSPH_SID_SOURCES replaces the sources.list of the host-side queries, for --plan
# only (unittest/tools/test_sid_root.sh points it at fixture repositories).
#
# Mounts: /proc, /sys, /dev and this source tree are mounted into the root only
# inside a private mount namespace (unshare --mount) that lives as long as one
# command, so no mount outlives it and the host never sees them: `rm -rf` of the
# root from the host is safe. Never delete the root from *inside* a `run`
# command: there /dev and the source tree are mounted in it.
set -euo pipefail

here=$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")
top=$(dirname "$(dirname "$here")")
GRANSPH_DEPS=${GRANSPH_DEPS:-$HOME/.cache/gransph}
SID=$GRANSPH_DEPS/sid
ROOT=$SID/root
LOCK=$SID/root.lock
APT_DIR=$SID/apt
export JOBS=${JOBS:-$(nproc)}

# What the root is made of: sid's current version of each.
SID_PACKAGES=(libkokkos-dev g++ cmake libopenmpi-dev openmpi-bin libgtest-dev libgmock-dev
  libyaml-dev libeigen3-dev ninja-build ccache pkgconf python3-numpy python3-matplotlib
  python3-gdal python3-stl)
# shellcheck disable=SC2191 # (name=version words, not array indices)
# The versions the stack last passed its tests with (2026-12-02). Not a pin: a root
# with others is used, with a warning that names them. Update after a passing run.
SID_TESTED=(libkokkos-dev=5.2.2-2 libkokkos5.2=5.2.2-2 g++=4:16.1.0-3 gcc-16=16.2.0-4
  cmake=4.3.4-1 libopenmpi-dev=6.0.0~rc2-2 openmpi-bin=6.0.0~rc2-2
  libgtest-dev=1.18.0-1 libgmock-dev=1.18.0-1 libyaml-dev=0.2.5-2+b1 libeigen3-dev=5.0.1-3)
# the root's packages the lock lists (and --refresh compares): ours and what they
# resolve to for the compiler, Kokkos, MPI and the C/C++ runtimes
LOCK_PATTERNS=("${SID_PACKAGES[@]}" 'gcc-[0-9]*' 'g++-[0-9]*' 'libkokkos*' 'libopenmpi[0-9]*'
  libc6 libstdc++6)
# What the port depends on: gransph_kokkos_compat.h serves Kokkos 5; Kokkos 5 needs
# LAMMPS 4Jul2026 or newer (and so does gransph_lammps_compat.h's current-LAMMPS side).
KOKKOS_MAJOR=5
LAMMPS_MIN=20260704

log() { printf '[sid] %s\n' "$*"; }
warn() { printf '[sid] WARNING: %s\n' "$*" >&2; }
die() { printf '[sid] %s\n' "$*" >&2; exit 1; }
timed() { # timed LABEL CMD...: run CMD, append its wall time to times.log
  local label=$1 start=$SECONDS; shift
  "$@"
  printf '%s  %-40s %4d s\n' "$(date -u +%FT%TZ)" "$label" $((SECONDS - start)) >> "$SID/times.log"
}

[ "$(id -u)" -eq 0 ] || die "must run as root (mmdebstrap, chroot and unshare need it)"
# shellcheck source=tools/stack/arch.sh
source "$here/arch.sh"
ARCH_CXX_FLAGS=$(gransph_arch_cxx_flags) || exit 1

# sid_run CMD...: CMD in the root, /proc /sys /dev and $top mounted in a private
# mount namespace that ends with CMD. Open MPI's libfabric transport (btl ofi) probes
# the fabric for about a second at every MPI_Init, one host needs none of it: without
# it a LAMMPS run starts in 0.7 s instead of 1.7 (the suite launches LAMMPS hundreds
# of times)
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
      OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl=^ofi ${SID_ENV:-} \
      bash -c "cd /gransph && exec \"\$@\"" _ "$@"
  ' _ "$ROOT" "$top" "$@"
}

# --- what sid offers now (apt on the host, with sid lists of its own: nothing in
# /etc/apt changes)

sid_apt_opts() {
  echo -o Dir::Etc::SourceList="$APT_DIR/sources.list" -o Dir::Etc::SourceParts="$APT_DIR/parts" \
    -o Dir::State::Lists="$APT_DIR/lists" -o Dir::Cache="$APT_DIR/cache" \
    -o Dir::State::status=/dev/null -o Acquire::Check-Valid-Until=false \
    -o Acquire::Languages=none -o APT::Sandbox::User=root -o APT::Architecture="$(dpkg --print-architecture)"
}
sid_mirror() {
  # shellcheck source=tools/stack/apt-mirror.sh
  source "$here/apt-mirror.sh"
  debian_mirror_uri bookworm
}
sid_sources() {
  if [ -n "${GRANSPH_SID_SOURCES:-}" ]; then printf '%s\n' "$GRANSPH_SID_SOURCES"; return; fi
  local mirror key=/usr/share/keyrings/debian-archive-keyring.gpg
  mirror=$(sid_mirror)
  printf 'deb [signed-by=%s] %s sid main\ndeb-src [signed-by=%s] %s sid main\n' \
    "$key" "$mirror" "$key" "$mirror"
}
# the network is asked only here, and only for a root or LAMMPS that is not in place or
# under --refresh; lists of the last hour from the same sources serve otherwise
UPDATED=0
sid_apt_update() {
  [ "$UPDATED" = 1 ] && return
  local sources; sources=$(sid_sources)
  if [ "$REFRESH" != 1 ] && [ "$sources" = "$(cat "$APT_DIR/sources.list" 2>/dev/null)" ] &&
     [ -n "$(find "$APT_DIR/updated" -mmin -60 2>/dev/null)" ]; then
    UPDATED=1; return
  fi
  mkdir -p "$APT_DIR/lists/partial" "$APT_DIR/parts" "$APT_DIR/cache/archives/partial"
  printf '%s\n' "$sources" > "$APT_DIR/sources.list"
  log "apt update of sid's package lists"
  # shellcheck disable=SC2046
  apt-get $(sid_apt_opts) update -qq --error-on=any ||
    die "apt update of sid failed. A root and LAMMPS in place need no network: without" \
        "GRANSPH_SID_REFRESH they are used as they are."
  touch "$APT_DIR/updated"
  UPDATED=1
}
# name=version of sid's candidate for each package named (nothing for one it lacks)
sid_candidates() {
  # shellcheck disable=SC2046
  apt-cache $(sid_apt_opts) policy "$@" 2>/dev/null |
    awk '/^[^ ]/ {name = $1; sub(/:$/, "", name)}
         /^  Candidate:/ && $2 != "(none)" {print name "=" $2}'
}
# "DEBVERSION ORIG SHA256" of sid's newest lammps source package, from the Sources
# index apt has checked against the Release file's signature
sid_lammps_source() {
  local best="" line
  # shellcheck disable=SC2046
  while read -r line; do
    if [ -z "$best" ] || dpkg --compare-versions "${line%% *}" gt "${best%% *}"; then best=$line; fi
  done < <(apt-cache $(sid_apt_opts) showsrc --only-source lammps 2>/dev/null | awk '
    /^Package:/ {v = ""} /^Version:/ {v = $2}
    /^Checksums-Sha256:/ {c = 1; next} /^[^ ]/ {c = 0}
    c && v != "" && $3 ~ /^lammps_.*\.orig\.tar\./ {print v, $3, $1}')
  echo "$best"
}

# --- what the root holds

join_comma() { local IFS=, s; s="$*"; echo "${s//,/, }"; }

# the root exists, complete, for the package list above
root_in_place() { [ "$(cat "$ROOT/.gransph-root" 2>/dev/null)" = "$(printf '%s\n' "${SID_PACKAGES[@]}")" ]; }
# name=version of each installed package of the root matching the patterns named
root_versions() {
  { dpkg-query --admindir="$ROOT/var/lib/dpkg" -W -f='${db:Status-Abbrev}${Package}=${Version}\n' "$@" \
      2>/dev/null || true; } | sed -n 's/^ii *//p' | sort -u
}
# "cmake 4.3.5-1 (tested 4.3.4-1), ..." for each SID_TESTED package that the
# name=version lines on stdin hold in another version, or not at all
untested() {
  local -A have=()
  local n v out=()
  while IFS='=' read -r n v; do have[$n]=$v; done
  for n in "${SID_TESTED[@]}"; do
    v=${n#*=} n=${n%%=*}
    [ "${have[$n]:-}" = "$v" ] || out+=("$n ${have[$n]:-absent} (tested $v)")
  done
  join_comma "${out[@]}"
}
# the Kokkos of libkokkos-dev version $1 (from $2) is of the major version the port serves
check_kokkos() {
  local up=${1#*:}
  [ -n "$1" ] || die "$2 has no libkokkos-dev: the 2026 stack needs sid's Kokkos $KOKKOS_MAJOR.x."
  [ "${up%%.*}" = "$KOKKOS_MAJOR" ] ||
    die "$2 has Kokkos ${up%%-*} (libkokkos-dev $1), but src/GRANSPH/gransph_kokkos_compat.h" \
        "serves Kokkos $KOKKOS_MAJOR.x only. Keep a root with Kokkos $KOKKOS_MAJOR (a root in place" \
        "is remade only under GRANSPH_SID_REFRESH), or port the compatibility layer to" \
        "Kokkos ${up%%.*} and set KOKKOS_MAJOR in tools/stack/sid-root.sh."
}
# warnings about the root as it is: versions other than the tested ones
check_root() {
  local pkgs diff
  pkgs=$(root_versions "${LOCK_PATTERNS[@]}")
  check_kokkos "$(sed -n 's/^libkokkos-dev=//p' <<< "$pkgs")" "the root"
  diff=$(untested <<< "$pkgs")
  [ -z "$diff" ] || warn "the root's packages differ from those last tested (SID_TESTED" \
    "in tools/stack/sid-root.sh): $diff. A failure may come from them."
}

# --- LAMMPS versions

lammps_date() { # 20260704 of 20260704+dfsg-2 (nothing when there is no date)
  local up=${1#*:}; up=${up%%[!0-9]*}
  [ ${#up} -eq 8 ] && echo "$up"
}
lammps_name() { date -u -d "$1" +%-d%b%Y; } # 4Jul2026
# the newest LAMMPS the compatibility layer knows: CMake's list of tested versions
KNOWN_LAMMPS=$(sed -n 's/^set(GRANSPH_TESTED_LAMMPS \(.*\))$/\1/p' "$top/cmake/GRANSPHLammps.cmake" |
  tr ' ' '\n' | sort -n | tail -n1)
[ -n "$KNOWN_LAMMPS" ] || die "no GRANSPH_TESTED_LAMMPS line in cmake/GRANSPHLammps.cmake"
# the warning for a LAMMPS newer than that (nothing otherwise)
lammps_newer_note() {
  local d; d=$(lammps_date "$1")
  [ "$d" -le "$KNOWN_LAMMPS" ] ||
    echo "LAMMPS $(lammps_name "$d") ($1) is newer than the newest version the compatibility layer knows ($(lammps_name "$KNOWN_LAMMPS")): built anyway; if the plugin does not compile or a test fails, look there first (src/GRANSPH/*_compat.h)."
}
# LAMMPS version $1 (from $2) is one the stack can use; warn loudly when it is newer
# than the compatibility layer knows
check_lammps() {
  local d note; d=$(lammps_date "$1") || die "cannot read a date from the lammps version '$1'"
  [ "$d" -ge "$LAMMPS_MIN" ] ||
    die "$2 LAMMPS is $(lammps_name "$d") ($1), older than $(lammps_name "$LAMMPS_MIN"), which" \
        "the 2026 stack needs (Kokkos $KOKKOS_MAJOR). $(what_to_do_lammps)"
  note=$(lammps_newer_note "$1")
  [ -z "$note" ] && return
  warn '!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!'
  warn "$note"
  warn '!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!'
}
what_to_do_lammps() {
  echo "Keep using the root and the LAMMPS tarball of $SID made before (run without" \
       "GRANSPH_SID_REFRESH: they are used offline), or build the plugin against a LAMMPS" \
       ">= $(lammps_name "$LAMMPS_MIN") of your own (README, 'Against your own LAMMPS')."
}
# "DEBVERSION ORIG SHA256" from a record file (nothing when there is none)
read_source() {
  [ -f "$1" ] || return 0
  awk -F= '{v[$1] = $2} END {if (v["deb"] != "") print v["deb"], v["orig"], v["sha256"]}' "$1"
}
write_source() { # FILE DEBVERSION ORIG SHA256
  printf 'deb=%s\norig=%s\nsha256=%s\n' "$2" "$3" "$4" > "$1.tmp" && mv "$1.tmp" "$1"
}

# --- decisions: what this run makes, from what is in place and (when that is not
# enough, or under --refresh) what sid offers now. They change nothing.

# ROOT_ACTION: keep or make
decide_root() {
  if ! root_in_place; then
    ROOT_ACTION='make'
    log "root: none for this package list in $ROOT: making one of sid's current packages"
  elif [ "$REFRESH" = 1 ]; then
    local moved
    sid_apt_update
    moved=$(root_vs_sid)
    if [ -n "$moved" ]; then
      ROOT_ACTION='make'
      warn "refresh: sid has moved since the root was made ($moved): remaking it"
    else
      ROOT_ACTION=keep
      log "refresh: the root's packages are sid's current ones"
    fi
  else
    ROOT_ACTION=keep
    log "root: made $(date -u -r "$ROOT/.gransph-root" +%F), used as it is (GRANSPH_SID_REFRESH=1 compares it with sid now)"
  fi
  [ "$ROOT_ACTION" = make ] && check_sid_packages
  return 0
}
# "cmake 4.3.4-1 -> 4.3.5-1, ..." for each package of the lock that sid now has in
# another version (or no longer has)
root_vs_sid() {
  local -A now=()
  local n v out=() pkgs
  pkgs=$(root_versions "${LOCK_PATTERNS[@]}")
  # shellcheck disable=SC2046
  while IFS='=' read -r n v; do now[$n]=$v; done < <(sid_candidates $(cut -d= -f1 <<< "$pkgs"))
  while IFS='=' read -r n v; do
    [ "${now[$n]:-}" = "$v" ] || out+=("$n $v -> ${now[$n]:-gone}")
  done <<< "$pkgs"
  join_comma "${out[@]}"
}
# sid has every package, a Kokkos of the right major version; name the untested ones
check_sid_packages() {
  local cands n diff
  sid_apt_update
  cands=$(sid_candidates "${SID_PACKAGES[@]}")
  for n in "${SID_PACKAGES[@]}"; do
    grep -q "^$n=" <<< "$cands" || die "sid has no package $n (needed in the root)"
  done
  check_kokkos "$(sed -n 's/^libkokkos-dev=//p' <<< "$cands")" "sid"
  diff=$(untested < <(sid_candidates "${SID_TESTED[@]%%=*}"))
  [ -z "$diff" ] || warn "sid's packages differ from those last tested (SID_TESTED in" \
    "tools/stack/sid-root.sh): $diff. Using sid's; a failure may come from them."
  log "sid's packages for the root: $(tr '\n' ' ' <<< "$cands")"
}

# L_DEB L_ORIG L_SUM: the LAMMPS source to use; L_ACTION: keep (in the root), unpack
# (the cached tarball) or fetch; BUILD_ACTION: keep or build
decide_lammps() {
  local in_root="" cached from src
  [ "$ROOT_ACTION" = keep ] && in_root=$(read_source "$ROOT/opt/lammps/.gransph-source")
  cached=$(read_source "$SID/src/lammps.source")
  if [ "$REFRESH" = 1 ] || [ -z "$in_root$cached" ]; then
    sid_apt_update
    src=$(sid_lammps_source) from="sid's"
    [ -n "$src" ] || die "sid has no lammps source package with an orig tarball. $(what_to_do_lammps)"
  elif [ -n "$in_root" ]; then
    src=$in_root from="the root's"
  else
    src=$cached from="the cached"
  fi
  read -r L_DEB L_ORIG L_SUM <<< "$src"
  check_lammps "$L_DEB" "$from"
  if [ "$src" = "$in_root" ]; then L_ACTION=keep
  elif [ "$src" = "$cached" ] && [ -f "$SID/src/$L_ORIG" ]; then L_ACTION=unpack
  else L_ACTION=fetch
  fi
  BUILD_ACTION=build
  [ "$L_ACTION" = keep ] && [ -f "$(lammps_stamp)" ] && [ -x "$ROOT/opt/lammps/build/lmp" ] && BUILD_ACTION=keep
  log "LAMMPS: $(lammps_name "$(lammps_date "$L_DEB")") ($L_DEB, $L_ORIG, sha256 $L_SUM) from $from source: $L_ACTION; build: $BUILD_ACTION"
}

# --- actions

make_root() {
  [ -z "${GRANSPH_SID_SOURCES:-}" ] || die "GRANSPH_SID_SOURCES is for --plan only"
  local mirror; mirror=$(sid_mirror)
  command -v mmdebstrap >/dev/null || apt-get install -y -qq mmdebstrap >/dev/null
  log "making the sid root with mmdebstrap (~2-5 min, 1.2 GB)"
  rm -rf "$ROOT.tmp"
  # the registry's sid Release file is past its Valid-Until date, hence the option
  local include; include=$(IFS=,; echo "${SID_PACKAGES[*]}")
  timed "mmdebstrap sid root" mmdebstrap --quiet --variant=buildd \
    --aptopt='Acquire::Check-Valid-Until "false"' --include="$include" \
    sid "$ROOT.tmp" "deb $mirror sid main"
  # the compiler cache outlives the root: a remade root with the same compiler rebuilds
  # LAMMPS from it in a minute or two
  if [ -d "$ROOT/var/cache/ccache" ]; then
    rm -rf "$ROOT.tmp/var/cache/ccache" && mv "$ROOT/var/cache/ccache" "$ROOT.tmp/var/cache/ccache"
  fi
  rm -rf "$ROOT" && mv "$ROOT.tmp" "$ROOT"
  printf '%s\n' "${SID_PACKAGES[@]}" > "$ROOT/.gransph-root"
}

# Packaging bug in sid's libkokkos-dev 5.2.2: its KokkosTargets-none.cmake names
# libkokkosalgorithms.a and libkokkossimd.a, which the package does not ship
# (algorithms and SIMD are header-only here), so any find_package(Kokkos) stops.
# Empty archives in their place let LAMMPS and the plugin configure.
fix_kokkos_config() {
  local t lib f
  for t in "$ROOT"/usr/lib/*/cmake/Kokkos/KokkosTargets-*.cmake; do
    [ -f "$t" ] || continue
    lib=${t%/cmake/Kokkos/*}
    for f in libkokkosalgorithms.a libkokkossimd.a; do
      if grep -q "$f" "$t" && [ ! -e "$lib/$f" ]; then
        log "empty $f in the root (libkokkos-dev packaging bug)"
        chroot "$ROOT" ar rcs "${lib#"$ROOT"}/$f"
      fi
    done
  done
}

# download the orig tarball of L_DEB, check it against the sha256 of the Sources index
fetch_lammps() {
  [ -z "${GRANSPH_SID_SOURCES:-}" ] || die "GRANSPH_SID_SOURCES is for --plan only"
  local orig=$SID/src/$L_ORIG
  mkdir -p "$SID/src"
  if ! echo "$L_SUM  $orig" | sha256sum --check --status 2>/dev/null; then
    log "downloading $L_ORIG (about 200 MB)"
    # the .dsc and .debian.tar.xz give 404 on the registry and apt-get then exits
    # non-zero after fetching the orig tarball: the checksum below decides
    # shellcheck disable=SC2046
    (cd "$SID/src" && timed "download LAMMPS orig" apt-get $(sid_apt_opts) source --download-only \
       "lammps=$L_DEB" >/dev/null 2>&1 || true)
  fi
  echo "$L_SUM  $orig" | sha256sum --check --quiet ||
    die "$L_ORIG: missing or not the sha256 of sid's Sources index"
  write_source "$SID/src/lammps.source" "$L_DEB" "$L_ORIG" "$L_SUM"
  # one tarball is kept: the one in use
  find "$SID/src" -maxdepth 1 -name 'lammps_*' ! -name "$L_ORIG" -delete
}

unpack_lammps() {
  local src=$ROOT/opt/lammps d
  echo "$L_SUM  $SID/src/$L_ORIG" | sha256sum --check --quiet || die "checksum mismatch for $L_ORIG"
  log "unpacking LAMMPS $L_DEB"
  rm -rf "$src" && mkdir -p "$src"
  timed "unpack LAMMPS" tar -xf "$SID/src/$L_ORIG" -C "$src"
  # a tarball with one top folder (lammps-DATE/): its content is the source
  for d in "$src"/*/; do
    if [ ! -d "$src/cmake" ] && [ -d "$d/cmake" ]; then
      (shopt -s dotglob; mv "$d"* "$src"/) && rmdir "$d"
    fi
  done
  [ -d "$src/cmake" ] || die "$L_ORIG holds no cmake/ folder: not a LAMMPS source?"
  write_source "$src/.gransph-source" "$L_DEB" "$L_ORIG" "$L_SUM"
}

# KOKKOS (the /kk styles; OpenMP, Debian's Kokkos), PLUGIN (loads us), SPH (the
# sph/taitwater peer in bench/), GRANULAR, MOLECULE (the fix harness needs it), RIGID
# (bodies of dummy particles moved by the sand);
# the instruction set of tools/stack/arch.sh (GRANSPH_ARCH).
# LAMMPS since 2025 always has exceptions (no LAMMPS_EXCEPTIONS option any more).
lammps_cmake_args() {
  echo -G Ninja -D CMAKE_BUILD_TYPE=Release -D CMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -D BUILD_SHARED_LIBS=on -D BUILD_MPI=on -D BUILD_OMP=on \
    -D PKG_KOKKOS=on -D EXTERNAL_KOKKOS=on \
    -D PKG_PLUGIN=on -D PKG_SPH=on -D PKG_GRANULAR=on -D PKG_MOLECULE=on -D PKG_RIGID=on \
    -D WITH_PNG=off -D WITH_JPEG=off -D WITH_FFMPEG=off
}
lammps_stamp() {
  echo "$ROOT/opt/lammps/build/.built-$L_DEB-$( (lammps_cmake_args; echo "$ARCH_CXX_FLAGS") | sha256sum | cut -c1-16)"
}

build_lammps() {
  local name; name=$(lammps_name "$(lammps_date "$L_DEB")")
  log "building LAMMPS $name in the root (~16 min on 2 idle cores without a warm ccache)"
  # shellcheck disable=SC2046
  SID_ENV='' timed "configure LAMMPS $name" sid_run cmake -S /opt/lammps/cmake -B /opt/lammps/build \
    $(lammps_cmake_args) -D "CMAKE_CXX_FLAGS=$ARCH_CXX_FLAGS" >/dev/null
  timed "build LAMMPS $name (-j$JOBS)" sid_run cmake --build /opt/lammps/build -j "$JOBS" >/dev/null
  touch "$(lammps_stamp)"
}

# the lock: what the stack in place is made of, so that two runs can be compared
write_lock() {
  local pkgs all src note diff version=""
  pkgs=$(root_versions "${LOCK_PATTERNS[@]}")
  all=$(root_versions '*')
  src=$(read_source "$ROOT/opt/lammps/.gransph-source")
  read -r L_DEB L_ORIG L_SUM <<< "${src:-none none none}"
  [ -f "$ROOT/opt/lammps/src/version.h" ] &&
    version=$(sed -n 's/^#define LAMMPS_VERSION "\(.*\)"/\1/p' "$ROOT/opt/lammps/src/version.h")
  diff=$(untested <<< "$pkgs")
  [ -n "$src" ] && note=$(lammps_newer_note "$L_DEB")
  printf '%s\n' "$all" > "$SID/root.packages"
  {
    echo "# the 2026 stack in $ROOT, as tools/stack/sid-root.sh made it: compare with the lock of"
    echo "# a run that passed to see what changed"
    echo "root.made=$(date -u -r "$ROOT/.gransph-root" +%FT%TZ)"
    echo "root.packages=$(wc -l <<< "$all") packages, sha256 $(sha256sum <<< "$all" | cut -c1-16) ($SID/root.packages)"
    echo "arch=$(gransph_arch)"
    echo "kokkos=$(sed -n 's/^libkokkos-dev=\([0-9]*:\)\{0,1\}\([^-]*\).*/\2/p' <<< "$pkgs")"
    echo "lammps=${version:-none}"
    echo "lammps.deb=$L_DEB"
    echo "lammps.orig=$L_ORIG"
    echo "lammps.sha256=$L_SUM"
    printf '%s\n' "$pkgs"
    [ -z "$diff" ] || echo "warning=untested package versions: $diff"
    [ -z "${note:-}" ] || echo "warning=$note"
  } > "$LOCK.tmp"
  mv "$LOCK.tmp" "$LOCK"
}

# --- main

usage() { sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//'; exit "${1:-0}"; }

if [ "${1:-}" = run ]; then
  shift
  root_in_place || die "no sid root in $ROOT yet: run tools/stack/sid-root.sh first"
  sid_run "$@"
  exit
fi

PLAN=0 REFRESH=${GRANSPH_SID_REFRESH:-0}
case $REFRESH in 0|1|'') ;; *) die "GRANSPH_SID_REFRESH is 1 or 0, not '$REFRESH'" ;; esac
for arg in "$@"; do
  case $arg in
    --plan) PLAN=1 ;;
    --refresh) REFRESH=1 ;;
    lock)
      root_in_place || die "no sid root in $ROOT yet: run tools/stack/sid-root.sh first"
      write_lock && cat "$LOCK"; exit ;;
    -h|--help) usage ;;
    *) usage 1 >&2 ;;
  esac
done

mkdir -p "$SID"
# both checkouts of a machine share the stack: one makes it at a time, and the other
# decides once it has finished
if [ "$PLAN" = 0 ]; then
  exec 9> "$SID/.making"
  flock -n 9 || { log "another tools/stack/sid-root.sh is making the stack: waiting for it"; flock 9; }
fi
decide_root
[ "$ROOT_ACTION" = keep ] && check_root
decide_lammps
if [ "$PLAN" = 1 ]; then
  log "plan: root: $ROOT_ACTION; LAMMPS $L_DEB: $L_ACTION; LAMMPS build: $BUILD_ACTION (nothing done)"
  exit 0
fi
if [ "$ROOT_ACTION" = make ]; then
  make_root
  check_root
fi
fix_kokkos_config
[ "$L_ACTION" = fetch ] && fetch_lammps
[ "$L_ACTION" = keep ] || unpack_lammps
[ "$BUILD_ACTION" = build ] && build_lammps
write_lock
log "ready: LAMMPS $L_DEB in $ROOT/opt/lammps/build (inside the root: /opt/lammps/build); lock: $LOCK"
