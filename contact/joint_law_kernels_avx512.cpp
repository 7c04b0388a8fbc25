// The joint law's kernels (joint_law_kernel.inc) compiled for AVX-512VL:
// lanes::pair_law_avx512 and lanes::pair_rest_avx512. The same four-lane
// 256-bit arithmetic, intrinsic for intrinsic, so the same bits; what
// AVX-512VL adds is 32 vector registers instead of 16, and the kernel,
// which holds a pair's frame and four subcontacts' state at once, spills
// far less to the stack. Built with -ffp-contract=off like every file
// (contact/CMakeLists.txt): AVX-512 has fused multiply-adds, which would
// change the bits.
#include "core/lanes_avx2.hpp"

#define POLYDEM_SIMD simd_avx2
#define POLYDEM_PAIR_LAW pair_law_avx512
#define POLYDEM_PAIR_REST pair_rest_avx512
#include "contact/joint_law_kernel.inc"
