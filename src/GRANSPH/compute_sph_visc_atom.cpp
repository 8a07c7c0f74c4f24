/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: compute sph/visc/atom.

   The pair style sums the viscous pressure only in the force evaluations of
   the steps this compute is scheduled to run on (timeflag: thermo, dumps and
   fixes that invoke it tell it their steps in advance), so that a run that
   does not ask for the diagnostic does not pay for its neighbour sums.
------------------------------------------------------------------------- */

#include "compute_sph_visc_atom.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "pair_sph_granular.h"
#include "update.h"

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   compute ID group-ID sph/visc/atom
------------------------------------------------------------------------- */

ComputeSPHViscAtom::ComputeSPHViscAtom(LAMMPS *lmp, int narg, char **arg) : Compute(lmp, narg, arg)
{
  if (narg != 3) error->all(FLERR, "Illegal compute sph/visc/atom command: no arguments");
  peratom_flag = 1;
  size_peratom_cols = 0;
  timeflag = 1;    // the pair style sums the diagnostic on the steps stored by addstep()
}

void ComputeSPHViscAtom::init()
{
  granular_pair();
}

// the pair style, looked up on every use: the compute may run (write_dump) before any
// run has called init
PairSPHGranular *ComputeSPHViscAtom::granular_pair() const
{
  auto pair = dynamic_cast<PairSPHGranular *>(force->pair);
  if (!pair) error->all(FLERR, "Compute sph/visc/atom requires pair_style sph/granular");
  return pair;
}

/* ---------------------------------------------------------------------- */

void ComputeSPHViscAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  const double *pressure = granular_pair()->viscous_pressure();
  if (!pressure)
    error->all(FLERR,
               "Compute sph/visc/atom: the viscous pressure was not summed on step {}: the pair "
               "style sums it in the force evaluation of each step the compute is scheduled "
               "for (by thermo, dump, fix ave/* and the like) and of a run's setup, so it can "
               "be read after that evaluation, not before it (as by a variable of fix sph/move)",
               update->ntimestep);
  const int nlocal = atom->nlocal;
  if ((int) values.size() < atom->nmax) values.resize(atom->nmax);
  const int *mask = atom->mask;
  for (int i = 0; i < nlocal; ++i) values[i] = mask[i] & groupbit ? pressure[i] : 0.0;
  vector_atom = values.data();
}

double ComputeSPHViscAtom::memory_usage()
{
  return (double) values.size() * sizeof(double);
}
