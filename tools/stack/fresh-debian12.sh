#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
# The README's two commands on a fresh Debian 12 machine: a minimal bookworm root
# (mmdebstrap, nothing in it but git to clone with), this repository's HEAD cloned into
# it, and then, as the README says, `bash tools/setup.sh` and `bash tools/test.sh`,
# each timed. Nothing of this machine's caches is used: every package is installed,
# every source fetched and everything compiled from nothing.
#
#   tools/stack/fresh-debian12.sh DIR   make the root in DIR (which must not exist; a few
#                                       GB), run both commands, print their times;
#                                       the log of each is DIR.setup.log, DIR.test.log
#   tools/stack/fresh-debian12.sh --in DIR NAME CMD
#                                       run CMD in the clone in that root again (log
#                                       DIR.NAME.log), e.g. GRANSPH_STACKS=2026 bash tools/test.sh
#
# Needs root (mmdebstrap, chroot, unshare). Takes about an hour on 2 cores. The root is
# left in DIR for a look afterwards; delete it with `rm -rf DIR` (no mount outlives the
# script: /proc, /sys and /dev are mounted in a private mount namespace).
set -euo pipefail
usage() { sed -n 3,18p "$0"; exit 2; }
[ "$(id -u)" -eq 0 ] || { echo "must run as root" >&2; exit 1; }
again=false
if [ "${1:-}" = --in ]; then
  [ $# -eq 4 ] || usage
  again=true
  shift
else
  [ $# -eq 1 ] || usage
fi
dir=$(readlink -m "$1")
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)

# run_in_root NAME CMD: CMD in the root's clone, as root, its output in DIR.NAME.log. The
# root is bound onto itself first: inside, / is then a mount point, as on a machine, which
# tools/stack/sid-root.sh's own private mount namespace needs
run_in_root() {
  local name=$1 cmd=$2 begin=$SECONDS rc=0
  unshare --mount --propagation private -- bash -euc '
    root=$1; shift
    mount --bind "$root" "$root"
    mount -t proc proc "$root/proc"
    mount --rbind /sys "$root/sys"
    mount --rbind /dev "$root/dev"
    cp /etc/resolv.conf "$root/etc/resolv.conf"
    exec chroot "$root" env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
      LANG=C.UTF-8 TERM=dumb bash -lc "cd /root/gransph && $1"' _ "$dir" "$cmd" \
    > "$dir.$name.log" 2>&1 || rc=$?
  echo "=== $name: $((SECONDS - begin)) s, exit $rc (log: $dir.$name.log)"
  tail -n 5 "$dir.$name.log"
  return $rc
}

if $again; then
  [ -d "$dir/root/gransph" ] || { echo "no clone in $dir/root/gransph" >&2; exit 1; }
  run_in_root "$2" "$3"
  exit
fi
[ ! -e "$dir" ] || { echo "$dir exists: give a new directory" >&2; exit 1; }
# shellcheck source=tools/stack/apt-mirror.sh
source "$top/tools/stack/apt-mirror.sh"
mirror=$(debian_mirror_uri bookworm)

start=$SECONDS
mmdebstrap --quiet --variant=minbase --include=git,ca-certificates bookworm "$dir" \
  "deb $mirror bookworm main" "deb $mirror bookworm-updates main"
echo "=== bookworm root: $((SECONDS - start)) s"
git clone --quiet "$top" "$dir/root/gransph"
git -C "$dir/root/gransph" log --oneline -1

run_in_root setup "bash tools/setup.sh"
run_in_root test "bash tools/test.sh"
echo "=== both commands on a fresh Debian 12 root: $((SECONDS - start)) s in all"
