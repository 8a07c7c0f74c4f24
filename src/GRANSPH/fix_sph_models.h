/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: the granular SPH integrators of the two models, fix sph/elastoplastic
   (Drucker-Prager) and fix sph/phasechange (Dunatunga & Kamrin 2015).
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_MODELS_H
#define LMP_FIX_SPH_MODELS_H

#include "fix_sph_model.h"
#include "gransph_drucker_prager.h"
#include "gransph_phase_change.h"

namespace LAMMPS_NS {

// its update returns early for disconnected and elastic grains: a scalar loop is faster
// (the jet collision's step, 1.3x; bench/README.md, fifth round)
template <> struct VectorisedStep<GRANSPH::PhaseChange> {
  static constexpr bool value = false;
};

using FixSPHElastoplastic = FixSPHModel<GRANSPH::DruckerPrager>;
using FixSPHPhaseChange = FixSPHModel<GRANSPH::PhaseChange>;
// each instantiated once, in its own small unit (fix_sph_elastoplastic.cpp,
// fix_sph_phasechange.cpp), in which the compiler inlines the model into the step's loop
// and vectorises it
extern template class FixSPHModel<GRANSPH::DruckerPrager>;
extern template class FixSPHModel<GRANSPH::PhaseChange>;

}    // namespace LAMMPS_NS

#endif
