/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: fix sph/phasechange, compiled once (fix_sph_model.h).
------------------------------------------------------------------------- */

#include "fix_sph_models.h"

namespace LAMMPS_NS {

template class FixSPHModel<GRANSPH::PhaseChange>;

}    // namespace LAMMPS_NS
