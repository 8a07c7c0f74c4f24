/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: the granular SPH integrator with a constitutive model: the
   predictor-corrector of gransph_integrator.h on the host, per particle of the
   fix group. Model is one of the value types of gransph_stress_model.h.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_MODEL_H
#define LMP_FIX_SPH_MODEL_H

#include "fix_sph_integrate.h"
#include "force.h"
#include "gransph_integrator.h"
#include "update.h"

#include <cstring>

namespace LAMMPS_NS {

template <class Model> class FixSPHModel : public FixSPHIntegrate {
 public:
  FixSPHModel(class LAMMPS *lmp, int narg, char **arg) :
      FixSPHIntegrate(lmp, narg, arg), model(Model::from(material))
  {
  }

  void initial_integrate(int) override { step(PREDICT); }
  void final_integrate() override
  {
    step(CORRECT);
    check_finite();
  }

  double mobilised_ratio(const GRANSPH::Sym3 &sigma) const override
  {
    return model.mobilised_ratio(sigma);
  }

  const Model model;

 protected:
  enum Stage { PREDICT, CORRECT };

 private:
  void step(Stage stage)
  {
    double **x = atom->x, **v = atom->v, **f = atom->f;
    const double *rmass = atom->rmass, *mass = atom->mass;
    const int *type = atom->type, *mask = atom->mask;
    const double dt = update->dt;
    for (int i = 0; i < atom->nlocal; ++i) {
      if (!(mask[i] & groupbit)) continue;
      const double ftm = force->ftm2v / (rmass ? rmass[i] : mass[type[i]]);
      GRANSPH::ParticleState p{{x[i][0], x[i][1], x[i][2]}, {v[i][0], v[i][1], v[i][2]},
                               state[i][RHO], GRANSPH::Sym3::load(&state[i][SIGMA])};
      GRANSPH::StepStart s{{start[i][V_START], start[i][V_START + 1], start[i][V_START + 2]},
                           start[i][RHO_START], GRANSPH::Sym3::load(&start[i][SIGMA_START])};
      // the predictor takes the acceleration of the last step's mid-point, which the
      // corrector kept; without a step, that of the setup evaluation
      const bool stored = stage == PREDICT && start[i][STEPPED] != 0.0;
      GRANSPH::StepRates r = rates_at(i, 0);
      if (!stored)
        for (int a = 0; a < 3; ++a) r.acc[a] = ftm * f[i][a];
      GRANSPH::Regime regime;
      if (stage == PREDICT) {
        if (predictor_extrapolated) {    // from the last two mid-points, which PREV then holds
          if (start[i][STEPPED] >= 2.0)
            r = GRANSPH::extrapolated(r, rates_at(i, PREV), rates[i][RATES_DT],
                                      rates[i][PREV + RATES_DT]);
          memcpy(&rates[i][PREV], rates[i], PREV * sizeof(double));
        }
        GRANSPH::predict(model, p, s, r, dt, regime);
        for (int a = 0; a < 3; ++a) start[i][V_START + a] = s.v[a];
        start[i][RHO_START] = s.rho;
        s.sigma.store(&start[i][SIGMA_START]);
      } else {
        GRANSPH::correct(model, p, s, r, dt, regime);
        for (int a = 0; a < 3; ++a) rates[i][ACC + a] = r.acc[a];
        if (predictor_extrapolated) rates[i][RATES_DT] = dt;
        start[i][STEPPED] = fmin(start[i][STEPPED] + 1.0, 2.0);
      }
      for (int a = 0; a < 3; ++a) {
        x[i][a] = p.x[a];
        v[i][a] = p.v[a];
      }
      state[i][RHO] = p.rho;
      p.sigma.store(&state[i][SIGMA]);
      state[i][REGIME] = regime;
    }
  }

  // the rates in the columns from `at` of atom i's row (0: the last evaluation's)
  GRANSPH::StepRates rates_at(int i, int at) const
  {
    const double *r = &rates[i][at];
    return {{r[ACC], r[ACC + 1], r[ACC + 2]}, r[DRHO], GRANSPH::Sym3::load(&r[STRAIN]),
            GRANSPH::Spin3::load(&r[SPIN])};
  }
};

}    // namespace LAMMPS_NS

#endif
