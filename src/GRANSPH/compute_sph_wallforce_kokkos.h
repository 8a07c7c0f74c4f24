/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: Kokkos twin of compute sph/wallforce: the sum of the forces on the
   wall's dummy particles is reduced where the forces are, on the device.
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_SPH_WALLFORCE_KOKKOS_H
#define LMP_COMPUTE_SPH_WALLFORCE_KOKKOS_H

#include "compute_sph_wallforce.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

template <class DeviceType> class ComputeSPHWallForceKokkos : public ComputeSPHWallForce {
 public:
  ComputeSPHWallForceKokkos(class LAMMPS *, int, char **);

  // device reduction (public: CUDA lambdas may not live in private members)
  void total_force(double *f) override;
};

}    // namespace LAMMPS_NS

#endif
