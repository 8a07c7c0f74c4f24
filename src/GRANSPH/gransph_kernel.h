/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: Wendland C2 kernel (paper eq. 3), support 2h, 2D and 3D.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_KERNEL_H
#define LMP_GRANSPH_KERNEL_H

#include <Kokkos_Macros.hpp>
#include <cmath>

namespace GRANSPH {

// sqrt and |x| in the precision of their argument, on host and device
KOKKOS_INLINE_FUNCTION double square_root(double x)
{
  return sqrt(x);
}
KOKKOS_INLINE_FUNCTION float square_root(float x)
{
  return sqrtf(x);
}
KOKKOS_INLINE_FUNCTION double magnitude(double x)
{
  return fabs(x);
}
KOKKOS_INLINE_FUNCTION float magnitude(float x)
{
  return fabsf(x);
}

// The kernel for one smoothing length h; the constants are set once so that a
// pair costs one sqrt and no division. Real is the arithmetic of the pair sums: double,
// or float for the grains' sums under the pair style's `precision mixed` (in_precision).
template <class Real> struct WendlandC2Of {
  Real h, inv_h;
  Real w_norm;       // alpha_d: 7/(4 pi h^2) in 2D, 21/(16 pi h^3) in 3D
  Real grad_norm;    // -5 alpha_d / h^2

  KOKKOS_INLINE_FUNCTION static WendlandC2Of make(double h, int dim)
  {
    constexpr double pi = 3.14159265358979323846;
    const double norm = dim == 2 ? 7.0 / (4.0 * pi * h * h) : 21.0 / (16.0 * pi * h * h * h);
    return {Real(h), Real(1.0 / h), Real(norm), Real(-5.0 * norm / (h * h))};
  }

  // the same kernel with its constants rounded to Other, set before a loop over pairs
  template <class Other> KOKKOS_INLINE_FUNCTION WendlandC2Of<Other> in_precision() const
  {
    return {Other(h), Other(inv_h), Other(w_norm), Other(grad_norm)};
  }

  KOKKOS_INLINE_FUNCTION Real cutsq() const { return Real(4) * h * h; }

  // q = r / h from r^2: the one sqrt of a pair
  KOKKOS_INLINE_FUNCTION Real q(Real rsq) const { return square_root(rsq) * inv_h; }

  // W at q < 2
  KOKKOS_INLINE_FUNCTION Real w_inside(Real q) const
  {
    const Real t = Real(1) - Real(0.5) * q;
    return w_norm * t * t * t * t * (Real(2) * q + Real(1));
  }

  // F with grad_i W(x_i - x_j) = F * (x_i - x_j), at q < 2; dW/dq = -5 q (1 - q/2)^3
  // alpha_d, so F = -5 alpha_d (1 - q/2)^3 / h^2 and no division by r is needed.
  KOKKOS_INLINE_FUNCTION Real grad_factor_inside(Real q) const
  {
    const Real t = Real(1) - Real(0.5) * q;
    return grad_norm * t * t * t;
  }

  // W(r, h) from r^2
  KOKKOS_INLINE_FUNCTION Real w(Real rsq) const
  {
    const Real qr = q(rsq);
    return qr < Real(2) ? w_inside(qr) : Real(0);
  }

  // F as above from r^2, zero outside the support
  KOKKOS_INLINE_FUNCTION Real grad_factor(Real rsq) const
  {
    const Real qr = q(rsq);
    return qr < Real(2) ? grad_factor_inside(qr) : Real(0);
  }
};
using WendlandC2 = WendlandC2Of<double>;

}    // namespace GRANSPH

#endif
