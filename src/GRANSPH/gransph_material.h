/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: named granular materials read from a potential-style file.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_MATERIAL_H
#define LMP_GRANSPH_MATERIAL_H

#include "pointers.h"

#include <string>

namespace LAMMPS_NS {

// One line of a *.gransph file (SI units). Angles are stored in radians.
struct GranSPHMaterial {
  std::string name;
  double rho0;     // reference density
  double E, nu;    // Young's modulus, Poisson's ratio
  double phi;      // friction angle
  double psi;      // dilatancy angle
  double c;        // cohesion
  double rho_c;    // critical density of the phase-change model
  double xi;       // rate parameter xi = I0 / (d sqrt(rho_s))
  double mu_s;     // static friction coefficient
  double mu_2;     // limiting friction coefficient

  // How Drucker-Prager's alpha_phi and k_c are matched to phi and c (not in the
  // file: fix sph/elastoplastic's keyword matching)
  enum Matching { PLANE_STRAIN, SIMPLE_SHEAR };
  Matching dp_matching = PLANE_STRAIN;
  // How a Drucker-Prager step returns to the yield surface (fix sph/elastoplastic's
  // keyword plastic): implicitly, or with the paper's explicit plastic rate (eqs. 32-33)
  enum PlasticStep { RETURN_MAPPING, EXPLICIT_RATE };
  PlasticStep dp_plastic = RETURN_MAPPING;

  double bulk_modulus() const { return E / (3.0 * (1.0 - 2.0 * nu)); }

  // Read material `name` from `file` on rank 0, check it and broadcast it.
  // `style` names the command in error messages.
  static GranSPHMaterial read(LAMMPS *lmp, const std::string &file, const std::string &name,
                              const std::string &style);
};

}    // namespace LAMMPS_NS

#endif
