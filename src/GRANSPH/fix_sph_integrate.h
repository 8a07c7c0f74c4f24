/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: shared base of the granular SPH integrators.

   Owns the per-atom SPH state (density and Cauchy stress), the rates the pair
   style writes (density rate, strain rate, spin) and the predictor copies, and
   sets the CFL timestep (eq. 19). FixSPHModel<Model> (fix_sph_model.h) adds the
   predictor-corrector with a constitutive model.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_INTEGRATE_H
#define LMP_FIX_SPH_INTEGRATE_H

#include "atom.h"
#include "fix.h"
#include "gransph_material.h"
#include "gransph_tensor.h"

namespace LAMMPS_NS {

class FixSPHIntegrate : public Fix {
 public:
  // Columns of the per-atom arrays. STATE is restarted and is the fix's per-atom
  // output (f_ID[1] = rho, f_ID[2..7] = stress, f_ID[8] = GRANSPH::Regime,
  // f_ID[9] = the pressure the artificial viscosity adds, from the pair style); its
  // first NCOMM columns are forward-communicated to ghosts.
  enum { RHO = 0, SIGMA = 1, REGIME = 7, VISC_PRESSURE = 8, NSTATE = 9, NCOMM = 7 };
  enum { DRHO = 0, STRAIN = 1, SPIN = 7, NRATES = 10 };
  enum { V_START = 0, RHO_START = 3, SIGMA_START = 4, WALL_V = 10, NSTART = 13 };

  FixSPHIntegrate(class LAMMPS *, int, char **);
  ~FixSPHIntegrate() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  void end_of_step() override;

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
  double **rates;    // drho/dt, strain rate (6), spin (xy xz yz)
  double **start;    // v, rho, sigma at the start of the step; last wall velocity
  int wallbit;       // group bit of the dummy-wall particles (0: no walls)
  GranSPHMaterial material;

  virtual void forward_comm_state();    // ghosts get fresh rho and sigma
  // What compute sph/stress/atom reads: the share of the model's strength that the
  // stress sigma uses (1 at yield), and state up to date on the host.
  virtual double mobilised_ratio(const GRANSPH::Sym3 &sigma) const = 0;
  virtual void sync_state_host() {}    // the plain fix keeps it there
  void gravity_vector(double *g) const;  // acceleration of the fix gravity on the grains

 protected:
  double rho_init;      // initial density of all particles (material rho0 by default)
  double cfl;           // CFL factor of eq. 19; 0 keeps the LAMMPS timestep
  int geostatic_flag;   // initialise a geostatic stress below surface_height
  double surface_height;
  int restored;         // state came from a restart file

  double smoothing_length() const;
  void check_finite() const;
  virtual void reset_cfl_timestep();
  void set_timestep(double dt);

 private:
  void init_geostatic_stress();
};

}    // namespace LAMMPS_NS

#endif
