// The joint law's kernels (joint_law_kernel.inc) in plain doubles:
// lanes::pair_law_portable and lanes::pair_rest_portable, every machine's.
#include "core/lanes_portable.hpp"

#define POLYDEM_SIMD simd_portable
#define POLYDEM_PAIR_LAW pair_law_portable
#define POLYDEM_PAIR_REST pair_rest_portable
#include "contact/joint_law_kernel.inc"
