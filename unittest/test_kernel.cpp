// Unit tests of the Wendland C2 kernel (paper eq. 3) and the SPH sums built on it.

#include "gransph_kernel.h"
#include "gransph_pair_terms.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace GRANSPH;

namespace {
constexpr double PI = 3.14159265358979323846;

// a particle at rest at the origin, with Young's modulus 20 MPa for its sound speed
PairParticle particle(double mass, double rho, const Sym3 &sigma)
{
  const double zero[3] = {0.0, 0.0, 0.0};
  return PairParticle::make(zero, zero, mass, rho, sigma, 20e6);
}

// Simpson's rule over the radial support [0, 2h] of r^(dim-1) W(r)
double radial_integral(int dim, double h)
{
  const int n = 2000;
  const double dr = 2.0 * h / n;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double r = k * dr;
    const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    sum += weight * std::pow(r, dim - 1) * WendlandC2::make(h, dim).w(r * r);
  }
  const double shell = dim == 3 ? 4.0 * PI : 2.0 * PI;
  return shell * sum * dr / 3.0;
}
}    // namespace

TEST(WendlandC2, NormalisedIn2DAnd3D)
{
  for (double h : {0.01, 0.5, 3.0}) {
    EXPECT_NEAR(radial_integral(2, h), 1.0, 1e-10) << "h = " << h;
    EXPECT_NEAR(radial_integral(3, h), 1.0, 1e-10) << "h = " << h;
  }
}

TEST(WendlandC2, CompactSupportOf2h)
{
  const double h = 0.2;
  EXPECT_GT(WendlandC2::make(h, 3).w(std::pow(1.999 * h, 2)), 0.0);
  EXPECT_EQ(WendlandC2::make(h, 3).w(std::pow(2.0 * h, 2)), 0.0);
  EXPECT_EQ(WendlandC2::make(h, 2).grad_factor(std::pow(2.5 * h, 2)), 0.0);
}

TEST(WendlandC2, GradientMatchesFiniteDifference)
{
  const double h = 0.3;
  for (int dim : {2, 3})
    for (double r : {0.05, 0.2, 0.41, 0.59}) {
      const WendlandC2 kernel = WendlandC2::make(h, dim);
      const double eps = 1e-6;
      const double dwdr = (kernel.w((r + eps) * (r + eps)) - kernel.w((r - eps) * (r - eps))) / (2.0 * eps);
      // grad_i W = F x_ij, so |grad W| = F r along x_ij
      EXPECT_NEAR(kernel.grad_factor(r * r) * r, dwdr, 1e-6 * std::fabs(dwdr) + 1e-9);
    }
}

TEST(WendlandC2, GradientIsAntisymmetric)
{
  const double h = 0.1;
  const double xij[3] = {0.03, -0.07, 0.05};
  const double rsq = xij[0] * xij[0] + xij[1] * xij[1] + xij[2] * xij[2];
  const double f = WendlandC2::make(h, 3).grad_factor(rsq);
  for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(f * xij[a], -(f * -xij[a]));
  EXPECT_LT(f, 0.0);    // W decreases away from the particle
}

namespace {
// Particles on a simple cubic lattice around the origin, spacing dx, h = 1.3 dx,
// moving with the velocity field v = L x.
struct Lattice {
  double dx = 0.01, h = 0.013, rho = 2000.0;
  double mass() const { return rho * dx * dx * dx; }

  template <class F> void for_neighbours(F &&f) const
  {
    const int n = 4;
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j)
        for (int k = -n; k <= n; ++k) {
          if (!i && !j && !k) continue;
          const double xj[3] = {i * dx, j * dx, k * dx};
          f(xj);
        }
  }

  // rates of the particle at the origin for velocity gradient L
  ParticleRates rates(const double L[3][3]) const
  {
    ParticleRates r = ParticleRates::zero();
    const PairParticle p = particle(mass(), rho, Sym3::zero());
    for_neighbours([&](const double *xj) {
      const double dx_ij[3] = {-xj[0], -xj[1], -xj[2]};
      const double rsq = xj[0] * xj[0] + xj[1] * xj[1] + xj[2] * xj[2];
      const double fw = WendlandC2::make(h, 3).grad_factor(rsq);
      const double gradw[3] = {fw * dx_ij[0], fw * dx_ij[1], fw * dx_ij[2]};
      double dv[3];
      for (int a = 0; a < 3; ++a) dv[a] = -(L[a][0] * xj[0] + L[a][1] * xj[1] + L[a][2] * xj[2]);
      r.add(PairTerms::make(p, p, dv, gradw, 0.0), p, 1.0);
    });
    return r;
  }

  // sum_j V_j (x_j - x_i)_x dW/dx_i: the discrete form of d x / d x = 1, which
  // the plain SPH gradient reproduces only to within a few percent
  double gradient_consistency() const
  {
    double sum = 0.0;
    for_neighbours([&](const double *xj) {
      const double rsq = xj[0] * xj[0] + xj[1] * xj[1] + xj[2] * xj[2];
      sum += xj[0] * WendlandC2::make(h, 3).grad_factor(rsq) * -xj[0];
    });
    return sum * dx * dx * dx;
  }
};
}    // namespace

TEST(WendlandC2, GradientConsistencyOnALattice)
{
  EXPECT_NEAR(Lattice().gradient_consistency(), 1.0, 0.03);
}

TEST(WendlandC2, LatticeSumIsPartitionOfUnity)
{
  const Lattice lat;
  double sum = WendlandC2::make(lat.h, 3).w(0.0);
  lat.for_neighbours([&](const double *xj) {
    sum += WendlandC2::make(lat.h, 3).w(xj[0] * xj[0] + xj[1] * xj[1] + xj[2] * xj[2]);
  });
  EXPECT_NEAR(sum * std::pow(lat.dx, 3), 1.0, 0.01);
}

TEST(PairTerms, RigidRotationHasSpinButNoStrainRate)
{
  const double omega = 2.5;    // about z: v = (-omega y, omega x, 0)
  const double L[3][3] = {{0.0, -omega, 0.0}, {omega, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  const Lattice lat;
  const ParticleRates r = lat.rates(L);
  EXPECT_NEAR(r.spin().xy, -omega * lat.gradient_consistency(), 1e-12 * omega);
  EXPECT_NEAR(r.spin().xz, 0.0, 1e-12);
  EXPECT_NEAR(r.spin().yz, 0.0, 1e-12);
  for (double d : {r.strain().xx, r.strain().yy, r.strain().zz, r.strain().xy, r.strain().xz, r.strain().yz})
    EXPECT_NEAR(d, 0.0, 1e-12);
  EXPECT_NEAR(r.drho, 0.0, 1e-9);
}

TEST(PairTerms, UniformCompressionRaisesDensity)
{
  const double rate = -0.3;    // v = rate * x in every direction
  const double L[3][3] = {{rate, 0.0, 0.0}, {0.0, rate, 0.0}, {0.0, 0.0, rate}};
  const Lattice lat;
  const ParticleRates r = lat.rates(L);
  const double k = lat.gradient_consistency();
  EXPECT_NEAR(r.strain().xx, rate * k, 1e-12);
  EXPECT_NEAR(r.strain().zz, rate * k, 1e-12);
  EXPECT_NEAR(r.strain().xy, 0.0, 1e-12);
  // continuity: drho/dt = -rho div v
  EXPECT_NEAR(r.drho, -lat.rho * 3.0 * rate * k, 1e-9 * lat.rho);
}

TEST(PairTerms, ViscosityOnlyBetweenApproachingParticles)
{
  const PairParticle p = particle(1.0, 1000.0, Sym3::zero());
  const double dx[3] = {0.01, 0.0, 0.0};
  const double approach[3] = {-1.0, 0.0, 0.0};
  const double separate[3] = {1.0, 0.0, 0.0};
  EXPECT_GT(monaghan_viscosity(dx, approach, 1e-4, 0.012, 1.0, 1.0, p, p), 0.0);
  EXPECT_EQ(monaghan_viscosity(dx, separate, 1e-4, 0.012, 1.0, 1.0, p, p), 0.0);
}

namespace {
// two particles under pressure, approaching: i at x_ij from j
struct TwoParticles {
  const PairParticle pi = particle(0.5, 1000.0, Sym3::iso(-2.0e4));
  const PairParticle pj = particle(0.7, 1100.0, {-1.0e4, -1.2e4, -0.9e4, 300.0, -200.0, 100.0});
  const double h = 0.012;
  const double xij[3] = {0.01, 0.002, -0.003};
  const double vij[3] = {-0.4, 0.1, 0.0};

  // the pair seen from i (from = +1) or from j (from = -1)
  PairTerms terms(double from) const
  {
    const double x[3] = {from * xij[0], from * xij[1], from * xij[2]};
    const double v[3] = {from * vij[0], from * vij[1], from * vij[2]};
    const double rsq = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    const double fw = WendlandC2::make(h, 3).grad_factor(rsq);
    const double g[3] = {fw * x[0], fw * x[1], fw * x[2]};
    const PairParticle &self = from > 0 ? pi : pj, &other = from > 0 ? pj : pi;
    return PairTerms::make(self, other, v, g, monaghan_viscosity(x, v, rsq, h, 1.0, 1.0, self, other));
  }
};
}    // namespace

TEST(PairTerms, PressureAndViscosityRepelAndConserveMomentum)
{
  const TwoParticles two;
  const PairTerms t = two.terms(1.0);
  ParticleRates ri = ParticleRates::zero(), rj = ParticleRates::zero();
  ri.add(t, two.pj, 1.0);
  rj.add(t, two.pi, -1.0);
  EXPECT_GT(ri.acc[0] * two.xij[0] + ri.acc[1] * two.xij[1] + ri.acc[2] * two.xij[2], 0.0);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(two.pi.mass * ri.acc[a], -two.pj.mass * rj.acc[a], 1e-12 * std::fabs(two.pi.mass * ri.acc[a]));
}

// A half neighbour list adds each pair's terms to j with side -1: the same rates as
// j's own view of the pair, which a full list uses.
TEST(PairTerms, OnePairServesBothParticles)
{
  const TwoParticles two;
  ParticleRates from_pair = ParticleRates::zero(), own = ParticleRates::zero();
  from_pair.add(two.terms(1.0), two.pi, -1.0);
  own.add(two.terms(-1.0), two.pi, 1.0);
  EXPECT_NEAR(from_pair.drho, own.drho, 1e-12 * std::fabs(own.drho));
  EXPECT_NE(own.drho, 0.0);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(from_pair.acc[a], own.acc[a], 1e-12 * std::fabs(own.acc[a]));
    for (int b = 0; b < 3; ++b)
      EXPECT_NEAR(from_pair.grad_v[a][b], own.grad_v[a][b], 1e-12 * std::fabs(own.grad_v[a][b]));
  }
}

TEST(WallSums, HydrostaticExtrapolationBelowGrains)
{
  // grains at rest above a dummy particle, stress sigma_k; gravity -z
  WallSums sums = WallSums::zero();
  const double rho = 1500.0, h = 0.01;
  const Sym3 sk = Sym3::iso(-3000.0);
  const double r_dk[3] = {0.0, 0.0, -0.01};    // dummy 1 cm below the grain
  sums.add(sk, rho, r_dk, WendlandC2::make(h, 3).w(1e-4));
  const double g[3] = {0.0, 0.0, -9.81};
  const Sym3 sd = sums.stress(g);
  // one layer deeper: more compressive by rho g dz
  EXPECT_NEAR(sd.zz, -3000.0 - rho * 9.81 * 0.01, 1e-9);
  EXPECT_NEAR(sd.xx, -3000.0 - rho * 9.81 * 0.01, 1e-9);
  EXPECT_EQ(sd.xy, 0.0);
  EXPECT_EQ(WallSums::zero().stress(g).zz, 0.0);    // no neighbours: stress-free
}
