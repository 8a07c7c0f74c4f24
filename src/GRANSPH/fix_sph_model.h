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
#include "gransph_simd.h"
#include "neighbor.h"
#include "update.h"

#include <type_traits>
#include <vector>

namespace LAMMPS_NS {

// Whether the host's step loop runs vectorised with model (variant) M: it pays where the
// model's update costs more than a lane's gathers and scatters of the grain's values
// (bench/README.md, fifth round)
template <class M> struct VectorisedStep {
  static constexpr bool value = true;
};

template <class Model> class FixSPHModel : public FixSPHIntegrate {
 public:
  FixSPHModel(class LAMMPS *lmp, int narg, char **arg) :
      FixSPHIntegrate(lmp, narg, arg), model(Model::from(material))
  {
  }

  void setup(int vflag) override
  {
    FixSPHIntegrate::setup(vflag);
    grains_listed = false;    // atoms, groups and masses may have changed since the last run
  }
  void initial_integrate(int) override { step(PREDICT); }
  void final_integrate() override
  {
    if (step(CORRECT)) check_finite();    // which atom, in the error message
  }

  double mobilised_ratio(const GRANSPH::Sym3 &sigma) const override
  {
    return model.mobilised_ratio(sigma);
  }
  double slide_friction() const override { return model.slide_friction(); }

  const Model model;

 protected:
  enum Stage { PREDICT, CORRECT };

  // What the grains' step reads and writes: each per-atom array as its rows from the
  // first (LAMMPS' x, v, f; state, rates, start), and the grains' indices and masses.
  struct GrainArrays {
    double *x, *v;
    const double *f;
    double *state, *rates, *start;
    int nrates, n;
    const int *index;
    const double *mass;
    double dt, ftm2v;
  };

  // Every grain's predictor or corrector step, with x, v, f where this rank's atoms have
  // them: chunks(advance) runs advance(begin, end) over [0, advance.a.n) of the grains,
  // at once (the plain fix) or in parallel chunks (its Kokkos twin on the host), and
  // returns the sum of what advance returns: the corrector's count of grains with a bad
  // new state (GRANSPH::bad_state).
  template <class Chunks> int step_grains(Stage stage, double **x, double **v, double **f,
                                          Chunks chunks)
  {
    // within a run, atoms are exchanged, sorted, created and deleted only when a step
    // reneighbours, between its predictor and its corrector
    if (!grains_listed || (stage == CORRECT && neighbor->ago == 0)) list_grains();
    if (grains.empty()) return 0;
    const GrainArrays a{x[0],    v[0],          f[0], state[0],          rates[0],
                        start[0], nrates,       (int) grains.size(), grains.data(),
                        grain_mass.data(), update->dt, force->ftm2v};
    // the model's variant for this run, so that the loop has no branch on it
    int bad = 0;
    with_run_variant(model, [&](const auto &m) {    // found by ADL: the model's own
      using M = typename std::decay<decltype(m)>::type;
      if (stage == PREDICT)
        bad = predictor_extrapolated ? chunks(Advance<PREDICT, true, M>{m, a})
                                     : chunks(Advance<PREDICT, false, M>{m, a});
      else
        bad = predictor_extrapolated ? chunks(Advance<CORRECT, true, M>{m, a})
                                     : chunks(Advance<CORRECT, false, M>{m, a});
    });
    return bad;
  }

 private:
  // the owned atoms of the group and their masses, for the step's loop
  std::vector<int> grains;
  std::vector<double> grain_mass;
  bool grains_listed = false;

  void list_grains()
  {
    grains_listed = true;
    grains.clear();
    grain_mass.clear();
    for (int i = 0; i < atom->nlocal; ++i)
      if (atom->mask[i] & groupbit) {
        grains.push_back(i);
        grain_mass.push_back(atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]]);
      }
  }

  // the number of grains with a bad new state (the corrector)
  int step(Stage stage)
  {
    return step_grains(stage, atom->x, atom->v, atom->f,
                       [](const auto &advance) { return advance(0, advance.a.n); });
  }

  // The step of the grains [begin, end), in a loop that the compiler can vectorise
  // (VectorisedStep): each per-atom array read and written at a fixed stride from its
  // first row, the choices of a lane as selections. Returns how many of them the
  // corrector left with a bad state (the run stops), 0 for the predictor.
  template <Stage STAGE, bool EXTRAPOLATE, class M> struct Advance {
    M m;
    GrainArrays a;

    int operator()(int begin, int end) const
    {
      using GRANSPH::Sym3;
      double *x = a.x, *v = a.v, *st = a.state, *ra = a.rates, *sa = a.start;
      const double *f = a.f, *mass = a.mass;
      const int *index = a.index, nr = a.nrates;
      const double dt = a.dt, ftm2v = a.ftm2v;
      int bad = 0;
      GRANSPH_SIMD_IF_SUM(VectorisedStep<M>::value, bad)
      for (int k = begin; k < end; ++k) {
        // grain i's values in each array, at a multiple of its row: what a gather can take
        const int i = index[k], ix = 3 * i, ist = NSTATE * i, ir = nr * i, is = NSTART * i;
        const double ftm = ftm2v / mass[k];
        GRANSPH::ParticleState p{{x[ix], x[ix + 1], x[ix + 2]}, {v[ix], v[ix + 1], v[ix + 2]},
                                 st[ist + RHO], Sym3::load(st, ist + SIGMA)};
        GRANSPH::StepStart s{{sa[is + V_START], sa[is + V_START + 1], sa[is + V_START + 2]},
                             sa[is + RHO_START], Sym3::load(sa, is + SIGMA_START)};
        // the predictor takes the acceleration of the last step's mid-point, which the
        // corrector kept, or a grain without a step that of the setup evaluation; the
        // corrector that of this evaluation
        GRANSPH::StepRates r = rates_of(ra, ir);
        const bool unstepped = STAGE == PREDICT && sa[is + STEPPED] == 0.0;
        if (STAGE == CORRECT || unstepped)    // a selection in the vectorised predictor
          for (int c = 0; c < 3; ++c) r.acc[c] = ftm * f[ix + c];
        GRANSPH::Regime regime;
        if (STAGE == PREDICT) {
          if (EXTRAPOLATE) {    // from the last two mid-points, which PREV then holds
            const GRANSPH::StepRates e = GRANSPH::extrapolated(
                r, rates_of(ra, ir + PREV), ra[ir + RATES_DT], ra[ir + PREV + RATES_DT]);
            r = GRANSPH::select(sa[is + STEPPED] >= 2.0, e, r);
            for (int c = 0; c < PREV; ++c) ra[ir + PREV + c] = ra[ir + c];
          }
          GRANSPH::predict(m, p, s, r, dt, regime);
          for (int c = 0; c < 3; ++c) sa[is + V_START + c] = s.v[c];
          sa[is + RHO_START] = s.rho;
          s.sigma.store(sa, is + SIGMA_START);
        } else {
          GRANSPH::correct(m, p, s, r, dt, regime);
          for (int c = 0; c < 3; ++c) ra[ir + ACC + c] = r.acc[c];
          if (EXTRAPOLATE) ra[ir + RATES_DT] = dt;
          const double stepped = sa[is + STEPPED] + 1.0;
          sa[is + STEPPED] = stepped < 2.0 ? stepped : 2.0;
        }
        for (int c = 0; c < 3; ++c) {
          x[ix + c] = p.x[c];
          v[ix + c] = p.v[c];
        }
        st[ist + RHO] = p.rho;
        p.sigma.store(st, ist + SIGMA);
        st[ist + REGIME] = regime;
        if (STAGE == CORRECT) bad += GRANSPH::bad_state(p);
      }
      return bad;
    }
  };

  // the rates in the columns from `at` of the array of all rows
  static GRANSPH::StepRates rates_of(const double *r, int at)
  {
    return {{r[at + ACC], r[at + ACC + 1], r[at + ACC + 2]}, r[at + DRHO],
            GRANSPH::Sym3::load(r, at + STRAIN), GRANSPH::Spin3::load(r, at + SPIN)};
  }
};

}    // namespace LAMMPS_NS

#endif
