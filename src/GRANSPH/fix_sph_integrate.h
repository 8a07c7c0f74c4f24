/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: shared base of the granular SPH integrators.

   Owns the per-atom SPH state (density and Cauchy stress), the rates the pair
   style writes (density rate, strain rate, spin) and the predictor copies, and
   sets the CFL timestep (eq. 19). FixSPHModel<Model> (fix_sph_model.h) adds the
   predictor-corrector with a constitutive model.

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
#include "gransph_tensor.h"

#include <vector>

namespace LAMMPS_NS {

class FixSPHIntegrate : public Fix {
 public:
  // Columns of the per-atom arrays. STATE is restarted and is the fix's per-atom
  // output (f_ID[1] = rho, f_ID[2..7] = stress, f_ID[8] = GRANSPH::Regime); its
  // first NCOMM columns are forward-communicated to ghosts. Restart files written
  // before December 2026 carry one more state column (STATE_WITH_VISC: the viscous
  // pressure, now compute sph/visc/atom's).
  enum { RHO = 0, SIGMA = 1, REGIME = 7, NSTATE = 8, STATE_WITH_VISC = 9, NCOMM = 7 };
  // RATES: what the pair style writes, and the acceleration of the same evaluation
  // that the next predictor uses; from RATES_DT on, only with predictor extrapolated
  // (which alone allocates those columns, see nrates, so that the default keeps the
  // layout and restart files of before): the step whose mid-point they are, and from
  // PREV the same for the step before. START: the start of the step for the
  // corrector, the wall velocity of the last evaluation, and STEPPED: the number of
  // steps, up to 2, whose evaluation the atom's rates (grains) or wall velocity (dummy
  // particles) come from; WALL_F: the grains' force on a dummy particle in the last
  // evaluation (the pair style's part of its f), which the setup of a run that
  // continues the last repeats.
  enum { DRHO = 0, STRAIN = 1, SPIN = 7, ACC = 10, RATES_DT = 13, PREV = 14, NRATES = 28 };
  enum {
    V_START = 0,
    RHO_START = 3,
    SIGMA_START = 4,
    WALL_V = 10,
    STEPPED = 13,
    WALL_F = 14,
    NSTART = 17
  };

  FixSPHIntegrate(class LAMMPS *, int, char **);
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

  // What sph/granular reads and writes.
  double **state;    // rho, sigma (xx yy zz xy xz yz), regime
  double **rates;    // drho/dt, strain rate (6), spin (xy xz yz), acceleration
  double **start;    // v, rho, sigma at the start of the step; last wall velocity; stepped;
                     // last wall force
  int wallbit;       // group bit of the dummy-wall particles (0: no walls)
  GranSPHMaterial material;

  virtual void forward_comm_state();    // ghosts get fresh rho and sigma
  // What compute sph/stress/atom reads: the share of the model's strength that the
  // stress sigma uses (1 at yield), and state up to date on the host.
  virtual double mobilised_ratio(const GRANSPH::Sym3 &sigma) const = 0;
  // the friction coefficient at which the model's layers slide (pair_style sph/granular
  // wall/friction group material)
  virtual double slide_friction() const = 0;
  virtual void sync_state_host() {}    // the plain fix keeps it there
  void gravity_vector(double *g) const;  // acceleration of the fix gravity on the grains
  // At a run's setup: whether the run continues the last step's (its first step takes
  // the rates, and the dummies the forces, of that step rather than of the setup
  // evaluation)
  bool continues_last_step() const { return fresh_start == nullptr; }

 protected:
  double rho_init;      // initial density of all particles (material rho0 by default)
  double cfl;           // CFL factor of eq. 19; 0 keeps the LAMMPS timestep
  int cfl_sound_reference;    // eq. 19's sound speed at rho_init, not at each grain's density
  int predictor_extrapolated;    // the predictor's rates extrapolated to the step's start
  int nrates;           // columns of `rates`: RATES_DT, or NRATES with the step before's
  int row_size() const { return NSTATE + nrates + NSTART; }    // all per-atom values
  int geostatic_flag;   // initialise a geostatic stress below surface_height
  double surface_height;
  int restored;         // state came from a restart file

  double smoothing_length() const;
  void check_finite() const;
  void check_plane() const;
  virtual void reset_cfl_timestep();
  void set_timestep(double dt);

 private:
  // what the last step ran with: a run continues with its rates only if unchanged
  double last_dt;
  std::vector<double> last_pair_settings;    // empty: no run yet
  const char *fresh_start;                   // why this run cannot continue, or nullptr
  std::vector<double> saved;                 // the arrays across the setup evaluation

  void init_geostatic_stress();
  const char *why_not_continue() const;
  void forget_steps();
  void save_step();
  void restore_step();
};

}    // namespace LAMMPS_NS

#endif
