/* ----------------------------------------------------------------------
   GRANSPH: granular SPH integrator with the elastoplastic Drucker-Prager model.
------------------------------------------------------------------------- */

#include "fix_sph_elastoplastic.h"

using namespace LAMMPS_NS;

FixSPHElastoplastic::FixSPHElastoplastic(LAMMPS *lmp, int narg, char **arg) :
    FixSPHIntegrate(lmp, narg, arg),
    model(GRANSPH::DruckerPrager::from_material(material.E, material.nu, material.phi,
                                                material.psi, material.c))
{
}

void FixSPHElastoplastic::update_stress(double dt, StressStep from)
{
  update_stress_with(model, dt, from);
}
