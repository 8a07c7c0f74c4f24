/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: smoothed particle hydrodynamics for granular flow in LAMMPS.
   Small 3-vector and symmetric/antisymmetric 3x3 tensor helpers, usable on host
   and device.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_TENSOR_H
#define LMP_GRANSPH_TENSOR_H

#include <Kokkos_Macros.hpp>
#include <cmath>

namespace GRANSPH {

KOKKOS_INLINE_FUNCTION double dot3(const double *a, const double *b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

KOKKOS_INLINE_FUNCTION double norm3(const double *a)
{
  return sqrt(dot3(a, a));
}

// Symmetric tensor: stress, strain rate. Tension positive.
struct Sym3 {
  double xx, yy, zz, xy, xz, yz;

  KOKKOS_INLINE_FUNCTION static Sym3 zero() { return {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}; }

  KOKKOS_INLINE_FUNCTION static Sym3 iso(double a) { return {a, a, a, 0.0, 0.0, 0.0}; }

  KOKKOS_INLINE_FUNCTION double trace() const { return xx + yy + zz; }

  KOKKOS_INLINE_FUNCTION Sym3 deviator() const
  {
    const double m = trace() / 3.0;
    return {xx - m, yy - m, zz - m, xy, xz, yz};
  }

  // A:B for symmetric tensors (off-diagonals count twice)
  KOKKOS_INLINE_FUNCTION double ddot(const Sym3 &b) const
  {
    return xx * b.xx + yy * b.yy + zz * b.zz + 2.0 * (xy * b.xy + xz * b.xz + yz * b.yz);
  }
};

KOKKOS_INLINE_FUNCTION Sym3 operator+(const Sym3 &a, const Sym3 &b)
{
  return {a.xx + b.xx, a.yy + b.yy, a.zz + b.zz, a.xy + b.xy, a.xz + b.xz, a.yz + b.yz};
}

KOKKOS_INLINE_FUNCTION Sym3 operator-(const Sym3 &a, const Sym3 &b)
{
  return {a.xx - b.xx, a.yy - b.yy, a.zz - b.zz, a.xy - b.xy, a.xz - b.xz, a.yz - b.yz};
}

KOKKOS_INLINE_FUNCTION Sym3 operator*(double s, const Sym3 &a)
{
  return {s * a.xx, s * a.yy, s * a.zz, s * a.xy, s * a.xz, s * a.yz};
}

// a if c, else b, by component: a choice that code vectorised across particles makes
// without a branch
KOKKOS_INLINE_FUNCTION Sym3 select(bool c, const Sym3 &a, const Sym3 &b)
{
  return {c ? a.xx : b.xx, c ? a.yy : b.yy, c ? a.zz : b.zz,
          c ? a.xy : b.xy, c ? a.xz : b.xz, c ? a.yz : b.yz};
}

// Second invariant of the deviator, J2 = S:S / 2.
KOKKOS_INLINE_FUNCTION double second_invariant(const Sym3 &s)
{
  const Sym3 d = s.deviator();
  return 0.5 * d.ddot(d);
}

// Antisymmetric tensor (spin): w_yx = -w_xy etc., diagonal zero.
struct Spin3 {
  double xy, xz, yz;

  KOKKOS_INLINE_FUNCTION static Spin3 zero() { return {0.0, 0.0, 0.0}; }
};

// The rotation part of the Jaumann rate, w.s - s.w (symmetric), written out as
// sigma^{ag} w^{bg} + sigma^{gb} w^{ag} of the paper's eq. 23.
KOKKOS_INLINE_FUNCTION Sym3 jaumann_rotation(const Sym3 &s, const Spin3 &w)
{
  // w as a full matrix: [[0, wxy, wxz], [-wxy, 0, wyz], [-wxz, -wyz, 0]]
  Sym3 r;
  r.xx = 2.0 * (w.xy * s.xy + w.xz * s.xz);
  r.yy = 2.0 * (-w.xy * s.xy + w.yz * s.yz);
  r.zz = 2.0 * (-w.xz * s.xz - w.yz * s.yz);
  r.xy = w.xy * (s.yy - s.xx) + w.xz * s.yz + w.yz * s.xz;
  r.xz = w.xz * (s.zz - s.xx) + w.xy * s.yz - w.yz * s.xy;
  r.yz = w.yz * (s.zz - s.yy) - w.xy * s.xz - w.xz * s.xy;
  return r;
}

// Hypoelastic (Hooke) rate for strain rate d: 2G dev(d) + K tr(d) I.
KOKKOS_INLINE_FUNCTION Sym3 elastic_rate(const Sym3 &d, double K, double G)
{
  return 2.0 * G * d.deviator() + Sym3::iso(K * d.trace());
}

// Trial stress of eq. 23: a step of length dt of the Jaumann rate with Hooke's law
// from s0, with the rotation evaluated at s (s = s0 for an explicit step, the
// mid-point stress for the corrector's second-order step).
KOKKOS_INLINE_FUNCTION Sym3 jaumann_trial(const Sym3 &s0, const Sym3 &s, const Sym3 &d,
                                          const Spin3 &w, double K, double G, double dt)
{
  return s0 + dt * (jaumann_rotation(s, w) + elastic_rate(d, K, G));
}

}    // namespace GRANSPH

#endif
