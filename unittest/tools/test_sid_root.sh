#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
# tools/stack/sid-root.sh when Debian sid moves: its decisions, run for real (--plan, and the
# lock of a root in place) against fixture apt repositories and fixture roots. Needs no
# network and builds nothing: apt-get/apt-cache read the fixtures, dpkg-query the roots'
# status files. Every check must pass; there is nothing to skip.
set -euo pipefail
script=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)/tools/stack/sid-root.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
arch=$(dpkg --print-architecture)
checks=0

# the script's own package list and tested versions, so that "today" follows it
eval "$(sed -n '/^SID_PACKAGES=(/,/)$/p; /^SID_TESTED=(/,/)$/p' "$script")"
if [ ${#SID_PACKAGES[@]} -lt 5 ] || [ ${#SID_TESTED[@]} -lt 5 ]; then
  echo "FAIL: cannot read SID_PACKAGES and SID_TESTED from $script"; exit 1
fi

# today's sid: the tested versions, and 1.0-1 of every other package of the root
today=("${SID_TESTED[@]}")
for p in "${SID_PACKAGES[@]}"; do
  printf '%s\n' "${SID_TESTED[@]}" | grep -q "^$p=" || today+=("$p=1.0-1")
done
# with("NAME=VERSION"...) : today's list with these replaced or added; NAME= removes
with() {
  local p q kept=()
  for p in "${today[@]}"; do
    for q; do [ "${p%%=*}" = "${q%%=*}" ] && continue 2; done
    kept+=("$p")
  done
  for q; do [ -n "${q#*=}" ] && kept+=("$q"); done
  printf '%s\n' "${kept[@]}"
}
fake_sum() { printf '%s' "$1" | sha256sum | cut -d' ' -f1; }

# repo NAME LAMMPS_DEB|none [NAME=VERSION lines on stdin]: a flat apt repository
repo() {
  local dir=$work/repo-$1 lammps=$2 p
  mkdir -p "$dir"
  while read -r p; do
    printf 'Package: %s\nVersion: %s\nArchitecture: %s\nFilename: pool/%s.deb\nSize: 1\nDescription: fixture\n\n' \
      "${p%%=*}" "${p#*=}" "$arch" "${p%%=*}"
  done > "$dir/Packages"
  : > "$dir/Sources"
  if [ "$lammps" != none ]; then
    local orig="lammps_${lammps%-*}.orig.tar.gz"
    printf 'Package: lammps\nVersion: %s\nDirectory: pool/main/l/lammps\nChecksums-Sha256:\n %s 1 %s\n %s 1 lammps_%s.dsc\n\n' \
      "$lammps" "$(fake_sum "$orig")" "$orig" "$(fake_sum dsc)" "$lammps" > "$dir/Sources"
  fi
}
# root NAME LAMMPS_DEB [NAME=VERSION lines on stdin]: a root in place (its dpkg status,
# the marker for the script's package list, an unpacked LAMMPS), in GRANSPH_DEPS=deps-NAME
root() {
  local r=$work/deps-$1/sid/root p orig="lammps_${2%-*}.orig.tar.gz"
  mkdir -p "$r/var/lib/dpkg" "$r/opt/lammps/src"
  while read -r p; do
    printf 'Package: %s\nStatus: install ok installed\nVersion: %s\nArchitecture: %s\n\n' "${p%%=*}" "${p#*=}" "$arch"
  done > "$r/var/lib/dpkg/status"
  printf '%s\n' "${SID_PACKAGES[@]}" > "$r/.gransph-root"
  printf 'deb=%s\norig=%s\nsha256=%s\n' "$2" "$orig" "$(fake_sum "$orig")" > "$r/opt/lammps/.gransph-source"
  echo '#define LAMMPS_VERSION "4 Jul 2026"' > "$r/opt/lammps/src/version.h"
}

# run CASE REPO ARGS...: the script with CASE's deps folder and REPO's sources; output in $out
run() {
  local c=$1 r=$2; shift 2
  local src="deb [trusted=yes] file:$work/repo-$r ./"$'\n'"deb-src [trusted=yes] file:$work/repo-$r ./"
  echo "--- $c: sid-root.sh $* (sid: $r)"
  rc=0
  out=$(GRANSPH_DEPS=$work/deps-$c GRANSPH_SID_SOURCES=$src bash "$script" "$@" 2>&1) || rc=$?
  printf '%s\n' "$out" | sed 's/^/    /'
}
fail() { echo "FAIL: $*"; exit 1; }
# expect ok|stop TEXT...: the last run completed (ok) or stopped (stop), and printed each TEXT
expect() {
  local want=$1 t; shift
  if [ "$want" = ok ]; then [ "$rc" -eq 0 ] || fail "exit $rc, expected 0"
  else [ "$rc" -ne 0 ] || fail "exit 0, expected a stop"; fi
  for t; do grep -qF -- "$t" <<< "$out" || fail "no '$t' in the output"; done
  checks=$((checks + 1))
}
expect_not() { local t; for t; do ! grep -qF -- "$t" <<< "$out" || fail "'$t' in the output"; done; }

with | repo today 20260704+dfsg-2
with cmake=4.3.5-1 gcc-16= g++=4:17.1.0-1 gcc-17=17.1.0-1 | repo drift 20261201+dfsg-1
with | repo old-lammps 20250207+dfsg-1
with | repo no-lammps none
with libkokkos-dev=6.0.0-1 libkokkos6.0=6.0.0-1 | repo kokkos6 20260704+dfsg-2

# no root yet, sid as tested: make it, no warning
run fresh today --plan
expect ok "apt update of sid" "cmake=4.3.4-1" "plan: root: make; LAMMPS 20260704+dfsg-2: fetch; LAMMPS build: build"
expect_not WARNING

# no root yet, sid has moved a compiler and cmake, and offers a LAMMPS newer than the
# compatibility layer knows: completes, naming each change
run fresh-drift drift --plan
expect ok "cmake 4.3.5-1 (tested 4.3.4-1)" "g++ 4:17.1.0-1 (tested 4:16.1.0-3)" "gcc-16 absent (tested 16.2.0-4)" \
  "WARNING: LAMMPS 1Dec2026 (20261201+dfsg-1) is newer than the newest version the compatibility layer knows (4Jul2026): built anyway" \
  "plan: root: make; LAMMPS 20261201+dfsg-1: fetch"

# LAMMPS older than 4Jul2026, or none, or a Kokkos of another major version: a stop that says what to do
run old old-lammps --plan
expect stop "LAMMPS is 7Feb2025 (20250207+dfsg-1), older than 4Jul2026" "Keep using the root"
run none no-lammps --plan
expect stop "sid has no lammps source package" "Keep using the root"
run kokkos kokkos6 --plan
expect stop "sid has Kokkos 6.0.0 (libkokkos-dev 6.0.0-1)" "serves Kokkos 5.x only" "port the compatibility layer"

# a root in place, as tested: used as it is without asking sid (its repository here
# does not exist: no network), and its lock lists every package and the tarball's sha256
with | root cached 20260704+dfsg-2
run cached nowhere --plan
expect ok "used as it is" "from the root's source: keep" "plan: root: keep; LAMMPS 20260704+dfsg-2: keep"
expect_not "apt update" WARNING
run cached nowhere lock
expect ok "lammps.deb=20260704+dfsg-2" "lammps.orig=lammps_20260704+dfsg.orig.tar.gz" \
  "lammps.sha256=$(fake_sum lammps_20260704+dfsg.orig.tar.gz)" "lammps=4 Jul 2026" "kokkos=5.2.2"
for p in "${today[@]}"; do expect ok "$p"; done
expect_not warning=

# sid has moved since: without --refresh nothing changes and sid is not asked;
# with it, the root is remade and the newer LAMMPS fetched, with the changes named
run cached drift --plan
expect ok "plan: root: keep; LAMMPS 20260704+dfsg-2: keep"
expect_not "apt update"
run cached drift --plan --refresh
expect ok "sid has moved since the root was made (" "cmake 4.3.4-1 -> 4.3.5-1" "gcc-16 16.2.0-4 -> gone" \
  "is newer than the newest version" "plan: root: make; LAMMPS 20261201+dfsg-1: fetch"
GRANSPH_SID_REFRESH=1 run cached today --plan
expect ok "the root's packages are sid's current ones" "plan: root: keep; LAMMPS 20260704+dfsg-2: keep"

# a root made of untested versions: used, with a warning naming them, in the lock too
with cmake=4.3.5-1 | root untested 20260704+dfsg-2
run untested nowhere --plan
expect ok "WARNING: the root's packages differ from those last tested" "cmake 4.3.5-1 (tested 4.3.4-1)" "plan: root: keep"
run untested nowhere lock
expect ok "warning=untested package versions: cmake 4.3.5-1 (tested 4.3.4-1)"

# a root with a Kokkos of another major version stops
with libkokkos-dev=6.0.0-1 | root kokkos6 20260704+dfsg-2
run kokkos6 nowhere --plan
expect stop "the root has Kokkos 6.0.0"

echo "all $checks checks passed"
