/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: the neighbour sums of sph/granular, written once for the plain and
   the Kokkos pair styles, over the pair terms of gransph_pair_terms.h.
   `Particles` is an accessor with

     int    num_neighbours(int i), neighbour(int i, int k)  (masked)
     const GRANSPH::PairParticle &particle(int i)
     bool   granular(int i), wall(int i)
     GRANSPH::WendlandC2 kernel; GRANSPH::Viscosity visc
     bool   wall_normal  (dummy neighbours enter drho and grad_v along the wall
                          normal only: WallVelocitySums)
     bool   shape_sums   (sum the shape matrix, which only the corrected gradient uses)

   Over a full neighbour list (the Kokkos styles: no atomics) each loop runs
   over one particle i and writes only to i. Over a half list with newton off
   (the plain style: each pair once, a pair with a ghost on both ranks) a loop
   adds each pair to both particles, to j only if j is owned.
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
// dx = x_i - x_j, dv = v_i - v_j, W_ij, grad_i W_ij and the viscosity Pi_ij (eq. 7).
struct PairGeometry {
  double dx[3], dv[3], gradw[3];
  double w, visc;

  KOKKOS_INLINE_FUNCTION PairTerms terms(const PairParticle &pi, const PairParticle &pj) const
  {
    return PairTerms::make(pi, pj, dx, dv, gradw, w, visc);
  }
};

// Fills g for the pair pi-pj, with the viscosity if `viscous`; false if pj is outside
// the support. A neighbour on top of pi (r = 0) has grad W = 0 and Pi = 0.
template <class Particles>
KOKKOS_INLINE_FUNCTION bool pair_geometry(const Particles &p, const PairParticle &pi,
                                          const PairParticle &pj, bool viscous, PairGeometry &g)
{
  for (int a = 0; a < 3; ++a) g.dx[a] = pi.x[a] - pj.x[a];
  const double rsq = g.dx[0] * g.dx[0] + g.dx[1] * g.dx[1] + g.dx[2] * g.dx[2];
  if (rsq >= p.kernel.cutsq()) return false;
  double fw;
  p.kernel.w_and_grad_factor(rsq, g.w, fw);
  for (int a = 0; a < 3; ++a) {
    g.dv[a] = pi.v[a] - pj.v[a];
    g.gradw[a] = fw * g.dx[a];
  }
  g.visc = viscous ? monaghan_viscosity(g.dx, g.dv, rsq, p.kernel.h, p.visc, pi, pj) : 0.0;
  return true;
}

// Two particles closer than a millionth of h lie on one place: two create_atoms commands
// filled one lattice site. Such a pair has no kernel gradient, so nothing keeps them apart.
KOKKOS_INLINE_FUNCTION double coincident_rsq(double h)
{
  return 1e-12 * h * h;
}

// Whether a neighbour that interacts with particle i (a grain, or a dummy next to grain
// i) lies on top of it.
template <class Particles>
KOKKOS_INLINE_FUNCTION bool has_coincident_neighbour(const Particles &p, int i)
{
  const bool i_granular = p.granular(i);
  if (!i_granular && !p.wall(i)) return false;
  const double tiny = coincident_rsq(p.kernel.h);
  const PairParticle &pi = p.particle(i);
  const int n = p.num_neighbours(i);
  for (int k = 0; k < n; ++k) {
    const int j = p.neighbour(i, k);
    if (!p.granular(j) && !(i_granular && p.wall(j))) continue;
    const PairParticle &pj = p.particle(j);
    double rsq = 0.0;
    for (int a = 0; a < 3; ++a) rsq += (pi.x[a] - pj.x[a]) * (pi.x[a] - pj.x[a]);
    if (rsq < tiny) return true;
  }
  return false;
}

// Rates of granular particle i (eqs. 6, 7, 34, 35); vir (may be null) gets its virial.
template <class Particles>
KOKKOS_INLINE_FUNCTION ParticleRates granular_rates(const Particles &p, int i, double *vir)
{
  ParticleRates r = ParticleRates::zero();
  WallVelocitySums walls = WallVelocitySums::zero();
  const PairParticle pi = p.particle(i);
  const int n = p.num_neighbours(i);
  for (int k = 0; k < n; ++k) {
    const int j = p.neighbour(i, k);
    if (!p.granular(j) && !p.wall(j)) continue;
    const PairParticle &pj = p.particle(j);
    PairGeometry g;
    if (!pair_geometry(p, pi, pj, p.granular(j) || p.visc.walls, g)) continue;
    const PairTerms t = g.terms(pi, pj);
    if (p.wall_normal && p.wall(j)) {
      walls.add(t, pj, 1.0);
      r.add_force_and_weights(t, pj, 1.0, p.shape_sums);
    } else
      r.add(t, pj, 1.0, p.shape_sums);
    if (vir) {
      const double mm = pi.mass * pj.mass;
      const double fij[3] = {mm * t.tg[0], mm * t.tg[1], mm * t.tg[2]};
      add_pair_virial(vir, g.dx, fij);
    }
  }
  if (p.wall_normal) walls.add_along_normal(r);
  return r;
}

// The sums of eq. 8 for dummy particle d over its granular neighbours.
template <class Particles> KOKKOS_INLINE_FUNCTION WallSums wall_sums(const Particles &p, int d)
{
  WallSums sums = WallSums::zero();
  const PairParticle pd = p.particle(d);
  const int n = p.num_neighbours(d);
  for (int k = 0; k < n; ++k) {
    const int j = p.neighbour(d, k);
    if (!p.granular(j)) continue;
    const PairParticle &pk = p.particle(j);
    const double r_dk[3] = {pd.x[0] - pk.x[0], pd.x[1] - pk.x[1], pd.x[2] - pk.x[2]};
    const double rsq = r_dk[0] * r_dk[0] + r_dk[1] * r_dk[1] + r_dk[2] * r_dk[2];
    if (rsq >= p.kernel.cutsq()) continue;
    sums.add(pk.sigma, pk.rho, r_dk, p.kernel.w(rsq));
  }
  return sums;
}

// Force of the granular neighbours on dummy particle d (eq. 9); vir as above.
template <class Particles>
KOKKOS_INLINE_FUNCTION void wall_force(const Particles &p, int d, double *force, double *vir)
{
  const PairParticle pd = p.particle(d);
  for (int a = 0; a < 3; ++a) force[a] = 0.0;
  const int n = p.num_neighbours(d);
  for (int k = 0; k < n; ++k) {
    const int j = p.neighbour(d, k);
    if (!p.granular(j)) continue;
    const PairParticle &pj = p.particle(j);
    PairGeometry g;
    if (!pair_geometry(p, pd, pj, p.visc.walls, g)) continue;
    double tg[3];
    stress_gradient(pd, pj, g.visc, g.gradw, tg);
    const double mm = pd.mass * pj.mass;
    const double fdj[3] = {mm * tg[0], mm * tg[1], mm * tg[2]};
    for (int a = 0; a < 3; ++a) force[a] += fdj[a];
    if (vir) add_pair_virial(vir, g.dx, fdj);
  }
}

// Half list: the pairs of particle i added to the sums of eq. 8 (WallSums, indexed by
// atom) of the dummy particles among i and its owned neighbours.
template <class Particles, class SumsArray>
KOKKOS_INLINE_FUNCTION void add_wall_sums(const Particles &p, int i, int nlocal,
                                          const SumsArray &sums)
{
  const bool i_wall = p.wall(i);
  if (!i_wall && !p.granular(i)) return;
  const PairParticle pi = p.particle(i);
  const int n = p.num_neighbours(i);
  for (int k = 0; k < n; ++k) {
    const int j = p.neighbour(i, k);
    if (i_wall ? !p.granular(j) : !(p.wall(j) && j < nlocal)) continue;
    const PairParticle &pj = p.particle(j);
    const double r_ij[3] = {pi.x[0] - pj.x[0], pi.x[1] - pj.x[1], pi.x[2] - pj.x[2]};
    const double rsq = r_ij[0] * r_ij[0] + r_ij[1] * r_ij[1] + r_ij[2] * r_ij[2];
    if (rsq >= p.kernel.cutsq()) continue;
    const double w = p.kernel.w(rsq);
    if (i_wall)
      sums[i].add(pj.sigma, pj.rho, r_ij, w);
    else {
      const double r_ji[3] = {-r_ij[0], -r_ij[1], -r_ij[2]};
      sums[j].add(pi.sigma, pi.rho, r_ji, w);
    }
  }
}

// Half list: the pairs of particle i added to the rates (ParticleRates, indexed by
// atom) of i and its owned neighbours: eqs. 6, 7, 34, 35 for granular particles, the
// acceleration of eq. 9 for dummy ones. With p.wall_normal a grain's dummy neighbours
// go to walls (WallVelocitySums, indexed by atom) instead of its drho and grad_v.
// tally(i, j, f_ij, x_ij) gets each pair's force on i if want_virial.
template <class Particles, class RatesArray, class WallsArray, class Tally>
KOKKOS_INLINE_FUNCTION void add_pair_rates(const Particles &p, int i, int nlocal,
                                           const RatesArray &rates, const WallsArray &walls,
                                           bool want_virial, const Tally &tally)
{
  const bool i_granular = p.granular(i);
  if (!i_granular && !p.wall(i)) return;
  ParticleRates ri = ParticleRates::zero();
  WallVelocitySums wi = WallVelocitySums::zero();
  const PairParticle pi = p.particle(i);
  const int n = p.num_neighbours(i);
  for (int k = 0; k < n; ++k) {
    const int j = p.neighbour(i, k);
    if (!p.granular(j) && !(i_granular && p.wall(j))) continue;
    const PairParticle &pj = p.particle(j);
    PairGeometry g;
    if (!pair_geometry(p, pi, pj, (i_granular && p.granular(j)) || p.visc.walls, g)) continue;
    const PairTerms t = g.terms(pi, pj);
    if (!i_granular)    // a dummy's rates serve its force only
      ri.add_force(t, pj, 1.0);
    else if (p.wall_normal && p.wall(j)) {
      wi.add(t, pj, 1.0);
      ri.add_force_and_weights(t, pj, 1.0, p.shape_sums);
    } else
      ri.add(t, pj, 1.0, p.shape_sums);
    if (j < nlocal) {
      if (!p.granular(j))
        rates[j].add_force(t, pi, -1.0);
      else if (p.wall_normal && !i_granular) {    // i is j's dummy neighbour
        walls[j].add(t, pi, -1.0);
        rates[j].add_force_and_weights(t, pi, -1.0, p.shape_sums);
      } else
        rates[j].add(t, pi, -1.0, p.shape_sums);
    }
    if (want_virial) {
      const double mm = pi.mass * pj.mass;
      const double fij[3] = {mm * t.tg[0], mm * t.tg[1], mm * t.tg[2]};
      tally(i, j, fij, g.dx);
    }
  }
  rates[i].add(ri);
  if (p.wall_normal) walls[i].add(wi);
}

}    // namespace GRANSPH

#endif
