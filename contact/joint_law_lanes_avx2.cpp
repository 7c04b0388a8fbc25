// The joint law's kernels (joint_law_lanes_kernel.inc) for AVX2: lanes::pair_law
// and lanes::pair_rest.
#define POLYDEM_PAIR_LAW pair_law
#define POLYDEM_PAIR_REST pair_rest
#include "contact/joint_law_lanes_kernel.inc"
