/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: compute sph/runout, the extent of a granular deposit on a floor
   measured from its thickness profile around a vertical axis, as experiments
   measure a runout, next to the outermost grain.
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_SPH_RUNOUT_H
#define LMP_COMPUTE_SPH_RUNOUT_H

#include "compute.h"
#include "gransph_materials.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeSPHRunout : public Compute {
 public:
  ComputeSPHRunout(class LAMMPS *, int, char **);
  ~ComputeSPHRunout() override;
  void init() override;
  void compute_vector() override;

 private:
  double axis[2];      // the vertical axis through (axis[0], axis[1]) (x in 2d)
  double scale;        // the thickness the threshold is a fraction of
  double width;        // of the sliding window (annulus) the thickness is taken over
  double threshold;    // edge: the thickness falls below threshold * scale
  const GRANSPH::MaterialTable *materials;    // a grain's volume is m / its rho0
  std::vector<double> volume;    // per fine bin, summed over the ranks

  static constexpr int BINS_PER_WINDOW = 9;    // odd: a window is centred on a bin

  double radius(const double *x) const;
  double grain_volume(int i) const;
  double floor_area(double r_in, double r_out) const;
  static int bin_of(double r, double bin, int nbins);
};

}    // namespace LAMMPS_NS

#endif
