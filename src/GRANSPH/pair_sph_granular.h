/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: pair_style sph/granular, the SPH rates of granular particles and
   the stress and force of dummy-wall particles.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_SPH_GRANULAR_H
#define LMP_PAIR_SPH_GRANULAR_H

#include "pair.h"

#include "atom.h"
#include "fix_sph_integrate.h"
#include "gransph_pair_settings.h"
#include "update.h"

#include <vector>

namespace LAMMPS_NS {

class FixSPHNormals;

class PairSPHGranular : public Pair {
 public:
  PairSPHGranular(class LAMMPS *);
  ~PairSPHGranular() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void *extract(const char *, int &) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

  // The pressure the artificial viscosity adds at each owned atom (0 but at grains),
  // which compute sph/visc/atom reports: summed only in the evaluations of the steps
  // such a compute is scheduled to run on (as LAMMPS tallies per-atom energies only on
  // the steps a compute asks for them); null where this step's evaluation did not sum it.
  virtual const double *viscous_pressure();

 protected:
  GRANSPH::PairSettings config;    // parsed from the defaults by each pair_style command
  bool warned_far_from_origin;       // of single-precision positions, once
  FixSPHIntegrate *integrator;
  const FixSPHNormals *normals_fix;    // the dummies' own normals, or nullptr (init_style)

  // what the neighbour sums read besides the particles in this evaluation (`limited`:
  // with walls of a friction of their own)
  GRANSPH::SumOptions sum_options(bool limited) const;
  GRANSPH::Viscosity viscosity() const;
  double pruned_cutsq() const;
  // the rows are made anew at a run's setup, after a list build and for other atoms
  // (nall); else when an atom has moved farther than sqrt(prune_renewal_sq()) since
  bool rows_outdated(int nall) const;
  double prune_renewal_sq() const;
  void pruned_anew(int nall);    // counted in pvector[0], which compute pair reports
  int pruned_nall;    // the atoms, owned and ghost, of the last pruning (-1: none)
  // the positions of that pruning: floats from pruned_origin (GRANSPH::PrunedPositions)
  double pruned_origin[3];

  // The passes of an evaluation over p, the particles as the twin's accessor reads them,
  // in the one order of both twins (pair_sph_granular.cpp's header). Twin: this style or
  // its Kokkos twin, whose steps of the same names take the data where it lives.
  template <class Twin, class Particles>
  void evaluate_passes(Twin &twin, const Particles &p, bool limited);

  void allocate();
  void stop_if_coincident(int i);
  // at a run's setup, collective: the dummies' spacing against the grains' (on the host)
  void check_wall_spacing();
  void tally_virial(int i, const double *vir);
  void pack_wall_normals(double *out, int n) const;
  void find_wall_normals();
  int pack_wall_friction(double *out, const double *unit_normals, int n) const;
  void stop_if_unnormalled(int i);
  // at the setup of a run that continues the last: the dummies take the last step's force
  bool repeats_last_wall_forces() const;
  void forward_comm_friction_slide();
  // the slide values where the classic forward communication packs and unpacks them: on
  // the host (the Kokkos twin brings them there, and marks them changed there after)
  virtual double *slide_on_host() { return slide; }
  virtual void slide_changed_on_host() {}
  double single_precision_origin(double *origin) const;
  void warn_if_far_from_single_origin();
  // the viscous-pressure diagnostic: the computes that report it, and the step of the
  // last evaluation that summed it (-1: none) with the owned atoms it summed for
  std::vector<class Compute *> visc_computes;
  bigint viscous_pressure_step;
  int viscous_pressure_nlocal;
  bool sums_viscous_pressure() const;    // this evaluation sums it for them
  void summed_viscous_pressure();        // it did
  bool has_viscous_pressure() const;     // of this step's atoms

 private:
  int nmax;
  // what the pairs read, per atom, owned and ghost
  GRANSPH::PairParticle *particles;
  GRANSPH::PairParticleSingle *particles_single;    // their copy under precision mixed
  double *normals;    // with wall/gradient normal or wall/friction: pack_wall_normals()
  double *friction;   // with wall/friction: pack_wall_friction()
  double *slide;      // with wall/friction: 4 per atom, a grain's share and slide direction
  std::vector<double> visc_pressure;    // owned atoms: viscous_pressure()
  // with prune: how many neighbours at the front of each owned atom's row of the list
  // count, and of them the grains, first (GRANSPH::prune_row), found at the positions
  // pruned_x (owned and ghost, 3 each)
  std::vector<int> pruned_count, pruned_grains;
  std::vector<float> pruned_x;

  void grow(int n);
  void pack_particles(int from, int to);
  const GRANSPH::PairParticleSingle *pack_particles_single(int n);
  template <class Particles> void check_no_coincident(const Particles &p);

  template <class Particles> void walls(const Particles &p, bool stress, bool forces);
  template <class Particles> void grains(const Particles &p);
  template <class Particles> Particles pruned(const Particles &p, int nall);
  template <class Particles> void viscous_pressures(const Particles &p);
};

template <class Twin, class Particles>
void PairSPHGranular::evaluate_passes(Twin &twin, const Particles &p, bool limited)
{
  FixSPHIntegrate &fix = *integrator;
  const int nall = atom->nlocal + atom->nghost;
  if (update->setupflag) {
    twin.check_no_coincident(p);
    if (fix.wallbit) twin.check_wall_spacing();
  }
  if (fix.wallbit) {
    twin.walls(p, true, !limited);
    fix.forward_comm_state();    // the ghosts get the dummies' new stress
    twin.pack_particles(atom->nlocal, nall);
  }
  if (config.mixed_precision) {
    if (update->setupflag) warn_if_far_from_single_origin();
    twin.grains(p.in_single(twin.pack_particles_single(nall)));
  } else
    twin.grains(p);
  if (limited) {
    forward_comm_friction_slide();
    twin.walls(p, false, true);
  }
}

}    // namespace LAMMPS_NS

#endif
