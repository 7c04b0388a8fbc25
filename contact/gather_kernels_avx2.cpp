// The gather's kernels (gather_kernel.inc) in AVX2 lanes:
// gather_lanes::gather_block_avx2 and gather_two_avx2. Compiled with -mavx2
// on x86-64 only (contact/CMakeLists.txt).
#include "core/lanes_avx2.hpp"

#define POLYDEM_SIMD simd_avx2
#define POLYDEM_GATHER_BLOCK gather_block_avx2
#define POLYDEM_GATHER_TWO gather_two_avx2
#include "contact/gather_kernel.inc"
