/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: what the Kokkos styles share. SPHStateKokkos is the per-atom SPH
   state of a /kk integrator as DualViews (the pair style finds it there);
   DeviceParticles is the device accessor for the neighbour sums of
   gransph_neighbour_sums.h, the twin of the plain pair's HostParticles.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_KOKKOS_H
#define LMP_GRANSPH_KOKKOS_H

#include "fix_sph_integrate.h"
#include "gransph_integrator.h"
#include "gransph_pair_terms.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

// The arrays of FixSPHIntegrate (same columns) on host and device.
class SPHStateKokkos {
 public:
  virtual ~SPHStateKokkos() = default;
  DAT::tdual_float_2d k_state, k_rates, k_start;
};

template <class DeviceType> struct DeviceParticles {
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array_randomread pos;
  typename AT::t_v_array_randomread vel;
  typename AT::t_int_1d_randomread mask, type;
  typename AT::t_float_1d_randomread rmass, mass;
  typename AT::t_float_2d state;
  typename AT::t_neighbors_2d neighbors;
  typename AT::t_int_1d_randomread numneigh;
  int granularbit, wallbit, use_rmass, dim;
  double E, h, alpha, beta;

  KOKKOS_INLINE_FUNCTION int num_neighbours(int i) const { return numneigh(i); }
  KOKKOS_INLINE_FUNCTION int neighbour(int i, int k) const { return neighbors(i, k) & NEIGHMASK; }
  KOKKOS_INLINE_FUNCTION double x(int i, int a) const { return pos(i, a); }
  KOKKOS_INLINE_FUNCTION double v(int i, int a) const { return vel(i, a); }
  KOKKOS_INLINE_FUNCTION bool granular(int i) const { return mask(i) & granularbit; }
  KOKKOS_INLINE_FUNCTION bool wall(int i) const { return mask(i) & wallbit; }
  KOKKOS_INLINE_FUNCTION double mass_of(int i) const { return use_rmass ? rmass(i) : mass(type(i)); }
  KOKKOS_INLINE_FUNCTION GRANSPH::ParticleView view(int i) const
  {
    constexpr int S = FixSPHIntegrate::SIGMA;
    const double rho = state(i, FixSPHIntegrate::RHO);
    return {mass_of(i), rho,
            {state(i, S), state(i, S + 1), state(i, S + 2), state(i, S + 3), state(i, S + 4),
             state(i, S + 5)}};
  }
};

}    // namespace LAMMPS_NS

#endif
