// Intersection of half-spaces by duality with the convex hull.
//
// Shift the origin to the interior point o. A half-space n·x <= d (|n| = 1)
// then reads n·y <= s with slack s = d - n·o > 0, and maps to the dual point
// q = n / s. The hull of the dual points carries the answer: each of its
// faces, with plane m·q = h (h > 0), is one vertex y = m / h of the
// intersection, and half-spaces whose dual points are not hull corners are
// redundant. If o is not strictly inside the dual hull the intersection is
// unbounded. Going through merged_hull() means several planes through one
// corner (a pyramid apex) give that corner once, not several nearly equal
// copies. The corners are then hulled again to get the faces.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "geometry/merged_hull.hpp"

namespace polydem {

Polyhedron halfspace_intersection(const std::vector<Vec3>& normals, const std::vector<double>& offsets,
                                  const Vec3& interior) {
  auto fail = [](const std::string& what) { throw GeometryError("halfspace_intersection: " + what); };
  if (normals.size() != offsets.size()) fail("normals and offsets differ in number");
  if (normals.size() < 4) fail("fewer than 4 half-spaces cannot bound a region (unbounded)");
  if (!interior.allFinite()) fail("interior point is not finite");

  std::vector<Vec3> dual;
  for (size_t i = 0; i < normals.size(); ++i) {
    const double len = normals[i].norm();
    if (!(len > 0) || !std::isfinite(len) || !std::isfinite(offsets[i]))
      fail("half-space " + std::to_string(i) + " has a zero or non-finite normal/offset");
    const Vec3 n = normals[i] / len;
    const double slack = offsets[i] / len - n.dot(interior);
    if (!(slack > 0)) {
      std::ostringstream m;
      m << "interior point is not strictly inside half-space " << i << " (it lies " << -slack
        << " outside); the intersection may be empty";
      fail(m.str());
    }
    dual.push_back(n / slack);
  }

  HullPolygons hull;
  try {
    hull = merged_hull(dual);
  } catch (const GeometryError& e) {
    fail(std::string("the half-spaces do not enclose a bounded region (") + e.what() + ")");
  }
  const double dual_size = bounding_box_diagonal(hull.vertices);

  std::vector<Vec3> corners;
  for (size_t f = 0; f < hull.faces.size(); ++f) {
    const auto& loop = hull.faces[f];
    Vec3 m = Vec3::Zero();
    const Vec3& q0 = hull.vertices[loop[0]];
    for (size_t k = 1; k + 1 < loop.size(); ++k)
      m += (hull.vertices[loop[k]] - q0).cross(hull.vertices[loop[k + 1]] - q0);
    m.normalize();
    double h = 0;
    for (int v : loop) h += m.dot(hull.vertices[v]);
    h /= static_cast<double>(loop.size());
    // h is the distance of o from this dual face; at (or past) zero the
    // matching corner is at infinity.
    if (!(h > 1e-12 * dual_size)) fail("the intersection is unbounded");
    corners.push_back(interior + m / h);
  }
  try {
    return convex_hull(corners);
  } catch (const GeometryError& e) {
    fail(std::string("degenerate intersection (") + e.what() + ")");
  }
  return {};  // not reached
}

}  // namespace polydem
