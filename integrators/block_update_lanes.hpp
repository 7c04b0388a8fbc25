// The blocks' update four blocks at a time: the AVX2 code path of
// Simulation::advance_block (simulation.cpp) for the dynamic stage's free
// blocks without point loads.
//
// The same bits as the portable update, as for the joint law's lanes
// (contact/joint_law_lanes.hpp): each lane performs the portable update's
// IEEE operations in its order, including Eigen's on SSE2 (Rᵀ·v is
// ((a + b) + c) in every row, R·v ((a + b) + c) in rows 0 and 1 and
// a + (b + c) in row 2, the quaternion product is Eigen's SSE2 kernel's
// sums of pairs, a quaternion's squared norm is (x² + z²) + (y² + w²), the
// rotation matrix is Eigen's formula), with no fused multiply-add. The
// block state stays an array of Vec3, Quat and Mat3 per block: four blocks'
// components are gathered into lanes and scattered back (the update's
// arithmetic is several times its loads and stores).
//
// A turn beyond the exponential's series (|θ|² ≥ 1e-6, a block spinning at
// over 100 rad/s at the spire's step) takes the portable update's closed
// form: advance_four() then writes nothing and returns false, and the
// caller updates those four blocks the portable way.
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

// Advances the four free blocks idx[0..3] (no point loads, gravity not
// rising, no local damping). False, and nothing written, if one of them
// turns too far for the series.
bool advance_four(const BlockArrays& a, const StepConstants& k, const int idx[4]);

}  // namespace polydem::block_lanes
