// Horizontal ground acceleration a_g(t) along a fixed direction, and the
// base velocity v_g(t) = ∫ a_g dt that kinematic base blocks follow.
//
// The two ways of applying it are equivalent for a rigid base: an inertial
// body force −m·a_g on every free block (the blocks are seen in the moving
// base's frame), or kinematic base blocks moving with v_g (the blocks are seen
// in a fixed frame). A record arrives here already sampled (io reads files).
#pragma once

#include "core/scene_spec.hpp"

#include <functional>
#include <vector>

namespace polydem {

// A caller's own ground acceleration a(t) (m/s², world, any direction), for
// loads a deck cannot describe: a vertical record beside the horizontal one,
// a motion computed by another code. Always applied as a body force −m·a(t)
// on every free block, added after the deck's motion; its work is load work
// in the ledger. Called once per step, from one thread, at the step's time.
using ExtraGroundAcceleration = std::function<Vec3(double t)>;

struct GroundMotion {
  GroundMotionKind kind = GroundMotionKind::none;
  GroundMotionApplication applied_as = GroundMotionApplication::body_force;
  Vec3 direction{1, 0, 0};
  double start_time = 0, acceleration = 0, rate = 0, period = 1, rise_time = 0;
  // Record samples (m/s²) at record_time (s, increasing), and the velocity
  // at each sample by the trapezoidal rule so that v_g is the exact integral
  // of the piecewise-linear acceleration.
  std::vector<double> record_time, record_acceleration, record_velocity;
  // The caller's own acceleration (run/run_scene.hpp RunControl); empty for
  // the deck's motion alone, which then has the same bits as without it.
  ExtraGroundAcceleration extra;

  // Further components ([[ground_motion.component]]: e.g. the other
  // horizontal record and the vertical one of a PEER NGA set), each with its
  // own direction, kind, scale and start time, applied as this one is.
  std::vector<GroundMotion> components;

  // This component (the section's own keys) is active; its scalar
  // acceleration is the one histories, checks and the assessment read.
  bool active() const { return kind != GroundMotionKind::none; }
  // Some component is (the section's or a further one).
  bool any_active() const { return active() || !components.empty(); }
  double acceleration_at(double t) const;  // m/s², this component along `direction`
  double velocity_at(double t) const;      // m/s
  // The ground's acceleration and velocity as vectors: Σ a_k(t)·direction_k
  // over the active components, the section's first, then the others in deck
  // order. Without further components exactly acceleration_at(t)·direction
  // (the bits of a one-component deck); a component whose acceleration is
  // zero (scale = 0) adds +0 or −0 to each coordinate, which leaves every
  // non-zero sum unchanged.
  Vec3 acceleration_vector(double t) const;
  Vec3 velocity_vector(double t) const;
};

// The absolute acceleration of a linear oscillator (frequency f_hz, damping
// ratio zeta) on the given base acceleration, by Newmark's average
// acceleration method on substeps of the record's own steps (exact for
// piecewise-linear input as the substeps shrink; 20 per step keeps the
// period error below 1e-4 for f·dt ≤ 0.2).
std::vector<double> oscillator_absolute_acceleration(const std::vector<double>& time,
                                                     const std::vector<double>& base_acceleration, double f_hz,
                                                     double zeta);

// record_time/record_acceleration may be empty unless spec.kind == record.
GroundMotion make_ground_motion(const GroundMotionSpec& spec, std::vector<double> record_time = {},
                                std::vector<double> record_acceleration = {});

}  // namespace polydem
