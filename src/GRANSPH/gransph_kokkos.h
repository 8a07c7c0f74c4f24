/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: what the Kokkos styles share. SPHStateKokkos is the per-atom SPH
   state of a /kk integrator as DualViews (the pair style finds it there);
   DeviceParticles is the device accessor for the neighbour sums of
   gransph_neighbour_sums.h, the twin of the plain pair's HostParticles.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_KOKKOS_H
#define LMP_GRANSPH_KOKKOS_H

#include "gransph_kernel.h"
#include "gransph_kokkos_compat.h"
#include "gransph_pair_settings.h"
#include "gransph_state.h"
#include "pointers.h"

#include <type_traits>

namespace LAMMPS_NS {

// The arrays of FixSPHIntegrate (same columns) on host and device.
class SPHStateKokkos {
 public:
  // as nothrow as Pointers::~Pointers() (noexcept(false) in current LAMMPS, noexcept in
  // 29Sep2021): a fix deriving from both may not be looser than either base
  virtual ~SPHStateKokkos() noexcept(std::is_nothrow_destructible<Pointers>::value) {}
  GRANSPHCompat::tdual_state k_state, k_rates, k_start;

  // the state by name (gransph_state.h) in DeviceType's memory
  template <class DeviceType>
  GRANSPH::StateAccess<typename GRANSPHCompat::KokkosTypes<DeviceType>::t_state> state_on() const
  {
    return {k_state.template view<DeviceType>(), k_rates.template view<DeviceType>(),
            k_start.template view<DeviceType>()};
  }
};

// Grains cost far more than dummy particles and lie in blocks of memory (creation
// order, or spatial bins after atom sorting), so equal static chunks leave threads
// idle: loops whose work is per grain hand out the particles dynamically.
template <class DeviceType>
using ParticlePolicy = Kokkos::RangePolicy<DeviceType, Kokkos::Schedule<Kokkos::Dynamic>>;

// The atoms as the shared neighbour sums read them on the device: their neighbour rows,
// roles and wall arrays
template <class DeviceType> struct DeviceAtoms {
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_neighbors_2d neighbors;
  typename AT::t_int_1d_randomread numneigh, mask;
  int granularbit, wallbit;
  // 3 per atom, with wall_normal or wall_friction
  Kokkos::View<const double *, DeviceType> normals;
  // with wall_friction, 1 and 4 per atom
  Kokkos::View<const double *, DeviceType> friction_mu, friction_slide;
};

// The device accessor for the neighbour sums (gransph_neighbour_sums.h), the twin of the
// plain pair's HostParticles. Particle: GRANSPH::PairParticle, or PairParticleSingle for
// the grains' sums under `precision mixed`.
template <class DeviceType, class Particle = GRANSPH::PairParticle>
struct DeviceParticles : GRANSPH::SumOptions, DeviceAtoms<DeviceType> {
  typedef ArrayTypes<DeviceType> AT;
  using Real = decltype(Particle::rho);
  using Atoms = DeviceAtoms<DeviceType>;
  Kokkos::View<const Particle *, DeviceType> particles;

  DeviceParticles(const GRANSPH::SumOptions &options, const Atoms &atoms,
                  Kokkos::View<const Particle *, DeviceType> particles) :
      GRANSPH::SumOptions(options), Atoms(atoms), particles(particles)
  {
  }

  // one particle's row of the list: contiguous on the host (LayoutRight), strided on GPUs
  struct NeighbourRow {
    decltype(Kokkos::subview(typename AT::t_neighbors_2d(), 0, Kokkos::ALL)) row;
    KOKKOS_INLINE_FUNCTION int operator()(int k) const { return row(k) & NEIGHMASK; }
  };

  KOKKOS_INLINE_FUNCTION int num_neighbours(int i) const { return this->numneigh(i); }
  KOKKOS_INLINE_FUNCTION NeighbourRow neighbours(int i) const
  {
    return {Kokkos::subview(this->neighbors, i, Kokkos::ALL)};
  }
  KOKKOS_INLINE_FUNCTION const Particle &particle(int i) const { return particles(i); }
  KOKKOS_INLINE_FUNCTION bool granular(int i) const { return this->mask(i) & this->granularbit; }
  KOKKOS_INLINE_FUNCTION bool wall(int i) const { return this->mask(i) & this->wallbit; }
  KOKKOS_INLINE_FUNCTION double normal(int i, int a) const { return this->normals(3 * i + a); }
  KOKKOS_INLINE_FUNCTION double friction(int i) const { return this->friction_mu(i); }
  KOKKOS_INLINE_FUNCTION double slide(int i, int k) const
  {
    return this->friction_slide(GRANSPH::SLIDE_VALUES * i + k);
  }

  // the same atoms and settings over `single`, the particles in single precision
  DeviceParticles<DeviceType, GRANSPH::PairParticleSingle>
  in_single(Kokkos::View<const GRANSPH::PairParticleSingle *, DeviceType> single) const
  {
    return {*this, *this, single};
  }
};

}    // namespace LAMMPS_NS

#endif
