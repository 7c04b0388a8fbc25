// Mass properties against closed forms, and their behaviour under rigid
// motions (volume invariant, centroid carried along, inertia R I Rᵀ).
#include "geometry/polyhedron.hpp"
#include "shapes.hpp"

namespace polydem {
namespace {

using namespace polydem::test;
constexpr double kRel = 1e-12;

TEST(MassProperties, Box) {
  const double a = 2, b = 3, c = 5;
  const Vec3 centre(1, -2, 3);
  const auto m = mass_properties(make_box(Vec3(a, b, c), centre));
  const double v = a * b * c;
  EXPECT_NEAR(m.volume, v, kRel * v);
  expect_vec_near(m.centroid, centre, kRel * 10);
  const Vec3 diag(b * b + c * c, a * a + c * c, a * a + b * b);
  expect_mat_near(m.inertia, Mat3((v / 12) * diag.asDiagonal()), kRel * m.inertia.norm());
}

TEST(MassProperties, CornerTetrahedronIncludingProducts) {
  // ∫x² dV = 1/60 and ∫xy dV = 1/120 about the origin; shift to the centroid
  // (1/4, 1/4, 1/4) with V = 1/6: x² -> 1/160, xy -> -1/480.
  const auto m = mass_properties(corner_tetrahedron());
  EXPECT_NEAR(m.volume, 1.0 / 6, kRel);
  expect_vec_near(m.centroid, Vec3::Constant(0.25), kRel);
  Mat3 want = Mat3::Constant(1.0 / 480);  // products of inertia: -(-1/480)
  want.diagonal().setConstant(2.0 / 160);
  expect_mat_near(m.inertia, want, kRel * want.norm());
}

TEST(MassProperties, RegularTetrahedron) {
  // Edge a = 2√2, V = a³/(6√2) = 8/3, I = V a²/20 about any centroidal axis.
  const auto p = convex_hull({Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)});
  const auto m = mass_properties(p);
  EXPECT_NEAR(m.volume, 8.0 / 3, kRel * 8 / 3);
  expect_vec_near(m.centroid, Vec3::Zero(), kRel);
  expect_mat_near(m.inertia, (8.0 / 3 * 8 / 20) * Mat3::Identity(), kRel * 2);
}

TEST(MassProperties, RegularOctagonalPrism) {
  // Regular n-gon of circumradius R: A = n/2 R² sin(2π/n), polar moment
  // J = A R²/6 (2 + cos(2π/n)), split equally between x and y.
  const double r = 1.3, z0 = -0.4, z1 = 2.1, h = z1 - z0;
  const auto m = mass_properties(make_prism(octagon(r), z0, z1));
  const double area = 4 * r * r * std::sin(std::numbers::pi / 4);
  const double j = area * r * r / 6 * (2 + std::cos(std::numbers::pi / 4));
  const double v = area * h;
  EXPECT_NEAR(m.volume, v, kRel * v);
  expect_vec_near(m.centroid, Vec3(0, 0, 0.5 * (z0 + z1)), kRel * 3);
  const double ixx = h * j / 2 + v * h * h / 12;
  expect_mat_near(m.inertia, Vec3(ixx, ixx, h * j).asDiagonal().toDenseMatrix(), kRel * ixx);
}

TEST(MassProperties, SquarePyramid) {
  // V = a²h/3, centroid h/4 above the base, Izz = V a²/10,
  // Ixx = Iyy = V (a²/20 + 3h²/80).
  const double a = 2, h = 3;
  const auto m = mass_properties(square_pyramid(a, h));
  const double v = a * a * h / 3;
  EXPECT_NEAR(m.volume, v, kRel * v);
  expect_vec_near(m.centroid, Vec3(0, 0, h / 4), kRel * 3);
  const double ixx = v * (a * a / 20 + 3 * h * h / 80);
  expect_mat_near(m.inertia, Vec3(ixx, ixx, v * a * a / 10).asDiagonal().toDenseMatrix(), kRel * ixx);
}

TEST(MassProperties, InvariantUnderRandomRigidMotions) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> u(-10, 10);
  const std::vector<Polyhedron> shapes = {make_box(Vec3(2, 3, 5), Vec3(1, -2, 3)), corner_tetrahedron(),
                                          make_prism(octagon(1.3), -0.4, 2.1), square_pyramid(2, 3)};
  for (size_t s = 0; s < shapes.size(); ++s) {
    const auto m0 = mass_properties(shapes[s]);
    for (int trial = 0; trial < 25; ++trial) {
      SCOPED_TRACE("shape " + std::to_string(s) + ", trial " + std::to_string(trial));
      const Mat3 rot = random_rotation(rng);
      const Vec3 t(u(rng), u(rng), u(rng));
      const Polyhedron q = transformed(shapes[s], rot, t);
      EXPECT_NO_THROW(validate(q));
      const auto m = mass_properties(q);
      EXPECT_NEAR(m.volume, m0.volume, kRel * m0.volume);
      expect_vec_near(m.centroid, rot * m0.centroid + t, kRel * 20);
      expect_mat_near(m.inertia, rot * m0.inertia * rot.transpose(), 10 * kRel * m0.inertia.norm());
      for (size_t f = 0; f < q.faces.size(); ++f) {
        expect_vec_near(q.normals[f], rot * shapes[s].normals[f], kRel);
        EXPECT_NEAR(q.normals[f].dot(q.vertices[q.faces[f][0]]), q.offsets[f], kRel * 20);
      }
    }
  }
}

}  // namespace
}  // namespace polydem
