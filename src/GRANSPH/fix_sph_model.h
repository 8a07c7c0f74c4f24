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

#include <vector>

namespace LAMMPS_NS {

// Whether the host's step loop runs vectorised with model (variant) M: it pays where the
// model's update costs more than a lane's gathers and scatters of the grain's values
// (bench/README.md, fifth round)
template <class M> constexpr bool vectorised_step = true;

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
  // the owned atoms of the group and their masses, for the step's loop
  std::vector<int> grains;
  std::vector<double> grain_mass;

  void step(Stage stage)
  {
    grains.clear();
    grain_mass.clear();
    for (int i = 0; i < atom->nlocal; ++i)
      if (atom->mask[i] & groupbit) {
        grains.push_back(i);
        grain_mass.push_back(atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]]);
      }
    if (grains.empty()) return;
    // a grain without a step predicts with the acceleration of the setup evaluation
    if (stage == PREDICT)
      for (size_t k = 0; k < grains.size(); ++k) {
        const int i = grains[k];
        if (start[i][STEPPED] != 0.0) continue;
        const double ftm = force->ftm2v / grain_mass[k];
        for (int a = 0; a < 3; ++a) rates[i][ACC + a] = ftm * atom->f[i][a];
      }
    // the model's variant for this run, so that the loop has no branch on it
    with_run_variant(model, [&](const auto &m) {    // found by ADL: the model's own
      if (stage == PREDICT)
        predictor_extrapolated ? advance<PREDICT, true>(m) : advance<PREDICT, false>(m);
      else
        predictor_extrapolated ? advance<CORRECT, true>(m) : advance<CORRECT, false>(m);
    });
  }

  // Every grain's predictor or corrector step, in a loop that the compiler can vectorise
  // (vectorised_step): each per-atom array read and written at a fixed stride from its
  // first row, the choices of a lane as selections.
  template <Stage STAGE, bool EXTRAPOLATE, class M> void advance(const M &m)
  {
    using GRANSPH::Sym3;
    double *x = atom->x[0], *v = atom->v[0];
    const double *f = atom->f[0], *mass = grain_mass.data();
    const int *index = grains.data();
    double *st = state[0], *ra = rates[0], *sa = start[0];
    const int n = grains.size(), nr = nrates;
    const double dt = update->dt, ftm2v = force->ftm2v;
#if !defined(__CUDACC__) && !defined(__HIPCC__)
#pragma omp simd if(simd : vectorised_step<M>)
#endif
    for (int k = 0; k < n; ++k) {
      // grain i's values in each array, at a multiple of its row: what a gather can take
      const int i = index[k], ix = 3 * i, ist = NSTATE * i, ir = nr * i, is = NSTART * i;
      const double ftm = ftm2v / mass[k];
      GRANSPH::ParticleState p{{x[ix], x[ix + 1], x[ix + 2]}, {v[ix], v[ix + 1], v[ix + 2]},
                               st[ist + RHO], Sym3::load(st, ist + SIGMA)};
      GRANSPH::StepStart s{{sa[is + V_START], sa[is + V_START + 1], sa[is + V_START + 2]},
                           sa[is + RHO_START], Sym3::load(sa, is + SIGMA_START)};
      // the predictor takes the acceleration of the last step's mid-point, which the
      // corrector kept (or step() put there), the corrector that of this evaluation
      GRANSPH::StepRates r = rates_of(ra, ir);
      if (STAGE == CORRECT)
        for (int a = 0; a < 3; ++a) r.acc[a] = ftm * f[ix + a];
      GRANSPH::Regime regime;
      if (STAGE == PREDICT) {
        if (EXTRAPOLATE) {    // from the last two mid-points, which PREV then holds
          const GRANSPH::StepRates e = GRANSPH::extrapolated(
              r, rates_of(ra, ir + PREV), ra[ir + RATES_DT], ra[ir + PREV + RATES_DT]);
          r = GRANSPH::select(sa[is + STEPPED] >= 2.0, e, r);
          for (int c = 0; c < PREV; ++c) ra[ir + PREV + c] = ra[ir + c];
        }
        GRANSPH::predict(m, p, s, r, dt, regime);
        for (int a = 0; a < 3; ++a) sa[is + V_START + a] = s.v[a];
        sa[is + RHO_START] = s.rho;
        s.sigma.store(sa, is + SIGMA_START);
      } else {
        GRANSPH::correct(m, p, s, r, dt, regime);
        for (int a = 0; a < 3; ++a) ra[ir + ACC + a] = r.acc[a];
        if (EXTRAPOLATE) ra[ir + RATES_DT] = dt;
        const double stepped = sa[is + STEPPED] + 1.0;
        sa[is + STEPPED] = stepped < 2.0 ? stepped : 2.0;
      }
      for (int a = 0; a < 3; ++a) {
        x[ix + a] = p.x[a];
        v[ix + a] = p.v[a];
      }
      st[ist + RHO] = p.rho;
      p.sigma.store(st, ist + SIGMA);
      st[ist + REGIME] = regime;
    }
  }

  // the rates in the columns from `at` of the array of all rows
  static GRANSPH::StepRates rates_of(const double *r, int at)
  {
    return {{r[at + ACC], r[at + ACC + 1], r[at + ACC + 2]}, r[at + DRHO],
            GRANSPH::Sym3::load(r, at + STRAIN), GRANSPH::Spin3::load(r, at + SPIN)};
  }
};

}    // namespace LAMMPS_NS

#endif
