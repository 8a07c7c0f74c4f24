/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: fix sph/inflow.

   Layer k leaves the nozzle plane at t_k = t_start + k dx / v, t_start being
   the time of the first setup. Each layer moves as a rigid block at v n, so at
   time t it lies v (t - t_k) in front of the plane: a layer that enters late
   in a step is placed that far forward, and consecutive layers stay exactly dx
   apart however the timestep varies. With a wave, the centre of layer k is
   displaced by A0 sin(2 pi f0 t_k) along the wave direction (eq. 37).

   The fix keeps its own clock, the sum of the actual timesteps (the GRANSPH
   integrator changes dt every step), because LAMMPS 29Sep2021 does not keep
   the simulation time in restart files.

   Layers enter in pre_exchange, on the rank that owns each lattice point, so
   that the following exchange and neighbor build see them. In a run, that is
   between the GRANSPH integrator's predictor and corrector: the new particle
   sits at the midpoint of the step and gets the start-of-step state the
   corrector continues from.
------------------------------------------------------------------------- */

#include "fix_sph_inflow.h"

#include "fix_sph_integrate.h"
#include "gransph_tensor.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "math_const.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;
using namespace FixConst;
using MathConst::MY_2PI;

/* ----------------------------------------------------------------------
   fix ID group sph/inflow type T center cx cy cz normal nx ny nz radius R
       speed v spacing dx [wave A0 f0 ex ey ez] [until t] [mass m]
------------------------------------------------------------------------- */

FixSPHInflow::FixSPHInflow(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg),
    ntype(0), center{0.0, 0.0, 0.0}, normal{0.0, 0.0, 0.0}, e1{0.0, 0.0, 0.0}, e2{0.0, 0.0, 0.0},
    radius(0.0), speed(0.0), spacing(0.0), amplitude(0.0), frequency(0.0), wave_dir{0.0, 0.0, 0.0},
    t_until(std::numeric_limits<double>::infinity()), new_mass(0.0), started(false), clock(0.0),
    t_start(0.0), nlayers(0), nparticles(0), integrator(nullptr)
{
  parse_keywords(3, narg, arg);
  build_lattice();

  vector_flag = 1;
  size_vector = 2;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  time_depend = 1;
  force_reneighbor = 1;
  next_reneighbor = -1;    // end_of_step schedules the steps on which a layer is due
}

void FixSPHInflow::parse_keywords(int iarg, int narg, char **arg)
{
  auto values = [&](const char *key, int n) {
    if (iarg + n >= narg) error->all(FLERR, "Fix sph/inflow: keyword {} needs {} value(s)", key, n);
    return &arg[iarg + 1];
  };
  auto number = [&](char *word) {
    return utils::numeric(FLERR, word, false, lmp);
  };
  // the value of a keyword that must be > 0, past which iarg then points
  auto positive = [&](const char *key) {
    const double value = number(*values(key, 1));
    if (value <= 0.0) error->all(FLERR, "Fix sph/inflow: {} must be > 0", key);
    iarg += 2;
    return value;
  };
  bool have_center = false, have_wave = false;

  while (iarg < narg) {
    const char *key = arg[iarg];
    if (strcmp(key, "type") == 0) {
      ntype = utils::inumeric(FLERR, *values(key, 1), false, lmp);
      if (ntype < 1 || ntype > atom->ntypes)
        error->all(FLERR, "Fix sph/inflow: type {} is out of range 1-{}", ntype, atom->ntypes);
      iarg += 2;
    } else if (strcmp(key, "center") == 0) {
      char **v = values(key, 3);
      for (int a = 0; a < 3; ++a) center[a] = number(v[a]);
      have_center = true;
      iarg += 4;
    } else if (strcmp(key, "normal") == 0) {
      char **v = values(key, 3);
      for (int a = 0; a < 3; ++a) normal[a] = number(v[a]);
      iarg += 4;
    } else if (strcmp(key, "radius") == 0) {
      radius = positive(key);
    } else if (strcmp(key, "speed") == 0) {
      speed = positive(key);
    } else if (strcmp(key, "spacing") == 0) {
      spacing = positive(key);
    } else if (strcmp(key, "wave") == 0) {
      char **v = values(key, 5);
      amplitude = number(v[0]);
      frequency = number(v[1]);
      for (int a = 0; a < 3; ++a) wave_dir[a] = number(v[2 + a]);
      if (amplitude < 0.0) error->all(FLERR, "Fix sph/inflow: wave amplitude must be >= 0");
      if (frequency <= 0.0) error->all(FLERR, "Fix sph/inflow: wave frequency must be > 0");
      have_wave = true;
      iarg += 6;
    } else if (strcmp(key, "until") == 0) {
      t_until = number(*values(key, 1));
      iarg += 2;
    } else if (strcmp(key, "mass") == 0) {
      new_mass = positive(key);
      if (!atom->rmass_flag)
        error->all(FLERR,
                   "Fix sph/inflow: keyword mass needs an atom style with per-atom masses; "
                   "set the type's mass with the mass command");
    } else
      error->all(FLERR, "Fix sph/inflow: unknown keyword {}", key);
  }

  if (ntype == 0) error->all(FLERR, "Fix sph/inflow: keyword type is required");
  if (!have_center) error->all(FLERR, "Fix sph/inflow: keyword center is required");
  if (radius == 0.0) error->all(FLERR, "Fix sph/inflow: keyword radius is required");
  if (speed == 0.0) error->all(FLERR, "Fix sph/inflow: keyword speed is required");
  if (spacing == 0.0) error->all(FLERR, "Fix sph/inflow: keyword spacing is required");
  if (atom->rmass_flag && new_mass == 0.0)
    error->all(FLERR, "Fix sph/inflow: keyword mass is required with per-atom masses");

  const double nlen = GRANSPH::norm3(normal);
  if (nlen == 0.0) error->all(FLERR, "Fix sph/inflow: normal must not be zero (keyword normal)");
  for (int a = 0; a < 3; ++a) normal[a] /= nlen;
  if (domain->dimension == 2 && (normal[2] != 0.0 || center[2] != 0.0))
    error->all(FLERR, "Fix sph/inflow: in 2d, the z components of center and normal must be 0");

  if (have_wave) {
    const double wlen = GRANSPH::norm3(wave_dir);
    if (wlen == 0.0) error->all(FLERR, "Fix sph/inflow: wave direction must not be zero");
    for (int a = 0; a < 3; ++a) wave_dir[a] /= wlen;
    if (fabs(GRANSPH::dot3(wave_dir, normal)) > 1.0e-6)
      error->all(FLERR, "Fix sph/inflow: wave direction must be perpendicular to the normal");
    if (domain->dimension == 2 && wave_dir[2] != 0.0)
      error->all(FLERR, "Fix sph/inflow: in 2d, the z component of the wave direction must be 0");
  }
}

/* ----------------------------------------------------------------------
   lattice axes e1, e2 orthonormal to n: e1 is the box axis least aligned
   with n (the first of equals), made orthogonal to n; e2 = n x e1. In 2d the
   nozzle is a segment along e1 = z x n. A layer holds the points
   (i e1 + j e2) dx within R of the centre, which is itself a lattice point.
------------------------------------------------------------------------- */

void FixSPHInflow::build_lattice()
{
  const int dim = domain->dimension;
  if (dim == 2) {
    e1[0] = -normal[1];
    e1[1] = normal[0];
  } else {
    int k = 0;
    for (int a = 1; a < 3; ++a)
      if (fabs(normal[a]) < fabs(normal[k])) k = a;
    for (int a = 0; a < 3; ++a) e1[a] = (a == k ? 1.0 : 0.0) - normal[k] * normal[a];
    const double len = GRANSPH::norm3(e1);
    for (int a = 0; a < 3; ++a) e1[a] /= len;
    e2[0] = normal[1] * e1[2] - normal[2] * e1[1];
    e2[1] = normal[2] * e1[0] - normal[0] * e1[2];
    e2[2] = normal[0] * e1[1] - normal[1] * e1[0];
  }

  // the tolerance keeps points that lie on the rim up to round-off
  const double rmax2 = (radius / spacing) * (radius / spacing) * (1.0 + 1.0e-10);
  const int nmax = static_cast<int>(radius / spacing) + 1;
  const int jmax = dim == 3 ? nmax : 0;
  for (int i = -nmax; i <= nmax; ++i)
    for (int j = -jmax; j <= jmax; ++j)
      if (i * i + j * j <= rmax2) {
        offsets.push_back(i * spacing);
        offsets.push_back(j * spacing);
      }
}

int FixSPHInflow::setmask()
{
  return POST_INTEGRATE | PRE_EXCHANGE | END_OF_STEP;
}

/* ----------------------------------------------------------------------
   the new particles must be advanced by the GRANSPH integrator as grains
------------------------------------------------------------------------- */

void FixSPHInflow::init()
{
  integrator = &FixSPHIntegrate::find(lmp, "Fix sph/inflow");
  const std::vector<int> &materials = integrator->material_groups;
  const bool of_material = std::find(materials.begin(), materials.end(), igroup) != materials.end();
  if (integrator->igroup != 0 && integrator->igroup != igroup && !of_material)
    error->all(FLERR,
               "Fix sph/inflow: its group {} is not integrated: the integrator fix {} acts on "
               "group {}; give fix sph/inflow that group, the group of one of its materials, "
               "or the integrator group all",
               group->names[igroup], integrator->id, group->names[integrator->igroup]);
  if (groupbit == integrator->wallbit)
    error->all(FLERR, "Fix sph/inflow: its group {} is the walls group of the integrator fix {}",
               group->names[igroup], integrator->id);
}

/* ----------------------------------------------------------------------
   the clock starts at the simulation time of the first setup, when the
   first layer leaves the nozzle
------------------------------------------------------------------------- */

void FixSPHInflow::setup_pre_exchange()
{
  if (!started) {
    clock = t_start = update->atime + (update->ntimestep - update->atimestep) * update->dt;
    started = true;
  }
  insert_due_layers(clock);
}

// after the step's dt is final and before its pre_exchange
void FixSPHInflow::post_integrate()
{
  clock += update->dt;
}

// the step's midpoint, where the integrator's predictor has put the particles
void FixSPHInflow::pre_exchange()
{
  insert_due_layers(clock - 0.5 * update->dt);
}

// the first step of a run needs the same scheduling as the steps after it
void FixSPHInflow::setup(int /*vflag*/)
{
  end_of_step();
}

/* ----------------------------------------------------------------------
   request a reneighboring on the next step if a layer is due at its midpoint.
   The integrator fix sets the next step's dt in its end_of_step; if it is
   defined after this fix, a layer whose time falls in a step that grew can
   enter one step late, at the place its emission time gives.
------------------------------------------------------------------------- */

void FixSPHInflow::end_of_step()
{
  if (layer_due(clock + 0.5 * update->dt)) next_reneighbor = update->ntimestep + 1;
}

/* ---------------------------------------------------------------------- */

double FixSPHInflow::emission_time(bigint k) const
{
  return t_start + static_cast<double>(k) * spacing / speed;
}

bool FixSPHInflow::layer_due(double t) const
{
  const double t_next = emission_time(nlayers);
  return started && t_next <= t && t_next <= t_until;
}

/* ----------------------------------------------------------------------
   insert every layer that has left the nozzle by time t_place, placed where
   it is at that time; the atom map and ghosts are rebuilt as in fix deposit
------------------------------------------------------------------------- */

void FixSPHInflow::insert_due_layers(double t_place)
{
  if (!layer_due(t_place)) return;

  if (atom->map_style != Atom::MAP_NONE) atom->map_clear();
  atom->nghost = 0;
  atom->avec->clear_bonus();

  bigint ncreated = 0, nexpected = 0;
  while (layer_due(t_place)) {
    ncreated += insert_layer(emission_time(nlayers), t_place);
    nexpected += offsets.size() / 2;
    ++nlayers;
  }

  bigint nall = 0;
  MPI_Allreduce(&ncreated, &nall, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (nall != nexpected)
    error->all(FLERR,
               "Fix sph/inflow: {} of {} new particles lie outside the box; the nozzle must be "
               "inside a fixed boundary",
               nexpected - nall, nexpected);
  atom->natoms += nall;
  nparticles += nall;
  atom->tag_extend();

  if (atom->map_style != Atom::MAP_NONE) {
    atom->map_init();
    atom->map_set();
  }
}

/* ----------------------------------------------------------------------
   create the particles of the layer that left the nozzle at t_emit, as they
   are at t_place; return how many this rank owns
------------------------------------------------------------------------- */

int FixSPHInflow::insert_layer(double t_emit, double t_place)
{
  const double shift = amplitude * sin(MY_2PI * frequency * t_emit);
  const double travel = speed * (t_place - t_emit);
  double c[3];
  for (int a = 0; a < 3; ++a) c[a] = center[a] + shift * wave_dir[a] + travel * normal[a];

  int ncreated = 0;
  for (std::size_t p = 0; p < offsets.size(); p += 2) {
    double x[3];
    for (int a = 0; a < 3; ++a) x[a] = c[a] + offsets[p] * e1[a] + offsets[p + 1] * e2[a];
    imageint image;
    if (!owns(x, image)) continue;

    atom->avec->create_atom(ntype, x);
    const int n = atom->nlocal - 1;
    atom->image[n] = image;
    atom->mask[n] |= groupbit | integrator->groupbit;    // a material's grains, or the fix's
    for (int a = 0; a < 3; ++a) atom->v[n][a] = speed * normal[a];
    if (atom->rmass_flag) atom->rmass[n] = new_mass;
    modify->create_attribute(n);

    // in a run the particle joins between the predictor and the corrector,
    // which continues from the start-of-step state: its own (at a setup the
    // predictor overwrites it)
    integrator->host_state().start_step_here(n, atom->v[n]);
    ++ncreated;
  }
  return ncreated;
}

/* ----------------------------------------------------------------------
   whether this rank owns point x (wrapped into a periodic box, image set).
   A shrink-wrapped box grows to take in points beyond its faces at the
   coming exchange, so the ranks at such a face own them.
------------------------------------------------------------------------- */

bool FixSPHInflow::owns(double *x, imageint &image) const
{
  image = ((imageint) IMGMAX << IMG2BITS) | ((imageint) IMGMAX << IMGBITS) | IMGMAX;
  domain->remap(x, image);

  double lamda[3];
  const double *p = x, *sublo = domain->sublo, *subhi = domain->subhi;
  if (domain->triclinic) {
    domain->x2lamda(x, lamda);
    p = lamda;
    sublo = domain->sublo_lamda;
    subhi = domain->subhi_lamda;
  }
  const bool tiled = comm->layout == Comm::LAYOUT_TILED;
  for (int d = 0; d < 3; ++d) {
    const bool lo_face = tiled ? comm->mysplit[d][0] == 0.0 : comm->myloc[d] == 0;
    const bool hi_face = tiled ? comm->mysplit[d][1] == 1.0
                               : comm->myloc[d] == comm->procgrid[d] - 1;
    if (p[d] < sublo[d] && !(lo_face && domain->boundary[d][0] >= 2)) return false;
    if (p[d] >= subhi[d] && !(hi_face && domain->boundary[d][1] >= 2)) return false;
  }
  return true;
}

/* ----------------------------------------------------------------------
   [layers inserted, particles inserted]
------------------------------------------------------------------------- */

double FixSPHInflow::compute_vector(int n)
{
  return static_cast<double>(n == 0 ? nlayers : nparticles);
}

/* ----------------------------------------------------------------------
   the clock, t_start and the layer count give the emission times, so a
   restarted run continues the jet where it stopped
------------------------------------------------------------------------- */

void FixSPHInflow::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double list[5] = {started ? 1.0 : 0.0, clock, t_start, ubuf(nlayers).d, ubuf(nparticles).d};
  const int size = sizeof(list);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(double), 5, fp);
}

void FixSPHInflow::restart(char *buf)
{
  const auto list = reinterpret_cast<double *>(buf);
  started = list[0] != 0.0;
  clock = list[1];
  t_start = list[2];
  nlayers = ubuf(list[3]).i;
  nparticles = ubuf(list[4]).i;
}
