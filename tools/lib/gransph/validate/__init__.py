# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""The validation studies of GRANSPH (tools/research/validate): a module per study (paper and
jets: the paper's four cases in validation/report.md; convergence, basal_friction, flume,
cfl, sphere_impact, erodible_bed: their folders of validation/), the column's measures
(collapse), the report writer (report) and the command line (cli). The runs go through
gransph.lammps' Runner, which holds how they run (ranks, /kk styles, --resume) and where
they write."""

import matplotlib

matplotlib.use("Agg")
