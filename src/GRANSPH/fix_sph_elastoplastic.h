/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: granular SPH integrator with the elastoplastic Drucker-Prager model.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_ELASTOPLASTIC_H
#define LMP_FIX_SPH_ELASTOPLASTIC_H

#include "fix_sph_model.h"
#include "gransph_drucker_prager.h"

namespace LAMMPS_NS {

using FixSPHElastoplastic = FixSPHModel<GRANSPH::DruckerPrager>;
// instantiated once, in fix_sph_elastoplastic.cpp: a small unit, in which the compiler inlines the
// model into the step's loop and vectorises it
extern template class FixSPHModel<GRANSPH::DruckerPrager>;

}    // namespace LAMMPS_NS

#endif
