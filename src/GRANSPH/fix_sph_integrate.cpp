/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: shared base of the granular SPH integrators: per-atom state, its
   migration, communication and restart, the continuation of a run, and the
   CFL timestep.
------------------------------------------------------------------------- */

#include "fix_sph_integrate.h"

#include "gransph_find_fix.h"
#include "gransph_integrator.h"
#include "gransph_lammps_compat.h"
#include "gransph_pair_settings.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "output.h"
#include "pair.h"
#include "thermo.h"
#include "update.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using GRANSPH::Sym3;

namespace {
// the settings of pair_style sph/granular (null for another pair style)
const GRANSPH::PairSettings *pair_settings(Force *force)
{
  int dim = 0;
  return force->pair ? static_cast<const GRANSPH::PairSettings *>(force->pair->extract("settings", dim))
                     : nullptr;
}

// In a fix's restart data, a settings record is marked by its version's negative where files
// written before it hold the count of their list of rate settings (>= 0)
constexpr double RECORD_FOLLOWS = -1.0;
}    // namespace

FixSPHIntegrate &FixSPHIntegrate::find(LAMMPS *lmp, const char *who)
{
  FixSPHIntegrate *found =
      GRANSPH::find_only_fix<FixSPHIntegrate>(lmp, who, "GRANSPH integrators");
  if (!found)
    lmp->error->all(FLERR,
                    "{} needs a GRANSPH integrator fix (fix sph/elastoplastic or fix "
                    "sph/phasechange)",
                    who);
  return *found;
}

// material NAME of FILE for the grains of GROUP: one group per material, of grains only
// (checked at each run: check_material_groups), from files that declare the same units
void FixSPHIntegrate::add_material(const std::string &group_name, const std::string &file,
                                   const std::string &name, const std::string &own_file,
                                   const std::string &units)
{
  const std::string style_name = std::string("fix ") + style;
  const int igroup = group->find(group_name);
  if (igroup < 0)
    error->all(FLERR, "{}: material group {} does not exist", style_name, group_name);
  if (igroup == 0 || igroup == this->igroup)
    error->all(FLERR, "{}: material group {} holds every grain: give the fix that material "
               "instead", style_name, group_name);
  for (int k = 1; k < (int) material_groups.size(); ++k)
    if (material_groups[k] == igroup)
      error->all(FLERR, "{}: group {} is given two materials, {} and {}", style_name,
                 group_name, material_records[k].name, name);
  if ((int) material_records.size() == GRANSPH::MaterialTable::MAX)
    error->all(FLERR, "{}: more than {} materials", style_name, GRANSPH::MaterialTable::MAX);
  const std::string its_units =
      utils::get_potential_units(utils::get_potential_file_path(file), "GRANSPH material");
  const auto declared = [](const std::string &u) {
    return u.empty() ? std::string("no units (no UNITS: on its first line)") : "units " + u;
  };
  if (its_units != units)
    error->all(FLERR, "{}: material file {} declares {}, the fix's material file {} {}: the "
               "materials of a run must declare the same units", style_name, file,
               declared(its_units), own_file, declared(units));
  material_records.push_back(GranSPHMaterial::read(lmp, file, name, style_name));
  material_groups.push_back(igroup);
}

/* ---------------------------------------------------------------------- */

FixSPHIntegrate::FixSPHIntegrate(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), wallbit(0), state(nullptr), rates(nullptr), start(nullptr),
    cfl(0.2), cfl_sound_reference(1), predictor_extrapolated(0), nrates(NEVALUATED_RATES),
    geostatic_flag(0), surface_height(0.0),
    restored(0), last_dt(0.0), ran_with_pair_settings(false), fresh_start(nullptr)
{
  const std::string style_name = std::string("fix ") + style;
  if (narg < 5) error->all(FLERR, "Illegal {} command: need a material file and name", style_name);

  material_records.push_back(GranSPHMaterial::read(lmp, arg[3], arg[4], style_name));
  material_groups.push_back(-1);
  const std::string units = utils::get_potential_units(utils::get_potential_file_path(arg[3]),
                                                       "GRANSPH material");
  double rho_init = material_records[0].rho0;
  GranSPHMaterial::Matching matching = GranSPHMaterial::PLANE_STRAIN;
  GranSPHMaterial::PlasticStep plastic = GranSPHMaterial::RETURN_MAPPING;

  int iarg = 5;
  // keyword iarg's value, one of two: 0 for the first, 1 for the second
  auto either = [&](const char *first, const char *second) {
    const std::string value = arg[iarg + 1];
    if (value != first && value != second)
      error->all(FLERR, "{}: {} must be {} or {}, not {}", style_name, arg[iarg], first, second,
                 value);
    return value == second ? 1 : 0;
  };
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg) error->all(FLERR, "{}: keyword {} needs a value", style_name, key);
    if (key == "material") {
      if (iarg + 3 >= narg)
        error->all(FLERR, "{}: keyword material needs a group, a material file and a name",
                   style_name);
      add_material(arg[iarg + 1], arg[iarg + 2], arg[iarg + 3], arg[3], units);
      iarg += 4;
      continue;
    } else if (key == "walls") {
      const int igroup = group->find(arg[iarg + 1]);
      if (igroup < 0) error->all(FLERR, "{}: walls group {} does not exist", style_name, arg[iarg + 1]);
      wallbit = group->bitmask[igroup];
      if (wallbit == groupbit)
        error->all(FLERR, "{}: walls group must differ from the fix group", style_name);
    } else if (key == "rho") {
      rho_init = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (rho_init <= 0.0) error->all(FLERR, "{}: rho must be > 0", style_name);
    } else if (key == "cfl") {
      if (strcmp(arg[iarg + 1], "none") == 0)
        cfl = 0.0;
      else {
        cfl = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
        if (cfl <= 0.0 || cfl > 1.0) error->all(FLERR, "{}: cfl must be in (0, 1] or none", style_name);
      }
    } else if (key == "cfl/sound") {
      cfl_sound_reference = either("local", "reference");
    } else if (key == "predictor") {
      predictor_extrapolated = either("midpoint", "extrapolated");
      nrates = predictor_extrapolated ? int(NRATES) : int(NEVALUATED_RATES);
    } else if (key == "matching" || key == "plastic") {
      if (!utils::strmatch(style, "^sph/elastoplastic"))
        error->all(FLERR, "{}: keyword {} is for fix sph/elastoplastic only", style_name, key);
      if (key == "matching")
        matching = either("plane_strain", "simple_shear") ? GranSPHMaterial::SIMPLE_SHEAR
                                                          : GranSPHMaterial::PLANE_STRAIN;
      else
        plastic = either("return", "paper") ? GranSPHMaterial::EXPLICIT_RATE
                                            : GranSPHMaterial::RETURN_MAPPING;
    } else if (key == "geostatic") {
      geostatic_flag = 1;
      surface_height = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    } else
      error->all(FLERR, "{}: unknown keyword {}", style_name, key);
    iarg += 2;
  }

  if (!atom->rmass_flag && !atom->mass) error->all(FLERR, "{} needs per-type or per-atom masses", style_name);
  if (geostatic_flag && material_records.size() > 1)
    error->all(FLERR, "{}: geostatic takes one density and is for one material, not {}: let "
               "layers of several materials settle under gravity instead", style_name,
               material_records.size());

  // every material takes the model's choices (matching, plastic) alike
  materials.n = material_records.size();
  for (int k = 0; k < materials.n; ++k) {
    GranSPHMaterial &m = material_records[k];
    m.dp_matching = matching;
    m.dp_plastic = plastic;
    materials.bits[k] = k ? group->bitmask[material_groups[k]] : 0;
    materials.any_bits |= materials.bits[k];
    materials.E[k] = m.E;
    materials.c0[k] = sqrt(m.bulk_modulus() / m.rho0);
    materials.rho0[k] = m.rho0;
    materials.rho_init[k] = k ? m.rho0 : rho_init;
  }

  time_integrate = 1;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  peratom_flag = 1;
  size_peratom_cols = NSTATE;
  peratom_freq = 1;
  comm_forward = NCOMM;
  nevery = 1;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; ++i) set_arrays(i);
}

FixSPHIntegrate::~FixSPHIntegrate()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(state);
  memory->sfree(rates);
  memory->sfree(start);
}

int FixSPHIntegrate::setmask()
{
  return INITIAL_INTEGRATE | PRE_FORCE | FINAL_INTEGRATE | END_OF_STEP;
}

/* ---------------------------------------------------------------------- */

void FixSPHIntegrate::init()
{
  if (!force->pair || !force->pair_match("sph/granular", 0))
    error->all(FLERR, "Fix {} requires pair_style sph/granular", style);
  if (update->whichflag == 1 && utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix {} does not support run_style respa", style);
  find(lmp, (std::string("Fix ") + style).c_str());    // the only one

  bool inflow = false;
  for (int i = 0; i < modify->nfix; ++i) inflow |= utils::strmatch(modify->fix[i]->style, "^sph/inflow");
  if (group->count(igroup) == 0 && !inflow)
    error->all(FLERR,
               "Fix {}: its group {} holds no atom, so there is nothing to integrate (did "
               "create_atoms place none? a region outside the box, or sand above it)",
               style, group->names[igroup]);

  const int *mask = atom->mask;
  const auto in_both = [&](int i) { return (mask[i] & groupbit) && (mask[i] & wallbit); };
  if (GRANSPH::any_owned_atom(lmp, in_both))
    error->all(FLERR, "Fix {}: an atom is in both the fix group and the walls group", style);
  check_material_groups();
}

// Collective: each material group still there; no grain claimed by two materials and no
// dummy particle by one (the first such atom named, with its material groups)
void FixSPHIntegrate::check_material_groups() const
{
  if (materials.n == 1) return;
  for (int k = 1; k < materials.n; ++k)
    if (!group->names[material_groups[k]] ||
        group->bitmask[material_groups[k]] != materials.bits[k])
      error->all(FLERR, "Fix {}: the group of material {} was deleted", style,
                 material_records[k].name);
  const auto claims = [&](int mask) {
    std::string names;
    for (int k = 1; k < materials.n; ++k)
      if (mask & materials.bits[k])
        names += fmt::format(" {} ({})", group->names[material_groups[k]], material_records[k].name);
    return names;
  };
  const int *mask = atom->mask;
  for (const bool walls : {false, true}) {
    // the lowest ID of an atom at fault, and its group bits
    tagint first = MAXTAGINT, lowest = MAXTAGINT;
    for (int i = 0; i < atom->nlocal; ++i) {
      const int claimed = mask[i] & materials.any_bits;
      const bool at_fault = walls ? (mask[i] & wallbit) && claimed
                                  : (mask[i] & groupbit) && (claimed & (claimed - 1));
      if (at_fault) first = MIN(first, atom->tag[i]);
    }
    MPI_Allreduce(&first, &lowest, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    if (lowest == MAXTAGINT) continue;
    const int i = atom->map(lowest);
    // the owner's bits: the other ranks give 0
    int bits = (i >= 0 && i < atom->nlocal) ? mask[i] : 0, all_bits = 0;
    MPI_Allreduce(&bits, &all_bits, 1, MPI_INT, MPI_SUM, world);
    if (walls)
      error->all(FLERR, "Fix {}: dummy particle {} of the walls group is in the material group{}: "
                 "a material is for grains only", style, lowest, claims(all_bits));
    error->all(FLERR, "Fix {}: grain {} is claimed by two materials, by the groups{}", style,
               lowest, claims(all_bits));
  }
}

// before the setup force evaluation: the geostatic stress, so that the first rates
// see it, and a copy of what that evaluation overwrites if this run continues the last
void FixSPHIntegrate::setup_pre_force(int /*vflag*/)
{
  sync_host();
  if (materials.n > 1 && !restored) start_materials_at_their_density();
  if (geostatic_flag && !restored) init_geostatic_stress();
  geostatic_flag = 0;
  fresh_start = why_not_continue();
  if (fresh_start)
    forget_steps();
  else
    save_step();
  modified_host();
}

// Before any output of the run: a run that continues the last restores its last step
// (fix_sph_integrate.h); otherwise the first step starts from the setup evaluation at t.
void FixSPHIntegrate::setup(int /*vflag*/)
{
  sync_host();
  check_plane();
  check_finite();
  if (fresh_start) {
    if (comm->me == 0)
      utils::logmesg(lmp, "Fix {}: {}: the first step starts from the rates at t of the setup "
                     "force evaluation\n", style, fresh_start);
    reset_cfl_timestep();
  } else
    restore_step();
  const GRANSPH::PairSettings *settings = pair_settings(force);
  ran_with_pair_settings = settings != nullptr;
  if (settings) last_pair_settings = *settings;
  modified_host();
}

void FixSPHIntegrate::end_of_step()
{
  reset_cfl_timestep();
  last_dt = update->dt;
  // LAMMPS checks for lost atoms with its thermo output, just after this
  if (update->ntimestep == output->next_thermo) stop_if_atoms_lost();
}

// Atoms that cross a fixed boundary are lost, which LAMMPS reports ("Lost atoms") without
// saying why or what to do; where and when it would stop for them (thermo_modify lost
// error, the default; at a thermo output step), stop first and say it
void FixSPHIntegrate::stop_if_atoms_lost() const
{
  if (output->thermo->lostflag != Thermo::ERROR) return;
  bigint local = atom->nlocal, total = 0;
  MPI_Allreduce(&local, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (total < atom->natoms)
    error->all(FLERR,
               "Fix {}: {} atoms left the box by step {} (an atom that crosses a fixed boundary "
               "is lost): fix sph/outflow over a region inside the box removes and counts the "
               "grains that leave the site (doc/fix_sph_outflow.rst), or make the box larger",
               style, atom->natoms - total, update->ntimestep);
}

/* ----------------------------------------------------------------------
   continuation across runs
------------------------------------------------------------------------- */

// nullptr if this run can continue with the rates of the last step, or the reason
const char *FixSPHIntegrate::why_not_continue() const
{
  const int *mask = atom->mask;
  const auto stepped = [&](int i) { return (mask[i] & groupbit) && start_of(i)[STEPPED] != 0.0; };
  if (!GRANSPH::any_owned_atom(lmp, stepped)) return "no previous step";
  const GRANSPH::PairSettings *settings = pair_settings(force);
  if (!settings || !ran_with_pair_settings || !settings->same_rates(last_pair_settings))
    return "the pair style settings changed since the last step";
  if (update->dt != last_dt) return "the timestep changed since the last step";
  return nullptr;
}

void FixSPHIntegrate::forget_steps()
{
  for (int i = 0; i < atom->nlocal; ++i) start_of(i)[STEPPED] = 0.0;
}

// The values of atom i that the setup evaluation overwrites (StateLayout), copied to
// `kept` or, with back, from it: a grain's rates, a dummy particle's stress and wall
// history; KEPT_PER_ATOM values either way
void FixSPHIntegrate::keep_evaluated(int i, double *kept, bool back)
{
  const auto copy = [back](double *column, double *copied, int n) {
    if (back)
      std::copy(copied, copied + n, column);
    else
      std::copy(column, column + n, copied);
  };
  if (atom->mask[i] & groupbit)
    copy(rates_of(i), kept, NEVALUATED_RATES);
  else if (atom->mask[i] & wallbit) {
    copy(&state[i][SIGMA], kept, KEPT_STEPPED);
    copy(start_of(i) + STEPPED, kept + KEPT_STEPPED, NWALL_HISTORY);
  }
}

void FixSPHIntegrate::save_step()
{
  const int nlocal = atom->nlocal;
  saved.resize((size_t) nlocal * KEPT_PER_ATOM);
  for (int i = 0; i < nlocal; ++i) keep_evaluated(i, &saved[(size_t) i * KEPT_PER_ATOM], false);
}

// atoms without a step (created since) keep the values of the setup evaluation
void FixSPHIntegrate::restore_step()
{
  const int nrows = MIN(atom->nlocal, (int) (saved.size() / KEPT_PER_ATOM));
  bigint fresh[2] = {0, 0};    // grains without a step, all grains
  for (int i = 0; i < nrows; ++i) {
    double *kept = &saved[(size_t) i * KEPT_PER_ATOM];
    const bool grain = atom->mask[i] & groupbit;
    // a grain's STEPPED is the integrator's, a dummy particle's the evaluation's: kept
    const double stepped = grain ? start_of(i)[STEPPED] : kept[KEPT_STEPPED];
    fresh[1] += grain;
    if (stepped == 0.0) {
      fresh[0] += grain;
      continue;
    }
    keep_evaluated(i, kept, true);
  }
  std::vector<double>().swap(saved);
  bigint total[2];
  MPI_Allreduce(fresh, total, 2, MPI_LMP_BIGINT, MPI_SUM, world);
  if (total[0] && comm->me == 0)
    utils::logmesg(lmp, "Fix {}: {} of {} grains are new since the last step: their first step "
                   "starts from the rates at t of the setup force evaluation\n", style, total[0],
                   total[1]);
}

// Global restart data: what the last step ran with (the timestep, and the pair style's
// settings as a record), and the elapsed time, which restart files of this LAMMPS
// version leave out although the CFL timestep varies.
void FixSPHIntegrate::write_restart(FILE *fp)
{
  std::vector<double> list = {last_dt, update->atime, (double) update->atimestep, 0.0};
  if (ran_with_pair_settings) {
    const std::vector<double> record = last_pair_settings.record();
    list.back() = RECORD_FOLLOWS;
    list.push_back(GRANSPH::PairSettings::VERSION);
    list.push_back(record.size());
    list.insert(list.end(), record.begin(), record.end());
  }
  if (comm->me == 0) {
    const int size = list.size() * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list.data(), sizeof(double), list.size(), fp);
  }
}

void FixSPHIntegrate::restart(char *buf)
{
  const auto list = reinterpret_cast<const double *>(buf);
  last_dt = list[0];
  if (update->atime == 0.0 && update->atimestep == 0) {    // nothing set the time since
    update->atime = list[1];
    update->atimestep = static_cast<bigint>(list[2]);
  }
  const int count = static_cast<int>(list[3]);
  ran_with_pair_settings = count != 0;
  if (list[3] == RECORD_FOLLOWS)
    last_pair_settings = GRANSPH::PairSettings::from_record(lmp, static_cast<int>(list[4]),
                                                            list + 6, static_cast<int>(list[5]));
  else if (count > 0)
    last_pair_settings = GRANSPH::PairSettings::from_legacy_rates(list + 4, count);
}

/* ---------------------------------------------------------------------- */

void FixSPHIntegrate::forward_comm_state()
{
  GRANSPHCompat::forward_comm_fix(comm, this);
}

double FixSPHIntegrate::smoothing_length() const
{
  int dim = 0;
  auto h = static_cast<double *>(force->pair->extract("h", dim));
  if (!h) error->all(FLERR, "Fix {}: pair style does not provide a smoothing length", style);
  return *h;
}

// sum of the accelerations of the fix gravity instances acting on the grains
// (defined on this fix's group or on all)
void FixSPHIntegrate::gravity_vector(double *g) const
{
  g[0] = g[1] = g[2] = 0.0;
  for (int i = 0; i < modify->nfix; ++i) {
    const Fix *fix = modify->fix[i];
    if (!utils::strmatch(fix->style, "^gravity")) continue;
    if (fix->igroup != igroup && fix->igroup != 0) continue;
    int dim = 0;
    auto gvec = static_cast<double *>(modify->fix[i]->extract("gvec", dim));
    if (gvec)
      for (int a = 0; a < 3; ++a) g[a] += gvec[a];
  }
}

/* ----------------------------------------------------------------------
   eq. 19: dt = C min(sqrt(h / max|a|), h / c) with c = sqrt(E / rho), rho the
   grains' (local) or the initial density (reference)
------------------------------------------------------------------------- */

void FixSPHIntegrate::reset_cfl_timestep()
{
  if (cfl == 0.0) return;
  constexpr int N = 1 + GRANSPH::MaterialTable::MAX;
  double local[N], global[N];
  local[0] = -1.0;
  for (int k = 0; k < materials.n; ++k) local[1 + k] = -DBL_MAX;
  cfl_maxima(local);
  MPI_Allreduce(local, global, 1 + materials.n, MPI_DOUBLE, MPI_MAX, world);
  if (global[0] < 0.0) return;    // no granular particles anywhere
  // the fastest sound of all materials (of a material without grains: none, at DBL_MAX)
  double c = 0.0;
  for (int k = 0; k < materials.n; ++k) {
    // the grains' lowest density, or under cfl/sound reference the initial one: a dilated grain,
    // whose few and distant neighbours make it no stiffer, does not shorten the step
    const double rho = cfl_sound_reference ? materials.rho_init[k] : -global[1 + k];
    c = MAX(c, GRANSPH::sound_speed(materials.E[k], rho));
  }
  set_timestep(GRANSPH::cfl_timestep(cfl, smoothing_length(), sqrt(global[0]) * force->ftm2v, c));
}

void FixSPHIntegrate::cfl_maxima(double *local)
{
  double **f = atom->f;
  const double *rmass = atom->rmass;
  const double *mass = atom->mass;
  const int *type = atom->type;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    const double m = rmass ? rmass[i] : mass[type[i]];
    const double a2 = GRANSPH::dot3(f[i], f[i]) / (m * m);
    local[0] = MAX(local[0], a2);
    if (cfl_sound_reference) continue;
    const int k = materials.of(mask[i]);
    local[1 + k] = MAX(local[1 + k], -state[i][RHO]);
  }
}

// as fix dt/reset does
void FixSPHIntegrate::set_timestep(double dt)
{
  if (dt == update->dt) return;
  update->update_time();
  update->dt = dt;
  update->dt_default = 0;
  if (force->pair) force->pair->reset_dt();
  for (int i = 0; i < modify->nfix; i++) modify->fix[i]->reset_dt();
}

// Grains that have not stepped start at the density of their material: groups are
// often made after the atoms, which then started at the fix's own (set_arrays)
void FixSPHIntegrate::start_materials_at_their_density()
{
  for (int i = 0; i < atom->nlocal; ++i)
    if ((atom->mask[i] & groupbit) && start_of(i)[STEPPED] == 0.0)
      state[i][RHO] = materials.rho_init[materials.of(atom->mask[i])];
}

/* ----------------------------------------------------------------------
   geostatic initial stress: sigma_v = rho0 |g| (z - z_s) below the surface
   (vertical = z in 3D, y in 2D), sigma_h = K0 sigma_v with K0 = nu / (1 - nu)
------------------------------------------------------------------------- */

void FixSPHIntegrate::init_geostatic_stress()
{
  double g[3];
  gravity_vector(g);
  const int up = domain->dimension == 3 ? 2 : 1;
  const double gmag = GRANSPH::norm3(g);
  if (gmag == 0.0) error->all(FLERR, "Fix {} geostatic needs a fix gravity", style);
  const double k0 = material_records[0].nu / (1.0 - material_records[0].nu);
  const double rho_init = materials.rho_init[0];
  double **x = atom->x;
  const int *mask = atom->mask;
  const HostState rows = host_state();
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    const double sv = MIN(0.0, rho_init * gmag * (x[i][up] - surface_height));
    Sym3 s = Sym3::iso(k0 * sv);
    if (up == 2) s.zz = sv;
    else s.yy = sv;
    rows.set_sigma(i, s);
  }
}

// A non-finite state or a non-positive density stops the run with the atom's ID
// rather than spreading NaNs (at setup: before the first output).
void FixSPHIntegrate::check_finite() const
{
  double **x = atom->x;
  double **v = atom->v;
  const int *mask = atom->mask;
  const HostState rows = host_state();
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    const GRANSPH::ParticleState p{{x[i][0], x[i][1], x[i][2]}, {v[i][0], v[i][1], v[i][2]},
                                   rows.rho(i), rows.sigma(i)};
    if (GRANSPH::bad_state(p))
      error->one(FLERR,
                 "Fix {}: atom {} has a non-finite state or non-positive density (rho {}, v {} {} "
                 "{}) at step {}",
                 style, atom->tag[i], state[i][RHO], v[i][0], v[i][1], v[i][2], update->ntimestep);
  }
}

// A 2d run moves particles in x and y only: grains or walls off the z = 0 plane, or
// moving out of it, would stay there unnoticed.
void FixSPHIntegrate::check_plane() const
{
  if (domain->dimension != 2) return;
  double **x = atom->x;
  double **v = atom->v;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i)
    if ((mask[i] & (groupbit | wallbit)) && (x[i][2] != 0.0 || v[i][2] != 0.0))
      error->one(FLERR, "Fix {}: atom {} is off the z = 0 plane of the 2d run (z {}, vz {})",
                 style, atom->tag[i], x[i][2], v[i][2]);
}

/* ----------------------------------------------------------------------
   per-atom arrays: they move with the atoms and survive restarts
------------------------------------------------------------------------- */

// The host reads the rows through int offsets (GRANSPH::HostRows: vector gathers)
void FixSPHIntegrate::check_row_offsets(int nmax) const
{
  if ((bigint) nmax * MAX(nrates, (int) NSTART) > MAXSMALLINT)
    error->one(FLERR, "Fix {}: {} atoms on one MPI rank are more than its per-atom arrays "
               "can index: run on more ranks", style, nmax);
}

void FixSPHIntegrate::grow_arrays(int nmax)
{
  check_row_offsets(nmax);
  memory->grow(state, nmax, NSTATE, "sph:state");
  rates = (double *) memory->srealloc(rates, sizeof(double) * nmax * nrates, "sph:rates");
  start = (double *) memory->srealloc(start, sizeof(double) * nmax * NSTART, "sph:start");
  array_atom = state;
}

void FixSPHIntegrate::copy_arrays(int i, int j, int /*delflag*/)
{
  if (i == j) return;    // LAMMPS copies the last atom onto itself when deleting it
  sync_host();
  memcpy(state[j], state[i], NSTATE * sizeof(double));
  memcpy(rates_of(j), rates_of(i), nrates * sizeof(double));
  memcpy(start_of(j), start_of(i), NSTART * sizeof(double));
  modified_host();
}

// new atoms (create_atoms, read_data, inflow fixes) start at rest and stress-free
void FixSPHIntegrate::set_arrays(int i)
{
  sync_host();
  state[i][RHO] = materials.rho_init[materials.of(atom->mask[i])];
  for (int k = 1; k < NSTATE; ++k) state[i][k] = 0.0;    // stress-free, ELASTIC
  std::fill_n(rates_of(i), nrates, 0.0);
  std::fill_n(start_of(i), NSTART, 0.0);
  modified_host();
}

int FixSPHIntegrate::pack_row(int i, double *buf) const
{
  int m = 0;
  for (int k = 0; k < NSTATE; ++k) buf[m++] = state[i][k];
  for (int k = 0; k < nrates; ++k) buf[m++] = rates_of(i)[k];
  for (int k = 0; k < NSTART; ++k) buf[m++] = start_of(i)[k];
  return m;
}

int FixSPHIntegrate::unpack_row(int i, const double *buf)
{
  int m = 0;
  for (int k = 0; k < NSTATE; ++k) state[i][k] = buf[m++];
  for (int k = 0; k < nrates; ++k) rates_of(i)[k] = buf[m++];
  for (int k = 0; k < NSTART; ++k) start_of(i)[k] = buf[m++];
  return m;
}

int FixSPHIntegrate::pack_exchange(int i, double *buf)
{
  sync_host();
  return pack_row(i, buf);
}

int FixSPHIntegrate::unpack_exchange(int nlocal, double *buf)
{
  sync_host();
  const int m = unpack_row(nlocal, buf);
  modified_host();
  return m;
}

// restart files hold everything the next step needs: the state, the rates and the
// start of the step
int FixSPHIntegrate::pack_restart(int i, double *buf)
{
  buf[0] = row_size() + 1;
  return 1 + pack_exchange(i, buf + 1);
}

// Files written before the viscous pressure left the state (STATE_WITH_VISC columns) are
// read past that column; their rates and start values by read_rates_and_start. Files of
// earlier versions hold the state only: those atoms start without a step.
void FixSPHIntegrate::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const int size = static_cast<int>(extra[nlocal][m++]) - 1;
  const double *row = &extra[nlocal][m];
  sync_host();
  memcpy(state[nlocal], row, NSTATE * sizeof(double));
  restored = 1;
  for (const int nstate : {NSTATE, STATE_WITH_VISC})
    for (const int nr : {int(NEVALUATED_RATES), int(RATES_WITH_ACC), int(NRATES)})
      for (const int nstart : {int(NSTART), int(START_SIDE_BY_SIDE)})
        if (size == nstate + nr + nstart) {
          read_rates_and_start(nlocal, row + nstate, nr, nstart);
          modified_host();
          return;
        }
  modified_host();
}

// Atom i's rates and start values from a file's row of nr rates (the evaluation's; with
// its acceleration, RATES_WITH_ACC, in files written before the acceleration moved to the
// start values; with predictor extrapolated NRATES), then nstart start values
// (START_SIDE_BY_SIDE: files of before the grains' and the dummies' shared their columns,
// read_start_side_by_side). Where a file's rates hold the acceleration, a grain keeps it
// with its start values (LAST_ACC). A file of the other predictor's layout (a file of
// `predictor midpoint` read under extrapolated, or the reverse) gives the columns both
// have: the grain's next step extrapolates once its own two mid-points are known.
void FixSPHIntegrate::read_rates_and_start(int i, const double *row, int nr, int nstart)
{
  double *rates_i = rates_of(i), *start_i = start_of(i);
  std::copy(row, row + NEVALUATED_RATES, rates_i);
  if (nstart == NSTART)
    std::copy(row + nr, row + nr + NSTART, start_i);
  else
    read_start_side_by_side(i, row + nr);
  const bool grain = atom->mask[i] & groupbit;
  if (grain && nr > NEVALUATED_RATES) std::copy(row + ACC, row + ACC + 3, start_i + LAST_ACC);
  if (nrates == NRATES) {
    std::fill(rates_i + ACC, rates_i + NRATES, 0.0);
    if (nr == NRATES)
      std::copy(row + ACC, row + NRATES, rates_i + ACC);
    else {    // the mid-point of the file's last step, of the timestep restart() read
      if (grain) std::copy(start_i + LAST_ACC, start_i + LAST_ACC + 3, rates_i + ACC);
      rates_i[RATES_DT] = last_dt;
    }
  }
  if ((nr == NRATES) != (nrates == NRATES)) start_i[STEPPED] = fmin(start_i[STEPPED], 1.0);
}

// atom i's start values from a row of START_SIDE_BY_SIDE: a grain's start of the step
// (v, rho, sigma: 10 values), a dummy particle's wall velocity (3), STEPPED, its wall
// force (3)
void FixSPHIntegrate::read_start_side_by_side(int i, const double *row)
{
  enum { GRAIN_START = 0, OLD_WALL_V = 10, OLD_STEPPED = 13, OLD_WALL_F = 14 };
  double *to = start_of(i);
  std::fill_n(to, NSTART, 0.0);
  to[STEPPED] = row[OLD_STEPPED];
  if (atom->mask[i] & groupbit)
    std::copy(row + GRAIN_START, row + OLD_WALL_V, to + V_START);
  else if (atom->mask[i] & wallbit) {
    std::copy(row + OLD_WALL_V, row + OLD_WALL_V + 3, to + WALL_V);
    std::copy(row + OLD_WALL_F, row + OLD_WALL_F + 3, to + WALL_F);
  }
}

int FixSPHIntegrate::size_restart(int /*nlocal*/)
{
  return row_size() + 1;
}

int FixSPHIntegrate::maxsize_restart()
{
  return row_size() + 1;
}

int FixSPHIntegrate::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/,
                                       int * /*pbc*/)
{
  sync_host(STATE_ONLY);
  int m = 0;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < NCOMM; ++k) buf[m++] = state[list[i]][k];
  return m;
}

void FixSPHIntegrate::unpack_forward_comm(int n, int first, double *buf)
{
  sync_host(STATE_ONLY);
  int m = 0;
  for (int i = first; i < first + n; ++i)
    for (int k = 0; k < NCOMM; ++k) state[i][k] = buf[m++];
  modified_host(STATE_ONLY);
}

double FixSPHIntegrate::memory_usage()
{
  return (double) atom->nmax * row_size() * sizeof(double);
}
