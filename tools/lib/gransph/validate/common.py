# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""What every study takes from a run (a number of its result line, its wall time) and the
sand's friction the thin-layer studies compare with."""

import math
import os

# Drucker-Prager with the plane-strain matching (the default): a layer at its friction
# limit slides against mu = 3 alpha_phi, alpha_phi = tan(phi) / sqrt(9 + 12 tan(phi)^2)
PHI_CHEN2019 = math.radians(37.0)
MU_PLANE_STRAIN = 3.0 * math.tan(PHI_CHEN2019) / math.sqrt(9.0 + 12.0 * math.tan(PHI_CHEN2019) ** 2)


def number_after(words, key):
    return float(words[words.index(key) + 1].rstrip(";"))


def wall_time(workdir):
    with open(os.path.join(workdir, "wall_time")) as f:
        return float(f.read())
