/* ----------------------------------------------------------------------
   GRANSPH: pair_style sph/granular.

   Per evaluation: ghosts get fresh density and stress; owned dummy particles
   get their stress by extrapolation (eq. 8), and with it the force the grains
   exert on them (eq. 9), and pass the stress to their ghosts; then every owned
   granular particle sums its rates (eqs. 6, 7, 34, 35). The full neighbour
   list lets each particle write only to itself.
------------------------------------------------------------------------- */

#include "pair_sph_granular.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_integrate.h"
#include "force.h"
#include "gransph_neighbour_sums.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

using namespace LAMMPS_NS;
using GRANSPH::PairParticle;
using GRANSPH::Sym3;

namespace {

// Host accessor for the shared neighbour sums (gransph_neighbour_sums.h).
struct HostParticles {
  const PairParticle *particles;
  int **firstneigh;
  const int *numneigh, *mask;
  int granularbit, wallbit;
  GRANSPH::WendlandC2 kernel;
  double alpha, beta;

  int num_neighbours(int i) const { return numneigh[i]; }
  int neighbour(int i, int k) const { return firstneigh[i][k] & NEIGHMASK; }
  const PairParticle &particle(int i) const { return particles[i]; }
  bool granular(int i) const { return mask[i] & granularbit; }
  bool wall(int i) const { return mask[i] & wallbit; }
};

}    // namespace

/* ---------------------------------------------------------------------- */

PairSPHGranular::PairSPHGranular(LAMMPS *lmp) :
    Pair(lmp), h(0.0), alpha(1.0), beta(1.0), integrator(nullptr), particles(nullptr),
    nmax_particles(0)
{
  restartinfo = 1;
  single_enable = 0;
  no_virial_fdotr_compute = 1;    // forces are written to owned atoms only
}

PairSPHGranular::~PairSPHGranular()
{
  memory->sfree(particles);
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
  double **v = atom->v;
  double **f = atom->f;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const double dt = update->dt;
  const int inum = list->inum;
  const int *ilist = list->ilist;

  fix.forward_comm_state();
  if (nall > nmax_particles) {
    nmax_particles = atom->nmax;
    memory->sfree(particles);
    particles = (PairParticle *) memory->smalloc(sizeof(PairParticle) * nmax_particles,
                                                 "pair:particles");
  }
  pack_particles(0, nall);
  const HostParticles p{particles, list->firstneigh, list->numneigh, mask, fix.groupbit,
                        fix.wallbit, GRANSPH::WendlandC2::make(h, domain->dimension), alpha, beta};

  if (fix.wallbit) {
    double g[3];
    fix.gravity_vector(g);
    for (int ii = 0; ii < inum; ++ii) {
      const int d = ilist[ii];
      if (!(mask[d] & fix.wallbit)) continue;
      // wall acceleration from its velocity change since the last evaluation
      double *v_last = &fix.start[d][FixSPHIntegrate::WALL_V];
      double g_minus_a[3];
      for (int a = 0; a < 3; ++a) {
        g_minus_a[a] = g[a] - (update->setupflag ? 0.0 : (v[d][a] - v_last[a]) / dt);
        v_last[a] = v[d][a];
      }
      const GRANSPH::WallSums sums = GRANSPH::wall_sums(p, d);
      particles[d].sigma = sums.stress(g_minus_a);
      particles[d].sigma.store(&fix.state[d][FixSPHIntegrate::SIGMA]);
      // the grains' force on d (eq. 9) needs its own new stress only, not that of
      // other walls; without grains inside the support it is zero
      if (!sums.has_neighbours()) continue;
      double vir[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      double fd[3];
      GRANSPH::wall_force(p, d, fd, vflag_either ? vir : nullptr);
      for (int a = 0; a < 3; ++a) f[d][a] += fd[a] / force->ftm2v;
      if (vflag_either) tally_virial(d, vir);
    }
    fix.forward_comm_state();
    pack_particles(nlocal, nall);
  }

  for (int ii = 0; ii < inum; ++ii) {
    const int i = ilist[ii];
    if (!(mask[i] & fix.groupbit)) continue;
    double vir[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    const GRANSPH::ParticleRates r = GRANSPH::granular_rates(p, i, vflag_either ? vir : nullptr);
    const double m = particles[i].mass;
    for (int a = 0; a < 3; ++a) f[i][a] += m * r.acc[a] / force->ftm2v;
    double *rates = fix.rates[i];
    rates[FixSPHIntegrate::DRHO] = r.drho;
    r.strain().store(&rates[FixSPHIntegrate::STRAIN]);
    r.spin().store(&rates[FixSPHIntegrate::SPIN]);
    if (vflag_either) tally_virial(i, vir);
  }
}

// the pair data of the granular and dummy particles among atoms [from, to)
void PairSPHGranular::pack_particles(int from, int to)
{
  const FixSPHIntegrate &fix = *integrator;
  const int sphbits = fix.groupbit | fix.wallbit;
  const double E = fix.material.E;
  for (int i = from; i < to; ++i) {
    if (!(atom->mask[i] & sphbits)) continue;
    const double m = atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]];
    const double *state = fix.state[i];
    particles[i] = PairParticle::make(atom->x[i], atom->v[i], m, state[FixSPHIntegrate::RHO],
                                      Sym3::load(&state[FixSPHIntegrate::SIGMA]), E);
  }
}

void PairSPHGranular::tally_virial(int i, const double *vir)
{
  if (vflag_global)
    for (int k = 0; k < 6; ++k) virial[k] += vir[k];
  if (vflag_atom)
    for (int k = 0; k < 6; ++k) vatom[i][k] += vir[k];
}

/* ----------------------------------------------------------------------
   pair_style sph/granular h [visc alpha beta]
------------------------------------------------------------------------- */

void PairSPHGranular::settings(int narg, char **arg)
{
  if (narg < 1) error->all(FLERR, "Illegal pair_style sph/granular command: need h");
  h = utils::numeric(FLERR, arg[0], false, lmp);
  if (h <= 0.0) error->all(FLERR, "Pair style sph/granular: smoothing length h must be > 0");
  int iarg = 1;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "visc") == 0) {
      if (iarg + 3 > narg) error->all(FLERR, "Pair style sph/granular: visc needs alpha and beta");
      alpha = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      beta = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      if (alpha < 0.0 || beta < 0.0)
        error->all(FLERR, "Pair style sph/granular: visc alpha and beta must be >= 0");
      iarg += 3;
    } else
      error->all(FLERR, "Pair style sph/granular: unknown keyword {}", arg[iarg]);
  }
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
  integrator = nullptr;
  for (int i = 0; i < modify->nfix; ++i)
    if ((integrator = dynamic_cast<FixSPHIntegrate *>(modify->fix[i]))) break;
  if (!integrator)
    error->all(FLERR,
               "Pair style sph/granular needs a GRANSPH integrator (fix sph/elastoplastic or "
               "fix sph/phasechange)");
  const int irequest = neighbor->request(this, instance_me);
  neighbor->requests[irequest]->half = 0;
  neighbor->requests[irequest]->full = 1;
}

double PairSPHGranular::init_one(int i, int j)
{
  if (setflag[i][j] == 0) error->all(FLERR, "Pair sph/granular: pair_coeff missing for types {} {}", i, j);
  return 2.0 * h;
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
  fwrite(&h, sizeof(double), 1, fp);
  fwrite(&alpha, sizeof(double), 1, fp);
  fwrite(&beta, sizeof(double), 1, fp);
}

void PairSPHGranular::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) {
    utils::sfread(FLERR, &h, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &alpha, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &beta, sizeof(double), 1, fp, nullptr, error);
  }
  MPI_Bcast(&h, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&alpha, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&beta, 1, MPI_DOUBLE, 0, world);
}

void *PairSPHGranular::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "h") == 0) return (void *) &h;
  return nullptr;
}
