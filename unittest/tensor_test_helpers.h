/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

// Helpers shared by the unit tests of the stress updates.

#ifndef GRANSPH_TENSOR_TEST_HELPERS_H
#define GRANSPH_TENSOR_TEST_HELPERS_H

#include "gransph_tensor.h"

#include <cmath>
#include <initializer_list>

namespace GRANSPH {

// R s R^T for R = R_x(b) R_z(a): a rotation by a about z, then by b about x
inline Sym3 rotate(const Sym3 &s, double a, double b = 0.0)
{
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
  const double Rz[3][3] = {{ca, -sa, 0}, {sa, ca, 0}, {0, 0, 1}};
  const double Rx[3][3] = {{1, 0, 0}, {0, cb, -sb}, {0, sb, cb}};
  double R[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) R[i][j] += Rx[i][k] * Rz[k][j];
  const double S[3][3] = {{s.xx, s.xy, s.xz}, {s.xy, s.yy, s.yz}, {s.xz, s.yz, s.zz}};
  double o[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) o[i][j] += R[i][k] * S[k][l] * R[j][l];
  return {o[0][0], o[1][1], o[2][2], o[0][1], o[0][2], o[1][2]};
}

inline double max_abs_diff(const Sym3 &a, const Sym3 &b)
{
  const Sym3 d = a - b;
  double m = 0.0;
  for (double v : {d.xx, d.yy, d.zz, d.xy, d.xz, d.yz}) m = std::fmax(m, std::fabs(v));
  return m;
}

}    // namespace GRANSPH

#endif
