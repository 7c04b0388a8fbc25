// The joint law's kernel (joint_law_lanes_kernel.inc) for AVX2: lanes::pair_law.
#define POLYDEM_PAIR_LAW pair_law
#include "contact/joint_law_lanes_kernel.inc"
