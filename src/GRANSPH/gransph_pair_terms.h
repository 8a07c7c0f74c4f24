/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: the pairwise SPH terms of the paper, one pair at a time.
   Continuity (eq. 6a), momentum with the full stress and Monaghan viscosity
   (eqs. 6b, 7), strain-rate and spin tensors (eqs. 34, 35), dummy-wall stress
   extrapolation (eq. 8). Usable on host and device.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_PAIR_TERMS_H
#define LMP_GRANSPH_PAIR_TERMS_H

#include "gransph_tensor.h"

namespace GRANSPH {

// Sound speed of the paper, c = sqrt(E / rho) (eq. 19; LOQUAT uses sqrt(K / rho)).
KOKKOS_INLINE_FUNCTION double sound_speed(double E, double rho)
{
  return sqrt(E / rho);
}

// What a particle brings to its pair interactions, set once per evaluation so
// that a pair needs no division or sqrt for it. Two cache lines: a neighbour's
// position and velocity (the cut-off test, the viscosity) come in the first.
struct alignas(64) PairParticle {
  double x[3], v[3];
  double rho, c;    // density and sound speed
  Sym3 sigma;
  double mass, inv_rho;

  KOKKOS_INLINE_FUNCTION static PairParticle make(const double *x, const double *v, double mass,
                                                  double rho, const Sym3 &sigma, double E)
  {
    return {{x[0], x[1], x[2]}, {v[0], v[1], v[2]}, rho, sound_speed(E, rho), sigma, mass,
            1.0 / rho};
  }
};

// Monaghan artificial viscosity Pi_ij, eq. 7, with phi = 0.1 h in the denominator.
// dx = x_i - x_j, dv = v_i - v_j. Acts only between approaching particles (v.x < 0):
// min(v.x, 0) = (v.x - |v.x|) / 2, exact and without a branch (which the neighbour
// loops could not predict), gives Pi = 0 for the others. (-alpha c_ij phi_ij + beta phi_ij^2) / rho_ij with
// phi_ij = h v.x / d, d = r^2 + 0.01 h^2, is taken over one denominator.
KOKKOS_INLINE_FUNCTION double monaghan_viscosity(const double *dx, const double *dv, double rsq,
                                                 double h, double alpha, double beta,
                                                 const PairParticle &pi, const PairParticle &pj)
{
  const double vdotx = dv[0] * dx[0] + dv[1] * dx[1] + dv[2] * dx[2];
  const double hv = h * 0.5 * (vdotx - fabs(vdotx));
  const double d = rsq + 0.01 * h * h;
  const double c_ij = 0.5 * (pi.c + pj.c);
  const double rho_ij = 0.5 * (pi.rho + pj.rho);
  return hv * (beta * hv - alpha * c_ij * d) / (d * d * rho_ij);
}

// Eq. 6b's bracket applied to grad_i W, ((s_i + s_j)/(rho_i rho_j) - Pi_ij I) grad_i W:
// the acceleration of i per unit mass of j. The bracket is symmetric and
// grad_j W = -grad_i W, so j gets the opposite per unit mass of i. The viscous term is
// a pressure (Monaghan 1992), hence the minus sign under our tension-positive stress;
// the paper's "+ Pi" assumes the opposite sign of Pi.
KOKKOS_INLINE_FUNCTION void stress_gradient(const PairParticle &pi, const PairParticle &pj,
                                            double visc, const double *gradw, double *tg)
{
  const Sym3 t = (pi.inv_rho * pj.inv_rho) * (pi.sigma + pj.sigma) - Sym3::iso(visc);
  tg[0] = t.xx * gradw[0] + t.xy * gradw[1] + t.xz * gradw[2];
  tg[1] = t.xy * gradw[0] + t.yy * gradw[1] + t.yz * gradw[2];
  tg[2] = t.xz * gradw[0] + t.yz * gradw[1] + t.zz * gradw[2];
}

// What pair i-j adds to the rates of either particle, computed once for both.
struct PairTerms {
  double dv[3], gradw[3];    // v_i - v_j, grad_i W_ij
  double dv_gradw;           // v_ij . grad_i W_ij = v_ji . grad_j W_ji
  double tg[3];              // stress_gradient()

  KOKKOS_INLINE_FUNCTION static PairTerms make(const PairParticle &pi, const PairParticle &pj,
                                               const double *dv, const double *gradw, double visc)
  {
    PairTerms t{{dv[0], dv[1], dv[2]},
                {gradw[0], gradw[1], gradw[2]},
                dv[0] * gradw[0] + dv[1] * gradw[1] + dv[2] * gradw[2],
                {0.0, 0.0, 0.0}};
    stress_gradient(pi, pj, visc, gradw, t.tg);
    return t;
  }
};

// Rates of a particle accumulated over its neighbours.
struct ParticleRates {
  double drho;            // eq. 6a
  double acc[3];          // eq. 6b
  double grad_v[3][3];    // velocity gradient dv_a/dx_b, sum_j m_j/rho_j v_ji (x) grad_i W_ij

  KOKKOS_INLINE_FUNCTION static ParticleRates zero()
  {
    return {0.0, {0.0, 0.0, 0.0}, {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}};
  }

  // the terms of a pair with `other`: side +1 for i, -1 for j (grad_j W = -grad_i W)
  KOKKOS_INLINE_FUNCTION void add(const PairTerms &t, const PairParticle &other, double side)
  {
    drho += other.mass * t.dv_gradw;
    for (int a = 0; a < 3; ++a) acc[a] += side * other.mass * t.tg[a];
    // v_ji (x) grad_i W = v_ij (x) grad_j W = -dv (x) gradw, weighted by the volume m/rho
    const double s = -other.mass * other.inv_rho;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) grad_v[a][b] += s * t.dv[a] * t.gradw[b];
  }

  KOKKOS_INLINE_FUNCTION void add(const ParticleRates &r)
  {
    drho += r.drho;
    for (int a = 0; a < 3; ++a) {
      acc[a] += r.acc[a];
      for (int b = 0; b < 3; ++b) grad_v[a][b] += r.grad_v[a][b];
    }
  }

  // strain-rate tensor, eq. 34: the symmetric part of grad_v
  KOKKOS_INLINE_FUNCTION Sym3 strain() const
  {
    const double(&l)[3][3] = grad_v;
    return {l[0][0], l[1][1], l[2][2], 0.5 * (l[0][1] + l[1][0]), 0.5 * (l[0][2] + l[2][0]),
            0.5 * (l[1][2] + l[2][1])};
  }

  // spin tensor, eq. 35: the antisymmetric part of grad_v
  KOKKOS_INLINE_FUNCTION Spin3 spin() const
  {
    const double(&l)[3][3] = grad_v;
    return {0.5 * (l[0][1] - l[1][0]), 0.5 * (l[0][2] - l[2][0]), 0.5 * (l[1][2] - l[2][1])};
  }
};

// Dummy-particle stress, eq. 8 (Adami et al. 2012 generalised to a tensor):
// sigma_d = (sum_k sigma_k W_dk - ((g - a_d) . sum_k rho_k r_dk W_dk) I) / sum_k W_dk,
// with r_dk = x_d - x_k pointing from the granular particle k to the dummy d.
struct WallSums {
  Sym3 sigma_w;
  double rho_r_w[3];
  double w;

  KOKKOS_INLINE_FUNCTION static WallSums zero() { return {Sym3::zero(), {0.0, 0.0, 0.0}, 0.0}; }

  // whether any granular particle lies inside the support (W > 0 there)
  KOKKOS_INLINE_FUNCTION bool has_neighbours() const { return w > 0.0; }

  KOKKOS_INLINE_FUNCTION void add(const Sym3 &sigma_k, double rho_k, const double *r_dk, double wdk)
  {
    sigma_w = sigma_w + wdk * sigma_k;
    for (int a = 0; a < 3; ++a) rho_r_w[a] += rho_k * r_dk[a] * wdk;
    w += wdk;
  }

  // g_minus_a = g - a_d (see wall_gravity); a dummy particle without granular
  // neighbours is stress-free
  KOKKOS_INLINE_FUNCTION Sym3 stress(const double *g_minus_a) const
  {
    if (w <= 0.0) return Sym3::zero();
    const double hydro =
        g_minus_a[0] * rho_r_w[0] + g_minus_a[1] * rho_r_w[1] + g_minus_a[2] * rho_r_w[2];
    return (1.0 / w) * (sigma_w - Sym3::iso(hydro));
  }
};

// g - a_d of eq. 8 for a dummy particle of velocity v, with its acceleration a_d from
// the velocity change since the last evaluation (inv_dt = 0 at a run's setup: none);
// v_last becomes v for the next one.
KOKKOS_INLINE_FUNCTION void wall_gravity(const double *g, const double *v, double *v_last,
                                         double inv_dt, double *g_minus_a)
{
  for (int a = 0; a < 3; ++a) {
    g_minus_a[a] = g[a] - (v[a] - v_last[a]) * inv_dt;
    v_last[a] = v[a];
  }
}

}    // namespace GRANSPH

#endif
