/* ----------------------------------------------------------------------
   GRANSPH: Kokkos twin of fix sph/inflow.
------------------------------------------------------------------------- */

#include "fix_sph_inflow_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"

using namespace LAMMPS_NS;

FixSPHInflowKokkos::FixSPHInflowKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixSPHInflow(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = Host;
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
}

void FixSPHInflowKokkos::setup_pre_exchange()
{
  atomKK->sync(Host, ALL_MASK);
  FixSPHInflow::setup_pre_exchange();
  atomKK->modified(Host, ALL_MASK);
}

void FixSPHInflowKokkos::pre_exchange()
{
  atomKK->sync(Host, ALL_MASK);
  FixSPHInflow::pre_exchange();
  atomKK->modified(Host, ALL_MASK);
}
