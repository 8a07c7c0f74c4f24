/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: the per-atom state that the integrator fix owns, and the contract
   through which the pair style, the computes and the other fixes read and write
   it: StateAccess, by name, on the host and on the device alike.

   Its layout, StateLayout, in one place for the code that reads columns:

   STATE is restarted and is the fix's per-atom output (f_ID[1] = rho,
   f_ID[2..7] = stress, f_ID[8] = GRANSPH::Regime); its first NCOMM columns are
   forward-communicated to ghosts. Restart files written before December 2026
   carry one more state column (STATE_WITH_VISC: the viscous pressure, now
   compute sph/visc/atom's).

   RATES: what the pair style writes (NEVALUATED_RATES columns, all the default
   allocates); from ACC on, only with predictor extrapolated: the acceleration of
   the same evaluation, the step whose mid-point they are, and from PREV the same
   for the step before.

   START: STEPPED, the number of steps, up to 2, whose evaluation the atom's rates
   (grains) or wall velocity (dummy particles) come from; then a grain's start of
   the step for the corrector, which between two steps holds from LAST_ACC the
   acceleration of the last evaluation that the next predictor uses (the start's
   velocity is then spent); or in the same columns a dummy particle's wall
   velocity of the last evaluation and WALL_F, the grains' force on it then (the
   pair style's part of its f), which the setup of a run that continues the last
   repeats. Older restart files hold both kinds' columns side by side
   (START_SIDE_BY_SIDE), or the acceleration in the rates also by default
   (RATES_WITH_ACC): FixSPHIntegrate::unpack_restart reads them.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_STATE_H
#define LMP_GRANSPH_STATE_H

#include "gransph_tensor.h"

namespace GRANSPH {

struct StateLayout {
  enum { RHO = 0, SIGMA = 1, REGIME = 7, NSTATE = 8, STATE_WITH_VISC = 9, NCOMM = 7 };
  enum { DRHO = 0, STRAIN = 1, SPIN = 7, ACC = 10, RATES_DT = 13, PREV = 14, NRATES = 28 };
  // a grain's start values (between steps LAST_ACC), and in the same columns a dummy
  // particle's (WALL_V, WALL_F); START_SIDE_BY_SIDE: the columns of the restart files
  // that held the two apart
  enum { STEPPED = 0, V_START = 1, RHO_START = 4, SIGMA_START = 5, NSTART = 11 };
  enum { LAST_ACC = 1, WALL_V = 1, WALL_F = 4, START_SIDE_BY_SIDE = 17 };
  // what a pair evaluation writes of an atom: a grain's rates before ACC (the rates'
  // columns by default; RATES_WITH_ACC: those of the restart files that held the
  // acceleration too); a dummy particle's stress and its wall history, STEPPED to WALL_F's
  // last
  enum { NEVALUATED_RATES = ACC, RATES_WITH_ACC = RATES_DT, NWALL_HISTORY = WALL_F + 3 - STEPPED };
};

// A per-atom array of STRIDE values per atom, as its rows from the first: atom i's column c
// lies at a multiple of its row, which a vector gather can take (host memory; marked for
// the device too, as the step's shared code that reads them is)
template <int STRIDE, class T = double> struct HostRows {
  T *first;
  KOKKOS_INLINE_FUNCTION T &operator()(int i, int c) const { return first[STRIDE * i + c]; }
};

// the same with a stride known at run time
struct HostRowsOf {
  double *first;
  int stride;
  KOKKOS_INLINE_FUNCTION double &operator()(int i, int c) const { return first[stride * i + c]; }
};

template <class Column> KOKKOS_INLINE_FUNCTION Sym3 sym3_at(const Column &col, int i, int c)
{
  return {col(i, c), col(i, c + 1), col(i, c + 2), col(i, c + 3), col(i, c + 4), col(i, c + 5)};
}

template <class Column>
KOKKOS_INLINE_FUNCTION void store_sym3(const Sym3 &s, const Column &col, int i, int c)
{
  col(i, c) = s.xx;
  col(i, c + 1) = s.yy;
  col(i, c + 2) = s.zz;
  col(i, c + 3) = s.xy;
  col(i, c + 4) = s.xz;
  col(i, c + 5) = s.yz;
}

// The per-atom state by name, over the integrator's three arrays, each callable as (i, c):
// HostRows on the host (FixSPHIntegrate::host_state), Kokkos views on a device
// (SPHStateKokkos::state_on)
template <class StateColumn, class RatesColumn = StateColumn, class StartColumn = StateColumn>
struct StateAccess {
  using L = StateLayout;
  StateColumn state;
  RatesColumn rates;
  StartColumn start;

  // grains and dummy particles
  KOKKOS_INLINE_FUNCTION double rho(int i) const { return state(i, L::RHO); }
  KOKKOS_INLINE_FUNCTION Sym3 sigma(int i) const { return sym3_at(state, i, L::SIGMA); }
  KOKKOS_INLINE_FUNCTION double regime(int i) const { return state(i, L::REGIME); }
  // a dummy particle's stress, extrapolated from the grains (eq. 8)
  KOKKOS_INLINE_FUNCTION void set_sigma(int i, const Sym3 &s) const { store_sym3(s, state, i, L::SIGMA); }
  // a grain's rates of the pair's evaluation (eqs. 6, 34, 35)
  KOKKOS_INLINE_FUNCTION void set_rates(int i, double drho, const Sym3 &d, const Spin3 &w) const
  {
    rates(i, L::DRHO) = drho;
    store_sym3(d, rates, i, L::STRAIN);
    rates(i, L::SPIN) = w.xy;
    rates(i, L::SPIN + 1) = w.xz;
    rates(i, L::SPIN + 2) = w.yz;
  }
  // a grain that joins within a step starts the step from where it is, at velocity v
  KOKKOS_INLINE_FUNCTION void start_step_here(int i, const double *v) const
  {
    for (int a = 0; a < 3; ++a) start(i, L::V_START + a) = v[a];
    start(i, L::RHO_START) = rho(i);
    store_sym3(sigma(i), start, i, L::SIGMA_START);
  }
  // a dummy particle's velocity at the last evaluation (3 values, kept by wall_gravity),
  // and the grains' force on it then (3 values, kept by keep_or_repeat_wall_force)
  KOKKOS_INLINE_FUNCTION double *last_wall_velocity(int i) const { return &start(i, L::WALL_V); }
  KOKKOS_INLINE_FUNCTION double *last_wall_force(int i) const { return &start(i, L::WALL_F); }
  // a dummy particle's history now comes from a step of the run
  KOKKOS_INLINE_FUNCTION void mark_stepped(int i) const { start(i, L::STEPPED) = 1.0; }
};

}    // namespace GRANSPH

#endif
