/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

// The host's lanes (gransph_lanes.h): granular_rates without options, four neighbours at a
// time, against the generic loop of gransph_neighbour_sums.h on the same particles. Built
// with the plugin's instruction set, only where it has the lanes (unittest/CMakeLists.txt).

#include "aligned_allocator.h"
#include "gransph_lanes.h"
#include "gransph_neighbour_sums.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#if !GRANSPH_LANES
#error "built only where the plugin's flags give the lanes"
#endif

using namespace GRANSPH;

namespace {

// Particles in a box, each a grain, a dummy or neither (massless, as the pair styles pack
// it), with full neighbour rows in a shuffled order, pruned: the accessor of the neighbour
// sums.
struct Box {
  using Real = double;
  enum Role { GRAIN, DUMMY, OTHER };
  AlignedVector<PairParticle> particles;
  std::vector<Role> roles;
  std::vector<std::vector<int>> rows;
  WendlandC2 kernel;
  Viscosity visc{0.25, 0.1, false, Viscosity::BULK};
  bool wall_normal = false, shape_sums = false, wall_friction = false;
  WallStick stick{false, {0.0, 0.0, 0.0}, 0.0};

  struct Row {
    const int *row;
    int operator()(int k) const { return row[k]; }
  };
  // the rows pruned grains first, as the pair styles prune them (prune_row)
  static constexpr double PRUNED_CUTSQ = 2.03 * 2.03;
  bool grains_first = false;
  std::vector<int> count, grains;

  int num_neighbours(int i) const { return grains_first ? count[i] : int(rows[i].size()); }
  int num_grain_neighbours(int i) const { return grains[i]; }
  Row neighbours(int i) const { return {rows[i].data()}; }
  const PairParticle &particle(int i) const { return particles[i]; }
  bool granular(int i) const { return roles[i] == GRAIN; }
  bool wall(int i) const { return roles[i] == DUMMY; }
  double normal(int, int) const { return 0.0; }
  double friction(int) const { return -1.0; }
  double slide(int, int) const { return 0.0; }

  // n particles in a cube of side `side` h (the last few far from all others, with rows
  // of fewer than four neighbours), rows within reach h
  Box(int n, double side, double reach, unsigned seed) : kernel(WendlandC2::make(1.0, 3))
  {
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < n; ++i) {
      const double spread = i < n - 6 ? side : 0.6 * side;
      double x[3] = {spread * u(gen), spread * u(gen), spread * u(gen)};
      if (i >= n - 6) x[0] += 40.0 + 3.5 * (i - (n - 6));    // isolated pairs and loners
      const double v[3] = {0.3 * u(gen), 0.3 * u(gen), 0.3 * u(gen)};
      const Sym3 s{-1e4 + 3e3 * u(gen), -1e4 + 3e3 * u(gen), -2e4 + 3e3 * u(gen),
                   2e3 * u(gen),        2e3 * u(gen),        2e3 * u(gen)};
      const double pick = 0.5 * (u(gen) + 1.0);
      const Role role = pick < 0.7 ? GRAIN : pick < 0.95 ? DUMMY : OTHER;
      const double mass = role == OTHER ? 0.0 : 2.0 + u(gen);
      particles.push_back(PairParticle::make(x, v, mass, 2000.0 * (1.0 + 0.05 * u(gen)), s,
                                             40.0 + 5.0 * u(gen)));
      roles.push_back(role);
    }
    rows.resize(n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        double rsq = 0.0;
        for (int a = 0; a < 3; ++a)
          rsq += (particles[i].x[a] - particles[j].x[a]) * (particles[i].x[a] - particles[j].x[a]);
        if (j != i && rsq < reach * reach) rows[i].push_back(j);
      }
      std::shuffle(rows[i].begin(), rows[i].end(), gen);
    }
    const auto at = [this](int j, int a) { return particles[j].x[a]; };
    for (int i = 0; i < n; ++i) {
      std::vector<int> &row = rows[i];
      const PrunedRow pruned =
          prune_row<true>(*this, i, at, PRUNED_CUTSQ, [&row](int k) -> int & { return row[k]; });
      count.push_back(pruned.count);
      grains.push_back(pruned.grains);
    }
    grains_first = true;
  }

  double rsq(int i, int j) const
  {
    double r = 0.0;
    for (int a = 0; a < 3; ++a)
      r += (particles[i].x[a] - particles[j].x[a]) * (particles[i].x[a] - particles[j].x[a]);
    return r;
  }
};

// The same particles in single precision, as the pair styles give them to the grains'
// sums under `precision mixed`
struct SingleBox {
  using Real = float;
  const Box &box;
  AlignedVector<PairParticleSingle> particles;
  WendlandC2 kernel;
  Viscosity visc;
  bool wall_normal = false, shape_sums = false, wall_friction = false;
  WallStick stick;

  explicit SingleBox(const Box &b) : box(b), kernel(b.kernel), visc(b.visc), stick(b.stick)
  {
    const double origin[3] = {0.0, 0.0, 0.0};
    for (const PairParticle &p : b.particles) particles.push_back(PairParticleSingle::of(p, origin));
  }
  bool grains_first = box.grains_first;
  int num_neighbours(int i) const { return box.num_neighbours(i); }
  int num_grain_neighbours(int i) const { return box.num_grain_neighbours(i); }
  Box::Row neighbours(int i) const { return box.neighbours(i); }
  const PairParticleSingle &particle(int i) const { return particles[i]; }
  bool granular(int i) const { return box.granular(i); }
  bool wall(int i) const { return box.wall(i); }
  double normal(int, int) const { return 0.0; }
  double friction(int) const { return -1.0; }
  double slide(int, int) const { return 0.0; }
};

// the 13 rates of the lanes' sums against the generic loop's, over every grain, to
// `tolerance` of their largest
template <class Particles> void expect_lanes_match(const Particles &box, double tolerance = 1e-13)
{
  double scale = 0.0, diff = 0.0;
  int compared = 0;
  for (int i = 0; i < int(box.particles.size()); ++i) {
    if (!box.granular(i)) continue;
    const ParticleRates a = granular_rates(box, i, nullptr, nullptr);
    const ParticleRates b = granular_rates<false, false, false, false>(box, i, nullptr, nullptr);
    double va[13] = {a.drho, a.acc[0], a.acc[1], a.acc[2]}, vb[13] = {b.drho, b.acc[0], b.acc[1], b.acc[2]};
    for (int c = 0; c < 9; ++c) {
      va[4 + c] = a.grad_v[c / 3][c % 3];
      vb[4 + c] = b.grad_v[c / 3][c % 3];
    }
    for (int c = 0; c < 13; ++c) {
      ASSERT_TRUE(std::isfinite(va[c])) << "grain " << i << " rate " << c;
      scale = std::max(scale, std::fabs(vb[c]));
      diff = std::max(diff, std::fabs(va[c] - vb[c]));
    }
    for (int c = 0; c < 6; ++c) EXPECT_EQ((&a.shape.xx)[c], 0.0);
    ++compared;
  }
  EXPECT_GT(compared, 100);
  EXPECT_GT(scale, 0.0);
  EXPECT_LE(diff, tolerance * scale) << "largest difference " << diff << " of rates up to " << scale;
}

}    // namespace

TEST(Lanes, PruneRowsGrainsFirst)
{
  // a grain's row: the grains within reach, then the dummies; a dummy's: the grains; the
  // rest of the row behind them, none lost
  const Box box(400, 2.5, 2.2, 7);
  int grains_with_dummies = 0;
  for (int i = 0; i < int(box.particles.size()); ++i) {
    std::vector<int> enter, front(box.rows[i].begin(), box.rows[i].begin() + box.count[i]);
    for (const int j : box.rows[i])
      if ((box.granular(j) || (box.granular(i) && box.wall(j))) && box.rsq(i, j) < Box::PRUNED_CUTSQ &&
          (box.granular(i) || box.wall(i)))
        enter.push_back(j);
    std::sort(enter.begin(), enter.end());
    std::sort(front.begin(), front.end());
    EXPECT_EQ(front, enter) << "particle " << i;
    for (int k = 0; k < box.count[i]; ++k)
      EXPECT_EQ(box.granular(box.rows[i][k]), k < box.grains[i]) << "particle " << i << ", entry " << k;
    grains_with_dummies += box.granular(i) && box.grains[i] > 0 && box.count[i] > box.grains[i];
  }
  EXPECT_GT(grains_with_dummies, 50);

  // in a run without walls: the grains only
  Box again(400, 2.5, 2.2, 7);
  const auto at = [&again](int j, int a) { return again.particles[j].x[a]; };
  again.grains_first = false;
  for (int i = 0; i < int(again.particles.size()); ++i) {
    if (!again.granular(i)) continue;
    std::vector<int> &row = again.rows[i];
    const PrunedRow pruned =
        prune_row<false>(again, i, at, Box::PRUNED_CUTSQ, [&row](int k) -> int & { return row[k]; });
    EXPECT_EQ(pruned.count, box.grains[i]) << "particle " << i;
    EXPECT_EQ(pruned.grains, pruned.count) << "particle " << i;
    std::vector<int> front(row.begin(), row.begin() + pruned.count),
        grains(box.rows[i].begin(), box.rows[i].begin() + box.grains[i]);
    std::sort(front.begin(), front.end());
    std::sort(grains.begin(), grains.end());
    EXPECT_EQ(front, grains) << "particle " << i;
  }
}

TEST(Lanes, TakeThePlainRatesOfBothRecords)
{
  EXPECT_TRUE(SumsInLanes<Box>::value);
  EXPECT_TRUE(SumsInLanes<SingleBox>::value);
}

TEST(Lanes, MatchTheGenericLoop)
{
  // rows of 0 to about 60 neighbours, within and beyond the support 2h
  expect_lanes_match(Box(400, 2.5, 2.2, 1));
}

TEST(Lanes, MatchTheGenericLoopWithViscosityAtWalls)
{
  Box box(400, 2.5, 2.2, 2);
  box.visc.walls = true;
  expect_lanes_match(box);
}

TEST(Lanes, MatchTheGenericLoopInSinglePrecision)
{
  // eight single-precision lanes against the generic loop's, both summing in float: they
  // differ by single precision's rounding, a few parts in 1e7 of the rates' scale
  const Box box(400, 2.5, 2.2, 4);
  expect_lanes_match(SingleBox(box), 2e-6);
}

TEST(Lanes, MatchTheGenericLoopInTheWallSums)
{
  // eq. 8's sums of every dummy over its grains, against the generic loop's
  const Box box(400, 2.5, 2.2, 5);
  double scale = 0.0, diff = 0.0;
  int compared = 0;
  for (int d = 0; d < int(box.particles.size()); ++d) {
    if (!box.wall(d)) continue;
    const WallSums a = wall_sums(box, d), b = wall_sums(box, d, std::false_type());
    const double va[10] = {a.sigma_w.xx, a.sigma_w.yy, a.sigma_w.zz, a.sigma_w.xy, a.sigma_w.xz,
                           a.sigma_w.yz, a.rho_r_w[0], a.rho_r_w[1], a.rho_r_w[2], a.w};
    const double vb[10] = {b.sigma_w.xx, b.sigma_w.yy, b.sigma_w.zz, b.sigma_w.xy, b.sigma_w.xz,
                           b.sigma_w.yz, b.rho_r_w[0], b.rho_r_w[1], b.rho_r_w[2], b.w};
    for (int c = 0; c < 10; ++c) {
      scale = std::max(scale, std::fabs(vb[c]));
      diff = std::max(diff, std::fabs(va[c] - vb[c]));
    }
    compared += b.w > 0.0;
  }
  EXPECT_GT(compared, 50);
  EXPECT_LE(diff, 1e-13 * scale) << "largest difference " << diff << " of sums up to " << scale;
}

TEST(Lanes, MatchTheGenericLoopInTheWallForce)
{
  // eq. 9's force of the grains on every dummy, with and without viscosity at the walls
  for (bool walls : {false, true}) {
    Box box(400, 2.5, 2.2, 6);
    box.visc.walls = walls;
    double scale = 0.0, diff = 0.0;
    for (int d = 0; d < int(box.particles.size()); ++d) {
      if (!box.wall(d)) continue;
      double a[3], b[3];
      wall_force(box, d, a, nullptr);
      wall_force<false, false>(box, d, b, nullptr);
      for (int c = 0; c < 3; ++c) {
        scale = std::max(scale, std::fabs(b[c]));
        diff = std::max(diff, std::fabs(a[c] - b[c]));
      }
    }
    EXPECT_GT(scale, 0.0);
    EXPECT_LE(diff, 1e-13 * scale) << "visc/walls " << walls << ": largest difference " << diff
                                   << " of forces up to " << scale;
  }
}

TEST(Lanes, LeaveOptionsAndRowsNotPrunedToTheGenericLoop)
{
  // with the corrected gradient's shape sums, or over rows not pruned, the rates are the
  // generic loop's, bit for bit
  for (const bool shape : {true, false}) {
    Box box(200, 2.5, 2.2, 3);
    box.shape_sums = shape;
    box.grains_first = shape;
    for (int i = 0; i < 200; ++i) {
      if (!box.granular(i)) continue;
      const ParticleRates a = granular_rates(box, i, nullptr, nullptr);
      const ParticleRates b = shape
          ? granular_rates<false, true, false, false>(box, i, nullptr, nullptr)
          : granular_rates<false, false, false, false>(box, i, nullptr, nullptr);
      EXPECT_EQ(a.drho, b.drho);
      EXPECT_EQ(a.acc[0], b.acc[0]);
      EXPECT_EQ(a.grad_v[2][1], b.grad_v[2][1]);
      EXPECT_EQ(a.shape.xx, b.shape.xx);
    }
  }
}
