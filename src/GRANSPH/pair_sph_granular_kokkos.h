/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: Kokkos twin of pair_style sph/granular. Same neighbour sums
   (gransph_neighbour_sums.h) over a full Kokkos neighbour list, one particle
   per thread writing only to itself: no atomics.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(sph/granular/kk,PairSPHGranularKokkos<LMPDeviceType>);
PairStyle(sph/granular/kk/device,PairSPHGranularKokkos<LMPDeviceType>);
PairStyle(sph/granular/kk/host,PairSPHGranularKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_PAIR_SPH_GRANULAR_KOKKOS_H
#define LMP_PAIR_SPH_GRANULAR_KOKKOS_H

#include "gransph_kokkos.h"
#include "kokkos_type.h"
#include "pair_sph_granular.h"

namespace LAMMPS_NS {

template <class DeviceType> class PairSPHGranularKokkos : public PairSPHGranular {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  PairSPHGranularKokkos(class LAMMPS *);
  ~PairSPHGranularKokkos() override;
  void compute(int, int) override;
  void init_style() override;

  // device kernels (public: CUDA lambdas may not live in private members)
  void pack_particles(SPHStateKokkos &kk, int from, int to);
  void walls(const DeviceParticles<DeviceType> &p, SPHStateKokkos &kk);
  void grains(const DeviceParticles<DeviceType> &p, SPHStateKokkos &kk);

 private:
  GRANSPHCompat::tdual_virial k_vatom;
  Kokkos::View<GRANSPH::PairParticle *, DeviceType> d_particles;    // owned and ghost atoms
  // with wall/gradient normal, 3 per atom (pack_wall_normals), copied to the device
  // when atoms may have moved between ranks or in memory
  Kokkos::DualView<double *, DeviceType> k_normals;

  void update_wall_normals(int nall);
};

}    // namespace LAMMPS_NS

#endif
#endif
