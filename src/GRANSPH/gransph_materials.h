/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: the materials of a run, as the per-particle code reads them on the
   host and on a device. The integrator fix's grains are of its own material
   (index 0) unless they are in the group of one of its `material` keywords
   (index 1, 2, ... in their order): a grain's material follows from its group
   bits, which LAMMPS carries with the atom to other ranks, to ghosts and into
   restart files, so the table needs no per-atom storage of its own.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_MATERIALS_H
#define LMP_GRANSPH_MATERIALS_H

#include "gransph_pair_terms.h"

namespace GRANSPH {

struct MaterialTable {
  static constexpr int MAX = 16;
  int n = 1;
  int bits[MAX] = {0};    // the group bit of material k (none for the fix's own, k = 0)
  int any_bits = 0;       // those of every material group
  double E[MAX] = {0.0};
  double c0[MAX] = {0.0};          // sqrt(K / rho0): the viscosity's visc/sound bulk
  double rho0[MAX] = {0.0};        // reference density, of a grain's volume m / rho0
  double rho_init[MAX] = {0.0};    // density of a new grain (fix keyword rho: the fix's own)
  double slide_friction[MAX] = {0.0};    // the model's, for wall/friction GROUP material

  // the material of a grain (of the fix group) with group bits `mask`
  KOKKOS_INLINE_FUNCTION int of(int mask) const
  {
    for (int k = 1; k < n; ++k)
      if (mask & bits[k]) return k;
    return 0;
  }
  // whether a grain with group bits `mask` is of material k (one material claims it)
  KOKKOS_INLINE_FUNCTION bool holds(int k, int mask) const
  {
    return (mask & any_bits) == bits[k];
  }
  // the sound speed of the artificial viscosity of a particle of material k at density rho
  KOKKOS_INLINE_FUNCTION double viscosity_sound(const Viscosity &visc, int k, double rho) const
  {
    return visc.sound == Viscosity::BULK ? c0[k] : sound_speed(E[k], rho);
  }
};

}    // namespace GRANSPH

#endif
