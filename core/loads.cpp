#include "core/loads.hpp"

namespace polydem {

Vec3 ground_body_acceleration(const GroundMotion& motion, double t) {
  const bool body_force = motion.active() && motion.applied_as == GroundMotionApplication::body_force;
  const Vec3 a = body_force ? Vec3(motion.acceleration_at(t) * motion.direction) : Vec3::Zero();
  if (!motion.extra) return a;
  return a + motion.extra(t);
}

}  // namespace polydem
