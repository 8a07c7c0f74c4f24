/* ----------------------------------------------------------------------
   GRANSPH: fix sph/elastoplastic, compiled once (fix_sph_model.h).
------------------------------------------------------------------------- */

#include "fix_sph_elastoplastic.h"

namespace LAMMPS_NS {

template class FixSPHModel<GRANSPH::DruckerPrager>;

}    // namespace LAMMPS_NS
