/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: compute sph/stress/atom.

   Reads the stress that the integrator fix keeps per atom (tension positive)
   and writes it compression positive, as soil mechanics does. Host code: the
   principal axes come from Eigen (gransph_stress_invariants.h); with the /kk
   integrator the state is copied to the host on the steps the compute runs.
------------------------------------------------------------------------- */

#include "compute_sph_stress_atom.h"

#include "atom.h"
#include "error.h"
#include "fix_sph_integrate.h"
#include "gransph_stress_invariants.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   compute ID group-ID sph/stress/atom
------------------------------------------------------------------------- */

ComputeSPHStressAtom::ComputeSPHStressAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), values(nullptr)
{
  if (narg != 3) error->all(FLERR, "Illegal compute sph/stress/atom command: no arguments");
  peratom_flag = 1;
  size_peratom_cols = NCOLS;
}

ComputeSPHStressAtom::~ComputeSPHStressAtom()
{
  memory->destroy(values);
}

void ComputeSPHStressAtom::init()
{
  integrator();
}

// the GRANSPH integrator, looked up on every use: the compute may run (write_dump)
// before any run has called init
FixSPHIntegrate *ComputeSPHStressAtom::integrator() const
{
  return &FixSPHIntegrate::find(lmp, "Compute sph/stress/atom");
}

/* ---------------------------------------------------------------------- */

void ComputeSPHStressAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(values);
    nmax = atom->nmax;
    memory->create(values, nmax, NCOLS, "sph/stress/atom:values");
    array_atom = values;
  }

  FixSPHIntegrate *fix = integrator();
  fix->sync_state_host();
  const FixSPHIntegrate::HostState state = fix->host_state();
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i) {
    double *out = values[i];
    if (!(mask[i] & groupbit)) {
      for (int k = 0; k < NCOLS; ++k) out[k] = 0.0;
      continue;
    }
    const GRANSPH::Sym3 sigma = state.sigma(i);
    const GRANSPH::StressInvariants s = GRANSPH::stress_invariants(sigma);
    out[P] = s.p;
    out[Q] = s.q;
    for (int k = 0; k < 3; ++k) {
      out[SIGMA1 + k] = s.principal[k];
      out[MAJOR_X + k] = s.major[k];
    }
    out[LODE] = s.lode;
    out[MOBILISED] = fix->mobilised_ratio(fix->materials.of(mask[i]), sigma);
    out[REGIME] = state.regime(i);
  }
}

double ComputeSPHStressAtom::memory_usage()
{
  return (double) nmax * (int) NCOLS * sizeof(double);
}
