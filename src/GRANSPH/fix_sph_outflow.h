/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: fix sph/outflow, deletes the particles of its group that have left
   a region, e.g. sand flowing off the end of a flume.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_OUTFLOW_H
#define LMP_FIX_SPH_OUTFLOW_H

#include "fix.h"

namespace LAMMPS_NS {

class FixSPHOutflow : public Fix {
 public:
  FixSPHOutflow(class LAMMPS *, int, char **);
  ~FixSPHOutflow() override;
  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  double compute_scalar() override;
  double compute_vector(int) override;

 private:
  char *idregion;
  class Region *region;    // looked up again at init
  int every;              // reneighbor at least every this many steps (0: as LAMMPS decides)
  bigint nremoved;        // atoms deleted so far, all ranks
  double mass_removed;    // their mass

  void remove_outside();
  bool warned_region_leaves_box;    // once per fix, not at every run
  void warn_if_region_leaves_box();
};

}    // namespace LAMMPS_NS

#endif
