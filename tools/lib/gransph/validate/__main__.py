# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
from .cli import main

main()
