/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: Kokkos twin of pair_style sph/granular.
------------------------------------------------------------------------- */

#include "pair_sph_granular_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_integrate.h"
#include "force.h"
#include "gransph_pair_passes.h"
#include "kokkos.h"
#include "memory_kokkos.h"
#include "neigh_list_kokkos.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
// values per grain of how it slides on walls with a friction of their own
constexpr int SLIDE = GRANSPH::SLIDE_VALUES;

// the virial of particle i into the reduction and, if wanted, into its per-atom entry
template <class VirialView>
KOKKOS_INLINE_FUNCTION void add_virial(EV_FLOAT &sum, const VirialView &vatom, bool want_vatom,
                                       int i, const double *vir)
{
  for (int k = 0; k < 6; ++k) sum.v[k] += vir[k];
  if (want_vatom)
    for (int k = 0; k < 6; ++k) vatom(i, k) += vir[k];
}

// Adds the force of the grains on dummy particle d (GRANSPH::add_dummy_force) into f, and
// its virial into the reduction.
template <class ForceView, class State, class VirialView> struct DummyForces {
  ForceView f;
  State state;
  VirialView vatom;
  double ftm2v;
  bool want_virial, want_vatom, repeat;

  template <class Particles>
  KOKKOS_INLINE_FUNCTION void add(const Particles &p, int d, bool has_grains, EV_FLOAT &sum) const
  {
    double vir[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    GRANSPH::add_dummy_force(p, d, has_grains, state, f, ftm2v, repeat,
                             want_virial ? vir : nullptr);
    add_virial(sum, vatom, want_vatom, d, vir);
  }
};
}    // namespace

template <class DeviceType>
PairSPHGranularKokkos<DeviceType>::PairSPHGranularKokkos(LAMMPS *lmp) :
    PairSPHGranular(lmp), state_kk(nullptr)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = X_MASK | V_MASK | F_MASK | TYPE_MASK | MASK_MASK | RMASS_MASK;
  datamask_modify = F_MASK;
}

template <class DeviceType> PairSPHGranularKokkos<DeviceType>::~PairSPHGranularKokkos()
{
  memoryKK->destroy_kokkos(k_vatom, vatom);
}

template <class DeviceType> void PairSPHGranularKokkos<DeviceType>::init_style()
{
  PairSPHGranular::init_style();
  // LAMMPS' Kokkos sizes the GPU's neighbour bins once, at the cut-off of its first init:
  // an init before any pair style (reset_atom_ids, as our inputs have) leaves the bin
  // size 0, hence one bin for the whole box and every list build O(N^2) (seen on an
  // H200: 90 s to set up 1e5 particles). Let this init size them from its cut-off.
  if (lmp->kokkos->ngpus > 0 && neighbor->binsizeflag && neighbor->binsize_user == 0.0)
    neighbor->binsizeflag = 0;
  state_kk = dynamic_cast<SPHStateKokkos *>(integrator);
  if (!state_kk)
    error->all(FLERR, "Pair style sph/granular/kk needs the /kk variant of the GRANSPH integrator");
  // a full list: each particle writes only to itself, no atomics
  GRANSPHCompat::kokkos_full_list<DeviceType>(neighbor, this);
  atomKK->k_mass.template modify<LMPHostType>();
  atomKK->k_mass.template sync<DeviceType>();
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairSPHGranularKokkos<DeviceType>::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag, 0);
  // the pair computes no energy: a per-atom energy (compute pe/atom) is zero, on the host
  if (eflag_atom) {
    memory->destroy(eatom);
    memory->create(eatom, maxeatom, "pair:eatom");
    for (int i = 0; i < maxeatom; ++i) eatom[i] = 0.0;
  }
  if (vflag_atom) {
    memoryKK->destroy_kokkos(k_vatom, vatom);
    memoryKK->create_kokkos(k_vatom, vatom, maxvatom, "pair:vatom");
  }
  atomKK->sync(execution_space, datamask_read);

  FixSPHIntegrate &fix = *integrator;
  SPHStateKokkos &kk = *state_kk;
  auto k_list = static_cast<NeighListKokkos<DeviceType> *>(list);
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;

  fix.forward_comm_state();
  kk.k_state.template sync<DeviceType>();
  kk.k_rates.template sync<DeviceType>();
  kk.k_start.template sync<DeviceType>();
  if ((int) d_particles.extent(0) < nall)
    d_particles = decltype(d_particles)(
        Kokkos::view_alloc(Kokkos::WithoutInitializing, "pair:particles"), atom->nmax);
  // with rows pruned since the last list build, the pack also finds how far the atoms
  // have moved since (one pass, one parallel region)
  const bool pruned_rows_may_stay = config.prune > 0.0 && !rows_outdated(nall);
  const double moved_sq = pack_particles(0, nall, pruned_rows_may_stay);

  const bool limited = fix.wallbit && config.has_friction_walls();
  DeviceAtoms<DeviceType> atoms;
  atoms.neighbors = k_list->d_neighbors;
  atoms.numneigh = k_list->d_numneigh;
  atoms.mask = atomKK->k_mask.template view<DeviceType>();
  atoms.granularbit = fix.groupbit;
  atoms.wallbit = fix.wallbit;
  if (config.wall_normal || limited) {
    const int unnormalled = update_wall_normals(nall, limited);
    if (limited && update->setupflag) stop_if_unnormalled(unnormalled);
    atoms.normals = k_normals.template view<DeviceType>();
  }
  if (limited) {
    if ((int) k_slide.extent(0) < SLIDE * nall) {
      k_slide = decltype(k_slide)("pair:slide", SLIDE * atom->nmax);
      auto host = k_slide.view_host();
      for (int k = 0; k < SLIDE * atom->nmax; ++k) host(k) = GRANSPH::WallFrictionSums::held(k);
      k_slide.template modify<LMPHostType>();
    }
    k_slide.template sync<DeviceType>();
    atoms.friction_mu = k_friction.template view<DeviceType>();
    atoms.friction_slide = k_slide.template view<DeviceType>();
  }
  DeviceParticles<DeviceType> p(sum_options(limited), atoms, d_particles);
  if (config.prune > 0.0) prune_rows(p, nall, moved_sq);
  evaluate_passes(*this, p, limited);
  atomKK->modified(execution_space, datamask_modify);
  if (vflag_atom) {
    k_vatom.template modify<DeviceType>();
    k_vatom.sync_host();
  }
}

// as PairSPHGranular::check_no_coincident
template <class DeviceType>
void PairSPHGranularKokkos<DeviceType>::check_no_coincident(const DeviceParticles<DeviceType> &p)
{
  auto ilist = static_cast<NeighListKokkos<DeviceType> *>(list)->d_ilist;
  int found = -1;
  Kokkos::parallel_reduce(
      Kokkos::RangePolicy<DeviceType>(0, list->inum),
      LAMMPS_LAMBDA(const int ii, int &last) {
        const int i = ilist(ii);
        if (i > last && GRANSPH::has_coincident_neighbour(p, i)) last = i;
      },
      Kokkos::Max<int>(found));
  if (found >= 0) atomKK->sync(Host, X_MASK | TAG_MASK);
  stop_if_coincident(found);
}

// the dummies' spacing, on the host
template <class DeviceType> void PairSPHGranularKokkos<DeviceType>::check_wall_spacing()
{
  atomKK->sync(Host, X_MASK | MASK_MASK | TYPE_MASK | RMASS_MASK);
  PairSPHGranular::check_wall_spacing();
}

// The wall normals (and with `limited` the dummies' friction) on the device: packed on
// the host when the atoms may have changed places (a run's setup, a neighbour list build)
// or the arrays grew; a step between builds copies nothing. Returns what
// pack_wall_friction does (-1 when it did not run).
template <class DeviceType>
int PairSPHGranularKokkos<DeviceType>::update_wall_normals(int nall, bool limited)
{
  const bool grown = (int) k_normals.extent(0) < 3 * nall ||
      (limited && (int) k_friction.extent(0) < nall);
  if (!grown && !update->setupflag && neighbor->ago != 0) return -1;
  if (grown) {
    k_normals = decltype(k_normals)("pair:normals", 3 * atom->nmax);
    if (limited) k_friction = decltype(k_friction)("pair:friction", atom->nmax);
  }
  atomKK->sync(Host, MASK_MASK);    // the roles are read on the host
  pack_wall_normals(k_normals.view_host().data(), nall);
  k_normals.template modify<LMPHostType>();
  k_normals.template sync<DeviceType>();
  if (!limited) return -1;
  const int unnormalled =
      pack_wall_friction(k_friction.view_host().data(), k_normals.view_host().data(), nall);
  k_friction.template modify<LMPHostType>();
  k_friction.template sync<DeviceType>();
  return unnormalled;
}

template <class DeviceType>
int PairSPHGranularKokkos<DeviceType>::pack_forward_comm_device(
    int n, const typename GRANSPHCompat::KokkosTypes<DeviceType>::SendList &sendlist,
    GRANSPHCompat::tdual_comm_buffer &k_buf)
{
  auto buf = k_buf.view<DeviceType>();
  auto slide = k_slide.template view<DeviceType>();
  Kokkos::parallel_for(
      Kokkos::RangePolicy<DeviceType>(0, n), LAMMPS_LAMBDA(const int k) {
        const int j = sendlist(k);
        for (int c = 0; c < SLIDE; ++c) buf(SLIDE * k + c) = slide(SLIDE * j + c);
      });
  return SLIDE * n;
}

template <class DeviceType>
void PairSPHGranularKokkos<DeviceType>::unpack_forward_comm_device(
    int n, int first, GRANSPHCompat::tdual_comm_buffer &k_buf)
{
  auto buf = k_buf.view<DeviceType>();
  auto slide = k_slide.template view<DeviceType>();
  Kokkos::parallel_for(
      Kokkos::RangePolicy<DeviceType>(0, n), LAMMPS_LAMBDA(const int k) {
        for (int c = 0; c < SLIDE; ++c) slide(SLIDE * (first + k) + c) = buf(SLIDE * k + c);
      });
  k_slide.template modify<DeviceType>();
}

// as PairSPHGranular::pack_particles; returns, since_pruned, the largest squared distance
// any of the atoms has moved since the rows were pruned
template <class DeviceType>
double PairSPHGranularKokkos<DeviceType>::pack_particles(int from, int to, bool since_pruned)
{
  double farthest = 0.0;
  if (from >= to) return farthest;
  auto particles = d_particles;
  auto x = atomKK->k_x.template view<DeviceType>();
  auto v = atomKK->k_v.template view<DeviceType>();
  auto mask = atomKK->k_mask.template view<DeviceType>();
  auto type = atomKK->k_type.template view<DeviceType>();
  auto rmass = atomKK->k_rmass.template view<DeviceType>();
  auto mass = atomKK->k_mass.template view<DeviceType>();
  const auto state = state_kk->template state_on<DeviceType>();
  const int sphbits = integrator->groupbit | integrator->wallbit;
  const int use_rmass = atom->rmass != nullptr;
  const GRANSPH::MaterialTable materials = integrator->materials;
  const GRANSPH::Viscosity visc = viscosity();
  const auto pack = LAMMPS_LAMBDA(const int i)
  {
    const double xi[3] = {x(i, 0), x(i, 1), x(i, 2)};
    const double vi[3] = {v(i, 0), v(i, 1), v(i, 2)};
    particles(i) = GRANSPH::pair_particle(mask(i), sphbits, state, i, xi, vi,
                                          use_rmass ? rmass(i) : mass(type(i)), visc, materials);
  };
  const Kokkos::RangePolicy<DeviceType> atoms(from, to);
  if (!since_pruned) {    // no reduction, which would wait for a device
    Kokkos::parallel_for(atoms, pack);
    return farthest;
  }
  const auto x0 = pruned_positions();
  Kokkos::parallel_reduce(
      atoms,
      LAMMPS_LAMBDA(const int i, double &most) {
        const double rsq = GRANSPH::pruned_displacement_sq(x, x0, i);
        if (rsq > most) most = rsq;
        pack(i);
      },
      Kokkos::Max<double>(farthest));
  return farthest;
}

// what adds the grains' forces to the dummy particles in this evaluation
template <class DeviceType> auto PairSPHGranularKokkos<DeviceType>::dummy_forces()
{
  auto f = atomKK->k_f.template view<DeviceType>();
  auto state = state_kk->template state_on<DeviceType>();
  auto vatom = k_vatom.template view<DeviceType>();
  return DummyForces<decltype(f), decltype(state), decltype(vatom)>{
      f, state, vatom, force->ftm2v, vflag_either != 0, vflag_atom != 0, repeats_last_wall_forces()};
}

// as PairSPHGranular::walls
template <class DeviceType>
void PairSPHGranularKokkos<DeviceType>::walls(const DeviceParticles<DeviceType> &p, bool stress,
                                              bool forces)
{
  // the forces after the grains' rates: with the ghosts' slide (forward_comm_friction_slide)
  if (!stress) k_slide.template sync<DeviceType>();
  auto ilist = static_cast<NeighListKokkos<DeviceType> *>(list)->d_ilist;
  auto particles = d_particles;
  const auto state = state_kk->template state_on<DeviceType>();
  const auto dummy = dummy_forces();
  double g[3];
  integrator->gravity_vector(g);
  const double gx = g[0], gy = g[1], gz = g[2];
  const double inv_dt = update->setupflag ? 0.0 : 1.0 / update->dt;
  const GRANSPH::WallSums::Mode mode = config.wall_stress;
  EV_FLOAT ev;
  Kokkos::parallel_reduce(
      ParticlePolicy<DeviceType>(0, list->inum, Kokkos::ChunkSize(64)),
      LAMMPS_LAMBDA(const int ii, EV_FLOAT &sum) {
        const int d = ilist(ii);
        if (!p.wall(d)) return;
        bool has_grains = true;
        if (stress) {
          const double gd[3] = {gx, gy, gz};
          has_grains = GRANSPH::dummy_stress(p, state, d, particles(d).v, gd, inv_dt, mode,
                                             particles(d).sigma)
                           .has_neighbours();
        }
        if (forces) dummy.add(p, d, has_grains, sum);
      },
      ev);
  if (vflag_global)
    for (int k = 0; k < 6; ++k) virial[k] += ev.v[k];
  if (stress) state_kk->k_state.template modify<DeviceType>();
  state_kk->k_start.template modify<DeviceType>();
}

// as PairSPHGranular::pack_particles_single
template <class DeviceType>
Kokkos::View<const GRANSPH::PairParticleSingle *, DeviceType>
PairSPHGranularKokkos<DeviceType>::pack_particles_single(int n)
{
  if ((int) d_particles_single.extent(0) < n)
    d_particles_single = decltype(d_particles_single)(
        Kokkos::view_alloc(Kokkos::WithoutInitializing, "pair:particles_single"), atom->nmax);
  auto particles = d_particles;
  auto single = d_particles_single;
  double origin[3];
  single_precision_origin(origin);
  const double ox = origin[0], oy = origin[1], oz = origin[2];
  Kokkos::parallel_for(
      Kokkos::RangePolicy<DeviceType>(0, n), LAMMPS_LAMBDA(const int i) {
        const double o[3] = {ox, oy, oz};
        single(i) = GRANSPH::PairParticleSingle::of(particles(i), o);
      });
  return single;
}

// as PairSPHGranular::pruned, on p itself; moved_sq: the largest squared distance since the
// last pruning
template <class DeviceType>
void PairSPHGranularKokkos<DeviceType>::prune_rows(DeviceParticles<DeviceType> &p, int nall,
                                                   double moved_sq)
{
  auto x = atomKK->k_x.template view<DeviceType>();
  if (rows_outdated(nall) || moved_sq > prune_renewal_sq()) {
    auto k_list = static_cast<NeighListKokkos<DeviceType> *>(list);
    if ((int) d_pruned_x.extent(0) < nall)
      d_pruned_x = decltype(d_pruned_x)(
          Kokkos::view_alloc(Kokkos::WithoutInitializing, "pair:pruned_x"), atom->nmax);
    if (d_pruned_count.extent(0) < k_list->d_neighbors.extent(0)) {
      d_pruned_count = decltype(d_pruned_count)("pair:pruned_count", k_list->d_neighbors.extent(0));
      d_pruned_grains = decltype(d_pruned_grains)("pair:pruned_grains", d_pruned_count.extent(0));
    }
    pruned_anew(nall);
    const auto x0 = pruned_positions();
    Kokkos::parallel_for(
        Kokkos::RangePolicy<DeviceType>(0, nall), LAMMPS_LAMBDA(const int i) {
          for (int a = 0; a < 3; ++a) x0.x0(i, a) = x(i, a) - x0.origin[a];
        });
    if (p.wallbit)
      prune_rows_of<true>(p);
    else
      prune_rows_of<false>(p);
  }
  p.numneigh = d_pruned_count;
  p.numgrains = d_pruned_grains;
  p.grains_first = true;
}

// the rows of p pruned anew at the positions pruned_x (GRANSPH::prune_row), with or
// without DUMMIES
template <class DeviceType>
template <bool DUMMIES>
void PairSPHGranularKokkos<DeviceType>::prune_rows_of(const DeviceParticles<DeviceType> &p)
{
  auto k_list = static_cast<NeighListKokkos<DeviceType> *>(list);
  auto ilist = k_list->d_ilist;
  auto rows = k_list->d_neighbors;
  const auto x0 = pruned_positions();
  auto count = d_pruned_count, grains = d_pruned_grains;
  const double cutsq = pruned_cutsq();
  Kokkos::parallel_for(
      ParticlePolicy<DeviceType>(0, list->inum, Kokkos::ChunkSize(64)),
      LAMMPS_LAMBDA(const int ii) {
        const int i = ilist(ii);
        const GRANSPH::PrunedRow counts = GRANSPH::prune_row<DUMMIES>(
            p, i, x0, cutsq, Kokkos::subview(rows, i, Kokkos::ALL));
        count(i) = counts.count;
        grains(i) = counts.grains;
      });
}

// as PairSPHGranular::grains, in the kernel of the sums' variant of this evaluation
template <class DeviceType>
template <class Particles>
void PairSPHGranularKokkos<DeviceType>::grains(const Particles &p)
{
  const bool limited = p.wall_friction;
  EV_FLOAT ev;
  GRANSPH::with_sum_variant(p, vflag_either, [&](auto variant) {
    ev = this->template grains_of<decltype(variant)>(p);
  });
  if (vflag_global)
    for (int k = 0; k < 6; ++k) virial[k] += ev.v[k];
  if (sums_viscous_pressure()) viscous_pressures(p);
  state_kk->k_rates.template modify<DeviceType>();
  if (limited) k_slide.template modify<DeviceType>();    // for forward_comm_friction_slide
}

// the grains' rates with the sums' variant Sums (GRANSPH::SumVariant): a kernel each
template <class DeviceType>
template <class Sums, class Particles>
EV_FLOAT PairSPHGranularKokkos<DeviceType>::grains_of(const Particles &p)
{
  auto ilist = static_cast<NeighListKokkos<DeviceType> *>(list)->d_ilist;
  const auto state = state_kk->template state_on<DeviceType>();
  auto f = atomKK->k_f.template view<DeviceType>();
  auto vatom = k_vatom.template view<DeviceType>();
  const int want_virial = vflag_either, want_vatom = vflag_atom;
  const double ftm2v = force->ftm2v;
  const int corrected = config.corrected_gradient, dim = domain->dimension;
  const bool limited = p.wall_friction;
  auto slide = k_slide.template view<DeviceType>();
  auto particles = d_particles;
  EV_FLOAT ev;
  Kokkos::parallel_reduce(
      ParticlePolicy<DeviceType>(0, list->inum, Kokkos::ChunkSize(64)),
      LAMMPS_LAMBDA(const int ii, EV_FLOAT &sum) {
        const int i = ilist(ii);
        if (!p.granular(i)) return;
        double vir[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        double s[SLIDE] = {1.0, 0.0, 0.0, 0.0};
        GRANSPH::add_grain_rates<Sums>(p, i, particles(i).mass, state, f, ftm2v, corrected,
                                       dim, want_virial ? vir : nullptr, limited ? s : nullptr);
        if (limited)
          for (int k = 0; k < SLIDE; ++k) slide(SLIDE * i + k) = s[k];
        add_virial(sum, vatom, want_vatom, i, vir);
      },
      ev);
  return ev;
}

// as PairSPHGranular::viscous_pressures
template <class DeviceType>
template <class Particles>
void PairSPHGranularKokkos<DeviceType>::viscous_pressures(const Particles &p)
{
  const int nlocal = atom->nlocal;
  if ((int) k_visc_pressure.extent(0) < nlocal)
    k_visc_pressure = decltype(k_visc_pressure)("pair:visc_pressure", atom->nmax);
  auto out = k_visc_pressure.template view<DeviceType>();
  auto ilist = static_cast<NeighListKokkos<DeviceType> *>(list)->d_ilist;
  Kokkos::parallel_for(
      Kokkos::RangePolicy<DeviceType>(0, nlocal), LAMMPS_LAMBDA(const int i) { out(i) = 0.0; });
  Kokkos::parallel_for(
      ParticlePolicy<DeviceType>(0, list->inum, Kokkos::ChunkSize(64)),
      LAMMPS_LAMBDA(const int ii) {
        const int i = ilist(ii);
        if (p.granular(i)) out(i) = GRANSPH::viscous_pressure(p, i);
      });
  k_visc_pressure.template modify<DeviceType>();
  summed_viscous_pressure();
}

template <class DeviceType> const double *PairSPHGranularKokkos<DeviceType>::viscous_pressure()
{
  if (!has_viscous_pressure()) return nullptr;
  k_visc_pressure.sync_host();
  return k_visc_pressure.view_host().data();
}

// the per-atom records and the pruned rows where the twin keeps them (a DualView once)
template <class DeviceType> double PairSPHGranularKokkos<DeviceType>::memory_usage()
{
  return d_particles.span() * sizeof(GRANSPH::PairParticle) +
      d_particles_single.span() * sizeof(GRANSPH::PairParticleSingle) +
      (k_normals.extent(0) + k_friction.extent(0) + k_slide.extent(0) +
       k_visc_pressure.extent(0)) * sizeof(double) + d_pruned_x.span() * sizeof(float) +
      (d_pruned_count.span() + d_pruned_grains.span()) * sizeof(int);
}

template <class DeviceType>
GRANSPH::PrunedPositions<Kokkos::View<float *[3], DeviceType>>
PairSPHGranularKokkos<DeviceType>::pruned_positions() const
{
  return {d_pruned_x, {pruned_origin[0], pruned_origin[1], pruned_origin[2]}};
}

namespace LAMMPS_NS {
template class PairSPHGranularKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class PairSPHGranularKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
