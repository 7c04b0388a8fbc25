// find_patch: narrow phase, common plane and contact patch, against
// configurations whose patch is known by hand (a unit cube on a larger base).
//
// Frame of every case: the base is a 3 × 3 × 1 box whose top face is z = 0,
// the cube is 1 m on a side. Areas are checked to 1e-12 m² (the values are
// sums of a few products of O(1) coordinates: round-off is ~1e-15) and
// separations to 1e-12 m for the same reason, unless a case says otherwise.
#include "contact/contact_patch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace polydem {
namespace {

constexpr double kTol = 1e-12;

struct Pair {
  Polyhedron base = make_box(Vec3(3, 3, 1));  // body frame: centred at the origin
  Polyhedron cube = make_box(Vec3(1, 1, 1));
  PosedBlock a{&base, Mat3::Identity(), Vec3(0, 0, -0.5)};  // top face at z = 0
  PosedBlock b{&cube, Mat3::Identity(), Vec3(0, 0, 0.5)};   // bottom face at z = 0
};

double area_sum(const Patch& p) {
  double s = 0;
  for (const PatchPoint& q : p.points) s += q.area;
  return s;
}

// Normal of the patch as the reference face's outward normal: +z from the
// base (ref_side 0) or −z from the cube's bottom (ref_side 1), in the pair's
// frame `Q`.
Vec3 expected_normal(const Patch& p, const Mat3& Q) { return p.ref_side == 0 ? Vec3(Q.col(2)) : Vec3(-Q.col(2)); }

Mat3 random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Quat q(n(rng), n(rng), n(rng), n(rng));
  q.normalize();
  return q.toRotationMatrix();
}

TEST(FindPatch, CubeRestingOnBaseHasFourCornerSubcontacts) {
  Pair p;
  const double gap = 1e-3, margin = 0.02;
  p.b.x.z() += gap;
  Patch patch;
  PatchScratch scratch;
  ASSERT_TRUE(find_patch(p.a, p.b, margin, -1, -1, patch, scratch));
  // Ties between the base's top face and the cube's bottom face go to the
  // first block: the base is the reference, the normal is +z out of it.
  EXPECT_EQ(patch.ref_side, 0);
  EXPECT_NEAR((patch.normal - Vec3(0, 0, 1)).norm(), 0.0, kTol);
  EXPECT_NEAR(patch.offset, 0.0, kTol);
  EXPECT_NEAR(patch.area, 1.0, kTol);
  EXPECT_NEAR(area_sum(patch), 1.0, kTol);
  ASSERT_EQ(patch.points.size(), 4u);
  // The points are the cube's bottom corners (±0.5, ±0.5, gap), each once.
  std::vector<bool> seen(4, false);
  for (const PatchPoint& q : patch.points) {
    EXPECT_NEAR(q.separation, gap, kTol);
    EXPECT_NEAR(q.area, 0.25, kTol);  // a square's fan about its centre: equal quarters
    EXPECT_NEAR(std::abs(q.point.x()), 0.5, kTol);
    EXPECT_NEAR(std::abs(q.point.y()), 0.5, kTol);
    EXPECT_NEAR(q.point.z(), gap, kTol);
    const int corner = (q.point.x() > 0 ? 1 : 0) + (q.point.y() > 0 ? 2 : 0);
    EXPECT_FALSE(seen[corner]) << "corner found twice";
    seen[corner] = true;
  }
}

TEST(FindPatch, OverlapGivesNegativeSeparation) {
  Pair p;
  const double overlap = 2e-4;
  p.b.x.z() -= overlap;
  Patch patch;
  PatchScratch scratch;
  ASSERT_TRUE(find_patch(p.a, p.b, 0.02, -1, -1, patch, scratch));
  ASSERT_EQ(patch.points.size(), 4u);
  for (const PatchPoint& q : patch.points) EXPECT_NEAR(q.separation, -overlap, kTol);
  EXPECT_NEAR(area_sum(patch), 1.0, kTol);
}

// The patch is a property of the pair, not of the frame it is described in.
TEST(FindPatch, InvariantUnderRigidMotionsOfThePair) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  const double gap = 1e-3, margin = 0.02;
  for (int trial = 0; trial < 20; ++trial) {
    Pair p;
    // A little sideways offset so that the motion is not about a symmetry.
    p.b.x += Vec3(0.3, -0.2, gap);
    const Mat3 Q = random_rotation(rng);
    const Vec3 t(u(rng), u(rng), u(rng));
    PosedBlock a{&p.base, Q * p.a.R, Q * p.a.x + t};
    PosedBlock b{&p.cube, Q * p.b.R, Q * p.b.x + t};
    Patch patch;
    PatchScratch scratch;
    ASSERT_TRUE(find_patch(a, b, margin, -1, -1, patch, scratch)) << "trial " << trial;
    // Coordinates are up to ~10 m: allow 1e-11 for the rotated round-off.
    EXPECT_NEAR(patch.area, 1.0, 1e-11) << "trial " << trial;
    EXPECT_NEAR(area_sum(patch), 1.0, 1e-11) << "trial " << trial;
    EXPECT_NEAR((patch.normal - expected_normal(patch, Q)).norm(), 0.0, 1e-12) << "trial " << trial;
    ASSERT_EQ(patch.points.size(), 4u) << "trial " << trial;
    for (const PatchPoint& q : patch.points) {
      EXPECT_NEAR(q.separation, gap, 1e-11) << "trial " << trial;
      // Every point lies over the cube's footprint, in the pair's frame.
      const Vec3 local = Q.transpose() * (q.point - t) - Vec3(0.3, -0.2, 0);
      EXPECT_NEAR(std::abs(local.x()), 0.5, 1e-11) << "trial " << trial;
      EXPECT_NEAR(std::abs(local.y()), 0.5, 1e-11) << "trial " << trial;
    }
  }
}

TEST(FindPatch, CubeHalfOverTheEdgeIsClippedToTheBase) {
  Pair p;
  p.b.x.x() = 1.5;  // cube spans x in [1, 2], base ends at x = 1.5
  Patch patch;
  PatchScratch scratch;
  ASSERT_TRUE(find_patch(p.a, p.b, 0.02, -1, -1, patch, scratch));
  EXPECT_EQ(patch.ref_side, 0);
  EXPECT_NEAR(patch.area, 0.5, kTol);
  EXPECT_NEAR(area_sum(patch), 0.5, kTol);
  ASSERT_EQ(patch.points.size(), 4u);
  int on_edge = 0, corners = 0;
  for (const PatchPoint& q : patch.points) {
    EXPECT_NEAR(q.separation, 0.0, kTol);
    EXPECT_NEAR(std::abs(q.point.y()), 0.5, kTol);
    if (std::abs(q.point.x() - 1.5) < kTol) ++on_edge;       // clipped by the base's side plane
    else if (std::abs(q.point.x() - 1.0) < kTol) ++corners;  // the cube's own corners
  }
  EXPECT_EQ(on_edge, 2);
  EXPECT_EQ(corners, 2);
}

// A cube turned 30° about z with a corner over the base's side plane
// x = 1.5 and then a hair beyond it: four vertices (the cube's corners)
// become five (the corner replaced by two crossings 2e-9 m apart). The
// vertices' areas and their first moment about the origin (what the
// pair's force and moment are made of at a uniform overlap) change by
// O(1e-9), as the polygon does; a fan about the vertices' mean moved its
// centre a fifth of the way to the doubled corner and the first moment by
// 0.07 m³.
TEST(FindPatch, AVertexAppearingAtASidePlaneMovesNoArea) {
  auto patch_at = [](double beyond) {
    Pair p;
    const double phi = std::numbers::pi / 6;
    p.b.R = Eigen::AngleAxisd(phi, Vec3::UnitZ()).toRotationMatrix();
    p.b.x.x() = 1.5 - 0.5 * (std::cos(phi) + std::sin(phi)) + beyond;
    p.b.x.y() = 0.2;
    Patch patch;
    PatchScratch scratch;
    EXPECT_TRUE(find_patch(p.a, p.b, 0.02, -1, -1, patch, scratch));
    return patch;
  };
  const Patch inside = patch_at(-1e-9), beyond = patch_at(1e-9);
  ASSERT_EQ(inside.points.size(), 4u);
  ASSERT_EQ(beyond.points.size(), 5u);
  auto first_moment = [](const Patch& p) {
    Vec3 m = Vec3::Zero();
    for (const PatchPoint& q : p.points) m += q.area * q.point;
    return m;
  };
  EXPECT_NEAR(area_sum(inside), 1.0, kTol);
  EXPECT_NEAR(area_sum(beyond), area_sum(inside), 1e-8);
  EXPECT_LT((first_moment(beyond) - first_moment(inside)).norm(), 1e-8);
}

// A cube tipped by θ about one bottom edge (the pivot, kept on z = 0): the
// pivot corners touch, the far corners are lifted by L·sin θ = 2b·sin θ.
TEST(FindPatch, CubeTiltedOnItsEdge) {
  const double theta = 0.1, L = 1.0;
  Pair p;
  p.b.R = Eigen::AngleAxisd(theta, Vec3::UnitY()).toRotationMatrix();
  // Pivot edge: body-frame x = +0.5, z = −0.5; put it at world x = 0.5, z = 0.
  p.b.x = Vec3(0.5, 0, 0) - p.b.R * Vec3(0.5, 0, -0.5);
  // With a margin wider than the lift, all four bottom corners are kept.
  Patch patch;
  PatchScratch scratch;
  ASSERT_TRUE(find_patch(p.a, p.b, 0.2, -1, -1, patch, scratch));
  EXPECT_EQ(patch.ref_side, 0);
  EXPECT_NEAR((patch.normal - Vec3(0, 0, 1)).norm(), 0.0, kTol);
  ASSERT_EQ(patch.points.size(), 4u);
  int pivots = 0, lifted = 0;
  for (const PatchPoint& q : patch.points) {
    if (std::abs(q.separation) < kTol) {
      ++pivots;
      EXPECT_NEAR(q.point.x(), 0.5, kTol);
    } else {
      EXPECT_NEAR(q.separation, L * std::sin(theta), kTol);
      ++lifted;
    }
  }
  EXPECT_EQ(pivots, 2);
  EXPECT_EQ(lifted, 2);
  // The patch is the footprint projected on the base: L × L·cos θ.
  EXPECT_NEAR(patch.area, L * L * std::cos(theta), kTol);
  EXPECT_NEAR(area_sum(patch), L * L * std::cos(theta), kTol);

  // With a margin narrower than the lift, only the pivot corners remain,
  // each with its own tributary area (a quarter of the footprint), and the
  // patch's area is theirs: the areas still add up to it.
  ASSERT_TRUE(find_patch(p.a, p.b, 0.05, -1, -1, patch, scratch));
  ASSERT_EQ(patch.points.size(), 2u);
  for (const PatchPoint& q : patch.points) {
    EXPECT_NEAR(q.separation, 0.0, kTol);
    EXPECT_NEAR(q.area, 0.25 * L * L * std::cos(theta), kTol);
  }
  EXPECT_NEAR(patch.area, area_sum(patch), kTol);
  EXPECT_NEAR(patch.area, 0.5 * L * L * std::cos(theta), kTol);
}

TEST(FindPatch, NoPatchBeyondTheMargin) {
  Pair p;
  p.b.x.z() += 0.05;  // gap 0.05 > margin 0.02
  Patch patch;
  PatchScratch scratch;
  EXPECT_FALSE(find_patch(p.a, p.b, 0.02, -1, -1, patch, scratch));
  // Also sideways: the cube beside the base, 0.03 away from its side face.
  Pair q;
  q.b.x = Vec3(1.5 + 0.5 + 0.03, 0, -0.5);
  EXPECT_FALSE(find_patch(q.a, q.b, 0.02, -1, -1, patch, scratch));
}

TEST(FindPatch, WithinTheMarginButApartGivesPositiveSeparation) {
  Pair p;
  const double gap = 0.005;
  p.b.x.z() += gap;
  Patch patch;
  PatchScratch scratch;
  ASSERT_TRUE(find_patch(p.a, p.b, 0.02, -1, -1, patch, scratch));
  ASSERT_EQ(patch.points.size(), 4u);
  for (const PatchPoint& q : patch.points) {
    EXPECT_GT(q.separation, 0.0);
    EXPECT_NEAR(q.separation, gap, kTol);
  }
}

// The previous reference face is kept while it is nearly as good as the best:
// the cube's bottom (face with normal −z) stays the reference when asked to.
TEST(FindPatch, KeepsThePreviousReferenceFace) {
  Pair p;
  int cube_bottom = -1;
  for (std::size_t f = 0; f < p.cube.normals.size(); ++f)
    if (p.cube.normals[f].z() < -0.5) cube_bottom = static_cast<int>(f);
  ASSERT_GE(cube_bottom, 0);
  Patch patch;
  PatchScratch scratch;
  ASSERT_TRUE(find_patch(p.a, p.b, 0.02, 1, cube_bottom, patch, scratch));
  EXPECT_EQ(patch.ref_side, 1);
  EXPECT_EQ(patch.ref_face, cube_bottom);
  EXPECT_NEAR((patch.normal - Vec3(0, 0, -1)).norm(), 0.0, kTol);
  EXPECT_NEAR(area_sum(patch), 1.0, kTol);
  ASSERT_EQ(patch.points.size(), 4u);
  // Incident points now lie on the base's top face, under the cube's corners.
  for (const PatchPoint& q : patch.points) {
    EXPECT_NEAR(q.point.z(), 0.0, kTol);
    EXPECT_NEAR(std::abs(q.point.x()), 0.5, kTol);
  }
}

// Two unit cubes crossed edge on edge: the lower one rotated 45° about x
// (its top is a ridge along x), the upper one 45° about y (its bottom is a
// ridge along y), the ridges overlapping by `overlap` at the origin. No face
// is aligned with the contact: the fallback gives a single subcontact.
struct CrossedRidges {
  Polyhedron cube = make_box(Vec3(1, 1, 1));
  double h = std::sqrt(0.5);  // centre-to-ridge distance of a cube turned 45°
  double overlap = 1e-3;
  PosedBlock lower{&cube, Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX()).toRotationMatrix(), Vec3(0, 0, -h)};
  PosedBlock upper{&cube, Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY()).toRotationMatrix(), Vec3(0, 0, h - overlap)};
};

TEST(FindPatch, EdgeOnEdgeFallbackGivesOneSubcontact) {
  CrossedRidges c;
  Patch patch;
  PatchScratch scratch;
  ASSERT_TRUE(find_patch(c.lower, c.upper, 0.02, -1, -1, patch, scratch));
  ASSERT_EQ(patch.points.size(), 1u);
  EXPECT_EQ(patch.ref_face, -1);
  // Normal along ±z (the ridges' common perpendicular), found by MPR: its
  // direction is accurate to the MPR tolerance, so allow 1e-6.
  EXPECT_NEAR(std::abs(patch.normal.z()), 1.0, 1e-6);
  // Separation: minus the ridges' overlap (MPR depth tolerance 1e-6·margin).
  EXPECT_NEAR(patch.points[0].separation, -c.overlap, 1e-6);
  // The area of one corner of a face contact between these blocks: the
  // smaller block's size squared over four (docs/contact.md).
  EXPECT_NEAR(patch.points[0].area, 0.25, kTol);
  EXPECT_NEAR(patch.area, 0.25, kTol);
}

// Where the single fallback subcontact acts: at the ridges' crossing, the
// only place the blocks touch. Anywhere else its force makes a spurious torque.
TEST(FindPatch, EdgeOnEdgeFallbackActsAtTheCrossing) {
  CrossedRidges c;
  Patch patch;
  PatchScratch scratch;
  ASSERT_TRUE(find_patch(c.lower, c.upper, 0.02, -1, -1, patch, scratch));
  ASSERT_EQ(patch.points.size(), 1u);
  // The blocks touch only at the origin; allow the margin.
  EXPECT_LE(patch.points[0].point.norm(), 0.02) << patch.points[0].point.transpose();
}


// The fallback's depth is the separating-axis test's over the face normals
// and the edges' cross products (exact for convex polyhedra), not MPR's,
// which measures along the line between the centres and is only an
// estimate. The poses are two 0.4 × 0.4 × 0.2 m stones of the tower test
// (collapse_slow_test.cpp) tumbling at t = 4.635 s, 0.25 mm apart edge to
// edge: MPR gave them 5.9 mm of overlap, and the subcontact 43 kJ of strain
// from nowhere.
TEST(FindPatch, EdgeOnEdgeDepthIsTheSeparatingAxisTestsNotMprs) {
  const Polyhedron stone = make_box(Vec3(0.4, 0.4, 0.2));
  const Mat3 ra = Quat(0.66771315671856057, -0.059355187525186467, 0.74140414225024176, -0.030919248260079361)
                      .normalized()
                      .toRotationMatrix();
  const Mat3 rb = Quat(0.68923168373908605, -0.12991944559254845, 0.71134946049303382, -0.045415513245797345)
                      .normalized()
                      .toRotationMatrix();
  const PosedBlock a{&stone, ra, Vec3(7.1084293038492801, 0.16427449648413722, 0.25035213806281204)};
  const PosedBlock b{&stone, rb, Vec3(7.3594048916884676, -0.19790178400419731, 0.41741978592268048)};
  // The exact separation: the largest over the 6 face normals and the 9
  // cross products of edge directions of the two boxes.
  std::vector<Vec3> axes;
  for (int k = 0; k < 3; ++k) axes.push_back(ra.col(k)), axes.push_back(rb.col(k));
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) axes.push_back(ra.col(k).cross(rb.col(l)).normalized());
  double exact = -1e300;
  for (Vec3 axis : axes) {
    if (axis.dot(b.x - a.x) < 0) axis = -axis;
    double top_a = -1e300, low_b = 1e300;
    for (const Vec3& v : stone.vertices) top_a = std::max(top_a, axis.dot(ra * v + a.x));
    for (const Vec3& v : stone.vertices) low_b = std::min(low_b, axis.dot(rb * v + b.x));
    exact = std::max(exact, low_b - top_a);
  }
  ASSERT_NEAR(exact, 2.5e-4, 0.1e-4) << "the stones are 0.25 mm apart";
  Patch patch;
  PatchScratch scratch;
  ASSERT_TRUE(find_patch(a, b, 0.006349604207872791, -1, -1, patch, scratch));
  ASSERT_EQ(patch.points.size(), 1u);
  EXPECT_EQ(patch.ref_face, -1);
  EXPECT_NEAR(patch.points[0].separation, exact, 1e-12);
}

}  // namespace
}  // namespace polydem
