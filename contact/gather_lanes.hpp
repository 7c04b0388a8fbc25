// The gather's kernels: gather.hpp's per-block sum with a block's force and
// moment each held in one lane vector, x y z in lanes 0-2.
//
// A block's force is a sum in its gather list's fixed order (the
// determinism contract): a chain of dependent additions that no lane may
// split, and lanes across blocks pay more to fill than they save. What one
// entry does is three components of the same operations: fk = s·F,
// f += fk, m += (p − x) × fk, the cross product's components
// (d_y·k_z − d_z·k_y, d_z·k_x − d_x·k_z, d_x·k_y − d_y·k_x) summed one lane
// over and put in place once per block. Written once (gather_kernel.inc)
// over a lane type (core/code_path.hpp), compiled in plain doubles and in AVX2
// lanes: the same bits. The chain, not the arithmetic, sets a block's time:
// gather_two keeps a second block's chain in flight beside it.
#pragma once

namespace polydem::gather_lanes {

// ContactSet's gather lists and force/point slots, and the blocks'
// centroid and contact force/moment records, as plain pointers (Vec3: x y z).
struct GatherArrays {
  const int* offset;       // gather_offset, blocks + 1 entries
  const int* entry;        // gather_sub
  const double* sign;      // gather_sign
  const double* force;     // sub.force
  const double* point;     // sub.point
  const double* centroid;  // BlockState::position
  double* contact_force;   // BlockState::contact_force
  double* contact_torque;  // BlockState::contact_torque
};

// Block i's joint force and moment about its centroid into its records.
// The AVX2 kernels only where lanes_available() (core/code_path.hpp).
void gather_block_portable(const GatherArrays& a, int i);
void gather_block_avx2(const GatherArrays& a, int i);

// The same for blocks i and j, their entries taken in turn: each sum is
// still its own chain in its own order (the same bits), and the other
// block's chain runs in the additions' latency.
void gather_two_portable(const GatherArrays& a, int i, int j);
void gather_two_avx2(const GatherArrays& a, int i, int j);

struct GatherKernels {
  void (*block)(const GatherArrays&, int);
  void (*two)(const GatherArrays&, int, int);
};

}  // namespace polydem::gather_lanes
