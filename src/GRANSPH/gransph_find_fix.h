/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANSPH: host helpers the styles share: the one fix of a kind that other
   styles look up, and questions to all ranks.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_FIND_FIX_H
#define LMP_GRANSPH_FIND_FIX_H

#include "atom.h"
#include "error.h"
#include "lammps.h"
#include "modify.h"

#include <string>

namespace GRANSPH {

  // The fix of class FixClass, or nullptr if there is none; an error that names `who`
  // (the style looking) and both fixes if there are two, `kind` saying what they are
  template <class FixClass>
  FixClass *find_only_fix(LAMMPS_NS::LAMMPS *lmp, const std::string &who, const char *kind)
  {
    FixClass *found = nullptr;
    for (int i = 0; i < lmp->modify->nfix; ++i)
      if (auto fix = dynamic_cast<FixClass *>(lmp->modify->fix[i])) {
        if (found)
          lmp->error->all(FLERR, "{}: fixes {} and {} are both {}; only one may be defined", who,
                          found->id, fix->id, kind);
        found = fix;
      }
    return found;
  }

  // Collective: whether `mine` holds on any rank
  inline bool any_rank(MPI_Comm world, bool mine)
  {
    int local = mine, any = 0;
    MPI_Allreduce(&local, &any, 1, MPI_INT, MPI_MAX, world);
    return any;
  }

  // Collective: whether holds(i) for any owned atom i on any rank
  template <class Predicate> bool any_owned_atom(LAMMPS_NS::LAMMPS *lmp, Predicate holds)
  {
    bool mine = false;
    for (int i = 0; i < lmp->atom->nlocal && !mine; ++i) mine = holds(i);
    return any_rank(lmp->world, mine);
  }

}    // namespace GRANSPH

#endif
