/* ----------------------------------------------------------------------
   GRANSPH: fix sph/phasechange, compiled once (fix_sph_model.h).
------------------------------------------------------------------------- */

#include "fix_sph_phasechange.h"

namespace LAMMPS_NS {

template class FixSPHModel<GRANSPH::PhaseChange>;

}    // namespace LAMMPS_NS
