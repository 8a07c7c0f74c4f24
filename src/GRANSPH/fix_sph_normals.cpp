/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: fix sph/normals, the dummy particles' own wall normals.
------------------------------------------------------------------------- */

#include "fix_sph_normals.h"

#include "gransph_find_fix.h"
#include "gransph_lammps_compat.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "tokenizer.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
// rows of a WallNormals section (ID nx ny nz) sent to every rank at a time
constexpr int CHUNK = 8192;
constexpr int ROW = 4;
}    // namespace

/* ----------------------------------------------------------------------
   fix ID group sph/normals [file FILE] [set GROUP nx ny nz] ...
------------------------------------------------------------------------- */

FixSPHNormals::FixSPHNormals(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), normals(nullptr)
{
  peratom_flag = 1;
  size_peratom_cols = 3;
  peratom_freq = 1;
  restart_peratom = 1;
  comm_forward = 3;
  create_attribute = 1;    // atoms created later start without a normal (set_arrays)
  // under Kokkos the atoms' own arrays stay where they are: this fix reads none of them
  datamask_read = datamask_modify = 0;

  grow_arrays(atom->nmax);
  for (int i = 0; i < atom->nmax; ++i) set_arrays(i);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);

  for (int iarg = 3; iarg < narg;) {
    if (strcmp(arg[iarg], "file") == 0) {
      if (iarg + 2 > narg) error->all(FLERR, "Fix sph/normals: keyword file needs a file name");
      read_file(arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "set") == 0) {
      if (iarg + 5 > narg)
        error->all(FLERR, "Fix sph/normals: keyword set needs a group ID and nx ny nz");
      double n[3];
      for (int a = 0; a < 3; ++a) n[a] = utils::numeric(FLERR, arg[iarg + 2 + a], false, lmp);
      set_group(arg[iarg + 1], n);
      iarg += 5;
    } else {
      error->all(FLERR, "Fix sph/normals: unknown keyword {} (valid: file, set)", arg[iarg]);
    }
  }
}

FixSPHNormals::~FixSPHNormals()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(normals);
}

const FixSPHNormals *FixSPHNormals::find(LAMMPS *lmp, const std::string &who)
{
  return GRANSPH::find_only_fix<const FixSPHNormals>(lmp, who,
                                                     "wall-normal fixes (sph/normals)");
}

int FixSPHNormals::setmask()
{
  return PRE_NEIGHBOR;
}

// the ghosts of a new neighbour list get their atoms' normals
void FixSPHNormals::setup_pre_neighbor()
{
  GRANSPHCompat::forward_comm_fix(comm, this);
}

void FixSPHNormals::pre_neighbor()
{
  GRANSPHCompat::forward_comm_fix(comm, this);
}

// Every atom of group_id (and of the fix's group) gets the normal n
void FixSPHNormals::set_group(const char *group_id, const double *n)
{
  const int igroup = group->find(group_id);
  if (igroup < 0) error->all(FLERR, "Fix sph/normals: group {} (keyword set) does not exist", group_id);
  if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0)
    error->all(FLERR, "Fix sph/normals: the normal of group {} must not be zero", group_id);
  const int bits = group->bitmask[igroup] | groupbit;
  bigint mine = 0, count = 0;
  for (int i = 0; i < atom->nlocal; ++i)
    if ((atom->mask[i] & bits) == bits) {
      for (int a = 0; a < 3; ++a) normals[i][a] = n[a];
      ++mine;
    }
  MPI_Allreduce(&mine, &count, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0)
    utils::logmesg(lmp, "Fix sph/normals: {} wall normals ({} {} {}) for group {}\n", count,
                   n[0], n[1], n[2], group_id);
}

// The WallNormals section of a LAMMPS data file (lines "ID nx ny nz" after a line
// "WallNormals", to the next section or the end): rank 0 reads it and sends it on in
// chunks, each rank keeps its atoms' rows. Every ID must be an atom of the fix's group.
void FixSPHNormals::read_file(const char *path)
{
  const bool temporary_map = atom->map_style == Atom::MAP_NONE;
  if (temporary_map) {
    atom->map_init();
    atom->map_set();
  }
  FILE *fp = nullptr;
  int line = 0;
  if (comm->me == 0) {
    fp = fopen(path, "r");
    if (!fp) error->one(FLERR, "Fix sph/normals: cannot open file {}: {}", path, strerror(errno));
    char text[1024];
    bool found = false;
    while (!found && fgets(text, sizeof(text), fp)) {
      ++line;
      found = utils::trim(utils::trim_comment(text)) == "WallNormals";
    }
    if (!found) error->one(FLERR, "Fix sph/normals: file {} has no WallNormals section", path);
  }

  std::vector<double> rows(ROW * CHUNK);
  bigint nrows = 0, mine = 0;
  for (int n = CHUNK; n == CHUNK;) {    // to a chunk that is not full
    n = 0;
    if (comm->me == 0) {
      char text[1024];
      while (n < CHUNK && fgets(text, sizeof(text), fp)) {
        ++line;
        const std::string row = utils::trim(utils::trim_comment(text));
        const std::vector<std::string> words = utils::split_words(row);
        if (words.empty()) continue;
        if (!utils::is_integer(words[0])) break;    // the next section
        const auto malformed = [&]() {
          error->one(FLERR, "Fix sph/normals: {}:{}: {} (expected ID nx ny nz)", path, line, row);
        };
        if (words.size() != ROW) malformed();
        try {
          ValueTokenizer values(row);
          const tagint tag = values.next_tagint();
          if (tag <= 0 || tag > atom->map_tag_max)
            error->one(FLERR, "Fix sph/normals: {}:{}: no atom has ID {}", path, line, tag);
          rows[ROW * n] = (double) tag;
          for (int a = 1; a < ROW; ++a) rows[ROW * n + a] = values.next_double();
          for (int a = 1; a < ROW; ++a)
            if (!std::isfinite(rows[ROW * n + a])) malformed();
        } catch (TokenizerException &) {
          malformed();
        }
        ++n;
      }
    }
    MPI_Bcast(&n, 1, MPI_INT, 0, world);
    MPI_Bcast(rows.data(), ROW * n, MPI_DOUBLE, 0, world);
    nrows += n;
    for (int k = 0; k < n; ++k) {
      const int i = atom->map((tagint) rows[ROW * k]);
      if (i < 0 || i >= atom->nlocal) continue;
      if (!(atom->mask[i] & groupbit))
        error->one(FLERR,
                   "Fix sph/normals: atom {} of file {} is not in group {} (was the file read "
                   "with an ID offset?)",
                   atom->tag[i], path, group->names[igroup]);
      for (int a = 0; a < 3; ++a) normals[i][a] = rows[ROW * k + 1 + a];
      ++mine;
    }
  }
  if (fp) fclose(fp);
  if (temporary_map) {    // as LAMMPS' fix property/atom leaves it
    atom->map_delete();
    atom->map_style = Atom::MAP_NONE;
  }

  bigint found = 0;
  MPI_Allreduce(&mine, &found, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (found != nrows)
    error->all(FLERR, "Fix sph/normals: {} of the {} atom IDs in WallNormals of {} belong to no atom",
               nrows - found, nrows, path);
  if (comm->me == 0) utils::logmesg(lmp, "Fix sph/normals: {} wall normals from {}\n", nrows, path);
  warn_if_periodic(path);
}

// A terrain in a box that is periodic across it continues on the other side (grains
// that leave one end meet the terrain's other end): a warning, since a periodic terrain
// (an infinite slope) is legitimate
void FixSPHNormals::warn_if_periodic(const char *path) const
{
  std::string across;
  for (int d = 0; d < domain->dimension; ++d)
    if (domain->periodicity[d]) across += std::string(across.empty() ? "" : " and ") + "xyz"[d];
  if (!across.empty() && comm->me == 0)
    error->warning(FLERR,
                   "Fix sph/normals: the box is periodic in {}: the terrain of {} continues "
                   "across that boundary; use boundary f (or s) there unless the terrain is "
                   "itself periodic",
                   across, path);
}

/* ----------------------------------------------------------------------
   per-atom arrays: they move with the atoms and survive restarts
------------------------------------------------------------------------- */

void FixSPHNormals::grow_arrays(int nmax)
{
  memory->grow(normals, nmax, 3, "sph/normals:normals");
  array_atom = normals;
}

void FixSPHNormals::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int a = 0; a < 3; ++a) normals[j][a] = normals[i][a];
}

// atoms created after the fix have no normal
void FixSPHNormals::set_arrays(int i)
{
  for (int a = 0; a < 3; ++a) normals[i][a] = 0.0;
}

int FixSPHNormals::pack_exchange(int i, double *buf)
{
  for (int a = 0; a < 3; ++a) buf[a] = normals[i][a];
  return 3;
}

int FixSPHNormals::unpack_exchange(int nlocal, double *buf)
{
  for (int a = 0; a < 3; ++a) normals[nlocal][a] = buf[a];
  return 3;
}

int FixSPHNormals::pack_restart(int i, double *buf)
{
  buf[0] = 4;
  return 1 + pack_exchange(i, buf + 1);
}

void FixSPHNormals::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  unpack_exchange(nlocal, &extra[nlocal][m + 1]);
}

int FixSPHNormals::size_restart(int /*nlocal*/)
{
  return 4;
}

int FixSPHNormals::maxsize_restart()
{
  return 4;
}

int FixSPHNormals::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  for (int k = 0; k < n; ++k) pack_exchange(list[k], buf + 3 * k);
  return 3 * n;
}

void FixSPHNormals::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; ++k) unpack_exchange(first + k, buf + 3 * k);
}

double FixSPHNormals::memory_usage()
{
  return (double) atom->nmax * 3 * sizeof(double);
}
