// The joint law's kernel (joint_law_lanes_kernel.inc) compiled for
// AVX-512VL: lanes::pair_law_wide. The same four-lane 256-bit arithmetic,
// intrinsic for intrinsic, so the same bits; what AVX-512VL adds is 32
// vector registers instead of 16, and the kernel, which holds a pair's
// frame and four subcontacts' state at once, spills far less to the stack
// (33 stack operands in the object against the AVX2 copy's 104; 11-12 %
// less time in the joint law on the Intel Xeon, docs/benchmarks.md). Built
// with -ffp-contract=off like every file (contact/CMakeLists.txt): AVX-512
// has fused multiply-adds, which would change the bits.
#define POLYDEM_PAIR_LAW pair_law_wide
#define POLYDEM_PAIR_REST pair_rest_wide
#include "contact/joint_law_lanes_kernel.inc"
