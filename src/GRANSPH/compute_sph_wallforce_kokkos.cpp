/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: Kokkos twin of compute sph/wallforce.
------------------------------------------------------------------------- */

#include "compute_sph_wallforce_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"

using namespace LAMMPS_NS;

template <class DeviceType>
ComputeSPHWallForceKokkos<DeviceType>::ComputeSPHWallForceKokkos(LAMMPS *lmp, int narg,
                                                                   char **arg) :
    ComputeSPHWallForce(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = F_MASK | MASK_MASK;
  datamask_modify = EMPTY_MASK;
}

// reduced on the device, without copying the forces to the host
template <class DeviceType> void ComputeSPHWallForceKokkos<DeviceType>::total_force(double *total)
{
  atomKK->sync(execution_space, datamask_read);
  auto f = atomKK->k_f.template view<DeviceType>();
  auto mask = atomKK->k_mask.template view<DeviceType>();
  const int groupbit = this->groupbit;
  double sum[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < 3; ++a)
    Kokkos::parallel_reduce(
        Kokkos::RangePolicy<DeviceType>(0, atom->nlocal),
        LAMMPS_LAMBDA(const int i, double &s) {
          if (mask(i) & groupbit) s += f(i, a);
        },
        sum[a]);
  MPI_Allreduce(sum, total, 3, MPI_DOUBLE, MPI_SUM, world);
}

namespace LAMMPS_NS {
template class ComputeSPHWallForceKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class ComputeSPHWallForceKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
