/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: granular SPH integrator with the phase-change model of
   Dunatunga & Kamrin (2015).
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_PHASECHANGE_H
#define LMP_FIX_SPH_PHASECHANGE_H

#include "fix_sph_model.h"
#include "gransph_phase_change.h"

namespace LAMMPS_NS {

// its update returns early for disconnected and elastic grains: a scalar loop is faster
// (the jet collision's step, 1.3x; bench/README.md, fifth round)
template <> struct VectorisedStep<GRANSPH::PhaseChange> {
  static constexpr bool value = false;
};
using FixSPHPhaseChange = FixSPHModel<GRANSPH::PhaseChange>;
// instantiated once, in fix_sph_phasechange.cpp: a small unit, in which the compiler inlines the
// model into the step's loop and vectorises it
extern template class FixSPHModel<GRANSPH::PhaseChange>;

}    // namespace LAMMPS_NS

#endif
