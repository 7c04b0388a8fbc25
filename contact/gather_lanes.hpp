// The gather's AVX2 code path: gather_block_force (gather.hpp) with a
// block's force and moment each held in one register, x y z in three lanes.
//
// A block's force is a sum in its gather list's fixed order (the
// determinism contract): a chain of dependent additions that no lane may
// split, and lanes across blocks pay more to fill than they save (docs/
// benchmarks.md, session 13). What one entry does is three components of
// the same operations: fk = s·F, f += fk, m += (p − x) × fk, the cross
// product's components (d_y·k_z − d_z·k_y, d_z·k_x − d_x·k_z,
// d_x·k_y − d_y·k_x) summed one lane over and put in place once per block.
// Each lane rounds exactly the portable loop's operations in its order (no
// fused multiply-add), so a block's force and moment have the same bits on
// either path; the fourth lane reads nothing (masked loads) and is not
// stored. The chain, not the arithmetic, sets a block's time: gather_two
// keeps a second block's chain in flight beside it (session 16).
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

// gather_block_force for block i, the same bits. Only call when
// lanes_available() (core/code_path.hpp).
void gather_block(const GatherArrays& a, int i);

// gather_block for blocks i and j, their entries taken in turn: each sum is
// still its own chain in its own order (the same bits), and the other
// block's chain runs in the additions' latency (measured on the spire, one
// thread: the gather and update 30.3 → 27.4 µs a step, docs/benchmarks.md).
void gather_two(const GatherArrays& a, int i, int j);

}  // namespace polydem::gather_lanes
