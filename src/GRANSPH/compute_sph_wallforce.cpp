/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: compute sph/wallforce.

   pair sph/granular adds to the force of every dummy particle the force the
   grains exert on it (eq. 9), so the force of the grains on a wall is the sum
   of the forces of its dummy particles, and eq. 10 its component along the
   wall normal.
------------------------------------------------------------------------- */

#include "compute_sph_wallforce.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_integrate.h"
#include "force.h"
#include "gransph_find_fix.h"
#include "gransph_tensor.h"
#include "group.h"
#include "modify.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   compute ID wall-group sph/wallforce nx ny nz
------------------------------------------------------------------------- */

ComputeSPHWallForce::ComputeSPHWallForce(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg)
{
  if (narg != 6) error->all(FLERR, "Illegal compute sph/wallforce command: expected nx ny nz");
  for (int a = 0; a < 3; ++a) normal[a] = utils::numeric(FLERR, arg[3 + a], false, lmp);
  const double norm = GRANSPH::norm3(normal);
  if (norm == 0.0) error->all(FLERR, "Compute sph/wallforce: normal nx ny nz must be non-zero");
  if (domain->dimension == 2 && normal[2] != 0.0)
    error->all(FLERR, "Compute sph/wallforce: normal must have nz = 0 for a 2d simulation");
  for (int a = 0; a < 3; ++a) normal[a] /= norm;

  vector_flag = 1;
  size_vector = 4;
  extvector = 1;    // a total force: grows with the size of the wall
  vector = new double[size_vector];
}

ComputeSPHWallForce::~ComputeSPHWallForce()
{
  delete[] vector;
}

/* ---------------------------------------------------------------------- */

void ComputeSPHWallForce::init()
{
  if (!force->pair_match("sph/granular", 0))
    error->all(FLERR, "Compute sph/wallforce requires pair_style sph/granular");

  const FixSPHIntegrate *integrator = &FixSPHIntegrate::find(lmp, "Compute sph/wallforce");
  if (!integrator->wallbit)
    error->all(FLERR, "Compute sph/wallforce: fix {} has no walls group (keyword walls)",
               integrator->id);
  // the pair style computes the wall force only for the fix's dummy particles
  const int *mask = atom->mask;
  const int wallbit = integrator->wallbit;
  const auto off_walls = [&](int i) { return (mask[i] & groupbit) && !(mask[i] & wallbit); };
  if (GRANSPH::any_owned_atom(lmp, off_walls))
    error->all(FLERR, "Compute sph/wallforce: group {} has atoms outside the walls group of fix {}",
               group->names[igroup], integrator->id);

  // fix gravity adds m g to the force of the atoms it acts on
  for (int k = 0; k < modify->nfix; ++k) {
    const Fix *fix = modify->fix[k];
    const auto pulled = [&](int i) { return (mask[i] & groupbit) && (mask[i] & fix->groupbit); };
    if (!utils::strmatch(fix->style, "^gravity") || !GRANSPH::any_owned_atom(lmp, pulled)) continue;
    if (comm->me == 0)
      error->warning(FLERR,
                     "Compute sph/wallforce: fix gravity {} acts on atoms of group {}, so their "
                     "weight is added to the wall force",
                     fix->id, group->names[igroup]);
  }
}

/* ----------------------------------------------------------------------
   Fx, Fy, Fz of the grains on the wall, then F_W = F . n (eq. 10)
------------------------------------------------------------------------- */

void ComputeSPHWallForce::compute_vector()
{
  invoked_vector = update->ntimestep;
  total_force(vector);
  vector[3] = GRANSPH::dot3(vector, normal);
}

void ComputeSPHWallForce::total_force(double *f)
{
  group->fcm(igroup, f);
}
