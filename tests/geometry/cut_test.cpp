// Cutting blocks by joint sets: the pieces fill the block exactly (volumes
// and first moments sum to the block's to 1e-12), never overlap, are convex
// and valid, and a cut parallel to a box's faces gives the corners one
// would list by hand, bit for bit.
#include "geometry/cut.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shapes.hpp"

namespace polydem {
namespace {

void expect_fills(const Polyhedron& parent, const std::vector<Polyhedron>& pieces) {
  const MassProperties whole = mass_properties(parent);
  double v = 0;
  Vec3 moment = Vec3::Zero();
  for (const Polyhedron& p : pieces) {
    EXPECT_NO_THROW(validate(p));
    const MassProperties mp = mass_properties(p);
    EXPECT_GT(mp.volume, 0);
    v += mp.volume;
    moment += mp.volume * mp.centroid;
  }
  EXPECT_NEAR(v, whole.volume, 1e-12 * whole.volume);
  const double size = bounding_box_diagonal(parent.vertices);
  EXPECT_LE((moment - whole.volume * whole.centroid).norm(), 1e-12 * whole.volume * size);
  // No two pieces overlap: at most touching (penetration at round-off).
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) EXPECT_LE(penetration_depth(pieces[i], pieces[j]), 1e-12 * size);
}

TEST(JointSetNormal, GeologicalConventionWithExactRightAngles) {
  EXPECT_EQ(joint_set_normal(0, 0), Vec3(0, 0, 1));      // horizontal bed
  EXPECT_EQ(joint_set_normal(0, 123), Vec3(0, 0, 1));    // dip direction of a flat plane is irrelevant
  EXPECT_EQ(joint_set_normal(90, 0), Vec3(0, 1, 0));     // vertical, striking east-west, facing north
  EXPECT_EQ(joint_set_normal(90, 90), Vec3(1, 0, 0));    // vertical, facing east
  EXPECT_EQ(joint_set_normal(90, 180), Vec3(0, -1, 0));  // facing south
  EXPECT_EQ(joint_set_normal(90, 270), Vec3(-1, 0, 0));  // facing west
  // Dipping 30° towards the east: the plane descends eastwards, so its
  // upward normal leans east: (sin 30°, 0, cos 30°).
  const Vec3 n = joint_set_normal(30, 90);
  EXPECT_NEAR(n.x(), 0.5, 1e-15);
  EXPECT_EQ(n.y(), 0.0);
  EXPECT_NEAR(n.z(), std::sqrt(3.0) / 2, 1e-15);
  // A line going down the dip direction stays in the plane when it falls
  // by tan(dip) per metre.
  const Vec3 m = joint_set_normal(40, 215);
  const double a = 215 * std::numbers::pi / 180;
  const Vec3 down(std::sin(a), std::cos(a), -std::tan(40 * std::numbers::pi / 180));
  EXPECT_NEAR(m.dot(down), 0, 1e-15);
  EXPECT_NEAR(m.norm(), 1, 1e-15);
}

TEST(SplitByPlane, BoxCutHorizontallyEqualsTheHandListedBoxesBitForBit) {
  const Polyhedron box = make_box(Vec3(1, 2, 1), Vec3(0.5, 1, 0.5));
  const PlanePieces p = split_by_plane(box, Vec3::UnitZ(), 0.25);
  std::vector<Vec3> lower, upper;
  for (double x : {0.0, 1.0})
    for (double y : {0.0, 2.0}) {
      lower.insert(lower.end(), {Vec3(x, y, 0), Vec3(x, y, 0.25)});
      upper.insert(upper.end(), {Vec3(x, y, 0.25), Vec3(x, y, 1)});
    }
  const Polyhedron lo = convex_hull(lower), up = convex_hull(upper);
  EXPECT_EQ(p.below.vertices, lo.vertices);
  EXPECT_EQ(p.below.faces, lo.faces);
  EXPECT_EQ(p.above.vertices, up.vertices);
  EXPECT_EQ(p.above.faces, up.faces);
  EXPECT_EQ(mass_properties(p.below).volume, 0.5);
  EXPECT_EQ(mass_properties(p.above).volume, 1.5);
}

TEST(SplitByPlane, PlaneThroughCornersAndMissingPlanes) {
  // The diagonal plane x = y through two vertical edges of a unit cube: two
  // prisms, half the volume each, no crossing point added.
  const Polyhedron cube = make_box(Vec3(1, 1, 1), Vec3(0.5, 0.5, 0.5));
  const Vec3 n = Vec3(1, -1, 0).normalized();
  const PlanePieces p = split_by_plane(cube, n, 0.0);
  EXPECT_EQ(p.below.vertices.size(), 6u);
  EXPECT_EQ(p.above.vertices.size(), 6u);
  expect_fills(cube, {p.below, p.above});
  EXPECT_NEAR(mass_properties(p.below).volume, 0.5, 1e-15);
  // A plane touching a face, or missing the block, does not cut it.
  EXPECT_THROW(split_by_plane(cube, Vec3::UnitZ(), 1.0), GeometryError);
  EXPECT_THROW(split_by_plane(cube, Vec3::UnitZ(), 2.0), GeometryError);
  // One passing 1e-9 m from a corner without going through it is refused.
  const Polyhedron pyramid = test::square_pyramid(1.0, 1.0);
  EXPECT_THROW(split_by_plane(pyramid, Vec3::UnitZ(), 1.0 - 1e-9), GeometryError);
}

TEST(CutByJointSet, RandomBlocksAndJointSetsFillTheBlockExactly) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0, 1);
  int cut = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Polyhedron prism = make_prism(test::octagon(0.3 + u(rng)), -0.4, 0.2 + 2 * u(rng));
    const Polyhedron block = transformed(prism, test::random_rotation(rng), Vec3(u(rng), u(rng), u(rng)));
    JointSet set;
    set.normal = joint_set_normal(90 * u(rng), 360 * u(rng));
    set.origin = mass_properties(block).centroid - 0.6 * set.normal;
    set.spacing = 0.05 + 0.3 * u(rng);
    set.count = 1 + static_cast<int>(6 * u(rng));
    set.min_thickness = 0.01;
    const std::vector<Polyhedron> pieces = cut_by_joint_set(block, set);
    cut += pieces.size() > 1;
    expect_fills(block, pieces);
    // Ordered along the normal, and no piece thinner than min_thickness.
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const double c = set.normal.dot(mass_properties(pieces[i]).centroid);
      if (i > 0) {
        EXPECT_GT(c, set.normal.dot(mass_properties(pieces[i - 1]).centroid));
      }
      double lo = 1e300, hi = -1e300;
      for (const Vec3& v : pieces[i].vertices) {
        lo = std::min(lo, set.normal.dot(v));
        hi = std::max(hi, set.normal.dot(v));
      }
      EXPECT_GE(hi - lo, set.min_thickness);
    }
    // A second, crossing set cuts the pieces again.
    JointSet cross = set;
    cross.normal = joint_set_normal(90, 360 * u(rng));
    cross.origin = mass_properties(block).centroid;
    cross.count = 2;
    std::vector<Polyhedron> all;
    for (const Polyhedron& p : pieces)
      for (Polyhedron& q : cut_by_joint_set(p, cross)) all.push_back(std::move(q));
    expect_fills(block, all);
  }
  EXPECT_GT(cut, 30);  // the test exercised real cuts
}

TEST(CutByJointSet, SliversAreNotMade) {
  const Polyhedron box = make_box(Vec3(1, 1, 1), Vec3(0.5, 0.5, 0.5));
  JointSet set;
  set.origin = Vec3(0, 0, 0.0005);
  set.min_thickness = 0.001;
  EXPECT_EQ(cut_by_joint_set(box, set).size(), 1u);  // would cut off 0.5 mm
  set.min_thickness = 0.0001;
  EXPECT_EQ(cut_by_joint_set(box, set).size(), 2u);
  // Planes 0.3 apart from z = 0.3: 0.3, 0.6, 0.9 (the last leaves 0.1 > 0.05).
  set.origin = Vec3(0, 0, 0.3);
  set.spacing = 0.3;
  set.count = 5;
  set.min_thickness = 0.05;
  EXPECT_EQ(cut_by_joint_set(box, set).size(), 4u);
  set.min_thickness = 0.15;  // the plane at 0.9 would cut off 0.1: skipped
  EXPECT_EQ(cut_by_joint_set(box, set).size(), 3u);
}

TEST(Overlap, PenetrationDepthAndSharedVolumeOfBoxes) {
  const Polyhedron a = make_box(Vec3(1, 1, 1));
  const Polyhedron b = make_box(Vec3(1, 1, 1), Vec3(0.9, 0.2, 0));
  EXPECT_NEAR(penetration_depth(a, b), 0.1, 1e-15);
  EXPECT_NEAR(*overlap_volume(a, b), 0.1 * 0.8, 1e-15);
  const Polyhedron touching = make_box(Vec3(1, 1, 1), Vec3(1, 0.3, 0));
  EXPECT_EQ(penetration_depth(a, touching), 0.0);
  EXPECT_EQ(*overlap_volume(a, touching), 0.0);
  const Polyhedron apart = make_box(Vec3(1, 1, 1), Vec3(1.5, 1.5, 0));
  EXPECT_LT(penetration_depth(a, apart), 0.0);
  // Edge against edge: a cube turned 45° about z and x, its lowest edge
  // pushed 0.05 into the top face of a slab... the SAT axis is the face normal.
  const Mat3 R = (Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitX())).toRotationMatrix();
  const Polyhedron tilted = transformed(make_box(Vec3(1, 1, 1)), R, Vec3(0, 0, 0.5 + std::sqrt(0.5) - 0.05));
  Vec3 axis;
  EXPECT_NEAR(penetration_depth(a, tilted, &axis), 0.05, 1e-12);
  EXPECT_NEAR(std::abs(axis.z()), 1.0, 1e-12);
}

}  // namespace
}  // namespace polydem
