/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: every setting of pair_style sph/granular in one value type.

   PairSettings is parsed from its defaults each time the style is issued (a
   re-issued pair_style inherits nothing), compared with == (what the rates depend
   on: same_rates), and written to restart files as one versioned record. The
   neighbour sums read the part they need as one SumOptions value, made from the
   settings once per evaluation and embedded whole in the host and device
   accessors (trivially copyable: a device copy is one struct).
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_PAIR_SETTINGS_H
#define LMP_GRANSPH_PAIR_SETTINGS_H

#include "gransph_kernel.h"
#include "gransph_pair_terms.h"

#include <cstdio>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace GRANSPH {

struct PairSettings {
  static constexpr int MAX_FRICTION_WALLS = 32;    // LAMMPS' number of groups
  // defaults: viscosity from the convergence study (doc/pair_sph_granular.rst), prune by
  // measurement (bench/README.md)
  double h = 0.0;                                          // smoothing length; support 2h
  double visc_alpha = 0.25, visc_beta = 0.0;               // eq. 7
  Viscosity::Sound visc_sound = Viscosity::BULK;           // visc/sound
  bool visc_walls = false;                                 // visc/walls
  bool corrected_gradient = false;                         // gradient corrected
  bool wall_normal = false;                                // wall/gradient normal
  WallSums::Mode wall_stress = WallSums::RATIO;            // wall/stress, eq. 8
  bool mixed_precision = false;                            // precision mixed
  bool hold_stick = false;                                 // wall/friction/hold stick
  double prune = 0.03;                                     // prune margin in h
  int nfriction = 0;                                       // wall/friction entries, in order:
  FrictionWall friction[MAX_FRICTION_WALLS] = {};          // the last that holds a dummy counts

  // pair_style sph/granular h keyword value ... (doc/pair_sph_granular.rst), from the
  // defaults; stops with an error naming the keyword for bad input
  static PairSettings parse(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);

  bool operator==(const PairSettings &o) const { return record() == o.record(); }
  // whether the rates of an evaluation are the same under both (prune changes only which
  // neighbours outside the support the sums visit)
  bool same_rates(const PairSettings &o) const;

  // The restart record: VERSION and the values, as doubles (exact for the whole numbers).
  // from_record() stops with an error that names a version it does not know.
  static constexpr int VERSION = 1;
  std::vector<double> record() const;
  static PairSettings from_record(LAMMPS_NS::LAMMPS *lmp, int version, const double *values,
                                  int count);
  // Collective: the record in a pair style's restart section (write: rank 0's file), and
  // back, also from files written before the record (read_legacy_restart)
  void write_restart(FILE *fp) const;
  static PairSettings read_restart(LAMMPS_NS::LAMMPS *lmp, FILE *fp);
  // the rate settings a fix's restart data held before the record (a list of doubles)
  static PairSettings from_legacy_rates(const double *values, int count);

  bool has_friction_walls() const { return nfriction > 0; }

 private:
  // f(value) for each setting but the friction walls' in the record's order, the count of
  // friction walls last: the one list of the settings that the record and == go by
  template <class Settings, class F> static void values_of(Settings &s, F &&f)
  {
    f(s.h);
    f(s.visc_alpha);
    f(s.visc_beta);
    f(s.visc_sound);
    f(s.visc_walls);
    f(s.corrected_gradient);
    f(s.wall_normal);
    f(s.wall_stress);
    f(s.mixed_precision);
    f(s.hold_stick);
    f(s.prune);
    f(s.nfriction);
  }
};

// What the neighbour sums of one evaluation read besides the particles (see
// gransph_neighbour_sums.h): the settings as the sums use them
struct SumOptions {
  WendlandC2 kernel;
  Viscosity visc;
  bool wall_normal;      // dummy neighbours enter drho and grad_v along their normal
  bool shape_sums;       // the shape matrix of the corrected gradient
  bool wall_friction;    // walls with a friction of their own (and dummy walls)
  WallStick stick;       // with wall_friction: how the walls hold a grain
};

}    // namespace GRANSPH

#endif
