/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: compute sph/runout.

   The grains' volume (m / rho0 of each one's material) is binned by distance
   r from a vertical axis in fine bins; the window of BINS_PER_WINDOW bins
   centred on each bin (an annulus of the given width in 3d, two strips in 2d)
   gives the deposit's equivalent thickness there, the volume in it over its
   area. The deposit edge is the outermost grain in a layer at least
   threshold * scale thick: a thickness fixed in the problem's units (a fraction
   of the column's radius, say), so the edge means the same at every
   resolution, while a layer thinner than that (the skirt) is reported by its
   volume fraction beyond the edge rather than hidden.
------------------------------------------------------------------------- */

#include "compute_sph_runout.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_integrate.h"
#include "math_const.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

enum { EDGE, R95, RMAX, SKIRT, THICKNESS, ZMAX, NVALUES };

/* ----------------------------------------------------------------------
   compute ID group sph/runout x0 y0 scale width [threshold f]   (3d)
   compute ID group sph/runout x0 scale width [threshold f]      (2d)
------------------------------------------------------------------------- */

ComputeSPHRunout::ComputeSPHRunout(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), axis{0.0, 0.0}, threshold(0.05), materials(nullptr)
{
  const int naxis = domain->dimension == 3 ? 2 : 1;
  if (narg < 5 + naxis)
    error->all(FLERR, "Illegal compute sph/runout command: expected {} scale width [threshold f]",
               naxis == 2 ? "x0 y0" : "x0");
  int iarg = 3;
  for (int a = 0; a < naxis; ++a) axis[a] = utils::numeric(FLERR, arg[iarg++], false, lmp);
  scale = utils::numeric(FLERR, arg[iarg++], false, lmp);
  width = utils::numeric(FLERR, arg[iarg++], false, lmp);
  if (scale <= 0.0 || width <= 0.0)
    error->all(FLERR, "Compute sph/runout: scale and width must be > 0");
  while (iarg < narg) {
    if (strcmp(arg[iarg], "threshold") == 0 && iarg + 1 < narg) {
      threshold = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (threshold <= 0.0 || threshold >= 1.0)
        error->all(FLERR, "Compute sph/runout: threshold must be in (0, 1)");
      iarg += 2;
    } else
      error->all(FLERR, "Compute sph/runout: unknown keyword or missing value: {}", arg[iarg]);
  }
  vector_flag = 1;
  size_vector = NVALUES;
  extvector = 0;
  vector = new double[size_vector];
}

ComputeSPHRunout::~ComputeSPHRunout()
{
  delete[] vector;
}

void ComputeSPHRunout::init()
{
  materials = &FixSPHIntegrate::find(lmp, "Compute sph/runout").materials;
}

double ComputeSPHRunout::radius(const double *x) const
{
  if (domain->dimension == 2) return fabs(x[0] - axis[0]);
  return sqrt((x[0] - axis[0]) * (x[0] - axis[0]) + (x[1] - axis[1]) * (x[1] - axis[1]));
}

double ComputeSPHRunout::grain_volume(int i) const
{
  const double rho0 = materials->rho0[materials->of(atom->mask[i])];
  return (atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]]) / rho0;
}

// floor area between r_in and r_out
double ComputeSPHRunout::floor_area(double r_in, double r_out) const
{
  if (domain->dimension == 2) return 2.0 * (r_out - r_in);
  return MathConst::MY_PI * (r_out * r_out - r_in * r_in);
}

int ComputeSPHRunout::bin_of(double r, double bin, int nbins)
{
  return std::min(nbins - 1, static_cast<int>(r / bin));
}

/* ----------------------------------------------------------------------
   r_edge, r_95 (the radius within which 95% of the volume lies), the outermost
   grain's r, the volume fraction beyond r_edge, the largest window thickness,
   the highest grain's z (y in 2d); radii and z are of the grains' centres
------------------------------------------------------------------------- */

void ComputeSPHRunout::compute_vector()
{
  invoked_vector = update->ntimestep;
  double **x = atom->x;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal, up = domain->dimension == 3 ? 2 : 1;

  double local_max[2] = {0.0, -HUGE_VAL};    // r, z
  for (int i = 0; i < nlocal; ++i)
    if (mask[i] & groupbit) {
      local_max[0] = std::max(local_max[0], radius(x[i]));
      local_max[1] = std::max(local_max[1], x[i][up]);
    }
  double global_max[2];
  MPI_Allreduce(local_max, global_max, 2, MPI_DOUBLE, MPI_MAX, world);

  const double bin = width / BINS_PER_WINDOW;
  const int nbins = static_cast<int>(global_max[0] / bin) + 1;
  std::vector<double> local(nbins + 1, 0.0);    // the last entry: the total
  for (int i = 0; i < nlocal; ++i)
    if (mask[i] & groupbit) {
      const double v = grain_volume(i);
      local[bin_of(radius(x[i]), bin, nbins)] += v;
      local[nbins] += v;
    }
  volume.assign(nbins + 1, 0.0);
  MPI_Allreduce(local.data(), volume.data(), nbins + 1, MPI_DOUBLE, MPI_SUM, world);
  const double total = volume[nbins];

  // thickness of the window centred on each bin
  const int half = BINS_PER_WINDOW / 2;
  std::vector<double> thickness(nbins, 0.0);
  double thickest = 0.0;
  for (int k = 0; k < nbins; ++k) {
    double in_window = 0.0;
    for (int m = std::max(0, k - half); m <= std::min(nbins - 1, k + half); ++m)
      in_window += volume[m];
    const double r_in = std::max(0, k - half) * bin, r_out = (k + half + 1) * bin;
    thickness[k] = in_window / floor_area(r_in, r_out);
    thickest = std::max(thickest, thickness[k]);
  }

  // the edge: the outermost grain in a layer at least threshold * scale thick
  double edge_local = 0.0, edge = 0.0;
  for (int i = 0; i < nlocal; ++i)
    if (mask[i] & groupbit) {
      const double r = radius(x[i]);
      if (thickness[bin_of(r, bin, nbins)] >= threshold * scale)
        edge_local = std::max(edge_local, r);
    }
  MPI_Allreduce(&edge_local, &edge, 1, MPI_DOUBLE, MPI_MAX, world);

  double r95 = 0.0, inside = 0.0;
  for (int k = 0; k < nbins; ++k) {
    if (inside + volume[k] >= 0.95 * total) {
      r95 = (k + (0.95 * total - inside) / volume[k]) * bin;
      break;
    }
    inside += volume[k];
  }

  double skirt_local = 0.0, skirt = 0.0;
  for (int i = 0; i < nlocal; ++i)
    if ((mask[i] & groupbit) && radius(x[i]) > edge) skirt_local += grain_volume(i);
  MPI_Allreduce(&skirt_local, &skirt, 1, MPI_DOUBLE, MPI_SUM, world);

  vector[EDGE] = edge;
  vector[R95] = r95;
  vector[RMAX] = global_max[0];
  vector[SKIRT] = total > 0.0 ? skirt / total : 0.0;
  vector[THICKNESS] = thickest;
  vector[ZMAX] = global_max[1];
}
