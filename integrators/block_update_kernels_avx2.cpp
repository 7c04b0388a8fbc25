// The blocks' update kernel (block_update_kernel.inc) in AVX2 lanes:
// block_lanes::advance_four_avx2. Compiled with -mavx2 on x86-64 only
// (integrators/CMakeLists.txt).
#include "core/lanes_avx2.hpp"

#define POLYDEM_SIMD simd_avx2
#define POLYDEM_ADVANCE_FOUR advance_four_avx2
#include "integrators/block_update_kernel.inc"
