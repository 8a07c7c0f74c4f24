/* ----------------------------------------------------------------------
   A study of a loop shape for the grains' sums (issue 21; bench/README.md,
   eleventh round), not part of the plugin: the grain-grain sums of
   granular_rates over each grain's pruned row, as the pair style runs them,
   against each pair once over clusters of four grains (GROMACS' cluster
   pairs: a grain against the four lanes of each cluster near it, whose values
   load as whole vectors; the pair's terms go to the grain's sums and to the
   cluster's). The pair terms are the plugin's own (gransph_pair_terms.h,
   gransph_kernel.h) on a four-lane type. Prints the clusters' pair efficiency
   and each shape's time (the best of N second runs in a row, the shapes in
   turn), and exits non-zero if the shapes' sums differ beyond round-off (ctest
   Bench:cluster_pairs runs it small, that it cannot rot; its times mean
   nothing there).

     gransph_cluster_pairs_study [edge] [repeats]    edge^3 grains (default 36)
------------------------------------------------------------------------- */

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

namespace GRANSPH {

// four doubles in one 256-bit vector, with the arithmetic the pair terms use
struct Lanes4 {
  typedef double v4 __attribute__((vector_size(32)));
  v4 v;
  Lanes4() = default;
  Lanes4(double s) : v(v4{} + s) {}
  Lanes4(v4 a) : v(a) {}
  double operator[](int k) const { return v[k]; }
  friend Lanes4 operator+(Lanes4 a, Lanes4 b) { return a.v + b.v; }
  friend Lanes4 operator-(Lanes4 a, Lanes4 b) { return a.v - b.v; }
  friend Lanes4 operator*(Lanes4 a, Lanes4 b) { return a.v * b.v; }
  friend Lanes4 operator/(Lanes4 a, Lanes4 b) { return a.v / b.v; }
  friend Lanes4 operator-(Lanes4 a) { return -a.v; }
  Lanes4 &operator+=(Lanes4 a) { v += a.v; return *this; }
};
struct Mask4 {
  typedef long long m4 __attribute__((vector_size(32)));
  m4 m;
  friend Mask4 operator&(Mask4 a, Mask4 b) { return {a.m & b.m}; }
};
inline Mask4 operator<(Lanes4 a, Lanes4 b) { return {a.v < b.v}; }
inline Lanes4 select(Mask4 c, Lanes4 a, Lanes4 b) { return c.m ? a.v : b.v; }
inline Lanes4 square_root(Lanes4 a) { return (Lanes4::v4) _mm256_sqrt_pd((__m256d) a.v); }
inline Lanes4 magnitude(Lanes4 a) { return (Lanes4::v4) _mm256_andnot_pd(_mm256_set1_pd(-0.0), (__m256d) a.v); }
inline double lane_sum(Lanes4 a) { return (a[0] + a[1]) + (a[2] + a[3]); }

// acc + a b: fused where FUSED and the instruction set has it (written in the source,
// so the plugin's -ffp-contract=off leaves it), else rounded twice
template <bool FUSED> inline void add_product(Lanes4 &acc, Lanes4 a, Lanes4 b)
{
#ifdef __FMA__
  if (FUSED) {
    acc = (Lanes4::v4) _mm256_fmadd_pd((__m256d) a.v, (__m256d) b.v, (__m256d) acc.v);
    return;
  }
#endif
  acc += a * b;
}

}    // namespace GRANSPH

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
};

// 64-byte aligned storage for std::vector (C++14's operator new does not honour alignas)
template <class T> struct Aligned64 {
  using value_type = T;
  Aligned64() = default;
  template <class U> Aligned64(const Aligned64<U> &) {}
  T *allocate(size_t n) { return static_cast<T *>(aligned_alloc(64, (n * sizeof(T) + 63) / 64 * 64)); }
  void deallocate(T *p, size_t) { free(p); }
  template <class U> bool operator==(const Aligned64<U> &) const { return true; }
  template <class U> bool operator!=(const Aligned64<U> &) const { return false; }
};
template <class T> using AlignedVector = std::vector<T, Aligned64<T>>;

constexpr int NSUM = 13;    // drho, acc (3), grad_v (9)

// four grains' values, each field one vector
struct alignas(64) Cluster {
  Lanes4 x, y, z, vx, vy, vz, rho, c, sxx, syy, szz, sxy, sxz, syz, m, inv_rho;
};
struct alignas(64) ClusterSums {
  Lanes4 s[NSUM];
};

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
// products with i's mass and volume, acc_j the opposite of i's bracket times m_i.
template <bool FUSED>
__attribute__((noinline)) void cluster_sums(const Grains &g, AlignedVector<Cluster> &cl, AlignedVector<ClusterSums> &sums,
                  const WendlandC2 &kernel_d, const Viscosity &visc, std::vector<double> &out)
{
  const int nclusters = cl.size();
  const PairParticle far{{1e30, 1e30, 1e30}, {0, 0, 0}, 1.0, 1.0, Sym3::zero(), 0.0, 1.0};
  for (int C = 0; C < nclusters; ++C) {    // the step's packing
    double *f = &cl[C].x.v[0];
    for (int l = 0; l < 4; ++l) {
      const int k = g.lane[4 * C + l];
      const PairParticle &s = k >= 0 ? g.p[k] : far;
      const double values[16] = {s.x[0],     s.x[1],     s.x[2],     s.v[0],     s.v[1],     s.v[2],
                                 s.rho,      s.c,        s.sigma.xx, s.sigma.yy, s.sigma.zz, s.sigma.xy,
                                 s.sigma.xz, s.sigma.yz, s.mass,     s.inv_rho};
      for (int q = 0; q < 16; ++q) f[4 * q + l] = values[q];
    }
    sums[C] = ClusterSums{};
  }
  const WendlandC2Of<Lanes4> kernel = kernel_d.in_precision<Lanes4>();
  const Lanes4 cutsq = kernel.cutsq(), h = kernel.h;
  const Lanes4::v4 lane = {0, 1, 2, 3};
  for (int I = 0; I < nclusters; ++I)
    for (int a = 0; a < 4; ++a) {
      const int i = g.lane[4 * I + a];
      if (i < 0) continue;
      const Cluster &ci = cl[I];
      const Lanes4 xi = ci.x[a], yi = ci.y[a], zi = ci.z[a], vxi = ci.vx[a], vyi = ci.vy[a],
                   vzi = ci.vz[a], rho_i = ci.rho[a], c_i = ci.c[a], m_i = ci.m[a],
                   inv_rho_i = ci.inv_rho[a], sxx_i = ci.sxx[a], syy_i = ci.syy[a],
                   szz_i = ci.szz[a], sxy_i = ci.sxy[a], sxz_i = ci.sxz[a], syz_i = ci.syz[a];
      const Lanes4 minus_volume_i = -(m_i * inv_rho_i);
      const Mask4 above_a{lane > Lanes4::v4{} + a};
      Lanes4 s[NSUM] = {};
      for (const int J : g.clusters_near[i]) {
        const Cluster &cj = cl[J];
        Lanes4 *sj = sums[J].s;
        const Lanes4 rx = xi - cj.x, ry = yi - cj.y, rz = zi - cj.z;
        const Lanes4 rsq = rx * rx + ry * ry + rz * rz;
        Mask4 inside = rsq < cutsq;
        if (J == I) inside = inside & above_a;
        const Lanes4 fw = select(inside, kernel.grad_factor_inside(kernel.q(rsq)), 0.0);
        const Lanes4 gwx = fw * rx, gwy = fw * ry, gwz = fw * rz;
        const Lanes4 dvx = vxi - cj.vx, dvy = vyi - cj.vy, dvz = vzi - cj.vz;
        const Lanes4 pi_ij = pair_viscosity(dvx * rx + dvy * ry + dvz * rz, rsq, h, visc, c_i,
                                            cj.c, rho_i, cj.rho, true);
        const Lanes4 inv_rho_ij = inv_rho_i * cj.inv_rho;
        const Lanes4 sxx = sxx_i + cj.sxx, syy = syy_i + cj.syy, szz = szz_i + cj.szz;
        const Lanes4 sxy = sxy_i + cj.sxy, sxz = sxz_i + cj.sxz, syz = syz_i + cj.syz;
        const Lanes4 t[3] = {stress_gradient(sxx, sxy, sxz, inv_rho_ij, pi_ij, gwx, gwy, gwz, gwx),
                             stress_gradient(sxy, syy, syz, inv_rho_ij, pi_ij, gwx, gwy, gwz, gwy),
                             stress_gradient(sxz, syz, szz, inv_rho_ij, pi_ij, gwx, gwy, gwz, gwz)};
        const Lanes4 dv_dot_g = dvx * gwx + dvy * gwy + dvz * gwz;
        const Lanes4 m_j = cj.m, minus_volume_j = -(m_j * cj.inv_rho), minus_m_i = -m_i;
        add_product<FUSED>(s[0], m_j, dv_dot_g);
        add_product<FUSED>(sj[0], m_i, dv_dot_g);
        for (int c = 0; c < 3; ++c) {
          add_product<FUSED>(s[1 + c], m_j, t[c]);
          add_product<FUSED>(sj[1 + c], minus_m_i, t[c]);
        }
        const Lanes4 dv[3] = {dvx, dvy, dvz}, gw[3] = {gwx, gwy, gwz};
        for (int c = 0; c < 3; ++c) {
          const Lanes4 wi = minus_volume_j * dv[c], wj = minus_volume_i * dv[c];
          for (int d = 0; d < 3; ++d) {
            add_product<FUSED>(s[4 + 3 * c + d], wi, gw[d]);
            add_product<FUSED>(sj[4 + 3 * c + d], wj, gw[d]);
          }
        }
      }
      Lanes4 *si = sums[I].s;
      for (int q = 0; q < NSUM; ++q) si[q].v[a] += lane_sum(s[q]);
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
  const Viscosity visc{0.25, 0.0, false, Viscosity::BULK, 30.0};
  const Rows rows{g.p.data(), first.data(), num.data(), WendlandC2::make(h, 3), visc};
  std::vector<double> by_rows(NSUM * n), by_clusters(NSUM * n), by_clusters_fused(NSUM * n);
  AlignedVector<Cluster> cl(nclusters);
  AlignedVector<ClusterSums> sums(nclusters);
  auto run_rows = [&]() {
    for (int i = 0; i < n; ++i) {
      const ParticleRates r = granular_rates<false, false, false, false>(rows, i, nullptr, nullptr);
      double *o = &by_rows[NSUM * i];
      o[0] = r.drho;
      for (int c = 0; c < 3; ++c) o[1 + c] = r.acc[c];
      for (int c = 0; c < 9; ++c) o[4 + c] = r.grad_v[c / 3][c % 3];
    }
  };
  auto run_clusters = [&]() { cluster_sums<false>(g, cl, sums, rows.kernel, visc, by_clusters); };
  auto run_fused = [&]() { cluster_sums<true>(g, cl, sums, rows.kernel, visc, by_clusters_fused); };
  // each shape timed on its second run in a row (its data in the caches, as from one
  // step to the next), the shapes in turn
  const std::function<void()> shapes[3] = {run_rows, run_clusters, run_fused};
  double best[3] = {1e30, 1e30, 1e30};
  for (int r = 0; r < repeats; ++r)
    for (int k = 0; k < 3; ++k) {
      shapes[k]();
      const double t0 = now();
      shapes[k]();
      best[k] = std::min(best[k], now() - t0);
    }
  double scale = 0.0, diff = 0.0, diff_fused = 0.0;
  for (int k = 0; k < NSUM * n; ++k) {
    scale = std::max(scale, std::fabs(by_rows[k]));
    diff = std::max(diff, std::fabs(by_rows[k] - by_clusters[k]));
    diff_fused = std::max(diff_fused, std::fabs(by_rows[k] - by_clusters_fused[k]));
  }
  std::printf("%d grains in %d clusters of four; rows %.1f neighbours a grain; clusters: %ld "
              "lane-pairs for %ld pairs within 2h, efficiency %.3f\n",
              n, nclusters, double(row_pairs) / n, g.lane_pairs, g.pairs,
              double(g.pairs) / g.lane_pairs);
  std::printf("rows (granular_rates): %.0f ns a grain\n", 1e9 * best[0] / n);
  std::printf("clusters, each pair once: %.0f ns a grain, %.2fx rows; largest difference %.2g "
              "of sums up to %.3g\n", 1e9 * best[1] / n, best[0] / best[1], diff, scale);
#ifdef __FMA__
  std::printf("clusters, sums by fused multiply-adds: %.0f ns a grain, %.2fx rows; largest "
              "difference %.2g\n", 1e9 * best[2] / n, best[0] / best[2], diff_fused);
#endif
  const double tolerance = 1e-12 * scale;
  if (!(diff <= tolerance && diff_fused <= tolerance)) {
    std::printf("FAILED: the clusters' sums differ from the rows' beyond %.2g\n", tolerance);
    return 1;
  }
  return 0;
}
