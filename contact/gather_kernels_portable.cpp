// The gather's kernels (gather_kernel.inc) in plain doubles:
// gather_lanes::gather_block_portable and gather_two_portable.
#include "core/lanes_portable.hpp"

#define POLYDEM_SIMD simd_portable
#define POLYDEM_GATHER_BLOCK gather_block_portable
#define POLYDEM_GATHER_TWO gather_two_portable
#include "contact/gather_kernel.inc"
