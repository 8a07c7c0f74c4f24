/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
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
  FixSPHModel(class LAMMPS *lmp, int narg, char **arg) : FixSPHIntegrate(lmp, narg, arg)
  {
    for (int k = 0; k < materials.n; ++k) {
      models.push_back(Model::from(material_records[k]));
      materials.slide_friction[k] = models[k].slide_friction();
    }
  }

  void setup(int vflag) override
  {
    FixSPHIntegrate::setup(vflag);
    grains_listed = false;    // atoms, groups and masses may have changed since the last run
  }
  void initial_integrate(int) override { step(GRANSPH::PREDICT); }
  void final_integrate() override
  {
    if (step(GRANSPH::CORRECT)) check_finite();    // which atom, in the error message
  }

  double mobilised_ratio(int k, const GRANSPH::Sym3 &sigma) const override
  {
    return models[k].mobilised_ratio(sigma);
  }

  std::vector<Model> models;    // of each material (FixSPHIntegrate::materials)

 protected:
  using Stage = GRANSPH::Stage;

  // The rows the grains' step reads and writes (GRANSPH::step_grain): LAMMPS' x, v, f and
  // the integrator's arrays, over the grains' indices; a grain's mass its own (rmass) or
  // its type's
  struct GrainRows {
    GRANSPH::HostRows<3> x, v;
    GRANSPH::HostRows<3, const double> f;
    GRANSPH::HostRows<NSTATE> state;
    GRANSPH::HostRowsOf rates;
    GRANSPH::HostRows<NSTART> start;
    const int *index;
    const double *rmass, *type_mass;
    const int *type;
    KOKKOS_INLINE_FUNCTION int atom(int k) const { return index[k]; }
    KOKKOS_INLINE_FUNCTION double mass(int k) const
    {
      return rmass ? rmass[index[k]] : type_mass[type[index[k]]];
    }
  };

  // The step of the grains [begin, end) of `rows`, in a loop that the compiler can
  // vectorise (VectorisedStep). Returns how many of them the corrector left with a bad
  // state (the run stops), 0 for the predictor.
  template <Stage STAGE, bool EXTRAPOLATE, class M> struct Advance {
    M m;
    GrainRows rows;
    int n;
    double dt, ftm2v;

    int operator()(int begin, int end) const
    {
      // local copies: the loop then keeps the arrays' bases and strides in registers
      const GrainRows r = rows;
      const double step = dt, to_acceleration = ftm2v;
      int bad = 0;
      GRANSPH_SIMD_IF_SUM(VectorisedStep<M>::value, bad)
      for (int k = begin; k < end; ++k)
        bad += GRANSPH::step_grain<STAGE, EXTRAPOLATE>(m, r, k, step, to_acceleration);
      return bad;
    }
  };

  // Every grain's predictor or corrector step, with x, v, f where this rank's atoms have
  // them, material by material: chunks(advance) runs advance(begin, end) over [0,
  // advance.n) of a material's grains, at once (the plain fix) or in parallel chunks (its
  // Kokkos twin on the host), and returns the sum of what advance returns: the
  // corrector's count of grains with a bad new state (GRANSPH::bad_state).
  template <class Chunks> int step_grains(Stage stage, double **x, double **v, double **f,
                                          Chunks chunks)
  {
    // within a run, atoms are exchanged, sorted, created and deleted only when a step
    // reneighbours, between its predictor and its corrector
    if (!grains_listed || (stage == GRANSPH::CORRECT && neighbor->ago == 0)) list_grains();
    const double dt = update->dt, ftm2v = force->ftm2v;
    int bad = 0;
    for (int k = 0; k < materials.n; ++k) {
      const int n = first_grain[k + 1] - first_grain[k];
      if (n == 0) continue;
      const GrainRows rows{{x[0]},
                           {v[0]},
                           {f[0]},
                           {state[0]},
                           {rates, nrates},
                           {start},
                           grains.data() + first_grain[k],
                           atom->rmass,
                           atom->mass,
                           atom->type};
      // the model's variant for this run, so that the loop has no branch on it
      with_run_variant(models[k], [&](const auto &m) {    // found by ADL: the model's own
        using M = typename std::decay<decltype(m)>::type;
        using GRANSPH::CORRECT;
        using GRANSPH::PREDICT;
        if (stage == PREDICT)
          bad += predictor_extrapolated ? chunks(Advance<PREDICT, true, M>{m, rows, n, dt, ftm2v})
                                        : chunks(Advance<PREDICT, false, M>{m, rows, n, dt, ftm2v});
        else
          bad += predictor_extrapolated ? chunks(Advance<CORRECT, true, M>{m, rows, n, dt, ftm2v})
                                        : chunks(Advance<CORRECT, false, M>{m, rows, n, dt, ftm2v});
      });
    }
    return bad;
  }

  // the step of every grain, at once (the Kokkos twin: where its atoms are); the number of
  // grains with a bad new state (the corrector)
  virtual int step(Stage stage)
  {
    return step_grains(stage, atom->x, atom->v, atom->f,
                       [](const auto &advance) { return advance(0, advance.n); });
  }

 private:
  // the owned atoms of the group, for the step's loop: those of material k from
  // first_grain[k] to first_grain[k + 1]
  std::vector<int> grains;
  std::vector<int> first_grain;
  bool grains_listed = false;

  void list_grains()
  {
    grains_listed = true;
    const int *mask = atom->mask;
    int n = 0;
    for (int i = 0; i < atom->nlocal; ++i) n += (mask[i] & groupbit) != 0;
    grains.clear();
    grains.reserve(n);    // their number (growing by doubling would hold up to twice it)
    first_grain.assign(1, 0);
    for (int k = 0; k < materials.n; ++k) {
      for (int i = 0; i < atom->nlocal; ++i)
        if ((mask[i] & groupbit) && materials.holds(k, mask[i])) grains.push_back(i);
      first_grain.push_back(grains.size());
    }
  }
};

}    // namespace LAMMPS_NS

#endif
