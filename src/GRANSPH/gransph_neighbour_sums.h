/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: the neighbour sums of sph/granular over a full neighbour list,
   written once for the plain and the Kokkos pair styles, over the pair terms
   of gransph_pair_terms.h. Each sum runs over the neighbours of one particle
   and writes to that particle only: no atomics, no scatter.
   `Particles` is a GRANSPH::ParticlesOf (gransph_pair_passes.h), its options the fields
   of SumOptions (gransph_pair_settings.h), where:
     neighbours(i)    i's row n, n(k) the k-th neighbour's index, masked: taken once per
                      particle, so that the loop reads the list as one contiguous row
     normal(i, a)     with wall_normal: a dummy's own unit wall normal, or zeros for a
                      dummy without one and for grains
     friction(i)      with wall_friction: mu = tan(delta) of a dummy's wall, 0 for a slip
                      wall, negative for a rough wall and for grains; a dummy with
                      mu >= 0 has its own normal
     slide(i, k)      with wall_friction: a grain's WallFrictionSums::share (k = 0) and
                      slide_direction (k = 1..3) of this evaluation, ghosts included;
                      read for grains only

   Vectorised on the host: each loop over the neighbours is an `omp simd` reduction
   into named scalars, its body free of branches (a neighbour outside the support or of
   no role adds zeros) and of local structs or arrays (GCC turns an addressable local of
   a simd loop into an array per lane, and then does not vectorise the loop). The
   options a run does not use are template arguments, so that their sums cost nothing.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_NEIGHBOUR_SUMS_H
#define LMP_GRANSPH_NEIGHBOUR_SUMS_H

#include "gransph_kernel.h"
#include "gransph_lanes.h"
#include "gransph_pair_terms.h"
#include "gransph_simd.h"

#include <type_traits>
#include <utility>

namespace GRANSPH {

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
  const auto neighbours = p.neighbours(i);
  for (int k = 0; k < n; ++k) {
    const int j = neighbours(k);
    if (!p.granular(j) && !(i_granular && p.wall(j))) continue;
    const PairParticle &pj = p.particle(j);
    double rsq = 0.0;
    for (int a = 0; a < 3; ++a) rsq += (pi.x[a] - pj.x[a]) * (pi.x[a] - pj.x[a]);
    if (rsq < tiny) return true;
  }
  return false;
}

// The counts at the front of a pruned row: the neighbours that enter the sums, and of
// them the grains, which come first
struct PrunedRow {
  int count, grains;
};

// The neighbours of particle i that enter its sums (a grain's grains and dummies, a
// dummy's grains) closer than sqrt(cutsq), moved to the front of its row, the grains
// first; their counts. The pair style's pruned rows (its keyword `prune`): the sums' lanes
// then carry no neighbour that would add zeros and tell a grain from a dummy by its
// place. The row keeps every neighbour (the others behind them), so that the next pruning
// before a list build finds them all: the pruned rows take no memory of their own.
// entry(k) is the row's k-th entry as stored (special bits and all), which the swaps move
// whole. x(j, a) are the positions, a dense copy (the particles' records are four times
// longer, and the loop waits on their loads). One pass without branches, so that on a GPU
// the warp stays together: the row is [grains | dummies | others | not yet seen], and each
// neighbour swaps places with the first of the others (none yet: itself), a grain then
// also with the first dummy (none: itself). Without DUMMIES (a run without walls) a
// row holds grains only, and the second swap is left out (bench/HISTORY.md: the jet
// prunes at every step).
template <bool DUMMIES, class Particles, class Positions, class Row>
KOKKOS_INLINE_FUNCTION PrunedRow prune_row(const Particles &p, int i, const Positions &x,
                                           double cutsq, const Row &entry)
{
  const bool i_granular = p.granular(i);
  if (!i_granular && !p.wall(i)) return {0, 0};
  const double xi = x(i, 0), yi = x(i, 1), zi = x(i, 2);
  const int n = p.num_neighbours(i);
  const auto neighbours = p.neighbours(i);
  int grains = 0, m = 0;
  for (int k = 0; k < n; ++k) {
    const int j = neighbours(k);    // entry k is as listed: the swaps so far moved [0, k)
    const double rx = xi - x(j, 0), ry = yi - x(j, 1), rz = zi - x(j, 2);
    const bool near = rx * rx + ry * ry + rz * rz < cutsq;
    const bool grain = near && p.granular(j), dummy = DUMMIES && near && i_granular && p.wall(j);
    const int listed = entry(k), first_other = entry(m);
    const int first_dummy = DUMMIES ? entry(grains) : 0;
    entry(k) = first_other;
    if (DUMMIES) {
      entry(m) = grain ? first_dummy : listed;
      // a grain goes first; else entry `grains` stays (the one just written if no dummy
      // lies between)
      entry(grains) = grain || grains == m ? listed : first_dummy;
    } else
      entry(m) = listed;
    grains += grain;
    m += grain || dummy;
  }
  return {m, grains};
}

// How far particle i, now at x(i, .), has moved since its row was pruned at x0(i, .):
// squared. Both dense (x LAMMPS' own, x0 PrunedPositions), so that the pass over all
// atoms reads 36 bytes of each.
template <class Positions, class PrunedPositions>
KOKKOS_INLINE_FUNCTION double pruned_displacement_sq(const Positions &x, const PrunedPositions &x0,
                                                     int i)
{
  const double dx = x(i, 0) - x0(i, 0), dy = x(i, 1) - x0(i, 1), dz = x(i, 2) - x0(i, 2);
  return dx * dx + dy * dy + dz * dz;
}

// The positions of the last pruning as floats from an origin in the rank's sub-domain (12
// bytes a particle), callable as (i, a) as the atoms' positions are: Floats is callable
// the same way. The rows are pruned at these positions and the atoms' displacements are
// measured from them, so their rounding does not enter the renewal distance (a pair left
// out lay beyond (2 + margin) h at them, and each atom has moved less than margin h / 2
// from them since).
template <class Floats> struct PrunedPositions {
  Floats x0;
  double origin[3];
  KOKKOS_INLINE_FUNCTION double operator()(int i, int a) const { return origin[a] + x0(i, a); }
};

// Rates of granular particle i (eqs. 6, 7, 34, 35) over its grain and dummy neighbours.
// With WALL_NORMAL a dummy with its own normal n enters drho and grad_v through
// (n . grad_i W) n; one without, through WallVelocitySums (the normal from the dummies'
// weighted centre).
// With FRICTION the dummies of walls with a friction of their own (friction(j) >= 0)
// push the grain with the tangential part of their force limited (WallFrictionSums), and
// slide gets the grain's share and slide direction (SLIDE_VALUES); those of slip walls
// (friction 0) enter drho and grad_v with the normal part of the relative velocity only,
// so that the grain feels no shear from them.
// With VIRIAL, vir gets its virial 0.5 x_ij (x) F_ij (each pair is visited from both
// sides), in LAMMPS' order xx yy zz xy xz yz; but for the pairs with a dummy of a wall
// with a friction of its own, whose whole virial the dummy tallies (wall_force). A
// neighbour on top of i (r = 0) has grad W = 0 and Pi = 0.
template <bool WALL_NORMAL, bool SHAPE, bool VIRIAL, bool FRICTION, class Particles>
KOKKOS_INLINE_FUNCTION ParticleRates granular_rates(const Particles &p, int i, double *vir,
                                                    double *slide)
{
  using Real = typename Particles::Real;    // double, or float under `precision mixed`
  const auto &pi = p.particle(i);
  const Real xi = pi.x[0], yi = pi.x[1], zi = pi.x[2];
  const Real vxi = pi.v[0], vyi = pi.v[1], vzi = pi.v[2];
  const Real rho_i = pi.rho, c_i = pi.c, inv_rho_i = pi.inv_rho, m_i = pi.mass;
  const Real sxx_i = pi.sigma.xx, syy_i = pi.sigma.yy, szz_i = pi.sigma.zz;
  const Real sxy_i = pi.sigma.xy, sxz_i = pi.sigma.xz, syz_i = pi.sigma.yz;
  // copies of the settings, in the sums' precision: read in the loop without a
  // condition on a lane, or a conversion
  const WendlandC2Of<Real> kernel = p.kernel.template in_precision<Real>();
  const Viscosity viscosity = p.visc;
  const Real cutsq = kernel.cutsq(), h = kernel.h;
  // the grain's own friction, that of walls with the friction of the grains' materials
  const Real mu_i = FRICTION ? Real(p.friction(i)) : Real(0);

  Real drho = 0, ax = 0, ay = 0, az = 0;
  // grad_v[a][b] = dv_a/dx_b
  Real lxx = 0, lxy = 0, lxz = 0, lyx = 0, lyy = 0, lyz = 0, lzx = 0, lzy = 0, lzz = 0;
  Real kxx = 0, kyy = 0, kzz = 0, kxy = 0, kxz = 0, kyz = 0;    // shape
  // WallVelocitySums: drho (d..), grad_v (g..), offset (o.)
  Real dxx = 0, dxy = 0, dxz = 0, dyx = 0, dyy = 0, dyz = 0, dzx = 0, dzy = 0, dzz = 0;
  Real gxx = 0, gxy = 0, gxz = 0, gyx = 0, gyy = 0, gyz = 0, gzx = 0, gzy = 0, gzz = 0;
  Real ox = 0, oy = 0, oz = 0;
  Real v0 = 0, v1 = 0, v2 = 0, v3 = 0, v4 = 0, v5 = 0;
  // WallFrictionSums
  Real fax = 0, fay = 0, faz = 0, fnx = 0, fny = 0, fnz = 0, f_lim = 0;
  // the friction walls' kernel-weighted velocity (u.), for wall/friction/hold stick
  Real uw = 0, ux_w = 0, uy_w = 0, uz_w = 0;

  const int n = p.num_neighbours(i);
  const auto neighbours = p.neighbours(i);
  GRANSPH_SIMD_SUM(drho, ax, ay, az, lxx, lxy, lxz, lyx, lyy, lyz, lzx, lzy, lzz, kxx, kyy,
                   kzz, kxy, kxz, kyz, dxx, dxy, dxz, dyx, dyy, dyz, dzx, dzy,
                   dzz, gxx, gxy, gxz, gyx, gyy, gyz, gzx, gzy, gzz, ox, oy, oz, v0, v1, v2,
                   v3, v4, v5, fax, fay, faz, fnx, fny, fnz, f_lim, uw, ux_w, uy_w, uz_w)
  for (int k = 0; k < n; ++k) {
    const int j = neighbours(k);
    const auto &pj = p.particle(j);
    const bool grain = p.granular(j), dummy = p.wall(j);
    const Real rx = xi - pj.x[0], ry = yi - pj.x[1], rz = zi - pj.x[2];
    const Real rsq = rx * rx + ry * ry + rz * rz;
    const bool inside = (grain || dummy) && rsq < cutsq;
    const Real q = kernel.q(rsq);
    const Real w = inside ? kernel.w_inside(q) : Real(0);
    const Real fw = inside ? kernel.grad_factor_inside(q) : Real(0);
    const Real gwx = fw * rx, gwy = fw * ry, gwz = fw * rz;    // grad_i W
    const Real dvx = vxi - pj.v[0], dvy = vyi - pj.v[1], dvz = vzi - pj.v[2];
    const Real visc = pair_viscosity(dvx * rx + dvy * ry + dvz * rz, rsq, h, viscosity, c_i,
                                     Real(pj.c), rho_i, Real(pj.rho), grain);

    // eq. 6b: the acceleration
    const Real inv_rho_ij = inv_rho_i * pj.inv_rho;
    const Real sxx = sxx_i + pj.sigma.xx, syy = syy_i + pj.sigma.yy, szz = szz_i + pj.sigma.zz;
    const Real sxy = sxy_i + pj.sigma.xy, sxz = sxz_i + pj.sigma.xz, syz = syz_i + pj.sigma.yz;
    const Real tx = stress_gradient(sxx, sxy, sxz, inv_rho_ij, visc, gwx, gwy, gwz, gwx);
    const Real ty = stress_gradient(sxy, syy, syz, inv_rho_ij, visc, gwx, gwy, gwz, gwy);
    const Real tz = stress_gradient(sxz, syz, szz, inv_rho_ij, visc, gwx, gwy, gwz, gwz);
    const Real m = pj.mass, volume = m * pj.inv_rho;
    // a dummy of a wall with a friction of its own: its push goes to the friction sums,
    // along its normal (nx, ny, nz; zeros for the others)
    bool limited = false, slip = false;
    Real nx = 0, ny = 0, nz = 0;
    if (FRICTION) {
      const Real mu_j = p.friction(j);
      const Real mu = mu_j == Real(FrictionWall::MATERIAL) ? mu_i : mu_j;
      limited = dummy && mu >= 0;
      slip = limited && mu == 0;
      nx = limited ? Real(p.normal(j, 0)) : Real(0);
      ny = limited ? Real(p.normal(j, 1)) : Real(0);
      nz = limited ? Real(p.normal(j, 2)) : Real(0);
      const Real an = m * (tx * nx + ty * ny + tz * nz);
      fax += limited ? m * tx : Real(0);
      fay += limited ? m * ty : Real(0);
      faz += limited ? m * tz : Real(0);
      fnx += an * nx;
      fny += an * ny;
      fnz += an * nz;
      f_lim += limited ? mu * an : Real(0);
      const Real vw = limited ? volume * w : Real(0);
      uw += vw;
      ux_w += vw * pj.v[0];
      uy_w += vw * pj.v[1];
      uz_w += vw * pj.v[2];
    }
    const Real m_a = limited ? Real(0) : m;
    ax += m_a * tx;
    ay += m_a * ty;
    az += m_a * tz;
    // the relative velocity in drho and grad_v: that along the normal of a slip wall
    const Real dv_n = dvx * nx + dvy * ny + dvz * nz;
    const Real ux = slip ? dv_n * nx : dvx, uy = slip ? dv_n * ny : dvy,
                 uz = slip ? dv_n * nz : dvz;

    // eq. 6a and the velocity gradient, v_ji (x) grad_i W = -dv (x) grad_i W weighted by
    // the volume m/rho; under WALL_NORMAL, of a dummy with its own normal n through
    // (n . grad_i W) n, of one without through the wall sums
    Real ex = gwx, ey = gwy, ez = gwz;
    bool to_wall = false;
    if (WALL_NORMAL) {
      const Real nx = p.normal(j, 0), ny = p.normal(j, 1), nz = p.normal(j, 2);
      const bool own = dummy && nx * nx + ny * ny + nz * nz > Real(0);
      const Real gn = nx * gwx + ny * gwy + nz * gwz;
      ex = own ? gn * nx : gwx;
      ey = own ? gn * ny : gwy;
      ez = own ? gn * nz : gwz;
      to_wall = dummy && !own;
    }
    const Real m_r = to_wall ? Real(0) : m, s_r = to_wall ? Real(0) : -volume;
    drho += m_r * (ux * ex + uy * ey + uz * ez);
    lxx += s_r * ux * ex;
    lxy += s_r * ux * ey;
    lxz += s_r * ux * ez;
    lyx += s_r * uy * ex;
    lyy += s_r * uy * ey;
    lyz += s_r * uy * ez;
    lzx += s_r * uz * ex;
    lzy += s_r * uz * ey;
    lzz += s_r * uz * ez;
    if (SHAPE) {    // x_ji (x) grad_i W = -dx (x) grad_i W, symmetric (grad W is along dx)
      kxx += -volume * rx * gwx;
      kyy += -volume * ry * gwy;
      kzz += -volume * rz * gwz;
      kxy += -volume * rx * gwy;
      kxz += -volume * rx * gwz;
      kyz += -volume * ry * gwz;
    }
    if (WALL_NORMAL) {
      const Real m_w = to_wall ? m : Real(0), s_w = to_wall ? -volume : Real(0);
      dxx += m_w * ux * gwx;
      dxy += m_w * ux * gwy;
      dxz += m_w * ux * gwz;
      dyx += m_w * uy * gwx;
      dyy += m_w * uy * gwy;
      dyz += m_w * uy * gwz;
      dzx += m_w * uz * gwx;
      dzy += m_w * uz * gwy;
      dzz += m_w * uz * gwz;
      gxx += s_w * ux * gwx;
      gxy += s_w * ux * gwy;
      gxz += s_w * ux * gwz;
      gyx += s_w * uy * gwx;
      gyy += s_w * uy * gwy;
      gyz += s_w * uy * gwz;
      gzx += s_w * uz * gwx;
      gzy += s_w * uz * gwy;
      gzz += s_w * uz * gwz;
      const Real vw = to_wall ? volume * w : Real(0);
      ox += vw * rx;
      oy += vw * ry;
      oz += vw * rz;
    }
    if (VIRIAL) {    // F_ij = m_i m_j t (a friction wall's pair: its dummy's)
      const Real mm = Real(0.5) * m_i * m_a;
      v0 += mm * rx * tx;
      v1 += mm * ry * ty;
      v2 += mm * rz * tz;
      v3 += mm * rx * ty;
      v4 += mm * rx * tz;
      v5 += mm * ry * tz;
    }
  }

  ParticleRates r{drho,
                  {ax, ay, az},
                  {{lxx, lxy, lxz}, {lyx, lyy, lyz}, {lzx, lzy, lzz}},
                  {kxx, kyy, kzz, kxy, kxz, kyz}};
  if (WALL_NORMAL) {
    const WallVelocitySums walls{{{dxx, dxy, dxz}, {dyx, dyy, dyz}, {dzx, dzy, dzz}},
                                 {{gxx, gxy, gxz}, {gyx, gyy, gyz}, {gzx, gzy, gzz}},
                                 {ox, oy, oz}};
    walls.add_along_normal(r);
  }
  if (FRICTION) {
    const WallFrictionSums friction{{fax, fay, faz}, {fnx, fny, fnz}, f_lim};
    const double v_i[3] = {vxi, vyi, vzi};
    const double v_w[3] = {uw > 0 ? ux_w / uw : 0.0, uw > 0 ? uy_w / uw : 0.0,
                           uw > 0 ? uz_w / uw : 0.0};
    double s = 0.0, t[3];    // share 0 under stick: each dummy takes mu_d (a_d . n_d) t
    if (!(p.stick.on && p.stick.add_push(r.acc, friction.normal, f_lim, v_i, v_w, t))) {
      s = friction.share();
      friction.slide_direction(t);
      friction.add_limited(r.acc, s);
    }
    if (slide) {
      slide[0] = s;
      for (int k = 0; k < 3; ++k) slide[1 + k] = t[k];
    }
  }
  if (VIRIAL) {
    const double sums[6] = {v0, v1, v2, v3, v4, v5};
    for (int k = 0; k < 6; ++k) vir[k] += sums[k];
  }
  return r;
}

// The particle records of accessor Particles: PairParticle, or PairParticleSingle
template <class Particles>
using RecordOf =
    typename std::decay<decltype(std::declval<Particles>().particle(0))>::type;

#if GRANSPH_LANES
// Whether the host takes granular_rates and wall_force without options, and wall_sums,
// in lanes (gransph_lanes.h)
template <class Particles>
using SumsInLanes =
    std::integral_constant<bool, !std::is_void<typename LanesOf<RecordOf<Particles>>::type>::value>;

// Neighbours k, k + 1, ... (Lanes::WIDTH of them) of particle `self`'s row of n: their
// records' fields in lanes (f[RecordField]). Lanes past the row's end take `self` itself.
template <class Lanes> struct NeighbourBlock {
  Lanes f[16];

  template <class Particles, class Row>
  void load(const Particles &p, const Row &neighbours, int n, int k, int self)
  {
    const typename Lanes::Record *records[Lanes::WIDTH];
    for (int l = 0; l < Lanes::WIDTH; ++l)
      records[l] = &p.particle(k + l < n ? neighbours(k + l) : self);
    Lanes::load_transposed(records, f);
  }
};

// granular_rates without options (no wall normal, shape, virial or wall friction) on the
// host over rows pruned grains first (prune_row), Lanes::WIDTH neighbours at a time: their
// records loaded whole and transposed (the loop above assembles its vectors field by field
// and lane by lane, a third of its instructions), a neighbour's role from its place in the
// row (the loop above reads each one's group bits), the pair terms the same functions' on
// Lanes, each sum added by a fused multiply-add. The same sums in another order and
// rounding: they differ from the loop's in the last digits. Rows not pruned: the loop above.
template <class Particles>
inline ParticleRates granular_rates_without_options(const Particles &p, int i, std::true_type)
{
  if (!p.grains_first) return granular_rates<false, false, false, false>(p, i, nullptr, nullptr);
  using Lanes = typename LanesOf<RecordOf<Particles>>::type;
  using Record = typename Lanes::Record;
  constexpr int X = FIELD_X, V = FIELD_V, RHO = FIELD_RHO, C = FIELD_C, SXX = FIELD_SXX,
                SYY = FIELD_SYY, SZZ = FIELD_SZZ, SXY = FIELD_SXY, SXZ = FIELD_SXZ,
                SYZ = FIELD_SYZ, MASS = FIELD_MASS, INV_RHO = FIELD_INV_RHO;
  const Record &pi = p.particle(i);
  const Lanes xi = pi.x[0], yi = pi.x[1], zi = pi.x[2];
  const Lanes vxi = pi.v[0], vyi = pi.v[1], vzi = pi.v[2];
  const Lanes rho_i = pi.rho, c_i = pi.c, inv_rho_i = pi.inv_rho;
  const Lanes sxx_i = pi.sigma.xx, syy_i = pi.sigma.yy, szz_i = pi.sigma.zz;
  const Lanes sxy_i = pi.sigma.xy, sxz_i = pi.sigma.xz, syz_i = pi.sigma.yz;
  const WendlandC2Of<Lanes> kernel = p.kernel.template in_precision<Lanes>();
  const Viscosity viscosity = p.visc;
  const Lanes cutsq = kernel.cutsq(), h = kernel.h;

  Lanes drho = 0.0f, ax = 0.0f, ay = 0.0f, az = 0.0f;
  Lanes lxx = 0.0f, lxy = 0.0f, lxz = 0.0f, lyx = 0.0f, lyy = 0.0f, lyz = 0.0f, lzx = 0.0f,
        lzy = 0.0f, lzz = 0.0f;
  const int n = p.num_neighbours(i), grains = p.num_grain_neighbours(i);
  const auto neighbours = p.neighbours(i);
  NeighbourBlock<Lanes> block;
  const Lanes *f = block.f;
  for (int k = 0; k < n; k += Lanes::WIDTH) {
    block.load(p, neighbours, n, k, i);
    const auto grain = Lanes::first(grains - k);
    const Lanes rx = xi - f[X], ry = yi - f[X + 1], rz = zi - f[X + 2];
    const Lanes rsq = rx * rx + ry * ry + rz * rz;
    const auto inside = Lanes::first(n - k) & (rsq < cutsq);
    const Lanes fw = zero_unless(inside, kernel.grad_factor_inside(kernel.q(rsq)));
    const Lanes gwx = fw * rx, gwy = fw * ry, gwz = fw * rz;    // grad_i W
    const Lanes dvx = vxi - f[V], dvy = vyi - f[V + 1], dvz = vzi - f[V + 2];
    const Lanes visc = pair_viscosity(dvx * rx + dvy * ry + dvz * rz, rsq, h, viscosity, c_i,
                                      f[C], rho_i, f[RHO], grain);
    // eq. 6b
    const Lanes inv_rho_ij = inv_rho_i * f[INV_RHO];
    const Lanes sxx = sxx_i + f[SXX], syy = syy_i + f[SYY], szz = szz_i + f[SZZ];
    const Lanes sxy = sxy_i + f[SXY], sxz = sxz_i + f[SXZ], syz = syz_i + f[SYZ];
    const Lanes tx = stress_gradient(sxx, sxy, sxz, inv_rho_ij, visc, gwx, gwy, gwz, gwx);
    const Lanes ty = stress_gradient(sxy, syy, syz, inv_rho_ij, visc, gwx, gwy, gwz, gwy);
    const Lanes tz = stress_gradient(sxz, syz, szz, inv_rho_ij, visc, gwx, gwy, gwz, gwz);
    const Lanes m = f[MASS], minus_volume = -(m * f[INV_RHO]);
    add_product(ax, m, tx);
    add_product(ay, m, ty);
    add_product(az, m, tz);
    // eq. 6a and the velocity gradient, -dv (x) grad_i W weighted by the volume m/rho
    add_product(drho, m, dvx * gwx + dvy * gwy + dvz * gwz);
    const Lanes ux = minus_volume * dvx, uy = minus_volume * dvy, uz = minus_volume * dvz;
    add_product(lxx, ux, gwx);
    add_product(lxy, ux, gwy);
    add_product(lxz, ux, gwz);
    add_product(lyx, uy, gwx);
    add_product(lyy, uy, gwy);
    add_product(lyz, uy, gwz);
    add_product(lzx, uz, gwx);
    add_product(lzy, uz, gwy);
    add_product(lzz, uz, gwz);
  }
  return {drho.sum(),
          {ax.sum(), ay.sum(), az.sum()},
          {{lxx.sum(), lxy.sum(), lxz.sum()},
           {lyx.sum(), lyy.sum(), lyz.sum()},
           {lzx.sum(), lzy.sum(), lzz.sum()}},
          Sym3::zero()};
}
#else
template <class Particles> using SumsInLanes = std::false_type;
#endif

// granular_rates without options, where the host has no lanes for p's records
template <class Particles>
KOKKOS_INLINE_FUNCTION ParticleRates granular_rates_without_options(const Particles &p, int i,
                                                                    std::false_type)
{
  return granular_rates<false, false, false, false>(p, i, nullptr, nullptr);
}

// granular_rates with its options fixed at compile time: a device kernel holds one such
// variant (a kernel's registers are those of its heaviest path, and the variant with
// every option would make the others spill); the host's loops too, chosen once per pass
template <bool WALL_NORMAL, bool SHAPE, bool VIRIAL, bool FRICTION> struct SumVariant {
  template <class Particles>
  KOKKOS_INLINE_FUNCTION static ParticleRates rates(const Particles &p, int i, double *vir,
                                                    double *slide)
  {
    return WALL_NORMAL || SHAPE || VIRIAL || FRICTION
        ? granular_rates<WALL_NORMAL, SHAPE, VIRIAL, FRICTION>(p, i, vir, slide)
        : granular_rates_without_options(p, i, SumsInLanes<Particles>());
  }
};

// f(SumVariant<...>()) for options = {wall normal, shape, virial, friction}
template <bool... FIXED> struct SumVariantOf {
  template <class F> static void choose(const bool *options, F &&f)
  {
    if (options[sizeof...(FIXED)])
      SumVariantOf<FIXED..., true>::choose(options, f);
    else
      SumVariantOf<FIXED..., false>::choose(options, f);
  }
};
template <bool WALL_NORMAL, bool SHAPE, bool VIRIAL, bool FRICTION>
struct SumVariantOf<WALL_NORMAL, SHAPE, VIRIAL, FRICTION> {
  template <class F> static void choose(const bool *, F &&f)
  {
    f(SumVariant<WALL_NORMAL, SHAPE, VIRIAL, FRICTION>());
  }
};

// f(SumVariant<...>()) for the options of p, with the virial if `virial`
template <class Particles, class F> void with_sum_variant(const Particles &p, bool virial, F &&f)
{
  const bool options[4] = {p.wall_normal, p.shape_sums, virial, p.wall_friction};
  SumVariantOf<>::choose(options, f);
}

// granular_rates with the options of p, the virial if vir is not null, and with
// wall/friction the grain's share and slide direction if slide is not null (on the host)
template <class Particles>
ParticleRates granular_rates(const Particles &p, int i, double *vir, double *slide)
{
  ParticleRates r;
  with_sum_variant(p, vir != nullptr,
                   [&](auto variant) { r = decltype(variant)::rates(p, i, vir, slide); });
  return r;
}

// The viscous-pressure diagnostic of granular particle i (compute sph/visc/atom): the
// kernel-weighted mean over its neighbours of rho_i rho_j Pi_ij / 2, the pressure that,
// put in place of Pi_ij in eq. 6b, pushes the pair apart as much. A loop of its own, run
// on the steps that ask for it only: granular_rates does not pay for it.
template <class Particles>
KOKKOS_INLINE_FUNCTION double viscous_pressure(const Particles &p, int i)
{
  using Real = typename Particles::Real;
  const auto &pi = p.particle(i);
  const Real xi = pi.x[0], yi = pi.x[1], zi = pi.x[2];
  const Real vxi = pi.v[0], vyi = pi.v[1], vzi = pi.v[2];
  const Real rho_i = pi.rho, c_i = pi.c;
  const WendlandC2Of<Real> kernel = p.kernel.template in_precision<Real>();
  const Viscosity viscosity = p.visc;
  const Real cutsq = kernel.cutsq(), h = kernel.h;
  Real w_sum = 0, visc_w = 0;
  const int n = p.num_neighbours(i);
  const auto neighbours = p.neighbours(i);
  GRANSPH_SIMD_SUM(w_sum, visc_w)
  for (int k = 0; k < n; ++k) {
    const int j = neighbours(k);
    const auto &pj = p.particle(j);
    const bool grain = p.granular(j), dummy = p.wall(j);
    const Real rx = xi - pj.x[0], ry = yi - pj.x[1], rz = zi - pj.x[2];
    const Real rsq = rx * rx + ry * ry + rz * rz;
    const bool inside = (grain || dummy) && rsq < cutsq;
    const Real w = inside ? kernel.w_inside(kernel.q(rsq)) : Real(0);
    const Real dvx = vxi - pj.v[0], dvy = vyi - pj.v[1], dvz = vzi - pj.v[2];
    const Real visc = pair_viscosity(dvx * rx + dvy * ry + dvz * rz, rsq, h, viscosity, c_i,
                                     Real(pj.c), rho_i, Real(pj.rho), grain);
    const Real volume = pj.mass * pj.inv_rho;
    w_sum += volume * w;
    visc_w += volume * w * (Real(0.5) * rho_i * pj.rho * visc);
  }
  return w_sum > 0 ? double(visc_w) / double(w_sum) : 0.0;
}

// The sums of eq. 8 for dummy particle d over its granular neighbours, in the generic loop.
template <class Particles>
KOKKOS_INLINE_FUNCTION WallSums wall_sums(const Particles &p, int d, std::false_type)
{
  const PairParticle &pd = p.particle(d);
  const double xd = pd.x[0], yd = pd.x[1], zd = pd.x[2];
  const WendlandC2 kernel = p.kernel;
  const double cutsq = kernel.cutsq();
  double sxx = 0.0, syy = 0.0, szz = 0.0, sxy = 0.0, sxz = 0.0, syz = 0.0;
  double rho_rx = 0.0, rho_ry = 0.0, rho_rz = 0.0, w_sum = 0.0;
  const int n = p.num_neighbours(d);
  const auto neighbours = p.neighbours(d);
  GRANSPH_SIMD_SUM(sxx, syy, szz, sxy, sxz, syz, rho_rx, rho_ry, rho_rz, w_sum)
  for (int k = 0; k < n; ++k) {
    const int j = neighbours(k);
    const PairParticle &pk = p.particle(j);
    // r_dk = x_d - x_k
    const double rx = xd - pk.x[0], ry = yd - pk.x[1], rz = zd - pk.x[2];
    const double rsq = rx * rx + ry * ry + rz * rz;
    const double w_in = kernel.w_inside(kernel.q(rsq));
    const double w = p.granular(j) && rsq < cutsq ? w_in : 0.0;
    sxx += w * pk.sigma.xx;
    syy += w * pk.sigma.yy;
    szz += w * pk.sigma.zz;
    sxy += w * pk.sigma.xy;
    sxz += w * pk.sigma.xz;
    syz += w * pk.sigma.yz;
    rho_rx += pk.rho * rx * w;
    rho_ry += pk.rho * ry * w;
    rho_rz += pk.rho * rz * w;
    w_sum += w;
  }
  return {{sxx, syy, szz, sxy, sxz, syz}, {rho_rx, rho_ry, rho_rz}, w_sum};
}

#if GRANSPH_LANES
// wall_sums on the host, Lanes::WIDTH grains at a time (as granular_rates_without_options:
// a pruned dummy's row holds its grains only)
template <class Particles> inline WallSums wall_sums(const Particles &p, int d, std::true_type)
{
  if (!p.grains_first) return wall_sums(p, d, std::false_type());
  using Lanes = typename LanesOf<RecordOf<Particles>>::type;
  using Record = typename Lanes::Record;
  const Record &pd = p.particle(d);
  const Lanes xd = pd.x[0], yd = pd.x[1], zd = pd.x[2];
  const WendlandC2Of<Lanes> kernel = p.kernel.template in_precision<Lanes>();
  const Lanes cutsq = kernel.cutsq();
  Lanes sxx = 0.0f, syy = 0.0f, szz = 0.0f, sxy = 0.0f, sxz = 0.0f, syz = 0.0f;
  Lanes rho_rx = 0.0f, rho_ry = 0.0f, rho_rz = 0.0f, w_sum = 0.0f;
  const int n = p.num_neighbours(d);
  const auto neighbours = p.neighbours(d);
  NeighbourBlock<Lanes> block;
  const Lanes *f = block.f;
  for (int k = 0; k < n; k += Lanes::WIDTH) {
    block.load(p, neighbours, n, k, d);
    // r_dk = x_d - x_k
    const Lanes rx = xd - f[FIELD_X], ry = yd - f[FIELD_X + 1], rz = zd - f[FIELD_X + 2];
    const Lanes rsq = rx * rx + ry * ry + rz * rz;
    const Lanes w =
        zero_unless(Lanes::first(n - k) & (rsq < cutsq), kernel.w_inside(kernel.q(rsq)));
    add_product(sxx, w, f[FIELD_SXX]);
    add_product(syy, w, f[FIELD_SYY]);
    add_product(szz, w, f[FIELD_SZZ]);
    add_product(sxy, w, f[FIELD_SXY]);
    add_product(sxz, w, f[FIELD_SXZ]);
    add_product(syz, w, f[FIELD_SYZ]);
    add_product(rho_rx, f[FIELD_RHO] * rx, w);
    add_product(rho_ry, f[FIELD_RHO] * ry, w);
    add_product(rho_rz, f[FIELD_RHO] * rz, w);
    w_sum = w_sum + w;
  }
  return {{sxx.sum(), syy.sum(), szz.sum(), sxy.sum(), sxz.sum(), syz.sum()},
          {rho_rx.sum(), rho_ry.sum(), rho_rz.sum()},
          w_sum.sum()};
}
#endif

// The sums of eq. 8 for dummy particle d over its granular neighbours: in lanes where the
// host has them
template <class Particles> KOKKOS_INLINE_FUNCTION WallSums wall_sums(const Particles &p, int d)
{
  return wall_sums(p, d, SumsInLanes<Particles>());
}

// Force of the granular neighbours on dummy particle d (eq. 9), with its stress of eq. 8
// in place; with VIRIAL, vir as in granular_rates. With FRICTION, a dummy of a wall with
// a friction of its own takes the opposite of the limited pair force (WallFrictionSums)
// and the pair's whole virial x_dj (x) f_dj, of which granular_rates tallies no half.
template <bool VIRIAL, bool FRICTION, class Particles>
KOKKOS_INLINE_FUNCTION void wall_force(const Particles &p, int d, double *force, double *vir)
{
  const PairParticle &pd = p.particle(d);
  const double xd = pd.x[0], yd = pd.x[1], zd = pd.x[2];
  const double vxd = pd.v[0], vyd = pd.v[1], vzd = pd.v[2];
  const double rho_d = pd.rho, c_d = pd.c, inv_rho_d = pd.inv_rho, m_d = pd.mass;
  const double sxx_d = pd.sigma.xx, syy_d = pd.sigma.yy, szz_d = pd.sigma.zz;
  const double sxy_d = pd.sigma.xy, sxz_d = pd.sigma.xz, syz_d = pd.sigma.yz;
  const WendlandC2 kernel = p.kernel;
  const Viscosity viscosity = p.visc;
  const double cutsq = kernel.cutsq();
  // the dummy's friction, or with the friction of the grains' materials each grain's own
  const double mu_d = FRICTION ? p.friction(d) : -1.0;
  const bool of_grains = mu_d == FrictionWall::MATERIAL, limited = mu_d >= 0.0 || of_grains;
  const double nx = limited ? p.normal(d, 0) : 0.0, ny = limited ? p.normal(d, 1) : 0.0,
               nz = limited ? p.normal(d, 2) : 0.0;
  const double share = limited ? 1.0 : 0.5;    // of the virial of each pair
  double fx = 0.0, fy = 0.0, fz = 0.0;
  double v0 = 0.0, v1 = 0.0, v2 = 0.0, v3 = 0.0, v4 = 0.0, v5 = 0.0;
  const int n = p.num_neighbours(d);
  const auto neighbours = p.neighbours(d);
  GRANSPH_SIMD_SUM(fx, fy, fz, v0, v1, v2, v3, v4, v5)
  for (int k = 0; k < n; ++k) {
    const int j = neighbours(k);
    const PairParticle &pj = p.particle(j);
    const double rx = xd - pj.x[0], ry = yd - pj.x[1], rz = zd - pj.x[2];
    const double rsq = rx * rx + ry * ry + rz * rz;
    const double fw_in = kernel.grad_factor_inside(kernel.q(rsq));
    const double fw = p.granular(j) && rsq < cutsq ? fw_in : 0.0;
    const double gwx = fw * rx, gwy = fw * ry, gwz = fw * rz;
    const double dvx = vxd - pj.v[0], dvy = vyd - pj.v[1], dvz = vzd - pj.v[2];
    const double visc = pair_viscosity(dvx * rx + dvy * ry + dvz * rz, rsq, kernel.h, viscosity,
                                       c_d, pj.c, rho_d, pj.rho, false);
    const double inv_rho_ij = inv_rho_d * pj.inv_rho;
    const double sxx = sxx_d + pj.sigma.xx, syy = syy_d + pj.sigma.yy, szz = szz_d + pj.sigma.zz;
    const double sxy = sxy_d + pj.sigma.xy, sxz = sxz_d + pj.sigma.xz, syz = syz_d + pj.sigma.yz;
    const double mm = m_d * pj.mass;
    double fdx = mm * stress_gradient(sxx, sxy, sxz, inv_rho_ij, visc, gwx, gwy, gwz, gwx);
    double fdy = mm * stress_gradient(sxy, syy, syz, inv_rho_ij, visc, gwx, gwy, gwz, gwy);
    double fdz = mm * stress_gradient(sxz, syz, szz, inv_rho_ij, visc, gwx, gwy, gwz, gwz);
    if (FRICTION) {
      const bool slides = limited && p.slide(j, 0) < 1.0;
      const double mu = of_grains ? p.friction(j) : mu_d;
      const double fn = fdx * nx + fdy * ny + fdz * nz, mu_fn = mu * fn;
      fdx = slides ? fn * nx + mu_fn * p.slide(j, 1) : fdx;
      fdy = slides ? fn * ny + mu_fn * p.slide(j, 2) : fdy;
      fdz = slides ? fn * nz + mu_fn * p.slide(j, 3) : fdz;
    }
    fx += fdx;
    fy += fdy;
    fz += fdz;
    if (VIRIAL) {
      v0 += share * rx * fdx;
      v1 += share * ry * fdy;
      v2 += share * rz * fdz;
      v3 += share * rx * fdy;
      v4 += share * rx * fdz;
      v5 += share * ry * fdz;
    }
  }
  force[0] = fx;
  force[1] = fy;
  force[2] = fz;
  if (VIRIAL) {
    const double sums[6] = {v0, v1, v2, v3, v4, v5};
    for (int k = 0; k < 6; ++k) vir[k] += sums[k];
  }
}

// wall_force without options (no virial, no wall friction), in the generic loop
template <class Particles>
KOKKOS_INLINE_FUNCTION void wall_force_without_options(const Particles &p, int d, double *force,
                                                       std::false_type)
{
  wall_force<false, false>(p, d, force, nullptr);
}

#if GRANSPH_LANES
// wall_force without options on the host, Lanes::WIDTH grains at a time (as wall_sums)
template <class Particles>
inline void wall_force_without_options(const Particles &p, int d, double *force, std::true_type)
{
  if (!p.grains_first) return wall_force<false, false>(p, d, force, nullptr);
  using Lanes = typename LanesOf<RecordOf<Particles>>::type;
  using Record = typename Lanes::Record;
  const Record &pd = p.particle(d);
  const Lanes xd = pd.x[0], yd = pd.x[1], zd = pd.x[2];
  const Lanes vxd = pd.v[0], vyd = pd.v[1], vzd = pd.v[2];
  const Lanes rho_d = pd.rho, c_d = pd.c, inv_rho_d = pd.inv_rho, m_d = pd.mass;
  const Lanes sxx_d = pd.sigma.xx, syy_d = pd.sigma.yy, szz_d = pd.sigma.zz;
  const Lanes sxy_d = pd.sigma.xy, sxz_d = pd.sigma.xz, syz_d = pd.sigma.yz;
  const WendlandC2Of<Lanes> kernel = p.kernel.template in_precision<Lanes>();
  const Viscosity viscosity = p.visc;
  const Lanes cutsq = kernel.cutsq(), h = kernel.h;
  Lanes fx = 0.0f, fy = 0.0f, fz = 0.0f;
  const int n = p.num_neighbours(d);
  const auto neighbours = p.neighbours(d);
  NeighbourBlock<Lanes> block;
  const Lanes *f = block.f;
  for (int k = 0; k < n; k += Lanes::WIDTH) {
    block.load(p, neighbours, n, k, d);
    const Lanes rx = xd - f[FIELD_X], ry = yd - f[FIELD_X + 1], rz = zd - f[FIELD_X + 2];
    const Lanes rsq = rx * rx + ry * ry + rz * rz;
    const Lanes fw = zero_unless(Lanes::first(n - k) & (rsq < cutsq),
                                 kernel.grad_factor_inside(kernel.q(rsq)));
    const Lanes gwx = fw * rx, gwy = fw * ry, gwz = fw * rz;
    const Lanes dvx = vxd - f[FIELD_V], dvy = vyd - f[FIELD_V + 1], dvz = vzd - f[FIELD_V + 2];
    const Lanes visc = pair_viscosity(dvx * rx + dvy * ry + dvz * rz, rsq, h, viscosity, c_d,
                                      f[FIELD_C], rho_d, f[FIELD_RHO], false);
    const Lanes inv_rho_ij = inv_rho_d * f[FIELD_INV_RHO];
    const Lanes sxx = sxx_d + f[FIELD_SXX], syy = syy_d + f[FIELD_SYY], szz = szz_d + f[FIELD_SZZ];
    const Lanes sxy = sxy_d + f[FIELD_SXY], sxz = sxz_d + f[FIELD_SXZ], syz = syz_d + f[FIELD_SYZ];
    const Lanes mm = m_d * f[FIELD_MASS];
    add_product(fx, mm, stress_gradient(sxx, sxy, sxz, inv_rho_ij, visc, gwx, gwy, gwz, gwx));
    add_product(fy, mm, stress_gradient(sxy, syy, syz, inv_rho_ij, visc, gwx, gwy, gwz, gwy));
    add_product(fz, mm, stress_gradient(sxz, syz, szz, inv_rho_ij, visc, gwx, gwy, gwz, gwz));
  }
  force[0] = fx.sum();
  force[1] = fy.sum();
  force[2] = fz.sum();
}
#endif

// wall_force with the options of p, with the virial if vir is not null
template <class Particles>
KOKKOS_INLINE_FUNCTION void wall_force(const Particles &p, int d, double *force, double *vir)
{
  if (p.wall_friction) {
    if (vir)
      wall_force<true, true>(p, d, force, vir);
    else
      wall_force<false, true>(p, d, force, vir);
  } else if (vir)
    wall_force<true, false>(p, d, force, vir);
  else
    wall_force_without_options(p, d, force, SumsInLanes<Particles>());
}

// The force of the grains on a dummy particle for this evaluation: fd as computed, kept in
// last (3 values) for the next run; or at the setup of a run that continues the last
// (repeat), the force of the last step, so that a body the dummies belong to (fix rigid,
// whose first half-kick takes the setup force) moves on as if the runs were one.
KOKKOS_INLINE_FUNCTION void keep_or_repeat_wall_force(double *fd, double *last, bool repeat)
{
  for (int a = 0; a < 3; ++a) {
    if (repeat)
      fd[a] = last[a];
    else
      last[a] = fd[a];
  }
}

}    // namespace GRANSPH

#endif
