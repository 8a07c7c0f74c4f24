/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: what a geomechanics user reads from a stress: the mean and the
   deviatoric stress, the principal stresses and the direction of the major
   one, the Lode angle. Compression positive, as in soil mechanics; the stress
   it reads is GRANSPH's tension-positive one.

   Host only: the principal axes come from Eigen's self-adjoint eigensolver,
   which nvcc does not compile. Do not include this header from device code
   or from any *_kokkos.cpp.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_STRESS_INVARIANTS_H
#define LMP_GRANSPH_STRESS_INVARIANTS_H

#include "gransph_tensor.h"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace GRANSPH {

struct StressInvariants {
  double p;               // mean stress -tr(sigma)/3
  double q;               // deviatoric stress sqrt(3 J2)
  double principal[3];    // sigma_1 >= sigma_2 >= sigma_3
  double major[3];        // unit direction of sigma_1, its largest component positive
  double lode;            // Lode angle in degrees: -30 triaxial compression, +30 extension
};

inline StressInvariants stress_invariants(const Sym3 &s)
{
  constexpr double DEGREES = 57.295779513082320876798;    // 180 / pi
  Eigen::Matrix3d m;
  m << s.xx, s.xy, s.xz, s.xy, s.yy, s.yz, s.xz, s.yz, s.zz;
  // iterative QL rather than computeDirect: the closed form loses digits when two
  // principal stresses are close, as the horizontal ones of a layer at rest are
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(m);

  StressInvariants r;
  r.p = -s.trace() / 3.0;
  r.q = std::sqrt(3.0 * second_invariant(s));
  // ascending tension-positive eigenvalues are descending compressions
  for (int k = 0; k < 3; ++k) r.principal[k] = -eigen.eigenvalues()(k);
  Eigen::Vector3d major = eigen.eigenvectors().col(0);
  Eigen::Index largest;
  major.cwiseAbs().maxCoeff(&largest);
  if (major(largest) < 0.0) major = -major;    // an eigenvector's sign is arbitrary
  for (int a = 0; a < 3; ++a) r.major[a] = major(a);
  // tan(lode) = (2 sigma_2 - sigma_1 - sigma_3) / (sqrt(3) (sigma_1 - sigma_3)); atan2
  // gives 0 for an isotropic stress, where the angle is undefined
  const double *sp = r.principal;
  r.lode = DEGREES * std::atan2(2.0 * sp[1] - sp[0] - sp[2], std::sqrt(3.0) * (sp[0] - sp[2]));
  return r;
}

}    // namespace GRANSPH

#endif
