/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: pair_style sph/granular.

   Per evaluation: ghosts get fresh density and stress; owned dummy particles
   get their stress by extrapolation (eq. 8), pass it to their ghosts and get
   the force the grains exert on them (eq. 9); then the grains get their rates
   (eqs. 6, 7, 34, 35). With walls of a friction of their own the dummies get
   their force after the grains, from how the grains slide on them. A full
   neighbour list: each particle sums over its own
   neighbours into itself alone (gransph_neighbour_sums.h, shared with the
   Kokkos twin), in loops the compiler vectorises.
------------------------------------------------------------------------- */

#include "pair_sph_granular.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_integrate.h"
#include "fix_sph_normals.h"
#include "force.h"
#include "group.h"
#include "gransph_find_fix.h"
#include "gransph_lammps_compat.h"
#include "gransph_pair_passes.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <unordered_map>
#include <vector>

using namespace LAMMPS_NS;
using GRANSPH::PairParticle;

namespace {
// values per grain of how it slides on walls with a friction of their own
constexpr int SLIDE = GRANSPH::SLIDE_VALUES;


// The atoms as the shared neighbour sums read them (gransph_neighbour_sums.h): their
// neighbour rows, roles and wall arrays
struct HostAtoms {
  int **firstneigh;
  const int *numneigh, *mask;
  int granularbit, wallbit;
  const double *normals;    // 3 per atom, with wall_normal or wall_friction
  const double *friction_mu, *friction_slide;    // 1 and 4 per atom, with wall_friction
  bool grains_first = false;                     // with the rows pruned: their grains
  const int *numgrains = nullptr;

  struct NeighbourRow {
    const int *row;
    int operator()(int k) const { return row[k] & NEIGHMASK; }
  };
  NeighbourRow row(int i) const { return {firstneigh[i]}; }
};

// the host accessor for the shared neighbour sums (GRANSPH::ParticlesOf)
using HostParticles = GRANSPH::ParticlesOf<HostAtoms, PairParticle, const PairParticle *>;

}    // namespace

/* ---------------------------------------------------------------------- */

PairSPHGranular::PairSPHGranular(LAMMPS *lmp) :
    Pair(lmp), warned_far_from_origin(false), integrator(nullptr), normals_fix(nullptr), pruned_nall(-1),
    pruned_origin{0.0, 0.0, 0.0},
    viscous_pressure_step(-1), viscous_pressure_nlocal(0), nmax(0),
    particles(nullptr),
    particles_single(nullptr), normals(nullptr), friction(nullptr), slide(nullptr)
{
  restartinfo = 1;
  single_enable = 0;
  nextra = 1;    // how often the rows were pruned (prune)
  memory->create(pvector, nextra, "pair:pvector");
  pvector[0] = 0.0;
  no_virial_fdotr_compute = 1;    // forces go to owned atoms only: the pairs tally the virial
}

PairSPHGranular::~PairSPHGranular()
{
  memory->sfree(particles);
  memory->sfree(particles_single);
  memory->sfree(normals);
  memory->sfree(friction);
  memory->sfree(slide);
  memory->destroy(pvector);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

/* ---------------------------------------------------------------------- */

void PairSPHGranular::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  FixSPHIntegrate &fix = *integrator;
  const int nall = atom->nlocal + atom->nghost;
  fix.forward_comm_state();
  const bool limited = fix.wallbit && config.has_friction_walls();
  const bool wall_normal = config.wall_normal;
  // wall/gradient normal, wall/friction or precision mixed may be set by a pair_style
  // issued again after the arrays grew
  const bool grown = nall > nmax || ((wall_normal || limited) && !normals) ||
      (limited && !friction) || (config.mixed_precision && !particles_single);
  if (grown) grow(atom->nmax);
  pack_particles(0, nall);
  // normals and frictions follow the atoms, which change places only at a run's setup or
  // a list build
  int unnormalled = -1;
  if ((wall_normal || limited) && (grown || update->setupflag || neighbor->ago == 0)) {
    pack_wall_normals(normals, nall);
    if (limited) unnormalled = pack_wall_friction(friction, normals, nall);
  }
  if (limited && update->setupflag) stop_if_unnormalled(unnormalled);
  const HostAtoms atoms{list->firstneigh, list->numneigh, atom->mask, fix.groupbit, fix.wallbit,
                        normals, friction, slide};
  const HostParticles listed(sum_options(limited), atoms, particles);
  evaluate_passes(*this, config.prune > 0.0 ? pruned(listed, nall) : listed, limited);
}

double PairSPHGranular::pruned_cutsq() const
{
  const double cut = (2.0 + config.prune) * config.h;
  return cut * cut;
}

bool PairSPHGranular::rows_outdated(int nall) const
{
  return update->setupflag || neighbor->ago == 0 || nall != pruned_nall;
}

double PairSPHGranular::prune_renewal_sq() const
{
  const double renew = 0.5 * config.prune * config.h;
  return renew * renew;
}

// the float positions are taken from the centre of this rank's sub-domain, as under
// precision mixed
void PairSPHGranular::pruned_anew(int nall)
{
  pruned_nall = nall;
  pvector[0] += 1.0;
  single_precision_origin(pruned_origin);
}

// p over its rows pruned in place (GRANSPH::prune_row), pruned anew when outdated or when
// an atom has moved too far
template <class Particles> Particles PairSPHGranular::pruned(const Particles &p, int nall)
{
  const double *x = nall > 0 ? atom->x[0] : nullptr;    // one block of 3 nmax
  const auto now_at = [x](int j, int a) { return x[3 * j + a]; };
  const auto pruned_at = [this]() -> GRANSPH::PrunedPositions<GRANSPH::HostRows<3, float>> {
    return {{pruned_x.data()}, {pruned_origin[0], pruned_origin[1], pruned_origin[2]}};
  };
  bool anew = rows_outdated(nall);
  if (!anew) {
    const auto x0 = pruned_at();
    double farthest = 0.0;
    GRANSPH_SIMD_MAX(farthest)
    for (int i = 0; i < nall; ++i)
      farthest = MAX(farthest, GRANSPH::pruned_displacement_sq(now_at, x0, i));
    anew = farthest > prune_renewal_sq();
  }
  if (anew) {
    pruned_anew(nall);
    pruned_x.resize(3 * nall);
    for (int i = 0; i < nall; ++i)
      for (int a = 0; a < 3; ++a) pruned_x[3 * i + a] = x[3 * i + a] - pruned_origin[a];
    const auto x0 = pruned_at();
    pruned_count.assign(atom->nlocal, 0);
    pruned_grains.assign(atom->nlocal, 0);
    const double cutsq = pruned_cutsq();
    const auto prune_rows = [&](auto dummies) {
      for (int ii = 0; ii < list->inum; ++ii) {
        const int i = list->ilist[ii];
        int *row = list->firstneigh[i];
        const GRANSPH::PrunedRow counts = GRANSPH::prune_row<decltype(dummies)::value>(
            p, i, x0, cutsq, [row](int k) -> int & { return row[k]; });
        pruned_count[i] = counts.count;
        pruned_grains[i] = counts.grains;
      }
    };
    if (p.wallbit)
      prune_rows(std::true_type());
    else
      prune_rows(std::false_type());
  }
  Particles q = p;
  q.numneigh = pruned_count.data();
  q.numgrains = pruned_grains.data();
  q.grains_first = true;
  return q;
}

// at the setup of a run: no two interacting particles on one place
template <class Particles> void PairSPHGranular::check_no_coincident(const Particles &p)
{
  int found = -1;
  for (int ii = 0; ii < list->inum && found < 0; ++ii)
    if (GRANSPH::has_coincident_neighbour(p, list->ilist[ii])) found = list->ilist[ii];
  stop_if_coincident(found);
}

// Collective: a wall or terrain made at another spacing than the sand is not the wall the
// sums assume (a coarser one lets grains through): the mean distance from a dummy to its
// nearest dummy must be within a factor 1.5 of the grains' mean spacing. The nearest dummy
// is searched in cells of side 2h over the owned and ghost dummies (the neighbour list
// may leave dummy pairs out: neigh_modify exclude).
void PairSPHGranular::check_wall_spacing()
{
  enum { WALL_GAPS, WALL_COUNT, GRAIN_SPACINGS, GRAIN_COUNT, DUMMIES, NSUMS };
  double local[NSUMS] = {0.0, 0.0, 0.0, 0.0, 0.0}, sums[NSUMS];
  const double cell = 2.0 * config.h;
  double **x = atom->x;
  const int *mask = atom->mask, wallbit = integrator->wallbit;
  const auto cell_of = [&](const double *xi, int a) { return (long long) floor(xi[a] / cell); };
  const auto key = [](long long cx, long long cy, long long cz) {
    return ((cx & 0x1fffff) << 42) | ((cy & 0x1fffff) << 21) | (cz & 0x1fffff);
  };
  std::unordered_map<long long, std::vector<int>> dummies;
  for (int j = 0; j < atom->nlocal + atom->nghost; ++j)
    if (mask[j] & wallbit) dummies[key(cell_of(x[j], 0), cell_of(x[j], 1), cell_of(x[j], 2))].push_back(j);
  for (int i = 0; i < atom->nlocal; ++i) {
    if (mask[i] & integrator->groupbit) {
      const double m = atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]];
      const double rho0 = integrator->materials.rho0[integrator->materials.of(mask[i])];
      local[GRAIN_SPACINGS] += GRANSPH::grain_spacing(m, rho0, domain->dimension);
      local[GRAIN_COUNT] += 1.0;
    }
    if (!(mask[i] & wallbit)) continue;
    local[DUMMIES] += 1.0;
    double nearest = cell * cell;
    for (long long cx = cell_of(x[i], 0) - 1; cx <= cell_of(x[i], 0) + 1; ++cx)
      for (long long cy = cell_of(x[i], 1) - 1; cy <= cell_of(x[i], 1) + 1; ++cy)
        for (long long cz = cell_of(x[i], 2) - 1; cz <= cell_of(x[i], 2) + 1; ++cz) {
          const auto found = dummies.find(key(cx, cy, cz));
          if (found == dummies.end()) continue;
          for (const int j : found->second) {
            double rsq = 0.0;
            for (int a = 0; a < 3; ++a) rsq += (x[i][a] - x[j][a]) * (x[i][a] - x[j][a]);
            if (rsq > 0.0 && rsq < nearest) nearest = rsq;
          }
        }
    if (nearest < cell * cell) {
      local[WALL_GAPS] += sqrt(nearest);
      local[WALL_COUNT] += 1.0;
    }
  }
  MPI_Allreduce(local, sums, NSUMS, MPI_DOUBLE, MPI_SUM, world);
  if (sums[GRAIN_COUNT] == 0.0 || sums[DUMMIES] == 0.0) return;
  constexpr double FACTOR = 1.5;
  const double grains = sums[GRAIN_SPACINGS] / sums[GRAIN_COUNT];
  if (sums[WALL_COUNT] == 0.0)
    error->all(FLERR,
               "Pair style sph/granular: no dummy particle has another within 2h = {:.4g} of it "
               "while the grains lie {:.4g} apart (their volume m / rho0): make the walls and "
               "terrain at the grains' spacing (tools/terrain --dx {:.4g})",
               cell, grains, grains);
  const double walls = sums[WALL_GAPS] / sums[WALL_COUNT];
  if (walls > FACTOR * grains || walls * FACTOR < grains)
    error->all(FLERR,
               "Pair style sph/granular: the dummy particles lie {:.4g} apart (the mean distance "
               "to the nearest dummy), the grains {:.4g} (their volume m / rho0): make the walls "
               "and terrain at the grains' spacing (tools/terrain --dx {:.4g})",
               walls, grains, grains);
}

// Collective: if any rank found an owned particle (index i >= 0) with a neighbour on top
// of it, every rank stops with both IDs and the place, from the lowest such rank.
void PairSPHGranular::stop_if_coincident(int i)
{
  const int nprocs = comm->nprocs;
  int mine = i >= 0 ? comm->me : nprocs, root = nprocs;
  MPI_Allreduce(&mine, &root, 1, MPI_INT, MPI_MIN, world);
  if (root == nprocs) return;
  double what[5] = {0.0, 0.0, 0.0, 0.0, 0.0};    // the two IDs and the place
  if (comm->me == root) {
    double **x = atom->x;
    const int nall = atom->nlocal + atom->nghost;
    auto distsq = [&](int j) {
      double rsq = 0.0;
      for (int a = 0; a < 3; ++a) rsq += (x[i][a] - x[j][a]) * (x[i][a] - x[j][a]);
      return rsq;
    };
    int j = 0;
    while (j < nall && (j == i || distsq(j) >= GRANSPH::coincident_rsq(config.h))) ++j;
    what[0] = atom->tag[i];
    what[1] = j < nall ? atom->tag[j] : 0;
    for (int a = 0; a < 3; ++a) what[2 + a] = x[i][a];
  }
  MPI_Bcast(what, 5, MPI_DOUBLE, root, world);
  error->all(FLERR,
             "Pair style sph/granular: atoms {} and {} are both at ({}, {}, {}); did two "
             "create_atoms commands fill one lattice site?",
             (tagint) what[0], (tagint) what[1], what[2], what[3], what[4]);
}

// the virial of owned particle i, global and per atom as asked
void PairSPHGranular::tally_virial(int i, const double *vir)
{
  if (vflag_global)
    for (int k = 0; k < 6; ++k) virial[k] += vir[k];
  if (vflag_atom)
    for (int k = 0; k < 6; ++k) vatom[i][k] += vir[k];
}

// The dummy particles: with `stress` their stress (eq. 8), with the wall acceleration
// from the velocity change since the last evaluation; with `forces` the grains' force on
// them (eq. 9; none without granular neighbours, which only the stress sums tell), or the
// last step's at the setup of a run that continues it, and its virial. A dummy's force
// needs its own new stress only: one pass does both, unless the forces wait for how the
// grains slide on walls with a friction of their own.
template <class Particles> void PairSPHGranular::walls(const Particles &p, bool stress, bool forces)
{
  FixSPHIntegrate &fix = *integrator;
  const FixSPHIntegrate::HostState state = fix.host_state();
  const GRANSPH::HostRows<3> f{atom->f[0]};
  const bool repeat = repeats_last_wall_forces();
  const int inum = list->inum;
  const int *ilist = list->ilist;
  double **v = atom->v;
  double g[3];
  fix.gravity_vector(g);
  const double inv_dt = update->setupflag ? 0.0 : 1.0 / update->dt;
  for (int ii = 0; ii < inum; ++ii) {
    const int d = ilist[ii];
    if (!p.wall(d)) continue;
    bool has_grains = true;
    if (stress)
      has_grains = GRANSPH::dummy_stress(p, state, d, v[d], g, inv_dt, config.wall_stress,
                                         particles[d].sigma)
                       .has_neighbours();
    if (!forces) continue;
    double vir[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    GRANSPH::add_dummy_force(p, d, has_grains, state, f, force->ftm2v, repeat,
                             vflag_either ? vir : nullptr);
    if (vflag_either) tally_virial(d, vir);
  }
}

bool PairSPHGranular::repeats_last_wall_forces() const
{
  return update->setupflag && integrator->continues_last_step();
}

// rates of the granular particles (eqs. 6, 7, 34, 35)
template <class Particles> void PairSPHGranular::grains(const Particles &p)
{
  const FixSPHIntegrate::HostState state = integrator->host_state();
  const int inum = list->inum;
  const int *ilist = list->ilist;
  const GRANSPH::HostRows<3> f{atom->f[0]};
  GRANSPH::with_sum_variant(p, vflag_either, [&](auto variant) {
    using Sums = decltype(variant);
    for (int ii = 0; ii < inum; ++ii) {
      const int i = ilist[ii];
      if (!p.granular(i)) continue;
      double vir[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      GRANSPH::add_grain_rates<Sums>(p, i, particles[i].mass, state, f, force->ftm2v,
                                     config.corrected_gradient, domain->dimension,
                                     vflag_either ? vir : nullptr,
                                     p.wall_friction ? &slide[SLIDE * i] : nullptr);
      if (vflag_either) tally_virial(i, vir);
    }
  });
  if (sums_viscous_pressure()) viscous_pressures(p);
}

// the viscous-pressure diagnostic of the owned atoms, for compute sph/visc/atom
template <class Particles> void PairSPHGranular::viscous_pressures(const Particles &p)
{
  visc_pressure.assign(atom->nlocal, 0.0);
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    if (p.granular(i)) visc_pressure[i] = GRANSPH::viscous_pressure(p, i);
  }
  summed_viscous_pressure();
}

bool PairSPHGranular::sums_viscous_pressure() const
{
  for (Compute *c : visc_computes)
    if (c->matchstep(update->ntimestep)) return true;
  return false;
}

void PairSPHGranular::summed_viscous_pressure()
{
  viscous_pressure_step = update->ntimestep;
  viscous_pressure_nlocal = atom->nlocal;
}

// summed in this step's evaluation, for the atoms there are now
bool PairSPHGranular::has_viscous_pressure() const
{
  return viscous_pressure_step == update->ntimestep && viscous_pressure_nlocal == atom->nlocal;
}

const double *PairSPHGranular::viscous_pressure()
{
  return has_viscous_pressure() ? visc_pressure.data() : nullptr;
}

void PairSPHGranular::grow(int n)
{
  nmax = n;
  memory->sfree(particles);
  memory->sfree(particles_single);
  memory->sfree(normals);
  memory->sfree(friction);
  memory->sfree(slide);
  particles = (PairParticle *) memory->smalloc(sizeof(PairParticle) * nmax, "pair:particles");
  particles_single = config.mixed_precision ? (GRANSPH::PairParticleSingle *) memory->smalloc(
                                           sizeof(GRANSPH::PairParticleSingle) * nmax,
                                           "pair:particles_single")
                                     : nullptr;
  const bool limited = config.has_friction_walls();
  normals = config.wall_normal || limited
      ? (double *) memory->smalloc(sizeof(double) * 3 * nmax, "pair:normals")
      : nullptr;
  friction = nullptr;
  slide = nullptr;
  if (!limited) return;
  friction = (double *) memory->smalloc(sizeof(double) * nmax, "pair:friction");
  slide = (double *) memory->smalloc(sizeof(double) * SLIDE * nmax, "pair:slide");
  for (int k = 0; k < SLIDE * nmax; ++k) slide[k] = GRANSPH::WallFrictionSums::held(k);
}

// the per-atom records and the pruned rows (LAMMPS' list counts its own)
double PairSPHGranular::memory_usage()
{
  double bytes = (double) nmax * sizeof(PairParticle);
  if (particles_single) bytes += (double) nmax * sizeof(GRANSPH::PairParticleSingle);
  if (normals) bytes += (double) nmax * 3 * sizeof(double);
  if (friction) bytes += (double) nmax * (1 + SLIDE) * sizeof(double);
  bytes += (double) visc_pressure.capacity() * sizeof(double);
  bytes += (double) (pruned_count.capacity() + pruned_grains.capacity()) * sizeof(int);
  bytes += (double) pruned_x.capacity() * sizeof(float);
  return bytes;
}

// The friction coefficient mu of atoms [0, n) into `out`: that of the last wall/friction
// entry whose group holds the dummy particle (FrictionWall::MATERIAL: each grain's own),
// -1 for rough walls and the others; a grain's that of its material. Returns an owned
// dummy of a wall with a friction of its own that has no normal (`normals`, as
// pack_wall_normals writes them; the friction is taken against it), or -1.
int PairSPHGranular::pack_wall_friction(double *out, const double *unit_normals, int n) const
{
  const int *mask = atom->mask, wallbit = integrator->wallbit, grainbit = integrator->groupbit;
  const GRANSPH::MaterialTable &materials = integrator->materials;
  int missing = -1;
  for (int i = 0; i < n; ++i) {
    out[i] = (mask[i] & grainbit) ? materials.slide_friction[materials.of(mask[i])] : -1.0;
    if (!(mask[i] & wallbit)) continue;
    for (int k = 0; k < config.nfriction; ++k)
      if (mask[i] & group->bitmask[config.friction[k].group])
        out[i] = config.friction[k].mu;
    const double *ni = &unit_normals[3 * i];
    const bool limits = out[i] >= 0.0 || out[i] == GRANSPH::FrictionWall::MATERIAL;
    if (limits && ni[0] == 0.0 && ni[1] == 0.0 && ni[2] == 0.0 && missing < 0 &&
        i < atom->nlocal)
      missing = i;
  }
  return missing;
}

// Collective, at a run's setup: stops the run if any rank has a dummy particle of a wall
// with a friction of its own without a normal (owned index i >= 0)
void PairSPHGranular::stop_if_unnormalled(int i)
{
  if (!GRANSPH::any_rank(world, i >= 0)) return;
  if (i >= 0)
    error->one(FLERR,
               "Pair style sph/granular: dummy particle {} of a wall/friction group has no wall "
               "normal: give the group's particles theirs with fix sph/normals (set GROUP nx "
               "ny nz, or file FILE for the .normals file of tools/terrain)",
               atom->tag[i]);
  MPI_Barrier(world);    // until the rank with such a particle stops the run
}

void PairSPHGranular::forward_comm_friction_slide()
{
  GRANSPHCompat::forward_comm_pair(comm, this);
}

int PairSPHGranular::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/,
                                       int * /*pbc*/)
{
  const double *values = slide_on_host();
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < SLIDE; ++c) buf[SLIDE * k + c] = values[SLIDE * list[k] + c];
  return SLIDE * n;
}

void PairSPHGranular::unpack_forward_comm(int n, int first, double *buf)
{
  double *values = slide_on_host();
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < SLIDE; ++c) values[SLIDE * (first + k) + c] = buf[SLIDE * k + c];
  slide_changed_on_host();
}

// The wall normals of atoms [0, n), 3 per atom into `out`: a dummy particle's own (fix
// sph/normals), made a unit vector; zeros for a dummy without one and for the others.
void PairSPHGranular::pack_wall_normals(double *out, int n) const
{
  const int *mask = atom->mask, wallbit = integrator->wallbit;
  for (int i = 0; i < n; ++i) {
    const double *ni = normals_fix && (mask[i] & wallbit) ? normals_fix->normal(i) : nullptr;
    const double len = ni ? GRANSPH::norm3(ni) : 0.0;
    for (int a = 0; a < 3; ++a) out[3 * i + a] = len > 0.0 ? ni[a] / len : 0.0;
  }
}

// Wall normals come from fix sph/normals only: a per-atom array of the name GRANSPH once
// read (fix property/atom d2_wall_normal) is an error, not silently ignored
void PairSPHGranular::find_wall_normals()
{
  normals_fix = FixSPHNormals::find(lmp, "Pair style sph/granular");
  int flag = 0, cols = 0;
  if (atom->find_custom("wall_normal", flag, cols) >= 0)
    error->all(FLERR,
               "Pair style sph/granular: wall normals are no longer read from the per-atom "
               "property wall_normal (fix property/atom d2_wall_normal): give them with fix "
               "sph/normals (file FILE for the .normals file of tools/terrain, set GROUP nx ny "
               "nz for a group)");
}

// the pair data of atoms [from, to) (GRANSPH::pair_particle)
void PairSPHGranular::pack_particles(int from, int to)
{
  const FixSPHIntegrate &fix = *integrator;
  const FixSPHIntegrate::HostState state = fix.host_state();
  const int sphbits = fix.groupbit | fix.wallbit;
  const GRANSPH::Viscosity visc = viscosity();
  for (int i = from; i < to; ++i)
    particles[i] = GRANSPH::pair_particle(
        atom->mask[i], sphbits, state, i, atom->x[i], atom->v[i],
        atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]], visc, fix.materials);
}

// the single-precision copy of atoms [0, n) for the grains' sums, with the dummies'
// stress of this evaluation in place
const GRANSPH::PairParticleSingle *PairSPHGranular::pack_particles_single(int n)
{
  double origin[3];
  single_precision_origin(origin);
  for (int i = 0; i < n; ++i)
    particles_single[i] = GRANSPH::PairParticleSingle::of(particles[i], origin);
  return particles_single;
}

// Under precision mixed: the centre of this rank's sub-domain (of the box if it is
// triclinic), from which the single-precision positions are taken; and how far from it
// a particle of the lists can lie (half the sub-domain's diagonal and the cut-off).
double PairSPHGranular::single_precision_origin(double *origin) const
{
  const bool sub = !domain->triclinic;
  const double *lo = sub ? domain->sublo : domain->boxlo, *hi = sub ? domain->subhi : domain->boxhi;
  double half_diagonal_sq = 0.0;
  for (int a = 0; a < 3; ++a) {
    origin[a] = 0.5 * (lo[a] + hi[a]);
    half_diagonal_sq += 0.25 * (hi[a] - lo[a]) * (hi[a] - lo[a]);
  }
  return sqrt(half_diagonal_sq) + 2.0 * config.h;
}

// Collective, at a run's setup under precision mixed: once, a warning if a particle can
// lie so far from its single-precision origin that single precision rounds its pair
// distances by more than a ten-thousandth of h.
void PairSPHGranular::warn_if_far_from_single_origin()
{
  if (warned_far_from_origin) return;
  double origin[3], largest = 0.0;
  double reach = single_precision_origin(origin);
  MPI_Allreduce(&reach, &largest, 1, MPI_DOUBLE, MPI_MAX, world);
  constexpr double FARTHEST = 1e3;    // in h: float's 6e-8 relative rounding gives 1e-4 h
  warned_far_from_origin = largest > FARTHEST * config.h;
  if (warned_far_from_origin && comm->me == 0)
    error->warning(FLERR,
                   "Pair style sph/granular precision mixed: particles lie up to {:.3g} h from "
                   "the origin of their single-precision positions, where single precision "
                   "rounds pair distances by more than 1e-4 h: run on more MPI ranks (smaller "
                   "sub-domains) or in double precision",
                   largest / config.h);
}

void PairSPHGranular::settings(int narg, char **arg)
{
  config = GRANSPH::PairSettings::parse(lmp, narg, arg);
}

GRANSPH::Viscosity PairSPHGranular::viscosity() const
{
  return {config.visc_alpha, config.visc_beta, config.visc_walls, config.visc_sound};
}

GRANSPH::SumOptions PairSPHGranular::sum_options(bool limited) const
{
  GRANSPH::WallStick stick{limited && config.hold_stick, {0.0, 0.0, 0.0},
                           GRANSPH::WallStick::STICK_DAMPING / update->dt};
  if (stick.on) integrator->gravity_vector(stick.gravity);
  return {GRANSPH::WendlandC2::make(config.h, domain->dimension),
          viscosity(),
          config.wall_normal,
          config.corrected_gradient,
          limited,
          stick};
}

// pair_coeff I J: which types interact; the roles come from the fix groups
void PairSPHGranular::coeff(int narg, char **arg)
{
  if (narg != 2) error->all(FLERR, "Incorrect args for pair_coeff sph/granular: expected I J only");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

void PairSPHGranular::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) setflag[i][j] = 0;
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
}

void PairSPHGranular::init_style()
{
  if (!comm->ghost_velocity)
    error->all(FLERR, "Pair style sph/granular needs ghost velocities: use comm_modify vel yes");
  integrator = &FixSPHIntegrate::find(lmp, "Pair style sph/granular");
  find_wall_normals();
  for (int k = 0; k < config.nfriction; ++k) {
    const int igroup = config.friction[k].group;
    if (!group->names[igroup])
      error->all(FLERR, "Pair style sph/granular: a wall/friction group was deleted");
    const int bits = group->bitmask[igroup] | integrator->wallbit;
    const auto dummy_of_group = [&](int i) { return (atom->mask[i] & bits) == bits; };
    if (integrator->wallbit && !GRANSPH::any_owned_atom(lmp, dummy_of_group))
      error->all(FLERR,
                 "Pair style sph/granular: wall/friction group {} holds no dummy particle of the "
                 "walls group of fix {}",
                 group->names[igroup], integrator->id);
  }
  if (config.has_friction_walls() && !integrator->wallbit)
    error->all(FLERR,
               "Pair style sph/granular: wall/friction needs dummy walls: the integrator fix "
               "has no walls group");
  comm_forward = config.has_friction_walls() ? SLIDE : 0;    // how the grains slide on the walls
  visc_computes.clear();
  for (int i = 0; i < modify->ncompute; ++i)
    if (utils::strmatch(modify->compute[i]->style, "^sph/visc/atom"))
      visc_computes.push_back(modify->compute[i]);
  viscous_pressure_step = -1;
  // a full list: each particle sums into itself alone, with no reverse communication
  GRANSPHCompat::request_full_list(neighbor, this, instance_me);
}

double PairSPHGranular::init_one(int i, int j)
{
  if (setflag[i][j] == 0) error->all(FLERR, "Pair sph/granular: pair_coeff missing for types {} {}", i, j);
  return 2.0 * config.h;
}

/* ---------------------------------------------------------------------- */

void PairSPHGranular::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) fwrite(&setflag[i][j], sizeof(int), 1, fp);
}

void PairSPHGranular::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (comm->me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
    }
}

void PairSPHGranular::write_restart_settings(FILE *fp)
{
  config.write_restart(fp);
}

void PairSPHGranular::read_restart_settings(FILE *fp)
{
  config = GRANSPH::PairSettings::read_restart(lmp, fp);
}

// h: the smoothing length; settings: the GRANSPH::PairSettings
void *PairSPHGranular::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "h") == 0) return (void *) &config.h;
  if (strcmp(name, "settings") == 0) return (void *) &config;
  return nullptr;
}
