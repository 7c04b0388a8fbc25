// Four doubles at a time in AVX2 registers: the lane type of the step's
// kernels (core/code_path.hpp says what a lane type is and how the kernels use
// it; core/lanes_portable.hpp is the same interface in plain doubles).
//
// Only the kernels' AVX2 and AVX-512VL files include this header; they are
// compiled for those instruction sets and must instantiate no inline code
// shared with the rest of the program (an AVX2 copy of an Eigen or std::
// function could be the one the linker keeps for every caller). So:
// intrinsics and functions of internal linkage only, and no Eigen in the
// same file. And no vector object at namespace scope (a `const __m256i` there
// is built by a static initialiser in AVX instructions, which runs before
// main() on every CPU, with or without AVX: build such constants in
// functions; tests/scripts/check_lanes_objects.py checks the objects).
#pragma once

#ifndef __AVX2__
#error "core/lanes_avx2.hpp is for the files compiled with -mavx2 only"
#endif
#ifdef EIGEN_WORLD_VERSION
#error "no Eigen in an AVX2 kernel's file: its inline code would be instantiated with AVX2 instructions"
#endif

#include <immintrin.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace polydem::simd_avx2 {

using V = __m256d;

static inline V zero() { return _mm256_setzero_pd(); }
static inline V bc(double x) { return _mm256_set1_pd(x); }
static inline V add(V a, V b) { return _mm256_add_pd(a, b); }
static inline V sub(V a, V b) { return _mm256_sub_pd(a, b); }
static inline V mul(V a, V b) { return _mm256_mul_pd(a, b); }
static inline V div(V a, V b) { return _mm256_div_pd(a, b); }
static inline V sqrt(V a) { return _mm256_sqrt_pd(a); }
static inline V neg(V a) { return _mm256_xor_pd(a, _mm256_set1_pd(-0.0)); }  // −a, exactly
// Comparisons as C++'s: false with a NaN.
static inline V le(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LE_OQ); }
static inline V lt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
static inline V gt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
static inline V all_lanes(bool c) { return _mm256_castsi256_pd(_mm256_set1_epi64x(c ? -1 : 0)); }
static inline V both(V a, V b) { return _mm256_and_pd(a, b); }
static inline V either(V a, V b) { return _mm256_or_pd(a, b); }
static inline V but_not(V a, V b) { return _mm256_andnot_pd(b, a); }  // a and not b
static inline V invert(V m) { return _mm256_xor_pd(m, all_lanes(true)); }
static inline V pick(V m, V a, V b) { return _mm256_blendv_pd(b, a, m); }  // m ? a : b
static inline int bits(V m) { return _mm256_movemask_pd(m); }              // bit k: lane k's mask
// std::max(a, 0.0) is (a < 0) ? 0 : a; MAXPD(0, a) is (0 > a) ? 0 : a: the
// same for every a, −0 and NaN included. std::min(a, b) is (b < a) ? b : a,
// which is MINPD(b, a); std::max(a, b) is (a < b) ? b : a, MAXPD(b, a).
static inline V max_zero(V a) { return _mm256_max_pd(_mm256_setzero_pd(), a); }
static inline V min_of(V a, V b) { return _mm256_min_pd(b, a); }
static inline V max_of(V a, V b) { return _mm256_max_pd(b, a); }
// (a·b) as Eigen's Vec3::dot: (x·x′ + y·y′) + z·z′.
static inline V dot3(V ax, V ay, V az, V bx, V by, V bz) { return add(add(mul(ax, bx), mul(ay, by)), mul(az, bz)); }

// Lane k of v, and v with lane k set (the kernels' rare per-lane work).
static inline double lane(V v, int k) {
  alignas(32) double t[4];
  _mm256_store_pd(t, v);
  return t[k];
}
static inline V with_lane(V v, int k, double x) {
  alignas(32) double t[4];
  _mm256_store_pd(t, v);
  t[k] = x;
  return _mm256_load_pd(t);
}

// A group of up to four consecutive entries of an array (the last group of
// a run may be short: its missing lanes are neither read nor written).
struct Group {
  bool full;
  int count;
  __m256i mask;
};
static inline Group group(std::size_t left) {
  Group g;
  g.count = left >= 4 ? 4 : static_cast<int>(left);
  g.full = g.count == 4;
  g.mask = _mm256_cmpgt_epi64(_mm256_set1_epi64x(g.count), _mm256_setr_epi64x(0, 1, 2, 3));
  return g;
}
static inline V load(const double* p, const Group& g) {
  return g.full ? _mm256_loadu_pd(p) : _mm256_maskload_pd(p, g.mask);
}
static inline void store(double* p, V v, const Group& g) {
  if (g.full)
    _mm256_storeu_pd(p, v);
  else
    _mm256_maskstore_pd(p, g.mask, v);
}
// Three lanes' vectors into an array of x y z per entry. A full group as
// three stores: x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3, each gathered from
// the three vectors turned so that every lane is in place.
static inline void store_xyz(double* p, V x, V y, V z, const Group& g) {
  if (g.full) {
    const V xp = _mm256_permute4x64_pd(x, 0x6C);  // x0 x3 x2 x1
    const V yp = _mm256_permute4x64_pd(y, 0xB1);  // y1 y0 y3 y2
    const V zp = _mm256_permute4x64_pd(z, 0xC6);  // z2 z1 z0 z3
    _mm256_storeu_pd(p, _mm256_blend_pd(_mm256_blend_pd(xp, yp, 0x2), zp, 0x4));
    _mm256_storeu_pd(p + 4, _mm256_blend_pd(_mm256_blend_pd(yp, zp, 0x2), xp, 0x4));
    _mm256_storeu_pd(p + 8, _mm256_blend_pd(_mm256_blend_pd(zp, xp, 0x2), yp, 0x4));
    return;
  }
  alignas(32) double tx[4], ty[4], tz[4];
  _mm256_store_pd(tx, x);
  _mm256_store_pd(ty, y);
  _mm256_store_pd(tz, z);
  for (int k = 0; k < g.count; ++k) {
    p[3 * k] = tx[k];
    p[3 * k + 1] = ty[k];
    p[3 * k + 2] = tz[k];
  }
}
// The group's bytes packed, byte k from entry k (missing lanes 0), and back.
static inline std::uint32_t load_bytes(const std::uint8_t* p, const Group& g) {
  std::uint32_t bytes = 0;
  if (g.full)
    std::memcpy(&bytes, p, 4);
  else
    for (int k = 0; k < g.count; ++k) bytes |= static_cast<std::uint32_t>(p[k]) << (8 * k);
  return bytes;
}
static inline void store_bytes(std::uint8_t* p, std::uint32_t bytes, const Group& g) {
  if (g.full) {
    std::memcpy(p, &bytes, 4);
    return;
  }
  for (int k = 0; k < g.count; ++k) p[k] = static_cast<std::uint8_t>(bytes >> (8 * k));
}
// The lanes whose byte has a bit of `bits` set, as a mask.
static inline V bytes_mask(std::uint32_t bytes, std::uint32_t bits) {
  const __m256i b = _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(static_cast<int>(bytes & (bits * 0x01010101u))));
  return _mm256_castsi256_pd(_mm256_cmpgt_epi64(b, _mm256_setzero_si256()));
}
// A mask as bytes 0 or 1: bit k of the mask to byte k.
static inline std::uint32_t mask_bytes(V m) {
  return (static_cast<std::uint32_t>(_mm256_movemask_pd(m)) * 0x00204081u) & 0x01010101u;
}

// Each vector's lanes summed as (l0 + l1) + (l2 + l3), six at once: hadd
// gives [a0 + a1, b0 + b1, a2 + a3, b2 + b3], the halves' sum the rest.
static inline void sum_lanes6(V a, V b, V c, V d, V e, V f, double out[6]) {
  const V h1 = _mm256_hadd_pd(a, b), h2 = _mm256_hadd_pd(c, d), h3 = _mm256_hadd_pd(e, f);
  const V s4 = add(_mm256_permute2f128_pd(h1, h2, 0x20), _mm256_permute2f128_pd(h1, h2, 0x31));
  const V s2 = add(h3, _mm256_permute2f128_pd(h3, h3, 0x01));
  _mm256_storeu_pd(out, s4);
  _mm_storeu_pd(out + 4, _mm256_castpd256_pd128(s2));
}

// A 3-vector in lanes 0-2 (lane 3 neither read nor stored).
static inline __m256i xyz_mask() { return _mm256_setr_epi64x(-1, -1, -1, 0); }
static inline V load3(const double* p) { return _mm256_maskload_pd(p, xyz_mask()); }
static inline void store3(double* p, V v) { _mm256_maskstore_pd(p, xyz_mask(), v); }
// (y, z, x, ·)
static inline V yzx(V v) { return _mm256_permute4x64_pd(v, _MM_SHUFFLE(3, 0, 2, 1)); }

// Component c of four records of `width` doubles, at idx[0..3], and back.
static inline V gather(const double* p, int width, int c, const int idx[4]) {
  return _mm256_setr_pd(p[width * idx[0] + c], p[width * idx[1] + c], p[width * idx[2] + c], p[width * idx[3] + c]);
}
static inline void scatter(double* p, int width, int c, const int idx[4], V v) {
  alignas(32) double t[4];
  _mm256_store_pd(t, v);
  for (int l = 0; l < 4; ++l) p[width * idx[l] + c] = t[l];
}

}  // namespace polydem::simd_avx2
