/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: Kokkos twin of pair_style sph/granular. Same neighbour sums
   (gransph_neighbour_sums.h) over a full Kokkos neighbour list, one particle
   per thread writing only to itself: no atomics.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_SPH_GRANULAR_KOKKOS_H
#define LMP_PAIR_SPH_GRANULAR_KOKKOS_H

#include "gransph_kokkos.h"
#include "kokkos_type.h"
#include "pair_sph_granular.h"

namespace LAMMPS_NS {

template <class DeviceType>
class PairSPHGranularKokkos : public PairSPHGranular, public KokkosBase {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  PairSPHGranularKokkos(class LAMMPS *);
  ~PairSPHGranularKokkos() override;
  void compute(int, int) override;
  void init_style() override;
  const double *viscous_pressure() override;
  double memory_usage() override;
  // how the grains slide on walls with a friction of their own, to the ghosts: on the
  // device, or through the host when comm/kokkos takes the classic path
  double *slide_on_host() override
  {
    k_slide.sync_host();
    return k_slide.view_host().data();
  }
  void slide_changed_on_host() override { k_slide.modify_host(); }
  GRANSPH_KOKKOS_PAIR_FORWARD_COMM
  int pack_forward_comm_device(int,
                               const typename GRANSPHCompat::KokkosTypes<DeviceType>::SendList &,
                               GRANSPHCompat::tdual_comm_buffer &);
  void unpack_forward_comm_device(int, int, GRANSPHCompat::tdual_comm_buffer &);

  // the steps of PairSPHGranular::evaluate_passes on DeviceType, and the device kernels
  // (public: CUDA lambdas may not live in private members)
  void check_no_coincident(const DeviceParticles<DeviceType> &p);
  void check_wall_spacing();
  double pack_particles(int from, int to, bool since_pruned = false);
  Kokkos::View<const GRANSPH::PairParticleSingle *, DeviceType> pack_particles_single(int n);
  void walls(const DeviceParticles<DeviceType> &p, bool stress, bool forces);
  // Particles: DeviceParticles<DeviceType> or, under precision mixed, over PairParticleSingle
  template <class Particles> void grains(const Particles &p);
  template <class Sums, class Particles> EV_FLOAT grains_of(const Particles &p);
  template <class Particles> void viscous_pressures(const Particles &p);
  void prune_rows(DeviceParticles<DeviceType> &p, int nall, double moved_sq);
  template <bool DUMMIES> void prune_rows_of(const DeviceParticles<DeviceType> &p);

 private:
  SPHStateKokkos *state_kk;    // the integrator's state in DualViews (init_style)
  GRANSPHCompat::tdual_virial k_vatom;
  Kokkos::View<GRANSPH::PairParticle *, DeviceType> d_particles;    // owned and ghost atoms
  Kokkos::View<GRANSPH::PairParticleSingle *, DeviceType> d_particles_single;    // their copy
                                                                 // under precision mixed
  // with wall/gradient normal or wall/friction, 3 per atom (pack_wall_normals), and with
  // wall/friction the dummies' friction coefficients (pack_wall_friction), copied to the
  // device when atoms may have moved between ranks or in memory
  Kokkos::DualView<double *, DeviceType> k_normals, k_friction;
  // with wall/friction, 4 per atom: a grain's share and slide direction
  Kokkos::DualView<double *, DeviceType> k_slide;
  // owned atoms: viscous_pressure()
  Kokkos::DualView<double *, DeviceType> k_visc_pressure;
  // with prune: how many neighbours at the front of each owned atom's row of the list
  // count, and of them the grains, first, pruned at the positions pruned_x of the owned
  // and ghost atoms (floats from pruned_origin)
  typename AT::t_int_1d d_pruned_count, d_pruned_grains;
  Kokkos::View<float *[3], DeviceType> d_pruned_x;
  GRANSPH::PrunedPositions<Kokkos::View<float *[3], DeviceType>> pruned_positions() const;

  int update_wall_normals(int nall, bool limited);
  auto dummy_forces();
};

}    // namespace LAMMPS_NS

#endif
