/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: the force check of our copies of LAMMPS' pair-style harness.

   The pair sums a particle's neighbours in SIMD lanes, whose grouping of the terms
   follows the machine's vector width, and the /kk pair over a neighbour list of its
   own order: the same terms in another order. A force component that cancels to
   round-off (a dummy particle's tangential force where the grains' shear stress is
   nearly zero, 1e-20 against forces of order 1) then differs by O(1) relative to
   itself, which the harness' per-component relative error reports as a failure. Here
   each component is compared relative to the atom's whole reference force, which is
   round-off where two sums of the same terms agree to round-off.
------------------------------------------------------------------------- */

#ifndef GRANSPH_FORCE_CHECK_H
#define GRANSPH_FORCE_CHECK_H

#include "error_stats.h"
#include "gtest/gtest.h"

#include <algorithm>
#include <cmath>
#include <string>

#define EXPECT_FORCE_LE_WITH_EPS(fi, ref, k, eps)                                        \
  do {                                                                                   \
    const double ref_k[3] = {(ref).x, (ref).y, (ref).z};                                 \
    const double scale = std::sqrt(ref_k[0] * ref_k[0] + ref_k[1] * ref_k[1] +           \
                                   ref_k[2] * ref_k[2]);                                 \
    const double diff = std::fabs((fi)[k] - ref_k[k]);                                   \
    const double err = (scale == 0.0) ? diff : diff / scale;                             \
    stats.add(err);                                                                      \
    EXPECT_PRED_FORMAT2(::testing::DoubleLE, err, eps);                                  \
  } while (0);

// LAMMPS 2025+, whose checks call EXPECT_FORCES of test_main.cpp: the same
// check of every atom, each component relative to the atom's whole reference force
template <class AtomT, class RefT>
void expect_forces_relative(const std::string &name, AtomT *atom, const RefT &f_ref, double eps)
{
  SCOPED_TRACE("EXPECT_FORCES (relative to the atom's force): " + name);
  double **f = atom->f;
  const auto *tag = atom->tag;
  const int nlocal = atom->nlocal;
  ASSERT_EQ(nlocal + 1, f_ref.size());
  ErrorStats stats;
  for (int i = 0; i < nlocal; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_FORCE_LE_WITH_EPS(f[i], f_ref[tag[i]], k, eps)
}

#endif
