/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

// Unit tests of the phase-change return map (Dunatunga & Kamrin 2015; Chen et al. 2019 eqs. 22-28).

#include "gransph_drucker_prager.h"
#include "gransph_phase_change.h"
#include "tensor_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace GRANSPH;

namespace {
constexpr double PI = 3.14159265358979323846;

// Table 2 of the paper
const PhaseChange PC = PhaseChange::from_material(20.0e6, 0.3, 1500.0, 1.1233, 0.6419, 0.8435);
const double RHO = 2450.0;

double tau_of(const Sym3 &s)
{
  const Sym3 dev = s.deviator();
  return std::sqrt(0.5 * dev.ddot(dev));
}

// a state under pressure p with shear tau on xy, and a shear strain rate
Sym3 sheared(double p, double tau) { return {-p, -p, -p, tau, 0.0, 0.0}; }
const Sym3 SHEAR_RATE{0.0, 0.0, 0.0, 50.0, 0.0, 0.0};

}    // namespace

TEST(PhaseChange, ElasticBranchReturnsTheTrialStress)
{
  const Sym3 s = sheared(1.0e4, 1.0e3);
  const double dt = 1e-6;
  const Sym3 trial = jaumann_trial(s, s, SHEAR_RATE, Spin3::zero(), PC.K, PC.G, dt);
  ASSERT_LT(tau_of(trial), PC.mu_s * 1.0e4);
  Regime regime;
  EXPECT_EQ(max_abs_diff(PC.update(s, s, SHEAR_RATE, Spin3::zero(), RHO, dt, regime), trial), 0.0);
  EXPECT_EQ(regime, ELASTIC);
}

TEST(PhaseChange, PlasticBranchSolvesEq26BetweenStaticAndDynamicYield)
{
  const double p = 1.0e4, dt = 1e-5;
  const Sym3 s = sheared(p, 0.63 * p);
  const Sym3 trial = jaumann_trial(s, s, SHEAR_RATE, Spin3::zero(), PC.K, PC.G, dt);
  const double tau_tr = tau_of(trial), p_tr = -trial.trace() / 3.0;
  ASSERT_GT(tau_tr, PC.mu_s * p_tr);
  Regime regime;
  const Sym3 next = PC.update(s, s, SHEAR_RATE, Spin3::zero(), RHO, dt, regime);
  EXPECT_EQ(regime, PLASTIC);
  const double tau = tau_of(next);
  const double alpha = PC.xi * PC.G * dt * std::sqrt(p_tr);
  const double B = PC.mu_2 * p_tr + tau_tr + alpha, H = PC.mu_2 * p_tr * tau_tr + PC.mu_s * p_tr * alpha;
  EXPECT_NEAR(tau * tau - B * tau + H, 0.0, 1e-9 * H);
  EXPECT_GE(tau, PC.mu_s * p_tr);
  EXPECT_LE(tau, PC.mu_2 * p_tr);
  EXPECT_LE(tau, tau_tr);
  // pressure and the direction of the deviator are those of the trial
  EXPECT_NEAR(-next.trace() / 3.0, p_tr, 1e-9 * p_tr);
  EXPECT_NEAR(next.deviator().ddot(trial.deviator()) / (2.0 * tau * tau_tr), 1.0, 1e-12);
}

TEST(PhaseChange, FlowStressFollowsMuOfI)
{
  // tau = p mu(I), mu(I) = mu_s + (mu_2 - mu_s) I / (I0 + I), with
  // I / I0 = gamma_dot d sqrt(rho_s / p) / I0 = (tau_tr - tau) / alpha
  const double p = 2.0e4, dt = 2e-5;
  for (double tau_tr : {0.7 * p, 0.9 * p, 3.0 * p}) {
    const double tau = PC.flow_stress(tau_tr, p, dt);
    const double alpha = PC.xi * PC.G * dt * std::sqrt(p);
    const double x = (tau_tr - tau) / alpha;
    EXPECT_NEAR(tau / p, PC.mu_s + (PC.mu_2 - PC.mu_s) * x / (1.0 + x), 1e-12);
  }
}

TEST(PhaseChange, DisconnectedBelowCriticalDensityAndInTension)
{
  const Sym3 s = sheared(1.0e4, 7.0e3);
  Regime regime;
  EXPECT_EQ(max_abs_diff(PC.update(s, s, SHEAR_RATE, Spin3::zero(), 1400.0, 1e-5, regime), Sym3::zero()), 0.0);
  EXPECT_EQ(regime, DISCONNECTED);
  const Sym3 tension{1.0e3, 2.0e3, -5.0e2, 3.0e2, 0.0, 0.0};
  EXPECT_EQ(max_abs_diff(PC.update(tension, tension, SHEAR_RATE, Spin3::zero(), RHO, 1e-5, regime), Sym3::zero()), 0.0);
  EXPECT_EQ(regime, DISCONNECTED);
}

TEST(PhaseChange, ObjectiveUnderRotationOfStressAndStrainRate)
{
  const Sym3 s{-1.2e4, -0.8e4, -1.0e4, 6.0e3, -2.0e3, 1.5e3};
  const Sym3 d{3.0, -1.0, 0.5, 40.0, -10.0, 5.0};
  const double dt = 1e-5, a = 0.7, b = -1.1;
  Regime r1, r2;
  const Sym3 rotated_after = rotate(PC.update(s, s, d, Spin3::zero(), RHO, dt, r1), a, b);
  const Sym3 after_rotated =
      PC.update(rotate(s, a, b), rotate(s, a, b), rotate(d, a, b), Spin3::zero(), RHO, dt, r2);
  EXPECT_EQ(r1, PLASTIC);
  EXPECT_EQ(r1, r2);
  EXPECT_LT(max_abs_diff(rotated_after, after_rotated), 1e-9 * 1.2e4);

  const DruckerPrager dp = DruckerPrager::from_material(20.0e6, 0.3, 37.0 * PI / 180.0, 0.0, 0.0);
  EXPECT_LT(max_abs_diff(rotate(dp.update(s, s, d, Spin3::zero(), RHO, dt, r1), a, b),
                         dp.update(rotate(s, a, b), rotate(s, a, b), rotate(d, a, b), Spin3::zero(), RHO, dt, r2)),
            1e-9 * 1.2e4);
}

TEST(PhaseChange, RateConsistentWithAlpha)
{
  // the same strain increment over half the time is a faster flow: alpha halves
  // and the shear stress rises towards the dynamic yield stress mu_2 p
  const double p = 1.0e4, dt = 1e-5;
  const Sym3 s = sheared(p, 0.63 * p);
  Regime regime;
  const Sym3 slow = PC.update(s, s, SHEAR_RATE, Spin3::zero(), RHO, dt, regime);
  const Sym3 fast = PC.update(s, s, 2.0 * SHEAR_RATE, Spin3::zero(), RHO, 0.5 * dt, regime);
  const Sym3 trial = jaumann_trial(s, s, SHEAR_RATE, Spin3::zero(), PC.K, PC.G, dt);
  const double tau_tr = tau_of(trial), p_tr = -trial.trace() / 3.0;
  EXPECT_NEAR(tau_of(slow), PC.flow_stress(tau_tr, p_tr, dt), 1e-9 * p);
  EXPECT_NEAR(tau_of(fast), PC.flow_stress(tau_tr, p_tr, 0.5 * dt), 1e-9 * p);
  EXPECT_GT(tau_of(fast), tau_of(slow));
  // limits: instantaneous flow gives min(tau_tr, mu_2 p), infinitely slow mu_s p
  EXPECT_NEAR(PC.flow_stress(tau_tr, p_tr, 1e-30), std::fmin(tau_tr, PC.mu_2 * p_tr), 1e-6 * p);
  EXPECT_NEAR(PC.flow_stress(tau_tr, p_tr, 1e6), PC.mu_s * p_tr, 1e-3 * p);
}
