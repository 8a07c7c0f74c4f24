/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: the pairwise SPH terms of the paper and what a particle's sums
   give. Per pair, in scalar arguments (the vectorised neighbour loops of
   gransph_neighbour_sums.h call them): the Monaghan viscosity (eq. 7) and the
   stress term of the momentum equation (eq. 6b). From the sums: the rates
   (eqs. 6a, 6b, 34, 35, the corrected gradient), a wall's share taken along its
   normal, and the dummy-wall stress extrapolation (eq. 8). Usable on host and
   device.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_PAIR_TERMS_H
#define LMP_GRANSPH_PAIR_TERMS_H

#include "gransph_kernel.h"
#include "gransph_tensor.h"

namespace GRANSPH {

// Sound speed of the paper, c = sqrt(E / rho) (eq. 19).
KOKKOS_INLINE_FUNCTION double sound_speed(double E, double rho)
{
  return sqrt(E / rho);
}

// The artificial viscosity of eq. 7 as the pair style is set: alpha, beta, whether it
// acts between grains and dummy wall particles, and the sound speed it uses.
struct Viscosity {
  enum Sound { PAPER, BULK };    // c = sqrt(E / rho) (eq. 19), or c0 = sqrt(K / rho0)
  double alpha, beta;
  bool walls;
  Sound sound;    // of each particle's material (MaterialTable::viscosity_sound)
};

// What a particle brings to its pair interactions, set once per evaluation so
// that a pair needs no division or sqrt for it. Two cache lines: a neighbour's
// position and velocity (the cut-off test, the viscosity) come in the first.
struct alignas(64) PairParticle {
  double x[3], v[3];
  double rho, c;    // density and the sound speed of the viscosity
  Sym3 sigma;
  double mass, inv_rho;

  KOKKOS_INLINE_FUNCTION static PairParticle make(const double *x, const double *v, double mass,
                                                  double rho, const Sym3 &sigma, double c)
  {
    return {{x[0], x[1], x[2]}, {v[0], v[1], v[2]}, rho, c, sigma, mass, 1.0 / rho};
  }
};

// PairParticle in single precision, for the grains' sums under the pair style's
// `precision mixed`: one cache line, and twice the pairs per vector instruction. Its
// position is taken from an origin near the particles (their sub-domain's centre), so
// that single precision rounds it, and so each pair's distance, relative to the
// sub-domain's size rather than to the distance from the box's origin.
struct alignas(64) PairParticleSingle {
  struct Stress {
    float xx, yy, zz, xy, xz, yz;
  };
  float x[3], v[3];
  float rho, c;
  Stress sigma;
  float mass, inv_rho;

  KOKKOS_INLINE_FUNCTION static PairParticleSingle of(const PairParticle &p,
                                                      const double *origin)
  {
    const Sym3 &s = p.sigma;
    return {{float(p.x[0] - origin[0]), float(p.x[1] - origin[1]), float(p.x[2] - origin[2])},
            {float(p.v[0]), float(p.v[1]), float(p.v[2])},
            float(p.rho),
            float(p.c),
            {float(s.xx), float(s.yy), float(s.zz), float(s.xy), float(s.xz), float(s.yz)},
            float(p.mass),
            float(p.inv_rho)};
  }
};

// Monaghan artificial viscosity Pi_ij, eq. 7, with phi = 0.1 h in the denominator, from
// v.x = v_ij . x_ij, r^2 and the pair's mean sound speed c_ij and density rho_ij. Acts
// only between approaching particles (v.x < 0): min(v.x, 0) = (v.x - |v.x|) / 2, exact
// and without a branch, gives Pi = 0 for the others. (-alpha c_ij phi_ij + beta
// phi_ij^2) / rho_ij with phi_ij = h v.x / d, d = r^2 + 0.01 h^2, is taken over one
// denominator.
// In the precision Real of the pair sums.
template <class Real>
KOKKOS_INLINE_FUNCTION Real monaghan_viscosity(Real vdotx, Real rsq, Real h, const Viscosity &visc,
                                               Real c_ij, Real rho_ij)
{
  const Real hv = h * Real(0.5) * (vdotx - magnitude(vdotx));
  const Real d = rsq + Real(0.01) * h * h;
  return hv * (Real(visc.beta) * hv - Real(visc.alpha) * c_ij * d) / (d * d * rho_ij);
}

// a where c holds, else 0
KOKKOS_INLINE_FUNCTION double zero_unless(bool c, double a)
{
  return c ? a : 0.0;
}
KOKKOS_INLINE_FUNCTION float zero_unless(bool c, float a)
{
  return c ? a : 0.0f;
}

// Pi_ij between a particle and a neighbour from v_ij . x_ij, r^2, their sound speeds and
// densities: Monaghan's term at the pair's mean c and rho, and none between a grain and
// a dummy particle unless visc/walls (grain_pair: both are grains). The grains' rates,
// the dummies' force and the viscous-pressure diagnostic take it from here alike.
// (grain_pair: a bool, or a lane type's mask where the sums take several pairs at once)
template <class Real, class Condition>
KOKKOS_INLINE_FUNCTION Real pair_viscosity(Real vdotx, Real rsq, Real h, const Viscosity &visc,
                                           Real c_i, Real c_j, Real rho_i, Real rho_j,
                                           Condition grain_pair)
{
  const Real pi_ij = monaghan_viscosity(vdotx, rsq, h, visc, Real(0.5) * (c_i + c_j),
                                        Real(0.5) * (rho_i + rho_j));
  return visc.walls ? pi_ij : zero_unless(grain_pair, pi_ij);
}

// Component a of eq. 6b's bracket applied to grad_i W, ((s_i + s_j)/(rho_i rho_j) -
// Pi_ij I) grad_i W: the acceleration of i per unit mass of j, from row a of s_i + s_j
// (s_ax, s_ay, s_az), 1/(rho_i rho_j), Pi_ij, grad_i W and its component g_a. The
// bracket is symmetric and grad_j W = -grad_i W, so j gets the opposite per unit mass of
// i. The viscous term is a pressure (Monaghan 1992), hence the minus sign under our
// tension-positive stress; the paper's "+ Pi" assumes the opposite sign of Pi.
template <class Real>
KOKKOS_INLINE_FUNCTION Real stress_gradient(Real s_ax, Real s_ay, Real s_az, Real inv_rho_ij,
                                            Real visc, Real gx, Real gy, Real gz, Real g_a)
{
  return inv_rho_ij * (s_ax * gx + s_ay * gy + s_az * gz) - visc * g_a;
}

// Inverse of a symmetric matrix; false (and inv untouched) if its determinant is
// below det_min.
KOKKOS_INLINE_FUNCTION bool invert(const Sym3 &m, double det_min, double inv[3][3])
{
  const double c_xx = m.yy * m.zz - m.yz * m.yz, c_xy = m.xz * m.yz - m.xy * m.zz,
               c_xz = m.xy * m.yz - m.xz * m.yy;
  const double det = m.xx * c_xx + m.xy * c_xy + m.xz * c_xz;
  if (!(det >= det_min)) return false;
  const double r = 1.0 / det;
  inv[0][0] = r * c_xx;
  inv[0][1] = inv[1][0] = r * c_xy;
  inv[0][2] = inv[2][0] = r * c_xz;
  inv[1][1] = r * (m.xx * m.zz - m.xz * m.xz);
  inv[1][2] = inv[2][1] = r * (m.xy * m.xz - m.xx * m.yz);
  inv[2][2] = r * (m.xx * m.yy - m.xy * m.xy);
  return true;
}

// Rates of a particle accumulated over its neighbours.
struct ParticleRates {
  double drho;            // eq. 6a
  double acc[3];          // eq. 6b
  double grad_v[3][3];    // velocity gradient dv_a/dx_b, sum_j m_j/rho_j v_ji (x) grad_i W_ij
  Sym3 shape;             // sum_j m_j/rho_j x_ji (x) grad_i W_ij: I inside the material

  // Below this determinant of `shape` (the full-support value is 1; a flat free
  // surface has about 0.5) a particle has too few neighbours for the correction.
  static constexpr double det_min = 0.1;

  // Renormalised velocity gradient grad_v shape^-1 (Randles & Libersky 1996; Bonet &
  // Lok 1999): exact for a linear velocity field also where the support is cut by a
  // free surface. A particle with too few neighbours keeps the plain gradient.
  KOKKOS_INLINE_FUNCTION void correct_gradient(int dim)
  {
    Sym3 m = shape;
    if (dim == 2) {
      m.zz = 1.0;
      m.xz = m.yz = 0.0;
    }
    double inv[3][3];
    if (!invert(m, det_min, inv)) return;
    for (int a = 0; a < 3; ++a) {
      const double g[3] = {grad_v[a][0], grad_v[a][1], grad_v[a][2]};
      for (int b = 0; b < 3; ++b) grad_v[a][b] = g[0] * inv[0][b] + g[1] * inv[1][b] + g[2] * inv[2][b];
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

// A grain's dummy neighbours' share of its density rate and velocity gradient, to be
// taken along the wall normal only (pair_style keyword wall/gradient normal):
// grad_i W -> (n . grad_i W) n. A wall, flat on the kernel's scale, moves rigidly, so
// its velocity varies across it and not along it. The sums along the wall are those of
// the dummy lattice: a grain sliding over it sees them swing with its position against
// the lattice (a volumetric strain of order 1e-3 per spacing passed, against the 1e-5
// a monolayer's weight holds), and hops over the floor as over a washboard once faster
// than a few sqrt(g dx). The normal is the direction from the dummies' volume-weighted
// centre to the grain (where walls meet, the mean of their normals).
struct WallVelocitySums {
  double drho[3][3];      // sum_d m_d v_id (x) grad_i W_id
  double grad_v[3][3];    // sum_d m_d/rho_d v_di (x) grad_i W_id
  double offset[3];       // sum_d m_d/rho_d x_id W_id, along the wall normal

  // adds the sums along the normal to the grain's rates
  KOKKOS_INLINE_FUNCTION void add_along_normal(ParticleRates &r) const
  {
    const double len = norm3(offset);
    if (len == 0.0) return;
    const double n[3] = {offset[0] / len, offset[1] / len, offset[2] / len};
    for (int a = 0; a < 3; ++a) {
      double dn = 0.0, gn = 0.0;
      for (int b = 0; b < 3; ++b) {
        dn += drho[a][b] * n[b];
        gn += grad_v[a][b] * n[b];
      }
      r.drho += dn * n[a];
      for (int b = 0; b < 3; ++b) r.grad_v[a][b] += gn * n[b];
    }
  }
};

// A dummy group with a friction of its own (wall/friction GROUP value): its dummies limit
// the grains' tangential force at mu times the normal one, mu = tan(delta) (0: slip);
// MATERIAL: the slide friction of each grain's material model; ROUGH: as the sand.
struct FrictionWall {
  static constexpr double ROUGH = -1.0, MATERIAL = -2.0;
  int group;    // an index into LAMMPS' groups
  double mu;
};

// Walls with a friction of their own (pair_style keyword wall/friction): Coulomb's law
// on the force that a grain's dummy neighbours of such walls put on it. Each pair's
// acceleration a_d is split along the dummy's own unit normal n_d (pointing into the
// sand): its normal part (a_d . n_d) n_d, and the rest, tangential. The walls can carry
// a tangential part up to sum_d mu_d (a_d . n_d), mu_d = tan(delta) of the dummy's wall
// (0 on a slip wall); beyond it the grain slides and the tangential part is scaled down
// to that limit, in its own direction t. The dummy of each pair takes the opposite of
// the limited pair force (wall_force): while the grain slides, its tangential part is
// mu_d (a_d . n_d) t, so that each wall takes its own friction where a grain touches
// two, and the walls feel what the grains feel.
// Values per grain of how it slides on walls with a friction of their own, for the
// dummies' forces: its share (WallFrictionSums::share) and slide direction
constexpr int SLIDE_VALUES = 4;

struct WallFrictionSums {
  double acc[3];       // sum_d a_d over the dummies of friction walls
  double normal[3];    // sum_d (a_d . n_d) n_d
  double limit;        // sum_d mu_d (a_d . n_d)

  // value k of a grain's SLIDE_VALUES before any evaluation: held (share 1, no direction)
  KOKKOS_INLINE_FUNCTION static double held(int k) { return k % SLIDE_VALUES == 0 ? 1.0 : 0.0; }

  // the share of its tangential part that the walls carry: 1 while they hold the
  // grain, below 1 while it slides, 0 on slip walls
  KOKKOS_INLINE_FUNCTION double share() const
  {
    const double t[3] = {acc[0] - normal[0], acc[1] - normal[1], acc[2] - normal[2]};
    const double t_len = norm3(t);
    const double bound = fmax(limit, 0.0);    // walls that pull the grain carry no friction
    return t_len > bound ? bound / t_len : 1.0;
  }

  // the direction t of the tangential part while the grain slides on walls that push
  // it (zeros otherwise: the walls hold it, or carry no friction)
  KOKKOS_INLINE_FUNCTION void slide_direction(double *t) const
  {
    for (int k = 0; k < 3; ++k) t[k] = acc[k] - normal[k];
    const double t_len = norm3(t);
    const bool slides = t_len > limit && limit > 0.0;
    for (int k = 0; k < 3; ++k) t[k] = slides ? t[k] / t_len : 0.0;
  }

  // adds the walls' acceleration to a, its tangential part scaled by `share`
  KOKKOS_INLINE_FUNCTION void add_limited(double *a, double share) const
  {
    for (int k = 0; k < 3; ++k) a[k] += normal[k] + share * (acc[k] - normal[k]);
  }
};

// How walls with a friction of their own hold a grain below Coulomb's limit (pair_style
// keyword wall/friction/hold). STRESS: with the push of their dummies' stress, whose
// tangential part is the grains' shear stress amplified by wall/stress (a layer thin
// enough that the walls carry all its weight holds only as long as its own stress can,
// and wall/stress ratio lets a monolayer at rest grow a stress pattern that breaks it:
// validation/README.md, "The rough floor's thinnest layer"). STICK: with whatever
// tangential push T keeps the grain at the walls' velocity, as a Coulomb contact does:
// T = -a_t - rate (v - v_w)_t, where a is the grain's acceleration from everything but
// that push (its other neighbours, the walls' normal push N, gravity), v_w the walls'
// kernel-weighted velocity, t the part normal to N, and rate the share of the relative
// velocity removed per unit time (STICK_DAMPING / dt); |T| is limited to the walls'
// Coulomb limit, sum_d mu_d (a_d . n_d). The tangential velocity left to the
// predictor-corrector's midpoint decays by 0.64 per step at STICK_DAMPING = 0.5 (1 is
// marginal: a two-step oscillation).
struct WallStick {
  static constexpr double STICK_DAMPING = 0.5;
  bool on;              // wall/friction/hold stick
  double gravity[3];    // the grains' gravity (fix gravity), which the walls also hold
  double rate;          // STICK_DAMPING / dt

  // The walls' push on the grain: adds N + T to acc, whose value on entry is the
  // acceleration from everything else but gravity; returns T / limit in t_per_limit (each
  // dummy takes mu_d (a_d . n_d) of it: WallFrictionSums' sliding rule). False where the
  // walls push the grain with no normal force or carry no friction: the caller falls back.
  KOKKOS_INLINE_FUNCTION bool add_push(double *acc, const double *normal, double limit,
                                       const double *v, const double *v_wall,
                                       double *t_per_limit) const
  {
    const double n_len = norm3(normal);
    if (!(n_len > 0.0 && limit > 0.0)) return false;
    const double n[3] = {normal[0] / n_len, normal[1] / n_len, normal[2] / n_len};
    double a[3], u[3], a_n = 0.0, u_n = 0.0;
    for (int k = 0; k < 3; ++k) {
      a[k] = acc[k] + normal[k] + gravity[k];
      u[k] = v[k] - v_wall[k];
      a_n += a[k] * n[k];
      u_n += u[k] * n[k];
    }
    double t[3], t_len = 0.0;
    for (int k = 0; k < 3; ++k) {
      t[k] = -(a[k] - a_n * n[k]) - rate * (u[k] - u_n * n[k]);
      t_len += t[k] * t[k];
    }
    t_len = sqrt(t_len);
    const double scale = t_len > limit ? limit / t_len : 1.0;
    for (int k = 0; k < 3; ++k) {
      acc[k] += normal[k] + scale * t[k];
      t_per_limit[k] = scale * t[k] / limit;
    }
    return true;
  }
};

// Dummy-particle stress, eq. 8 (Adami et al. 2012 generalised to a tensor): the grains'
// stress extrapolated to dummy particle d, sigma_e = sum_k sigma_k W_dk / sum_k W_dk, and
// the weight of the grains between them, from R = sum_k rho_k r_dk W_dk / sum_k W_dk with
// r_dk = x_d - x_k pointing from grain k to the dummy. Two ways to add the weight
// (pair_style keyword wall/stress):
//   PAPER  eq. 8 in index form, sigma_d^aa = sigma_e^aa - (g - a_d)^a R^a with no sum
//          over a: each normal component gets its own direction's term (gravity along z:
//          sigma_zz only).
//   RATIO  the normal stress on the wall, n.sigma.n with n = R / |R|, grows by all of
//          q = (g - a_d) . R, and the other components in proportion: the dummies carry
//          the grains' stress ratio (their mobilised friction) at the wall's pressure.
//          Under PAPER the wall's shear stress is only the grains', against a normal stress
//          raised by q, so a layer whose own stress is small against q (a few particles
//          thick) feels a fraction of its friction at the wall.
struct WallSums {
  enum Mode { PAPER, RATIO };
  // RATIO: the other components grow at most this many times their extrapolated value
  // where the grains' normal stress is small against q (stress-free grains landing)
  static constexpr double max_growth = 4.0;

  Sym3 sigma_w;
  double rho_r_w[3];
  double w;

  KOKKOS_INLINE_FUNCTION static WallSums zero() { return {Sym3::zero(), {0.0, 0.0, 0.0}, 0.0}; }

  // whether any granular particle lies inside the support (W > 0 there)
  KOKKOS_INLINE_FUNCTION bool has_neighbours() const { return w > 0.0; }

  // g_minus_a = g - a_d (see wall_gravity); a dummy particle without granular
  // neighbours is stress-free
  KOKKOS_INLINE_FUNCTION Sym3 stress(const double *g_minus_a, Mode mode) const
  {
    if (w <= 0.0) return Sym3::zero();
    const double inv_w = 1.0 / w;
    const Sym3 sigma_e = inv_w * sigma_w;
    const double r[3] = {inv_w * rho_r_w[0], inv_w * rho_r_w[1], inv_w * rho_r_w[2]};
    if (mode == PAPER)
      return sigma_e -
          Sym3{g_minus_a[0] * r[0], g_minus_a[1] * r[1], g_minus_a[2] * r[2], 0.0, 0.0, 0.0};
    const double r_len = norm3(r);
    if (r_len == 0.0) return sigma_e;
    const double n[3] = {r[0] / r_len, r[1] / r_len, r[2] / r_len};
    const Sym3 nn{n[0] * n[0], n[1] * n[1], n[2] * n[2], n[0] * n[1], n[0] * n[2], n[1] * n[2]};
    const double sigma_nn = sigma_e.ddot(nn);
    // no tension on the wall from a negative q (a wall above the grains)
    const double q = fmax(dot3(g_minus_a, r), fmin(sigma_nn, 0.0));
    const double base = fmax(-sigma_nn, fabs(q) / max_growth);
    const double growth = base > 0.0 ? q / base : 0.0;
    return sigma_e + growth * (sigma_e - sigma_nn * nn) - q * nn;
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
