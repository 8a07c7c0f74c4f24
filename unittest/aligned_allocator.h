/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

// std::vector storage on 64-byte boundaries: C++14's operator new does not honour the
// alignas(64) of PairParticle, and code built for AVX-512 may move such records with
// aligned instructions.

#ifndef GRANSPH_ALIGNED_ALLOCATOR_H
#define GRANSPH_ALIGNED_ALLOCATOR_H

#include <cstddef>
#include <stdlib.h>
#include <new>
#include <vector>

template <class T> struct Aligned64 {
  using value_type = T;
  Aligned64() = default;
  template <class U> Aligned64(const Aligned64<U> &) {}
  T *allocate(std::size_t n)
  {
    void *p = aligned_alloc(64, (n * sizeof(T) + 63) / 64 * 64);    // C11, in <stdlib.h>
    if (!p) throw std::bad_alloc();
    return static_cast<T *>(p);
  }
  void deallocate(T *p, std::size_t) { free(p); }
  template <class U> bool operator==(const Aligned64<U> &) const { return true; }
  template <class U> bool operator!=(const Aligned64<U> &) const { return false; }
};
template <class T> using AlignedVector = std::vector<T, Aligned64<T>>;

#endif
