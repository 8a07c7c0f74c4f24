/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: Kokkos twin of fix sph/move.
------------------------------------------------------------------------- */

#include "fix_sph_move_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"

using namespace LAMMPS_NS;

template <class DeviceType>
FixSPHMoveKokkos<DeviceType>::FixSPHMoveKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixSPHMove(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = X_MASK | V_MASK | MASK_MASK;
  datamask_modify = X_MASK | V_MASK;
}

template <class DeviceType>
void FixSPHMoveKokkos<DeviceType>::move(const double *dx, const double *v)
{
  atomKK->sync(execution_space, datamask_read);
  auto x = atomKK->k_x.template view<DeviceType>();
  auto vel = atomKK->k_v.template view<DeviceType>();
  auto mask = atomKK->k_mask.template view<DeviceType>();
  const int groupbit = this->groupbit;
  const double dx0 = dx[0], dx1 = dx[1], dx2 = dx[2];
  const double v0 = v[0], v1 = v[1], v2 = v[2];
  Kokkos::parallel_for(
      Kokkos::RangePolicy<DeviceType>(0, atom->nlocal), LAMMPS_LAMBDA(const int i) {
        if (!(mask(i) & groupbit)) return;
        x(i, 0) += dx0;
        x(i, 1) += dx1;
        x(i, 2) += dx2;
        vel(i, 0) = v0;
        vel(i, 1) = v1;
        vel(i, 2) = v2;
      });
  atomKK->modified(execution_space, datamask_modify);
}

namespace LAMMPS_NS {
template class FixSPHMoveKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixSPHMoveKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
