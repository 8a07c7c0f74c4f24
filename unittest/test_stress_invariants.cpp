/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

// Unit tests of what compute sph/stress/atom reports: principal stresses and the major
// direction (Eigen), p, q and the Lode angle, the mobilised strength of the models.

#include "gransph_drucker_prager.h"
#include "gransph_phase_change.h"
#include "gransph_stress_invariants.h"
#include "tensor_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace GRANSPH;

namespace {
constexpr double PI = 3.14159265358979323846;

// Table 2 of the paper
const DruckerPrager DP = DruckerPrager::from_material(20.0e6, 0.3, 37.0 * PI / 180.0, 0.0, 0.0);
const PhaseChange PC = PhaseChange::from_material(20.0e6, 0.3, 1500.0, 1.1233, 0.6419, 0.8435);

// tension-positive stress of compressions c1, c2, c3 along the axes x, y, z
Sym3 compressions(double c1, double c2, double c3)
{
  return {-c1, -c2, -c3, 0.0, 0.0, 0.0};
}
}    // namespace

TEST(StressInvariants, PrincipalStressesAndMajorDirectionOfARotatedStress)
{
  // compressions 5e4 > 3e4 > 1e4 along z, x, y; then turned by a about z and b about x
  const double a = 0.7, b = -0.4;
  const Sym3 s = rotate(compressions(3.0e4, 1.0e4, 5.0e4), a, b);
  const StressInvariants r = stress_invariants(s);
  EXPECT_NEAR(r.principal[0], 5.0e4, 1e-12 * 5.0e4);
  EXPECT_NEAR(r.principal[1], 3.0e4, 1e-12 * 5.0e4);
  EXPECT_NEAR(r.principal[2], 1.0e4, 1e-12 * 5.0e4);
  // z turned by R_x(b) R_z(a) is (0, -sin b, cos b); the sign: largest component positive
  EXPECT_NEAR(r.major[0], 0.0, 1e-12);
  EXPECT_NEAR(r.major[1], -std::sin(b), 1e-12);
  EXPECT_NEAR(r.major[2], std::cos(b), 1e-12);
}

TEST(StressInvariants, MajorDirectionHasItsLargestComponentPositive)
{
  // a vertical major stress in 2d plane strain; and one along -x turned a little
  const StressInvariants v = stress_invariants({-2.0e3, -1.0e3, -9.0e3, 1.0e2, 0.0, 0.0});
  EXPECT_GT(v.major[2], 0.999);
  const StressInvariants x = stress_invariants(rotate(compressions(4.0, 1.0, 2.0), PI + 0.1));
  EXPECT_NEAR(x.major[0], std::cos(0.1), 1e-12);
  EXPECT_NEAR(x.major[1], std::sin(0.1), 1e-12);
}

TEST(StressInvariants, TriaxialCompression)
{
  // cell pressure 1e4, axial compression 4e4: p = (4 + 1 + 1) / 3 e4, q = 3e4
  const StressInvariants r = stress_invariants(rotate(compressions(1.0e4, 1.0e4, 4.0e4), 0.3, 0.2));
  EXPECT_NEAR(r.p, 2.0e4, 1e-12 * 4.0e4);
  EXPECT_NEAR(r.q, 3.0e4, 1e-12 * 4.0e4);
  EXPECT_NEAR(r.lode, -30.0, 1e-6);
}

TEST(StressInvariants, TriaxialExtension)
{
  const StressInvariants r = stress_invariants(compressions(4.0e4, 1.0e4, 4.0e4));
  EXPECT_NEAR(r.p, 3.0e4, 1e-12 * 4.0e4);
  EXPECT_NEAR(r.q, 3.0e4, 1e-12 * 4.0e4);
  EXPECT_NEAR(r.lode, 30.0, 1e-6);
}

TEST(StressInvariants, LodeAngleAgreesWithTheThirdInvariant)
{
  // sin(3 lode) = -(3 sqrt(3) / 2) J3 / J2^(3/2), J3 = det of the compression-positive deviator
  const double c[3] = {6.0e4, 2.5e4, 1.0e4};
  const StressInvariants r = stress_invariants(rotate(compressions(c[1], c[2], c[0]), 1.1, 0.5));
  const double m = (c[0] + c[1] + c[2]) / 3.0;
  const double j2 = ((c[0] - m) * (c[0] - m) + (c[1] - m) * (c[1] - m) + (c[2] - m) * (c[2] - m)) / 2;
  const double j3 = (c[0] - m) * (c[1] - m) * (c[2] - m);
  const double expected = std::asin(-1.5 * std::sqrt(3.0) * j3 / std::pow(j2, 1.5)) / 3.0;
  EXPECT_NEAR(r.lode, expected * 180.0 / PI, 1e-9);
  EXPECT_NEAR(r.q, std::sqrt(3.0 * j2), 1e-12 * c[0]);
}

TEST(StressInvariants, StressFreeStateIsAllZero)
{
  const StressInvariants r = stress_invariants(Sym3::zero());
  for (double v : {r.p, r.q, r.principal[0], r.principal[1], r.principal[2], r.lode})
    EXPECT_EQ(v, 0.0);
  EXPECT_NEAR(r.major[0] * r.major[0] + r.major[1] * r.major[1] + r.major[2] * r.major[2], 1.0,
              1e-15);
}

TEST(MobilisedRatio, DruckerPragerIsOneWhereTheReturnMapPutsTheStress)
{
  const Sym3 outside{-1.0e4, -3.0e4, -2.0e4, 4.0e4, -1.0e4, 2.0e4};
  ASSERT_GT(DP.mobilised_ratio(outside), 1.0);
  Regime regime = ELASTIC;
  EXPECT_NEAR(DP.mobilised_ratio(DP.return_to_cone(outside, regime)), 1.0, 1e-12);
  // a plastic step of the full update ends on the cone too
  const double p = 2.0e4;
  const Sym3 on{-p, -p, -p, DP.alpha_phi * 3.0 * p, 0.0, 0.0};
  const Sym3 d{0.0, 0.0, 0.0, 0.5, 0.0, 0.0};
  const Sym3 next = DP.update(on, on, d, Spin3::zero(), 0.0, 1e-5, regime);
  ASSERT_EQ(regime, PLASTIC);
  EXPECT_NEAR(DP.mobilised_ratio(next), 1.0, 1e-12);
}

TEST(MobilisedRatio, DruckerPragerIsBelowOneForAnElasticState)
{
  const Sym3 s{-1.0e4, -2.0e4, -1.5e4, 1.0e3, 0.0, 0.0};
  Regime regime;
  const Sym3 next = DP.update(s, s, {1e-3, -2e-3, 5e-4, 1e-3, 0.0, 0.0}, Spin3::zero(), 0.0,
                              1e-5, regime);
  ASSERT_EQ(regime, ELASTIC);
  const double ratio = DP.mobilised_ratio(next);
  EXPECT_GT(ratio, 0.0);
  EXPECT_LT(ratio, 1.0);
  EXPECT_NEAR(ratio, std::sqrt(second_invariant(next)) / (-DP.alpha_phi * next.trace()), 1e-15);
}

TEST(MobilisedRatio, DruckerPragerApexIsFullyMobilised)
{
  Regime regime = ELASTIC;
  EXPECT_NEAR(
      DP.mobilised_ratio(DP.return_to_cone({2.0e3, 1.0e3, 5.0e2, 3.0e2, 0.0, 1.0e2}, regime)), 1.0,
      1e-12);
  EXPECT_EQ(DP.mobilised_ratio(Sym3::zero()), 1.0);
  // with cohesion the apex is at I1 = k_c / alpha_phi, and a stress-free state is elastic
  const DruckerPrager cohesive = DruckerPrager::from_material(20.0e6, 0.3, 0.6, 0.0, 5.0e3);
  EXPECT_EQ(cohesive.mobilised_ratio(cohesive.return_to_cone(Sym3::iso(1.0e6), regime)), 1.0);
  EXPECT_EQ(cohesive.mobilised_ratio(Sym3::zero()), 0.0);
}

TEST(MobilisedRatio, PhaseChangeIsShearOverStaticStrength)
{
  const double p = 1.0e4;
  const Sym3 solid{-p, -p, -p, 0.5 * PC.mu_s * p, 0.0, 0.0};    // tau = 0.5 mu_s p
  EXPECT_NEAR(PC.mobilised_ratio(solid), 0.5, 1e-15);
  // a plastic step: mu(I) > mu_s, so the ratio is mu(I) / mu_s, above 1
  Regime regime;
  const Sym3 flowing = PC.update(solid, solid, {0.0, 0.0, 0.0, 50.0, 0.0, 0.0}, Spin3::zero(),
                                 2000.0, 1e-4, regime);
  ASSERT_EQ(regime, PLASTIC);
  const double tau = std::sqrt(second_invariant(flowing)), pf = -flowing.trace() / 3.0;
  EXPECT_NEAR(PC.mobilised_ratio(flowing), tau / (PC.mu_s * pf), 1e-15);
  EXPECT_GT(PC.mobilised_ratio(flowing), 1.0);
  EXPECT_LT(PC.mobilised_ratio(flowing), PC.mu_2 / PC.mu_s);
  EXPECT_EQ(PC.mobilised_ratio(Sym3::zero()), 1.0);    // disconnected
}
