// Shapes and checks shared by the geometry tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "geometry/polyhedron.hpp"

namespace polydem::test {

// Regular octagon of circumradius r, first corner at angle phase.
inline std::vector<Vec2> octagon(double r, double phase = 0.1) {
  std::vector<Vec2> p;
  for (int k = 0; k < 8; ++k) {
    const double a = phase + 2 * std::numbers::pi * k / 8;
    p.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return p;
}

// Corner tetrahedron 0, e1, e2, e3 (faces CCW from outside).
inline Polyhedron corner_tetrahedron() {
  return make_polyhedron({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)},
                         {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
}

// Square pyramid: base side a centred on the origin in z = 0, apex at height h.
inline Polyhedron square_pyramid(double a, double h) {
  const double s = a / 2;
  return make_polyhedron({Vec3(-s, -s, 0), Vec3(s, -s, 0), Vec3(s, s, 0), Vec3(-s, s, 0), Vec3(0, 0, h)},
                         {{3, 2, 1, 0}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
}

// Uniformly distributed rotation (normalised Gaussian quaternion).
inline Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Quat q(g(rng), g(rng), g(rng), g(rng));
  return q.normalized().toRotationMatrix();
}

inline void expect_vec_near(const Vec3& a, const Vec3& b, double tol) {
  EXPECT_LE((a - b).norm(), tol) << "got " << a.transpose() << ", want " << b.transpose();
}

inline void expect_mat_near(const Mat3& a, const Mat3& b, double tol) {
  EXPECT_LE((a - b).norm(), tol) << "got\n" << a << "\nwant\n" << b;
}

}  // namespace polydem::test
