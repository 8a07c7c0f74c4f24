/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: what the Kokkos styles share. SPHStateKokkos is the per-atom SPH
   state of a /kk integrator as DualViews (the pair style finds it there);
   DeviceParticles is the device accessor for the neighbour sums of
   gransph_neighbour_sums.h, the twin of the plain pair's HostParticles.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_KOKKOS_H
#define LMP_GRANSPH_KOKKOS_H

#include "fix_sph_integrate.h"
#include "gransph_kernel.h"
#include "gransph_kokkos_compat.h"
#include "gransph_pair_terms.h"

#include <type_traits>

namespace LAMMPS_NS {

// The arrays of FixSPHIntegrate (same columns) on host and device.
class SPHStateKokkos {
 public:
  // as nothrow as Pointers::~Pointers() (noexcept(false) in current LAMMPS, noexcept in
  // 29Sep2021): a fix deriving from both may not be looser than either base
  virtual ~SPHStateKokkos() noexcept(std::is_nothrow_destructible<Pointers>::value) {}
  GRANSPHCompat::tdual_state k_state, k_rates, k_start;
};

// Grains cost far more than dummy particles and lie in blocks of memory (creation
// order, or spatial bins after atom sorting), so equal static chunks leave threads
// idle: loops whose work is per grain hand out the particles dynamically.
template <class DeviceType>
using ParticlePolicy = Kokkos::RangePolicy<DeviceType, Kokkos::Schedule<Kokkos::Dynamic>>;

// Particle: GRANSPH::PairParticle, or PairParticleSingle for the grains' sums under
// `precision mixed`
template <class DeviceType, class Particle = GRANSPH::PairParticle> struct DeviceParticles {
  typedef ArrayTypes<DeviceType> AT;
  using Real = decltype(Particle::rho);
  Kokkos::View<const Particle *, DeviceType> particles;
  typename AT::t_neighbors_2d neighbors;
  typename AT::t_int_1d_randomread numneigh, mask;
  int granularbit, wallbit;
  GRANSPH::WendlandC2 kernel;
  GRANSPH::Viscosity visc;
  bool wall_normal, shape_sums, wall_friction;
  // 3 per atom, with wall_normal or wall_friction
  Kokkos::View<const double *, DeviceType> normals;
  // with wall_friction, 1 and 4 per atom
  Kokkos::View<const double *, DeviceType> friction_mu, friction_slide;
  GRANSPH::WallStick stick;    // with wall_friction: how the walls hold a grain

  // one particle's row of the list: contiguous on the host (LayoutRight), strided on GPUs
  struct NeighbourRow {
    decltype(Kokkos::subview(typename AT::t_neighbors_2d(), 0, Kokkos::ALL)) row;
    KOKKOS_INLINE_FUNCTION int operator()(int k) const { return row(k) & NEIGHMASK; }
  };

  KOKKOS_INLINE_FUNCTION int num_neighbours(int i) const { return numneigh(i); }
  KOKKOS_INLINE_FUNCTION NeighbourRow neighbours(int i) const
  {
    return {Kokkos::subview(neighbors, i, Kokkos::ALL)};
  }
  KOKKOS_INLINE_FUNCTION const Particle &particle(int i) const { return particles(i); }
  KOKKOS_INLINE_FUNCTION bool granular(int i) const { return mask(i) & granularbit; }
  KOKKOS_INLINE_FUNCTION bool wall(int i) const { return mask(i) & wallbit; }
  KOKKOS_INLINE_FUNCTION double normal(int i, int a) const { return normals(3 * i + a); }
  KOKKOS_INLINE_FUNCTION double friction(int i) const { return friction_mu(i); }
  KOKKOS_INLINE_FUNCTION double slide(int i, int k) const
  {
    return friction_slide(GRANSPH::SLIDE_VALUES * i + k);
  }

  // the same atoms and settings over `single`, the particles in single precision
  DeviceParticles<DeviceType, GRANSPH::PairParticleSingle>
  in_single(Kokkos::View<const GRANSPH::PairParticleSingle *, DeviceType> single) const
  {
    DeviceParticles<DeviceType, GRANSPH::PairParticleSingle> p;
    p.particles = single;
    p.neighbors = neighbors;
    p.numneigh = numneigh;
    p.mask = mask;
    p.granularbit = granularbit;
    p.wallbit = wallbit;
    p.kernel = kernel;
    p.visc = visc;
    p.wall_normal = wall_normal;
    p.shape_sums = shape_sums;
    p.wall_friction = wall_friction;
    p.normals = normals;
    p.friction_mu = friction_mu;
    p.friction_slide = friction_slide;
    p.stick = stick;
    return p;
  }
};

}    // namespace LAMMPS_NS

#endif
