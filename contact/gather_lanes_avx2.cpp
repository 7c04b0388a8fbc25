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
// (y, z, x, ·) and (z, x, y, ·)
inline V yzx(V v) { return _mm256_permute4x64_pd(v, _MM_SHUFFLE(3, 0, 2, 1)); }
inline V zxy(V v) { return _mm256_permute4x64_pd(v, _MM_SHUFFLE(3, 1, 0, 2)); }

}  // namespace

void gather_block(const GatherArrays& a, int i) {
  const V x = load3(a.centroid + 3 * static_cast<long>(i));
  V f = _mm256_setzero_pd(), m = _mm256_setzero_pd();
  for (int k = a.offset[i], end = a.offset[i + 1]; k < end; ++k) {
    const long q = 3 * static_cast<long>(a.entry[k]);
    const V fk = mul(bc(a.sign[k]), load3(a.force + q));
    f = add(f, fk);
    const V d = sub(load3(a.point + q), x);
    m = add(m, sub(mul(yzx(d), zxy(fk)), mul(zxy(d), yzx(fk))));
  }
  store3(a.contact_force + 3 * static_cast<long>(i), f);
  store3(a.contact_torque + 3 * static_cast<long>(i), m);
}

}  // namespace polydem::gather_lanes
