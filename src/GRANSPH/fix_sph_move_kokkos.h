/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: Kokkos twin of fix sph/move. The velocity is evaluated on the
   host, as in the plain fix; the atoms move on the Kokkos device.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_MOVE_KOKKOS_H
#define LMP_FIX_SPH_MOVE_KOKKOS_H

#include "fix_sph_move.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixSPHMoveKokkos : public FixSPHMove {
 public:
  FixSPHMoveKokkos(class LAMMPS *, int, char **);

  // device kernel (public: CUDA lambdas may not live in private members)
  void move(const double *dx, const double *v) override;
};

}    // namespace LAMMPS_NS

#endif
