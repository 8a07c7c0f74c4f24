/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: fix sph/inflow, a granular nozzle: inserts layers of particles on a
   square lattice inside a disk, one layer each time the previous one has
   travelled a lattice spacing, optionally with the nozzle centre oscillating
   (the wavy jet of Chen et al. 2019, section 5.4, eq. 37).
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_INFLOW_H
#define LMP_FIX_SPH_INFLOW_H

#include "fix.h"

#include <vector>

namespace LAMMPS_NS {

class FixSPHInflow : public Fix {
 public:
  FixSPHInflow(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void setup_pre_exchange() override;
  void post_integrate() override;
  void pre_exchange() override;
  void end_of_step() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  bool layer_due(double t) const;
  // every layer due by t_place (the Kokkos twin: with the atoms on the host)
  virtual void insert_due_layers(double t_place);

 private:
  int ntype;
  double center[3], normal[3], e1[3], e2[3];    // nozzle disk and its lattice axes
  double radius, speed, spacing;
  double amplitude, frequency, wave_dir[3];    // eq. 37; amplitude 0: no wave
  double t_until;                              // no layer leaves the nozzle after this time
  double new_mass;                             // per-atom mass of new particles (rmass styles)
  std::vector<double> offsets;    // lattice points of a layer: (a, b) pairs along e1, e2

  bool started;         // the clock runs (since the first setup or from a restart file)
  double clock;         // time at the end of the current step
  double t_start;       // layer k leaves the nozzle plane at t_start + k spacing / speed
  bigint nlayers;       // layers inserted so far
  bigint nparticles;    // particles inserted so far, all ranks

  class FixSPHIntegrate *integrator;

  void parse_keywords(int, int, char **);
  void build_lattice();
  double emission_time(bigint k) const;
  int insert_layer(double t_emit, double t_place);
  bool owns(double *x, imageint &image) const;
};

}    // namespace LAMMPS_NS

#endif
