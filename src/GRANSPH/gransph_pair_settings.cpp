/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: the settings of pair_style sph/granular: parsing and the restart
   record.
------------------------------------------------------------------------- */

#include "gransph_pair_settings.h"

#include "comm.h"
#include "error.h"
#include "group.h"
#include "lammps.h"
#include "utils.h"

#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace GRANSPH {

namespace {
// what the restart section of a record starts with: "GSPH" as a little-endian int; a file
// written before the record starts with h, a double whose first four bytes are followed by
// an exponent that no int count below 2^20 can be
constexpr int RECORD_MARK = 0x48505347;
constexpr int RECORD_VERSIONS = 1 << 20;

// the restart files before the record mark their layout by a dated number before the
// choices, where the oldest have their first choice (0 or 1)
constexpr int LEGACY_WITH_PRECISION = -20261204, LEGACY_WITH_HOLD = -20261205,
              LEGACY_WITH_PRUNE = -20261206;
}    // namespace

// pair_style sph/granular h keyword value ...: doc/pair_sph_granular.rst
PairSettings PairSettings::parse(LAMMPS *lmp, int narg, char **arg)
{
  Error *error = lmp->error;
  const char *keywords = "visc, visc/sound, visc/walls, gradient, wall/gradient, wall/stress, "
                         "wall/friction, wall/friction/hold, precision, prune";
  if (narg < 1) error->all(FLERR, "Illegal pair_style sph/granular command: need h");
  PairSettings s;
  s.h = utils::numeric(FLERR, arg[0], false, lmp);
  if (s.h <= 0.0) error->all(FLERR, "Pair style sph/granular: smoothing length h must be > 0");
  // the value of keyword iarg among `choices`, as its index
  auto choice = [&](int iarg, std::initializer_list<const char *> choices) {
    if (iarg + 2 > narg) error->all(FLERR, "Pair style sph/granular: {} needs a value", arg[iarg]);
    std::string valid;
    int index = 0;
    for (const char *c : choices) {
      if (strcmp(arg[iarg + 1], c) == 0) return index;
      valid += (index++ ? " or " : "") + std::string(c);
    }
    error->all(FLERR, "Pair style sph/granular: unknown value {} of keyword {} (it takes {})",
               arg[iarg + 1], arg[iarg], valid);
    return -1;
  };
  // a number, or an error that names the keyword
  auto number = [&](int iarg, const char *what) {
    if (!utils::is_double(arg[iarg]))
      error->all(FLERR, "Pair style sph/granular: {} must be a number, not {}", what, arg[iarg]);
    return utils::numeric(FLERR, arg[iarg], false, lmp);
  };
  int iarg = 1;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "wall/friction") {
      if (iarg + 3 > narg)
        error->all(FLERR, "Pair style sph/granular: wall/friction needs a group and a value");
      const int igroup = lmp->group->find(arg[iarg + 1]);
      if (igroup < 0)
        error->all(FLERR, "Pair style sph/granular: wall/friction group {} does not exist",
                   arg[iarg + 1]);
      const std::string value = arg[iarg + 2];
      double mu = FrictionWall::ROUGH;
      if (value == "slip")
        mu = 0.0;
      else if (value == "material")
        mu = FrictionWall::MATERIAL;
      else if (value != "rough") {
        const double delta = utils::is_double(value) ? number(iarg + 2, "") : -1.0;
        if (delta < 0.0 || delta >= 90.0)
          error->all(FLERR,
                     "Pair style sph/granular: wall/friction of group {} must be rough, slip, "
                     "material or an angle in [0, 90) degrees, not {}",
                     arg[iarg + 1], value);
        mu = tan(delta * M_PI / 180.0);
      }
      if (s.nfriction == MAX_FRICTION_WALLS)
        error->all(FLERR, "Pair style sph/granular: more than {} wall/friction entries",
                   MAX_FRICTION_WALLS);
      s.friction[s.nfriction++] = {igroup, mu};
      iarg += 3;
      continue;
    }
    if (key == "prune") {
      if (iarg + 2 > narg) error->all(FLERR, "Pair style sph/granular: prune needs a value");
      s.prune = number(iarg + 1, "prune");
      if (s.prune < 0.0)
        error->all(FLERR, "Pair style sph/granular: prune must be >= 0, not {}", arg[iarg + 1]);
      iarg += 2;
      continue;
    }
    if (key == "visc") {
      if (iarg + 3 > narg) error->all(FLERR, "Pair style sph/granular: visc needs alpha and beta");
      s.visc_alpha = number(iarg + 1, "visc alpha");
      s.visc_beta = number(iarg + 2, "visc beta");
      if (s.visc_alpha < 0.0 || s.visc_beta < 0.0)
        error->all(FLERR, "Pair style sph/granular: visc alpha and beta must be >= 0");
      iarg += 3;
      continue;
    }
    if (key == "visc/sound")
      s.visc_sound = choice(iarg, {"paper", "bulk"}) ? Viscosity::BULK : Viscosity::PAPER;
    else if (key == "visc/walls")
      s.visc_walls = choice(iarg, {"no", "yes"}) == 1;
    else if (key == "gradient")
      s.corrected_gradient = choice(iarg, {"plain", "corrected"}) == 1;
    else if (key == "wall/gradient")
      s.wall_normal = choice(iarg, {"full", "normal"}) == 1;
    else if (key == "wall/stress")
      s.wall_stress = choice(iarg, {"paper", "ratio"}) ? WallSums::RATIO : WallSums::PAPER;
    else if (key == "wall/friction/hold")
      s.hold_stick = choice(iarg, {"stress", "stick"}) == 1;
    else if (key == "precision")
      s.mixed_precision = choice(iarg, {"double", "mixed"}) == 1;
    else
      error->all(FLERR, "Pair style sph/granular: unknown keyword {} (the keywords are h, then {})",
                 key, keywords);
    iarg += 2;
  }
  if (s.hold_stick && !s.has_friction_walls())
    error->all(FLERR,
               "Pair style sph/granular: wall/friction/hold stick needs walls with a friction "
               "of their own (wall/friction group delta)");
  return s;
}

bool PairSettings::same_rates(const PairSettings &o) const
{
  PairSettings a = *this, b = o;
  a.prune = b.prune = 0.0;
  return a.record() == b.record();
}

/* ----------------------------------------------------------------------
   the restart record: the values of values_of() in their order, then each
   friction wall's group and mu
------------------------------------------------------------------------- */

namespace {
// a record's double as the setting's type
void assign(double &v, double x)
{
  v = x;
}
void assign(bool &v, double x)
{
  v = x != 0.0;
}
template <class Choice> void assign(Choice &v, double x)
{
  v = static_cast<Choice>(static_cast<int>(x));
}
}    // namespace

std::vector<double> PairSettings::record() const
{
  std::vector<double> r;
  values_of(*this, [&r](const auto &v) { r.push_back(static_cast<double>(v)); });
  for (int k = 0; k < nfriction; ++k) {
    r.push_back(friction[k].group);
    r.push_back(friction[k].mu);
  }
  return r;
}

PairSettings PairSettings::from_record(LAMMPS *lmp, int version, const double *r, int count)
{
  if (version != VERSION)
    lmp->error->all(FLERR,
                    "Pair style sph/granular: the restart file holds settings of record version "
                    "{}, which this GRANSPH does not know (it reads version {} and the files "
                    "written before the record)",
                    version, VERSION);
  PairSettings s;
  int fixed = 0;
  values_of(s, [&fixed](const auto &) { ++fixed; });
  const int walls = count >= fixed ? static_cast<int>(r[fixed - 1]) : -1;
  if (walls < 0 || walls > MAX_FRICTION_WALLS || count != fixed + 2 * walls)
    lmp->error->all(FLERR, "Pair style sph/granular: the restart file's settings record is "
                           "damaged ({} values)", count);
  int k = 0;
  values_of(s, [&](auto &v) { assign(v, r[k++]); });
  for (int w = 0; w < walls; ++w)
    s.friction[w] = {static_cast<int>(r[fixed + 2 * w]), r[fixed + 2 * w + 1]};
  return s;
}

void PairSettings::write_restart(FILE *fp) const
{
  const std::vector<double> r = record();
  const int head[3] = {RECORD_MARK, VERSION, static_cast<int>(r.size())};
  fwrite(head, sizeof(int), 3, fp);
  fwrite(r.data(), sizeof(double), r.size(), fp);
}

namespace {
// The settings of a restart file written before the record, whose first 8 bytes (h) are
// in `first`: h, alpha, beta, then a dated mark and the choices as ints (sound, walls,
// gradient, wall stress, wall normal, the number of friction walls, precision, hold), each
// friction wall as an int group and a double mu, and prune (LEGACY_WITH_PRUNE). Rank 0.
PairSettings read_legacy_restart(LAMMPS *lmp, FILE *fp, const char *first)
{
  Error *error = lmp->error;
  double values[3];
  memcpy(&values[0], first, sizeof(double));
  utils::sfread(FLERR, values + 1, sizeof(double), 2, fp, nullptr, error);
  int mark = 0;
  utils::sfread(FLERR, &mark, sizeof(int), 1, fp, nullptr, error);
  // files without a mark hold 5 choices (the first read as the mark), then friction walls
  // but no precision or hold: double precision, held by stress
  int choices[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  const int count = mark == LEGACY_WITH_PRUNE || mark == LEGACY_WITH_HOLD ? 8
      : mark == LEGACY_WITH_PRECISION                                    ? 7
                                                                         : 5;
  if (count == 5) choices[0] = mark;
  utils::sfread(FLERR, count == 5 ? choices + 1 : choices, sizeof(int), count, fp, nullptr,
                error);
  // as the list of rate settings a fix's restart data held then, which holds all but prune
  const int nfriction = choices[5];
  if (nfriction < 0 || nfriction > PairSettings::MAX_FRICTION_WALLS)
    error->one(FLERR, "Pair style sph/granular: the restart file's settings are damaged ({} "
                      "friction walls)", nfriction);
  std::vector<double> rates{values[0], values[1], values[2]};
  for (int k = 0; k < 5; ++k) rates.push_back(choices[k]);
  for (int k = 0; k < nfriction; ++k) {
    int group = 0;
    double mu = 0.0;
    utils::sfread(FLERR, &group, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &mu, sizeof(double), 1, fp, nullptr, error);
    rates.push_back(group);
    rates.push_back(mu);
  }
  if (choices[6]) rates.push_back(-1.0);
  if (choices[7]) rates.push_back(-2.0);
  PairSettings s = PairSettings::from_legacy_rates(rates.data(), rates.size());
  if (mark == LEGACY_WITH_PRUNE) utils::sfread(FLERR, &s.prune, sizeof(double), 1, fp, nullptr, error);
  return s;
}
}    // namespace

PairSettings PairSettings::read_restart(LAMMPS *lmp, FILE *fp)
{
  // rank 0 reads and sends the record (a file before it: read_legacy_restart's)
  std::vector<double> r;
  int version = VERSION;
  if (lmp->comm->me == 0) {
    int head[2];
    utils::sfread(FLERR, head, sizeof(int), 2, fp, nullptr, lmp->error);
    if (head[0] == RECORD_MARK && head[1] > 0 && head[1] < RECORD_VERSIONS) {
      version = head[1];
      int count = 0;
      utils::sfread(FLERR, &count, sizeof(int), 1, fp, nullptr, lmp->error);
      r.resize(count > 0 ? count : 0);
      utils::sfread(FLERR, r.data(), sizeof(double), r.size(), fp, nullptr, lmp->error);
    } else
      r = read_legacy_restart(lmp, fp, reinterpret_cast<const char *>(head)).record();
  }
  int count = r.size();
  MPI_Bcast(&version, 1, MPI_INT, 0, lmp->world);
  MPI_Bcast(&count, 1, MPI_INT, 0, lmp->world);
  r.resize(count);
  MPI_Bcast(r.data(), count, MPI_DOUBLE, 0, lmp->world);
  return from_record(lmp, version, r.data(), count);
}

// h, alpha, beta, sound, walls, gradient, wall stress, wall normal, each friction wall's
// group and mu, then -1 with precision mixed and -2 with hold stick (groups are >= 0)
PairSettings PairSettings::from_legacy_rates(const double *v, int count)
{
  PairSettings s;
  if (count < 8) return s;
  s.h = v[0];
  s.visc_alpha = v[1];
  s.visc_beta = v[2];
  s.visc_sound = static_cast<Viscosity::Sound>(static_cast<int>(v[3]));
  s.visc_walls = v[4] != 0.0;
  s.corrected_gradient = v[5] != 0.0;
  s.wall_stress = static_cast<WallSums::Mode>(static_cast<int>(v[6]));
  s.wall_normal = v[7] != 0.0;
  int k = 8;
  for (; k + 1 < count && v[k] >= 0.0 && s.nfriction < MAX_FRICTION_WALLS; k += 2)
    s.friction[s.nfriction++] = {static_cast<int>(v[k]), v[k + 1]};
  for (; k < count; ++k) {
    s.mixed_precision |= v[k] == -1.0;
    s.hold_stick |= v[k] == -2.0;
  }
  return s;
}

}    // namespace GRANSPH
