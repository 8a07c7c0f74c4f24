/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

// Unit tests of the Jaumann rate and the Drucker-Prager stress update.

#include "gransph_drucker_prager.h"
#include "gransph_phase_change.h"
#include "gransph_tensor.h"
#include "tensor_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace GRANSPH;

namespace {
constexpr double PI = 3.14159265358979323846;

// Table 2 of the paper
const double E = 20.0e6, NU = 0.3, PHI = 37.0 * PI / 180.0;
const DruckerPrager DP = DruckerPrager::from_material(E, NU, PHI, 0.0, 0.0);
}    // namespace

TEST(Jaumann, PureRotationRotatesStress)
{
  const Sym3 s0{-3.0e4, -1.0e4, -2.0e4, 5.0e3, -2.0e3, 1.0e3};
  const double omega = 3.0, t_end = PI / 4.0 / omega;    // a 45 degree turn about z
  const Spin3 w{-omega, 0.0, 0.0};                        // v = omega z x x
  const int n = 20000;
  const double dt = t_end / n;
  Sym3 s = s0;
  for (int k = 0; k < n; ++k) s = jaumann_trial(s, s, Sym3::zero(), w, 1e7, 1e7, dt);
  EXPECT_LT(max_abs_diff(s, rotate(s0, omega * t_end)), 1e-3 * 3.0e4);
  // invariants are those of s0
  EXPECT_NEAR(s.trace(), s0.trace(), 1e-9 * 3.0e4);
  EXPECT_NEAR(second_invariant(s), second_invariant(s0), 1e-3 * second_invariant(s0));
}

TEST(Jaumann, RotationCreatesNoStressFromNothingOrFromPressure)
{
  const Spin3 w{0.7, -1.1, 2.3};
  const Sym3 none = jaumann_trial(Sym3::zero(), Sym3::zero(), Sym3::zero(), w, 1e7, 1e7, 1e-3);
  EXPECT_EQ(max_abs_diff(none, Sym3::zero()), 0.0);
  const Sym3 p = Sym3::iso(-5.0e4);
  EXPECT_LT(max_abs_diff(jaumann_trial(p, p, Sym3::zero(), w, 1e7, 1e7, 1e-3), p), 1e-9);
}

TEST(Jaumann, HookeRateSplitsIntoVolumetricAndDeviatoric)
{
  const double K = 1.0e7, G = 4.0e6, dt = 1e-4;
  const Sym3 d{1.0, -0.5, 0.25, 0.3, 0.0, -0.2};
  const Sym3 s = jaumann_trial(Sym3::zero(), Sym3::zero(), d, Spin3::zero(), K, G, dt);
  EXPECT_NEAR(s.trace(), 3.0 * K * d.trace() * dt, 1e-6);
  EXPECT_NEAR(s.xy, 2.0 * G * d.xy * dt, 1e-9);
  EXPECT_NEAR(s.deviator().xx, 2.0 * G * d.deviator().xx * dt, 1e-6);
}

TEST(DruckerPrager, MaterialConstantsOfPlaneStrainMatching)
{
  const double t = std::tan(PHI);
  EXPECT_NEAR(DP.alpha_phi, t / std::sqrt(9.0 + 12.0 * t * t), 1e-15);    // eq. 30
  EXPECT_EQ(DP.k_c, 0.0);                                                 // c = 0
  EXPECT_NEAR(DP.K, E / (3.0 * (1.0 - 2.0 * NU)), 1e-6);
  EXPECT_NEAR(DP.G, E / (2.0 * (1.0 + NU)), 1e-6);
}

// The friction at which a layer slides (pair_style sph/granular wall/friction material):
// tan 29.6 deg under the plane-strain matching for phi = 37 deg, tan(phi) under the
// simple-shear one
TEST(DruckerPrager, SlideFrictionOfEitherMatching)
{
  EXPECT_NEAR(std::atan(DP.slide_friction()) * 180.0 / PI, 29.6172, 1e-4);
  const DruckerPrager shear = DruckerPrager::from_material(E, NU, PHI, 0.0, 0.0, true);
  EXPECT_NEAR(shear.slide_friction(), std::tan(PHI), 1e-12);
}

TEST(DruckerPrager, ElasticBelowTheYieldSurface)
{
  const Sym3 s = Sym3::iso(-1.0e4);    // pure pressure: well inside the cone
  const Sym3 d{1e-3, -2e-3, 5e-4, 1e-3, 0.0, 0.0};
  const Spin3 w{0.1, 0.0, 0.0};
  const double dt = 1e-5;
  const Sym3 trial = jaumann_trial(s, s, d, w, DP.K, DP.G, dt);
  ASSERT_LT(DP.yield_function(trial), 0.0);
  Regime regime;
  EXPECT_LT(max_abs_diff(DP.update(s, s, d, w, 0.0, dt, regime), trial), 1e-9);
  EXPECT_EQ(regime, ELASTIC);
}

TEST(DruckerPrager, PlasticStepEndsOnTheYieldSurface)
{
  // start on the surface under pressure p with shear only, keep shearing
  const double p = 2.0e4;
  const double tau = DP.alpha_phi * 3.0 * p;    // sqrt(J2) = tau for pure xy shear
  const Sym3 s{-p, -p, -p, tau, 0.0, 0.0};
  ASSERT_NEAR(DP.yield_function(s), 0.0, 1e-9 * p);
  const Sym3 d{0.0, 0.0, 0.0, 0.5, 0.0, 0.0};
  const double dt = 1e-5;
  const Sym3 trial = jaumann_trial(s, s, d, Spin3::zero(), DP.K, DP.G, dt);
  ASSERT_GT(DP.yield_function(trial), 1e-3 * p);    // elastic trial leaves the cone
  Regime regime;
  const Sym3 next = DP.update(s, s, d, Spin3::zero(), 0.0, dt, regime);
  EXPECT_NEAR(DP.yield_function(next), 0.0, 1e-9 * p);
  EXPECT_EQ(regime, PLASTIC);
  EXPECT_NEAR(next.trace(), s.trace(), 1e-9 * p);    // psi = 0: no dilatancy
}

TEST(DruckerPrager, DilatancyRaisesPressureUnderPlasticShear)
{
  const DruckerPrager dilatant = DruckerPrager::from_material(E, NU, PHI, 10.0 * PI / 180.0, 0.0);
  const double p = 2.0e4;
  const Sym3 s{-p, -p, -p, dilatant.alpha_phi * 3.0 * p, 0.0, 0.0};
  const Sym3 d{0.0, 0.0, 0.0, 0.5, 0.0, 0.0};
  Regime regime;
  const Sym3 next = dilatant.update(s, s, d, Spin3::zero(), 0.0, 1e-5, regime);
  EXPECT_LT(next.trace(), s.trace());    // more compressive
  EXPECT_LE(dilatant.yield_function(next), 1e-9 * p);
}

TEST(DruckerPrager, TensionIsReturnedToTheApex)
{
  // cohesionless: any tensile state becomes stress-free
  const Sym3 tension{2.0e3, 1.0e3, 5.0e2, 3.0e2, 0.0, 1.0e2};
  Regime regime = ELASTIC;
  const Sym3 r = DP.return_to_cone(tension, regime);
  EXPECT_LT(max_abs_diff(r, Sym3::zero()), 1e-9);
  EXPECT_EQ(regime, DISCONNECTED);
  // with cohesion the apex sits at I1 = k_c / alpha_phi
  const DruckerPrager cohesive = DruckerPrager::from_material(E, NU, PHI, 0.0, 5.0e3);
  const Sym3 rc = cohesive.return_to_cone(Sym3::iso(1.0e6), regime);
  EXPECT_NEAR(rc.trace(), cohesive.k_c / cohesive.alpha_phi, 1e-6);
  EXPECT_NEAR(second_invariant(rc), 0.0, 1e-9);
}

TEST(DruckerPrager, StatesOutsideTheConeAreScaledOntoIt)
{
  const Sym3 outside{-1.0e4, -3.0e4, -2.0e4, 4.0e4, -1.0e4, 2.0e4};
  ASSERT_GT(DP.yield_function(outside), 0.0);
  Regime regime = ELASTIC;
  const Sym3 r = DP.return_to_cone(outside, regime);
  EXPECT_NEAR(DP.yield_function(r), 0.0, 1e-9 * 3.0e4);
  EXPECT_EQ(regime, PLASTIC);
  EXPECT_NEAR(r.trace(), outside.trace(), 1e-9);    // pressure is kept
  // the deviator keeps its direction
  const Sym3 a = outside.deviator(), b = r.deviator();
  EXPECT_NEAR(a.ddot(b) / std::sqrt(a.ddot(a) * b.ddot(b)), 1.0, 1e-12);
}

// The step of a grain in a thin layer sliding on the floor at 1 m/s over dx = 0.01 m: a
// shear rate of 48/s (an elastic increment 60 times the strength per step) and, from
// passing over the dummy particles' lattice, a small isochoric stretch across it.
namespace {
const double P_LAYER = 240.0;    // rho g dx
const double TAU_LAYER = 3.0 * DP.alpha_phi * P_LAYER;
const Sym3 S_LAYER{-P_LAYER, -P_LAYER, -P_LAYER, 0.0, TAU_LAYER, 0.0};    // at its strength
const Sym3 D_SLIDING{2.0, 0.0, -2.0, 0.0, 24.0, 0.0};                      // 1/s
const double DT_SLIDING = 2.6e-5;
}    // namespace

TEST(DruckerPrager, ReturnMappingEndsOnTheYieldSurfaceAfterALargeStep)
{
  Regime regime;
  const Sym3 trial = jaumann_trial(S_LAYER, S_LAYER, D_SLIDING, Spin3::zero(), DP.K, DP.G, DT_SLIDING);
  ASSERT_GT(sqrt(second_invariant(trial)), 50.0 * TAU_LAYER);
  const Sym3 next = DP.update(S_LAYER, S_LAYER, D_SLIDING, Spin3::zero(), 0.0, DT_SLIDING, regime);
  EXPECT_EQ(regime, PLASTIC);
  EXPECT_NEAR(DP.mobilised_ratio(next), 1.0, 1e-12);
  EXPECT_NEAR(next.trace(), trial.trace(), 1e-9 * P_LAYER);    // psi = 0: pressure kept
  const Sym3 a = trial.deviator(), b = next.deviator();         // the deviator's direction
  EXPECT_NEAR(a.ddot(b) / std::sqrt(a.ddot(a) * b.ddot(b)), 1.0, 1e-12);
  // the shear stress that carries the layer's friction stays at nearly all of it
  EXPECT_GT(next.xz, 0.98 * TAU_LAYER);
}

TEST(DruckerPrager, ReturnMappingWithDilatancyEndsOnTheYieldSurface)
{
  const DruckerPrager dilatant = DruckerPrager::from_material(E, NU, PHI, 10.0 * PI / 180.0, 0.0);
  Regime regime;
  const Sym3 next =
      dilatant.update(S_LAYER, S_LAYER, D_SLIDING, Spin3::zero(), 0.0, DT_SLIDING, regime);
  EXPECT_EQ(regime, PLASTIC);
  EXPECT_NEAR(dilatant.yield_function(next), 0.0, 1e-9 * P_LAYER);
  EXPECT_LT(next.trace(), S_LAYER.trace());    // dilatancy under confinement: more compressive
}

TEST(DruckerPrager, ReturnThroughTheApexLeavesNoStress)
{
  Regime regime;
  const Sym3 next = DP.return_mapping(Sym3{50.0, -20.0, 10.0, 0.0, 300.0, 0.0}, regime);
  EXPECT_LT(max_abs_diff(next, Sym3::zero()), 1e-12);
  EXPECT_EQ(regime, DISCONNECTED);
}

TEST(DruckerPrager, PaperStepAgreesForSmallStepsAndLosesTheShearInLargeOnes)
{
  const DruckerPrager paper = DruckerPrager::from_material(E, NU, PHI, 0.0, 0.0, false, true);
  Regime regime;
  // a step whose elastic increment is small against the strength: the two agree to
  // the explicit rate's first order
  const double dt = 1e-9;
  const Sym3 implicit = DP.update(S_LAYER, S_LAYER, D_SLIDING, Spin3::zero(), 0.0, dt, regime);
  const Sym3 explicit_step =
      paper.update(S_LAYER, S_LAYER, D_SLIDING, Spin3::zero(), 0.0, dt, regime);
  EXPECT_LT(max_abs_diff(implicit, explicit_step), 1e-3 * TAU_LAYER);
  // the sliding layer's step: the explicit rate removes the increment along the old
  // stress and keeps the small stretch across it at its full elastic size, which then
  // takes the direction of the returned stress: the shear stress is lost
  const Sym3 lost =
      paper.update(S_LAYER, S_LAYER, D_SLIDING, Spin3::zero(), 0.0, DT_SLIDING, regime);
  EXPECT_LT(lost.xz, 0.5 * TAU_LAYER);
}
