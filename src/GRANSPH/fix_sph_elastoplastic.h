/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: granular SPH integrator with the elastoplastic Drucker-Prager model.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/elastoplastic,FixSPHElastoplastic);
// clang-format on
#else

#ifndef LMP_FIX_SPH_ELASTOPLASTIC_H
#define LMP_FIX_SPH_ELASTOPLASTIC_H

#include "fix_sph_integrate.h"
#include "gransph_drucker_prager.h"

namespace LAMMPS_NS {

class FixSPHElastoplastic : public FixSPHIntegrate {
 public:
  FixSPHElastoplastic(class LAMMPS *, int, char **);

  const GRANSPH::DruckerPrager model;

 protected:
  void update_stress(double dt, StressStep from) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
