// validate() must reject each kind of broken shape with a message that says
// what is wrong and where.
#include <gmock/gmock.h>

#include "geometry/polyhedron.hpp"
#include "shapes.hpp"

namespace polydem {
namespace {

using ::testing::HasSubstr;

// Unit cube as plain arrays, to be broken in each test.
struct Raw {
  std::vector<Vec3> v;
  std::vector<std::vector<int>> f;
};
Raw cube() {
  const auto p = make_box(Vec3(1, 1, 1));
  return {p.vertices, p.faces};
}

std::string error_of(Raw r) {
  try {
    make_polyhedron(std::move(r.v), std::move(r.f));
  } catch (const GeometryError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Validate, AcceptsCube) { EXPECT_EQ(error_of(cube()), "no error"); }

TEST(Validate, RejectsOpenShape) {
  Raw r = cube();
  r.f.pop_back();
  const std::string msg = error_of(r);
  EXPECT_THAT(msg, HasSubstr("open"));
  EXPECT_THAT(msg, HasSubstr("face"));
}

TEST(Validate, RejectsFlippedFace) {
  Raw r = cube();
  std::reverse(r.f[2].begin(), r.f[2].end());
  const std::string msg = error_of(r);
  EXPECT_THAT(msg, HasSubstr("flipped face"));
  EXPECT_THAT(msg, HasSubstr(" 2"));
}

TEST(Validate, RejectsInsideOutShape) {
  Raw r = cube();
  for (auto& f : r.f) std::reverse(f.begin(), f.end());
  EXPECT_THAT(error_of(r), HasSubstr("oriented inward"));
}

TEST(Validate, RejectsNonConvexShape) {
  // Triangular bipyramid whose lower apex is pushed up inside: closed, planar
  // triangles, positive volume, but dented.
  Raw r;
  r.v = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.3, 0.3, 1), Vec3(0.3, 0.3, 0.5)};
  r.f = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}};
  const std::string msg = error_of(r);
  EXPECT_THAT(msg, HasSubstr("not convex"));
  EXPECT_THAT(msg, HasSubstr("vertex"));
  EXPECT_THAT(msg, HasSubstr("face"));
}

TEST(Validate, RejectsFlatShape) {
  // Tetrahedron topology with all four corners in z = 0.
  Raw r;
  r.v = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.25, 0.25, 0)};
  r.f = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  EXPECT_THAT(error_of(r), HasSubstr("flat or degenerate"));
}

TEST(Validate, RejectsNonPlanarFace) {
  Raw r = cube();
  r.v[7] += Vec3(0.01, 0.02, 0.03);
  EXPECT_THAT(error_of(r), HasSubstr("face 1 is not planar: vertex"));
}

TEST(Validate, RejectsDuplicateVertex) {
  Raw r = cube();
  r.v.push_back(r.v[3]);
  EXPECT_THAT(error_of(r), HasSubstr("vertices 3 and 8 coincide"));
}

TEST(Validate, RejectsUnmergedCoplanarFaces) {
  Raw r = cube();
  const auto q = r.f[5];  // +z quad, split into two triangles
  r.f[5] = {q[0], q[1], q[2]};
  r.f.push_back({q[0], q[2], q[3]});
  EXPECT_THAT(error_of(r), HasSubstr("faces 5 and 6 are coplanar neighbours"));
}

TEST(Validate, RejectsBadIndicesAndTooFewFaces) {
  Raw r = cube();
  r.f[0][1] = 99;
  EXPECT_THAT(error_of(r), HasSubstr("face 0 refers to vertex 99"));
  Raw t = cube();
  t.f.resize(3);
  EXPECT_THAT(error_of(t), HasSubstr("3 faces"));
}

}  // namespace
}  // namespace polydem
