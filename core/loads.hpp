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

namespace polydem {

// The ground acceleration felt as a body force at time t (m/s², world):
// a_g(t) along the record's direction when the motion is applied as a body
// force, zero otherwise (no motion, or kinematic base blocks).
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

// Work (J) of a force (N) on a point moving at `velocity` (m/s, the
// mid-step velocity) over a step dt (s): dt·F·v.
inline double load_work(double dt, const Vec3& force, const Vec3& velocity) { return dt * force.dot(velocity); }

}  // namespace polydem
