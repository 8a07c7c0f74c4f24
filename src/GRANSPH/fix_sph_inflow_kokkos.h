/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: Kokkos twin of fix sph/inflow. Creating atoms is host work in
   LAMMPS 29Sep2021 (as for fix deposit), so the twin only tells Kokkos what it
   touches: nothing on ordinary steps, and all atom data on the host in the
   pre_exchange where a layer enters. Without it, LAMMPS would copy every atom
   to the host on every step for this fix's post_integrate and end_of_step.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_INFLOW_KOKKOS_H
#define LMP_FIX_SPH_INFLOW_KOKKOS_H

#include "fix_sph_inflow.h"

namespace LAMMPS_NS {

class FixSPHInflowKokkos : public FixSPHInflow {
 public:
  FixSPHInflowKokkos(class LAMMPS *, int, char **);

 protected:
  void insert_due_layers(double t_place) override;
};

}    // namespace LAMMPS_NS

#endif
