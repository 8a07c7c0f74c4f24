/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: fix sph/outflow.

   An atom is lost when it is outside the box at an exchange, which follows
   pre_exchange at every reneighboring (and at the setup of a run). Deleting
   the atoms outside a region that lies inside the box right before each
   exchange therefore removes every atom that leaves the box before LAMMPS
   can lose it.
------------------------------------------------------------------------- */

#include "fix_sph_outflow.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "gransph_lammps_compat.h"
#include "region.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ----------------------------------------------------------------------
   fix ID group sph/outflow region-ID [every N]
------------------------------------------------------------------------- */

FixSPHOutflow::FixSPHOutflow(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), idregion(nullptr), region(nullptr), every(0), nremoved(0), mass_removed(0.0),
    warned_region_leaves_box(false)
{
  if (narg < 4) error->all(FLERR, "Illegal fix sph/outflow command: need a region ID");
  region = GRANSPHCompat::find_region(domain, arg[3]);
  if (!region) error->all(FLERR, "Fix sph/outflow: region {} does not exist", arg[3]);
  idregion = utils::strdup(arg[3]);

  for (int iarg = 4; iarg < narg; iarg += 2) {
    if (strcmp(arg[iarg], "every") != 0)
      error->all(FLERR, "Fix sph/outflow: unknown keyword {}", arg[iarg]);
    if (iarg + 1 >= narg) error->all(FLERR, "Fix sph/outflow: keyword every needs a value");
    every = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
    if (every < 1) error->all(FLERR, "Fix sph/outflow: every must be >= 1");
  }

  // deleting single atoms would break bonds
  if (atom->molecular != Atom::ATOMIC)
    error->all(FLERR, "Fix sph/outflow cannot delete atoms of a molecular system");

  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 2;
  global_freq = 1;
  extscalar = 0;
  extvector = 0;
  force_reneighbor = every > 0;
  next_reneighbor = -1;    // set at the setup of each run
}

FixSPHOutflow::~FixSPHOutflow()
{
  delete[] idregion;
}

int FixSPHOutflow::setmask()
{
  return PRE_EXCHANGE;
}

void FixSPHOutflow::init()
{
  region = GRANSPHCompat::find_region(domain, idregion);
  if (!region) error->all(FLERR, "Fix sph/outflow: region {} does not exist", idregion);
  // copying the last atom into a deleted one's slot would break the ordering
  if (atom->firstgroup >= 0)
    error->all(FLERR, "Fix sph/outflow cannot be used with atom_modify first");
  warn_if_region_leaves_box();
}

/* ----------------------------------------------------------------------
   also at the setup of a run: the previous run may have ended between
   reneighborings with atoms outside the box, which the setup's exchange
   would lose
------------------------------------------------------------------------- */

void FixSPHOutflow::setup_pre_exchange()
{
  pre_exchange();
}

void FixSPHOutflow::pre_exchange()
{
  remove_outside();
  if (every) next_reneighbor = update->ntimestep + every;
}

/* ----------------------------------------------------------------------
   delete the group's atoms outside the region as fix evaporate does: the
   last atom, with its per-atom fix data, is copied into the deleted slot
------------------------------------------------------------------------- */

void FixSPHOutflow::remove_outside()
{
  region->prematch();
  double **x = atom->x;
  const int *mask = atom->mask;
  const int *type = atom->type;
  const double *rmass = atom->rmass;
  const double *mass = atom->mass;

  bigint nlocal_removed = 0;
  double mass_local = 0.0;
  // backwards, so that the atom copied into slot i has been checked already
  for (int i = atom->nlocal - 1; i >= 0; --i) {
    if (!(mask[i] & groupbit) || region->match(x[i][0], x[i][1], x[i][2])) continue;
    mass_local += rmass ? rmass[i] : mass[type[i]];
    atom->avec->copy(atom->nlocal - 1, i, 1);
    atom->nlocal--;
    ++nlocal_removed;
  }

  bigint nall = 0;
  MPI_Allreduce(&nlocal_removed, &nall, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (nall == 0) return;
  double mass_all = 0.0;
  MPI_Allreduce(&mass_local, &mass_all, 1, MPI_DOUBLE, MPI_SUM, world);
  atom->natoms -= nall;
  nremoved += nall;
  mass_removed += mass_all;

  // the map still points at deleted atoms and at ghosts, which the coming
  // exchange and borders rebuild: map the owned atoms now
  if (atom->map_style != Atom::MAP_NONE) {
    atom->nghost = 0;
    atom->map_init();
    atom->map_set();
  }
}

/* ----------------------------------------------------------------------
   where the region reaches beyond a fixed (f) boundary, an atom can leave the
   box while still inside the region, and is lost at the next exchange
------------------------------------------------------------------------- */

void FixSPHOutflow::warn_if_region_leaves_box()
{
  if (warned_region_leaves_box || comm->me != 0 || !region->bboxflag || domain->triclinic) return;
  const double lo[3] = {region->extent_xlo, region->extent_ylo, region->extent_zlo};
  const double hi[3] = {region->extent_xhi, region->extent_yhi, region->extent_zhi};
  for (int d = 0; d < domain->dimension; ++d)
    if ((domain->boundary[d][0] == 1 && lo[d] < domain->boxlo[d]) ||
        (domain->boundary[d][1] == 1 && hi[d] > domain->boxhi[d])) {
      error->warning(FLERR,
                     "Fix sph/outflow: region {} extends beyond a fixed boundary of the box; "
                     "atoms leaving the box there are lost",
                     idregion);
      warned_region_leaves_box = true;
      return;
    }
}

/* ----------------------------------------------------------------------
   cumulative number of deleted atoms, and [count, mass]
------------------------------------------------------------------------- */

double FixSPHOutflow::compute_scalar()
{
  return static_cast<double>(nremoved);
}

double FixSPHOutflow::compute_vector(int n)
{
  return n == 0 ? static_cast<double>(nremoved) : mass_removed;
}
