/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: compute sph/material/atom, the material of each grain: 1 for the
   integrator fix's own, 2, 3, ... for those of its material keywords in their
   order, 0 for atoms that are not its grains.
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_SPH_MATERIAL_ATOM_H
#define LMP_COMPUTE_SPH_MATERIAL_ATOM_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeSPHMaterialAtom : public Compute {
 public:
  ComputeSPHMaterialAtom(class LAMMPS *, int, char **);
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  std::vector<double> values;
};

}    // namespace LAMMPS_NS

#endif
