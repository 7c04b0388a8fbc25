// The blocks' update kernel (block_update_kernel.inc) in plain doubles:
// block_lanes::advance_four_portable.
#include "core/lanes_portable.hpp"

#define POLYDEM_SIMD simd_portable
#define POLYDEM_ADVANCE_FOUR advance_four_portable
#include "integrators/block_update_kernel.inc"
