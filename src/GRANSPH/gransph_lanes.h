/* -*- c++ -*- ----------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------
   GRANSPH: the host's explicit SIMD lanes, for x86-64 with AVX2 and FMA
   (GRANSPH_LANES is 0 elsewhere: on devices, in generic builds). A lane type
   holds one 256-bit vector, four doubles (Lanes4) or eight floats (Lanes8f),
   with the arithmetic of the pair terms of gransph_pair_terms.h and
   gransph_kernel.h, so that the same functions give several pairs at once;
   load_transposed() reads the particles' records (PairParticle, 16 doubles,
   or PairParticleSingle, 16 floats) as whole rows and turns them into their
   fields.
------------------------------------------------------------------------- */

#ifndef LMP_GRANSPH_LANES_H
#define LMP_GRANSPH_LANES_H

#if defined(__AVX2__) && defined(__FMA__) && !defined(__CUDACC__) && !defined(__HIPCC__)
#define GRANSPH_LANES 1
#else
#define GRANSPH_LANES 0
#endif

#if GRANSPH_LANES

#include "gransph_pair_terms.h"

#include <cstddef>
#include <immintrin.h>

namespace GRANSPH {

// a condition per lane: all bits set where it holds
struct Mask4 {
  __m256d m;
  friend Mask4 operator&(Mask4 a, Mask4 b) { return {_mm256_and_pd(a.m, b.m)}; }
  friend Mask4 operator|(Mask4 a, Mask4 b) { return {_mm256_or_pd(a.m, b.m)}; }
};
struct Mask8f {
  __m256 m;
  friend Mask8f operator&(Mask8f a, Mask8f b) { return {_mm256_and_ps(a.m, b.m)}; }
  friend Mask8f operator|(Mask8f a, Mask8f b) { return {_mm256_or_ps(a.m, b.m)}; }
};

struct Lanes4 {
  using Scalar = double;
  using Record = PairParticle;
  using Mask = Mask4;
  static constexpr int WIDTH = 4;
  __m256d v;
  Lanes4() = default;
  Lanes4(double s) : v(_mm256_set1_pd(s)) {}
  Lanes4(__m256d a) : v(a) {}
  friend Lanes4 operator+(Lanes4 a, Lanes4 b) { return _mm256_add_pd(a.v, b.v); }
  friend Lanes4 operator-(Lanes4 a, Lanes4 b) { return _mm256_sub_pd(a.v, b.v); }
  friend Lanes4 operator*(Lanes4 a, Lanes4 b) { return _mm256_mul_pd(a.v, b.v); }
  friend Lanes4 operator/(Lanes4 a, Lanes4 b) { return _mm256_div_pd(a.v, b.v); }
  friend Lanes4 operator-(Lanes4 a) { return _mm256_xor_pd(a.v, _mm256_set1_pd(-0.0)); }
  friend Mask operator<(Lanes4 a, Lanes4 b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)}; }
  friend Lanes4 zero_unless(Mask c, Lanes4 a) { return _mm256_and_pd(c.m, a.v); }
  friend Lanes4 zero_unless(bool c, Lanes4 a) { return c ? a : Lanes4(0.0); }
  friend Lanes4 square_root(Lanes4 a) { return _mm256_sqrt_pd(a.v); }
  friend Lanes4 magnitude(Lanes4 a) { return _mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v); }
  // acc + a b, rounded once
  friend void add_product(Lanes4 &acc, Lanes4 a, Lanes4 b) { acc.v = _mm256_fmadd_pd(a.v, b.v, acc.v); }
  // the lanes before lane `count`
  static Mask first(int count)
  {
    return {_mm256_cmp_pd(_mm256_set_pd(3.0, 2.0, 1.0, 0.0), _mm256_set1_pd(count), _CMP_LT_OQ)};
  }
  // the four lanes' sum, pairwise
  double sum() const
  {
    const __m128d pair = _mm_add_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
    return _mm_cvtsd_f64(_mm_add_sd(pair, _mm_unpackhi_pd(pair, pair)));
  }
  // four records' 16 fields: f[q] holds the records' q-th doubles
  static void load_transposed(const Record *const r[4], Lanes4 f[16])
  {
    static_assert(sizeof(Record) == 16 * sizeof(double), "PairParticle: 16 doubles");
    for (int q = 0; q < 16; q += 4) {
      // unaligned loads: a LAMMPS built without LAMMPS_MEMALIGN puts records on 16 bytes
      const __m256d a = _mm256_loadu_pd(r[0]->x + q), b = _mm256_loadu_pd(r[1]->x + q),
                    c = _mm256_loadu_pd(r[2]->x + q), d = _mm256_loadu_pd(r[3]->x + q);
      const __m256d ab_lo = _mm256_unpacklo_pd(a, b), ab_hi = _mm256_unpackhi_pd(a, b);
      const __m256d cd_lo = _mm256_unpacklo_pd(c, d), cd_hi = _mm256_unpackhi_pd(c, d);
      f[q] = _mm256_permute2f128_pd(ab_lo, cd_lo, 0x20);
      f[q + 1] = _mm256_permute2f128_pd(ab_hi, cd_hi, 0x20);
      f[q + 2] = _mm256_permute2f128_pd(ab_lo, cd_lo, 0x31);
      f[q + 3] = _mm256_permute2f128_pd(ab_hi, cd_hi, 0x31);
    }
  }
};

struct Lanes8f {
  using Scalar = float;
  using Record = PairParticleSingle;
  using Mask = Mask8f;
  static constexpr int WIDTH = 8;
  __m256 v;
  Lanes8f() = default;
  Lanes8f(float s) : v(_mm256_set1_ps(s)) {}
  Lanes8f(__m256 a) : v(a) {}
  friend Lanes8f operator+(Lanes8f a, Lanes8f b) { return _mm256_add_ps(a.v, b.v); }
  friend Lanes8f operator-(Lanes8f a, Lanes8f b) { return _mm256_sub_ps(a.v, b.v); }
  friend Lanes8f operator*(Lanes8f a, Lanes8f b) { return _mm256_mul_ps(a.v, b.v); }
  friend Lanes8f operator/(Lanes8f a, Lanes8f b) { return _mm256_div_ps(a.v, b.v); }
  friend Lanes8f operator-(Lanes8f a) { return _mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f)); }
  friend Mask operator<(Lanes8f a, Lanes8f b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)}; }
  friend Lanes8f zero_unless(Mask c, Lanes8f a) { return _mm256_and_ps(c.m, a.v); }
  friend Lanes8f zero_unless(bool c, Lanes8f a) { return c ? a : Lanes8f(0.0f); }
  friend Lanes8f square_root(Lanes8f a) { return _mm256_sqrt_ps(a.v); }
  friend Lanes8f magnitude(Lanes8f a) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.v); }
  friend void add_product(Lanes8f &acc, Lanes8f a, Lanes8f b) { acc.v = _mm256_fmadd_ps(a.v, b.v, acc.v); }
  static Mask first(int count)
  {
    return {_mm256_cmp_ps(_mm256_set_ps(7.0f, 6.0f, 5.0f, 4.0f, 3.0f, 2.0f, 1.0f, 0.0f),
                          _mm256_set1_ps(float(count)), _CMP_LT_OQ)};
  }
  // the eight lanes' sum, pairwise
  float sum() const
  {
    __m128 s = _mm_add_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    s = _mm_add_ps(s, _mm_movehl_ps(s, s));
    return _mm_cvtss_f32(_mm_add_ss(s, _mm_movehdup_ps(s)));
  }
  // eight records' 16 fields: f[q] holds the records' q-th floats
  static void load_transposed(const Record *const r[8], Lanes8f f[16])
  {
    static_assert(sizeof(Record) == 16 * sizeof(float), "PairParticleSingle: 16 floats");
    for (int q = 0; q < 16; q += 8) {
      __m256 t[8], u[8];
      for (int l = 0; l < 8; l += 2) {
        const __m256 a = _mm256_loadu_ps(r[l]->x + q), b = _mm256_loadu_ps(r[l + 1]->x + q);
        t[l] = _mm256_unpacklo_ps(a, b);
        t[l + 1] = _mm256_unpackhi_ps(a, b);
      }
      for (int l = 0; l < 8; l += 4) {
        u[l] = _mm256_shuffle_ps(t[l], t[l + 2], 0x44);
        u[l + 1] = _mm256_shuffle_ps(t[l], t[l + 2], 0xEE);
        u[l + 2] = _mm256_shuffle_ps(t[l + 1], t[l + 3], 0x44);
        u[l + 3] = _mm256_shuffle_ps(t[l + 1], t[l + 3], 0xEE);
      }
      for (int l = 0; l < 4; ++l) {
        f[q + l] = _mm256_permute2f128_ps(u[l], u[l + 4], 0x20);
        f[q + l + 4] = _mm256_permute2f128_ps(u[l], u[l + 4], 0x31);
      }
    }
  }
};

// The fields of a particle record (PairParticle, PairParticleSingle) in the order
// load_transposed() hands them out: its scalars in memory order.
enum RecordField {
  FIELD_X = 0,
  FIELD_V = 3,
  FIELD_RHO = 6,
  FIELD_C = 7,
  FIELD_SXX = 8,
  FIELD_SYY,
  FIELD_SZZ,
  FIELD_SXY,
  FIELD_SXZ,
  FIELD_SYZ,
  FIELD_MASS = 14,
  FIELD_INV_RHO = 15
};
template <class Record, class Scalar> constexpr bool fields_in_order()
{
  return offsetof(Record, v) == FIELD_V * sizeof(Scalar) &&
      offsetof(Record, rho) == FIELD_RHO * sizeof(Scalar) &&
      offsetof(Record, c) == FIELD_C * sizeof(Scalar) &&
      offsetof(Record, sigma) == FIELD_SXX * sizeof(Scalar) &&
      offsetof(Record, mass) == FIELD_MASS * sizeof(Scalar) &&
      offsetof(Record, inv_rho) == FIELD_INV_RHO * sizeof(Scalar);
}
static_assert(fields_in_order<PairParticle, double>() &&
                  fields_in_order<PairParticleSingle, float>(),
              "the particle records' fields in the order of RecordField");

// the lane type for a particle record type (none: void)
template <class Record> struct LanesOf {
  using type = void;
};
template <> struct LanesOf<PairParticle> {
  using type = Lanes4;
};
template <> struct LanesOf<PairParticleSingle> {
  using type = Lanes8f;
};

}    // namespace GRANSPH

#endif    // GRANSPH_LANES
#endif
