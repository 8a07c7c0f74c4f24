/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: what pair_style sph/granular does for one particle in each pass of
   an evaluation, written once for the plain style's loops and its Kokkos twin's
   kernels: the particle's pair data, a dummy particle's stress (eq. 8) and the
   grains' force on it (eq. 9), a grain's rates (eqs. 6, 7, 34, 35).

   `Particles` is an accessor of gransph_neighbour_sums.h (both twins make a
   ParticlesOf), `State` a GRANSPH::StateAccess (gransph_state.h), `Forces`
   LAMMPS' forces callable as f(i, a).
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_PAIR_PASSES_H
#define LMP_GRANSPH_PAIR_PASSES_H

#include "gransph_materials.h"
#include "gransph_neighbour_sums.h"
#include "gransph_pair_settings.h"
#include "gransph_state.h"

namespace GRANSPH {

// element i of a per-atom array: a pointer's (the plain style) or a Kokkos view's
template <class T> KOKKOS_INLINE_FUNCTION T &element(T *a, int i)
{
  return a[i];
}
template <class View>
KOKKOS_INLINE_FUNCTION auto element(const View &a, int i) -> decltype(a(i))
{
  return a(i);
}

// The accessor of the neighbour sums (gransph_neighbour_sums.h) that both twins make: the
// settings; the atoms as Atoms holds them, with row(i) particle i's row of neighbours and
// the per-atom arrays numneigh, mask, normals, friction_mu and friction_slide (pointers or
// views) beside the role bits granularbit and wallbit, and with rows pruned grains first
// (grains_first) numgrains; and the particles' records, of
// Particle: PairParticle, or PairParticleSingle for the grains' sums under `precision
// mixed`.
template <class Atoms, class Particle, class Records> struct ParticlesOf : SumOptions, Atoms {
  using Real = decltype(Particle::rho);
  Records particles;

  ParticlesOf(const SumOptions &options, const Atoms &atoms, const Records &particles) :
      SumOptions(options), Atoms(atoms), particles(particles)
  {
  }

  KOKKOS_INLINE_FUNCTION int num_neighbours(int i) const { return element(this->numneigh, i); }
  // of a row pruned grains first (GRANSPH::prune_row): its grains, at its front
  KOKKOS_INLINE_FUNCTION int num_grain_neighbours(int i) const
  {
    return element(this->numgrains, i);
  }
  KOKKOS_INLINE_FUNCTION auto neighbours(int i) const { return this->row(i); }
  KOKKOS_INLINE_FUNCTION const Particle &particle(int i) const { return element(particles, i); }
  KOKKOS_INLINE_FUNCTION bool granular(int i) const
  {
    return element(this->mask, i) & this->granularbit;
  }
  KOKKOS_INLINE_FUNCTION bool wall(int i) const { return element(this->mask, i) & this->wallbit; }
  KOKKOS_INLINE_FUNCTION double normal(int i, int a) const
  {
    return element(this->normals, 3 * i + a);
  }
  KOKKOS_INLINE_FUNCTION double friction(int i) const { return element(this->friction_mu, i); }
  KOKKOS_INLINE_FUNCTION double slide(int i, int k) const
  {
    return element(this->friction_slide, SLIDE_VALUES * i + k);
  }

  // the same atoms and settings over `single`, the particles in single precision
  template <class Single>
  ParticlesOf<Atoms, PairParticleSingle, Single> in_single(const Single &single) const
  {
    return {*this, *this, single};
  }
};

// The pair data of atom i with group bits `mask`: a grain's or a dummy particle's (in
// sphbits), with the sound speed of its material (a dummy particle's: the integrator's
// own), or, for an atom that is neither, a massless one (the neighbour sums read it, and
// add nothing from it)
template <class State>
KOKKOS_INLINE_FUNCTION PairParticle pair_particle(int mask, int sphbits, const State &state,
                                                  int i, const double *x, const double *v,
                                                  double mass, const Viscosity &visc,
                                                  const MaterialTable &materials)
{
  if (!(mask & sphbits)) return PairParticle::make(x, v, 0.0, 1.0, Sym3::zero(), 0.0);
  const double rho = state.rho(i);
  return PairParticle::make(x, v, mass, rho, state.sigma(i),
                            materials.viscosity_sound(visc, materials.of(mask), rho));
}

// A grain's spacing as its volume m / rho0 gives it, in dim dimensions
KOKKOS_INLINE_FUNCTION double grain_spacing(double mass, double rho0, int dim)
{
  return dim == 2 ? sqrt(mass / rho0) : cbrt(mass / rho0);
}

// Dummy particle d's stress (eq. 8) from its grains, into sigma and the state, with the
// wall's acceleration from d's velocity v_d since the last evaluation (wall_gravity;
// inv_dt 0 at a run's setup, which keeps that history as it is). Returns the sums.
template <class Particles, class State>
KOKKOS_INLINE_FUNCTION WallSums dummy_stress(const Particles &p, const State &state, int d,
                                             const double *v_d, const double *g, double inv_dt,
                                             WallSums::Mode mode, Sym3 &sigma)
{
  double g_minus_a[3];
  wall_gravity(g, v_d, state.last_wall_velocity(d), inv_dt, g_minus_a);
  if (inv_dt > 0.0) state.mark_stepped(d);
  const WallSums sums = wall_sums(p, d);
  sigma = sums.stress(g_minus_a, mode);
  state.set_sigma(d, sigma);
  return sums;
}

// The force of the grains on dummy particle d (eq. 9; none without granular neighbours),
// or at the setup of a run that continues the last (repeat) the last step's, added to f;
// its virial into vir (if not null)
template <class Particles, class State, class Forces>
KOKKOS_INLINE_FUNCTION void add_dummy_force(const Particles &p, int d, bool has_grains,
                                            const State &state, const Forces &f, double ftm2v,
                                            bool repeat, double *vir)
{
  double fd[3] = {0.0, 0.0, 0.0};
  if (has_grains) wall_force(p, d, fd, vir);
  keep_or_repeat_wall_force(fd, state.last_wall_force(d), repeat);
  for (int a = 0; a < 3; ++a) f(d, a) += fd[a] / ftm2v;
}

// Grain i's rates into the state and its mass times its acceleration into f; its virial
// into vir and how it slides on walls with a friction of their own into slide (each if
// not null). corrected: the renormalised velocity gradient (in dim dimensions). Sums: the
// variant of the neighbour sums (SumVariant, chosen once per pass: with_sum_variant)
template <class Sums, class Particles, class State, class Forces>
KOKKOS_INLINE_FUNCTION void add_grain_rates(const Particles &p, int i, double mass,
                                            const State &state, const Forces &f, double ftm2v,
                                            bool corrected, int dim, double *vir, double *slide)
{
  ParticleRates r = Sums::rates(p, i, vir, slide);
  for (int a = 0; a < 3; ++a) f(i, a) += mass * r.acc[a] / ftm2v;
  if (corrected) r.correct_gradient(dim);
  state.set_rates(i, r.drho, r.strain(), r.spin());
}

}    // namespace GRANSPH

#endif
