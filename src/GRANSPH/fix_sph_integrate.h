/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: shared base of the granular SPH integrators.

   Owns the per-atom SPH state (density and Cauchy stress), the rates the pair
   style writes (density rate, strain rate, spin) and the predictor copies, and
   sets the CFL timestep (eq. 19). FixSPHModel<Model> (fix_sph_model.h) adds the
   predictor-corrector with a constitutive model. The other styles find it with
   find() and reach its state by name (host_state(); SPHStateKokkos::state_on on
   a device).

   A run continues the previous one exactly: the predictor of a step uses the
   rates and acceleration of the previous step's mid-point, so they, the wall
   velocity history and the timestep are kept across run commands (the setup
   force evaluation must not replace them) and in restart files.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_INTEGRATE_H
#define LMP_FIX_SPH_INTEGRATE_H

#include "atom.h"
#include "fix.h"
#include "gransph_material.h"
#include "gransph_materials.h"
#include "gransph_pair_settings.h"
#include "gransph_state.h"
#include "gransph_tensor.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

// The owner of the per-atom GRANSPH state: its columns are GRANSPH::StateLayout, its
// contract with the other styles GRANSPH::StateAccess (gransph_state.h)
class FixSPHIntegrate : public Fix, public GRANSPH::StateLayout {
 public:
  FixSPHIntegrate(class LAMMPS *, int, char **);
  // The GRANSPH integrator fix: an error that names `who` (e.g. "Compute sph/runout") if
  // there is none or more than one
  static FixSPHIntegrate &find(class LAMMPS *lmp, const char *who);
  ~FixSPHIntegrate() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  void end_of_step() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

  // The per-atom state by name, on the host (the Kokkos twin's host copies: sync them
  // first), for the pair style, the computes and the other fixes
  using HostState = GRANSPH::StateAccess<GRANSPH::HostRows<NSTATE>, GRANSPH::HostRowsOf,
                                         GRANSPH::HostRows<NSTART>>;
  HostState host_state() const
  {
    return {{state ? state[0] : nullptr}, {rates, nrates}, {start}};
  }
  int wallbit;       // group bit of the dummy-wall particles (0: no walls)
  // The grains' materials: the fix's own (index 0), then those of its keywords material
  // GROUP FILE NAME in order, each with the group (-1: the fix's own) whose grains it
  // claims; and their table, which the per-particle code reads (gransph_materials.h)
  std::vector<GranSPHMaterial> material_records;
  std::vector<int> material_groups;
  GRANSPH::MaterialTable materials;

  virtual void forward_comm_state();    // ghosts get fresh rho and sigma
  // What compute sph/stress/atom reads: the share of the strength of material k's model
  // that the stress sigma uses (1 at yield), and state up to date on the host.
  virtual double mobilised_ratio(int k, const GRANSPH::Sym3 &sigma) const = 0;
  void sync_state_host() { sync_host(STATE_ONLY); }
  void gravity_vector(double *g) const;  // acceleration of the fix gravity on the grains
  // At a run's setup: whether the run continues the last step's (its first step takes
  // the rates, and the dummies the forces, of that step rather than of the setup
  // evaluation)
  bool continues_last_step() const { return fresh_start == nullptr; }

 protected:
  double **state;    // rho, sigma (xx yy zz xy xz yz), regime; rows: the fix's output
  // nrates and NSTART values an atom, in one block each, without row pointers (8 bytes a
  // slot each): atom i's from rates_of(i), start_of(i)
  double *rates;     // drho/dt, strain rate (6), spin (xy xz yz); with predictor
                     // extrapolated also the acceleration, dt and the step before's
  double *start;     // stepped; a grain's v, rho, sigma at the start of the step (between
                     // steps: its last acceleration), or a dummy particle's last wall
                     // velocity and force
  double *rates_of(int i) const { return rates + (bigint) i * nrates; }
  double *start_of(int i) const { return start + (bigint) i * NSTART; }
  void check_row_offsets(int nmax) const;    // an error if nmax atoms' rows need more
  double cfl;           // CFL factor of eq. 19; 0 keeps the LAMMPS timestep
  int cfl_sound_reference;    // eq. 19's sound speed at rho_init, not at each grain's density
  int predictor_extrapolated;    // the predictor's rates extrapolated to the step's start
  int nrates;           // columns of `rates`: NEVALUATED_RATES, or NRATES (extrapolated)
  int row_size() const { return NSTATE + nrates + NSTART; }    // all per-atom values
  int geostatic_flag;   // initialise a geostatic stress below surface_height
  double surface_height;
  int restored;         // state came from a restart file

  // Where the host callbacks find the arrays: the Kokkos twin's DualViews are brought to
  // the host before a callback reads them (sync_host) and marked changed there after it
  // writes them (modified_host), all three or `state` alone; the plain fix keeps them there
  enum Arrays { ALL_ARRAYS, STATE_ONLY };
  virtual void sync_host(Arrays = ALL_ARRAYS) {}
  virtual void modified_host(Arrays = ALL_ARRAYS) {}

  double smoothing_length() const;
  void check_finite() const;
  void stop_if_atoms_lost() const;
  void check_plane() const;
  void reset_cfl_timestep();
  // eq. 19's maxima over this rank's grains into local: max |a|^2 (left negative without
  // grains) and, with cfl/sound local, from local[1] on minus the lowest density of the
  // grains of each material
  virtual void cfl_maxima(double *local);
  void set_timestep(double dt);

 private:
  // what the last step ran with: a run continues with its rates only if unchanged
  double last_dt;
  bool ran_with_pair_settings;                // false: no run yet
  GRANSPH::PairSettings last_pair_settings;
  const char *fresh_start;                   // why this run cannot continue, or nullptr
  // across the setup evaluation of a run that continues the last: what it overwrites
  // a dummy particle's: its stress (6), then its wall history from STEPPED
  static constexpr int KEPT_STEPPED = 6, KEPT_PER_ATOM = KEPT_STEPPED + NWALL_HISTORY;
  static_assert(KEPT_PER_ATOM >= NEVALUATED_RATES, "a grain's rates fit");
  std::vector<double> saved;

  void add_material(const std::string &group_name, const std::string &file,
                    const std::string &name, const std::string &own_file,
                    const std::string &units);
  void check_material_groups() const;
  void start_materials_at_their_density();
  void init_geostatic_stress();
  const char *why_not_continue() const;
  void forget_steps();
  void keep_evaluated(int i, double *kept, bool back);
  void save_step();
  void restore_step();
  // an atom's row of all per-atom values (row_size()), as exchange and restart carry it
  int pack_row(int i, double *buf) const;
  void read_rates_and_start(int i, const double *row, int nr, int nstart);
  void read_start_side_by_side(int i, const double *row);
  int unpack_row(int i, const double *buf);
};

}    // namespace LAMMPS_NS

#endif
