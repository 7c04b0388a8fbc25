// Loads: the external (non-contact) forces on the blocks.
//
// A load is a force on a block that does not come from its joints. The time
// step adds it to the gathered contact force, F = external + contact, and
// the energy ledger counts the work it does, dt·F_load·v (v at mid-step),
// so that the balance kinetic + potential + strain + dissipated − load work
// stays at zero. Two loads exist today:
//   - gravity, m·g, on every free block (its work is the ledger's
//     gravitational potential, −Σ m g·x, so it is not counted as load work);
//   - the ground motion applied as a body force: the blocks are seen in the
//     frame of the moving base, which adds the inertial force −m·a_g(t).
// (The ground motion applied through kinematic base blocks is not a load on
// the free blocks: the base moves and pushes them through the joints; its
// work is −dt·F_joint·v on the base blocks.)
//
// Adding a load, e.g. a point force P at a body point r on block i: give it
// a term here (the force, and the torque (R·r)×P about the centroid, as a
// function of the block, the time and what the deck gives), add it in
// external_force() (or an external_torque()) for the blocks it acts on, and
// count dt·P·v(point) in the ledger with load_work(). A change of the sum's
// order changes the bits of every result: append new terms at the end.
#pragma once

#include "core/blocks.hpp"
#include "core/ground_motion.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace polydem {

// ---- Point loads and prescribed motions ([[load]], [[prescribe]]) ----
//
// A [[load]] puts a force P (at a point fixed in the block, by default its
// centroid) and a moment M on each block it selects, times f(t), a
// piecewise-linear table (1 without one). On free block i the time step adds
// F = f(t)·P and T = (R·r)×F + f(t)·M (r: the point in the body frame) to the
// force and torque after the contact force (a new last term of the sum, so
// a deck without loads keeps its bits), and the ledger books their work
// dt·(F·v + T·ω) at the mid-step velocities: the power of a force at a point
// moving at v + ω×(R·r) is F·v + ((R·r)×F)·ω.
//
// A [[prescribe]] makes its blocks kinematic: each moves with the velocity
// v(t) (constant or a table) and turns with the angular velocity ω about its
// centroid; the ground motion's kinematic base does not move them. Their
// joints push the free blocks, and the ledger books the work the blocks do
// through the joints, −dt·(F_joint·v + T_joint·ω), as for the base.

// f(t) of a table (the value's x, or the vector): linear between its points,
// constant beyond its ends.
Vec3 table_value(const TimeTable& table, double t);

struct PointLoad {
  int block = 0;
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  Vec3 arm_local = Vec3::Zero();  // point − centroid, body frame
  bool at_point = false;
  TimeTable factor;
};

struct Prescription {
  int block = 0;
  Vec3 velocity = Vec3::Zero(), angular_velocity = Vec3::Zero();
  TimeTable velocity_table;
  TimeTable displacement_table;  // when given: the position is start + u(t)
  Vec3 start = Vec3::Zero();     // the block's centroid at t = 0
  Vec3 velocity_at(double t) const { return velocity_table.empty() ? velocity : table_value(velocity_table, t); }
};

struct BlockLoads {
  std::vector<PointLoad> loads;          // in deck order, then block order
  std::vector<Prescription> prescribed;  // one per prescribed block (the last [[prescribe]] selecting it)
  bool empty() const { return loads.empty() && prescribed.empty(); }
};

// The blocks a selection names: every block listed by name and every block
// of every group listed, in block order, each once.
std::vector<int> select_blocks(const std::vector<BlockSpec>& blocks, const std::vector<std::string>& names,
                               const std::vector<std::string>& groups);

// Makes the blocks the [[prescribe]] tables select kinematic, with their
// velocity at t = 0 (setup calls it before building the blocks).
void apply_prescriptions(std::vector<BlockSpec>& blocks, const std::vector<PrescribeSpec>& prescribed);

// The loads and prescriptions resolved to blocks (points in body frames).
BlockLoads resolve_loads(const Blocks& blocks, const std::vector<BlockSpec>& specs,
                         const std::vector<LoadSpec>& loads, const std::vector<PrescribeSpec>& prescribed);

// The ground acceleration felt as a body force at time t (m/s², world):
// a_g(t) along the record's direction when the motion is applied as a body
// force, zero otherwise (no motion, or kinematic base blocks); plus the
// caller's extra acceleration when there is one (GroundMotion::extra).
Vec3 ground_body_acceleration(const GroundMotion& motion, double t);

// The inertial force of the moving base frame on a block of mass m (kg):
// −m·a_g (N).
inline Vec3 ground_inertial_force(double mass, const Vec3& ground_acceleration) {
  return -mass * ground_acceleration;
}

// The external (non-contact) force on free block i (N): m·g − m·a_g, for
// gravity g and ground (body-force) acceleration a_g in m/s². Evaluated as
// m·g + (−m·a_g), which has the same bits as m·g − m·a_g.
inline Vec3 external_force(const BlockProperties& props, int i, const Vec3& gravity,
                           const Vec3& ground_acceleration) {
  const double m = props.mass[i];
  return m * gravity + ground_inertial_force(m, ground_acceleration);
}

// Gravity at time t under a rise time T (simulation.gravity_rise_time): it
// rises linearly from 0 at t = 0 to g at t = T and holds, so that the joints
// load quasi-statically instead of being struck by the full weight (a sudden
// load overshoots to twice the static deflection and, with no damping, the
// joints unload every period: frictional blocks ratchet). Returns g itself
// (the same bits) when T is 0 or t ≥ T. Under the rise the applied force
// differs from the m·g of the ledger's potential by m·(g(t) − g): the time
// step counts that difference as load work.
inline Vec3 gravity_at(const Vec3& gravity, double rise_time, double t) {
  if (!(t < rise_time)) return gravity;
  return (t / rise_time) * gravity;
}

// Cundall's local (non-viscous) damping of a generalised force F on a body
// moving at v, component by component: F − α·|F|·sign(v) (Cundall 1987; as
// in UDEC, 3DEC and PFC). It removes a fraction α of the force's work in
// every oscillation whatever its frequency, and vanishes at rest, so it
// changes the way to equilibrium, never the equilibrium. Used only by the
// static stage (run/equilibrium.hpp).
inline Vec3 locally_damped(const Vec3& force, const Vec3& velocity, double alpha) {
  Vec3 f = force;
  for (int k = 0; k < 3; ++k) {
    const double v = velocity[k];
    if (v > 0) f[k] -= alpha * std::abs(force[k]);
    else if (v < 0) f[k] += alpha * std::abs(force[k]);
  }
  return f;
}

// Work (J) of a force (N) on a point moving at `velocity` (m/s, the
// mid-step velocity) over a step dt (s): dt·F·v.
inline double load_work(double dt, const Vec3& force, const Vec3& velocity) { return dt * force.dot(velocity); }

}  // namespace polydem
