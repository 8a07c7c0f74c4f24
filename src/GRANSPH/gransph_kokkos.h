/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: what the Kokkos styles share. SPHStateKokkos is the per-atom SPH
   state of a /kk integrator as DualViews (the pair style finds it there);
   DeviceParticles is the accessor for the neighbour sums of
   gransph_neighbour_sums.h over the atoms on a device.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_KOKKOS_H
#define LMP_GRANSPH_KOKKOS_H

#include "gransph_kernel.h"
#include "gransph_kokkos_compat.h"
#include "gransph_pair_passes.h"
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
  // with the rows pruned grains first, their grains
  bool grains_first = false;
  typename AT::t_int_1d_randomread numgrains;
  // 3 per atom, with wall_normal or wall_friction
  Kokkos::View<const double *, DeviceType> normals;
  // with wall_friction, 1 and 4 per atom
  Kokkos::View<const double *, DeviceType> friction_mu, friction_slide;

  // one particle's row of the list: contiguous on the host (LayoutRight), strided on GPUs
  struct NeighbourRow {
    decltype(Kokkos::subview(typename AT::t_neighbors_2d(), 0, Kokkos::ALL)) row;
    KOKKOS_INLINE_FUNCTION int operator()(int k) const { return row(k) & NEIGHMASK; }
  };
  KOKKOS_INLINE_FUNCTION NeighbourRow row(int i) const
  {
    return {Kokkos::subview(neighbors, i, Kokkos::ALL)};
  }
};

// The accessor for the neighbour sums over the atoms on a device (GRANSPH::ParticlesOf)
template <class DeviceType, class Particle = GRANSPH::PairParticle>
using DeviceParticles = GRANSPH::ParticlesOf<DeviceAtoms<DeviceType>, Particle,
                                             Kokkos::View<const Particle *, DeviceType>>;

}    // namespace LAMMPS_NS

#endif
