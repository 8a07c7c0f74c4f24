/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: fix sph/normals, the owner of the dummy particles' own wall normals.

   Each atom of its group may carry an outward wall normal: read from the
   WallNormals section of a data file (tools/terrain writes one) or set for a
   group. The normals move with their atoms, reach the ghosts at each neighbour
   list build and survive restart files. pair_style sph/granular reads them
   (wall/gradient normal, wall/friction); a dummy without one has none.

   A fix of its own rather than fix property/atom: LAMMPS 29Sep2021's KOKKOS
   package crashes reading a data file's section into fix property/atom and
   passing its arrays to ghosts, while a fix's own per-atom arrays are carried
   by every LAMMPS version, plain and Kokkos alike.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_NORMALS_H
#define LMP_FIX_SPH_NORMALS_H

#include "fix.h"

#include <string>

namespace LAMMPS_NS {

class FixSPHNormals : public Fix {
 public:
  FixSPHNormals(class LAMMPS *, int, char **);
  // The fix sph/normals, or nullptr if there is none; an error that names `who` if
  // there are several
  static const FixSPHNormals *find(class LAMMPS *lmp, const std::string &who);
  ~FixSPHNormals() override;
  int setmask() override;
  void setup_pre_neighbor() override;
  void pre_neighbor() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

  // atom i's normal as given (not made a unit vector), zeros for none; ghosts too
  const double *normal(int i) const { return normals[i]; }

 private:
  double **normals;

  void read_file(const char *path);
  void set_group(const char *group_id, const double *n);
  void warn_if_periodic(const char *path) const;
};

}    // namespace LAMMPS_NS

#endif
