/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: what every constitutive model provides.

   A model is a small value type with

     Sym3 update(const Sym3 &s0, const Sym3 &s, const Sym3 &d, const Spin3 &w,
                 double rho, double dt, Regime &regime) const;

   the stress after a step of length dt from s0, with the Jaumann rotation and
   the flow direction evaluated at s, for strain rate d, spin w and density rho;
   it also says in which regime the particle ended the step. The integrator
   fixes and their Kokkos twins call it per particle. And

     double mobilised_ratio(const Sym3 &s) const;

   the share of the model's strength that the stress s uses, 1 at yield (compute
   sph/stress/atom).

   A host loop over the particles calls f(variant) through with_run_variant(model, f),
   where variant is the model itself, or a type that fixes a choice the model makes per
   run (DruckerPrager's plastic treatment), so that the loop has no branch on it.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_STRESS_MODEL_H
#define LMP_GRANSPH_STRESS_MODEL_H

#include "gransph_tensor.h"

namespace GRANSPH {

// Per-particle state of the material after a stress update (a per-atom output).
enum Regime {
  ELASTIC = 0,        // elastic, "solid" (phase change); inside the yield surface
  PLASTIC = 1,        // on the yield surface, flowing
  DISCONNECTED = 2    // stress-free: below rho_c or in tension (phase change), or
                      // cut off at the apex of the Drucker-Prager cone
};

template <class Model, class F> void with_run_variant(const Model &model, F &&f)
{
  f(model);
}

}    // namespace GRANSPH

#endif
