#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
# Set everything up on a fresh Debian 12 machine and run the column-collapse example.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$top/tools/stack/build.sh"
cd "$top/examples/column_collapse"
"$top/tools/lmp" -in in.column_collapse -log log.column_collapse.setup | grep -E "^result:"
