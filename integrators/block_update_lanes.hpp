// The blocks' update four blocks at a time: Simulation::advance_block's
// update (simulation.cpp) for the free blocks of the dynamic stage without
// point loads, written once (block_update_kernel.inc) over a lane type
// (core/code_path.hpp), compiled in plain doubles and in AVX2 lanes.
//
// Each lane performs advance_block's IEEE operations in its order, including
// Eigen's on SSE2 (Rᵀ·v is ((a + b) + c) in every row, R·v ((a + b) + c) in
// rows 0 and 1 and a + (b + c) in row 2, the quaternion product is Eigen's
// SSE2 kernel's sums of pairs, a quaternion's squared norm is
// (x² + z²) + (y² + w²), the rotation matrix is Eigen's formula), with no
// fused multiply-add. The block state stays an array of Vec3, Quat and Mat3
// per block: four blocks' components are gathered into lanes and scattered
// back (the update's arithmetic is several times its loads and stores).
#pragma once

namespace polydem::block_lanes {

// The arrays of BlockState, BlockProperties and the Simulation's per-block
// records, as plain pointers (Vec3: x y z; Quat: x y z w; Mat3: 9 doubles,
// column-major, per block).
struct BlockArrays {
  double* position;
  double* velocity;
  double* angular_momentum;
  double* angular_velocity;
  double* orientation;
  double* rotation;
  const double* contact_force;
  const double* contact_torque;
  const double* mass;
  const double* inv_mass;
  const double* inv_inertia;  // principal, body frame
  double* velocity_mid;
  double* omega_mid;
  double* position_prev;
  double* orientation_prev;
  double* load_work;
};

struct StepConstants {
  double gravity[3];
  double ground_acceleration[3];
  double dt;     // this step
  double dv_dt;  // the velocity update's span, ½(dt_prev + dt)
};

// Advances the free blocks idx[0..3] (no point loads, gravity not rising,
// no local damping); fewer than four repeat the last index (its lanes then
// write the same values twice). The AVX2 kernel only where lanes_available()
// (core/code_path.hpp).
void advance_four_portable(const BlockArrays& a, const StepConstants& k, const int idx[4]);
void advance_four_avx2(const BlockArrays& a, const StepConstants& k, const int idx[4]);
using AdvanceFour = void (*)(const BlockArrays&, const StepConstants&, const int[4]);

}  // namespace polydem::block_lanes
