// Loads: the external force on a free block is m·g − m·a_g (the contact
// force is added by the time step), with the bits the time step has always
// had; the ground acceleration is a body force only when the motion is
// applied as one.
#include "core/loads.hpp"

#include <gtest/gtest.h>

namespace polydem {
namespace {

Blocks one_block(double density) {
  BlockSpec s;
  s.name = "b";
  s.density = density;
  s.shape = make_box(Vec3(1, 2, 3));
  return build_blocks({s});
}

TEST(Loads, ExternalForceIsWeightLessGroundInertia) {
  const Blocks b = one_block(2000.0);  // m = 12000 kg
  const double m = b.props.mass[0];
  ASSERT_DOUBLE_EQ(m, 12000.0);
  const Vec3 g(0.3, -0.1, -9.81);
  const Vec3 a(1.7, 0.25, -0.03);
  const Vec3 contact(-3.1e3, 2.2e4, 1.1e5);
  const Vec3 f = external_force(b.props, 0, g, a) + contact;
  // Bit for bit as the time step summed it before loads had a home.
  const Vec3 expected = m * g - m * a + contact;
  EXPECT_EQ(f.x(), expected.x());
  EXPECT_EQ(f.y(), expected.y());
  EXPECT_EQ(f.z(), expected.z());
  // And by hand.
  EXPECT_NEAR(f.x(), 12000.0 * (0.3 - 1.7) - 3.1e3, 1e-9);
  EXPECT_NEAR(f.y(), 12000.0 * (-0.1 - 0.25) + 2.2e4, 1e-9);
  EXPECT_NEAR(f.z(), 12000.0 * (-9.81 + 0.03) + 1.1e5, 1e-9);
  // The ground's part alone.
  EXPECT_EQ(ground_inertial_force(m, a), Vec3(-m * a));
  // At rest on still ground: the weight.
  EXPECT_EQ(external_force(b.props, 0, g, Vec3::Zero()), Vec3(m * g));
}

TEST(Loads, GroundAccelerationIsABodyForceOnlyWhenAppliedAsOne) {
  GroundMotionSpec spec;
  spec.kind = GroundMotionKind::constant;
  spec.acceleration = 2.0;
  spec.direction = Vec3(0, 1, 0);
  const GroundMotion body = make_ground_motion(spec);
  EXPECT_EQ(ground_body_acceleration(body, 1.0), Vec3(0, 2.0, 0));
  spec.applied_as = GroundMotionApplication::kinematic;
  EXPECT_EQ(ground_body_acceleration(make_ground_motion(spec), 1.0), Vec3::Zero());
  EXPECT_EQ(ground_body_acceleration(GroundMotion{}, 1.0), Vec3::Zero());
}

TEST(Loads, WorkIsForceTimesMidStepVelocityTimesStep) {
  EXPECT_DOUBLE_EQ(load_work(1e-3, Vec3(10, 0, -2), Vec3(0.5, 7, 1)), 1e-3 * (5.0 - 2.0));
}

}  // namespace
}  // namespace polydem
