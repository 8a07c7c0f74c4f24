/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   A study of loop shapes for the grains' sums (issue 21; bench/README.md,
   eleventh round), beside the plugin: granular_rates without options over
   each grain's pruned row in three shapes,
     - the generic loop (an omp simd reduction, its vectors assembled field by
       field and lane by lane),
     - the host's lanes (gransph_lanes.h: four neighbours' records loaded whole
       and transposed), which the pair style runs where it has them,
     - each pair once over clusters of four grains (GROMACS' cluster pairs: a
       grain against the four lanes of each cluster near it, whose values sit
       side by side; the pair's terms go to the grain's sums and the cluster's),
   on a perturbed cubic lattice of grains, with the plugin's own pair terms.
   Prints the clusters' pair efficiency and each shape's time (the best of N
   second runs in a row, the shapes in turn), and exits non-zero if the
   shapes' sums differ beyond round-off (ctest Bench:loop_shapes runs it
   small, that it cannot rot; its times mean nothing there).

     gransph_loop_shapes [edge] [repeats]    edge^3 grains (default 36)
------------------------------------------------------------------------- */

#include "aligned_allocator.h"
#include "gransph_lanes.h"
#include "gransph_neighbour_sums.h"

#include <immintrin.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <vector>

#if !GRANSPH_LANES
#error "the study needs the host's lanes (gransph_lanes.h: AVX2 and FMA)"
#endif

namespace {
using namespace GRANSPH;

// the accessor of the plugin's host sums (grains only, no wall options)
struct Rows {
  struct Row {
    const int *row;
    int operator()(int k) const { return row[k]; }
  };
  using Real = double;
  const PairParticle *parts;
  const int *const *first;
  const int *num;
  WendlandC2 kernel;
  Viscosity visc;
  bool wall_normal = false, shape_sums = false, wall_friction = false;
  WallStick stick{};
  int num_neighbours(int i) const { return num[i]; }
  Row neighbours(int i) const { return {first[i]}; }
  const PairParticle &particle(int i) const { return parts[i]; }
  bool granular(int) const { return true; }
  bool wall(int) const { return false; }
  double normal(int, int) const { return 0.0; }
  double friction(int) const { return -1.0; }
  double slide(int, int) const { return 0.0; }
  bool grains_first = true;    // grains only
  int num_grain_neighbours(int i) const { return num[i]; }
};

constexpr int NSUM = 13;    // drho, acc (3), grad_v (9)

// the lanes where c holds
Mask4 where(const bool *c)
{
  return {_mm256_castsi256_pd(_mm256_set_epi64x(-(long long) c[3], -(long long) c[2],
                                                -(long long) c[1], -(long long) c[0]))};
}

// four grains' values, each field's four side by side (a PairParticle record's fields)
struct alignas(64) Cluster {
  double f[16][4];
};
struct alignas(64) ClusterSums {
  double s[NSUM][4];
};
constexpr int X = 0, V = 3, RHO = 6, C = 7, SXX = 8, SYY = 9, SZZ = 10, SXY = 11, SXZ = 12,
              SYZ = 13, MASS = 14, INV_RHO = 15;

struct Grains {
  AlignedVector<PairParticle> p;    // in cluster order
  std::vector<int> lane;          // cluster lane -> grain (-1: empty lane)
  std::vector<std::vector<int>> rows;
  std::vector<std::vector<int>> clusters_near;    // grain -> clusters J >= its own, near it
  long lane_pairs = 0, pairs = 0;
};

// a perturbed simple cubic lattice of spacing 1 in clusters of four: columns of 2 x 2
// lattice sites, each sorted by height and cut into fours (one layer of the column)
Grains make_grains(int edge, double h, double cut)
{
  std::mt19937 gen(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int columns = (edge + 1) / 2;
  std::vector<AlignedVector<PairParticle>> column(columns * columns);
  for (int a = 0; a < edge; ++a)
    for (int b = 0; b < edge; ++b)
      for (int c = 0; c < edge; ++c) {
        const double x[3] = {a + 0.05 * u(gen), b + 0.05 * u(gen), c + 0.05 * u(gen)};
        const double v[3] = {0.01 * u(gen), 0.01 * u(gen), 0.01 * u(gen)};
        const Sym3 s{-1e3 + 100 * u(gen), -1e3 + 100 * u(gen), -2e3 + 100 * u(gen),
                     50 * u(gen),         50 * u(gen),         50 * u(gen)};
        column[(a / 2) * columns + b / 2].push_back(
            PairParticle::make(x, v, 1.0, 1.0 + 0.01 * u(gen), s, 30.0));
      }
  Grains g;
  for (auto &col : column) {
    std::sort(col.begin(), col.end(),
              [](const PairParticle &a, const PairParticle &b) { return a.x[2] < b.x[2]; });
    for (size_t k = 0; k < col.size(); k += 4)
      for (size_t l = 0; l < 4; ++l) {
        g.lane.push_back(k + l < col.size() ? int(g.p.size()) : -1);
        if (k + l < col.size()) g.p.push_back(col[k + l]);
      }
  }
  const int n = g.p.size();
  std::vector<int> cluster_of(n);
  for (size_t s = 0; s < g.lane.size(); ++s)
    if (g.lane[s] >= 0) cluster_of[g.lane[s]] = s / 4;
  // rows within cut, from a grid of cells of side cut
  const int cells = int(edge / cut) + 3;
  auto cell = [&](double x) { return std::min(cells - 1, std::max(0, int((x + 1.0) / cut))); };
  std::vector<std::vector<int>> grid(cells * cells * cells);
  for (int i = 0; i < n; ++i)
    grid[(cell(g.p[i].x[0]) * cells + cell(g.p[i].x[1])) * cells + cell(g.p[i].x[2])].push_back(i);
  g.rows.resize(n);
  g.clusters_near.resize(n);
  for (int i = 0; i < n; ++i) {
    const int cx = cell(g.p[i].x[0]), cy = cell(g.p[i].x[1]), cz = cell(g.p[i].x[2]);
    for (int a = std::max(0, cx - 1); a <= std::min(cells - 1, cx + 1); ++a)
      for (int b = std::max(0, cy - 1); b <= std::min(cells - 1, cy + 1); ++b)
        for (int c = std::max(0, cz - 1); c <= std::min(cells - 1, cz + 1); ++c)
          for (int j : grid[(a * cells + b) * cells + c]) {
            double rsq = 0.0;
            for (int d = 0; d < 3; ++d) rsq += (g.p[i].x[d] - g.p[j].x[d]) * (g.p[i].x[d] - g.p[j].x[d]);
            if (j == i || rsq >= cut * cut) continue;
            g.rows[i].push_back(j);
            if (j > i && rsq < 4.0 * h * h) ++g.pairs;
            if (cluster_of[j] >= cluster_of[i]) g.clusters_near[i].push_back(cluster_of[j]);
          }
    std::sort(g.rows[i].begin(), g.rows[i].end());
    auto &near = g.clusters_near[i];
    near.push_back(cluster_of[i]);
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (int J : near) g.lane_pairs += J == cluster_of[i] ? 3 : 4;
  }
  return g;
}

// Each grain-grain pair once: grain i (lane a of cluster I) against the four lanes of each
// cluster J >= I near it (lanes above a in its own), its sums in lanes reduced at the end
// of its clusters, cluster J's added to J's sums. drho_j and grad_v_j take the pair's
// products with i's mass and volume, acc_j the opposite of i's bracket times m_i. Sums by
// fused multiply-adds, as the plugin's lanes add them.
__attribute__((noinline)) void cluster_sums(const Grains &g, AlignedVector<Cluster> &cl,
                                            AlignedVector<ClusterSums> &sums,
                                            const WendlandC2 &kernel_d, const Viscosity &visc,
                                            std::vector<double> &out)
{
  const int nclusters = cl.size();
  const PairParticle far{{1e30, 1e30, 1e30}, {0, 0, 0}, 1.0, 1.0, Sym3::zero(), 0.0, 1.0};
  for (int C = 0; C < nclusters; ++C) {    // the step's packing
    for (int l = 0; l < 4; ++l) {
      const int k = g.lane[4 * C + l];
      const double *record = (k >= 0 ? g.p[k] : far).x;
      for (int q = 0; q < 16; ++q) cl[C].f[q][l] = record[q];
    }
    sums[C] = ClusterSums{};
  }
  const WendlandC2Of<Lanes4> kernel = kernel_d.in_precision<Lanes4>();
  const Lanes4 cutsq = kernel.cutsq(), h = kernel.h;
  const bool all[4] = {true, true, true, true};
  const Mask4 grains = where(all);
  for (int I = 0; I < nclusters; ++I)
    for (int a = 0; a < 4; ++a) {
      const int i = g.lane[4 * I + a];
      if (i < 0) continue;
      const auto &fi = cl[I].f;
      const Lanes4 xi = fi[X][a], yi = fi[X + 1][a], zi = fi[X + 2][a], vxi = fi[V][a],
                   vyi = fi[V + 1][a], vzi = fi[V + 2][a], rho_i = fi[RHO][a], c_i = fi[C][a],
                   m_i = fi[MASS][a], inv_rho_i = fi[INV_RHO][a], sxx_i = fi[SXX][a],
                   syy_i = fi[SYY][a], szz_i = fi[SZZ][a], sxy_i = fi[SXY][a],
                   sxz_i = fi[SXZ][a], syz_i = fi[SYZ][a];
      const Lanes4 minus_volume_i = -(m_i * inv_rho_i), minus_m_i = -m_i;
      const bool above[4] = {0 > a, 1 > a, 2 > a, 3 > a};
      const Mask4 above_a = where(above);
      Lanes4 s[NSUM];
      for (int q = 0; q < NSUM; ++q) s[q] = 0.0;
      for (const int J : g.clusters_near[i]) {
        const auto &fj = cl[J].f;
        auto &sj = sums[J].s;
        const auto field = [&](int q) { return Lanes4(_mm256_load_pd(fj[q])); };
        // j's sum q plus a b
        const auto add_to_j = [&](int q, Lanes4 a, Lanes4 b) {
          Lanes4 v = _mm256_load_pd(sj[q]);
          add_product(v, a, b);
          _mm256_store_pd(sj[q], v.v);
        };
        const Lanes4 rx = xi - field(X), ry = yi - field(X + 1), rz = zi - field(X + 2);
        const Lanes4 rsq = rx * rx + ry * ry + rz * rz;
        Mask4 inside = rsq < cutsq;
        if (J == I) inside = inside & above_a;
        const Lanes4 fw = zero_unless(inside, kernel.grad_factor_inside(kernel.q(rsq)));
        const Lanes4 gw[3] = {fw * rx, fw * ry, fw * rz};
        const Lanes4 dv[3] = {vxi - field(V), vyi - field(V + 1), vzi - field(V + 2)};
        const Lanes4 pi_ij = pair_viscosity(dv[0] * rx + dv[1] * ry + dv[2] * rz, rsq, h, visc,
                                            c_i, field(C), rho_i, field(RHO), grains);
        const Lanes4 inv_rho_ij = inv_rho_i * field(INV_RHO);
        const Lanes4 sxx = sxx_i + field(SXX), syy = syy_i + field(SYY), szz = szz_i + field(SZZ);
        const Lanes4 sxy = sxy_i + field(SXY), sxz = sxz_i + field(SXZ), syz = syz_i + field(SYZ);
        const Lanes4 t[3] = {
            stress_gradient(sxx, sxy, sxz, inv_rho_ij, pi_ij, gw[0], gw[1], gw[2], gw[0]),
            stress_gradient(sxy, syy, syz, inv_rho_ij, pi_ij, gw[0], gw[1], gw[2], gw[1]),
            stress_gradient(sxz, syz, szz, inv_rho_ij, pi_ij, gw[0], gw[1], gw[2], gw[2])};
        const Lanes4 dv_dot_g = dv[0] * gw[0] + dv[1] * gw[1] + dv[2] * gw[2];
        const Lanes4 m_j = field(MASS), minus_volume_j = -(m_j * field(INV_RHO));
        add_product(s[0], m_j, dv_dot_g);
        add_to_j(0, m_i, dv_dot_g);
        for (int c = 0; c < 3; ++c) {
          add_product(s[1 + c], m_j, t[c]);
          add_to_j(1 + c, minus_m_i, t[c]);
        }
        for (int c = 0; c < 3; ++c) {
          const Lanes4 wi = minus_volume_j * dv[c], wj = minus_volume_i * dv[c];
          for (int d = 0; d < 3; ++d) {
            add_product(s[4 + 3 * c + d], wi, gw[d]);
            add_to_j(4 + 3 * c + d, wj, gw[d]);
          }
        }
      }
      for (int q = 0; q < NSUM; ++q) sums[I].s[q][a] += s[q].sum();
    }
  for (int C = 0; C < nclusters; ++C)
    for (int l = 0; l < 4; ++l)
      if (g.lane[4 * C + l] >= 0)
        for (int q = 0; q < NSUM; ++q) out[NSUM * g.lane[4 * C + l] + q] = sums[C].s[q][l];
}

double now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}    // namespace

int main(int argc, char **argv)
{
  const int edge = argc > 1 ? std::atoi(argv[1]) : 36;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 15;
  const double h = 1.2, cut = 2.03 * h;    // the pair style's default prune margin
  const Grains g = make_grains(edge, h, cut);
  const int n = g.p.size();
  const int nclusters = g.lane.size() / 4;
  std::vector<const int *> first(n);
  std::vector<int> num(n);
  long row_pairs = 0;
  for (int i = 0; i < n; ++i) {
    first[i] = g.rows[i].data();
    num[i] = g.rows[i].size();
    row_pairs += num[i];
  }
  const Viscosity visc{0.25, 0.0, false, Viscosity::BULK};
  const Rows rows{g.p.data(), first.data(), num.data(), WendlandC2::make(h, 3), visc};
  // the shapes' sums: the generic loop over the rows, the host's lanes over the rows (what
  // the pair style runs where it has them), the clusters
  std::vector<double> sums_of[3] = {std::vector<double>(NSUM * n), std::vector<double>(NSUM * n),
                                    std::vector<double>(NSUM * n)};
  AlignedVector<Cluster> cl(nclusters);
  AlignedVector<ClusterSums> sums(nclusters);
  const auto keep = [&](int shape, int i, const ParticleRates &r) {
    double *o = &sums_of[shape][NSUM * i];
    o[0] = r.drho;
    for (int c = 0; c < 3; ++c) o[1 + c] = r.acc[c];
    for (int c = 0; c < 9; ++c) o[4 + c] = r.grad_v[c / 3][c % 3];
  };
  const std::function<void()> shapes[3] = {
      [&]() {
        for (int i = 0; i < n; ++i)
          keep(0, i, granular_rates<false, false, false, false>(rows, i, nullptr, nullptr));
      },
      [&]() {
        for (int i = 0; i < n; ++i) keep(1, i, granular_rates(rows, i, nullptr, nullptr));
      },
      [&]() { cluster_sums(g, cl, sums, rows.kernel, visc, sums_of[2]); }};
  // each shape timed on its second run in a row (its data in the caches, as from one
  // step to the next), the shapes in turn
  double best[3] = {1e30, 1e30, 1e30};
  for (int r = 0; r < repeats; ++r)
    for (int k = 0; k < 3; ++k) {
      shapes[k]();
      const double t0 = now();
      shapes[k]();
      best[k] = std::min(best[k], now() - t0);
    }
  double scale = 0.0, diff[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < NSUM * n; ++k) {
    scale = std::max(scale, std::fabs(sums_of[0][k]));
    for (int shape = 1; shape < 3; ++shape)
      diff[shape] = std::max(diff[shape], std::fabs(sums_of[0][k] - sums_of[shape][k]));
  }
  std::printf("%d grains in %d clusters of four; rows %.1f neighbours a grain; clusters: %ld "
              "lane-pairs for %ld pairs within 2h, efficiency %.3f\n",
              n, nclusters, double(row_pairs) / n, g.lane_pairs, g.pairs,
              double(g.pairs) / g.lane_pairs);
  std::printf("rows, the generic loop: %.0f ns a grain\n", 1e9 * best[0] / n);
  const char *names[3] = {"", "rows, the host's lanes", "clusters, each pair once"};
  for (int shape = 1; shape < 3; ++shape)
    std::printf("%s: %.0f ns a grain, %.2fx the generic loop; largest difference %.2g of sums "
                "up to %.3g\n", names[shape], 1e9 * best[shape] / n, best[0] / best[shape],
                diff[shape], scale);
  const double tolerance = 1e-12 * scale;
  if (!(diff[1] <= tolerance && diff[2] <= tolerance)) {
    std::printf("FAILED: the sums differ beyond %.2g\n", tolerance);
    return 1;
  }
  return 0;
}
