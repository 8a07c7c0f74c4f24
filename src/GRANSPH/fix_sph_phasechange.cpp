/* ----------------------------------------------------------------------
   GRANSPH: granular SPH integrator with the phase-change model of
   Dunatunga & Kamrin (2015).
------------------------------------------------------------------------- */

#include "fix_sph_phasechange.h"

using namespace LAMMPS_NS;

FixSPHPhaseChange::FixSPHPhaseChange(LAMMPS *lmp, int narg, char **arg) :
    FixSPHIntegrate(lmp, narg, arg),
    model(GRANSPH::PhaseChange::from_material(material.E, material.nu, material.rho_c,
                                              material.xi, material.mu_s, material.mu_2))
{
}

void FixSPHPhaseChange::update_stress(double dt, StressStep from)
{
  update_stress_with(model, dt, from);
}
