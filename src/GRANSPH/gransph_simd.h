/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: the `omp simd` pragmas of the host's vectorised loops (honoured
   with -fopenmp or -fopenmp-simd; device compilers go without).
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_SIMD_H
#define LMP_GRANSPH_SIMD_H

#if defined(__CUDACC__) || defined(__HIPCC__)
#define GRANSPH_SIMD_SUM(...)
#define GRANSPH_SIMD_IF_SUM(condition, ...)
#define GRANSPH_SIMD_MAX(...)
#else
#define GRANSPH_PRAGMA(text) _Pragma(#text)
// a loop whose lanes sum into the named variables
#define GRANSPH_SIMD_SUM(...) GRANSPH_PRAGMA(omp simd reduction(+ : __VA_ARGS__))
// a loop whose lanes take the largest of the named variables
#define GRANSPH_SIMD_MAX(...) GRANSPH_PRAGMA(omp simd reduction(max : __VA_ARGS__))
// GRANSPH_SIMD_SUM, vectorised where the compile-time condition holds, in order otherwise
#define GRANSPH_SIMD_IF_SUM(condition, ...) \
  GRANSPH_PRAGMA(omp simd if(simd : condition) reduction(+ : __VA_ARGS__))
#endif

#endif
