/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: elastic-perfectly plastic Drucker-Prager stress update with the
   Jaumann rate (paper eqs. 29-33; Bui, Fukagawa, Sako & Ohno 2008).
   Stress is tension positive, so the yield function reads
       f = sqrt(J2) + alpha_phi I1 - k_c
   (the paper prints the compression-positive form). Usable on host and device.

   Two ways to take a step (fix sph/elastoplastic keyword plastic):
   - return mapping (default): the elastic trial, then the implicit (backward Euler)
     return along eq. 32's plastic flow, which lands on the yield surface whatever the
     size of the step;
   - the paper's: eq. 32 with the plastic rate of eq. 33 evaluated at the step's start,
     then Bui's scaling of states left outside the cone. With the time steps of SPH the
     elastic increment of one step can be many times the strength (a layer sliding on
     the floor at 1 m/s, dx = 0.01 m: 2 G gamma_dot dt = 10 kPa against 0.1 kPa), and a
     dilating step (tr d > 0) then makes the explicit plastic correction overshoot into
     the cone: a thin sliding layer holds a fraction of its strength
     (validation/basal_friction/basal_friction.md).
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_DRUCKER_PRAGER_H
#define LMP_GRANSPH_DRUCKER_PRAGER_H

#include "gransph_stress_model.h"

namespace GRANSPH {

struct DruckerPrager {
  double K, G;          // bulk and shear moduli, eqs. 24-25
  double alpha_phi;     // eq. 30
  double k_c;           // eq. 31
  double sin_psi;       // dilatancy angle
  bool explicit_rate;   // the paper's explicit plastic rate instead of the return mapping

  // alpha_phi and k_c from friction angle phi and dilatancy psi (radians) and cohesion c:
  // Bui et al.'s plane-strain matching (eqs. 30-31, the paper's), under which a layer in
  // simple shear yields at tan(theta) = 3 alpha_phi (29.6 deg for phi = 37 deg), or the
  // matching whose simple-shear strength is c + tan(phi) sigma_n (with psi = 0 the flow
  // is coaxial and deviatoric, so the normal stresses are equal in steady simple shear).
  KOKKOS_INLINE_FUNCTION static DruckerPrager from_material(double E, double nu, double phi,
                                                            double psi, double c,
                                                            bool simple_shear = false,
                                                            bool explicit_rate = false)
  {
    const double tphi = tan(phi);
    const double root = simple_shear ? 3.0 : sqrt(9.0 + 12.0 * tphi * tphi);
    return {E / (3.0 * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu)), tphi / root,
            (simple_shear ? 1.0 : 3.0 / root) * c, sin(psi), explicit_rate};
  }

  // from a material record with E, nu, phi, psi, c, dp_matching and dp_plastic (host)
  template <class Material> static DruckerPrager from(const Material &m)
  {
    return from_material(m.E, m.nu, m.phi, m.psi, m.c, m.dp_matching == Material::SIMPLE_SHEAR,
                         m.dp_plastic == Material::EXPLICIT_RATE);
  }

  KOKKOS_INLINE_FUNCTION double yield_function(const Sym3 &s) const
  {
    return sqrt(second_invariant(s)) + alpha_phi * s.trace() - k_c;
  }

  // The friction coefficient at which a cohesionless layer in steady simple shear yields:
  // tan(theta) = 3 alpha_phi (above)
  double slide_friction() const { return 3.0 * alpha_phi; }

  // The part of the strength that the stress uses, sqrt(J2) / (k_c - alpha_phi I1): 1 on
  // the cone, below 1 inside it. At the apex there is no strength left to mobilise: 1.
  // With cohesion the strength there is k_c - alpha_phi I1 = round-off, hence the
  // tolerance (that of plastic_rate).
  KOKKOS_INLINE_FUNCTION double mobilised_ratio(const Sym3 &s) const
  {
    const double strength = k_c - alpha_phi * s.trace();
    if (strength <= 1.0e-10 * (k_c + fabs(alpha_phi * s.trace()))) return 1.0;
    return sqrt(second_invariant(s)) / strength;
  }

  // Bui's treatment of states outside the admissible region: tension beyond the
  // apex of the cone is cut back to the apex (tension cracking), then a deviator
  // outside the cone is scaled back onto it. Raises regime accordingly. Written without
  // branches (each case a selection, every division by a guarded divisor), so that the
  // host's loop over the grains vectorises (FixSPHModel::Advance).
  KOKKOS_INLINE_FUNCTION Sym3 return_to_cone(Sym3 s, Regime &regime) const
  {
    const double excess = s.trace() - k_c / (alpha_phi > 0.0 ? alpha_phi : 1.0);
    const bool cut = (alpha_phi > 0.0) & (excess > 0.0);
    s = select(cut, s - Sym3::iso(excess / 3.0), s);
    const double strength = k_c - alpha_phi * s.trace();
    const bool apex = strength <= 0.0;
    const double sqrt_j2 = sqrt(second_invariant(s));
    const bool outside = !apex & (sqrt_j2 > strength);
    const Sym3 mean = Sym3::iso(s.trace() / 3.0);
    const double scale = strength / (outside ? sqrt_j2 : 1.0);
    regime = (cut | apex) ? DISCONNECTED : (outside & (regime == ELASTIC)) ? PLASTIC : regime;
    return select(apex, mean, select(outside, mean + scale * s.deviator(), s));
  }

  // Plastic part of the stress rate of eq. 32, lambda (9 K sin(psi) I + G S / sqrt(J2)),
  // for a state on the yield surface that is loaded (lambda > 0, eq. 33). At the
  // apex of the cone the surface normal is undefined: there (sqrt(J2) at round-off
  // level against this step's elastic increment) return_to_cone does the work, so
  // that the update stays continuous in its input.
  KOKKOS_INLINE_FUNCTION Sym3 plastic_rate(const Sym3 &s, const Sym3 &d, double dt) const
  {
    const double sqrt_j2 = sqrt(second_invariant(s));
    const double increment = dt * 2.0 * G * sqrt(second_invariant(d));
    if (sqrt_j2 <= 1.0e-8 * increment) return Sym3::zero();
    const double tol = 1.0e-10 * (k_c + fabs(alpha_phi * s.trace()) + sqrt_j2);
    if (yield_function(s) < -tol) return Sym3::zero();
    const Sym3 dev = s.deviator();
    const double lambda = (3.0 * alpha_phi * K * d.trace() + (G / sqrt_j2) * dev.ddot(d)) /
        (27.0 * alpha_phi * K * sin_psi + G);
    if (lambda <= 0.0) return Sym3::zero();
    return lambda * (Sym3::iso(9.0 * K * sin_psi) + (G / sqrt_j2) * dev);
  }

  // The implicit return of an elastic trial state along eq. 32's plastic flow: with
  // dlambda = f_trial / (G + 27 alpha_phi K sin(psi)),
  //   sigma = trial - dlambda (9 K sin(psi) I + G s_trial / sqrt(J2_trial))
  // lies on the yield surface (with psi = 0: the deviator scaled at constant pressure). A
  // return past the cone's axis keeps no deviator; tension beyond the apex is cut as Bui
  // does.
  KOKKOS_INLINE_FUNCTION Sym3 return_mapping(const Sym3 &trial, Regime &regime) const
  {
    const double f = yield_function(trial);
    const double sqrt_j2 = sqrt(second_invariant(trial));
    const bool plastic = !((f <= 0.0) | (sqrt_j2 == 0.0));
    const double dlambda = f / (G + 27.0 * alpha_phi * K * sin_psi);
    const double scale = 1.0 - dlambda * G / (plastic ? sqrt_j2 : 1.0);
    const Sym3 pressure = Sym3::iso(trial.trace() / 3.0 - 9.0 * K * sin_psi * dlambda);
    regime = plastic ? PLASTIC : ELASTIC;
    return return_to_cone(
        select(plastic, pressure + (scale > 0.0 ? scale : 0.0) * trial.deviator(), trial),
        regime);
  }

  // A step of length dt from s0 with the rate evaluated at s (see jaumann_trial), back
  // into the admissible region as explicit_rate says; the stress-model interface of
  // gransph_stress_model.h. This model ignores the density.
  KOKKOS_INLINE_FUNCTION Sym3 update(const Sym3 &s0, const Sym3 &s, const Sym3 &d,
                                     const Spin3 &w, double rho, double dt,
                                     Regime &regime) const
  {
    return explicit_rate ? update_with<true>(s0, s, d, w, rho, dt, regime)
                         : update_with<false>(s0, s, d, w, rho, dt, regime);
  }

  // update with the plastic treatment EXPLICIT (explicit_rate) fixed at compile time
  template <bool EXPLICIT>
  KOKKOS_INLINE_FUNCTION Sym3 update_with(const Sym3 &s0, const Sym3 &s, const Sym3 &d,
                                          const Spin3 &w, double /*rho*/, double dt,
                                          Regime &regime) const
  {
    const Sym3 trial = jaumann_trial(s0, s, d, w, K, G, dt);
    if (!EXPLICIT) return return_mapping(trial, regime);
    const Sym3 plastic = plastic_rate(s, d, dt);
    regime = plastic.ddot(plastic) > 0.0 ? PLASTIC : ELASTIC;
    return return_to_cone(trial - dt * plastic, regime);
  }
};

// DruckerPrager with its plastic treatment fixed for a run: a loop over the particles
// that calls its update has no branch on it (with_run_variant)
template <bool EXPLICIT> struct DruckerPragerWith {
  DruckerPrager model;

  KOKKOS_INLINE_FUNCTION Sym3 update(const Sym3 &s0, const Sym3 &s, const Sym3 &d,
                                     const Spin3 &w, double rho, double dt,
                                     Regime &regime) const
  {
    return model.update_with<EXPLICIT>(s0, s, d, w, rho, dt, regime);
  }
};

template <class F> void with_run_variant(const DruckerPrager &model, F &&f)
{
  if (model.explicit_rate)
    f(DruckerPragerWith<true>{model});
  else
    f(DruckerPragerWith<false>{model});
}

}    // namespace GRANSPH

#endif
