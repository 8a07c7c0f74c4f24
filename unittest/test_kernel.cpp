/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

// Unit tests of the Wendland C2 kernel (paper eq. 3) and the SPH sums built on it, the
// sums through the neighbour loops of the pair styles (gransph_neighbour_sums.h).

#include "gransph_kernel.h"
#include "gransph_neighbour_sums.h"
#include "gransph_pair_terms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace GRANSPH;

namespace {
constexpr double PI = 3.14159265358979323846;

// a particle at rest at the origin, with the sound speed of Young's modulus 20 MPa
PairParticle particle(double mass, double rho, const Sym3 &sigma)
{
  const double zero[3] = {0.0, 0.0, 0.0};
  return PairParticle::make(zero, zero, mass, rho, sigma, sound_speed(20e6, rho));
}

// the paper's viscosity, alpha = beta = 1 with c = sqrt(E / rho)
const Viscosity PAPER_VISCOSITY{1.0, 1.0, true, Viscosity::PAPER};

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
// Particle 0 and its neighbours, each a grain or a dummy: the accessor of the neighbour
// sums (gransph_neighbour_sums.h) over a list of particle 0's neighbours alone.
struct Neighbourhood {
  using Real = double;
  enum Role { GRAIN, DUMMY, OTHER };    // OTHER: neither (the pair styles pack it massless)
  std::vector<PairParticle> particles;
  std::vector<Role> roles;
  std::vector<double> normals;    // 3 per particle: a dummy's own wall normal, or zeros
  std::vector<double> mus;        // a dummy's wall friction (wall_friction), -1: rough
  std::vector<double> slides;     // 4 per particle: a grain's share and slide direction
  WendlandC2 kernel;
  Viscosity visc{0.0, 0.0, false, Viscosity::BULK};
  bool wall_normal = false, shape_sums = true, wall_friction = false;
  WallStick stick{false, {0.0, 0.0, 0.0}, 0.0};

  Neighbourhood(double h, int dim) : kernel(WendlandC2::make(h, dim)) {}

  void add(Role role, const PairParticle &particle, const double *normal = nullptr)
  {
    particles.push_back(particle);
    roles.push_back(role);
    for (int a = 0; a < 3; ++a) normals.push_back(normal ? normal[a] : 0.0);
    mus.push_back(-1.0);
    for (double held : {1.0, 0.0, 0.0, 0.0}) slides.push_back(held);
  }
  int num_neighbours(int i) const { return i == 0 ? int(particles.size()) - 1 : 0; }
  struct Others {    // the neighbours of particle 0: all the others
    int operator()(int k) const { return k + 1; }
  };
  Others neighbours(int) const { return {}; }
  const PairParticle &particle(int i) const { return particles[i]; }
  bool granular(int i) const { return roles[i] == GRAIN; }
  bool wall(int i) const { return roles[i] == DUMMY; }
  double normal(int i, int a) const { return normals[3 * i + a]; }
  double friction(int i) const { return mus[i]; }
  double slide(int i, int k) const { return slides[4 * i + k]; }

  // the rates of grain 0, its virial if vir is not null and its share and slide
  // direction on the walls with a friction of their own (4 values) if slide is not null
  ParticleRates rates(double *vir = nullptr, double *slide = nullptr) const
  {
    return granular_rates(*this, 0, vir, slide);
  }
  double viscous_pressure() const { return GRANSPH::viscous_pressure(*this, 0); }
};

// The same neighbourhood in single precision, as the pair styles give it to the grains'
// sums under `precision mixed`.
struct SingleNeighbourhood {
  using Real = float;
  const Neighbourhood &near;
  std::vector<PairParticleSingle> particles;
  WendlandC2 kernel;
  Viscosity visc;
  bool wall_normal, shape_sums, wall_friction;
  WallStick stick;

  explicit SingleNeighbourhood(const Neighbourhood &n) :
      near(n), kernel(n.kernel), visc(n.visc), wall_normal(n.wall_normal),
      shape_sums(n.shape_sums), wall_friction(n.wall_friction), stick(n.stick)
  {
    const double origin[3] = {0.0, 0.0, 0.0};    // 1.5 m away: a sub-domain 3 m across
    for (const PairParticle &p : n.particles) particles.push_back(PairParticleSingle::of(p, origin));
  }
  int num_neighbours(int i) const { return near.num_neighbours(i); }
  Neighbourhood::Others neighbours(int i) const { return near.neighbours(i); }
  const PairParticleSingle &particle(int i) const { return particles[i]; }
  bool granular(int i) const { return near.granular(i); }
  bool wall(int i) const { return near.wall(i); }
  double normal(int i, int a) const { return near.normal(i, a); }
  double friction(int i) const { return near.friction(i); }
  double slide(int i, int k) const { return near.slide(i, k); }
  ParticleRates rates() const { return granular_rates(*this, 0, nullptr, nullptr); }
  double viscous_pressure() const { return GRANSPH::viscous_pressure(*this, 0); }
};

// a particle at x with velocity v, otherwise as particle()
PairParticle particle_at(const double *x, const double *v, double mass, double rho,
                         const Sym3 &sigma = Sym3::zero())
{
  return PairParticle::make(x, v, mass, rho, sigma, sound_speed(20e6, rho));
}

// Particles on a simple cubic lattice around the origin, spacing dx, h = 1.3 dx,
// moving with the velocity field v = L x. With a free surface at z = surface, only
// the particles below it are neighbours (the origin is half a spacing or more below).
struct Lattice {
  double dx = 0.01, h = 0.013, rho = 2000.0;
  double surface = 1.0;
  double mass() const { return rho * dx * dx * dx; }

  template <class F> void for_neighbours(F &&f) const
  {
    const int n = 4;
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j)
        for (int k = -n; k <= n; ++k) {
          if (!i && !j && !k) continue;
          const double xj[3] = {i * dx, j * dx, k * dx};
          if (xj[2] > surface) continue;
          f(xj);
        }
  }

  // rates of the particle at the origin for velocity gradient L
  ParticleRates rates(const double L[3][3]) const
  {
    Neighbourhood near(h, 3);
    near.add(Neighbourhood::GRAIN, particle(mass(), rho, Sym3::zero()));
    for_neighbours([&](const double *xj) {
      double vj[3];
      for (int a = 0; a < 3; ++a) vj[a] = L[a][0] * xj[0] + L[a][1] * xj[1] + L[a][2] * xj[2];
      near.add(Neighbourhood::GRAIN, particle_at(xj, vj, mass(), rho));
    });
    return near.rates();
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
  const double dx[3] = {0.01, 0.0, 0.0};
  const double approach = -1.0 * dx[0], separate = 1.0 * dx[0];    // v_ij . x_ij
  const double c = sound_speed(20e6, 1000.0);
  EXPECT_GT(monaghan_viscosity(approach, 1e-4, 0.012, PAPER_VISCOSITY, c, 1000.0), 0.0);
  EXPECT_EQ(monaghan_viscosity(separate, 1e-4, 0.012, PAPER_VISCOSITY, c, 1000.0), 0.0);
}

namespace {
// two particles under pressure, approaching: i at x_ij from j, with the paper's viscosity
struct TwoParticles {
  const double h = 0.012;
  const double xij[3] = {0.01, 0.002, -0.003};
  const double vij[3] = {-0.4, 0.1, 0.0};
  const double zero[3] = {0.0, 0.0, 0.0};
  const double mi = 0.5, mj = 0.7, rhoi = 1000.0, rhoj = 1100.0;
  const Sym3 si = Sym3::iso(-2.0e4), sj{-1.0e4, -1.2e4, -0.9e4, 300.0, -200.0, 100.0};
  const PairParticle pi = particle_at(xij, vij, mi, rhoi, si);
  const PairParticle pj = particle_at(zero, zero, mj, rhoj, sj);

  // the pair seen from i (j its neighbour) or from j; j is a dummy if j_role says so
  Neighbourhood from_i(Neighbourhood::Role j_role = Neighbourhood::GRAIN) const
  {
    Neighbourhood near(h, 3);
    near.visc = PAPER_VISCOSITY;
    near.add(Neighbourhood::GRAIN, pi);
    near.add(j_role, pj);
    return near;
  }
  Neighbourhood from_j() const
  {
    Neighbourhood near(h, 3);
    near.visc = PAPER_VISCOSITY;
    near.add(Neighbourhood::GRAIN, pj);
    near.add(Neighbourhood::GRAIN, pi);
    return near;
  }
};
}    // namespace

TEST(PairTerms, PressureAndViscosityRepelAndConserveMomentum)
{
  const TwoParticles two;
  const ParticleRates ri = two.from_i().rates(), rj = two.from_j().rates();
  EXPECT_GT(ri.acc[0] * two.xij[0] + ri.acc[1] * two.xij[1] + ri.acc[2] * two.xij[2], 0.0);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(two.mi * ri.acc[a], -two.mj * rj.acc[a], 1e-12 * std::fabs(two.mi * ri.acc[a]));
  // the continuity equation sees the same approach from either side
  EXPECT_NEAR(ri.drho / two.mj, rj.drho / two.mi, 1e-12 * std::fabs(ri.drho / two.mj));
  EXPECT_GT(ri.drho, 0.0);
}

// The force on a dummy particle (eq. 9) is the reaction of the grain's acceleration by it,
// and each side's virial is half the pair's.
TEST(PairTerms, WallForceIsTheReactionOnTheGrain)
{
  const TwoParticles two;
  double vir_i[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, vir_d[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const ParticleRates ri = two.from_i(Neighbourhood::DUMMY).rates(vir_i);
  Neighbourhood walls = two.from_j();
  walls.roles[0] = Neighbourhood::DUMMY;
  double fd[3];
  wall_force(walls, 0, fd, vir_d);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(fd[a], -two.mi * ri.acc[a], 1e-12 * std::fabs(fd[a]));
    EXPECT_NE(fd[a], 0.0);
  }
  const double f[3] = {two.mi * ri.acc[0], two.mi * ri.acc[1], two.mi * ri.acc[2]};
  const double x_f[6] = {two.xij[0] * f[0], two.xij[1] * f[1], two.xij[2] * f[2],
                         two.xij[0] * f[1], two.xij[0] * f[2], two.xij[1] * f[2]};
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(vir_i[k], 0.5 * x_f[k], 1e-12 * std::fabs(x_f[k]) + 1e-300) << k;
    EXPECT_NEAR(vir_d[k], 0.5 * x_f[k], 1e-12 * std::fabs(x_f[k]) + 1e-300) << k;
  }
}

namespace {
// A grain above a floor of dummies (own normal +z), the grain and the dummies in a
// sheared stress state, so that the floor pushes it up and drags it along x
struct GrainOnFloor {
  const double dx = 0.01, h = 0.012;
  Neighbourhood near{h, 3};

  explicit GrainOnFloor(double mu)
  {
    const double up[3] = {0.0, 0.0, 1.0}, origin[3] = {0.0, 0.0, 0.5 * dx},
                 v[3] = {0.3, 0.0, 0.0}, still[3] = {0.0, 0.0, 0.0};
    const Sym3 sigma{-1.0e3, -1.0e3, -2.0e3, 0.0, 900.0, 0.0};    // shear stress xz
    const double m = 1500.0 * dx * dx * dx;
    near.wall_friction = true;
    near.add(Neighbourhood::GRAIN, particle_at(origin, v, m, 1500.0, sigma));
    for (int a = -2; a <= 2; ++a)
      for (int b = -2; b <= 2; ++b)
        for (int c = 0; c < 2; ++c) {
          const double x[3] = {a * dx + 0.3 * dx, b * dx, -(c + 0.5) * dx};
          near.add(Neighbourhood::DUMMY, particle_at(x, still, m, 1500.0, sigma), up);
          near.mus.back() = mu;
        }
  }

  // the forces on the dummies, summed: each dummy's wall_force with the grain's share
  // and slide direction
  void dummy_forces(const double *slide, double *sum) const
  {
    for (int a = 0; a < 3; ++a) sum[a] = 0.0;
    for (size_t d = 1; d < near.particles.size(); ++d) {
      Neighbourhood from_d(h, 3);
      from_d.wall_friction = true;
      from_d.add(Neighbourhood::DUMMY, near.particles[d], &near.normals[3 * d]);
      from_d.mus[0] = near.mus[d];
      from_d.add(Neighbourhood::GRAIN, near.particles[0]);
      for (int k = 0; k < 4; ++k) from_d.slides[4 + k] = slide[k];
      double fd[3];
      wall_force(from_d, 0, fd, nullptr);
      for (int a = 0; a < 3; ++a) sum[a] += fd[a];
    }
  }
};
}    // namespace

// Coulomb's law at a wall with a friction of its own: the tangential force on the grain
// is at most mu times the normal one, the normal one unchanged; a rough wall (mu < 0)
// and a wall that holds (mu large) leave the force as it is; and the dummies take the
// opposite of what the grain gets.
TEST(PairTerms, WallFrictionLimitsTheTangentialForce)
{
  const GrainOnFloor rough(-1.0);
  const ParticleRates free = rough.near.rates();
  ASSERT_GT(free.acc[2], 0.0);                        // pushed up
  ASSERT_GT(std::fabs(free.acc[0]), 0.1 * free.acc[2]);    // and dragged
  for (double mu : {0.0, 0.1, 0.3, 100.0}) {
    const GrainOnFloor floor(mu);
    double slide[4] = {-1.0, 0.0, 0.0, 0.0};
    const ParticleRates r = floor.near.rates(nullptr, slide);
    const double share = slide[0];
    const double tangential = std::sqrt(r.acc[0] * r.acc[0] + r.acc[1] * r.acc[1]);
    EXPECT_NEAR(r.acc[2], free.acc[2], 1e-12 * free.acc[2]) << mu;
    const double free_t = std::sqrt(free.acc[0] * free.acc[0] + free.acc[1] * free.acc[1]);
    EXPECT_NEAR(tangential, std::fmin(free_t, mu * free.acc[2]), 1e-12 * free_t) << mu;
    EXPECT_NEAR(share, std::fmin(1.0, mu * free.acc[2] / free_t), 1e-12) << mu;
    double fd[3];
    floor.dummy_forces(slide, fd);
    const double m = floor.near.particles[0].mass;
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(fd[a], -m * r.acc[a], 1e-12 * m * free.acc[2]) << mu << " " << a;
  }
}

// Where a sliding grain touches two walls of different friction, each wall takes its own:
// tan(delta) times the normal force it takes.
TEST(PairTerms, TwoWallsTakeTheirOwnFriction)
{
  GrainOnFloor floor(0.1);
  for (size_t d = 1; d < floor.near.particles.size(); ++d)
    if (floor.near.particles[d].x[0] > 0.0) floor.near.mus[d] = 0.3;
  double slide[4];
  floor.near.rates(nullptr, slide);
  ASSERT_LT(slide[0], 1.0);    // it slides
  for (double mu : {0.1, 0.3}) {
    GrainOnFloor wall = floor;    // the dummies of one wall only
    for (size_t d = 1; d < wall.near.particles.size(); ++d)
      if (wall.near.mus[d] != mu) wall.near.particles[d].mass = 0.0;
    double fd[3];
    wall.dummy_forces(slide, fd);
    EXPECT_LT(fd[2], 0.0);    // pushed down
    EXPECT_NEAR(std::sqrt(fd[0] * fd[0] + fd[1] * fd[1]), -mu * fd[2], 1e-12 * std::fabs(fd[2]));
  }
}

// wall/friction/hold stick: below Coulomb's limit the walls push the grain tangentially
// with whatever cancels its other tangential acceleration (here gravity along x; the
// dummies' shear stress, which the stress hold would pass on, counts for nothing) and
// removes a share of its velocity relative to them; at the limit they push with mu times
// the normal force against that; the normal push is unchanged; and the dummies take the
// opposite of what the grain gets.
TEST(PairTerms, StickWallsHoldUpToCoulombsLimit)
{
  const GrainOnFloor rough(-1.0);
  const double push = rough.near.rates().acc[2];    // the floor's normal push
  const double g_x = 2.0, rate = 100.0, v_x = 0.3;  // the grain moves at 0.3 m/s along x
  const double needed = g_x + rate * v_x;           // |T| that holds it
  for (double mu : {0.1, 0.3, 100.0}) {
    GrainOnFloor floor(mu);
    floor.near.stick = WallStick{true, {g_x, 0.0, -9.81}, rate};
    double slide[4];
    const ParticleRates r = floor.near.rates(nullptr, slide);
    EXPECT_NEAR(r.acc[2], push, 1e-12 * push) << mu;
    EXPECT_NEAR(r.acc[1], 0.0, 1e-12 * push) << mu;
    EXPECT_NEAR(r.acc[0], -std::fmin(needed, mu * push), 1e-12 * needed) << mu;
    EXPECT_EQ(slide[0], 0.0) << mu;    // the dummies take the push along slide[1..3]
    double fd[3];
    floor.dummy_forces(slide, fd);
    const double m = floor.near.particles[0].mass;
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(fd[a], -m * r.acc[a], 1e-12 * m * push) << mu << " " << a;
  }
}

// A slip wall gives no shear: the grain's velocity gradient sees only the normal part of
// its velocity relative to the dummies.
TEST(PairTerms, SlipWallsGiveNoShear)
{
  GrainOnFloor slip(0.0), rough(-1.0);
  const ParticleRates r_slip = slip.near.rates(), r_rough = rough.near.rates();
  EXPECT_GT(std::fabs(r_rough.grad_v[0][2]), 1.0);    // the grain moves at 0.3 m/s along x
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) EXPECT_EQ(r_slip.grad_v[a][b], 0.0) << a << b;
  EXPECT_EQ(r_slip.drho, 0.0);
}

// Neighbours outside the support, and atoms that are neither grain nor dummy (packed
// massless by the pair styles), add nothing.
TEST(PairTerms, OnlyNeighboursInsideTheSupportCount)
{
  const TwoParticles two;
  const ParticleRates alone = two.from_i().rates();
  Neighbourhood near = two.from_i();
  const double far[3] = {0.05, 0.0, 0.0}, v[3] = {3.0, 0.0, 0.0};
  near.add(Neighbourhood::GRAIN, particle_at(far, v, 1.0, 1000.0, Sym3::iso(-1e5)));
  near.add(Neighbourhood::DUMMY, particle_at(far, v, 1.0, 1000.0, Sym3::iso(-1e5)));
  const double close[3] = {0.0, 0.0, 0.005};
  PairParticle other = PairParticle::make(close, v, 0.0, 1.0, Sym3::zero(), 0.0);
  near.add(Neighbourhood::OTHER, other);
  const ParticleRates r = near.rates();
  EXPECT_EQ(r.drho, alone.drho);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(r.acc[a], alone.acc[a]);
  EXPECT_EQ(near.viscous_pressure(), two.from_i().viscous_pressure());
}

// The viscous pressure of a pair is rho_i rho_j Pi_ij / 2: the pressure that, put in
// place of Pi in eq. 6b, pushes the pair apart as much.
TEST(PairTerms, ViscousPressureOfOnePair)
{
  const TwoParticles two;
  const double p_visc = two.from_i().viscous_pressure();
  const double rsq = two.xij[0] * two.xij[0] + two.xij[1] * two.xij[1] + two.xij[2] * two.xij[2];
  const double vdotx = two.vij[0] * two.xij[0] + two.vij[1] * two.xij[1] + two.vij[2] * two.xij[2];
  const double pi_ij = monaghan_viscosity(vdotx, rsq, two.h, PAPER_VISCOSITY,
                                          0.5 * (two.pi.c + two.pj.c), 0.5 * (two.rhoi + two.rhoj));
  EXPECT_GT(pi_ij, 0.0);
  EXPECT_NEAR(p_visc, 0.5 * two.rhoi * two.rhoj * pi_ij, 1e-12 * p_visc);
}

// A general linear velocity field v = L x
const double LINEAR_FIELD[3][3] = {{0.3, -1.2, 0.5}, {0.7, -0.4, 2.0}, {-0.9, 0.25, 0.1}};

// The renormalised gradient is exact for a linear field inside the material, where
// the plain one is off by the lattice's gradient consistency (a few percent)...
TEST(CorrectedGradient, ExactForALinearFieldInside)
{
  Lattice lat;
  ParticleRates r = lat.rates(LINEAR_FIELD);
  EXPECT_GT(std::fabs(r.grad_v[0][1] - LINEAR_FIELD[0][1]), 1e-3);
  r.correct_gradient(3);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(r.grad_v[a][b], LINEAR_FIELD[a][b], 1e-12);
}

// ...and at a free surface, where the plain gradient loses up to half of it.
TEST(CorrectedGradient, ExactForALinearFieldAtAFreeSurface)
{
  for (double surface : {0.0, 0.01}) {    // on the surface, one spacing below it
    Lattice lat;
    lat.surface = surface;
    ParticleRates r = lat.rates(LINEAR_FIELD);
    EXPECT_GT(std::fabs(r.grad_v[1][2] - LINEAR_FIELD[1][2]), 0.1) << surface;
    r.correct_gradient(3);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) EXPECT_NEAR(r.grad_v[a][b], LINEAR_FIELD[a][b], 1e-12) << surface;
  }
}

// Next to a wall the dummy particles are neighbours like the grains (the neighbour
// sums add them with the same terms): a grain in a monolayer on three layers of
// dummies that move with the field, with a free surface above, gets the exact
// gradient too; in 2d too.
TEST(CorrectedGradient, ExactNextToAWallAndIn2D)
{
  const double dx = 0.01, h = 0.012, rho = 1500.0;
  for (int dim : {2, 3}) {
    const double m = rho * std::pow(dx, dim);
    Neighbourhood near(h, dim);
    near.add(Neighbourhood::GRAIN, particle(m, rho, Sym3::zero()));
    // grain at the origin in a monolayer (j = 0), dummies in three layers below it
    const int nk = dim == 3 ? 4 : 0;
    for (int i = -4; i <= 4; ++i)
      for (int k = -nk; k <= nk; ++k)
        for (int j = -3; j <= 0; ++j) {
          const double xj[3] = {i * dx, dim == 3 ? k * dx : j * dx, dim == 3 ? j * dx : 0.0};
          if (xj[0] == 0.0 && xj[1] == 0.0 && xj[2] == 0.0) continue;
          double vj[3];
          for (int a = 0; a < 3; ++a)
            vj[a] = LINEAR_FIELD[a][0] * xj[0] + LINEAR_FIELD[a][1] * xj[1] +
                (dim == 3 ? LINEAR_FIELD[a][2] * xj[2] : 0.0);
          if (dim == 2) vj[2] = 0.0;
          near.add(j == 0 ? Neighbourhood::GRAIN : Neighbourhood::DUMMY, particle_at(xj, vj, m, rho));
        }
    ParticleRates r = near.rates();
    r.correct_gradient(dim);
    for (int a = 0; a < dim; ++a)
      for (int b = 0; b < dim; ++b) EXPECT_NEAR(r.grad_v[a][b], LINEAR_FIELD[a][b], 1e-12) << dim;
  }
}

// A grain resting half a spacing above three layers of dummy particles at rest, offset by
// `s` spacings along x against their lattice and moving with velocity v: its rates from
// the dummies, entered in full (ParticleRates::add) or along the wall normal only
// (WallVelocitySums).
ParticleRates rates_over_a_floor(double s, const double *v, bool along_normal,
                                 const double *own_normal = nullptr)
{
  const double dx = 0.01, h = 0.012, rho = 2450.0, m = rho * dx * dx * dx;
  const double zero[3] = {0.0, 0.0, 0.0};
  Neighbourhood near(h, 3);
  near.wall_normal = along_normal;
  near.add(Neighbourhood::GRAIN, particle_at(zero, v, m, rho));
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j)
      for (int k = 0; k < 3; ++k) {
        const double xd[3] = {(i - s) * dx, j * dx, -(k + 1) * dx};
        near.add(Neighbourhood::DUMMY, particle_at(xd, zero, m, rho), own_normal);
      }
  return near.rates();
}

// Sliding over the floor, a grain sees the dummies' sums along the wall swing with its
// place against their lattice: a spurious volumetric strain rate (and density rate)
// of half a percent of the shear rate, which a monolayer, held by its weight alone,
// cannot bear (it hops over the floor). Taken along the wall normal, the wall adds the
// same shear and normal rates, and about a tenth of that swing (the normal, from the
// dummies' weighted centre, tilts by a few 1e-4 rad as the grain passes).
TEST(WallGradient, AlongTheNormalTheFloorIsSmooth)
{
  const double slide[3] = {2.0, 0.0, 0.0}, approach[3] = {0.0, 0.0, -0.5};
  for (double s : {0.1, 0.2, 0.3, 0.4}) {
    const ParticleRates full = rates_over_a_floor(s, slide, false);
    const ParticleRates normal = rates_over_a_floor(s, slide, true);
    const double shear = full.grad_v[0][2];
    EXPECT_GT(std::fabs(full.grad_v[0][0]), 2e-3 * std::fabs(shear)) << s;
    EXPECT_LT(std::fabs(normal.grad_v[0][0]), 0.15 * std::fabs(full.grad_v[0][0])) << s;
    EXPECT_LT(std::fabs(normal.drho), 0.15 * std::fabs(full.drho)) << s;
    EXPECT_NEAR(normal.grad_v[0][2], shear, 1e-3 * std::fabs(shear)) << s;
    const ParticleRates full_in = rates_over_a_floor(s, approach, false);
    const ParticleRates normal_in = rates_over_a_floor(s, approach, true);
    EXPECT_NEAR(normal_in.grad_v[2][2], full_in.grad_v[2][2], 1e-3 * std::fabs(full_in.grad_v[2][2]));
    EXPECT_NEAR(normal_in.drho, full_in.drho, 1e-3 * std::fabs(full_in.drho)) << s;
    // the force is not the velocity's: the same either way
    for (int a = 0; a < 3; ++a) EXPECT_EQ(normal.acc[a], full.acc[a]) << s;
  }
  // on a lattice site the two agree
  const ParticleRates full = rates_over_a_floor(0.0, slide, false);
  const ParticleRates normal = rates_over_a_floor(0.0, slide, true);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      EXPECT_NEAR(normal.grad_v[a][b], full.grad_v[a][b], 1e-12 * std::fabs(full.grad_v[0][2]));
}

// Dummies with their own normal (the floor's, +z) enter the rates along it exactly: a
// grain sliding over the floor gets the shear rate and no spurious volumetric rate
// wherever it is against the dummies' lattice, and approaching it the same normal rates
// as with the normal from the dummies' centre.
TEST(WallGradient, OwnNormalsAreExact)
{
  const double up[3] = {0.0, 0.0, 1.0};
  const double slide[3] = {2.0, 0.0, 0.0}, approach[3] = {0.0, 0.0, -0.5};
  for (double s : {0.0, 0.1, 0.2, 0.3, 0.4}) {
    const ParticleRates own = rates_over_a_floor(s, slide, true, up);
    const ParticleRates centre = rates_over_a_floor(s, slide, true);
    EXPECT_EQ(own.grad_v[0][0], 0.0) << s;
    EXPECT_EQ(own.drho, 0.0) << s;
    EXPECT_NEAR(own.grad_v[0][2], centre.grad_v[0][2], 1e-3 * std::fabs(centre.grad_v[0][2])) << s;
    const ParticleRates own_in = rates_over_a_floor(s, approach, true, up);
    const ParticleRates centre_in = rates_over_a_floor(s, approach, true);
    EXPECT_NEAR(own_in.drho, centre_in.drho, 1e-3 * std::fabs(centre_in.drho)) << s;
    EXPECT_NEAR(own_in.grad_v[2][2], centre_in.grad_v[2][2], 1e-3 * std::fabs(centre_in.grad_v[2][2]));
    for (int a = 0; a < 3; ++a) EXPECT_EQ(own.acc[a], centre.acc[a]) << s;
  }
  // on a lattice site, where the centre's normal is +z too, the two agree to round-off
  const ParticleRates own = rates_over_a_floor(0.0, slide, true, up);
  const ParticleRates centre = rates_over_a_floor(0.0, slide, true);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      EXPECT_NEAR(own.grad_v[a][b], centre.grad_v[a][b], 1e-12 * std::fabs(centre.grad_v[0][2]));
}

// Too few neighbours: the correction would divide by a near-singular matrix, so the
// plain gradient stays.
TEST(CorrectedGradient, FewNeighboursKeepThePlainGradient)
{
  Neighbourhood near(0.012, 3);
  const double zero[3] = {0.0, 0.0, 0.0}, xj[3] = {0.01, 0.0, 0.0}, vj[3] = {0.02, 0.0, 0.0};
  near.add(Neighbourhood::GRAIN, particle_at(zero, zero, 1.0, 1000.0));
  near.add(Neighbourhood::GRAIN, particle_at(xj, vj, 1.0, 1000.0));
  ParticleRates r = near.rates();
  const double plain = r.grad_v[0][0];
  EXPECT_NE(plain, 0.0);
  r.correct_gradient(3);
  EXPECT_EQ(r.grad_v[0][0], plain);
}

namespace {
// a dummy particle dz below a grain of stress sk; gravity -z
WallSums one_grain_above(const Sym3 &sk, double rho, double dz)
{
  Neighbourhood near(0.01, 3);
  const double zero[3] = {0.0, 0.0, 0.0}, up[3] = {0.0, 0.0, dz};
  near.add(Neighbourhood::DUMMY, particle_at(zero, zero, 1.0, 1000.0));
  near.add(Neighbourhood::GRAIN, particle_at(up, zero, 1.0, rho, sk));
  return wall_sums(near, 0);
}
const double G_DOWN[3] = {0.0, 0.0, -9.81};
}    // namespace

// Eq. 8 in index form: only the component along gravity gets the weight of the
// grains above the dummy.
TEST(WallSums, PaperAddsTheWeightAlongGravityOnly)
{
  const double rho = 1500.0, dz = 0.01;
  const Sym3 sk{-3000.0, -2000.0, -4000.0, 100.0, 600.0, -300.0};
  const Sym3 sd = one_grain_above(sk, rho, dz).stress(G_DOWN, WallSums::PAPER);
  EXPECT_NEAR(sd.zz, sk.zz - rho * 9.81 * dz, 1e-9);
  EXPECT_NEAR(sd.xx, sk.xx, 1e-9);
  EXPECT_NEAR(sd.xz, sk.xz, 1e-9);
  EXPECT_EQ(WallSums::zero().stress(G_DOWN, WallSums::PAPER).zz, 0.0);    // stress-free
}

// RATIO: the same normal stress on the wall, and the shear stress (and every other
// component) in the grains' proportion to it, so the wall's friction is the grains'.
TEST(WallSums, RatioKeepsTheGrainsStressRatio)
{
  const double rho = 1500.0, dz = 0.01, q = rho * 9.81 * dz;
  const Sym3 sk{-3000.0, -2000.0, -4000.0, 100.0, 600.0, -300.0};
  const Sym3 sd = one_grain_above(sk, rho, dz).stress(G_DOWN, WallSums::RATIO);
  EXPECT_NEAR(sd.zz, sk.zz - q, 1e-9);
  const double growth = (sk.zz - q) / sk.zz;
  for (double ratio : {sd.xx / sk.xx, sd.yy / sk.yy, sd.xy / sk.xy, sd.xz / sk.xz, sd.yz / sk.yz})
    EXPECT_NEAR(ratio, growth, 1e-12);
}

// A stress-free grain (landing) gives the weight alone on the normal; a wall above
// the grains (negative weight) gets no tension; no neighbours, no stress.
TEST(WallSums, RatioLimits)
{
  const double rho = 1500.0, dz = 0.01, q = rho * 9.81 * dz;
  const Sym3 free_fall = one_grain_above(Sym3::zero(), rho, dz).stress(G_DOWN, WallSums::RATIO);
  EXPECT_NEAR(free_fall.zz, -q, 1e-9);
  EXPECT_NEAR(free_fall.xx, 0.0, 1e-12);
  EXPECT_NEAR(free_fall.xz, 0.0, 1e-12);

  // a small stress against q: the other components grow at most max_growth times
  const Sym3 small{-1.0, -1.0, -1.0, 0.0, 0.5, 0.0};
  const Sym3 sd = one_grain_above(small, rho, dz).stress(G_DOWN, WallSums::RATIO);
  EXPECT_NEAR(sd.zz, small.zz - q, 1e-9);
  EXPECT_NEAR(sd.xz, (1.0 + WallSums::max_growth) * small.xz, 1e-12);

  const double g_up[3] = {0.0, 0.0, 9.81};
  const Sym3 sk = Sym3::iso(-100.0);
  const Sym3 ceiling = one_grain_above(sk, rho, dz).stress(g_up, WallSums::RATIO);
  EXPECT_LE(ceiling.zz, 1e-12);
  EXPECT_GE(ceiling.zz, sk.zz);
  EXPECT_EQ(WallSums::zero().stress(G_DOWN, WallSums::RATIO).zz, 0.0);
}

// Under `precision mixed` a grain's sums run in single precision: in a neighbourhood far
// from the origin (the positions' rounding), moving and sheared, under a stress that
// grows with depth, with grains and dummies, every rate is the double one's within 2e-5
// of its scale (measured: 4e-6 for the acceleration, 2e-6 for the velocity gradient), and
// not to the last digit (the sums did run in single precision).
TEST(MixedPrecision, GrainRatesAgreeWithDoubleToSinglePrecision)
{
  const double dx = 0.01, h = 1.2 * dx, rho = 2450.0, m = rho * dx * dx * dx;
  const double origin[3] = {1.37, -0.82, 0.45}, drift[3] = {2.0, -0.5, 1.0};
  const double L[3][3] = {{0.3, -1.2, 0.5}, {0.7, -0.4, 2.0}, {-0.9, 0.25, 0.1}};
  Neighbourhood near(h, 3);
  near.visc = PAPER_VISCOSITY;
  near.shape_sums = false;
  auto add = [&](Neighbourhood::Role role, int i, int j, int k) {
    const double r[3] = {i * dx + 1e-3 * dx * ((i * 7 + j * 3 + k) % 5), j * dx, k * dx};
    double x[3], v[3];
    for (int a = 0; a < 3; ++a) {
      x[a] = origin[a] + r[a];
      v[a] = drift[a] + L[a][0] * r[0] + L[a][1] * r[1] + L[a][2] * r[2];
    }
    const double depth = 0.3 - r[2];    // lithostatic stress, tension positive
    Sym3 sigma = Sym3::iso(-rho * 9.81 * depth);
    sigma.xz = 150.0 * r[0] / dx;
    near.add(role, particle_at(x, v, m, rho * (1.0 + 1e-3 * r[1] / dx), sigma));
  };
  add(Neighbourhood::GRAIN, 0, 0, 0);
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j)
      for (int k = -3; k <= 3; ++k)
        if (i || j || k) add(k < -1 ? Neighbourhood::DUMMY : Neighbourhood::GRAIN, i, j, k);
  const ParticleRates full = near.rates();
  const ParticleRates single = SingleNeighbourhood(near).rates();

  const double acc_scale = rho * 9.81 * 0.3 / (rho * dx);    // the stress over a spacing
  const double grad_scale = 2.0;                            // |L|
  bool all_equal = single.drho == full.drho;
  EXPECT_NEAR(single.drho, full.drho, 2e-5 * rho * grad_scale);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(single.acc[a], full.acc[a], 2e-5 * acc_scale) << "acc " << a;
    all_equal = all_equal && single.acc[a] == full.acc[a];
    for (int b = 0; b < 3; ++b) {
      EXPECT_NEAR(single.grad_v[a][b], full.grad_v[a][b], 2e-5 * grad_scale) << a << b;
      all_equal = all_equal && single.grad_v[a][b] == full.grad_v[a][b];
    }
  }
  const double p_visc = near.viscous_pressure();
  EXPECT_NEAR(SingleNeighbourhood(near).viscous_pressure(), p_visc, 2e-5 * std::fabs(p_visc));
  EXPECT_GT(std::fabs(p_visc), 0.0);
  EXPECT_FALSE(all_equal);    // the single-precision sums ran
}
