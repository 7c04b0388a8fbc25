// Box and prism generators, and the face measures on them.
#include <gmock/gmock.h>

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

TEST(MakeBox, TopologyAndOutwardNormals) {
  const Vec3 c(1, 2, 3);
  const auto p = make_box(Vec3(2, 4, 6), c);
  EXPECT_EQ(p.vertices.size(), 8u);
  EXPECT_EQ(p.edges.size(), 12u);
  ASSERT_EQ(p.faces.size(), 6u);
  for (size_t f = 0; f < 6; ++f) {
    EXPECT_EQ(p.faces[f].size(), 4u);
    EXPECT_GT(p.normals[f].dot(face_centroid(p, static_cast<int>(f)) - c), 0) << "face " << f;
    EXPECT_NEAR(p.normals[f].cwiseAbs().maxCoeff(), 1, 1e-15);
  }
  for (const auto& e : p.edges) EXPECT_LT(e[0], e[1]);
}

TEST(FaceMeasures, BoxAreasCentroidsRadius) {
  const auto p = make_box(Vec3(2, 4, 6), Vec3(1, 2, 3));
  EXPECT_NEAR(surface_area(p), 2 * (8 + 24 + 12), 1e-12);
  for (int f = 0; f < 6; ++f) {
    const Vec3 n = p.normals[f];
    const Vec3 half(1, 2, 3);
    expect_vec_near(face_centroid(p, f), Vec3(1, 2, 3) + n.cwiseProduct(half).cwiseAbs().sum() * n, 1e-14);
    expect_vec_near(face_vector_area(p, f), face_area(p, f) * n, 1e-14);
  }
  EXPECT_NEAR(bounding_radius(p, Vec3(1, 2, 3)), std::sqrt(1 + 4 + 9), 1e-14);
}

TEST(FaceMeasures, PolarMomentOfSquare) {
  // Square of side a: ∫|x - c|² dA = a⁴/6 about its centre; about a corner the
  // parallel-axis term adds A·|d|² = a² · a²/2.
  const double a = 3;
  const auto p = make_box(Vec3(a, a, 1));
  int top = -1;
  for (int f = 0; f < 6; ++f)
    if (p.normals[f].z() > 0.5) top = f;
  ASSERT_GE(top, 0);
  EXPECT_NEAR(face_polar_moment(p, top, Vec3(0, 0, 0.5)), std::pow(a, 4) / 6, 1e-12);
  EXPECT_NEAR(face_polar_moment(p, top, Vec3(a / 2, a / 2, 0.5)), 2 * std::pow(a, 4) / 3, 1e-12);
  EXPECT_NEAR(face_area(p, top), a * a, 1e-13);
}

TEST(MakeBox, RejectsNonPositiveSize) {
  EXPECT_THAT(error_of([] { make_box(Vec3(1, 0, 1)); }), HasSubstr("positive"));
}

TEST(MakePrism, EitherOrientationGivesTheSameSolid) {
  auto poly = octagon(1.0);
  const auto ccw = make_prism(poly, 0, 2);
  std::reverse(poly.begin(), poly.end());
  const auto cw = make_prism(poly, 0, 2);
  EXPECT_EQ(ccw.faces.size(), 10u);
  EXPECT_EQ(cw.faces.size(), 10u);
  EXPECT_NEAR(mass_properties(cw).volume, mass_properties(ccw).volume, 1e-14);
  EXPECT_GT(mass_properties(cw).volume, 0);
}

TEST(MakePrism, RejectsBadPolygons) {
  const std::vector<Vec2> collinear = {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(2, 1), Vec2(0, 1)};
  EXPECT_THAT(error_of([&] { make_prism(collinear, 0, 1); }), HasSubstr("collinear points at point 1"));
  const std::vector<Vec2> repeated = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(0, 1)};
  EXPECT_THAT(error_of([&] { make_prism(repeated, 0, 1); }), HasSubstr("repeated point"));
  const std::vector<Vec2> arrow = {Vec2(0, 0), Vec2(2, 1), Vec2(0, 2), Vec2(0.5, 1)};
  EXPECT_THAT(error_of([&] { make_prism(arrow, 0, 1); }), HasSubstr("not convex at point 3"));
  std::vector<Vec2> pentagram;
  for (int k = 0; k < 5; ++k) {
    const double a = 2 * std::numbers::pi * (2 * k) / 5;
    pentagram.emplace_back(std::cos(a), std::sin(a));
  }
  EXPECT_THAT(error_of([&] { make_prism(pentagram, 0, 1); }), HasSubstr("self-intersecting"));
  EXPECT_THAT(error_of([&] { make_prism(octagon(1), 1, 1); }), HasSubstr("z1 > z0"));
  EXPECT_THAT(error_of([] { make_prism({Vec2(0, 0), Vec2(1, 0)}, 0, 1); }), HasSubstr("at least 3"));
}

}  // namespace
}  // namespace polydem
