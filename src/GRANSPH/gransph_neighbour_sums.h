/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: the per-particle neighbour sums of sph/granular, written once for
   the plain and the Kokkos pair styles. `Particles` is an accessor with

     int    num_neighbours(int i), neighbour(int i, int k)  (full list, masked)
     double x(int i, int a), v(int i, int a)
     bool   granular(int i), wall(int i)
     GRANSPH::ParticleView view(int i)
     double E, h, alpha, beta; int dim    (E: Young's modulus, for the sound speed)

   All loops run over one particle i and write only to i (full neighbour list).
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_NEIGHBOUR_SUMS_H
#define LMP_GRANSPH_NEIGHBOUR_SUMS_H

#include "gransph_kernel.h"
#include "gransph_pair_terms.h"

namespace GRANSPH {

// 0.5 x_ij (x) F_ij: with a full list each pair is visited from both sides.
KOKKOS_INLINE_FUNCTION void add_pair_virial(double *vir, const double *dx, const double *fij)
{
  vir[0] += 0.5 * dx[0] * fij[0];
  vir[1] += 0.5 * dx[1] * fij[1];
  vir[2] += 0.5 * dx[2] * fij[2];
  vir[3] += 0.5 * dx[0] * fij[1];
  vir[4] += 0.5 * dx[0] * fij[2];
  vir[5] += 0.5 * dx[1] * fij[2];
}

// What a pair i-j inside the kernel support shares with every term:
// dx = x_i - x_j, dv = v_i - v_j, grad_i W_ij and the viscosity Pi_ij (eq. 7).
struct PairGeometry {
  double dx[3], dv[3], gradw[3];
  double visc;
};

// Fills g for neighbour j of i; false if j is outside the support (or on top of i).
template <class Particles>
KOKKOS_INLINE_FUNCTION bool pair_geometry(const Particles &p, int i, int j, const ParticleView &pi,
                                          const ParticleView &pj, PairGeometry &g)
{
  for (int a = 0; a < 3; ++a) g.dx[a] = p.x(i, a) - p.x(j, a);
  const double rsq = g.dx[0] * g.dx[0] + g.dx[1] * g.dx[1] + g.dx[2] * g.dx[2];
  if (rsq >= 4.0 * p.h * p.h || rsq == 0.0) return false;
  const double fw = WendlandC2::grad_factor(rsq, p.h, p.dim);
  for (int a = 0; a < 3; ++a) {
    g.dv[a] = p.v(i, a) - p.v(j, a);
    g.gradw[a] = fw * g.dx[a];
  }
  g.visc = monaghan_viscosity(g.dx, g.dv, rsq, p.h, p.alpha, p.beta, p.E, pi, pj);
  return true;
}

// Rates of granular particle i (eqs. 6, 7, 34, 35); vir (may be null) gets its virial.
template <class Particles>
KOKKOS_INLINE_FUNCTION ParticleRates granular_rates(const Particles &p, int i, double *vir)
{
  ParticleRates r = ParticleRates::zero();
  const ParticleView pi = p.view(i);
  const int n = p.num_neighbours(i);
  for (int k = 0; k < n; ++k) {
    const int j = p.neighbour(i, k);
    if (!p.granular(j) && !p.wall(j)) continue;
    const ParticleView pj = p.view(j);
    PairGeometry g;
    if (!pair_geometry(p, i, j, pi, pj, g)) continue;
    if (vir) {
      double acc[3] = {0.0, 0.0, 0.0};
      momentum_term(pi, pj, g.visc, g.gradw, acc);
      const double fij[3] = {pi.mass * acc[0], pi.mass * acc[1], pi.mass * acc[2]};
      add_pair_virial(vir, g.dx, fij);
    }
    add_neighbour(r, pi, pj, g.dv, g.gradw, g.visc);
  }
  return r;
}

// Stress of dummy particle d extrapolated from its granular neighbours (eq. 8).
template <class Particles>
KOKKOS_INLINE_FUNCTION Sym3 wall_stress(const Particles &p, int d, const double *g_minus_a)
{
  WallSums sums = WallSums::zero();
  const double cutsq = 4.0 * p.h * p.h;
  const int n = p.num_neighbours(d);
  for (int k = 0; k < n; ++k) {
    const int j = p.neighbour(d, k);
    if (!p.granular(j)) continue;
    const double r_dk[3] = {p.x(d, 0) - p.x(j, 0), p.x(d, 1) - p.x(j, 1), p.x(d, 2) - p.x(j, 2)};
    const double rsq = r_dk[0] * r_dk[0] + r_dk[1] * r_dk[1] + r_dk[2] * r_dk[2];
    if (rsq >= cutsq) continue;
    const ParticleView pk = p.view(j);
    sums.add(pk.sigma, pk.rho, r_dk, WendlandC2::w(rsq, p.h, p.dim));
  }
  return sums.stress(g_minus_a);
}

// Force of the granular neighbours on dummy particle d (eq. 9); vir as above.
template <class Particles>
KOKKOS_INLINE_FUNCTION void wall_force(const Particles &p, int d, double *force, double *vir)
{
  const ParticleView pd = p.view(d);
  double acc[3] = {0.0, 0.0, 0.0};
  const int n = p.num_neighbours(d);
  for (int k = 0; k < n; ++k) {
    const int j = p.neighbour(d, k);
    if (!p.granular(j)) continue;
    const ParticleView pj = p.view(j);
    PairGeometry g;
    if (!pair_geometry(p, d, j, pd, pj, g)) continue;
    double accj[3] = {0.0, 0.0, 0.0};
    momentum_term(pd, pj, g.visc, g.gradw, accj);
    for (int a = 0; a < 3; ++a) acc[a] += accj[a];
    if (vir) {
      const double fij[3] = {pd.mass * accj[0], pd.mass * accj[1], pd.mass * accj[2]};
      add_pair_virial(vir, g.dx, fij);
    }
  }
  for (int a = 0; a < 3; ++a) force[a] = pd.mass * acc[a];
}

}    // namespace GRANSPH

#endif
