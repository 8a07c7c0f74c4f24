/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: compute sph/visc/atom, the pressure the artificial viscosity of
   pair_style sph/granular adds at each grain: the diagnostic that shows the
   viscosity's size next to the granular stress.
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_SPH_VISC_ATOM_H
#define LMP_COMPUTE_SPH_VISC_ATOM_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeSPHViscAtom : public Compute {
 public:
  ComputeSPHViscAtom(class LAMMPS *, int, char **);
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  std::vector<double> values;

  class PairSPHGranular *granular_pair() const;
};

}    // namespace LAMMPS_NS

#endif
