/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: Wendland C2 kernel (paper eq. 3), support 2h, 2D and 3D.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_KERNEL_H
#define LMP_GRANSPH_KERNEL_H

#include <Kokkos_Macros.hpp>
#include <cmath>

namespace GRANSPH {

// The kernel for one smoothing length h; the constants are set once so that a
// pair costs one sqrt and no division.
struct WendlandC2 {
  double h, inv_h;
  double w_norm;       // alpha_d: 7/(4 pi h^2) in 2D, 21/(16 pi h^3) in 3D
  double grad_norm;    // -5 alpha_d / h^2

  KOKKOS_INLINE_FUNCTION static WendlandC2 make(double h, int dim)
  {
    constexpr double pi = 3.14159265358979323846;
    const double norm = dim == 2 ? 7.0 / (4.0 * pi * h * h) : 21.0 / (16.0 * pi * h * h * h);
    return {h, 1.0 / h, norm, -5.0 * norm / (h * h)};
  }

  KOKKOS_INLINE_FUNCTION double cutsq() const { return 4.0 * h * h; }

  // q = r / h from r^2: the one sqrt of a pair
  KOKKOS_INLINE_FUNCTION double q(double rsq) const { return sqrt(rsq) * inv_h; }

  // W at q < 2
  KOKKOS_INLINE_FUNCTION double w_inside(double q) const
  {
    const double t = 1.0 - 0.5 * q;
    return w_norm * t * t * t * t * (2.0 * q + 1.0);
  }

  // F with grad_i W(x_i - x_j) = F * (x_i - x_j), at q < 2; dW/dq = -5 q (1 - q/2)^3
  // alpha_d, so F = -5 alpha_d (1 - q/2)^3 / h^2 and no division by r is needed.
  KOKKOS_INLINE_FUNCTION double grad_factor_inside(double q) const
  {
    const double t = 1.0 - 0.5 * q;
    return grad_norm * t * t * t;
  }

  // W(r, h) from r^2
  KOKKOS_INLINE_FUNCTION double w(double rsq) const
  {
    const double qr = q(rsq);
    return qr < 2.0 ? w_inside(qr) : 0.0;
  }

  // F as above from r^2, zero outside the support
  KOKKOS_INLINE_FUNCTION double grad_factor(double rsq) const
  {
    const double qr = q(rsq);
    return qr < 2.0 ? grad_factor_inside(qr) : 0.0;
  }
};

}    // namespace GRANSPH

#endif
