/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: Kokkos twin of FixSPHModel<Model>: the per-atom SPH state lives in
   DualViews; predictor, corrector, stress update, CFL reduction and forward
   communication run on the device with the same per-particle functions as the
   plain styles (gransph_integrator.h). Migration and sorting: as
   GRANSPH_KOKKOS_FIX_DEVICE_EXCHANGE says; restarts and creation of atoms use the
   host copies.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_MODEL_KOKKOS_H
#define LMP_FIX_SPH_MODEL_KOKKOS_H

#include "fix_sph_model.h"
#include "gransph_kokkos.h"
#include "kokkos_base.h"

namespace LAMMPS_NS {

template <class DeviceType, class Model>
class FixSPHModelKokkos : public FixSPHModel<Model>, public KokkosBase, public SPHStateKokkos {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  FixSPHModelKokkos(class LAMMPS *, int, char **);
  ~FixSPHModelKokkos() override;
  void init() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  void final_integrate() override;
  void end_of_step() override;
  void post_run() override;
  void forward_comm_state() override;

  void grow_arrays(int) override;
  GRANSPH_KOKKOS_FIX_FORWARD_COMM
  GRANSPH_KOKKOS_FIX_DEVICE_EXCHANGE(k_state, k_rates, k_start)
  int pack_forward_comm_device(int, const typename GRANSPHCompat::KokkosTypes<DeviceType>::SendList &,
                               GRANSPHCompat::tdual_comm_buffer &);
  void unpack_forward_comm_device(int, int, GRANSPHCompat::tdual_comm_buffer &);

  // device kernels (public: CUDA lambdas may not live in private members)
  int step(GRANSPH::Stage stage) override;
  int step_on_host(GRANSPH::Stage stage);
  int step_on_device(GRANSPH::Stage stage);
  void cfl_maxima(double *local) override;

 protected:
  using Arrays = FixSPHIntegrate::Arrays;
  void sync_host(Arrays = FixSPHIntegrate::ALL_ARRAYS) override;
  void modified_host(Arrays = FixSPHIntegrate::ALL_ARRAYS) override;
};

}    // namespace LAMMPS_NS

#endif
