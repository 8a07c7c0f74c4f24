/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: fix sph/move, moves walls of dummy particles with a prescribed
   velocity, in step with the GRANSPH predictor-corrector at any timestep.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_MOVE_H
#define LMP_FIX_SPH_MOVE_H

#include "fix.h"

namespace LAMMPS_NS {

class FixSPHMove : public Fix {
 public:
  FixSPHMove(class LAMMPS *, int, char **);
  ~FixSPHMove() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void initial_integrate(int) override;
  void final_integrate() override;

 protected:
  // shift the group's atoms by dx and give them velocity v
  virtual void move(const double *dx, const double *v);

 private:
  // a velocity component: a constant, or an equal-style variable
  struct Component {
    double value;
    char *variable;
    int ivariable;
  };
  Component component[3];
  double u_start[3], u_end[3];    // the prescribed velocity at the start and end of the step

  void evaluate(double *u);
  void check_not_granular() const;
};

}    // namespace LAMMPS_NS

#endif
