/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: one particle's predictor-corrector step (paper eqs. 11-17) and the
   CFL timestep (eq. 19), usable on host and device.

   A LAMMPS step evaluates the pair once, between the predictor
   (initial_integrate) and the corrector (final_integrate). The paper evaluates
   the rates twice per step, at t for the predictor and at t+dt/2 for the
   corrector. Here the predictor uses the rates of the previous step's mid-point
   evaluation, t-dt/2 (a run's first step: FixSPHIntegrate::setup).
   That changes the predicted mid-point state by O(dt^2), so the corrector, which
   integrates from t with the mid-point rates, stays second order at one rate
   evaluation per step.

   The stress takes the corrector's full step from t too, with the Jaumann
   rotation and plastic flow evaluated at the predicted stress. The paper's
   eq. 18 instead continues from the predicted stress with the mid-point rate,
   sigma_n + dt/2 (rate_n + rate_{n+1/2}), which saves storing sigma_n but is
   first order. unittest/physics/test_time_order.py shows the order.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_INTEGRATOR_H
#define LMP_GRANSPH_INTEGRATOR_H

#include "gransph_pair_terms.h"
#include "gransph_state.h"
#include "gransph_stress_model.h"

namespace GRANSPH {

// What the integrator advances for one granular particle.
struct ParticleState {
  double x[3], v[3];
  double rho;
  Sym3 sigma;
};

// The particle at the start of the step, kept for the corrector.
struct StepStart {
  double v[3];
  double rho;
  Sym3 sigma;
};

// The latest rates of a particle: acceleration, density rate, strain rate, spin.
struct StepRates {
  double acc[3];
  double drho;
  Sym3 d;
  Spin3 w;
};

// a if c, else b, by component (a lane's choice in a vectorised loop)
KOKKOS_INLINE_FUNCTION StepRates select(bool c, const StepRates &a, const StepRates &b)
{
  return {{c ? a.acc[0] : b.acc[0], c ? a.acc[1] : b.acc[1], c ? a.acc[2] : b.acc[2]},
          c ? a.drho : b.drho,
          select(c, a.d, b.d),
          {c ? a.w.xy : b.w.xy, c ? a.w.xz : b.w.xz, c ? a.w.yz : b.w.yz}};
}

// The predictor's rates extrapolated to the step's start (fix keyword predictor
// extrapolated): linearly from those of the last two mid-points, which lie dt_last / 2
// and dt_last / 2 + dt_before / 2 before it (Adams-Bashforth; 1.5 r_{n-1/2} - 0.5
// r_{n-3/2} at a fixed step). The last mid-point's rates alone (predictor midpoint, the
// default) amplify an undamped oscillation of angular frequency w by 4e-4 per step at
// w dt = 0.2 and 3% at 0.5; these damp it below w dt = 0.7 (validation/README.md).
KOKKOS_INLINE_FUNCTION StepRates extrapolated(const StepRates &last, const StepRates &before,
                                              double dt_last, double dt_before)
{
  const double k = dt_last / (dt_last + dt_before);
  StepRates r;
  for (int a = 0; a < 3; ++a) r.acc[a] = last.acc[a] + k * (last.acc[a] - before.acc[a]);
  r.drho = last.drho + k * (last.drho - before.drho);
  r.d = last.d + k * (last.d - before.d);
  r.w = {last.w.xy + k * (last.w.xy - before.w.xy), last.w.xz + k * (last.w.xz - before.w.xz),
         last.w.yz + k * (last.w.yz - before.w.yz)};
  return r;
}

// Predictor, eqs. 11-14: half a step with the latest rates.
template <class Model>
KOKKOS_INLINE_FUNCTION void predict(const Model &model, ParticleState &p, StepStart &start,
                                    const StepRates &r, double dt, Regime &regime)
{
  const double half = 0.5 * dt;
  for (int a = 0; a < 3; ++a) {
    start.v[a] = p.v[a];
    p.x[a] += half * p.v[a];
    p.v[a] += half * r.acc[a];
  }
  start.rho = p.rho;
  // by component: a copy of the whole struct kept GCC 12 from vectorising the host's loop
  start.sigma = {p.sigma.xx, p.sigma.yy, p.sigma.zz, p.sigma.xy, p.sigma.xz, p.sigma.yz};
  p.rho += half * r.drho;
  p.sigma = model.update(p.sigma, p.sigma, r.d, r.w, p.rho, half, regime);
}

// Corrector, eqs. 15-17 and the full stress step: from t with the mid-point rates.
template <class Model>
KOKKOS_INLINE_FUNCTION void correct(const Model &model, ParticleState &p, const StepStart &start,
                                    const StepRates &r, double dt, Regime &regime)
{
  for (int a = 0; a < 3; ++a) {
    // x_{n+1} = x_n + dt v_{n+1/2}, with x_n = x_{n+1/2} - dt/2 v_n
    p.x[a] += dt * (p.v[a] - 0.5 * start.v[a]);
    p.v[a] = start.v[a] + dt * r.acc[a];
  }
  p.rho = start.rho + dt * r.drho;
  p.sigma = model.update(start.sigma, p.sigma, r.d, r.w, p.rho, dt, regime);
}

// Whether a particle's state must stop the run: the sum of its position, velocity,
// density and stress is finite only if they all are (sum - sum is 0 for finite sums
// only); the density must be positive. Without a branch (|): a vectorised loop counts them.
KOKKOS_INLINE_FUNCTION bool bad_state(const ParticleState &p)
{
  const double sum = p.x[0] + p.x[1] + p.x[2] + p.v[0] + p.v[1] + p.v[2] + p.rho + p.sigma.xx +
      p.sigma.yy + p.sigma.zz + p.sigma.xy + p.sigma.xz + p.sigma.yz;
  return !(sum - sum == 0.0) | !(p.rho > 0.0);
}

/* ----------------------------------------------------------------------
   One grain's predictor or corrector step, written once for the plain
   integrators (a vectorised loop over the grains) and their Kokkos twins (a
   kernel over the atoms), over `rows`, an accessor of the per-atom rows with

     int    atom(int k)        the atom index of the loop's k-th grain
     double mass(int k)        its mass
     x, v, f                   LAMMPS' positions, velocities, forces, and
     state, rates, start       the integrator's arrays (StateLayout's columns),
                               each callable as (i, c) for atom i's column c

   `ftm2v` converts force / mass to an acceleration. Returns whether the corrector
   left the grain with a bad state (bad_state: the run stops), 0 for the predictor.
   Without a branch on the grain's values: a lane's choices are selections.
------------------------------------------------------------------------- */

enum Stage { PREDICT, CORRECT };

// the rates of an evaluation in the columns from `at` of atom i's row of rates, with the
// acceleration acc
template <class Column>
KOKKOS_INLINE_FUNCTION StepRates rates_at(const Column &r, int i, int at, const double *acc)
{
  using L = StateLayout;
  return {{acc[0], acc[1], acc[2]},
          r(i, at + L::DRHO),
          sym3_at(r, i, at + L::STRAIN),
          {r(i, at + L::SPIN), r(i, at + L::SPIN + 1), r(i, at + L::SPIN + 2)}};
}

// (forced inline: the host's loop over the grains vectorises only with it inside)
template <Stage STAGE, bool EXTRAPOLATE, class Model, class Rows>
KOKKOS_FORCEINLINE_FUNCTION int step_grain(const Model &m, const Rows &rows, int k, double dt,
                                           double ftm2v)
{
  using L = StateLayout;
  const int i = rows.atom(k);
  const double ftm = ftm2v / rows.mass(k);
  ParticleState p{{rows.x(i, 0), rows.x(i, 1), rows.x(i, 2)},
                  {rows.v(i, 0), rows.v(i, 1), rows.v(i, 2)},
                  rows.state(i, L::RHO),
                  sym3_at(rows.state, i, L::SIGMA)};
  StepStart s{{rows.start(i, L::V_START), rows.start(i, L::V_START + 1),
               rows.start(i, L::V_START + 2)},
              rows.start(i, L::RHO_START),
              sym3_at(rows.start, i, L::SIGMA_START)};
  // the predictor takes the acceleration of the last step's mid-point, which the corrector
  // kept (LAST_ACC), or a grain without a step that of the setup evaluation; the corrector
  // that of this evaluation
  const bool unstepped = STAGE == PREDICT && rows.start(i, L::STEPPED) == 0.0;
  double acc[3];
  for (int c = 0; c < 3; ++c)
    acc[c] = STAGE == CORRECT || unstepped ? ftm * rows.f(i, c) : rows.start(i, L::LAST_ACC + c);
  StepRates r = rates_at(rows.rates, i, 0, acc);
  Regime regime;
  if (STAGE == PREDICT) {
    if (EXTRAPOLATE) {    // from the last two mid-points, which PREV then holds
      const double acc_before[3] = {rows.rates(i, L::PREV + L::ACC),
                                    rows.rates(i, L::PREV + L::ACC + 1),
                                    rows.rates(i, L::PREV + L::ACC + 2)};
      const StepRates e = extrapolated(r, rates_at(rows.rates, i, L::PREV, acc_before),
                                       rows.rates(i, L::RATES_DT),
                                       rows.rates(i, L::PREV + L::RATES_DT));
      r = select(rows.start(i, L::STEPPED) >= 2.0, e, r);
      for (int c = 0; c < L::PREV; ++c) rows.rates(i, L::PREV + c) = rows.rates(i, c);
    }
    predict(m, p, s, r, dt, regime);
    for (int c = 0; c < 3; ++c) rows.start(i, L::V_START + c) = s.v[c];
    rows.start(i, L::RHO_START) = s.rho;
    store_sym3(s.sigma, rows.start, i, L::SIGMA_START);
  } else {
    correct(m, p, s, r, dt, regime);
    for (int c = 0; c < 3; ++c) {
      rows.start(i, L::LAST_ACC + c) = r.acc[c];    // the start's velocity is spent
      if (EXTRAPOLATE) rows.rates(i, L::ACC + c) = r.acc[c];    // for PREV
    }
    if (EXTRAPOLATE) rows.rates(i, L::RATES_DT) = dt;
    const double stepped = rows.start(i, L::STEPPED) + 1.0;
    rows.start(i, L::STEPPED) = stepped < 2.0 ? stepped : 2.0;
  }
  for (int c = 0; c < 3; ++c) {
    rows.x(i, c) = p.x[c];
    rows.v(i, c) = p.v[c];
  }
  rows.state(i, L::RHO) = p.rho;
  store_sym3(p.sigma, rows.state, i, L::SIGMA);
  rows.state(i, L::REGIME) = regime;
  return STAGE == CORRECT ? bad_state(p) : 0;
}

// Eq. 19: dt = C min(sqrt(h / max|a|), h / max c).
KOKKOS_INLINE_FUNCTION double cfl_timestep(double cfl, double h, double amax, double cmax)
{
  double dt = h / cmax;
  if (amax > 0.0 && sqrt(h / amax) < dt) dt = sqrt(h / amax);
  return cfl * dt;
}

}    // namespace GRANSPH

#endif
