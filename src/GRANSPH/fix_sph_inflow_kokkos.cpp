/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

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

// all atom data on the host where a layer enters, none on the other steps
void FixSPHInflowKokkos::insert_due_layers(double t_place)
{
  if (!layer_due(t_place)) return;
  atomKK->sync(Host, ALL_MASK);
  FixSPHInflow::insert_due_layers(t_place);
  atomKK->modified(Host, ALL_MASK);
}
