/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: compute sph/material/atom.
------------------------------------------------------------------------- */

#include "compute_sph_material_atom.h"

#include "atom.h"
#include "error.h"
#include "fix_sph_integrate.h"
#include "update.h"

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   compute ID group-ID sph/material/atom
------------------------------------------------------------------------- */

ComputeSPHMaterialAtom::ComputeSPHMaterialAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg)
{
  if (narg != 3) error->all(FLERR, "Illegal compute sph/material/atom command: no arguments");
  peratom_flag = 1;
  size_peratom_cols = 0;
}

void ComputeSPHMaterialAtom::init()
{
  FixSPHIntegrate::find(lmp, "Compute sph/material/atom");
}

void ComputeSPHMaterialAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  const FixSPHIntegrate &fix = FixSPHIntegrate::find(lmp, "Compute sph/material/atom");
  if ((int) values.size() < atom->nmax) values.resize(atom->nmax);
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i)
    values[i] = (mask[i] & groupbit) && (mask[i] & fix.groupbit) ? 1 + fix.materials.of(mask[i]) : 0;
  vector_atom = values.data();
}

double ComputeSPHMaterialAtom::memory_usage()
{
  return (double) values.size() * sizeof(double);
}
