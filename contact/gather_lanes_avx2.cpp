// The gather in AVX2 lanes (see gather_lanes.hpp). Compiled with -mavx2 on
// x86-64 only; it includes nothing that instantiates inline code shared
// with other files (core/avx2_lanes.hpp).
#include "contact/gather_lanes.hpp"

#include "core/avx2_lanes.hpp"

namespace polydem::gather_lanes {
namespace {

using namespace avx2;

// Lanes x y z, not the fourth. A function, not a namespace-scope constant:
// that would be built by a static initialiser with AVX instructions, run
// before main() on every CPU (core/avx2_lanes.hpp).
inline __m256i xyz() { return _mm256_setr_epi64x(-1, -1, -1, 0); }

inline V load3(const double* p) { return _mm256_maskload_pd(p, xyz()); }
inline void store3(double* p, V v) { _mm256_maskstore_pd(p, xyz(), v); }
// (y, z, x, ·)
inline V yzx(V v) { return _mm256_permute4x64_pd(v, _MM_SHUFFLE(3, 0, 2, 1)); }

// Entry k of a block's list at centroid x: fk = s·F, f += fk, and
// m += d·yzx(fk) − yzx(d)·fk with d = p − x. Lane 0 of that term is
// d_x·fk_y − d_y·fk_x, the moment's z, lane 1 its x, lane 2 its y: each
// component of d × fk with the portable loop's products and difference,
// one lane over. A lane's sum never mixes lanes, so the permuted sum is
// the sum of the permuted terms, bit for bit: the block's moment is
// yzx(m), permuted once (two permutations an entry instead of four, which
// share one port).
inline void add_entry(const GatherArrays& a, int k, V x, V& f, V& m) {
  const long q = 3 * static_cast<long>(a.entry[k]);
  const V fk = mul(bc(a.sign[k]), load3(a.force + q));
  f = add(f, fk);
  const V d = sub(load3(a.point + q), x);
  m = add(m, sub(mul(d, yzx(fk)), mul(yzx(d), fk)));
}

inline void store_block(const GatherArrays& a, int i, V f, V m) {
  store3(a.contact_force + 3 * static_cast<long>(i), f);
  store3(a.contact_torque + 3 * static_cast<long>(i), yzx(m));
}

}  // namespace

void gather_block(const GatherArrays& a, int i) {
  const V x = load3(a.centroid + 3 * static_cast<long>(i));
  V f = _mm256_setzero_pd(), m = _mm256_setzero_pd();
  for (int k = a.offset[i], end = a.offset[i + 1]; k < end; ++k) add_entry(a, k, x, f, m);
  store_block(a, i, f, m);
}

void gather_two(const GatherArrays& a, int i, int j) {
  const V xi = load3(a.centroid + 3 * static_cast<long>(i));
  const V xj = load3(a.centroid + 3 * static_cast<long>(j));
  V fi = _mm256_setzero_pd(), mi = _mm256_setzero_pd();
  V fj = _mm256_setzero_pd(), mj = _mm256_setzero_pd();
  int ki = a.offset[i], kj = a.offset[j];
  const int ei = a.offset[i + 1], ej = a.offset[j + 1];
  for (; ki < ei && kj < ej; ++ki, ++kj) {  // both chains in flight
    add_entry(a, ki, xi, fi, mi);
    add_entry(a, kj, xj, fj, mj);
  }
  for (; ki < ei; ++ki) add_entry(a, ki, xi, fi, mi);
  for (; kj < ej; ++kj) add_entry(a, kj, xj, fj, mj);
  store_block(a, i, fi, mi);
  store_block(a, j, fj, mj);
}

}  // namespace polydem::gather_lanes
