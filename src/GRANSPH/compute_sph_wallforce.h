/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: compute sph/wallforce, the total force of the grains on a wall of
   dummy particles and its normal component (paper eqs. 9-10).
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_SPH_WALLFORCE_H
#define LMP_COMPUTE_SPH_WALLFORCE_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeSPHWallForce : public Compute {
 public:
  ComputeSPHWallForce(class LAMMPS *, int, char **);
  ~ComputeSPHWallForce() override;
  void init() override;
  void compute_vector() override;

 protected:
  double normal[3];    // unit normal of the wall

  // the total force on the group's atoms, on all ranks
  virtual void total_force(double *f);
};

}    // namespace LAMMPS_NS

#endif
