// Four doubles at a time: the helpers of the AVX2 kernels (the joint law's,
// contact/joint_law_lanes_kernel.inc, compiled by joint_law_lanes_avx2.cpp
// with -mavx2 and by joint_law_lanes_avx512.cpp with -mavx512vl; the
// gather's, contact/gather_lanes_avx2.cpp; the blocks' update,
// integrators/block_update_lanes_avx2.cpp).
//
// Only those files include this header; they are compiled for AVX2 or
// AVX-512VL and must instantiate no inline code shared with the rest of the
// program (an AVX2 copy of an Eigen or std:: function could be the one the
// linker keeps for every caller). So: intrinsics and functions of internal
// linkage only, and no Eigen in the same file. And no vector object at
// namespace scope (a `const __m256i` there is built by a static initialiser
// in AVX instructions, which runs before main() on every CPU, with or
// without AVX: build such constants in functions; the test
// LanesObjects.HaveNoStaticInitialisers checks the objects).
//
// Every helper is one IEEE operation per lane, or a fixed sequence of them
// written out, so that a kernel's lanes repeat the portable code's arithmetic
// in its order (core/code_path.hpp).
#pragma once

#ifndef __AVX2__
#error "core/avx2_lanes.hpp is for the files compiled with -mavx2 only"
#endif
#ifdef EIGEN_WORLD_VERSION
#error "no Eigen in an AVX2 kernel's file: its inline code would be instantiated with AVX2 instructions"
#endif

#include <immintrin.h>

namespace polydem::avx2 {

using V = __m256d;

static inline V bc(double x) { return _mm256_set1_pd(x); }
static inline V add(V a, V b) { return _mm256_add_pd(a, b); }
static inline V sub(V a, V b) { return _mm256_sub_pd(a, b); }
static inline V mul(V a, V b) { return _mm256_mul_pd(a, b); }
static inline V div(V a, V b) { return _mm256_div_pd(a, b); }
static inline V neg(V a) { return _mm256_xor_pd(a, _mm256_set1_pd(-0.0)); }  // −a, exactly
// Comparisons as C++'s: false with a NaN.
static inline V le(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LE_OQ); }
static inline V lt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
static inline V gt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
static inline V both(V a, V b) { return _mm256_and_pd(a, b); }
static inline V either(V a, V b) { return _mm256_or_pd(a, b); }
static inline V but_not(V a, V b) { return _mm256_andnot_pd(b, a); }  // a and not b
static inline V pick(V m, V a, V b) { return _mm256_blendv_pd(b, a, m); }  // m ? a : b
static inline V all_lanes(bool c) { return _mm256_castsi256_pd(_mm256_set1_epi64x(c ? -1 : 0)); }
// (a·b) as Eigen's Vec3::dot: (x·x′ + y·y′) + z·z′.
static inline V dot3(V ax, V ay, V az, V bx, V by, V bz) {
  return add(add(mul(ax, bx), mul(ay, by)), mul(az, bz));
}

}  // namespace polydem::avx2
