// The rotation by a rotation vector w (the exponential map) as a unit
// quaternion. A step turns a block by far less than 1e-3 rad, where the
// fourth-order series is exact to round-off and avoids sin/cos; larger
// turns take the closed form (Eigen's AngleAxis). The blocks' update kernel
// (block_update_kernel.inc) performs the same operations lane by lane.
#pragma once

#include "geometry/polyhedron.hpp"

#include <cmath>

namespace polydem {

// The large turn out of line: the series, taken at every step of every
// block, inlines into the update.
[[gnu::noinline]] inline Quat large_rotation_quaternion(const Vec3& w, double a2) {
  const double angle = std::sqrt(a2);
  return Quat(Eigen::AngleAxisd(angle, w / angle));
}

[[gnu::always_inline]] inline Quat rotation_quaternion(const Vec3& w) {
  const double a2 = w.squaredNorm();
  if (a2 < 1e-6) [[likely]] {
    const double c = 1.0 - a2 / 8.0 + a2 * a2 / 384.0;    // cos(a/2)
    const double h = 0.5 - a2 / 48.0 + a2 * a2 / 3840.0;  // sin(a/2)/a
    return Quat(c, h * w.x(), h * w.y(), h * w.z());
  }
  return large_rotation_quaternion(w, a2);
}

}  // namespace polydem
