/* ----------------------------------------------------------------------
   GRANSPH: the integrator fixes with their constitutive models, each compiled
   once (fix_sph_model.h).
------------------------------------------------------------------------- */

#include "fix_sph_elastoplastic.h"
#include "fix_sph_phasechange.h"

namespace LAMMPS_NS {

template class FixSPHModel<GRANSPH::DruckerPrager>;
template class FixSPHModel<GRANSPH::PhaseChange>;

}    // namespace LAMMPS_NS
