/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: compute sph/stress/atom, the stress of each particle as a
   geomechanics user reads it: p, q, principal stresses, the major direction,
   Lode angle, the mobilised strength of the integrator's model, and the regime.
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_SPH_STRESS_ATOM_H
#define LMP_COMPUTE_SPH_STRESS_ATOM_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeSPHStressAtom : public Compute {
 public:
  // columns of the per-atom array (c_ID[1] is P)
  enum { P, Q, SIGMA1, SIGMA2, SIGMA3, MAJOR_X, MAJOR_Y, MAJOR_Z, LODE, MOBILISED, REGIME, NCOLS };

  ComputeSPHStressAtom(class LAMMPS *, int, char **);
  ~ComputeSPHStressAtom() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  int nmax;
  double **values;

  class FixSPHIntegrate *integrator() const;
};

}    // namespace LAMMPS_NS

#endif
