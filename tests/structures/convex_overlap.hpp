// Do two convex polyhedra overlap? The separating-axis test, for the
// generators' tests (wall, tower): no two blocks may overlap, no block may
// reach into an opening.
#pragma once

#include <algorithm>

#include "geometry/polyhedron.hpp"

namespace polydem::test {

// True if the interiors overlap by more than tol along every candidate
// separating axis (both sets of face normals and the cross products of
// their edges).
inline bool interiors_overlap(const Polyhedron& a, const Polyhedron& b, double tol) {
  auto separated = [&](Vec3 axis) {
    const double n = axis.norm();
    if (n < 1e-12) return false;
    axis /= n;
    double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
    for (const auto& v : a.vertices) a0 = std::min(a0, axis.dot(v)), a1 = std::max(a1, axis.dot(v));
    for (const auto& v : b.vertices) b0 = std::min(b0, axis.dot(v)), b1 = std::max(b1, axis.dot(v));
    return a1 <= b0 + tol || b1 <= a0 + tol;
  };
  for (const auto& n : a.normals)
    if (separated(n)) return false;
  for (const auto& n : b.normals)
    if (separated(n)) return false;
  for (const auto& ea : a.edges)
    for (const auto& eb : b.edges)
      if (separated((a.vertices[ea[1]] - a.vertices[ea[0]]).cross(b.vertices[eb[1]] - b.vertices[eb[0]])))
        return false;
  return true;
}

}  // namespace polydem::test
