/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH: Wendland C2 kernel (paper eq. 3), support 2h, 2D and 3D.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_KERNEL_H
#define LMP_GRANSPH_KERNEL_H

#include <Kokkos_Macros.hpp>
#include <cmath>

namespace GRANSPH {

struct WendlandC2 {
  // alpha_d h^dim: 7/(4 pi) in 2D, 21/(16 pi) in 3D
  KOKKOS_INLINE_FUNCTION static double norm(int dim, double h)
  {
    constexpr double pi = 3.14159265358979323846;
    return dim == 2 ? 7.0 / (4.0 * pi * h * h) : 21.0 / (16.0 * pi * h * h * h);
  }

  // W(r, h) from r^2
  KOKKOS_INLINE_FUNCTION static double w(double rsq, double h, int dim)
  {
    const double q = sqrt(rsq) / h;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    return norm(dim, h) * t * t * t * t * (2.0 * q + 1.0);
  }

  // F with grad_i W(x_i - x_j) = F * (x_i - x_j); dW/dq = -5 q (1 - q/2)^3 alpha_d,
  // so F = -5 alpha_d (1 - q/2)^3 / h^2 and no division by r is needed.
  KOKKOS_INLINE_FUNCTION static double grad_factor(double rsq, double h, int dim)
  {
    const double q = sqrt(rsq) / h;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    return -5.0 * norm(dim, h) * t * t * t / (h * h);
  }
};

}    // namespace GRANSPH

#endif
