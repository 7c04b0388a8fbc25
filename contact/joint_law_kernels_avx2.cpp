// The joint law's kernels (joint_law_kernel.inc) in AVX2 lanes:
// lanes::pair_law_avx2 and lanes::pair_rest_avx2. Compiled with -mavx2 on
// x86-64 only (contact/CMakeLists.txt).
#include "core/lanes_avx2.hpp"

#define POLYDEM_SIMD simd_avx2
#define POLYDEM_PAIR_LAW pair_law_avx2
#define POLYDEM_PAIR_REST pair_rest_avx2
#include "contact/joint_law_kernel.inc"
