// build_blocks: mass from density × volume, body frame at the centroid on
// the principal axes (diagonal inertia), body-frame shape consistent with the
// world shape, initial velocities and angular momenta.
//
// Tolerances: mass properties are exact up to round-off on O(1) coordinates,
// so 1e-12 relative; the eigen-decomposition adds a few ulps of the largest
// moment, so off-diagonals are checked to 1e-12 of it.
#include "core/blocks.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace polydem {
namespace {

// A 1 × 2 × 3 box turned about a skew axis and moved away from the origin:
// its principal axes are not the world axes.
BlockSpec turned_box() {
  BlockSpec s;
  s.name = "box";
  s.density = 2000.0;
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  s.shape = transformed(make_box(Vec3(1, 2, 3)), R, Vec3(4, -1, 2));
  return s;
}

// An irregular tetrahedron: no symmetry at all.
BlockSpec tetrahedron() {
  BlockSpec s;
  s.name = "tet";
  s.density = 2600.0;
  s.shape = make_polyhedron({Vec3(0, 0, 0), Vec3(2, 0, 0.1), Vec3(0.3, 1.5, 0), Vec3(0.4, 0.2, 1.2)},
                            {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  return s;
}

void expect_principal_frame(const Blocks& b, int i, const BlockSpec& spec) {
  const MassProperties mp = mass_properties(spec.shape);
  // Mass = density × volume.
  EXPECT_NEAR(b.props.mass[i], spec.density * mp.volume, 1e-12 * b.props.mass[i]);
  EXPECT_NEAR(b.props.inv_mass[i], 1.0 / b.props.mass[i], 1e-12 / b.props.mass[i]);
  // Centroid.
  EXPECT_NEAR((b.state.position[i] - mp.centroid).norm(), 0.0, 1e-12);
  // R·diag(I)·Rᵀ is the world inertia tensor.
  const Mat3& R = b.state.rotation[i];
  EXPECT_NEAR((R * R.transpose() - Mat3::Identity()).norm(), 0.0, 1e-14);
  EXPECT_NEAR(R.determinant(), 1.0, 1e-14);
  const Mat3 world = spec.density * mp.inertia;
  const double scale = world.norm();
  const Mat3 rebuilt = R * b.props.principal_inertia[i].asDiagonal() * R.transpose();
  EXPECT_NEAR((rebuilt - world).norm(), 0.0, 1e-12 * scale);
  // The body-frame shape has its centroid at the origin and a diagonal tensor.
  const MassProperties local = mass_properties(b.props.local_shape[i]);
  EXPECT_NEAR(local.centroid.norm(), 0.0, 1e-12);
  const Mat3 Ib = spec.density * local.inertia;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (r != c) {
        EXPECT_NEAR(Ib(r, c), 0.0, 1e-12 * scale) << "(" << r << "," << c << ")";
      }
  EXPECT_NEAR((Ib.diagonal() - b.props.principal_inertia[i]).norm(), 0.0, 1e-12 * scale);
  // Vertex k of the body-frame shape maps back onto world vertex k.
  ASSERT_EQ(b.props.local_shape[i].vertices.size(), spec.shape.vertices.size());
  for (std::size_t k = 0; k < spec.shape.vertices.size(); ++k)
    EXPECT_NEAR((world_vertex(b, i, static_cast<int>(k)) - spec.shape.vertices[k]).norm(), 0.0, 1e-12);
  // Bounding radius and size.
  EXPECT_NEAR(b.props.radius[i], bounding_radius(spec.shape, mp.centroid), 1e-12);
  EXPECT_NEAR(b.props.size[i], std::cbrt(mp.volume), 1e-12);
}

TEST(BuildBlocks, TurnedBoxIsOnItsPrincipalAxes) {
  const BlockSpec spec = turned_box();
  const Blocks b = build_blocks({spec});
  ASSERT_EQ(b.count, 1);
  EXPECT_NEAR(b.props.mass[0], 2000.0 * 6.0, 1e-9);
  // Moments of a 1 × 2 × 3 box: m(b²+c²)/12 …, in the solver's ascending order.
  const double m = 12000.0;
  const Vec3 expected(m * (1 + 4) / 12.0, m * (1 + 9) / 12.0, m * (4 + 9) / 12.0);
  EXPECT_NEAR((b.props.principal_inertia[0] - expected).norm(), 0.0, 1e-12 * expected.norm());
  expect_principal_frame(b, 0, spec);
}

TEST(BuildBlocks, IrregularTetrahedronIsOnItsPrincipalAxes) {
  const BlockSpec spec = tetrahedron();
  const Blocks b = build_blocks({spec});
  expect_principal_frame(b, 0, spec);
}

TEST(BuildBlocks, MotionKindsAndInitialVelocities) {
  BlockSpec free = turned_box();
  free.velocity = Vec3(0.1, -0.2, 0.3);
  free.angular_velocity = Vec3(1.0, -2.0, 0.5);
  BlockSpec fixed = tetrahedron();
  fixed.name = "fixed";
  fixed.motion = BlockMotion::fixed;
  fixed.velocity = Vec3(1, 1, 1);  // ignored: fixed blocks never move
  BlockSpec kin = tetrahedron();
  kin.name = "kin";
  kin.motion = BlockMotion::kinematic;
  kin.shape = transformed(kin.shape, Mat3::Identity(), Vec3(10, 0, 0));
  kin.velocity = Vec3(0.5, 0, 0);
  const Blocks b = build_blocks({free, fixed, kin});
  ASSERT_EQ(b.count, 3);
  EXPECT_EQ(b.free_blocks, std::vector<int>{0});
  EXPECT_EQ(b.kinematic_blocks, std::vector<int>{2});
  EXPECT_EQ(b.find("kin"), 2);
  EXPECT_EQ(b.find("nope"), -1);
  EXPECT_TRUE(b.is_free(0));
  EXPECT_FALSE(b.is_free(1));
  // Free: its velocity, and L = R·diag(I)·Rᵀ·ω.
  EXPECT_EQ(b.state.velocity[0], free.velocity);
  EXPECT_EQ(b.state.angular_velocity[0], free.angular_velocity);
  const Mat3& R = b.state.rotation[0];
  const Mat3 I = R * b.props.principal_inertia[0].asDiagonal() * R.transpose();
  EXPECT_NEAR((b.state.angular_momentum[0] - I * free.angular_velocity).norm(), 0.0,
              1e-12 * (I * free.angular_velocity).norm());
  // Fixed: no velocity, no inverse mass or inertia (it cannot be moved).
  EXPECT_EQ(b.state.velocity[1], Vec3::Zero());
  EXPECT_EQ(b.props.inv_mass[1], 0.0);
  EXPECT_EQ(b.props.inv_principal_inertia[1], Vec3::Zero());
  // Kinematic: keeps its velocity, is not integrated, does not rotate.
  EXPECT_EQ(b.state.velocity[2], kin.velocity);
  EXPECT_EQ(b.props.inv_mass[2], 0.0);
  EXPECT_EQ(b.state.angular_velocity[2], Vec3::Zero());
  EXPECT_GT(b.props.mass[2], 0.0);
  // Initial pose is remembered.
  EXPECT_EQ(b.initial_position, b.state.position);
}

}  // namespace
}  // namespace polydem
