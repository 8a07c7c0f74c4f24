/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: Kokkos twin of the granular SPH integrators.
------------------------------------------------------------------------- */

#include "fix_sph_model_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "error.h"
#include "fix_sph_models.h"
#include "force.h"
#include "memory_kokkos.h"
#include "output.h"
#include "pair.h"
#include "update.h"

using namespace LAMMPS_NS;
using FSI = FixSPHIntegrate;

namespace {

// The rows the grains' step reads and writes (GRANSPH::step_grain) on the device: the
// loop's k-th atom is atom k
template <class DeviceType> struct DeviceGrainRows {
  typedef GRANSPHCompat::KokkosTypes<DeviceType> KT;
  typename KT::t_x x;
  typename KT::t_v v;
  typename KT::t_f_const f;
  typename KT::t_state state, rates, start;
  typename KT::t_int_const type;
  typename KT::t_mass_const rmass, type_mass;
  int use_rmass;

  KOKKOS_INLINE_FUNCTION int atom(int k) const { return k; }
  KOKKOS_INLINE_FUNCTION double mass(int k) const { return use_rmass ? rmass(k) : type_mass(type(k)); }
};

// One predictor or corrector step of every granular particle of material k
template <class DeviceType, class Model, GRANSPH::Stage STAGE, bool EXTRAPOLATE>
struct StepFunctor {
  Model model;
  DeviceGrainRows<DeviceType> rows;
  typename GRANSPHCompat::KokkosTypes<DeviceType>::t_int_const mask;
  int groupbit;
  GRANSPH::MaterialTable materials;
  int k;
  double dt, ftm2v;

  // whether atom i is a grain that the corrector left with a bad state
  KOKKOS_INLINE_FUNCTION int step(const int i) const
  {
    const bool grain = (mask(i) & groupbit) && materials.holds(k, mask(i));
    return grain ? GRANSPH::step_grain<STAGE, EXTRAPOLATE>(model, rows, i, dt, ftm2v) : 0;
  }
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { step(i); }
};

// A step as a reduction: the count of grains left with a bad state
template <class Step> struct CountingBadStates {
  Step s;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, int &bad) const { bad += s.step(i); }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType, class Model>
FixSPHModelKokkos<DeviceType, Model>::FixSPHModelKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixSPHModel<Model>(lmp, narg, arg)
{
  this->kokkosable = 1;
  this->forward_comm_device = 1;
  GRANSPHCompat::enable_device_exchange(this, this->row_size());
  this->atomKK = (AtomKokkos *) this->atom;
  this->execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  this->datamask_read = X_MASK | V_MASK | F_MASK | MASK_MASK | RMASS_MASK | TYPE_MASK;
  this->datamask_modify = X_MASK | V_MASK;

  // the base constructor made plain host arrays: move the state into DualViews
  this->memory->destroy(this->state);
  this->memory->sfree(this->rates);
  this->memory->sfree(this->start);
  this->rates = this->start = nullptr;
  grow_arrays(this->atom->nmax);
  for (int i = 0; i < this->atom->nlocal; ++i) this->set_arrays(i);
}

template <class DeviceType, class Model> FixSPHModelKokkos<DeviceType, Model>::~FixSPHModelKokkos()
{
  this->memoryKK->destroy_kokkos(k_state, this->state);
  // rates and start point into the DualViews' host copies, which free themselves
  this->rates = this->start = nullptr;
}

template <class DeviceType, class Model> void FixSPHModelKokkos<DeviceType, Model>::init()
{
  FixSPHModel<Model>::init();
  if (!this->force->pair->kokkosable)
    this->error->all(FLERR, "Fix {} needs pair_style sph/granular/kk", this->style);
  // LAMMPS 29Sep2021's fix property/atom/kk keeps rmass on the host only
  if (this->atom->rmass && this->atomKK->k_rmass.view_host().data() != this->atom->rmass)
    this->error->all(FLERR, "Fix {}: per-atom masses of fix property/atom are not available "
                     "to Kokkos styles in this LAMMPS version", this->style);
  this->atomKK->k_mass.template modify<LMPHostType>();
  this->atomKK->k_mass.template sync<DeviceType>();
}

template <class DeviceType, class Model>
void FixSPHModelKokkos<DeviceType, Model>::setup_pre_force(int vflag)
{
  this->atomKK->sync(Host, X_MASK | MASK_MASK);
  FixSPHModel<Model>::setup_pre_force(vflag);
}

// the checks and the continuation work on the host copies, once per run
template <class DeviceType, class Model> void FixSPHModelKokkos<DeviceType, Model>::setup(int vflag)
{
  this->atomKK->sync(this->execution_space, this->datamask_read);
  this->atomKK->sync(Host, X_MASK | V_MASK | MASK_MASK | TAG_MASK);
  FixSPHModel<Model>::setup(vflag);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType, class Model>
void FixSPHModelKokkos<DeviceType, Model>::final_integrate()
{
  if (step(GRANSPH::CORRECT)) {
    // find and name the atom on the host; this only happens once, on failure
    this->atomKK->sync(Host, X_MASK | V_MASK | MASK_MASK | TAG_MASK);
    sync_host();
    this->check_finite();
  }
}

template <class DeviceType, class Model>
int FixSPHModelKokkos<DeviceType, Model>::step(GRANSPH::Stage stage)
{
  return this->execution_space == Host ? step_on_host(stage) : step_on_device(stage);
}

// On the host, the plain fix's loop over the grains (the same arithmetic, vectorised) in
// parallel chunks
template <class DeviceType, class Model>
int FixSPHModelKokkos<DeviceType, Model>::step_on_host(GRANSPH::Stage stage)
{
  constexpr int CHUNK = 256;
  this->atomKK->sync(Host, this->datamask_read);
  sync_host();
  const int bad = this->step_grains(stage, this->atom->x, this->atom->v, this->atom->f,
                                    [](const auto &advance) {
                                      const int n = advance.n;
                                      int count = 0;
                                      Kokkos::parallel_reduce(
                                          ParticlePolicy<LMPHostType>(0, (n + CHUNK - 1) / CHUNK),
                                          [&](const int c, int &sum) {
                                            const int end = (c + 1) * CHUNK;
                                            sum += advance(c * CHUNK, end < n ? end : n);
                                          },
                                          count);
                                      return count;
                                    });
  this->atomKK->modified(Host, this->datamask_modify);
  modified_host();
  return bad;
}

// the step's kernel; the corrector's is a reduction that counts the grains with a bad state
template <class DeviceType, class Model>
int FixSPHModelKokkos<DeviceType, Model>::step_on_device(GRANSPH::Stage stage)
{
  AtomKokkos *atomKK = this->atomKK;
  atomKK->sync(this->execution_space, this->datamask_read);
  k_state.template sync<DeviceType>();
  k_rates.template sync<DeviceType>();
  k_start.template sync<DeviceType>();

  const DeviceGrainRows<DeviceType> rows{atomKK->k_x.template view<DeviceType>(),
                                         atomKK->k_v.template view<DeviceType>(),
                                         atomKK->k_f.template view<DeviceType>(),
                                         k_state.template view<DeviceType>(),
                                         k_rates.template view<DeviceType>(),
                                         k_start.template view<DeviceType>(),
                                         atomKK->k_type.template view<DeviceType>(),
                                         atomKK->k_rmass.template view<DeviceType>(),
                                         atomKK->k_mass.template view<DeviceType>(),
                                         this->atom->rmass != nullptr};
  const auto mask = atomKK->k_mask.template view<DeviceType>();
  const int groupbit = this->groupbit;
  const double dt = this->update->dt, ftm2v = this->force->ftm2v;
  const ParticlePolicy<DeviceType> atoms(0, this->atom->nlocal, Kokkos::ChunkSize(256));
  int bad = 0;
  const auto run = [&](auto functor) {
    int material_bad = 0;
    if (stage == GRANSPH::PREDICT)
      Kokkos::parallel_for(atoms, functor);    // no reduction, which would wait for a device
    else
      Kokkos::parallel_reduce(atoms, CountingBadStates<decltype(functor)>{functor}, material_bad);
    bad += material_bad;
  };
  const bool extrapolate = this->predictor_extrapolated;
  using GRANSPH::CORRECT;
  using GRANSPH::PREDICT;
  const GRANSPH::MaterialTable &materials = this->materials;
  for (int k = 0; k < materials.n; ++k) {
    const Model &model = this->models[k];
    if (stage == PREDICT && extrapolate)
      run(StepFunctor<DeviceType, Model, PREDICT, true>{model, rows, mask, groupbit, materials, k, dt, ftm2v});
    else if (stage == PREDICT)
      run(StepFunctor<DeviceType, Model, PREDICT, false>{model, rows, mask, groupbit, materials, k, dt, ftm2v});
    else if (extrapolate)
      run(StepFunctor<DeviceType, Model, CORRECT, true>{model, rows, mask, groupbit, materials, k, dt, ftm2v});
    else
      run(StepFunctor<DeviceType, Model, CORRECT, false>{model, rows, mask, groupbit, materials, k, dt, ftm2v});
  }

  atomKK->modified(this->execution_space, this->datamask_modify);
  k_state.template modify<DeviceType>();
  k_start.template modify<DeviceType>();
  if (extrapolate) k_rates.template modify<DeviceType>();    // PREV, ACC and RATES_DT
  return bad;    // local: the rank that has one stops the run (error->one), no collective
}

// both maxima reduced on the device
template <class DeviceType, class Model>
void FixSPHModelKokkos<DeviceType, Model>::cfl_maxima(double *local)
{
  k_state.template sync<DeviceType>();
  auto f = this->atomKK->k_f.template view<DeviceType>();
  auto mask = this->atomKK->k_mask.template view<DeviceType>();
  auto type = this->atomKK->k_type.template view<DeviceType>();
  auto rmass = this->atomKK->k_rmass.template view<DeviceType>();
  auto mass = this->atomKK->k_mass.template view<DeviceType>();
  auto state = k_state.template view<DeviceType>();
  const int groupbit = this->groupbit;
  const int use_rmass = this->atom->rmass != nullptr;
  Kokkos::parallel_reduce(
      Kokkos::RangePolicy<DeviceType>(0, this->atom->nlocal),
      LAMMPS_LAMBDA(const int i, double &amax2) {
        if (!(mask(i) & groupbit)) return;
        const double m = use_rmass ? rmass(i) : mass(type(i));
        const double a2 = (f(i, 0) * f(i, 0) + f(i, 1) * f(i, 1) + f(i, 2) * f(i, 2)) / (m * m);
        if (a2 > amax2) amax2 = a2;
      },
      Kokkos::Max<double>(local[0]));
  if (this->cfl_sound_reference) return;
  // a parallel region of its own per material, needed by local only
  const GRANSPH::MaterialTable materials = this->materials;
  for (int k = 0; k < materials.n; ++k) {
    Kokkos::parallel_reduce(
        Kokkos::RangePolicy<DeviceType>(0, this->atom->nlocal),
        LAMMPS_LAMBDA(const int i, double &most) {
          const bool grain = (mask(i) & groupbit) && materials.holds(k, mask(i));
          if (grain && -state(i, FSI::RHO) > most) most = -state(i, FSI::RHO);
        },
        Kokkos::Max<double>(local[1 + k]));
  }
}

// The per-atom output is read on the host: bring it there on output steps only.
template <class DeviceType, class Model> void FixSPHModelKokkos<DeviceType, Model>::end_of_step()
{
  FixSPHModel<Model>::end_of_step();
  if (this->update->ntimestep == this->output->next) k_state.template sync<LMPHostType>();
}

template <class DeviceType, class Model> void FixSPHModelKokkos<DeviceType, Model>::post_run()
{
  sync_host();
}

/* ----------------------------------------------------------------------
   forward communication of rho and sigma: on the device, or through the
   host buffers when comm/kokkos chooses the classic path
------------------------------------------------------------------------- */

template <class DeviceType, class Model>
void FixSPHModelKokkos<DeviceType, Model>::forward_comm_state()
{
  k_state.template sync<DeviceType>();
  GRANSPHCompat::forward_comm_fix(this->comm, this);
}

template <class DeviceType, class Model>
int FixSPHModelKokkos<DeviceType, Model>::pack_forward_comm_device(
    int n, const typename GRANSPHCompat::KokkosTypes<DeviceType>::SendList &sendlist,
    GRANSPHCompat::tdual_comm_buffer &k_buf)
{
  auto buf = k_buf.view<DeviceType>();
  auto state = k_state.template view<DeviceType>();
  Kokkos::parallel_for(
      Kokkos::RangePolicy<DeviceType>(0, n), LAMMPS_LAMBDA(const int i) {
        const int j = sendlist(i);
        for (int k = 0; k < FSI::NCOMM; ++k) buf(FSI::NCOMM * i + k) = state(j, k);
      });
  return n * FSI::NCOMM;
}

template <class DeviceType, class Model>
void FixSPHModelKokkos<DeviceType, Model>::unpack_forward_comm_device(
    int n, int first, GRANSPHCompat::tdual_comm_buffer &k_buf)
{
  auto buf = k_buf.view<DeviceType>();
  auto state = k_state.template view<DeviceType>();
  Kokkos::parallel_for(
      Kokkos::RangePolicy<DeviceType>(0, n), LAMMPS_LAMBDA(const int i) {
        for (int k = 0; k < FSI::NCOMM; ++k) state(first + i, k) = buf(FSI::NCOMM * i + k);
      });
  k_state.template modify<DeviceType>();
}

/* ----------------------------------------------------------------------
   host callbacks: the base class works on the host copies
------------------------------------------------------------------------- */

template <class DeviceType, class Model>
void FixSPHModelKokkos<DeviceType, Model>::sync_host(Arrays arrays)
{
  k_state.template sync<LMPHostType>();
  if (arrays == FixSPHIntegrate::STATE_ONLY) return;
  k_rates.template sync<LMPHostType>();
  k_start.template sync<LMPHostType>();
}

template <class DeviceType, class Model>
void FixSPHModelKokkos<DeviceType, Model>::modified_host(Arrays arrays)
{
  k_state.template modify<LMPHostType>();
  if (arrays == FixSPHIntegrate::STATE_ONLY) return;
  k_rates.template modify<LMPHostType>();
  k_start.template modify<LMPHostType>();
}

template <class DeviceType, class Model>
void FixSPHModelKokkos<DeviceType, Model>::grow_arrays(int nmax)
{
  this->check_row_offsets(nmax);
  sync_host();    // the host copies hold the values that the larger arrays keep
  this->memoryKK->grow_kokkos(k_state, this->state, nmax, FSI::NSTATE, "sph:state");
  // rates and start as the base's blocks: the host copies' rows, without row pointers
  const auto grow = [nmax](auto &dual, int columns, const char *name) {
    if (dual.view_host().data())
      dual.resize(nmax, columns);
    else
      dual = std::decay_t<decltype(dual)>(name, nmax, columns);
    return dual.view_host().data();
  };
  this->rates = grow(k_rates, this->nrates, "sph:rates");
  this->start = grow(k_start, FSI::NSTART, "sph:start");
  this->array_atom = this->state;
}

namespace LAMMPS_NS {
template class FixSPHModelKokkos<LMPDeviceType, GRANSPH::DruckerPrager>;
template class FixSPHModelKokkos<LMPDeviceType, GRANSPH::PhaseChange>;
#ifdef LMP_KOKKOS_GPU
template class FixSPHModelKokkos<LMPHostType, GRANSPH::DruckerPrager>;
template class FixSPHModelKokkos<LMPHostType, GRANSPH::PhaseChange>;
#endif
}    // namespace LAMMPS_NS
