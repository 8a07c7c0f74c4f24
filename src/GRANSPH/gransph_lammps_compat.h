/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: the LAMMPS API differences the plain styles meet, in one place.

   GRANSPH_LAMMPS_VERSION is the version of the LAMMPS we are built against as
   YYYYMMDD; CMakeLists.txt reads it from that LAMMPS' src/version.h (LAMMPS has
   no numeric version macro of its own). Tested: 20210929 (29 Sep 2021, update 2)
   and 20260704 (4 Jul 2026). The API of versions in between is taken to be the
   newer one; they are not tested.

   gransph_kokkos_compat.h holds the Kokkos-side differences.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_LAMMPS_COMPAT_H
#define LMP_GRANSPH_LAMMPS_COMPAT_H

#include "comm.h"
#include "domain.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "region.h"

#ifndef GRANSPH_LAMMPS_VERSION
#error "GRANSPH_LAMMPS_VERSION (YYYYMMDD) is not defined: CMakeLists.txt defines it"
#endif

// 1 for the API of LAMMPS after the 29 Sep 2021 stable release: Comm::forward_comm(Fix *),
// Domain::get_region_by_id(), Neighbor::add_request() with protected NeighRequest fields
#define GRANSPH_LAMMPS_NEW_API (GRANSPH_LAMMPS_VERSION > 20211231)

namespace LAMMPS_NS {
namespace GRANSPHCompat {

  // forward communication of a fix's per-atom data to the ghosts
  inline void forward_comm_fix(Comm *comm, Fix *fix)
  {
#if GRANSPH_LAMMPS_NEW_API
    comm->forward_comm(fix);
#else
    comm->forward_comm_fix(fix);
#endif
  }

  // forward communication of a pair style's per-atom data to the ghosts
  inline void forward_comm_pair(Comm *comm, Pair *pair)
  {
#if GRANSPH_LAMMPS_NEW_API
    comm->forward_comm(pair);
#else
    comm->forward_comm_pair(pair);
#endif
  }

  // the region with this ID, or nullptr
  inline Region *find_region(Domain *domain, const char *id)
  {
#if GRANSPH_LAMMPS_NEW_API
    return domain->get_region_by_id(id);
#else
    const int i = domain->find_region(id);
    return i < 0 ? nullptr : domain->regions[i];
#endif
  }

  // a pair style's full neighbour list
  inline void request_full_list(Neighbor *neighbor, Pair *pair, int instance_me)
  {
#if GRANSPH_LAMMPS_NEW_API
    neighbor->add_request(pair, NeighConst::REQ_FULL);
    (void) instance_me;
#else
    const int irequest = neighbor->request(pair, instance_me);
    neighbor->requests[irequest]->half = 0;
    neighbor->requests[irequest]->full = 1;
#endif
  }

}    // namespace GRANSPHCompat
}    // namespace LAMMPS_NS

#endif
