// Convex hull (with coplanar facets merged) and half-space intersection.
#include <gmock/gmock.h>

#include <algorithm>
#include <random>

#include "geometry/polyhedron.hpp"
#include "shapes.hpp"

namespace polydem {
namespace {

using namespace polydem::test;
using ::testing::HasSubstr;

std::string error_of(const auto& build) {
  try {
    build();
  } catch (const GeometryError& e) {
    return e.what();
  }
  return "no error";
}

std::vector<Vec3> box_corners(const Vec3& size) {
  return make_box(size).vertices;
}

// Every vertex of p is one of `want` (within tol) and the counts agree.
void expect_same_vertices(const Polyhedron& p, const std::vector<Vec3>& want, double tol) {
  ASSERT_EQ(p.vertices.size(), want.size());
  for (const auto& w : want) {
    double best = 1e300;
    for (const auto& v : p.vertices) best = std::min(best, (v - w).norm());
    EXPECT_LE(best, tol) << "missing corner " << w.transpose();
  }
}

TEST(ConvexHull, CubeWithInteriorPointsHasSixQuads) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.49, 0.49);
  std::vector<Vec3> pts = box_corners(Vec3(1, 1, 1));
  for (int i = 0; i < 50; ++i) pts.emplace_back(u(rng), u(rng), u(rng));
  std::shuffle(pts.begin(), pts.end(), rng);
  const auto p = convex_hull(pts);
  ASSERT_EQ(p.faces.size(), 6u);
  for (const auto& f : p.faces) EXPECT_EQ(f.size(), 4u);
  EXPECT_EQ(p.edges.size(), 12u);
  expect_same_vertices(p, box_corners(Vec3(1, 1, 1)), 0);
  EXPECT_NEAR(mass_properties(p).volume, 1, 1e-14);
}

TEST(ConvexHull, PointsOnFacesAndEdgesAreNotCorners) {
  std::vector<Vec3> pts = box_corners(Vec3(2, 2, 2));
  for (int a = 0; a < 3; ++a)
    for (double s : {-1.0, 1.0}) {
      Vec3 c = Vec3::Zero();
      c[a] = s;
      pts.push_back(c);                                      // face centre
      pts.push_back(c + Vec3::Unit((a + 1) % 3) * 1.0);      // edge midpoint
      pts.push_back(c + Vec3::Unit((a + 2) % 3) * 0.5);      // inside a face
    }
  const auto p = convex_hull(pts);
  EXPECT_EQ(p.faces.size(), 6u);
  expect_same_vertices(p, box_corners(Vec3(2, 2, 2)), 0);
}

TEST(ConvexHull, OctagonalPrismHasTenFacesEvenWhenRotated) {
  const auto prism = make_prism(octagon(1.3), -0.4, 2.1);
  std::mt19937 rng(11);
  for (int trial = 0; trial < 10; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const Mat3 rot = trial == 0 ? Mat3::Identity() : random_rotation(rng);
    const Polyhedron moved = transformed(prism, rot, Vec3(3, -1, 2));
    const auto p = convex_hull(moved.vertices);
    ASSERT_EQ(p.faces.size(), 10u);
    int octagons = 0;
    for (const auto& f : p.faces) octagons += f.size() == 8;
    EXPECT_EQ(octagons, 2);
    EXPECT_EQ(p.vertices.size(), 16u);
    EXPECT_NEAR(mass_properties(p).volume, mass_properties(prism).volume, 1e-12);
  }
}

TEST(ConvexHull, RandomPointsAreAllInsideTheHull) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Vec3> pts;
    for (int i = 0; i < 300; ++i) pts.push_back(Vec3(g(rng), g(rng), g(rng)) + Vec3(100, -50, 20));
    const auto p = convex_hull(pts);  // make_polyhedron validated it
    for (const auto& x : pts)
      for (size_t f = 0; f < p.faces.size(); ++f) ASSERT_LE(p.normals[f].dot(x) - p.offsets[f], 1e-9);
  }
}

// The hull's numbering is the points' own, not CGAL's: the same points in
// any order, built any number of times, give the same vertices and faces.
TEST(ConvexHull, NumberingDoesNotDependOnInputOrderOrHeap) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  std::vector<Vec3> pts;
  for (int i = 0; i < 60; ++i) pts.push_back(Vec3(g(rng), g(rng), g(rng)));
  for (const Vec3& c : box_corners(Vec3(1, 2, 3))) pts.push_back(c);  // coplanar groups too
  const Polyhedron first = convex_hull(pts);
  std::vector<std::vector<char>> heap;  // different heap layout between builds
  for (int trial = 0; trial < 6; ++trial) {
    heap.emplace_back(1000 + 4096 * trial);
    std::shuffle(pts.begin(), pts.end(), rng);
    const Polyhedron again = convex_hull(pts);
    EXPECT_EQ(again.vertices, first.vertices);
    EXPECT_EQ(again.faces, first.faces);
  }
}

TEST(ConvexHull, RejectsTooFewOrCoplanarPoints) {
  EXPECT_THAT(error_of([] { convex_hull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}); }),
              HasSubstr("need at least 4"));
  EXPECT_THAT(error_of([] { convex_hull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)}); }),
              HasSubstr("coplanar"));
  EXPECT_THAT(error_of([] { convex_hull({Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2), Vec3(3, 3, 3)}); }),
              HasSubstr("collinear"));
}

// Planes of an axis-aligned box of half-sizes h centred at c, normals scaled
// by k to check that unnormalised input is accepted.
void box_planes(const Vec3& h, const Vec3& c, std::vector<Vec3>& n, std::vector<double>& d, double k = 1) {
  for (int a = 0; a < 3; ++a)
    for (double s : {-1.0, 1.0}) {
      const Vec3 u = s * Vec3::Unit(a);
      n.push_back(k * u);
      d.push_back(k * (u.dot(c) + h[a]));
    }
}

TEST(HalfspaceIntersection, SixPlanesGiveTheBox) {
  const Vec3 size(2, 3, 5), c(1, -2, 3);
  std::vector<Vec3> n;
  std::vector<double> d;
  box_planes(size / 2, c, n, d, 2.5);
  n.push_back(Vec3(1, 1, 1));  // redundant: far outside the box
  d.push_back(100);
  const auto p = halfspace_intersection(n, d, c + Vec3(0.1, 0.2, -0.3));
  EXPECT_EQ(p.faces.size(), 6u);
  for (const auto& f : p.faces) EXPECT_EQ(f.size(), 4u);
  expect_same_vertices(p, make_box(size, c).vertices, 1e-12);
  EXPECT_NEAR(mass_properties(p).volume, 30, 1e-11);
}

TEST(HalfspaceIntersection, FourPlanesThroughOneApex) {
  // Square pyramid: base z >= 0 and four sides through the apex (0, 0, 3).
  const double a = 2, h = 3;
  std::vector<Vec3> n = {Vec3(0, 0, -1)};
  std::vector<double> d = {0};
  for (const Vec3& s : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)}) {
    n.push_back(h * s + Vec3(0, 0, a / 2));  // plane through the apex and a base edge
    d.push_back(n.back().z() * h);
  }
  const auto p = halfspace_intersection(n, d, Vec3(0, 0, 0.5));
  EXPECT_EQ(p.vertices.size(), 5u);
  EXPECT_EQ(p.faces.size(), 5u);
  EXPECT_NEAR(mass_properties(p).volume, a * a * h / 3, 1e-12);
}

TEST(HalfspaceIntersection, RejectsUnboundedAndBadInterior) {
  std::vector<Vec3> n;
  std::vector<double> d;
  box_planes(Vec3(1, 1, 1), Vec3::Zero(), n, d);
  n.pop_back();  // drop +z
  d.pop_back();
  EXPECT_THAT(error_of([&] { halfspace_intersection(n, d, Vec3::Zero()); }), HasSubstr("unbounded"));

  n.push_back(Vec3(0, 0, 1));
  d.push_back(1);
  EXPECT_THAT(error_of([&] { halfspace_intersection(n, d, Vec3(0, 0, 2)); }),
              HasSubstr("not strictly inside half-space 5"));
  // Empty: z <= -2 together with z >= -1; no interior point exists.
  d.back() = -2;
  EXPECT_THAT(error_of([&] { halfspace_intersection(n, d, Vec3::Zero()); }), HasSubstr("empty"));
}

}  // namespace
}  // namespace polydem
