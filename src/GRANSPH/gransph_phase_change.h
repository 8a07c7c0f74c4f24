/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: phase-change granular model of Dunatunga & Kamrin (JFM 2015) as used
   by Chen et al. (2019), eqs. 22-28: elastic "solid" below the static yield
   stress mu_s p, mu(I)-rheology plastic flow above it, stress-free
   ("disconnected") below the critical density rho_c or under tension.

   The rate term. Chen et al. print alpha = xi G dt p_tr, which has units Pa^(3/2).
   With mu(I) = mu_s + (mu_2 - mu_s) I / (I0 + I), I = gamma_dot d sqrt(rho_s / p)
   and the plastic shear rate gamma_dot = (tau_tr - tau) / (G dt) of the
   elastic predictor, tau = mu(I) p gives exactly tau^2 - B tau + H = 0 (eq. 26)
   with alpha = xi G dt sqrt(p_tr) and xi = I0 / (d sqrt(rho_s)) (Dunatunga &
   Kamrin's definition; Table 2's xi = 1.1233 is I0 = 0.278, d = 5 mm,
   rho_s = 2450). That dimensionally consistent form is used here.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_PHASE_CHANGE_H
#define LMP_GRANSPH_PHASE_CHANGE_H

#include "gransph_stress_model.h"

namespace GRANSPH {

struct PhaseChange {
  double K, G;        // bulk and shear moduli, eqs. 24-25
  double rho_c;       // critical density
  double xi;          // I0 / (d sqrt(rho_s))
  double mu_s, mu_2;  // static and limiting friction coefficients

  KOKKOS_INLINE_FUNCTION static PhaseChange from_material(double E, double nu, double rho_c,
                                                          double xi, double mu_s, double mu_2)
  {
    return {E / (3.0 * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu)), rho_c, xi, mu_s, mu_2};
  }

  // from a material record with E, nu, rho_c, xi, mu_s, mu_2 (host)
  template <class Material> static PhaseChange from(const Material &m)
  {
    return from_material(m.E, m.nu, m.rho_c, m.xi, m.mu_s, m.mu_2);
  }

  // The friction coefficient at which a layer starts to slide: the static one
  double slide_friction() const { return mu_s; }

  // Shear stress over the static yield stress, tau / (mu_s p): below 1 in the solid, 1 at
  // yield, mu(I) / mu_s when flowing. A stress-free (disconnected) state has no strength
  // left to mobilise: 1.
  KOKKOS_INLINE_FUNCTION double mobilised_ratio(const Sym3 &s) const
  {
    const double strength = -mu_s * s.trace() / 3.0;
    return strength > 0.0 ? sqrt(second_invariant(s)) / strength : 1.0;
  }

  // Shear stress after a plastic step: the smaller root of eq. 26 in the
  // cancellation-free form of eq. 27; tau_tr > mu_s p_tr and mu_2 >= mu_s keep
  // the discriminant non-negative, the clamp only absorbs round-off.
  KOKKOS_INLINE_FUNCTION double flow_stress(double tau_tr, double p_tr, double dt) const
  {
    const double s0 = mu_s * p_tr;
    const double s2 = mu_2 * p_tr;
    const double alpha = xi * G * dt * sqrt(p_tr);
    const double b = s2 + tau_tr + alpha;
    const double h = s2 * tau_tr + s0 * alpha;
    const double disc = b * b - 4.0 * h;
    return 2.0 * h / (b + sqrt(disc > 0.0 ? disc : 0.0));
  }

  // The stress-model interface of gransph_stress_model.h.
  KOKKOS_INLINE_FUNCTION Sym3 update(const Sym3 &s0, const Sym3 &s, const Sym3 &d,
                                     const Spin3 &w, double rho, double dt,
                                     Regime &regime) const
  {
    regime = DISCONNECTED;
    if (rho < rho_c) return Sym3::zero();                          // step 1
    const Sym3 trial = jaumann_trial(s0, s, d, w, K, G, dt);      // eq. 23
    const double p_tr = -trial.trace() / 3.0;
    if (p_tr <= 0.0) return Sym3::zero();                          // step 2
    const Sym3 dev = trial.deviator();
    const double tau_tr = sqrt(0.5 * dev.ddot(dev));
    if (tau_tr <= mu_s * p_tr) {                                   // step 3, elastic
      regime = ELASTIC;
      return trial;
    }
    regime = PLASTIC;
    const double tau = flow_stress(tau_tr, p_tr, dt);               // eqs. 26-27
    return (tau / tau_tr) * dev - Sym3::iso(p_tr);                 // eq. 28
  }
};

}    // namespace GRANSPH

#endif
