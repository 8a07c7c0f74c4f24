# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
# Sourced by tools/stack/deps.sh and tools/stack/sid-root.sh: the Debian mirror this machine's
# own apt configuration uses, so that no registry host name is written in our code.
#
# debian_mirror_uri [SUITE]  prints the URI of the first `deb` entry for SUITE
# (default bookworm; the release itself, not -updates/-security) found in
# /etc/apt/sources.list, /etc/apt/sources.list.d/*.list (one-line format) and
# /etc/apt/sources.list.d/*.sources (deb822 format), or fails with a message.
# APT_ETC overrides /etc/apt (for tests).
debian_mirror_uri() {
  local suite=${1:-bookworm} etc=${APT_ETC:-/etc/apt} uri f
  local lists=() sources=()
  [ -f "$etc/sources.list" ] && lists+=("$etc/sources.list")
  for f in "$etc"/sources.list.d/*.list; do [ -f "$f" ] && lists+=("$f"); done
  for f in "$etc"/sources.list.d/*.sources; do [ -f "$f" ] && sources+=("$f"); done
  uri=$(
    {
      # one-line format: deb [options] URI SUITE COMPONENTS...
      [ ${#lists[@]} -gt 0 ] && awk -v s="$suite" '
        $1 == "deb" { i = 2; if ($2 ~ /^\[/) { while (i <= NF && $i !~ /\]$/) i++; i++ }
                      if ($(i + 1) == s) { print $i; exit } }' "${lists[@]}"
      # deb822: paragraphs separated by blank lines; Types, URIs and Suites may hold lists
      [ ${#sources[@]} -gt 0 ] && awk -v s="$suite" '
        function flush() { if (deb && suite_ok && u != "" && enabled) { print u; found = 1 }
                           deb = 0; suite_ok = 0; u = ""; enabled = 1 }
        BEGIN { enabled = 1 }
        FNR == 1 { flush() }
        /^[ \t]*$/ { flush(); next }
        /^#/ { next }
        tolower($1) == "types:"   { for (i = 2; i <= NF; i++) if ($i == "deb") deb = 1 }
        tolower($1) == "uris:"    { u = $2 }
        tolower($1) == "suites:"  { for (i = 2; i <= NF; i++) if ($i == s) suite_ok = 1 }
        tolower($1) == "enabled:" { enabled = (tolower($2) != "no") }
        found { exit }
        END { if (!found) flush() }' "${sources[@]}"
    } | head -n1)
  if [ -z "$uri" ]; then
    echo "no 'deb' entry for $suite in $etc/sources.list{,.d/*.list,.d/*.sources}:" \
         "cannot tell which Debian mirror to use" >&2
    return 1
  fi
  printf '%s\n' "${uri%/}"
}
